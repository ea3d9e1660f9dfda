"""A capture take onto a model's parameters: mapping tables, angles, clamping, what was lost.

:func:`retarget` returns the values of every parameter the take drives, at
the take's own frames, clamped to each parameter's range, with a report of
what was clamped and warnings for what the model or the mapping lacks.
:func:`resample` puts them on an even frame grid for a video or tracks table.

>>> import numpy as np
>>> from engine import load_model
>>> from engine.capture.stream import CaptureStream
>>> take = CaptureStream("t.csv", "arkit", np.array([0.0, 33.3]), {"jawOpen": np.array([0.0, 1.0]),
...                      "head_turn_rad": np.array([0.0, np.radians(10)])})
>>> result = retarget(take, load_model())
>>> result.parameters
['head_turn', 'jaw_open']
>>> np.round(result.values[1], 4).tolist()
[0.1745, 1.0]
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from engine.capture import mapping_tables as tables
from engine.capture.stream import ROTATION_AXES, CaptureStream
from engine.model.model import Model

LOST_THRESHOLD = 0.1
"""A lost channel is warned about when it ever exceeds this (blendshape 0–1, or AU 0–5 / 5)."""


@dataclass
class Clamped:
    """Frames where a parameter's mapped value left its range."""

    frames: int
    lowest: float
    highest: float


@dataclass
class Retargeted:
    """Values of the driven parameters (model tree order) at the take's frames."""

    times_ms: np.ndarray
    parameters: list[str]
    values: np.ndarray
    """(F, P), clamped to each parameter's range."""
    clamped: dict[str, Clamped] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)


def retarget(stream: CaptureStream, model: Model) -> Retargeted:
    """Map ``stream`` onto ``model`` (see ``docs/capture-streams.md`` for the tables)."""
    channels = dict(stream.channels)
    if stream.format in ("arkit", "mediapipe"):
        table, lost, scale = tables.ARKIT_TABLE, tables.ARKIT_LOST, 1.0
        _eye_angles_from_shapes(channels)
    else:
        table, lost, scale = tables.OPENFACE_TABLE, tables.OPENFACE_LOST, 5.0
    tree = model.parameters
    names = set(tree.names)
    sums: dict[str, np.ndarray] = {}
    warnings: list[str] = []
    missing: dict[str, list[str]] = {}
    direct = arkit_targets(model) if stream.format in ("arkit", "mediapipe") else {}
    for channel, target in direct.items():           # the model's own ARKit targets take their channel as is
        if channel in channels:
            sums[target] = np.asarray(channels[channel], dtype=float)
    for channel, target, weight, _ in table:
        if channel not in channels or channel in direct:
            continue
        if target not in names:
            missing.setdefault(target, []).append(channel)
            continue
        sums[target] = sums.get(target, 0.0) + weight * channels[channel]
    for channel, target in tables.ROTATION_TARGETS.items():
        if channel not in channels or not np.any(channels[channel]):
            continue
        value = _rotation_value(model, target, channel, channels[channel], warnings)
        if value is None:
            if target not in names:
                missing.setdefault(target, []).append(channel)
            continue
        sums[target] = value
    for target, sources in missing.items():
        warnings.append(f"the model has no parameter '{target}': {', '.join(sorted(set(sources)))} skipped")
    for channel, why in lost.items():
        if channel in channels and channel not in direct and np.max(np.abs(channels[channel])) / scale > LOST_THRESHOLD:
            warnings.append(f"{channel} is not carried over ({why})")
    ordered = [n for n in tree.names if n in sums]
    values = np.zeros((stream.frames, len(ordered)))
    clamped: dict[str, Clamped] = {}
    for j, name in enumerate(ordered):
        raw = np.broadcast_to(np.asarray(sums[name], dtype=float), (stream.frames,))
        low, high = tree[name].minimum, tree[name].maximum
        outside = (raw < low) | (raw > high)
        if outside.any():
            clamped[name] = Clamped(int(outside.sum()), float(raw.min()), float(raw.max()))
        values[:, j] = np.clip(raw, low, high)
    return Retargeted(stream.times_ms.copy(), ordered, values, clamped, warnings)


