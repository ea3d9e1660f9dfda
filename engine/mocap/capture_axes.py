"""Which way is up in a recording, and turning it to the toolkit's axes (+Y up, +Z facing, +X the subject's left).

Capture systems differ: C3D data are usually Z-up, OpenSim's TRC files
Y-up, and the facing direction is whatever the lab's calibration made it.
PCA names its components and draws its plots in the toolkit's axes, so the
markers are turned before anything else. The file's axes are found from the
MPEG-4 names: "up" runs from the mouth and chin (2.x, 8.x) to the eyes,
brows and nose (3.x, 4.x, 9.x, 10.x, 11.x); "left" from the right to the
left member of symmetric pairs (8.3/8.4 lip corners, 4.1/4.2 brows …);
facing is left × up. Each is snapped to the nearest file axis, so a head
tilted by less than 45° does not change the result. The user may give the
up axis (``--up Z``); the facing direction then still comes from the markers
where they tell it, else from the smallest turn that brings up to +Y.

>>> import numpy as np
>>> names = ["2.1", "9.3", "8.3", "8.4"]
>>> y_up = np.array([[[0, 0, 0], [0, 80, 30], [25, 50, 0], [-25, 50, 0]]], dtype=float)
>>> z_up = y_up[..., [0, 2, 1]] * [1, -1, 1]          # the same face, Z up, facing -Y
>>> axes = detect_axes(names, z_up)
>>> axes.up, axes.facing, axes.source
('+Z', '-Y', 'markers')
>>> np.allclose(axes.apply(z_up), y_up)
True
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from engine.mocap.errors import MocapError

UPPER_GROUPS = ("3.", "4.", "9.", "10.", "11.")
LOWER_GROUPS = ("2.", "8.")
LEFT_RIGHT_PAIRS = (("8.3", "8.4"), ("8.5", "8.6"), ("8.7", "8.8"), ("2.4", "2.5"), ("4.1", "4.2"),
                    ("4.3", "4.4"), ("4.5", "4.6"), ("3.1", "3.2"), ("3.3", "3.4"), ("3.5", "3.6"), ("9.1", "9.2"))
"""MPEG-4 feature points in (left, right) pairs of the subject, as the default head has them."""
AXIS_NAMES = ("X", "Y", "Z")


@dataclass
class CaptureAxes:
    """The file's up and facing axes (``'+Z'``, ``'-Y'`` …), where they came from, and the turn to apply."""

    up: str
    facing: str
    source: str
    """``markers``, ``--up`` (the up axis given, facing from the markers or the smallest turn), ``file`` (the
    up axis the file names, C3D ``POINT:Y_SCREEN``, when the markers cannot tell) or ``assumed``."""
    rotation: np.ndarray
    """(3, 3) rows: the file's left, up and facing directions; toolkit position = rotation @ file position."""

    def apply(self, positions: np.ndarray) -> np.ndarray:
        """(…, 3) file positions in the toolkit's axes (NaN stays NaN)."""
        return np.asarray(positions, dtype=float) @ self.rotation.T

    def describe(self) -> str:
        how = {"markers": "found from the markers", "--up": "up as given",
               "file": "up as the file's POINT:Y_SCREEN names it; the markers cannot tell",
               "assumed": "assumed: the markers cannot tell (no MPEG-4 names above and below the mouth)"}
        turned = "kept as they are" if np.array_equal(self.rotation, np.eye(3)) else "turned to +Y up, +Z facing"
        return f"axes: the file's {self.up} is up and {self.facing} faces forward ({how[self.source]}); {turned}"


def parse_axis(text: str) -> np.ndarray:
    """``'Z'``, ``'+z'``, ``'-Y'`` … as a unit vector."""
    t = text.strip().upper()
    sign = -1.0 if t.startswith("-") else 1.0
    name = t.lstrip("+-")
    if name not in AXIS_NAMES or len(t) - len(name) > 1:
        raise MocapError(f"'{text}' is not an axis (use X, Y, Z, -X, -Y or -Z)")
    vector = np.zeros(3)
    vector[AXIS_NAMES.index(name)] = sign
    return vector


def axis_name(vector: np.ndarray) -> str:
    k = int(np.argmax(np.abs(vector)))
    return ("+" if vector[k] > 0 else "-") + AXIS_NAMES[k]


def detect_axes(markers: Sequence[str], positions: np.ndarray, up: str | None = None,
                file_up: str | None = None) -> CaptureAxes:
    """The file's axes from MPEG-4-named markers ``(F, M, 3)``.

    ``up`` (e.g. ``'Z'``) overrides the up axis; ``file_up`` is the up axis the
    file names, used when the markers cannot tell.
    """
    mean = _mean_positions(positions)
    index = {m: k for k, m in enumerate(markers) if np.all(np.isfinite(mean[k]))}
    up_direction = _up_direction(index, mean)
    left_direction = _left_direction(index, mean)
    if up is not None:
        up_axis, source = parse_axis(up), "--up"
    elif up_direction is not None:
        up_axis, source = _snap(up_direction), "markers"
    elif file_up is not None:
        up_axis, source = parse_axis(file_up), "file"
    else:
        return CaptureAxes("+Y", "+Z", "assumed", np.eye(3))
    if left_direction is not None:
        left_axis = _snap(left_direction - np.dot(left_direction, up_axis) * up_axis, exclude=up_axis)
    else:
        left_axis = _smallest_turn_left(up_axis)
    facing_axis = np.cross(left_axis, up_axis)
    rotation = np.vstack([left_axis, up_axis, facing_axis]) + 0.0  # no -0.0 entries
    return CaptureAxes(axis_name(up_axis), axis_name(facing_axis), source, rotation)


def _mean_positions(positions: np.ndarray) -> np.ndarray:
    positions = np.asarray(positions, dtype=float)
    seen = np.isfinite(positions).all(axis=-1)
    total = np.where(seen[..., None], positions, 0.0).sum(axis=0)
    count = seen.sum(axis=0)[:, None]
    out = np.full(total.shape, np.nan)
    np.divide(total, count, out=out, where=count > 0)
    return out


def _up_direction(index: dict[str, int], mean: np.ndarray) -> np.ndarray | None:
    upper = [k for m, k in index.items() if m.startswith(UPPER_GROUPS)]
    lower = [k for m, k in index.items() if m.startswith(LOWER_GROUPS)]
    if not upper or not lower:
        return None
    direction = mean[upper].mean(axis=0) - mean[lower].mean(axis=0)
    return direction if np.linalg.norm(direction) > 0 else None


def _left_direction(index: dict[str, int], mean: np.ndarray) -> np.ndarray | None:
    pairs = [(index[a], index[b]) for a, b in LEFT_RIGHT_PAIRS if a in index and b in index]
    if not pairs:
        return None
    direction = np.mean([mean[a] - mean[b] for a, b in pairs], axis=0)
    return direction if np.linalg.norm(direction) > 0 else None


def _snap(direction: np.ndarray, exclude: np.ndarray | None = None) -> np.ndarray:
    weights = np.abs(direction).copy()
    if exclude is not None:
        weights[np.abs(exclude) > 0] = -1.0
    k = int(np.argmax(weights))
    out = np.zeros(3)
    out[k] = 1.0 if direction[k] >= 0 else -1.0
    return out


def _smallest_turn_left(up_axis: np.ndarray) -> np.ndarray:
    """The subject's left when only up is known: +X unless X is the up axis, then +Y turned like X would be."""
    if abs(up_axis[0]) > 0:
        return np.array([0.0, -up_axis[0], 0.0])
    return np.array([1.0, 0.0, 0.0])
