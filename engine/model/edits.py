"""Edits of a model's parameter tree (§2.2), each returning the state that undoes it.

Every edit here changes the model in place (bumping its revision, so the
deformer is rebuilt) and returns a :class:`TreeState`: the parameters in
order and the regions the edit replaced or removed. Passing that state to
:func:`restore_tree` puts the model back bit for bit — parameters, their
order, regions' indices, weights and displacements — and returns the state
that redoes the edit. An edit the model refuses raises
:class:`~engine.errors.UserError` and leaves the model untouched.

>>> from engine.model import InfluenceRegion, Model, Parameter
>>> model = Model([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [3, 0, 1, 2])
>>> undo = add_parameter(model, Parameter("jaw", "rotation"), InfluenceRegion([0, 1], [1.0, 0.5]))
>>> undo_add = add_parameter(model, Parameter("lip", "translation", parent="jaw"))
>>> undo_rename = rename_parameter(model, "jaw", "jaw_open")
>>> [(p.name, p.parent) for p in model.parameters]
[('jaw_open', None), ('lip', 'jaw_open')]
>>> redo = restore_tree(model, undo_rename)                # undo the rename
>>> [(p.name, p.parent) for p in model.parameters], model.regions["jaw"].weights.tolist()
([('jaw', None), ('lip', 'jaw')], [1.0, 0.5])
>>> _ = restore_tree(model, redo)                          # and redo it
>>> model.parameters.names
['jaw_open', 'lip']

The regions a state carries are shared, not copied: engine edits replace a
region, they never write into one.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from engine.errors import ParameterError, UserError
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree


@dataclass(frozen=True, eq=False)
class TreeState:
    """A parameter tree to make current: the parameters in order and the regions it brings.

    Attributes
    ----------
    parameters : tuple of Parameter
        The whole tree in order (private copies: restoring copies them again,
        so one state can be restored any number of times).
    regions : mapping name → InfluenceRegion
        Regions to put in place. A parameter not named here keeps the region
        it has in the model (under its old name if ``renamed`` says so).
    renamed : mapping current name → name in this state
        Parameters that restoring the state renames (the rest keep their names).
    """

    parameters: tuple[Parameter, ...]
    regions: Mapping[str, InfluenceRegion] = field(default_factory=dict)
    renamed: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "parameters", tuple(p.copy() for p in self.parameters))
        object.__setattr__(self, "regions", MappingProxyType(dict(self.regions)))
        object.__setattr__(self, "renamed", MappingProxyType(dict(self.renamed)))

    @classmethod
    def of(cls, model: Model, region_names: Iterable[str] = ()) -> TreeState:
        """The model's tree as it is now, carrying the regions named in ``region_names``."""
        return cls(tuple(model.parameters), {name: model.regions[name] for name in region_names})

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.parameters]


def restore_tree(model: Model, state: TreeState) -> TreeState:
    """Make ``model``'s tree ``state``'s (in its order) with its regions; returns the state before.

    Regions of parameters the state does not have are dropped. Raises
    :class:`~engine.errors.UserError` (a :class:`~engine.errors.ParameterError`
    for a bad tree), leaving the model as it was, if the result is not a valid
    model or a parameter of the state has no region to take.
    """
    tree = ParameterTree(p.copy() for p in state.parameters)     # validates names, parents, loops
    source = {new: old for old, new in state.renamed.items()}
    regions: dict[str, InfluenceRegion] = {}
    taken: set[str] = set()           # current names whose region moves into the new tree as it is
    missing = []
    for p in tree:
        if p.name in state.regions:
            regions[p.name] = state.regions[p.name]
            continue
        old = source.get(p.name, None if p.name in state.renamed else p.name)
        if old is None or old not in model.regions:
            missing.append(p.name)
            continue
        regions[p.name] = model.regions[old]
        taken.add(old)
    if missing:
        raise ParameterError(f"no influence region for {', '.join(missing)}: the tree cannot be restored")
    undo = TreeState(tuple(model.parameters),
                     {name: region for name, region in model.regions.items() if name not in taken},
                     {new: old for old, new in state.renamed.items()})
    old_tree, old_regions = model.parameters, model.regions
    model.parameters, model.regions = tree, regions
    try:
        model.validate()
    except UserError:
        model.parameters, model.regions = old_tree, old_regions
        raise
    model.changed()
    return undo


