"""Weight edits of one influence region, each returning its exact inverse (§2.2.2's painted weights).

A :class:`WeightChange` is the one form in which changed weights travel:
the vertex indices, their weights before and after, and **NaN meaning "not
in the region"**, so that a vertex listed with weight 0 stays distinct from
one that is absent and undo can take out exactly the vertices an edit put
in. :func:`apply_weight_change` writes one into a model and returns the
change that undoes it, its "after" read back from the model, so undo is bit
for bit whatever the change believed was there.

>>> from engine.model import InfluenceRegion, Model, Parameter
>>> model = Model([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [3, 0, 1, 2])
>>> model.add_parameter(Parameter("jaw", "rotation"), InfluenceRegion([0, 1], [1.0, 0.0]))
>>> change = weight_change(model, "jaw", [1, 2], [float("nan"), 0.25])   # 1 leaves, 2 joins
>>> undo = apply_weight_change(model, "jaw", change)
>>> model.regions["jaw"].indices.tolist(), model.regions["jaw"].weights.tolist()
([0, 2], [1.0, 0.25])
>>> undo.after                                   # vertex 1 was listed at 0, vertex 2 was absent
array([ 0., nan])
>>> redo = apply_weight_change(model, "jaw", undo)
>>> model.regions["jaw"].indices.tolist(), model.regions["jaw"].weights.tolist()
([0, 1], [1.0, 0.0])
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.model import InfluenceRegion, Model


@dataclass(frozen=True, eq=False, init=False)
class WeightChange:
    """The weights of ``indices`` in one region went from ``before`` to ``after`` (NaN: not in the region).

    All three are 1-D and the same length; the constructor sorts them by
    index, refuses a vertex listed twice and weights outside [0, 1], and
    makes the arrays read-only. ``==`` compares bit for bit (NaN equal to NaN).
    """

    indices: np.ndarray
    before: np.ndarray
    after: np.ndarray

    def __init__(self, indices: npt.ArrayLike, before: npt.ArrayLike, after: npt.ArrayLike):
        indices = np.asarray(indices, dtype=np.int64).reshape(-1)
        before = np.asarray(before, dtype=np.float64).reshape(-1)
        after = np.asarray(after, dtype=np.float64).reshape(-1)
        if not indices.shape == before.shape == after.shape:
            raise UserError(f"weights: {len(indices)} vertex indices, {len(before)} weights before "
                            f"and {len(after)} after")
        for weights in (before, after):
            known = weights[~np.isnan(weights)]
            if np.any(known < 0) or np.any(known > 1):     # inf fails too
                raise UserError("weights must be numbers in [0, 1] (NaN: not in the region)")
        order = np.argsort(indices, kind="stable")
        indices, before, after = indices[order], before[order], after[order]
        if len(indices) > 1 and np.any(indices[1:] == indices[:-1]):
            raise UserError("weights: a vertex index is listed twice")
        for name, array in (("indices", indices), ("before", before), ("after", after)):
            array.setflags(write=False)
            object.__setattr__(self, name, array)

    @classmethod
    def empty(cls) -> WeightChange:
        return cls(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))

    def __len__(self) -> int:
        return len(self.indices)

    def __bool__(self) -> bool:
        return len(self.indices) > 0

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, WeightChange):
            return NotImplemented
        return (np.array_equal(self.indices, other.indices)
                and _same_bits(self.before, other.before) and _same_bits(self.after, other.after))

    def __hash__(self) -> int:
        return hash((self.indices.tobytes(), _canonical_bits(self.before), _canonical_bits(self.after)))

    def inverse(self) -> WeightChange:
        """The change back: ``after`` to ``before``."""
        return WeightChange(self.indices, self.after, self.before)

    def followed_by(self, later: WeightChange) -> WeightChange:
        """This change and then ``later`` as one: each vertex's first ``before`` and last ``after``.

        What makes one brush stroke one undo step.

        >>> a = WeightChange([1, 2], [0.0, float("nan")], [0.5, 0.5])
        >>> b = WeightChange([2, 3], [0.5, 0.25], [1.0, 0.0])
        >>> ab = a.followed_by(b)
        >>> ab.indices.tolist(), ab.before.tolist(), ab.after.tolist()
        ([1, 2, 3], [0.0, nan, 0.25], [0.5, 1.0, 0.0])
        """
        return WeightChange(*merged_changes(self, later))


class IndexedChange(Protocol):
    """Values of some vertices before and after an edit: sorted ``indices`` and ``before``/``after`` beside them."""

    @property
    def indices(self) -> np.ndarray: ...
    @property
    def before(self) -> np.ndarray: ...
    @property
    def after(self) -> np.ndarray: ...


def merged_changes(first: IndexedChange, later: IndexedChange) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(indices, before, after)`` of ``first`` followed by ``later``: every vertex either touched,
    with its value before ``first`` (or before ``later``, if only ``later`` touched it) and its last value.

    >>> a = WeightChange([1, 2], [0.0, 0.1], [0.5, 0.5])
    >>> [x.tolist() for x in merged_changes(a, WeightChange([2, 3], [0.5, 0.2], [1.0, 0.0]))]
    [[1, 2, 3], [0.0, 0.1, 0.2], [0.5, 1.0, 0.0]]
    """
    indices = np.union1d(first.indices, later.indices)
    mine = np.isin(indices, first.indices, assume_unique=True)
    theirs = np.isin(indices, later.indices, assume_unique=True)
    before = np.empty(len(indices))
    before[mine] = first.before
    before[~mine] = later.before[np.searchsorted(later.indices, indices[~mine])]
    after = np.empty(len(indices))
    after[theirs] = later.after
    after[~theirs] = first.after[np.searchsorted(first.indices, indices[~theirs])]
    return indices, before, after


