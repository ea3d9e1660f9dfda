"""The animation of a web site: a dense frame table of the parameters that move, quantised, as JSON.

Why a frame table and not glTF animation channels or keyframes: the engine's tracks *are* a
frame table (``time_ms,<parameter>,...``, one row per frame), so the player shows exactly the
values the MP4 shows, with nothing fitted or thinned; a sentence moves only a handful of
parameters, so the table stays small (one short integer per parameter per frame), and the
player interpolates linearly between frames as :meth:`engine.timeline.tracks.TracksTable.sample`
does. Each channel stores ``round((value - default) / step)`` with a step of 1/10000 of the
channel's largest excursion, far below what a pixel shows.

>>> import numpy as np
>>> channel = quantised_channel("jaw_open", np.array([0.0, 0.25, 0.5]), default=0.0)
>>> channel["step"], channel["values"]
(5e-05, [0, 5000, 10000])
>>> dequantised(channel).tolist()
[0.0, 0.25, 0.5]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from engine.speech.synthesis import Segment

__all__ = ["ANIMATION_FORMAT", "LEVELS", "animation_document", "dequantised", "moving_parameters",
           "quantised_channel"]

ANIMATION_FORMAT = "artificial-person-web-animation"
LEVELS = 10000


def moving_parameters(names: Sequence[str], values: np.ndarray, defaults: Sequence[float]) -> list[str]:
    """The parameters (columns of ``values``, frames × parameters) that ever leave their default."""
    return [name for j, name in enumerate(names) if np.any(values[:, j] != defaults[j])]


def quantised_channel(name: str, values: np.ndarray, default: float) -> dict[str, Any]:
    """One parameter's values over the frames as integers: value = default + step × integer."""
    excursion = float(np.max(np.abs(values - default), initial=0.0))
    step = float(f"{excursion / LEVELS:.6g}") if excursion > 0 else 1.0
    integers = np.round((values - default) / step).astype(int)
    return {"parameter": name, "default": default, "step": step, "values": integers.tolist()}


def dequantised(channel: dict[str, Any]) -> np.ndarray:
    """A channel's values back as floats (what the player uses)."""
    return channel["default"] + channel["step"] * np.asarray(channel["values"], dtype=float)


def peak_value(channel: dict[str, Any]) -> float:
    """The value farthest from the default that a channel reaches (its morph target's value)."""
    values = dequantised(channel)
    return float(values[int(np.argmax(np.abs(values - channel["default"])))])


def animation_document(names: Sequence[str], values: np.ndarray, defaults: Sequence[float], frame_ms: float,
                       joints: Sequence[str], phones: Sequence[Segment] = (), words: Sequence[Segment] = (),
                       duration_ms: float | None = None) -> dict[str, Any]:
    """The animation JSON: frame ``n`` at ``n × frame_ms``; a channel per moving parameter (``joint``
    for the skeleton's, ``morph`` for the rest, with the value its target shows at weight 1);
    phones and words with their times for events and checks."""
    channels = []
    for name in moving_parameters(names, values, defaults):
        j = list(names).index(name)
        channel = quantised_channel(name, values[:, j], float(defaults[j]))
        if name in joints:
            channel["kind"] = "joint"
        else:
            channel["kind"] = "morph"
            channel["target_value"] = peak_value(channel)
        channels.append(channel)
    frames = len(values)
    return {
        "format": ANIMATION_FORMAT, "version": 1,
        "frame_ms": frame_ms, "frames": frames,
        "duration_ms": float(duration_ms if duration_ms is not None else max(frames - 1, 0) * frame_ms),
        "channels": channels,
        "phones": [{"phone": p.label, "start_ms": round(p.start_ms, 3), "end_ms": round(p.end_ms, 3),
                    "word": p.word} for p in phones],
        "words": [{"word": w.label, "start_ms": round(w.start_ms, 3), "end_ms": round(w.end_ms, 3)} for w in words],
    }
