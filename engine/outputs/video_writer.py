"""Talking-head video: poses rendered offscreen, piped into ffmpeg as H.264 + AAC in MP4.

Frame ``n`` of the video shows the face with the parameter values of row
``n``, which must be the pose at time ``times_ms[n] = times_ms[0] + n·1000/fps``.
Audio sample ``i`` plays at ``i/sample_rate`` s, so the video starts at audio
time ``times_ms[0]`` (normally 0); the audio is cut or padded with silence to
exactly the video's length (``frames/fps``), so both streams start together
and end together (to within one AAC sample).

>>> import numpy as np
>>> from engine import load_model
>>> from engine.outputs.video_writer import write_video, progress_printer
>>> head = load_model()
>>> times = np.arange(90) * (1000 / 30)                       # 3 s at 30 fps
>>> values = np.sin(times / 300)[:, None] * [0.4, 0.2] + [0.4, 0]
>>> write_video("nod.mp4", head, times, values, ["jaw_open", "head_nod"], fps=30,
...             progress=progress_printer("rendering"))       # doctest: +SKIP

Reading a video back (frame counts, frames, audio, contact sheets) is
:mod:`engine.outputs.video_probe`. Needs the ``ffmpeg`` program (Debian
package ``ffmpeg``); without it the functions here raise :class:`FFmpegMissing`.

Speed: one :class:`~engine.outputs.render.FrameRenderer` draws the frames (the scene
is built once, only the vertex positions and normals change) — with a second
process drawing every other frame on a machine with two or more cores
(:mod:`engine.outputs.render_helper`) — while ffmpeg
encodes in its own process; a writer thread keeps the pipe to ffmpeg full so
drawing and encoding overlap. The ``look`` (:mod:`engine.outputs.looks`, default
``portrait``) decides the anti-aliasing unless ``antialias`` is given: a look
smoothed by FXAA (``portrait``, ``flat``) has it, which costs a few milliseconds a
frame, so the frames look exactly like :func:`engine.outputs.render.render_model`'s
pictures; the ``legacy`` look's 8× multisampling costs about three times the rest
of the drawing without a GPU (Mesa llvmpipe), so its videos are drawn without it,
as they always were, unless ``antialias=True``. ``benchmarks/bench_video.py``
measures them.
"""

from __future__ import annotations

import math
import resource
import subprocess
import sys
import tempfile
import time
import wave
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import IO, Any

import numpy as np
from numpy.typing import ArrayLike

from engine.errors import UserError
from engine.formats.atomic import atomic_files
from engine.model.model import Model
from engine.outputs.frame_pipe import FrameWriter
from engine.outputs.looks import Look, look_from
from engine.outputs.render_helper import RenderHelper, helper_wanted
from engine.outputs.video_encoding import Encoding, encoding_from
from engine.outputs.video_tools import FFmpegMissing, VideoError, find_tool, stderr_tail
from engine.processes import with_parent_death_signal

__all__ = ["FFmpegMissing", "VideoError", "VideoRequest", "VideoStats", "check_video", "encode_video",
           "progress_printer", "write_video"]

Progress = Callable[[int, int], None]
"""``progress(done, total)``: called as work is done."""

#: The default H.264 settings: a fast preset (the frames are simple, the machine small), 4:2:0 for every
#: player; a video's own ``encoding`` (:mod:`engine.outputs.video_encoding`) may choose others.
VIDEO_ARGS = Encoding().ffmpeg_args()
AUDIO_ARGS = ["-c:a", "aac", "-b:a", "96k"]
#: Sample rates the AAC encoder takes; other rates are resampled to the next one up.
AAC_RATES = (7350, 8000, 11025, 12000, 16000, 22050, 24000, 32000, 44100, 48000, 64000, 88200, 96000)
FRAME_TIME_TOLERANCE = 0.01          # of a frame interval: how far a frame time may be off its slot


@dataclass
class VideoStats:
    """What :func:`write_video` did and where the time went (seconds)."""

    path: Path
    frames: int
    fps: float
    deform: float = 0.0          # Model deformation, all frames
    render: float = 0.0          # drawing and reading back the pictures
    encoder_wait: float = 0.0    # the renderer waiting for ffmpeg to take frames
    finish: float = 0.0          # after the last frame: ffmpeg flushing and writing the file
    encoder_cpu: float = 0.0     # CPU time ffmpeg used (user + system)
    total: float = 0.0           # wall clock, start to finished file

    @property
    def duration(self) -> float:
        """Length of the video in seconds."""
        return self.frames / self.fps

    @property
    def real_time_factor(self) -> float:
        """Wall-clock time per second of video (below 1: faster than real time)."""
        return self.total / self.duration


