"""Talking-head video: poses rendered offscreen, piped into ffmpeg as H.264 + AAC in MP4.

Frame ``n`` of the video shows the face with the parameter values of row
``n``, which must be the pose at time ``times_ms[n] = times_ms[0] + n·1000/fps``.
Audio sample ``i`` plays at ``i/sample_rate`` s, so the video starts at audio
time ``times_ms[0]`` (normally 0); the audio is cut or padded with silence to
exactly the video's length (``frames/fps``), so both streams start together
and end together (to within one AAC sample).

>>> import numpy as np
>>> from engine import load_model
>>> from engine.outputs.video import write_video, progress_printer, probe, contact_sheet
>>> head = load_model()
>>> times = np.arange(90) * (1000 / 30)                       # 3 s at 30 fps
>>> values = np.sin(times / 300)[:, None] * [0.4, 0.2] + [0.4, 0]
>>> write_video("nod.mp4", head, times, values, ["jaw_open", "head_nod"], fps=30,
...             progress=progress_printer("rendering"))       # doctest: +SKIP
>>> probe("nod.mp4").frames                                    # doctest: +SKIP
90
>>> sheet = contact_sheet("nod.mp4", columns=5, count=10, path="nod.png")   # doctest: +SKIP

Needs the ``ffmpeg`` program (Debian package ``ffmpeg``, which also brings
``ffprobe``); without it the functions here raise :class:`FFmpegMissing`.

Speed: one :class:`~engine.outputs.render.FrameRenderer` draws every frame (the scene
is built once, only the vertex positions and normals change), while ffmpeg
encodes in its own process; a writer thread keeps the pipe to ffmpeg full so
drawing and encoding overlap. ``antialias=False`` (the default here) skips
multisampling, which on a machine without a GPU (Mesa llvmpipe) costs about
three times as much as the rest of the drawing; pass ``antialias=True`` for
frames that look exactly like :func:`engine.outputs.render.render_model`'s pictures.
``benchmarks/bench_video.py`` measures both.
"""

from __future__ import annotations

import json
import math
import os
import queue
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import wave
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from engine.errors import UserError
from engine.outputs.raster import draw_text

FFMPEG_PACKAGE = "ffmpeg"            # Debian package with both ffmpeg and ffprobe
#: H.264 settings: a fast preset (the frames are simple, the machine small), 4:2:0 for every player.
VIDEO_ARGS = ["-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p",
              "-colorspace", "smpte170m"]      # swscale converts RGB → YUV with BT.601: say so
AUDIO_ARGS = ["-c:a", "aac", "-b:a", "96k"]
#: Sample rates the AAC encoder takes; other rates are resampled to the next one up.
AAC_RATES = (7350, 8000, 11025, 12000, 16000, 22050, 24000, 32000, 44100, 48000, 64000, 88200, 96000)
STDERR_LINES = 8                      # how much of ffmpeg's complaint goes into an error message
FRAME_TIME_TOLERANCE = 0.01          # of a frame interval: how far a frame time may be off its slot
QUEUED_FRAMES = 4                     # frames rendered ahead of the encoder


class FFmpegMissing(UserError):
    """The ``ffmpeg`` (or ``ffprobe``) program is not installed."""


class VideoError(UserError):
    """ffmpeg failed, or a video could not be read."""


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


# ---------------------------------------------------------------------------
# Writing

