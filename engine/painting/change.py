"""What a paint operation changed in dense weights, and how that becomes a change of the model.

A :class:`Change` holds the vertex indices an operation touched with their
dense weights before and after (0 outside the region), so a tool can undo it
exactly and recolour only those vertices. :func:`weight_change_from_dense`
turns one into the model's :class:`~engine.model.weight_changes.WeightChange`
(NaN: not in the region), the one form weights cross into an undo stack in.

>>> import numpy as np
>>> w = np.zeros(4)
>>> change = Change.between(w, np.array([0.0, 0.5, 0.25, 0.0]))
>>> change.indices, change.after
(array([1, 2]), array([0.5 , 0.25]))
>>> change.redo(w); w
array([0.  , 0.5 , 0.25, 0.  ])
>>> change.undo(w); w
array([0., 0., 0., 0.])
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.errors import UserError
from engine.model.model import Model
from engine.model.weight_changes import WeightChange, merged_changes, weight_change


@dataclass(frozen=True)
class Change:
    """Dense weights of ``indices`` went from ``before`` to ``after`` (all 1-D, same length, indices sorted)."""

    indices: np.ndarray
    before: np.ndarray
    after: np.ndarray

    @classmethod
    def empty(cls) -> Change:
        return cls(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))

    @classmethod
    def between(cls, old: np.ndarray, new: np.ndarray) -> Change:
        """The change from dense array ``old`` to ``new`` (only entries whose bits differ)."""
        old, new = np.asarray(old, dtype=float), np.asarray(new, dtype=float)
        if old.shape != new.shape:
            raise UserError(f"weights of {old.shape[0]} and {new.shape[0]} vertices cannot be compared")
        idx = np.flatnonzero(old.view(np.uint64) != new.view(np.uint64))
        return cls(idx, old[idx].copy(), new[idx].copy())

    def __len__(self) -> int:
        return len(self.indices)

    def __bool__(self) -> bool:
        return len(self.indices) > 0

    def redo(self, weights: np.ndarray) -> None:
        """Write ``after`` into ``weights`` (in place)."""
        weights[self.indices] = self.after

    def undo(self, weights: np.ndarray) -> None:
        """Write ``before`` into ``weights`` (in place): bit-for-bit the state before the change."""
        weights[self.indices] = self.before

    def inverse(self) -> Change:
        """The change back: ``after`` to ``before``."""
        return Change(self.indices, self.after, self.before)

    def followed_by(self, later: Change) -> Change:
        """This change and then ``later`` as one: each vertex's first ``before`` and last ``after``.

        >>> a = Change(np.array([1, 2]), np.array([0.0, 0.0]), np.array([0.5, 0.5]))
        >>> b = Change(np.array([2, 3]), np.array([0.5, 0.0]), np.array([1.0, 0.25]))
        >>> ab = a.followed_by(b)
        >>> ab.indices.tolist(), ab.before.tolist(), ab.after.tolist()
        ([1, 2, 3], [0.0, 0.0, 0.0], [0.5, 1.0, 0.25])
        """
        if not self:
            return later
        if not later:
            return self
        return Change(*merged_changes(self, later))


def weight_change_from_dense(model: Model, name: str, change: Change) -> WeightChange:
    """The change of parameter ``name``'s region that a dense painting ``change`` stands for.

    A vertex painted down to 0 leaves the region, unless it carries a
    non-zero displacement of a field translation (it would be lost: it stays
    listed at 0); a vertex painted up from outside joins it. ``before`` is
    read from the model, so undo puts back exactly what it had, listed zeros
    included. Apply the result with
    :func:`~engine.model.weight_changes.apply_weight_change`.

    >>> from engine.model import InfluenceRegion, Model, Parameter
    >>> model = Model([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], [4, 0, 1, 3, 2])
    >>> model.add_parameter(Parameter("jaw", "rotation"), InfluenceRegion([1, 2], [0.5, 0.5]))
    >>> dense = Change(np.array([1, 3]), np.array([0.5, 0.0]), np.array([0.0, 0.2]))
    >>> change = weight_change_from_dense(model, "jaw", dense)
    >>> change.before, change.after
    (array([0.5, nan]), array([nan, 0.2]))
    """
    model.parameters[name]                     # unknown names raise with a suggestion
    region = model.regions[name]
    indices = np.asarray(change.indices, dtype=np.int64)
    after = np.asarray(change.after, dtype=float).copy()
    zero = after == 0.0
    if region.displacements is not None and zero.any():
        pos = np.searchsorted(region.indices, indices)
        inside = pos < len(region.indices)
        inside[inside] = region.indices[pos[inside]] == indices[inside]
        moving = np.zeros(len(indices), dtype=bool)
        moving[inside] = region.displacements[pos[inside]].view(np.uint64).any(axis=1)
        zero &= ~moving
    after[zero] = np.nan
    return weight_change(model, name, indices, after)
