"""The files of one spoken utterance, written all together or not at all.

An utterance (:class:`engine.speech.say.Speech`) becomes any of: the video
with its audio (MP4), the audio alone (WAV), the low-level commands (XML),
the phones, the tracks and the landmarks (CSV).
:func:`write_speech_files` writes them: the timeline is sampled once, at the
video's frames, and the video, the tracks and the landmarks all show those
same samples. Every file goes to a hidden temporary name beside its target
first; only when every one is complete are they renamed into place
(:func:`engine.formats.atomic.atomic_files`). An error, a cancel or Ctrl-C
half-way leaves nothing behind, and files of the same names that were there
before stay untouched.

``artificial-person say`` and the workbench's Export speech… both call it;
:class:`ExportPlan` is the workbench's way of naming the files: one folder,
one base name, a suffix per kind.

>>> plan = ExportPlan(Path("out"), "hello", {"mp4", "wav", "tracks"}, fps=30)
>>> [p.name for p in plan.paths().values()]
['hello.mp4', 'hello.wav', 'hello-tracks.csv']
>>> write_speech_files(speech, model, {"mp4": "hello.mp4", "tracks": "hello.csv"}, fps=30)   # doctest: +SKIP
[PosixPath('hello.mp4'), PosixPath('hello.csv')]
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from engine.errors import UserError
from engine.formats.atomic import atomic_files
from engine.model.model import Model
from engine.outputs.data_files import FrameData, write_data_file
from engine.outputs.video_writer import Progress, VideoRequest, check_video, encode_video

if TYPE_CHECKING:
    from engine.outputs.looks import Look
    from engine.speech.say import Speech

#: Every kind of file, in the order they are written, with what each holds.
SPEECH_FILE_KINDS: dict[str, str] = {
    "mp4": "video with audio (H.264 + AAC)",
    "wav": "audio (16-bit PCM)",
    "xml": "low-level commands",
    "phones": "phones: start_ms,end_ms,phone,word",
    "tracks": "tracks: every parameter at every frame",
    "landmarks": "landmarks: positions (mm) at every frame",
}
#: The kinds Export speech… offers: kind → (file name after the base name, what it holds), in order.
KINDS: dict[str, tuple[str, str]] = {
    kind: (suffix, SPEECH_FILE_KINDS[kind])
    for kind, suffix in (("mp4", ".mp4"), ("wav", ".wav"), ("phones", "-phones.csv"), ("tracks", "-tracks.csv"),
                         ("landmarks", "-landmarks.csv"))
}


class ExportCancelled(Exception):
    """The user cancelled the writing; nothing was written."""


def write_speech_files(speech: Speech, model: Model, targets: Mapping[str, str | Path], fps: float = 30.0,
                       size: tuple[int, int] = (640, 480), view: str = "front", progress: Progress | None = None,
                       cancelled: Callable[[], bool] | None = None, antialias: bool | None = None,
                       look: str | Look | None = None, encoding: object = None) -> list[Path]:
    """Write the files ``targets`` names (kind → path) for ``speech`` on ``model``, all or nothing.

    Kinds (:data:`SPEECH_FILE_KINDS`): ``mp4``, ``wav``, ``xml``, ``phones``,
    ``tracks``, ``landmarks``. ``fps`` (frames per second) applies to the
    video, the tracks and the landmarks, which all have frame ``n`` at
    ``n·1000/fps`` ms, until the speech ends (:meth:`Speech.frame_times`);
    ``size`` (width, height in pixels, even), ``view``, ``antialias``, ``look`` and
    ``encoding`` are the video's (:func:`engine.outputs.video_writer.write_video`). The WAV is
    the speech alone; the video's audio is padded with silence to its length.

    ``progress(done, total)`` is called before anything is written and as
    work is done: a video frame counts one step, every other file one.
    ``cancelled()`` is asked between frames and files; when it says yes,
    everything written so far is removed and :class:`ExportCancelled` is
    raised. Bad arguments raise :class:`~engine.errors.UserError` before
    anything is written. Returns the paths written, in kind order.
    """
    unknown = sorted(set(targets) - set(SPEECH_FILE_KINDS))
    if unknown:
        raise UserError(f"unknown kind of speech file: {', '.join(unknown)} (use {', '.join(SPEECH_FILE_KINDS)})")
    if not targets:
        raise UserError("nothing to write: name at least one file")
    if not (fps > 0 and math.isfinite(fps)):
        raise UserError(f"frames per second must be a positive number (got {fps:g})")
    paths = {kind: Path(targets[kind]) for kind in SPEECH_FILE_KINDS if kind in targets}
    for kind, path in paths.items():
        if kind != "mp4" and path.suffix.lower() != _SUFFIX[kind]:
            raise UserError(f"unknown extension '{path.suffix or path.name}' for the {kind} "
                            f"(use {_SUFFIX[kind]})", file=path)
    times = speech.frame_times(fps)
    values = speech.timeline.sample(times)             # the one sampling every file shows
    video: VideoRequest | None = None
    if "mp4" in paths:
        video = check_video(paths["mp4"], model, times, values, speech.timeline.parameters, fps,
                            audio=speech.utterance.samples, sample_rate=speech.utterance.sample_rate,
                            size=size, view=view, look=look, encoding=encoding)
    data = FrameData(speech.timeline.parameters, times, values, speech.utterance, model, speech.activations)
    steps = _Steps(len(times) * (video is not None) + len(paths) - (video is not None), progress, cancelled)
    steps.start()
    with atomic_files(paths.values()) as temporary:
        for kind, path in paths.items():
            steps.check()
            destination = temporary[path]
            if video is not None and kind == "mp4":
                encode_video(video, destination, steps.frame, antialias)
                continue
            write_data_file(kind, destination, data)
            steps.advance()
    return list(paths.values())


_SUFFIX = {"mp4": ".mp4", "wav": ".wav", "xml": ".xml", "phones": ".csv", "tracks": ".csv", "landmarks": ".csv"}


class _Steps:
    """Progress in steps (a frame or a file each) and the cancel check between them."""

    def __init__(self, total: int, progress: Progress | None, cancelled: Callable[[], bool] | None):
        self.total, self.done = total, 0
        self.progress, self.cancelled = progress, cancelled

    def start(self) -> None:
        if self.progress is not None:
            self.progress(0, self.total)

    def check(self) -> None:
        if self.cancelled is not None and self.cancelled():
            raise ExportCancelled()

    def advance(self) -> None:
        self.done += 1
        if self.progress is not None:
            self.progress(self.done, self.total)
        self.check()

    def frame(self, done: int, _count: int) -> None:
        """The video's own progress: frame 0 is its start (only a cancel check), then one step a frame."""
        if done == 0:
            self.check()
        else:
            self.advance()