@dataclass
class VideoRequest:
    """One video, checked and ready to encode (:func:`check_video`)."""

    path: Path
    """Where the video goes (``*.mp4``); named in errors."""
    model: Model
    values: np.ndarray
    """(F, P): every parameter, in the model's tree order, at every frame."""
    fps: float
    size: tuple[int, int]
    """(width, height) in pixels, both even."""
    view: str
    audio: np.ndarray | None
    """Mono float32 samples covering exactly the video (cut or padded), or None."""
    sample_rate: int | None
    look: Look = field(default_factory=look_from)
    """How the head is lit and shaded (:mod:`engine.outputs.looks`)."""
    encoding: Encoding = field(default_factory=Encoding)
    """How the frames are compressed (:mod:`engine.outputs.video_encoding`)."""

    def antialias(self, asked: bool | None) -> bool:
        """Whether the frames are smoothed: as ``asked``, or (``None``) where the look's method is FXAA."""
        return self.look.antialias == "fxaa" if asked is None else bool(asked)

    @property
    def frames(self) -> int:
        """Number of frames."""
        return len(self.values)


# ---------------------------------------------------------------------------
# Writing

def write_video(path: str | Path, model: Model, times_ms: ArrayLike, values: ArrayLike,
                parameter_names: Sequence[str], fps: float, audio: ArrayLike | None = None,
                sample_rate: int | None = None, size: tuple[int, int] = (640, 480), view: str = "front",
                progress: Progress | None = None, antialias: bool | None = None,
                look: str | Look | None = None, encoding: object = None) -> VideoStats:
    """Render one frame per row of ``values`` and write them, with ``audio``, as an MP4.

    Parameters
    ----------
    path : ``*.mp4``
        Written atomically (:func:`engine.formats.atomic.atomic_files`):
        ffmpeg writes a hidden temporary file beside it, which is renamed over
        ``path`` only when complete. On an error or Ctrl-C nothing is left
        behind (and an existing ``path`` is untouched).
    model : engine.Model
    times_ms : (F,) frame times, ms
        ``times_ms[n]`` must be ``times_ms[0] + n·1000/fps`` (to 1 % of a frame);
        ``times_ms[0]`` is where the video starts on the audio's clock.
    values : (F, P) array
        Column ``j`` is parameter ``parameter_names[j]``; parameters not named
        take their default. Values are applied as given (no range check).
    fps : frames per second.
    audio : (S,) float array in [-1, 1] (mono), optional
        Integer samples are scaled by their type's range. Cut or padded with
        silence to the video's length.
    sample_rate : Hz, required with ``audio``.
    size : (width, height), both even (H.264 4:2:0 needs even sizes).
    view : ``"front"``, ``"side"`` or ``"three-quarter"`` (as :func:`engine.outputs.render.render_model`).
    progress : callable ``(frames done, frames total)``, optional
        Called once before the first frame and after each one; see
        :func:`progress_printer`.
    antialias : smoothed edges, the look's way; ``None``: where it is cheap (see the module notes).
    look : a look's name, a :class:`~engine.outputs.looks.Look` or its settings (default ``portrait``).
    encoding : ``"lossless"``, an x264 preset's name, ``{"preset": …, "crf": …}`` or an
        :class:`~engine.outputs.video_encoding.Encoding` (default ``veryfast``, CRF 20).

    Returns
    -------
    :class:`VideoStats` (frame count and the time spent in each stage).
    """
    started = time.perf_counter()
    request = check_video(path, model, times_ms, values, parameter_names, fps, audio, sample_rate, size, view, look,
                          encoding)
    with atomic_files([request.path]) as temporary:
        stats = encode_video(request, temporary[request.path], progress, antialias)
    stats.total = time.perf_counter() - started
    return stats


