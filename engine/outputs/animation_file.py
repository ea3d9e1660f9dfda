"""An animation — every parameter on a grid of times — written as a tracks table (``.csv``) or a video (``.mp4``).

What ``mocap animate`` and ``capture animate`` write: the output's kind is its
extension; a video may carry a WAV, shifted by a number of ms against the
animation's first frame.

>>> check_output("take.csv")
PosixPath('take.csv')
>>> check_output("take.avi")                       # doctest: +ELLIPSIS
Traceback (most recent call last):
...
engine.errors.UserError: take.avi: unknown output extension '.avi' (use .csv or .mp4)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.model.model import Model

OUTPUT_SUFFIXES = (".csv", ".mp4")


def check_output(output: str | Path, audio: str | Path | None = None) -> Path:
    """``output`` as a path, or a :class:`UserError` if it is neither a tracks table nor a video (with audio)."""
    out = Path(output)
    if out.suffix.lower() not in OUTPUT_SUFFIXES:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' (use .csv or .mp4)", file=out)
    if audio is not None and out.suffix.lower() != ".mp4":
        raise UserError("--audio goes with a video (.mp4) output")
    return out


def write_animation(output: str | Path, model: Model, names: Sequence[str], times_ms: np.ndarray, values: np.ndarray,
                    fps: float, *, audio: str | Path | None = None, audio_offset_ms: float = 0.0,
                    size: tuple[int, int] = (640, 480), view: str = "front",
                    progress: Callable[[int, int], None] | None = None) -> Path:
    """Write ``values`` (frames × ``names``) at ``times_ms`` as ``output`` (checked by :func:`check_output`).

    ``audio_offset_ms``: when the WAV's first sample sounds relative to the
    first frame (positive: later — silence is put before it; negative:
    earlier — its first samples are dropped).
    """
    out = check_output(output, audio)
    if not np.isfinite(audio_offset_ms):
        raise UserError(f"the audio offset must be a number of ms, not {audio_offset_ms}")
    if out.suffix.lower() == ".csv":
        from engine.formats.atomic import atomic_write_text
        from engine.timeline.tracks import tracks_csv_text

        atomic_write_text(out, tracks_csv_text(list(names), times_ms, values))
        return out
    from engine.outputs.video_writer import write_video

    samples, sample_rate = None, None
    if audio is not None:
        from engine.speech.synthesis import read_wav

        samples, sample_rate = read_wav(audio)
        samples = shift_audio(samples, sample_rate, audio_offset_ms)
    write_video(out, model, times_ms, values, list(names), fps=fps, audio=samples, sample_rate=sample_rate,
                size=size, view=view, progress=progress)
    return out


def shift_audio(samples: np.ndarray, sample_rate: int, offset_ms: float) -> np.ndarray:
    """``samples`` starting ``offset_ms`` later (silence before) or earlier (the first samples dropped).

    >>> shift_audio(np.ones(4, np.float32), 1000, 2).tolist(), shift_audio(np.ones(4, np.float32), 1000, -3).tolist()
    ([0.0, 0.0, 1.0, 1.0, 1.0, 1.0], [1.0])
    """
    n = round(abs(offset_ms) * sample_rate / 1000.0)
    if offset_ms >= 0:
        return np.concatenate([np.zeros(n, dtype=samples.dtype), samples])
    return samples[n:]
