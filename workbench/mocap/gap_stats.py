"""Gap statistics per marker before import: what the engine's gap filling will fill and what it will leave.

The rule is the engine's (:mod:`engine.mocap.gaps`): a gap of at most
``max_gap_frames`` frames with samples on both sides is filled, longer gaps
and gaps touching the first or last frame stay missing (excluded from
analysis). Counting on the masks alone, without fitting the splines, keeps
the table live while the user moves the max-gap setting; the numbers equal
the ``report["gaps"]`` of the session the import then builds.

>>> import numpy as np
>>> p = np.zeros((10, 1, 3)); p[2:4] = np.nan; p[6:9] = np.nan
>>> marker_gap_stats(p, 2)[0]["filled_frames"], marker_gap_stats(p, 2)[0]["missing_frames"]
(2, 3)
"""

from __future__ import annotations

import numpy as np

from engine.mocap.gaps import find_gaps


def marker_gap_stats(positions: np.ndarray, max_gap_frames: int) -> list[dict]:
    """Per marker of (F, M, 3) positions (NaN = no sample): the engine report's counts plus two more.

    Keys: ``gaps``, ``filled_gaps``, ``filled_frames``, ``missing_gaps``,
    ``missing_frames`` (as :func:`engine.mocap.gaps.fill_gaps` reports them),
    ``absent_frames`` (frames without a sample in the file) and
    ``longest_gap`` (frames).
    """
    positions = np.asarray(positions, dtype=float)
    n_frames = positions.shape[0]
    absent = np.any(~np.isfinite(positions), axis=2)
    out = []
    for m in range(positions.shape[1]):
        gaps = find_gaps(absent[:, m]) if absent[:, m].any() else []
        fillable = [(a, b) for a, b in gaps if 0 < a and b < n_frames and b - a <= max_gap_frames]
        filled = sum(b - a for a, b in fillable)
        total = int(absent[:, m].sum())
        out.append({"gaps": len(gaps), "filled_gaps": len(fillable), "filled_frames": filled,
                    "missing_gaps": len(gaps) - len(fillable), "missing_frames": total - filled,
                    "absent_frames": total, "longest_gap": max((b - a for a, b in gaps), default=0)})
    return out