def check_video(path: str | Path, model: Model, times_ms: ArrayLike, values: ArrayLike,
                parameter_names: Sequence[str], fps: float, audio: ArrayLike | None = None,
                sample_rate: int | None = None, size: tuple[int, int] = (640, 480),
                view: str = "front", look: str | Look | None = None, encoding: object = None) -> VideoRequest:
    """Everything :func:`write_video` checks, before any work: a :class:`VideoRequest`, or a :class:`UserError`.

    The arguments are :func:`write_video`'s. A writer that writes the video
    together with other files checks it first, then encodes it with
    :func:`encode_video` into a temporary file of its own.
    """
    path = Path(path)
    chosen_encoding = encoding_from(encoding)
    frame_values, fps = _check_frames(model, times_ms, values, parameter_names, fps)
    width, height = _check_video_size(size)
    from engine.outputs.render import VIEWS

    if view not in VIEWS:
        raise UserError(f"unknown view '{view}' (use {', '.join(VIEWS)})")
    if path.suffix.lower() != ".mp4":
        raise UserError("the video must be written as .mp4", file=path)
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise UserError("cannot write: the folder does not exist", file=path)
    if path.is_dir():
        raise UserError("cannot write: this is a folder", file=path)
    samples = None
    if audio is not None:
        samples, sample_rate = _check_audio(audio, sample_rate)
        samples = _fit_audio(samples, sample_rate, float(np.asarray(times_ms, dtype=float)[0]),
                             len(frame_values), fps)
    return VideoRequest(path, model, frame_values, fps, (width, height), view, samples,
                        sample_rate if samples is not None else None, look_from(look), chosen_encoding)


def encode_video(request: VideoRequest, destination: str | Path, progress: Progress | None = None,
                 antialias: bool | None = None,
                 on_frame: Callable[[int, np.ndarray], None] | None = None,
                 on_positions: Callable[[int, np.ndarray], None] | None = None) -> VideoStats:
    """Render and encode ``request`` into ``destination`` as it is: no temporary file, no rename.

    For writers that make the file atomic themselves (as :func:`write_video`
    and :func:`engine.outputs.speech_files.write_speech_files` do with
    :func:`engine.formats.atomic.atomic_files`): ``destination`` is their
    temporary file; errors name ``request.path``. ``progress`` and
    ``antialias`` as in :func:`write_video`. If anything goes wrong (Ctrl-C
    included), ffmpeg is stopped before the exception leaves. ``on_frame(n, image)``, when given, sees
    every frame's picture as drawn (height × width × 3), so a caller needing one picture draws it no more;
    ``on_positions(n, positions)`` sees the vertex positions (N × 3, mm) every frame was drawn from, in
    frame order, so a caller measuring the face's motion deforms no frame again (issue 35: each result
    computed once).
    """
    started = time.perf_counter()
    ffmpeg = find_tool("ffmpeg")
    from engine.outputs.render import FrameRenderer

    path, count, fps = request.path, request.frames, request.fps
    antialias = request.antialias(antialias)
    width, height = request.size
    stats = VideoStats(path=path, frames=count, fps=float(fps))
    deformer = request.model.deformer()
    process = None
    writer = None
    helper: RenderHelper | None = None
    with tempfile.TemporaryDirectory(prefix="artificial-person-video-") as scratch, \
            open(Path(scratch) / "ffmpeg.log", "w+b") as log:
        try:
            command = [ffmpeg, "-hide_banner", "-nostdin", "-nostats", "-loglevel", "error", "-y",
                       "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{width}x{height}",
                       "-framerate", _rate_text(fps), "-i", "pipe:0"]
            if request.audio is not None and request.sample_rate is not None:
                rate = request.sample_rate
                wav = Path(scratch) / "audio.wav"
                _write_wav(wav, request.audio, rate)
                command += ["-i", str(wav), "-map", "0:v:0", "-map", "1:a:0", *AUDIO_ARGS]
                if rate not in AAC_RATES:
                    command += ["-ar", str(next((r for r in AAC_RATES if r >= rate), AAC_RATES[-1]))]
            command += [*request.encoding.ffmpeg_args(), "-movflags", "+faststart", "-f", "mp4", str(destination)]
            if helper_wanted(count):              # forked before our renderer and ffmpeg exist
                helper = RenderHelper(request, antialias, positions=on_positions is not None)
            with FrameRenderer(request.model, size=(width, height), view=request.view,
                               antialias=antialias, look=request.look) as renderer:
                cpu_before = _children_cpu()
                process = subprocess.Popen(with_parent_death_signal(command), stdin=subprocess.PIPE,
                                           stdout=subprocess.DEVNULL, stderr=log,
                                           start_new_session=True)   # Ctrl-C reaches us, not it
                assert process.stdin is not None              # stdin=PIPE
                writer = FrameWriter(process.stdin)
                if progress is not None:
                    progress(0, count)
                for n in range(count):
                    t0 = time.perf_counter()
                    image = helper.frame(n) if helper is not None and helper.owns(n) else None
                    positions = helper.positions if image is not None and helper is not None else None
                    t1 = time.perf_counter()
                    if image is None:
                        positions = deformer.deform(request.values[n])
                        t1 = time.perf_counter()
                        image = renderer.render(positions)
                    t2 = time.perf_counter()
                    if on_frame is not None:
                        on_frame(n, image)
                    if on_positions is not None and positions is not None:
                        on_positions(n, positions)
                    if not writer.put(image):
                        break                               # ffmpeg stopped taking frames: report below
                    t3 = time.perf_counter()
                    stats.deform += t1 - t0
                    stats.render += t2 - t1
                    stats.encoder_wait += t3 - t2
                    if progress is not None:
                        progress(n + 1, count)
            t_end = time.perf_counter()
            writer.close()
            code = process.wait()
            stats.finish = time.perf_counter() - t_end
            stats.encoder_cpu = _children_cpu() - cpu_before
            if code != 0 or writer.error is not None:
                raise VideoError(_ffmpeg_failure(log, code, writer.error), file=path)
        except OSError as exc:
            raise UserError(f"cannot write the video: {exc.strerror or exc}", file=path) from None
        finally:
            if helper is not None:
                helper.close()
            if writer is not None:
                writer.abandon()
            if process is not None and process.poll() is None:
                process.kill()
                process.wait()
    stats.total = time.perf_counter() - started
    return stats


