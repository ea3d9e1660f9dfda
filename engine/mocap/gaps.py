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

The rule itself (which gaps get filled) is :func:`marker_gaps`; both
:func:`fill_gaps` and :func:`marker_gap_stats` (the counts without the
filling, for a table that follows the max-gap setting live) use it, so the
two can never disagree.
"""

from __future__ import annotations

from dataclasses import dataclass

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
    return [(int(a), int(b)) for a, b in zip(edges[0::2], edges[1::2], strict=True)]


def max_gap_frames(max_gap_ms: float, rate_hz: float) -> int:
    """The longest gap (in frames) that ``max_gap_ms`` allows at ``rate_hz``; a gap of n frames lasts n / rate.

    >>> max_gap_frames(100, 60), max_gap_frames(100, 100), max_gap_frames(0, 60)
    (6, 10, 0)
    """
    if max_gap_ms < 0:
        raise ValueError("the longest gap to fill must not be negative")
    return int(np.floor(max_gap_ms * rate_hz / 1000.0 + 1e-9))


@dataclass(frozen=True)
class MarkerGaps:
    """The fill rule applied to one marker: its gaps, those to fill, and how many frames lack a sample."""

    gaps: list[tuple[int, int]]
    """Every run of frames without a sample, ``(start, stop)``, ``stop`` exclusive."""
    fillable: list[tuple[int, int]]
    """The gaps the rule fills."""
    absent_frames: int

    @property
    def filled_frames(self) -> int:
        """Frames the rule fills."""
        return sum(b - a for a, b in self.fillable)

    def report(self) -> dict[str, int]:
        """The counts :func:`fill_gaps` reports for the marker."""
        return {"gaps": len(self.gaps), "filled_gaps": len(self.fillable), "filled_frames": self.filled_frames,
                "missing_gaps": len(self.gaps) - len(self.fillable),
                "missing_frames": self.absent_frames - self.filled_frames}


def marker_gaps(absent: np.ndarray, max_gap_frames: int) -> MarkerGaps:
    """The fill rule for one marker's (F,) mask of frames without a sample.

    A gap is filled when it lasts at most ``max_gap_frames`` frames and has a
    sample on both sides (it touches neither the first nor the last frame);
    the samples either side then always give the spline at least two points.

    >>> marker_gaps(np.array([1, 0, 1, 1, 0, 0, 1], bool), max_gap_frames=2).report()
    {'gaps': 3, 'filled_gaps': 1, 'filled_frames': 2, 'missing_gaps': 2, 'missing_frames': 2}
    """
    absent = np.asarray(absent, bool)
    n_frames = len(absent)
    gaps = find_gaps(absent) if absent.any() else []
    fillable = [(a, b) for a, b in gaps if a > 0 and b < n_frames and b - a <= max_gap_frames]
    return MarkerGaps(gaps, fillable, int(absent.sum()))


def marker_gap_stats(positions: np.ndarray, max_gap_frames: int) -> list[dict[str, int]]:
    """Per marker of (F, M, 3) positions (NaN = no sample): what :func:`fill_gaps` will report, and two more.

    Keys: ``gaps``, ``filled_gaps``, ``filled_frames``, ``missing_gaps``,
    ``missing_frames`` (equal to :func:`fill_gaps`'s report), ``absent_frames``
    (frames without a sample in the file) and ``longest_gap`` (frames).
    Counting on the masks alone, without fitting the splines, is quick enough
    to follow a max-gap setting as the user moves it.

    >>> p = np.zeros((10, 1, 3)); p[2:4] = np.nan; p[6:9] = np.nan
    >>> stats = marker_gap_stats(p, 2)[0]
    >>> stats["filled_frames"], stats["missing_frames"], stats["longest_gap"]
    (2, 3, 3)
    """
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 3 or positions.shape[2] != 3:
        raise ValueError(f"positions must be (frames, markers, 3), not {positions.shape}")
    absent = np.any(~np.isfinite(positions), axis=2)
    out = []
    for m in range(positions.shape[1]):
        rule = marker_gaps(absent[:, m], max_gap_frames)
        out.append({**rule.report(), "absent_frames": rule.absent_frames,
                    "longest_gap": max((b - a for a, b in rule.gaps), default=0)})
    return out


def fill_gaps(positions: np.ndarray,
              max_gap_frames: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict[int, dict[str, int]]]:
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
    report: dict[int, dict[str, int]] = {}
    for m in range(n_markers):
        rule = marker_gaps(absent[:, m], max_gap_frames)
        if rule.fillable:
            at = np.concatenate([np.arange(a, b) for a, b in rule.fillable])
            valid = np.flatnonzero(~absent[:, m] & _near(at, n_frames, max(SPLINE_REACH, 2 * max_gap_frames)))
            from scipy.interpolate import CubicSpline  # scipy.interpolate takes a second to import: only here

            spline = CubicSpline(valid, filled[valid, m], axis=0, bc_type="not-a-knot")
            filled[at, m] = spline(at)
            was_filled[at, m] = True
        report[m] = rule.report()
    missing = absent & ~was_filled
    return filled, was_filled, missing, report


def _near(frames: np.ndarray, n_frames: int, reach: int) -> np.ndarray:
    """(F,) mask of the frames within ``reach`` of any of ``frames``."""
    step = np.zeros(n_frames + 1, np.int64)
    np.add.at(step, np.clip(frames - reach, 0, n_frames), 1)
    np.add.at(step, np.clip(frames + reach + 1, 0, n_frames), -1)
    return np.cumsum(step[:-1]) > 0
