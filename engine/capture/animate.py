"""A capture take → the head's tracks table or a video: the one function the CLI (and the workbench) call.

>>> from engine import load_model
>>> report = animate_capture("take.csv", load_model(), "take.mp4")            # doctest: +SKIP
>>> print(report.summary())                                                   # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from engine.capture.readers import read_capture
from engine.capture.retarget import Retargeted, nominal_fps, resample, retarget
from engine.capture.stream import CaptureFileError, CaptureStream
from engine.commands.limits import MAX_FRAMES, MAX_TIME_MS
from engine.model.model import Model
from engine.outputs.animation_file import check_output, write_animation
from engine.timeline.tracks import TracksTable


@dataclass
class CaptureAnimation:
    """What :func:`animate_capture` read, mapped and wrote."""

    stream: CaptureStream
    mapped: Retargeted
    fps: float
    frames: int
    output: Path

    def summary(self) -> list[str]:
        """Lines for the user: the take, the frames written, clamped parameters."""
        lines = [f"{self.stream.source}: {self.stream.format}, {self.stream.frames} frames at "
                 f"{self.stream.rate_hz:.2f} Hz, {self.stream.times_ms[-1] / 1000:.2f} s; "
                 f"{len(self.mapped.parameters)} parameters driven",
                 f"wrote {self.output} ({self.frames} frames at {self.fps:g} fps)"]
        for name, clamp in self.mapped.clamped.items():
            lines.append(f"clamped {name} in {clamp.frames} frame(s) (mapped {clamp.lowest:.3g} … "
                         f"{clamp.highest:.3g})")
        return lines


def capture_tracks(stream: CaptureStream, model: Model, fps: float | None = None
                   ) -> tuple[Retargeted, float, np.ndarray, np.ndarray]:
    """The take on an even grid: (mapping, fps, times ms (F,), every model parameter (F, P) in tree order)."""
    mapped = retarget(stream, model)
    rate = fps if fps is not None else nominal_fps(stream.rate_hz)
    if stream.times_ms[-1] > MAX_TIME_MS or stream.times_ms[-1] * rate / 1000.0 > MAX_FRAMES:
        raise CaptureFileError(f"the take lasts {stream.times_ms[-1] / 3.6e6:.1f} h: more than "
                               f"{MAX_TIME_MS / 3.6e6:g} h or {MAX_FRAMES} frames", file=stream.source)
    times, driven = resample(mapped.times_ms, mapped.values, rate) if stream.frames > 1 else \
        (np.zeros(1), mapped.values[:1])
    tree = model.parameters
    full = np.tile([tree[n].default for n in tree.names], (len(times), 1)).astype(float)
    for j, name in enumerate(mapped.parameters):
        full[:, tree.names.index(name)] = driven[:, j]
    return mapped, rate, times, full


def capture_table(path: str | Path, model: Model, format: str = "auto", fps: float | None = None
                  ) -> tuple[TracksTable, CaptureStream, Retargeted, float]:
    """The take as a :class:`~engine.timeline.tracks.TracksTable` (what the workbench's player plays).

    Returns (table, the take as read, its mapping, the frame rate of the table).
    """
    stream = read_capture(path, format, fps)
    mapped, rate, times, values = capture_tracks(stream, model, fps)
    return TracksTable(times, list(model.parameters.names), values, model, str(path)), stream, mapped, rate


def animate_capture(path: str | Path, model: Model, output: str | Path, format: str = "auto",
                    fps: float | None = None, audio: str | Path | None = None, size: tuple[int, int] = (640, 480),
                    view: str = "front", progress: Callable[[int, int], None] | None = None) -> CaptureAnimation:
    """Read ``path``, map it onto ``model`` and write ``output``: a tracks CSV or an MP4 (``audio``: a WAV)."""
    out = check_output(output, audio)
    stream = read_capture(path, format, fps)
    mapped, rate, times, values = capture_tracks(stream, model, fps)
    write_animation(out, model, model.parameters.names, times, values, rate, audio=audio, size=size, view=view,
                    progress=progress)
    return CaptureAnimation(stream, mapped, rate, len(times), out)
