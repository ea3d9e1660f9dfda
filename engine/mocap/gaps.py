"""Missing marker samples: find the gaps, fill the short ones, report what was filled and what is left.

A gap is a run of consecutive frames in which one marker has no sample. A
gap of at most ``max_gap_frames`` frames with data on both sides is filled
by a cubic spline through that marker's samples around it (an
interpolating, not-a-knot spline per coordinate through every sample within
:data:`SPLINE_REACH` frames of a gap to fill, or twice the gap limit if that
is more; farther samples would change the fill by less than 1e-4 of the
motion); longer gaps, and gaps that touch the
first or last frame (nothing to interpolate towards), stay missing (NaN)
and are excluded from analysis.

>>> import numpy as np
>>> x = np.arange(10.0)[:, None, None] * np.ones((1, 1, 3))
>>> x[3:5] = np.nan                     # 2-frame gap: filled
>>> filled, was_filled, missing, report = fill_gaps(x, max_gap_frames=3)
>>> np.allclose(filled[3:5, 0, 0], [3, 4]), int(was_filled.sum()), int(missing.sum())
(True, 2, 0)
>>> report[0]
{'gaps': 1, 'filled_gaps': 1, 'filled_frames': 2, 'missing_gaps': 0, 'missing_frames': 0}
"""

from __future__ import annotations

import numpy as np


SPLINE_REACH = 12
"""Frames either side of a gap whose samples carry the spline."""


def find_gaps(missing: np.ndarray) -> list[tuple[int, int]]:
    """Runs of True in a 1-D mask as ``(start, stop)`` frame ranges, ``stop`` exclusive.

    >>> find_gaps(np.array([0, 1, 1, 0, 1], bool))
    [(1, 3), (4, 5)]
    """
    m = np.concatenate([[False], np.asarray(missing, bool), [False]])
    edges = np.flatnonzero(np.diff(m.astype(np.int8)))
    return [(int(a), int(b)) for a, b in zip(edges[0::2], edges[1::2])]


def max_gap_frames(max_gap_ms: float, rate_hz: float) -> int:
    """The longest gap (in frames) that ``max_gap_ms`` allows at ``rate_hz``; a gap of n frames lasts n / rate.

    >>> max_gap_frames(100, 60), max_gap_frames(100, 100), max_gap_frames(0, 60)
    (6, 10, 0)
    """
    if max_gap_ms < 0:
        raise ValueError("the longest gap to fill must not be negative")
    return int(np.floor(max_gap_ms * rate_hz / 1000.0 + 1e-9))


def fill_gaps(positions: np.ndarray, max_gap_frames: int):
    """Fill short gaps in (F, M, 3) positions (NaN where missing).

    Returns ``(filled, was_filled, missing, report)``: the positions with the
    short gaps filled, an (F, M) mask of the filled samples, an (F, M) mask of
    the samples still missing, and per marker index a dict with ``gaps``
    (count in the input), ``filled_gaps``, ``filled_frames``,
    ``missing_gaps`` and ``missing_frames`` (left missing).
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[2] != 3:
        raise ValueError(f"positions must be (frames, markers, 3), not {positions.shape}")
    n_frames, n_markers = positions.shape[:2]
    filled = positions.copy()
    absent = np.any(~np.isfinite(positions), axis=2)
    filled[absent] = np.nan
    was_filled = np.zeros((n_frames, n_markers), bool)
    report = {}
    for m in range(n_markers):
        gaps = find_gaps(absent[:, m]) if absent[:, m].any() else []
        fillable = [(a, b) for a, b in gaps if 0 < a and b < n_frames and b - a <= max_gap_frames]
        if fillable:
            at = np.concatenate([np.arange(a, b) for a, b in fillable])
            valid = np.flatnonzero(~absent[:, m] & _near(at, n_frames, max(SPLINE_REACH, 2 * max_gap_frames)))
            if len(valid) >= 2:
                from scipy.interpolate import CubicSpline  # scipy.interpolate takes a second to import: only here

                spline = CubicSpline(valid, filled[valid, m], axis=0, bc_type="not-a-knot")
                filled[at, m] = spline(at)
                was_filled[at, m] = True
            else:  # one sample cannot carry a curve: nothing is filled
                fillable = []
        n_filled = sum(b - a for a, b in fillable)
        n_missing = int(absent[:, m].sum()) - n_filled
        report[m] = {"gaps": len(gaps), "filled_gaps": len(fillable), "filled_frames": n_filled,
                     "missing_gaps": len(gaps) - len(fillable), "missing_frames": n_missing}
    missing = absent & ~was_filled
    return filled, was_filled, missing, report


def _near(frames: np.ndarray, n_frames: int, reach: int) -> np.ndarray:
    """(F,) mask of the frames within ``reach`` of any of ``frames``."""
    step = np.zeros(n_frames + 1, np.int64)
    np.add.at(step, np.clip(frames - reach, 0, n_frames), 1)
    np.add.at(step, np.clip(frames + reach + 1, 0, n_frames), -1)
    return np.cumsum(step[:-1]) > 0