def write_video(path, model, times_ms, values, parameter_names: Sequence[str], fps: float,
                audio=None, sample_rate: int | None = None, size: tuple[int, int] = (640, 480),
                view: str = "front", progress: Callable[[int, int], None] | None = None,
                antialias: bool = False) -> VideoStats:
    """Render one frame per row of ``values`` and write them, with ``audio``, as an MP4.

    Parameters
    ----------
    path : ``*.mp4``
        Written atomically: ffmpeg writes a hidden temporary file beside it,
        which is renamed over ``path`` only when complete. On an error or
        Ctrl-C nothing is left behind (and an existing ``path`` is untouched).
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
    antialias : multisampled drawing (slower without a GPU; see the module notes).

    Returns
    -------
    :class:`VideoStats` (frame count and the time spent in each stage).
    """
    started = time.perf_counter()
    path = Path(path)
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
    count = len(frame_values)
    samples = None
    if audio is not None:
        samples, sample_rate = _check_audio(audio, sample_rate)
        samples = _fit_audio(samples, sample_rate, float(times_ms[0]), count, fps)
    ffmpeg = find_tool("ffmpeg")

    from engine.outputs.render import FrameRenderer

    stats = VideoStats(path=path, frames=count, fps=float(fps))
    deformer = model.deformer()
    tmp = None
    process = None
    writer = None
    log = None
    with tempfile.TemporaryDirectory(prefix="artificial-person-video-") as scratch:
        try:
            command = [ffmpeg, "-hide_banner", "-nostdin", "-nostats", "-loglevel", "error", "-y",
                       "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{width}x{height}",
                       "-framerate", _rate_text(fps), "-i", "pipe:0"]
            if samples is not None:
                wav = Path(scratch) / "audio.wav"
                _write_wav(wav, samples, sample_rate)
                command += ["-i", str(wav), "-map", "0:v:0", "-map", "1:a:0"] + AUDIO_ARGS
                if sample_rate not in AAC_RATES:
                    command += ["-ar", str(next((r for r in AAC_RATES if r >= sample_rate), AAC_RATES[-1]))]
            command += VIDEO_ARGS + ["-movflags", "+faststart", "-f", "mp4"]
            fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
            os.close(fd)
            command.append(tmp)
            with FrameRenderer(model, size=(width, height), view=view, antialias=antialias) as renderer:
                log = open(Path(scratch) / "ffmpeg.log", "w+b")
                cpu_before = _children_cpu()
                process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                           stderr=log, start_new_session=True)   # Ctrl-C reaches us, not it
                writer = _FrameWriter(process.stdin)
                if progress is not None:
                    progress(0, count)
                for n in range(count):
                    t0 = time.perf_counter()
                    positions = deformer.deform(frame_values[n])
                    t1 = time.perf_counter()
                    image = renderer.render(positions)
                    t2 = time.perf_counter()
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
            os.chmod(tmp, 0o666 & ~_umask())
            os.replace(tmp, path)
            tmp = None
        except OSError as exc:
            raise UserError(f"cannot write the video: {exc.strerror or exc}", file=path) from None
        finally:
            if writer is not None:
                writer.abandon()
            if process is not None and process.poll() is None:
                process.kill()
                process.wait()
            if tmp is not None:
                _unlink_quietly(tmp)
            if log is not None:
                log.close()
    stats.total = time.perf_counter() - started
    return stats


class _FrameWriter:
    """A thread that writes frames into ffmpeg's stdin, so drawing the next frame
    overlaps with ffmpeg reading this one."""

    def __init__(self, pipe):
        self.pipe = pipe
        self.error: BaseException | None = None
        self._queue: queue.Queue = queue.Queue(maxsize=QUEUED_FRAMES)
        self._thread = threading.Thread(target=self._run, name="ffmpeg-writer", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while True:
            frame = self._queue.get()
            if frame is None:
                break
            if self.error is not None:
                continue                      # keep draining so put() never blocks forever
            try:
                self.pipe.write(memoryview(frame).cast("B"))
            except (OSError, ValueError) as exc:      # BrokenPipeError: ffmpeg exited
                self.error = exc
        try:
            self.pipe.close()
        except OSError as exc:
            if self.error is None:
                self.error = exc

    def put(self, frame: np.ndarray) -> bool:
        """Queue a frame (waits while the queue is full); False once writing has failed."""
        if self.error is not None:
            return False
        self._queue.put(frame)
        return self.error is None

    def close(self) -> None:
        """No more frames: finish writing and close the pipe (ffmpeg then sees the end)."""
        self._queue.put(None)
        self._thread.join()

    def abandon(self) -> None:
        """After a failure: stop the thread without waiting for ffmpeg (which is then killed)."""
        if self._thread.is_alive():
            self.error = self.error or RuntimeError("abandoned")
            try:
                while True:
                    self._queue.get_nowait()
            except queue.Empty:
                pass
            try:
                self._queue.put_nowait(None)
            except queue.Full:
                pass


def _check_frames(model, times_ms, values, parameter_names, fps):
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


def _check_video_size(size) -> tuple[int, int]:
    from engine.outputs.render import check_size

    width, height = check_size(size)
    if width % 2 or height % 2:
        raise UserError(f"video size {width}x{height}: width and height must be even (H.264, 4:2:0)")
    return width, height


def _check_audio(audio, sample_rate):
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
    first = int(round(start_ms * rate / 1000.0))
    count = int(round(frames * rate / fps))
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


def _ffmpeg_failure(log, code: int, write_error) -> str:
    log.seek(0)
    lines = [line.strip() for line in log.read().decode("utf-8", "replace").splitlines() if line.strip()]
    tail = "; ".join(lines[-STDERR_LINES:])
    if code != 0:
        what = f"ffmpeg failed (exit status {code})"
    else:
        what = f"writing frames to ffmpeg failed ({write_error})"
    return f"{what}: {tail}" if tail else what


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _unlink_quietly(path) -> None:
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass


# ---------------------------------------------------------------------------
# Progress

def progress_printer(label: str = "rendering", stream=None, interval: float = 0.1) -> Callable[[int, int], None]:
    """A ``progress(done, total)`` callable that reports on ``stream`` (default stderr).

    On a terminal it redraws one line in place (a bar, frames, frames per
    second and time left), at most every ``interval`` seconds, and ends the
    line when done. Elsewhere (a log file, a pipe) it writes one plain line
    at each quarter — 25 %, 50 %, 75 %, 100 % — so logs stay short.
    """
    out = stream if stream is not None else sys.stderr
    tty = bool(getattr(out, "isatty", lambda: False)())
    state = {"start": None, "last": 0.0, "quarter": 0}

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
                    f"{done}/{total} frames")
            if rate:
                line += f", {rate:.1f} fps, {int(left) // 60}:{int(left) % 60:02d} left"
            out.write(line + ("\n" if done >= total else "\x1b[K"))
            out.flush()
        else:
            quarter = 4 * done // total
            if quarter > state["quarter"]:
                state["quarter"] = quarter
                out.write(f"{label}: {25 * quarter}% ({done}/{total} frames)\n")
                out.flush()

    return report


