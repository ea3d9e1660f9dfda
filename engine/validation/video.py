"""The frames of a video looked at in turn, cheaply: found once, followed, found again.

The face is looked for (dlib's HOG detector) in the first frame, then every
:data:`DETECT_EVERY` frames and in every frame after one where it was not found; in between its
68 points are found from the box of the last detection moved with the face (the shape
predictor takes 2 ms where the detector takes 15–60). A frame counts as *lost* when the detector
ran and found no face in it, or when it lies between such a frame and the next detection. Every
frame gets its lip aperture and its seven emotion probabilities; :data:`DESCRIBED_FRAMES` frames
spread over the video give the identity descriptor (0.1–0.3 s each).

>>> from engine.validation.video import FrameJudge
>>> judge = FrameJudge(fps=30.0, declared_frames=90)                       # doctest: +SKIP
>>> for frame in frames: judge.add(frame)                                  # doctest: +SKIP
>>> judge.frames, judge.lost                                               # doctest: +SKIP
(90, 0)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.validation.faces import emotion_face, find_faces
from engine.validation.measures import FaceMeasures, face_measures
from engine.validation.observers import Detection, Observers

DETECT_EVERY = 5
"""Frames between two runs of the face detector while the face is followed."""
DESCRIBED_FRAMES = 4
"""A video's identity is the mean descriptor of this many frames spread over it."""
JUMP = 0.5
"""A followed face whose points move more than this share of the face's width from one frame to the
next is looked for again at once (a cut, a face that moved away)."""


@dataclass
class FrameLook:
    """One frame's measures (None where the face was lost)."""

    aperture: float | None
    emotions: np.ndarray | None


class FrameJudge:
    """Takes a video's frames one by one (:meth:`add`) and keeps what the verdict needs."""

    def __init__(self, eyes: Observers, fps: float, declared_frames: int = 0):
        self.eyes = eyes
        self.fps = fps if fps > 0 else 30.0
        self.step = max(1, declared_frames // DESCRIBED_FRAMES) if declared_frames > 0 else int(self.fps)
        self.looks: list[FrameLook] = []
        self.descriptors: list[np.ndarray] = []
        self.counts: list[int] = []           # faces the detector found, where it ran (−1: followed)
        self.best: Detection | None = None
        self.best_measures: FaceMeasures | None = None
        self._box: tuple[float, float, float, float] | None = None
        self._box_centre = np.zeros(2)            # the points' centre when the box was detected
        self._points: np.ndarray | None = None
        self._since_detection = 0

    @property
    def frames(self) -> int:
        return len(self.looks)

    @property
    def lost(self) -> int:
        return sum(1 for look in self.looks if look.aperture is None)

    def add(self, rgb: np.ndarray) -> FrameLook:
        """Look at the next frame."""
        n = len(self.looks)
        box = self._follow(rgb)
        if box is None:
            look = FrameLook(None, None)
        else:
            points: np.ndarray | None = self.eyes.landmarks(rgb, box)
            if self._points is not None and points is not None and self._jumped(points):
                box = self._detect(rgb)
                points = self.eyes.landmarks(rgb, box) if box is not None else None
            if points is None:
                look = FrameLook(None, None)
            else:
                if self._since_detection == 0:
                    self._box_centre = points.mean(axis=0)
                self._points = points
                measures = face_measures(points)
                if self.best_measures is None or self._since_detection == 0:
                    self.best_measures = measures
                look = FrameLook(measures.lip_aperture, self.eyes.emotions(emotion_face(rgb, points)))
                if n % self.step == 0 and len(self.descriptors) < DESCRIBED_FRAMES:
                    self.descriptors.append(self.eyes.descriptor(rgb, points))
        self.looks.append(look)
        return look

    def _follow(self, rgb: np.ndarray) -> tuple[float, float, float, float] | None:
        """The box to find the points in: a new detection when due, else the last box moved with the face."""
        due = self._box is None or self._since_detection >= DETECT_EVERY - 1
        if due:
            return self._detect(rgb)
        self._since_detection += 1
        assert self._box is not None and self._points is not None
        dx, dy = self._points.mean(axis=0) - self._box_centre
        left, top, right, bottom = self._box
        return (left + dx, top + dy, right + dx, bottom + dy)

    def _detect(self, rgb: np.ndarray) -> tuple[float, float, float, float] | None:
        found = find_faces(rgb, "hog", still=False, eyes=self.eyes)
        self.counts.append(len(found))
        self._since_detection = 0
        if not found:
            self._box, self._points = None, None
            return None
        if self.best is None or found[0].score > self.best.score:
            self.best = found[0]
        self._box = found[0].box
        return self._box

    def _jumped(self, points: np.ndarray) -> bool:
        assert self._points is not None
        width = float(np.ptp(self._points[:, 0])) or 1.0
        return float(np.abs(points.mean(axis=0) - self._points.mean(axis=0)).max()) > JUMP * width

    def faces(self) -> int:
        """The usual number of faces where the detector found any (the median)."""
        found = [c for c in self.counts if c > 0]
        return int(np.median(found)) if found else 0