def _canonical_bits(weights: np.ndarray) -> bytes:
    """The bytes of ``weights`` with every NaN the same NaN (what ``==`` compares)."""
    return np.where(np.isnan(weights), np.nan, weights).tobytes()


def _same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    nan_a, nan_b = np.isnan(a), np.isnan(b)
    return bool(np.array_equal(nan_a, nan_b) and a[~nan_a].tobytes() == b[~nan_b].tobytes())


def weights_at(region: InfluenceRegion, indices: npt.ArrayLike) -> np.ndarray:
    """The region's weight at each vertex in ``indices``; NaN where the vertex is not in the region.

    >>> weights_at(InfluenceRegion([2, 5], [0.5, 0.0]), [5, 3, 2])
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


def with_weights(region: InfluenceRegion, indices: npt.ArrayLike, weights: npt.ArrayLike) -> InfluenceRegion:
    """A new region: ``region`` with the vertices ``indices`` given ``weights`` (NaN: taken out).

    Vertices not listed keep their weight. A vertex added to a displacement
    field's region gets a zero displacement (it moves nothing until the field
    is edited); taking one with a non-zero displacement out of such a region
    is refused, because the displacement would be lost. Raises
    :class:`~engine.errors.UserError` for repeated indices or weights outside [0, 1].

    >>> r = with_weights(InfluenceRegion([2, 5], [0.5, 1.0]), [5, 7], [float("nan"), 0.25])
    >>> r.indices.tolist(), r.weights.tolist()
    ([2, 7], [0.5, 0.25])
    """
    indices = np.asarray(indices, dtype=np.int64).reshape(-1)
    weights = np.asarray(weights, dtype=float).reshape(-1)
    if indices.shape != weights.shape:
        raise UserError(f"weights: {len(indices)} vertex indices but {len(weights)} weights")
    if len(np.unique(indices)) != len(indices):
        raise UserError("weights: a vertex index is listed twice")
    keep = ~np.isin(region.indices, indices)
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
    return InfluenceRegion(new_indices, new_weights, displacements)


def weight_change(model: Model, name: str, indices: npt.ArrayLike, after: npt.ArrayLike) -> WeightChange:
    """The change giving the vertices ``indices`` of ``name``'s region the weights ``after`` (NaN: out),
    with ``before`` read from the model now."""
    model.parameters[name]                     # unknown names raise with a suggestion
    indices = np.asarray(indices, dtype=np.int64).reshape(-1)
    return WeightChange(indices, weights_at(model.regions[name], indices), after)


def apply_weight_change(model: Model, name: str, change: WeightChange) -> WeightChange:
    """Write ``change.after`` into parameter ``name``'s region; returns the change that undoes it.

    The inverse's ``after`` is read from the model before the write (not
    taken from ``change.before``), so applying it restores the region bit
    for bit: indices, weights, listed zeros, displacements. Raises
    :class:`~engine.errors.UserError`, the model untouched, when the region
    would be invalid (e.g. a vertex with a displacement taken out of a field).
    An empty change leaves the model as it is.
    """
    model.parameters[name]                     # unknown names raise with a suggestion
    if not change:
        return WeightChange.empty()
    region = model.regions[name]
    now = weights_at(region, change.indices)
    model.set_region(name, with_weights(region, change.indices, change.after))
    return WeightChange(change.indices, weights_at(model.regions[name], change.indices), now)