def _check_frames(model: Model, times_ms: ArrayLike, values: ArrayLike, parameter_names: Sequence[str],
                  fps: float) -> tuple[np.ndarray, float]:
    """The values of every parameter (tree order) at every frame, after checking the inputs."""
    try:
        fps = float(fps)
    except (TypeError, ValueError):
        raise UserError(f"frames per second must be a number, not {fps!r}") from None
    if not (fps > 0 and math.isfinite(fps)):
        raise UserError(f"frames per second must be a positive number (got {fps:g})")
    times = np.asarray(times_ms, dtype=float)
    if times.ndim != 1 or len(times) == 0:
        raise UserError("a video needs at least one frame time")
    if not np.all(np.isfinite(times)):
        raise UserError("frame times must be finite numbers")
    interval = 1000.0 / fps
    slots = times[0] + np.arange(len(times)) * interval
    wrong = np.flatnonzero(np.abs(times - slots) > FRAME_TIME_TOLERANCE * interval)
    if len(wrong):
        n = int(wrong[0])
        raise UserError(f"frame {n} is at {times[n]:g} ms, but at {fps:g} fps it must be at {slots[n]:g} ms "
                        f"(frame n at start + n·1000/fps)")
    names = list(parameter_names)
    values = np.asarray(values, dtype=float)
    if values.ndim == 1 and len(names) == 1:
        values = values[:, None]
    if values.shape != (len(times), len(names)):
        raise UserError(f"expected {len(times)} frames × {len(names)} parameters of values, "
                        f"got shape {values.shape}")
    if not np.all(np.isfinite(values)):
        raise UserError("parameter values must be finite numbers")
    if len(set(names)) != len(names):
        raise UserError("a parameter is named twice")
    order = {name: i for i, name in enumerate(model.parameters.names)}
    columns = []
    for name in names:
        if name not in order:
            model.parameters[name]                  # raises ParameterError with a suggestion
        columns.append(order[name])
    full = np.tile(model.values_array(), (len(times), 1))
    full[:, columns] = values
    return full, fps


def _check_video_size(size: tuple[int, int]) -> tuple[int, int]:
    from engine.outputs.render import check_size

    width, height = check_size(size)
    if width % 2 or height % 2:
        raise UserError(f"video size {width}x{height}: width and height must be even (H.264, 4:2:0)")
    return width, height


