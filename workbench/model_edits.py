"""Model edits the engine has no single operation for: rename, restore a tree, set some weights.

The engine edits a model one parameter at a time (``Model.add_parameter``,
``remove_parameter``, ``set_region``, ``ParameterTree.replace``). Two edits
the workbench needs change more than one parameter at once:

* **rename** changes a parameter's name, its region's key and the ``parent``
  of each of its children, keeping the tree's order;
* **undoing a removal** puts back a parameter *at its place in the order*
  and gives its children their parent back (``ParameterTree.remove`` moved
  them up to the grandparent).

Both are done by building the new tree in full (so ``ParameterTree``
validates it: unique names, parents exist, no loops, displacement fields are
leaves) and then swapping it in with :func:`restore_tree`, which validates the
model and bumps its revision.

Painting changes the weights of some vertices of one region;
:func:`with_weights` builds the new region from ``(indices, weights)``, and
:func:`weights_at` reads them back, with NaN standing for "not in the
region", so an undo can take a vertex out again as exactly as it came in.

No Qt here: these are candidates to move into the engine
(``Model.rename_parameter``, ``Model.restore_parameters``,
``InfluenceRegion.with_weights``).

>>> import engine
>>> tree = engine.ParameterTree([engine.Parameter("jaw", "rotation"),
...                              engine.Parameter("lip", "translation", parent="jaw")])
>>> [(p.name, p.parent) for p in renamed_parameters(tree, "jaw", "jaw_open")]
[('jaw_open', None), ('lip', 'jaw_open')]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np

import engine
from engine.errors import ParameterError, UserError


@dataclass(frozen=True)
class TreeSnapshot:
    """The parameters of a model in order (deep copies) and the regions named in ``regions``.

    ``regions`` holds only the regions an edit touches (sharing the arrays is
    safe: engine edits replace regions, they never write into one).
    """

    parameters: tuple[engine.Parameter, ...]
    regions: Mapping[str, engine.InfluenceRegion]

    @classmethod
    def of(cls, model: engine.Model, region_names=()) -> "TreeSnapshot":
        return cls(tuple(p.copy() for p in model.parameters),
                   {name: model.regions[name] for name in region_names})


def restore_tree(model: engine.Model, snapshot: TreeSnapshot, drop_regions=()) -> None:
    """Make ``model``'s tree the snapshot's (in its order), with its regions put back.

    Regions named in ``drop_regions`` are removed first (e.g. the old key of a
    renamed parameter). Raises :class:`engine.UserError`, leaving the model
    as it was, if the result is not a valid model.
    """
    tree = engine.ParameterTree(p.copy() for p in snapshot.parameters)
    old_tree, old_regions = model.parameters, dict(model.regions)
    regions = {k: r for k, r in model.regions.items() if k not in set(drop_regions)}
    regions.update(snapshot.regions)
    missing = [p.name for p in tree if p.name not in regions]
    extra = [k for k in regions if k not in tree]
    if missing or extra:
        raise ParameterError(f"tree and regions do not match (no region for {missing}, "
                             f"region without parameter {extra})")
    model.parameters, model.regions = tree, {p.name: regions[p.name] for p in tree}
    try:
        model.validate()
    except engine.UserError:
        model.parameters, model.regions = old_tree, old_regions
        raise
    model.changed()


def renamed_parameters(tree: engine.ParameterTree, old: str, new: str) -> list[engine.Parameter]:
    """The tree's parameters (copies, same order) with ``old`` called ``new`` and its children following.

    Raises :class:`engine.ParameterError` for an unknown ``old``, a ``new``
    name already taken, or a name the model format does not allow.
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


def subtree(tree: engine.ParameterTree, name: str) -> list[str]:
    """``name`` and every parameter below it, in the tree's order.

    >>> tree = engine.ParameterTree([engine.Parameter("head", "rotation"),
    ...                              engine.Parameter("jaw", "rotation", parent="head"),
    ...                              engine.Parameter("lip", "translation", parent="jaw"),
    ...                              engine.Parameter("brow", "translation")])
    >>> subtree(tree, "jaw"), subtree(tree, "head")
    (['jaw', 'lip'], ['head', 'jaw', 'lip'])
    """
    tree[name]  # unknown names raise with a suggestion
    inside = {name}
    for candidate in tree.topological():       # parents before children: one pass is enough
        if tree[candidate].parent in inside:
            inside.add(candidate)
    return [p.name for p in tree if p.name in inside]


