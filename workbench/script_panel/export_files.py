"""Writing one spoken utterance to files, all or nothing (no Qt here).

The script panel's "Export speech…" writes any of: the video with its audio
(MP4), the audio (WAV), the phones, the tracks and the landmarks (CSV), with
the engine's own writers (the same ones ``artificial-person say`` uses). Each
file is first written under a hidden temporary name in the target folder;
only when every one is complete are they renamed into place. Cancelling or
failing half-way leaves nothing behind, and files of the same names that
were there before stay untouched.

>>> plan = ExportPlan(Path("out"), "hello", {"mp4", "wav", "tracks"}, fps=30)
>>> [p.name for p in plan.paths().values()]
['hello.mp4', 'hello.wav', 'hello-tracks.csv']
>>> export_speech(plan, speech, model)          # doctest: +SKIP
[PosixPath('out/hello.mp4'), PosixPath('out/hello.wav'), PosixPath('out/hello-tracks.csv')]
"""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from engine.errors import UserError

#: kind → (file name after the base name, what it holds); the order files are written and listed in
KINDS: dict[str, tuple[str, str]] = {
    "mp4": (".mp4", "video with audio (H.264 + AAC)"),
    "wav": (".wav", "audio (16-bit PCM)"),
    "phones": ("-phones.csv", "phones: start_ms,end_ms,phone,word"),
    "tracks": ("-tracks.csv", "tracks: every parameter at every frame"),
    "landmarks": ("-landmarks.csv", "landmarks: positions (mm) at every frame"),
}

Progress = Callable[[int, int], None]


class ExportCancelled(Exception):
    """The user cancelled the export; nothing was written."""


@dataclass
class ExportPlan:
    """Which files to write, where, and how the frames are sampled.

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


def export_speech(plan: ExportPlan, speech, model, progress: Progress | None = None,
                  cancelled: Callable[[], bool] = lambda: False) -> list[Path]:
    """Write the files of ``plan`` for ``speech`` (:class:`engine.speech.say.Speech`) on ``model``.

    ``progress(done, total)`` is called as work is done (video frames count one
    each, every other file one); ``cancelled()`` is asked between frames and
    files — when it says yes, everything written so far is removed and
    :class:`ExportCancelled` is raised. Returns the paths written.
    """
    plan.check()
    targets = plan.paths()
    times = speech.frame_times(plan.fps)
    frames = len(times) if "mp4" in targets else 0
    total = frames + len(targets) - (1 if frames else 0)
    done = 0
    staged: dict[Path, str] = {}

    def report(step: int = 1) -> None:
        nonlocal done
        done += step
        if progress is not None:
            progress(done, total)
        if cancelled():
            raise ExportCancelled()

    def temporary(target: Path) -> str:
        fd, name = tempfile.mkstemp(prefix=f".{target.stem}.", suffix=target.suffix, dir=target.parent)
        os.close(fd)
        staged[target] = name
        return name

    try:
        if progress is not None:
            progress(0, total)
        for kind, target in targets.items():
            if cancelled():
                raise ExportCancelled()
            _write(kind, temporary(target), speech, model, plan, times,
                   lambda n, _count: report(0) if n == 0 else report())
            if kind != "mp4":
                report()
        for target, name in staged.items():
            os.chmod(name, 0o666 & ~_umask())
            os.replace(name, target)
        staged.clear()
    except OSError as exc:
        raise UserError(f"cannot write: {exc.strerror or exc}", file=getattr(exc, "filename", None)
                        or plan.folder) from None
    finally:
        for name in staged.values():
            try:
                os.unlink(name)
            except OSError:
                pass
    return list(targets.values())


def _write(kind: str, path: str, speech, model, plan: ExportPlan, times, frame_progress: Progress) -> None:
    if kind == "mp4":
        from engine.outputs.video import write_video

        values = speech.timeline.sample(times)
        write_video(path, model, times, values, speech.timeline.parameters, plan.fps,
                    audio=speech.utterance.samples, sample_rate=speech.utterance.sample_rate,
                    size=tuple(plan.size), view=plan.view, progress=frame_progress)
    elif kind == "wav":
        from engine.speech.synthesis import write_wav

        write_wav(path, speech.utterance)
    elif kind == "phones":
        from engine.speech.synthesis import write_phones_csv

        write_phones_csv(path, speech.utterance)
    elif kind == "tracks":
        speech.timeline.write_tracks(path, fps=plan.fps, end=float(times[-1]))
    elif kind == "landmarks":
        from engine.speech.say import write_landmarks

        write_landmarks(path, speech, model, plan.fps)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
