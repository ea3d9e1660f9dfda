"""The common form of marker data as a file holds it: :class:`Recording`, and the unit and gap helpers.

Every marker-file reader (:mod:`engine.mocap.qtm_tsv`, :mod:`engine.mocap.c3d_file`,
:mod:`engine.mocap.trc`, :mod:`engine.mocap.csv_table`) returns a
:class:`Recording`: the file's own marker labels, positions in millimetres with
NaN wherever the file has no sample, and the frame rate as the file states it.

>>> import numpy as np
>>> rec = Recording(["a"], np.zeros((5, 1, 3)), 60.0, "take1.tsv", "tsv")
>>> rec.n_frames, unit_scale("cm", Path("take1.trc"))
(5, 10.0)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.mocap.errors import MarkerFileError

UNIT_SCALE = {"mm": 1.0, "cm": 10.0, "m": 1000.0}
"""Factor from a file's length unit to millimetres."""


@dataclass
class Recording:
    """Marker trajectories as a file holds them, converted to mm.

    ``positions`` is (F, M, 3) in mm with NaN where the file has no sample;
    ``labels`` are the file's own marker names; ``start_ms`` is the time the
    file gives its first frame (0 when it gives none); ``events`` are named
    instants (QTM ``EVENT`` lines) as ``(name, time_ms)`` on the recording's
    clock, whose 0 is the first frame.
    """

    labels: list[str]
    positions: np.ndarray
    rate_hz: float
    source: str
    format: str
    units: str = "mm"
    start_ms: float = 0.0
    events: list[tuple[str, float]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    up_hint: str | None = None
    """The up axis the file names, if any (C3D ``POINT:Y_SCREEN``, e.g. ``'+Z'``)."""

    @property
    def n_frames(self) -> int:
        return int(self.positions.shape[0])


UNIT_WORDS = {"millimeters": 1.0, "millimetres": 1.0, "centimeters": 10.0, "centimetres": 10.0,
              "meters": 1000.0, "metres": 1000.0}
"""Units written out; a writer may cut them to a fixed width (``'mete'`` in some C3D files)."""


MIN_RATE_HZ = 1e-3
MAX_RATE_HZ = 1e6
"""Frame rates a marker file may state: a frame every 1000 s up to a million a second (cameras reach ~10 kHz)."""


def check_rate(rate: float, what: str, path: Path, line: int | None = None) -> float:
    """``rate`` (frames per second) if it is one; else :class:`MarkerFileError` naming ``what``, file and line."""
    if not (np.isfinite(rate) and MIN_RATE_HZ <= rate <= MAX_RATE_HZ):
        raise MarkerFileError(f"{what} must be a frame rate from {MIN_RATE_HZ:g} to {MAX_RATE_HZ:g} frames per "
                              f"second, not {rate:g}", file=path, line=line)
    return float(rate)


def unit_scale(unit: str, path: Path, line: int | None = None) -> float:
    """Millimetres per file unit for ``mm``, ``cm`` or ``m`` (any case; NUL padding and spelled-out units too)."""
    text = unit.replace("\0", " ").strip().lower()
    scale = UNIT_SCALE.get(text)
    if scale is None and len(text) >= 3:
        scale = next((v for word, v in UNIT_WORDS.items() if word.startswith(text)), None)
    if scale is None:
        raise MarkerFileError(f"unknown length unit '{unit.strip()}' (use mm, cm or m)", file=path, line=line)
    return scale


def zero_triplets_to_nan(positions: np.ndarray) -> np.ndarray:
    """QTM and some C3D writers store a missing sample as exactly (0, 0, 0): make those NaN (in place)."""
    gap = np.all(positions == 0.0, axis=-1)
    positions[gap] = np.nan
    return positions


def scaled_to_mm(values: np.ndarray, scale: float) -> np.ndarray:
    """``values · scale`` where a value too large for millimetres (1e308 m) becomes inf, not a numpy warning."""
    with np.errstate(over="ignore", invalid="ignore"):
        return values * scale


MAX_COORDINATE_MM = 1e6
"""The largest marker coordinate a file may hold (1 km from the origin): capture volumes are metres across;
a coordinate beyond it (or infinite) is a damaged export, and 1e308 made the gap filler's spline overflow."""


def check_coordinates(positions: np.ndarray, labels: list[str], path: Path,
                      line_of_frame: Callable[[int], int] | None = None, gap: str = "as NaN") -> np.ndarray:
    """``positions`` (F, M, 3) in mm if every coordinate is finite and within :data:`MAX_COORDINATE_MM`, or NaN.

    NaN is a missing sample (a gap); an infinite coordinate, or one beyond the
    bound, is no measurement: :class:`MarkerFileError` naming the marker, the
    frame and (with ``line_of_frame``) the line it is on. ``gap`` says how the
    format writes a missing sample, for the message (``"as 0 0 0"``).
    """
    with np.errstate(invalid="ignore"):
        bad = np.abs(positions) > MAX_COORDINATE_MM          # inf too; NaN compares False
    if not bad.any():
        return positions
    frame, marker, axis = (int(i) for i in np.argwhere(bad)[0])
    value = float(positions[frame, marker, axis])
    raise MarkerFileError(f"marker '{labels[marker]}' {'XYZ'[axis]} in frame {frame + 1} is {value:g} mm: not a "
                          f"position (a coordinate must be finite and within ±{MAX_COORDINATE_MM:g} mm; a missing "
                          f"sample is written {gap})", file=path,
                          line=line_of_frame(frame) if line_of_frame is not None else None)


def nan_partial_samples(positions: np.ndarray) -> np.ndarray:
    """A sample with any coordinate missing is missing altogether (in place)."""
    bad = np.any(~np.isfinite(positions), axis=-1)
    positions[bad] = np.nan
    return positions