def moved_parameters(tree: engine.ParameterTree, name: str, parent: str | None,
                     before: str | None = None) -> list[engine.Parameter]:
    """The tree's parameters (copies, in order) with ``name`` moved under ``parent`` (``None``: the top).

    Placed just before its new sibling ``before``, or after the parent's last
    child when ``before`` is ``None``; its own subtree goes with it (the
    children keep their places). Raises :class:`ParameterError` for a move
    into its own subtree or a ``before`` that is not a child of ``parent``.

    >>> tree = engine.ParameterTree([engine.Parameter("head", "rotation"),
    ...                              engine.Parameter("jaw", "rotation", parent="head"),
    ...                              engine.Parameter("lip", "translation", parent="head"),
    ...                              engine.Parameter("brow", "translation")])
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


def without_subtree(model: engine.Model, name: str) -> tuple[TreeSnapshot, list[str]]:
    """The tree with ``name`` and everything below it gone, and the names removed.

    Pass both to :func:`restore_tree` (the names as ``drop_regions``).
    """
    removed = subtree(model.parameters, name)
    gone = set(removed)
    return TreeSnapshot(tuple(p.copy() for p in model.parameters if p.name not in gone), {}), removed


def unique_name(tree: engine.ParameterTree, base: str = "parameter") -> str:
    """``base`` if the tree has no parameter of that name, else ``base_2``, ``base_3``, …

    >>> unique_name(engine.ParameterTree([engine.Parameter("parameter", "rotation")]))
    'parameter_2'
    """
    if base not in tree:
        return base
    n = 2
    while f"{base}_{n}" in tree:
        n += 1
    return f"{base}_{n}"


def weights_at(region: engine.InfluenceRegion, indices) -> np.ndarray:
    """The region's weight at each vertex in ``indices``; NaN where the vertex is not in the region.

    >>> weights_at(engine.InfluenceRegion([2, 5], [0.5, 0.0]), [5, 3, 2])
    array([0. , nan, 0.5])
    """
    indices = np.asarray(indices, dtype=np.int64).reshape(-1)
    out = np.full(len(indices), np.nan)
    pos = np.searchsorted(region.indices, indices)
    inside = pos < len(region.indices)
    hit = np.zeros(len(indices), dtype=bool)
    hit[inside] = region.indices[pos[inside]] == indices[inside]
    out[hit] = region.weights[pos[hit]]
    return out


def with_weights(region: engine.InfluenceRegion, indices, weights) -> engine.InfluenceRegion:
    """A new region: ``region`` with the vertices ``indices`` given ``weights`` (NaN: taken out).

    Vertices not listed keep their weight. A vertex added to a displacement
    field's region gets a zero displacement (it moves nothing until the field
    is edited); taking one with a non-zero displacement out of such a region
    is refused, because the displacement would be lost. Raises :class:`engine.UserError` for repeated
    indices or weights outside [0, 1].

    >>> r = with_weights(engine.InfluenceRegion([2, 5], [0.5, 1.0]), [5, 7], [np.nan, 0.25])
    >>> r.indices.tolist(), r.weights.tolist()
    ([2, 7], [0.5, 0.25])
    """
    indices = np.asarray(indices, dtype=np.int64).reshape(-1)
    weights = np.asarray(weights, dtype=float).reshape(-1)
    if indices.shape != weights.shape:
        raise UserError(f"weights: {len(indices)} vertex indices but {len(weights)} weights")
    if len(np.unique(indices)) != len(indices):
        raise UserError("weights: a vertex index is listed twice")
    listed = np.isin(region.indices, indices)
    keep = ~listed
    member = ~np.isnan(weights)
    new_indices = np.concatenate([region.indices[keep], indices[member]])
    new_weights = np.concatenate([region.weights[keep], weights[member]])
    displacements = None
    if region.displacements is not None:
        was = ~np.isnan(weights_at(region, indices))
        disp = np.zeros((len(indices), 3))
        disp[was] = region.displacements[np.searchsorted(region.indices, indices[was])]
        # Taking a vertex out is fine only if nothing is lost: its displacement is the
        # zero it would get back if it were added again (all bits zero, so not -0.0).
        if np.any(~member & was & disp.view(np.uint64).any(axis=1)):
            raise UserError("weights: a vertex with a displacement cannot be taken out of a displacement "
                            "field's region (the displacement would be lost); give it weight 0 instead")
        displacements = np.concatenate([region.displacements[keep], disp[member]])
    return engine.InfluenceRegion(new_indices, new_weights, displacements)
