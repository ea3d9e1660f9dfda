"""What a paint operation changed, and one mouse drag gathered into one undo step.

A :class:`Change` holds the vertex indices an operation touched with their
weights before and after, so the workbench can undo and redo it exactly and
recolour only those vertices. A :class:`Stroke` applies the dabs of one drag
to a dense weight array as they come and hands back one combined change.

>>> import numpy as np
>>> w = np.zeros(5)
>>> stroke = Stroke(w)
>>> _ = stroke.apply(Change.between(w, np.array([0.0, 0.5, 0.5, 0.0, 0.0])))
>>> _ = stroke.apply(Change.between(w, np.array([0.0, 0.5, 1.0, 0.25, 0.0])))
>>> step = stroke.finish()
>>> step.indices, step.before, step.after
(array([1, 2, 3]), array([0., 0., 0.]), array([0.5 , 1.  , 0.25]))
>>> step.undo(w); w
array([0., 0., 0., 0., 0.])
>>> step.redo(w); w
array([0.  , 0.5 , 1.  , 0.25, 0.  ])
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.errors import UserError


@dataclass(frozen=True)
class Change:
    """Weights of ``indices`` went from ``before`` to ``after`` (all 1-D, same length, indices sorted)."""

    indices: np.ndarray
    before: np.ndarray
    after: np.ndarray

    @classmethod
    def empty(cls) -> "Change":
        return cls(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))

    @classmethod
    def between(cls, old: np.ndarray, new: np.ndarray) -> "Change":
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


class Stroke:
    """One mouse drag: dabs applied to ``weights`` in place, gathered into one :class:`Change`.

    ``weights`` is the dense float array being painted (length N); the
    stroke keeps a copy of it as it was when the stroke began, so
    :meth:`finish` returns exactly the vertices whose bits differ with their
    original and final values (one undo step).
    """

    def __init__(self, weights: np.ndarray):
        if not isinstance(weights, np.ndarray) or weights.ndim != 1 or weights.dtype != np.float64:
            raise UserError("a stroke paints a 1-D float64 weight array (one weight per vertex)")
        self.weights = weights
        self._start = weights.copy()
        self._touched = np.zeros(len(weights), dtype=bool)
        self.dabs = 0

    def apply(self, change: Change) -> Change:
        """Write one change into the weights and remember what it touched; returns it."""
        change.redo(self.weights)
        self._touched[change.indices] = True
        self.dabs += 1
        return change

    def dab(self, ctx, brush, point, view_direction=None, **options) -> Change:
        """Compute a brush dab (:func:`~engine.painting.brush.compute_dab`) on the current weights and apply it."""
        from engine.painting.brush import compute_dab
        return self.apply(compute_dab(ctx, self.weights, brush, point, view_direction, **options))

    def finish(self) -> Change:
        """The whole stroke as one change (vertices back at their original value are left out)."""
        idx = np.flatnonzero(self._touched)
        differ = self._start[idx].view(np.uint64) != self.weights[idx].view(np.uint64)
        idx = idx[differ]
        return Change(idx, self._start[idx].copy(), self.weights[idx].copy())
