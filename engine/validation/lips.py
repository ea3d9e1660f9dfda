"""The lips seen against the lips the engine meant: per-frame aperture, correlation, closures.

The engine's intended lip gap is the distance between its inner lip midpoints, MPEG-4
feature points 2.2 and 2.3, in mm (DESIGN.md's landmarks table). The pixels give the
distance between the 68-point scheme's inner lip midpoints (62, 66) over the inter-ocular
distance. The two are compared at the video's frame times: Pearson's r over the frames
where a face was found, and every intended closure (a run of frames with a gap of at most
:data:`CLOSED_GAP_MM`, a bilabial /p b m/) counts as seen when the pixels show closed lips
(:data:`engine.validation.measures.CLOSED_APERTURE`) within a frame of it.

>>> import numpy as np
>>> intended = LipTrack(np.array([0.0, 100, 200, 300]), np.array([2.6, 0.3, 0.3, 9.0]))
>>> seen = np.array([0.05, 0.01, 0.02, 0.20])
>>> check = compare_lips(seen, np.array([0.0, 100, 200, 300]), intended)
>>> round(check.r, 3), check.closures_intended, check.closures_seen
(0.996, 1, 1)
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.formats.csv_tables import read_table
from engine.model import Model
from engine.model.vertex_subset import model_at_landmarks
from engine.validation.measures import CLOSED_APERTURE

UPPER, LOWER = "2.2", "2.3"
MAX_COORDINATE_MM = 1e6
CLOSED_GAP_MM = 1.0
"""An intended gap of at most this is a closure (the default head: 2.6 mm at rest, 0.2–0.4 mm at /p/)."""


@dataclass(frozen=True)
class LipTrack:
    """The engine's lip gap (mm) at ``times`` (ms, rising)."""

    times: np.ndarray
    gaps: np.ndarray

    def at(self, times: np.ndarray) -> np.ndarray:
        return np.interp(times, self.times, self.gaps)


@dataclass(frozen=True)
class LipCheck:
    """What the pixels say of the lips of one video."""

    frames: int
    r: float | None
    closures_intended: int
    closures_seen: int
    aperture_min: float | None
    aperture_max: float | None


def compare_lips(aperture: np.ndarray, times: np.ndarray, intended: LipTrack | None) -> LipCheck:
    """The check of a video's per-frame ``aperture`` (NaN where no face) at ``times`` (ms)."""
    aperture = np.asarray(aperture, dtype=float)
    found = np.isfinite(aperture)
    low = float(aperture[found].min()) if found.any() else None
    high = float(aperture[found].max()) if found.any() else None
    if intended is None or not found.any():
        return LipCheck(len(aperture), None, 0, 0, low, high)
    gaps = intended.at(np.asarray(times, dtype=float))
    r = None
    if found.sum() >= 3 and np.std(aperture[found]) > 0 and np.std(gaps[found]) > 0:
        r = float(np.corrcoef(aperture[found], gaps[found])[0, 1])
    closed = gaps <= CLOSED_GAP_MM
    runs = _runs(closed)
    seen = 0
    for start, end in runs:
        window = aperture[max(0, start - 1):end + 1]
        window = window[np.isfinite(window)]
        seen += bool(window.size and window.min() <= CLOSED_APERTURE)
    return LipCheck(len(aperture), r, len(runs), seen, low, high)


def lip_track(model: Model, times: np.ndarray, values: np.ndarray) -> LipTrack:
    """The intended lip gap of ``model`` at ``values`` (frames × parameters, tree order) at ``times``."""
    if UPPER not in model.landmarks or LOWER not in model.landmarks:
        raise UserError(f"the model names no inner lip landmarks {UPPER} and {LOWER}")
    deformer = model_at_landmarks(model, [UPPER, LOWER]).deformer()   # the two lips alone, moved exactly
    gaps = [float(np.linalg.norm(np.subtract(*deformer.deform(row)))) for row in values]
    return LipTrack(np.asarray(times, dtype=float), np.asarray(gaps))


def read_landmarks_track(path: str | Path) -> LipTrack:
    """The intended lip gap from a landmarks table (``say --landmarks``: ``frame,time_ms,<id>_x,…``)."""
    header, rows = read_table(path, what="landmarks table")
    needed = ["time_ms"] + [f"{point}_{axis}" for point in (UPPER, LOWER) for axis in "xyz"]
    if any(name not in header for name in needed):
        raise UserError(f"not a landmarks table: its header must have {', '.join(needed)}", file=path, line=1)
    times: list[float] = []
    gaps: list[float] = []
    for line, row in rows:
        try:
            t, *xyz = (float(row[name]) for name in needed)
        except ValueError:
            raise UserError("a row with a missing or non-numeric value", file=path, line=line) from None
        if not all(np.isfinite([t, *xyz])) or (times and t < times[-1]):
            raise UserError("times must be finite and must not go back; coordinates finite", file=path, line=line)
        if max(abs(c) for c in xyz) > MAX_COORDINATE_MM:
            raise UserError(f"a coordinate beyond ±{MAX_COORDINATE_MM:g} mm: not a face's landmark", file=path,
                            line=line)
        times.append(t)
        gaps.append(float(np.linalg.norm(np.subtract(xyz[:3], xyz[3:]))))
    if not times:
        raise UserError("the landmarks table has no rows", file=path)
    return LipTrack(np.array(times), np.array(gaps))


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(start, end) of each run of True in ``mask``, end exclusive."""
    edges = np.diff(np.concatenate([[0], mask.astype(int), [0]]))
    return list(zip(np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist(), strict=True))
