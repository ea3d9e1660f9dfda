"""From an engine :class:`~engine.painting.Change` on dense weights to an undo command on the model.

The painting engine works on dense arrays (0 outside the region); the
model's regions are sparse, and :class:`~workbench.undo_commands.WeightsChangedCommand`
says "not in the region" with NaN. :func:`weights_command` translates: a
vertex painted down to 0 leaves the region (unless it carries a displacement
of a field translation, which would be lost — it then stays listed at 0), a
vertex painted up from outside joins it. ``before`` is read from the model,
so undo puts back exactly what the file had, listed zeros included.

>>> change = Change.between(dense.weights, invert_weights(ctx, dense.weights))   # doctest: +SKIP
>>> document.push(weights_command(document, "jaw_open", change, "Invert weights of jaw_open"))  # doctest: +SKIP
"""

from __future__ import annotations

import numpy as np

from engine.painting import Change

from ..undo_commands import WeightsChangedCommand


def model_weights(region, indices: np.ndarray, after: np.ndarray) -> np.ndarray:
    """``after`` with NaN ("leave the region") where a weight is 0 and no displacement would be lost.

    >>> import engine
    >>> model_weights(engine.InfluenceRegion([1, 2], [0.5, 0.5]), np.array([1, 3]), np.array([0.0, 0.2]))
    array([nan, 0.2])
    """
    out = np.asarray(after, dtype=float).copy()
    zero = out == 0.0
    if region.displacements is not None and zero.any():
        pos = np.searchsorted(region.indices, indices)
        inside = pos < len(region.indices)
        inside[inside] = region.indices[pos[inside]] == indices[inside]
        moving = np.zeros(len(indices), dtype=bool)
        moving[inside] = region.displacements[pos[inside]].view(np.uint64).any(axis=1)
        zero &= ~moving
    out[zero] = np.nan
    return out


def weights_command(document, name: str, change: Change, text: str) -> WeightsChangedCommand:
    """An undo command writing ``change.after`` into parameter ``name``'s region (not yet applied)."""
    region = document.model.regions[name]
    after = model_weights(region, change.indices, change.after)
    return WeightsChangedCommand(document, name, change.indices, after, text=text)