@dataclass
class ExportPlan:
    """Which files Export speech… writes, where, and how the frames are sampled.

    ``size`` is the video's (width, height) in pixels (even numbers);
    ``fps`` applies to the video, the tracks and the landmarks.
    """

    folder: Path
    base: str
    kinds: set[str] = field(default_factory=lambda: set(KINDS))
    fps: float = 30.0
    size: tuple[int, int] = (640, 480)
    view: str = "front"

    def paths(self) -> dict[str, Path]:
        """The file each chosen kind is written to, in :data:`KINDS` order."""
        return {kind: Path(self.folder) / f"{self.base}{KINDS[kind][0]}" for kind in KINDS if kind in self.kinds}

    def check(self) -> None:
        """A :class:`UserError` for a plan that cannot be written (nothing chosen, no folder, a bad name)."""
        if not self.kinds:
            raise UserError("nothing to export: choose at least one file")
        unknown = set(self.kinds) - set(KINDS)
        if unknown:
            raise UserError(f"unknown export kind(s): {', '.join(sorted(unknown))}")
        base = self.base.strip()
        if not base or "/" in base or os.sep in base or base in (".", ".."):
            raise UserError(f"'{self.base}' is not a file name (no folders, not empty)")
        if not Path(self.folder).is_dir():
            raise UserError("the folder does not exist", file=self.folder)
        if not self.fps > 0:
            raise UserError(f"frames per second must be positive (got {self.fps:g})")
        width, height = self.size
        if width % 2 or height % 2 or width < 16 or height < 16:
            raise UserError(f"the video size must be even numbers of at least 16 pixels (got {width}x{height})")


def export_speech(plan: ExportPlan, speech: Speech, model: Model, progress: Progress | None = None,
                  cancelled: Callable[[], bool] | None = None) -> list[Path]:
    """Check ``plan`` and write its files (:func:`write_speech_files`); returns the paths written."""
    plan.check()
    width, height = plan.size
    return write_speech_files(speech, model, plan.paths(), plan.fps, (width, height), plan.view, progress, cancelled)
