"""Looking at a video: stream facts (ffprobe), decoded frames and audio, a contact sheet.

Tests and users check a written video by reading it back: :func:`probe`
gives frame count, rate and the start and length of each stream;
:func:`read_frames` and :func:`read_audio` decode pictures and samples;
:func:`contact_sheet` lays frames spread over a video out in one picture.
Writing is :mod:`engine.outputs.video_writer`.

>>> from engine.outputs.video_probe import probe, read_frames, contact_sheet
>>> probe("nod.mp4").frames                                    # doctest: +SKIP
90
>>> sheet = contact_sheet("nod.mp4", columns=5, count=10, path="nod.png")   # doctest: +SKIP

Needs ``ffmpeg`` and ``ffprobe`` (Debian package ``ffmpeg``); without them
the functions here raise :class:`~engine.outputs.video_tools.FFmpegMissing`.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.outputs.raster import draw_text
from engine.outputs.video_tools import FFmpegMissing, VideoError, find_tool, stderr_tail
from engine.processes import with_parent_death_signal

__all__ = ["FFmpegMissing", "Probe", "VideoError", "contact_sheet", "probe", "read_audio", "read_frames"]


@dataclass
class Probe:
    """Stream facts of a video file, from ffprobe. Durations and start times in seconds."""

    width: int
    height: int
    frames: int
    fps: float
    video_duration: float
    video_start: float
    audio_duration: float | None = None
    audio_start: float | None = None
    sample_rate: int | None = None
    video_codec: str = ""
    audio_codec: str | None = None


def probe(path: str | Path) -> Probe:
    """Frame count, frame rate, and the durations and start times of the video and
    audio streams (the first of each), as ffprobe reports them."""
    path = Path(path)
    if not path.is_file():
        raise UserError("no such video file", file=path)
    result = subprocess.run(with_parent_death_signal([find_tool("ffprobe"), "-v", "error", "-print_format", "json",
                                                      "-show_streams", "-show_format", str(path)]),
                            capture_output=True, timeout=60, check=False)
    if result.returncode != 0:
        raise VideoError(f"ffprobe cannot read it: {stderr_tail(result.stderr)}", file=path)
    info = json.loads(result.stdout)
    streams = info.get("streams", [])
    video = next((s for s in streams if s.get("codec_type") == "video"), None)
    audio = next((s for s in streams if s.get("codec_type") == "audio"), None)
    if video is None:
        raise VideoError("no video stream", file=path)
    fps = float(Fraction(video.get("avg_frame_rate") or video.get("r_frame_rate") or "0"))
    frames = int(video.get("nb_frames") or 0)
    if not frames:
        frames = len(read_frames(path, size=(2, 2)))
    out = Probe(width=int(video["width"]), height=int(video["height"]), frames=frames, fps=fps,
                video_duration=float(video.get("duration", "nan")),
                video_start=float(video.get("start_time", "nan")), video_codec=video.get("codec_name", ""))
    if audio is not None:
        out.audio_duration = float(audio.get("duration", "nan"))
        out.audio_start = float(audio.get("start_time", "nan"))
        out.sample_rate = int(audio.get("sample_rate", 0))
        out.audio_codec = audio.get("codec_name")
    return out


def read_frames(path: str | Path, indices: Sequence[int] | None = None,
                size: tuple[int, int] | None = None) -> np.ndarray:
    """Decoded frames (k, H, W, 3) uint8 RGB: all of them, or those numbered ``indices``
    (in increasing order), scaled to ``size`` = (width, height) if given."""
    path = Path(path)
    if not path.is_file():
        raise UserError("no such video file", file=path)
    info = None
    if size is None:
        info = probe(path)
        width, height = info.width, info.height
    else:
        width, height = (int(s) for s in size)
    filters = []
    if indices is not None:
        indices = sorted({int(i) for i in indices})
        if not indices:
            return np.zeros((0, height, width, 3), dtype=np.uint8)
        filters.append("select=" + "+".join(f"eq(n\\,{i})" for i in indices))
    if size is not None:
        filters.append(f"scale={width}:{height}:flags=area")
    command = [find_tool("ffmpeg"), "-v", "error", "-nostdin", "-i", str(path), "-map", "0:v:0"]
    if filters:
        command += ["-vf", ",".join(filters)]
    command += ["-fps_mode", "passthrough", "-f", "rawvideo", "-pix_fmt", "rgb24", "pipe:1"]
    result = subprocess.run(with_parent_death_signal(command), capture_output=True, timeout=600, check=False)
    if result.returncode != 0:
        raise VideoError(f"ffmpeg cannot decode it: {stderr_tail(result.stderr)}", file=path)
    frame_bytes = width * height * 3
    count = len(result.stdout) // frame_bytes
    return np.frombuffer(result.stdout[:count * frame_bytes], dtype=np.uint8).reshape(count, height, width, 3)


def read_audio(path: str | Path, sample_rate: int | None = None) -> tuple[np.ndarray, int]:
    """The first audio stream decoded to mono float32 samples, and its sample rate
    (resampled to ``sample_rate`` if given).

    Cut to the stream's duration in the container: AAC codes whole blocks of
    1024 samples, and ffmpeg's decoder returns the padding of the last one
    too, which players leave out."""
    path = Path(path)
    info = probe(path)
    if info.sample_rate is None:
        raise VideoError("no audio stream", file=path)
    rate = int(sample_rate or info.sample_rate)
    result = subprocess.run(with_parent_death_signal([find_tool("ffmpeg"), "-v", "error", "-nostdin", "-i", str(path),
                                                      "-map", "0:a:0", "-ac", "1", "-ar", str(rate), "-f", "f32le",
                                                      "pipe:1"]), capture_output=True, timeout=600, check=False)
    if result.returncode != 0:
        raise VideoError(f"ffmpeg cannot decode its audio: {stderr_tail(result.stderr)}", file=path)
    samples = np.frombuffer(result.stdout, dtype="<f4")
    if info.audio_duration is not None and math.isfinite(info.audio_duration):
        samples = samples[:round(info.audio_duration * rate)]
    return samples.copy(), rate


# ---------------------------------------------------------------------------
# Contact sheet

SHEET_BACKGROUND = (255, 255, 255)
SHEET_TEXT = (40, 40, 40)


def contact_sheet(source: str | Path | np.ndarray | Sequence[np.ndarray], columns: int = 4,
                  count: int = 12, width: int = 200, times_ms: Sequence[float] | None = None,
                  fps: float | None = None, path: str | Path | None = None) -> np.ndarray:
    """A grid of ``count`` frames spread evenly over a video, each labelled with its
    frame number and time, to see a whole video at a glance.

    ``source`` is an MP4 (frames decoded with ffmpeg; times from its frame
    rate) or frames in memory, (F, H, W, 3) uint8 or a list of such pictures
    (times from ``times_ms``, or from ``fps``, else frame numbers only).
    Thumbnails are about ``width`` pixels wide. Returns the sheet as an
    (H, W, 3) uint8 array, also written to ``path`` (PNG) if given.
    """
    from engine.outputs.render import write_png

    if columns < 1 or count < 1 or width < 8:
        raise UserError("a contact sheet needs columns ≥ 1, count ≥ 1 and width ≥ 8")
    thumbs: np.ndarray | list[np.ndarray]
    if isinstance(source, (str, os.PathLike)):
        source = Path(source)
        info = probe(source)
        total = info.frames
        picks = _spread(total, count)
        scale = max(1, math.ceil(info.width / width))
        thumb = (max(2, info.width // scale), max(2, info.height // scale))
        thumbs = read_frames(source, picks, size=thumb)
        picks = picks[:len(thumbs)]
        times = [1000.0 * n / info.fps for n in picks] if info.fps else None
    else:
        frames = source if isinstance(source, np.ndarray) else np.stack([np.asarray(f) for f in source])
        if frames.ndim != 4 or frames.shape[3] != 3:
            raise UserError(f"expected frames (F, H, W, 3), got shape {frames.shape}")
        picks = _spread(len(frames), count)
        scale = max(1, math.ceil(frames.shape[2] / width))
        thumbs = [_shrink(frames[n], scale) for n in picks]
        if times_ms is not None:
            times = [float(times_ms[n]) for n in picks]
        elif fps:
            times = [1000.0 * n / fps for n in picks]
        else:
            times = None
    if len(picks) == 0:
        raise UserError("no frames to put on a contact sheet")
    labels = [f"#{n}" + (f" {times[k] / 1000:.3f}s" if times is not None else "") for k, n in enumerate(picks)]
    th, tw = thumbs[0].shape[:2]
    gap, text_scale = 6, 2 if tw >= 160 else 1
    label_h = 7 * text_scale + 6
    rows = math.ceil(len(thumbs) / columns)
    cols = min(columns, len(thumbs))
    sheet = np.empty((gap + rows * (th + label_h + gap), gap + cols * (tw + gap), 3), dtype=np.uint8)
    sheet[:] = SHEET_BACKGROUND
    for k, (image, label) in enumerate(zip(thumbs, labels, strict=True)):
        r, c = divmod(k, columns)
        y, x = gap + r * (th + label_h + gap), gap + c * (tw + gap)
        sheet[y:y + th, x:x + tw] = image
        draw_text(sheet, label, x, y + th + 3, SHEET_TEXT, scale=text_scale)
    if path is not None:
        if Path(path).suffix.lower() != ".png":
            raise UserError("the contact sheet must be written as .png", file=path)
        write_png(path, sheet)
    return sheet


def _spread(total: int, count: int) -> list[int]:
    """``count`` frame numbers spread evenly from the first frame to the last."""
    if total <= 0:
        return []
    if count >= total:
        return list(range(total))
    if count == 1:
        return [0]
    return sorted({round(i * (total - 1) / (count - 1)) for i in range(count)})


def _shrink(image: np.ndarray, factor: int) -> np.ndarray:
    """Average ``factor`` × ``factor`` blocks (the edges that do not fill a block are dropped)."""
    image = np.asarray(image)
    if factor == 1:
        return image.astype(np.uint8, copy=False)
    h, w = (image.shape[0] // factor) * factor, (image.shape[1] // factor) * factor
    blocks = image[:h, :w].reshape(h // factor, factor, w // factor, factor, 3).astype(np.float32)
    return np.round(blocks.mean(axis=(1, 3))).astype(np.uint8)