def add_parameters(model: Model, parameters_and_regions: Iterable[tuple[Parameter, InfluenceRegion | None]]
                   ) -> TreeState:
    """Add several parameters at the end of the order, each with its region (``None``: empty); all or none.

    The model holds copies of the parameters. Returns the state before
    (restoring it removes them again).
    """
    items = list(parameters_and_regions)
    tree = model.parameters
    seen: set[str] = set()
    for parameter, _ in items:
        if parameter.name in tree or parameter.name in seen:
            raise ParameterError(f"parameter '{parameter.name}' already exists")
        seen.add(parameter.name)
    regions = {p.name: region if region is not None else InfluenceRegion() for p, region in items}
    return restore_tree(model, TreeState((*tree, *(p for p, _ in items)), regions))


def add_parameter(model: Model, parameter: Parameter, region: InfluenceRegion | None = None) -> TreeState:
    """Add ``parameter`` last in the order with ``region`` (empty if ``None``); returns the state before."""
    return add_parameters(model, [(parameter, region)])


def remove_parameter(model: Model, name: str) -> TreeState:
    """Remove a parameter and its region; its children move up to its parent (as
    :meth:`Model.remove_parameter <engine.model.Model.remove_parameter>` does). Returns the state before."""
    removed = model.parameters[name]
    kept = [p.copy(parent=removed.parent) if p.parent == name else p for p in model.parameters if p.name != name]
    return restore_tree(model, TreeState(tuple(kept)))


def remove_subtree(model: Model, name: str) -> TreeState:
    """Remove ``name``, every parameter below it, and their regions; returns the state before."""
    gone = set(subtree(model.parameters, name))
    return restore_tree(model, TreeState(tuple(p for p in model.parameters if p.name not in gone)))


def rename_parameter(model: Model, old: str, new: str) -> TreeState:
    """Rename ``old`` to ``new``; its region and its children's ``parent`` follow, the order stays.

    Raises :class:`~engine.errors.ParameterError` for an unknown ``old``, a
    ``new`` that is taken or a name the model format does not allow.
    Returns the state before (restoring it renames back).
    """
    return restore_tree(model, TreeState(tuple(renamed_parameters(model.parameters, old, new)), {}, {old: new}))


def move_parameter(model: Model, name: str, parent: str | None, before: str | None = None) -> TreeState:
    """Move ``name`` (with its subtree) under ``parent`` (``None``: the top), just before its new sibling
    ``before`` or after the last one (see :func:`moved_parameters`); returns the state before."""
    return restore_tree(model, TreeState(tuple(moved_parameters(model.parameters, name, parent, before))))


def replace_parameter(model: Model, parameter: Parameter) -> TreeState:
    """Give the parameter of the same name new properties (kind, axis, pivot, range, parent, …).

    The whole model is validated (e.g. a field translation needs
    displacements); returns the state before.
    """
    model.parameters[parameter.name]           # unknown names raise with a suggestion
    return restore_tree(model, TreeState(tuple(parameter if p.name == parameter.name else p
                                               for p in model.parameters)))


def set_region(model: Model, name: str, region: InfluenceRegion) -> InfluenceRegion:
    """Replace parameter ``name``'s whole influence region; returns the region it had (set it back to undo)."""
    model.parameters[name]                     # unknown names raise with a suggestion
    old = model.regions[name]
    model.set_region(name, region)
    return old


# -- queries ---------------------------------------------------------------------------
def subtree(tree: ParameterTree, name: str) -> list[str]:
    """``name`` and every parameter below it, in the tree's order.

    >>> tree = ParameterTree([Parameter("head", "rotation"), Parameter("jaw", "rotation", parent="head"),
    ...                       Parameter("lip", "translation", parent="jaw"), Parameter("brow", "translation")])
    >>> subtree(tree, "jaw"), subtree(tree, "head")
    (['jaw', 'lip'], ['head', 'jaw', 'lip'])
    """
    tree[name]  # unknown names raise with a suggestion
    inside = {name}
    for candidate in tree.topological():       # parents before children: one pass is enough
        if tree[candidate].parent in inside:
            inside.add(candidate)
    return [p.name for p in tree if p.name in inside]


def unique_name(tree: ParameterTree, base: str = "parameter") -> str:
    """``base`` if the tree has no parameter of that name, else ``base_2``, ``base_3``, …

    >>> unique_name(ParameterTree([Parameter("parameter", "rotation")]))
    'parameter_2'
    """
    if base not in tree:
        return base
    n = 2
    while f"{base}_{n}" in tree:
        n += 1
    return f"{base}_{n}"