# ---------------------------------------------------------------------------
# Reading back (tests, contact sheets)

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


def probe(path) -> Probe:
    """Frame count, frame rate, and the durations and start times of the video and
    audio streams (the first of each), as ffprobe reports them."""
    path = Path(path)
    if not path.is_file():
        raise UserError("no such video file", file=path)
    result = subprocess.run([find_tool("ffprobe"), "-v", "error", "-print_format", "json",
                             "-show_streams", "-show_format", str(path)],
                            capture_output=True, timeout=60)
    if result.returncode != 0:
        raise VideoError(f"ffprobe cannot read it: {_tail(result.stderr)}", file=path)
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


def read_frames(path, indices: Sequence[int] | None = None, size: tuple[int, int] | None = None) -> np.ndarray:
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
    result = subprocess.run(command, capture_output=True, timeout=600)
    if result.returncode != 0:
        raise VideoError(f"ffmpeg cannot decode it: {_tail(result.stderr)}", file=path)
    frame_bytes = width * height * 3
    count = len(result.stdout) // frame_bytes
    return np.frombuffer(result.stdout[:count * frame_bytes], dtype=np.uint8).reshape(count, height, width, 3)


def read_audio(path, sample_rate: int | None = None) -> tuple[np.ndarray, int]:
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
    result = subprocess.run([find_tool("ffmpeg"), "-v", "error", "-nostdin", "-i", str(path), "-map", "0:a:0",
                             "-ac", "1", "-ar", str(rate), "-f", "f32le", "pipe:1"], capture_output=True, timeout=600)
    if result.returncode != 0:
        raise VideoError(f"ffmpeg cannot decode its audio: {_tail(result.stderr)}", file=path)
    samples = np.frombuffer(result.stdout, dtype="<f4")
    if info.audio_duration is not None and math.isfinite(info.audio_duration):
        samples = samples[:int(round(info.audio_duration * rate))]
    return samples.copy(), rate


def find_tool(name: str) -> str:
    """Full path of ``ffmpeg`` or ``ffprobe``, or :class:`FFmpegMissing` naming the Debian package."""
    found = shutil.which(name)
    if found is None:
        raise FFmpegMissing(f"{name} is not installed; it comes with the Debian package {FFMPEG_PACKAGE}: "
                            f"sudo apt-get install {FFMPEG_PACKAGE}")
    return found


def _tail(stderr: bytes) -> str:
    lines = [line.strip() for line in stderr.decode("utf-8", "replace").splitlines() if line.strip()]
    return "; ".join(lines[-STDERR_LINES:]) or "no message"


# ---------------------------------------------------------------------------
# Contact sheet

SHEET_BACKGROUND = (255, 255, 255)
SHEET_TEXT = (40, 40, 40)


def contact_sheet(source, columns: int = 4, count: int = 12, width: int = 200,
                  times_ms: Sequence[float] | None = None, fps: float | None = None,
                  path=None) -> np.ndarray:
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
    if isinstance(source, (str, os.PathLike)):
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
    for k, (image, label) in enumerate(zip(thumbs, labels)):
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
    return sorted({int(round(i * (total - 1) / (count - 1))) for i in range(count)})


def _shrink(image: np.ndarray, factor: int) -> np.ndarray:
    """Average ``factor`` × ``factor`` blocks (the edges that do not fill a block are dropped)."""
    image = np.asarray(image)
    if factor == 1:
        return image.astype(np.uint8, copy=False)
    h, w = (image.shape[0] // factor) * factor, (image.shape[1] // factor) * factor
    blocks = image[:h, :w].reshape(h // factor, factor, w // factor, factor, 3).astype(np.float32)
    return np.round(blocks.mean(axis=(1, 3))).astype(np.uint8)
