"""One file judged: a still picture or a video, against what it was meant to show.

A still is looked at once (:func:`engine.validation.faces.look`). A video is looked at frame by
frame: faces found (frames where the face was lost are counted), the emotion probabilities of
every frame averaged over the frames with a face, the lip aperture of every frame compared with
the engine's intended lip gap, and the identity descriptor averaged over a few frames spread
over the video (:mod:`engine.validation.video`). Nothing here raises on a bad file: its
:class:`Verdict` carries a plain ``status`` instead.

>>> from skimage import data                                       # doctest: +SKIP
>>> verdict = judge_pixels(data.astronaut(), "astronaut", Intended(emotion="happy"))   # doctest: +SKIP
>>> verdict.status, verdict.judged, verdict.intended_probability > 0.9                 # doctest: +SKIP
('ok', 'happy', True)
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.validation.faces import Seen, look
from engine.validation.intended import Intended
from engine.validation.lips import LipCheck, LipTrack, compare_lips
from engine.validation.media import MediaError, Picture, Video, open_media
from engine.validation.observers import EMOTIONS, Observers, ObserversMissing, observers
from engine.validation.video import FrameJudge

Progress = Callable[[int, int], None]


@dataclass
class Verdict:
    """What the observers said of one file (``status`` "ok", or why not)."""

    file: str
    kind: str
    intended: Intended
    status: str = "ok"
    faces: int = 0
    face_score: float | None = None
    detector: str = ""
    emotions: np.ndarray | None = None
    descriptor: np.ndarray | None = None
    lip_aperture: float | None = None
    eye_opening: float | None = None
    brow_height: float | None = None
    frames: int = 0
    frames_lost: int = 0
    lips: LipCheck | None = None
    aperture_trace: tuple[np.ndarray, np.ndarray, np.ndarray | None] | None = None
    """A video's (times ms, pixel aperture, intended gap mm or None), for the report's traces."""
    identity_own: float | None = None
    identity_reference: str = ""
    nearest_other: str = ""
    nearest_other_distance: float | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def judged(self) -> str | None:
        return None if self.emotions is None else EMOTIONS[int(np.argmax(self.emotions))]

    @property
    def judged_probability(self) -> float | None:
        return None if self.emotions is None else float(np.max(self.emotions))

    @property
    def intended_probability(self) -> float | None:
        if self.emotions is None or self.intended.emotion not in EMOTIONS:
            return None
        return float(self.emotions[EMOTIONS.index(self.intended.emotion)])

    @property
    def read_as_intended(self) -> bool | None:
        """True or False where an emotion was meant and a face judged, else None."""
        if self.intended.emotion is None or self.emotions is None:
            return None
        return self.judged == self.intended.emotion


def judge_file(path: str | Path, intended: Intended | None = None, lips: LipTrack | None = None,
               detector: str = "auto", eyes: Observers | None = None, progress: Progress | None = None) -> Verdict:
    """The verdict on the picture or video in ``path`` (``lips``: the engine's intended lip gap)."""
    intended = intended or Intended()
    try:
        media = open_media(path)
    except MediaError as exc:
        return Verdict(str(path), "?", intended, status=exc.message)
    eyes = eyes or observers()
    if isinstance(media, Picture):
        return judge_pixels(media.pixels, str(path), intended, detector, eyes)
    return _judge_video(media, intended, lips, eyes, progress)


def judge_pixels(rgb: np.ndarray, name: str, intended: Intended | None = None, detector: str = "auto",
                 eyes: Observers | None = None) -> Verdict:
    """The verdict on one picture already in memory ((H, W, 3) uint8 RGB), named ``name``."""
    seen = look(rgb, detector=detector, eyes=eyes)
    verdict = Verdict(name, "image", intended or Intended(), status=_face_status(seen.faces))
    _take(verdict, seen)
    return verdict


def _judge_video(video: Video, intended: Intended, lips: LipTrack | None, eyes: Observers,
                 progress: Progress | None) -> Verdict:
    judge = FrameJudge(eyes, video.fps, video.declared_frames)
    for n, frame in enumerate(video.frames()):
        judge.add(frame)
        if progress is not None:
            progress(n + 1, video.declared_frames)
    verdict = video_verdict(judge, str(video.path), intended, lips, video.declared_frames)
    verdict.notes.extend(video.problems)
    if verdict.status == "ok" and video.problems:
        verdict.status = "decoded with errors"
    return verdict


def judge_frames(frames: Iterable[np.ndarray], fps: float, name: str, intended: Intended | None = None,
                 lips: LipTrack | None = None, eyes: Observers | None = None) -> Verdict:
    """The verdict on a video's frames already in memory (a stimulus being made), named ``name``."""
    frames = list(frames) if not isinstance(frames, list) else frames
    judge = FrameJudge(eyes or observers(), fps, len(frames))
    for frame in frames:
        judge.add(frame)
    return video_verdict(judge, name, intended or Intended(), lips, len(frames))


def video_verdict(judge: FrameJudge, name: str, intended: Intended, lips: LipTrack | None,
                  declared: int = 0) -> Verdict:
    """The verdict from a video's looked-at frames."""
    verdict = Verdict(name, "video", intended, frames=judge.frames, frames_lost=judge.lost)
    if not judge.frames:
        verdict.status = "no frames could be decoded"
        return verdict
    if judge.best is None:
        verdict.status = "no face in any frame"
        return verdict
    verdict.faces = judge.faces()
    verdict.face_score, verdict.detector = judge.best.score, judge.best.detector
    probabilities = [look.emotions for look in judge.looks if look.emotions is not None]
    verdict.emotions = np.mean(probabilities, axis=0) if probabilities else None
    verdict.descriptor = np.mean(judge.descriptors, axis=0) if judge.descriptors else None
    aperture = np.array([np.nan if look.aperture is None else look.aperture for look in judge.looks])
    times = np.arange(len(aperture)) * 1000.0 / judge.fps
    verdict.lips = compare_lips(aperture, times, lips)
    verdict.aperture_trace = (times, aperture, None if lips is None else lips.at(times))
    verdict.lip_aperture = float(np.nanmedian(aperture))
    if judge.best_measures is not None:
        verdict.eye_opening, verdict.brow_height = judge.best_measures.eye_opening, judge.best_measures.brow_height
    problems = []
    if verdict.faces > 1:
        problems.append(f"{verdict.faces} faces (the most certain judged)")
    if declared and verdict.frames < declared:
        problems.append(f"cut short: {verdict.frames} of {declared} frames decoded")
    if verdict.frames_lost:
        problems.append(f"face lost in {verdict.frames_lost} of {verdict.frames} frames")
    verdict.status = "; ".join(problems) or "ok"
    return verdict


def _take(verdict: Verdict, seen: Seen) -> None:
    if not seen.detections:
        return
    verdict.faces = seen.faces
    verdict.face_score, verdict.detector = seen.detections[0].score, seen.detections[0].detector
    verdict.emotions, verdict.descriptor = seen.emotions, seen.descriptor
    if seen.measures is not None:
        verdict.lip_aperture = seen.measures.lip_aperture
        verdict.eye_opening, verdict.brow_height = seen.measures.eye_opening, seen.measures.brow_height


def _face_status(faces: int) -> str:
    if faces == 0:
        return "no face"
    return "ok" if faces == 1 else f"{faces} faces (the most certain judged)"


def safe_judge(path: str | Path, intended: Intended | None = None, lips: LipTrack | None = None,
               detector: str = "auto", eyes: Observers | None = None, progress: Progress | None = None) -> Verdict:
    """:func:`judge_file`, with any :class:`UserError` (a video program missing, a bad landmarks
    table) turned into the file's status: one bad file never stops a run."""
    try:
        return judge_file(path, intended, lips, detector, eyes, progress)
    except ObserversMissing:
        raise
    except UserError as exc:
        return Verdict(str(path), "?", intended or Intended(), status=exc.message)