def renamed_parameters(tree: ParameterTree, old: str, new: str) -> list[Parameter]:
    """The tree's parameters (copies, same order) with ``old`` called ``new`` and its children following.

    Raises :class:`~engine.errors.ParameterError` for an unknown ``old``, a
    ``new`` name already taken, or a name the model format does not allow.

    >>> tree = ParameterTree([Parameter("jaw", "rotation"), Parameter("lip", "translation", parent="jaw")])
    >>> [(p.name, p.parent) for p in renamed_parameters(tree, "jaw", "jaw_open")]
    [('jaw_open', None), ('lip', 'jaw_open')]
    """
    tree[old]  # unknown names raise with a suggestion
    if new != old and new in tree:
        raise ParameterError(f"cannot rename '{old}' to '{new}': a parameter called '{new}' already exists")
    out = []
    for p in tree:
        changes = {}
        if p.name == old:
            changes["name"] = new
        if p.parent == old:
            changes["parent"] = new
        # Parameter.copy runs __post_init__ again, so an illegal new name is refused here.
        out.append(p.copy(**changes))
    return out


def moved_parameters(tree: ParameterTree, name: str, parent: str | None,
                     before: str | None = None) -> list[Parameter]:
    """The tree's parameters (copies, in order) with ``name`` moved under ``parent`` (``None``: the top).

    Placed just before its new sibling ``before``, or after the parent's last
    child when ``before`` is ``None``; its own subtree goes with it (the
    children keep their places). Raises :class:`~engine.errors.ParameterError`
    for a move into its own subtree or a ``before`` that is not a child of ``parent``.

    >>> tree = ParameterTree([Parameter("head", "rotation"), Parameter("jaw", "rotation", parent="head"),
    ...                       Parameter("lip", "translation", parent="head"), Parameter("brow", "translation")])
    >>> [p.name for p in moved_parameters(tree, "lip", "head", before="jaw")]
    ['head', 'lip', 'jaw', 'brow']
    >>> [(p.name, p.parent) for p in moved_parameters(tree, "brow", "head")][:4]
    [('head', None), ('jaw', 'head'), ('lip', 'head'), ('brow', 'head')]
    """
    tree[name]  # unknown names raise with a suggestion
    if parent is not None:
        tree[parent]
        if parent in subtree(tree, name):
            what = "the parameter itself" if parent == name else f"one of {name}'s descendants"
            raise ParameterError(f"cannot move {name} under {parent}: {parent} is {what} "
                                 "(the parent chain loops)")
    if before is not None and tree[before].parent != parent:
        raise ParameterError(f"cannot place {name} before {before}: {before} is not a child of "
                             f"{parent if parent is not None else 'the top level'}")
    parameters = [p.copy() for p in tree]
    if before == name:
        return parameters
    moved = next(p for p in parameters if p.name == name).copy(parent=parent)
    parameters = [p for p in parameters if p.name != name]
    names = [p.name for p in parameters]
    if before is not None:
        at = names.index(before)
    else:
        siblings = [i for i, p in enumerate(parameters) if p.parent == parent]
        at = siblings[-1] + 1 if siblings else names.index(parent) + 1 if parent is not None else len(names)
    parameters.insert(at, moved)
    return parameters


def same_parameter(a: Parameter, b: Parameter) -> bool:
    """Whether two parameters are equal in every attribute, bit for bit (arrays and numbers alike).

    >>> p = Parameter("jaw", "rotation", pivot=(0, 1, 2))
    >>> same_parameter(p, p.copy()), same_parameter(p, p.copy(pivot=(0, 1, 3)))
    (True, False)
    """
    return (a.name, a.kind, a.parent, a.field, a.description) == (b.name, b.kind, b.parent, b.field, b.description) \
        and _bits(a) == _bits(b)


def _bits(p: Parameter) -> bytes:
    numbers = np.array([p.minimum, p.maximum, p.default, p.degrees_per_unit], dtype=np.float64)
    return b"".join(np.ascontiguousarray(a, dtype=np.float64).tobytes()
                    for a in (numbers, p.axis, p.pivot, p.direction))


def changed_parameters(before: Sequence[Parameter], after: Sequence[Parameter]) -> list[str]:
    """Names of parameters added, removed, or with other properties between two trees (``after``'s order,
    then the removed ones); empty when only the order differs.

    >>> old = [Parameter("jaw", "rotation"), Parameter("lip", "translation")]
    >>> changed_parameters(old, [old[1], old[0].copy(maximum=2.0)])
    ['jaw']
    """
    old = {p.name: p for p in before}
    new = {p.name: p for p in after}
    changed = [name for name, p in new.items() if name not in old or not same_parameter(old[name], p)]
    return changed + [name for name in old if name not in new]