def arkit_targets(model: Model) -> dict[str, str]:
    """The model's parameters named after ARKit blendshapes (any capitalisation: ``jawOpen``, ``JawOpen``):
    blendshape → parameter. A model made for ARKit capture (its own 52 targets) is driven through them
    directly, each channel's value as the parameter's; the others go through the tables."""
    from engine.capture.arkit_names import canonical_blendshape

    found: dict[str, str] = {}
    for name in model.parameters.names:
        shape = canonical_blendshape(name)
        if shape is not None:
            found.setdefault(shape, name)
    return found


def _eye_angles_from_shapes(channels: dict[str, np.ndarray]) -> None:
    """Eye turn and raise from the eyeLook shapes, where the stream has no eye angles (MediaPipe)."""
    if "eye_left_turn_rad" in channels or "eyeLookOutLeft" not in channels:
        return
    turn, up = tables.EYE_LOOK_RAD["turn"], tables.EYE_LOOK_RAD["raise"]
    # looking to the subject's left: the left eye looks out, the right eye looks in
    channels["eye_left_turn_rad"] = turn * (channels["eyeLookOutLeft"] - channels["eyeLookInLeft"])
    channels["eye_right_turn_rad"] = turn * (channels["eyeLookInRight"] - channels["eyeLookOutRight"])
    channels["eye_left_raise_rad"] = up * (channels["eyeLookUpLeft"] - channels["eyeLookDownLeft"])
    channels["eye_right_raise_rad"] = up * (channels["eyeLookUpRight"] - channels["eyeLookDownRight"])


def _rotation_value(model: Model, target: str, channel: str, radians: np.ndarray,
                    warnings: list[str]) -> np.ndarray | None:
    """Parameter values turning ``target`` by ``radians`` about the channel's axis, or None if it cannot."""
    if target not in model.parameters.names:
        return None
    parameter = model.parameters[target]
    if parameter.kind != "rotation":
        warnings.append(f"'{target}' is not a rotation on this model: {channel} skipped")
        return None
    along = float(np.dot(np.asarray(parameter.axis, dtype=float), ROTATION_AXES[channel]))
    if abs(along) < 0.7:          # more than 45° off the axis the channel turns about
        warnings.append(f"'{target}' turns about {np.round(parameter.axis, 2).tolist()}, not the "
                        f"{ROTATION_AXES[channel]} axis {channel} needs: skipped")
        return None
    return np.degrees(radians) / parameter.degrees_per_unit * np.sign(along)


def resample(times_ms: np.ndarray, values: np.ndarray, fps: float) -> tuple[np.ndarray, np.ndarray]:
    """Values on the grid ``0, 1000/fps, …`` up to the last frame, linear between frames.

    >>> t, v = resample(np.array([0.0, 100.0]), np.array([[0.0], [1.0]]), fps=20)
    >>> t.tolist(), v[:, 0].tolist()
    ([0.0, 50.0, 100.0], [0.0, 0.5, 1.0])
    """
    count = int(np.floor(times_ms[-1] * fps / 1000.0 + 1e-9)) + 1
    grid = np.arange(count) * (1000.0 / fps)
    out = np.empty((count, values.shape[1]))
    for j in range(values.shape[1]):
        out[:, j] = np.interp(grid, times_ms, values[:, j])
    return grid, out


def nominal_fps(rate_hz: float) -> float:
    """A take's rate snapped to a common video rate within 1 %, else rounded to 0.01.

    >>> nominal_fps(30.01), nominal_fps(59.9), nominal_fps(17.333)
    (30.0, 60.0, 17.33)
    """
    for common in (24.0, 25.0, 30.0, 48.0, 50.0, 60.0, 90.0, 100.0, 120.0):
        if abs(rate_hz - common) <= 0.01 * common:
            return common
    return round(rate_hz, 2)