def _check_audio(audio: ArrayLike, sample_rate: int | None) -> tuple[np.ndarray, int]:
    samples = np.asarray(audio)
    if samples.ndim != 1:
        raise UserError(f"audio must be one channel (a 1-D array of samples), got shape {samples.shape}")
    if sample_rate is None:
        raise UserError("audio given without its sample rate")
    try:
        rate = int(sample_rate)
    except (TypeError, ValueError):
        raise UserError(f"sample rate must be a whole number of Hz, not {sample_rate!r}") from None
    if rate != sample_rate or not 1000 <= rate <= 384000:
        raise UserError(f"sample rate {sample_rate!r} Hz must be a whole number in 1000..384000")
    if np.issubdtype(samples.dtype, np.integer):
        samples = samples / max(abs(np.iinfo(samples.dtype).min), np.iinfo(samples.dtype).max)
    elif not np.issubdtype(samples.dtype, np.floating):
        raise UserError(f"audio samples must be numbers, not {samples.dtype}")
    samples = samples.astype(np.float32)
    if not np.all(np.isfinite(samples)):
        raise UserError("audio samples must be finite numbers")
    return samples, rate


def _fit_audio(samples: np.ndarray, rate: int, start_ms: float, frames: int, fps: float) -> np.ndarray:
    """The stretch of audio the video covers: from ``start_ms`` for ``frames/fps`` s,
    silence where the samples run out (or before they begin)."""
    first = round(start_ms * rate / 1000.0)
    count = round(frames * rate / fps)
    out = np.zeros(count, dtype=np.float32)
    lo, hi = max(first, 0), min(first + count, len(samples))
    if hi > lo:
        out[lo - first:hi - first] = samples[lo:hi]
    return out


def _write_wav(path: Path, samples: np.ndarray, rate: int) -> None:
    pcm = np.round(np.clip(samples, -1.0, 1.0) * 32767.0).astype("<i2")
    with wave.open(str(path), "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(rate)
        out.writeframes(pcm.tobytes())


def _rate_text(fps: float) -> str:
    """A frame rate as ffmpeg takes it: a fraction, so 29.97 stays 2997/100 and 30 stays 30."""
    rate = Fraction(fps).limit_denominator(1_000_000)
    return str(rate.numerator) if rate.denominator == 1 else f"{rate.numerator}/{rate.denominator}"


def _ffmpeg_failure(log: IO[bytes], code: int, write_error: BaseException | None) -> str:
    log.seek(0)
    complaint = log.read()
    if code != 0:
        what = f"ffmpeg failed (exit status {code})"
    else:
        what = f"writing frames to ffmpeg failed ({write_error})"
    return f"{what}: {stderr_tail(complaint)}" if complaint.strip() else what


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


# ---------------------------------------------------------------------------
# Progress

def progress_printer(label: str = "rendering", stream: IO[str] | None = None, interval: float = 0.1,
                     unit: str = "frames") -> Progress:
    """A ``progress(done, total)`` callable that reports on ``stream`` (default stderr).

    On a terminal it redraws one line in place (a bar, frames, frames per
    second and time left), at most every ``interval`` seconds, and ends the
    line when done. Elsewhere (a log file, a pipe) it writes one plain line
    at each quarter — 25 %, 50 %, 75 %, 100 % — so logs stay short. ``unit``
    names what is counted (``"steps"`` when a video is written with tables:
    :func:`engine.outputs.speech_files.write_speech_files` counts a frame or
    a file as one step).
    """
    speed = "fps" if unit == "frames" else f"{unit}/s"
    out = stream if stream is not None else sys.stderr
    tty = bool(getattr(out, "isatty", lambda: False)())
    state: dict[str, Any] = {"start": None, "last": 0.0, "quarter": 0}

    def report(done: int, total: int) -> None:
        now = time.perf_counter()
        if state["start"] is None or done == 0:
            state["start"], state["last"], state["quarter"] = now, 0.0, 0
        total = max(int(total), 1)
        if tty:
            if done < total and now - state["last"] < interval:
                return
            state["last"] = now
            elapsed = now - state["start"]
            rate = done / elapsed if elapsed > 0 and done else 0.0
            left = (total - done) / rate if rate else 0.0
            filled = int(24 * done / total)
            line = (f"\r{label} [{'#' * filled}{'.' * (24 - filled)}] {100 * done // total:3d}% "
                    f"{done}/{total} {unit}")
            if rate:
                line += f", {rate:.1f} {speed}, {int(left) // 60}:{int(left) % 60:02d} left"
            out.write(line + ("\n" if done >= total else "\x1b[K"))
            out.flush()
        else:
            quarter = 4 * done // total
            if quarter > state["quarter"]:
                state["quarter"] = quarter
                out.write(f"{label}: {25 * quarter}% ({done}/{total} {unit})\n")
                out.flush()

    return report
