"""One picture looked at by the observers: the faces found, the main face's points, measures,
emotion probabilities and identity descriptor.

>>> from skimage import data                                  # doctest: +SKIP
>>> seen = look(data.astronaut())                             # doctest: +SKIP
>>> seen.faces, EMOTIONS[int(seen.emotions.argmax())]         # doctest: +SKIP
(1, 'happy')
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from engine.validation.measures import FaceMeasures, emotion_box, face_measures
from engine.validation.observers import EMOTION_INPUT, EMOTIONS, Detection, Observers, observers

__all__ = ["DETECTORS", "EMOTIONS", "Seen", "look"]

DETECTORS = ("auto", "hog", "cnn")
"""``hog``: dlib's HOG detector (fast, frontal faces); ``cnn``: its CNN detector (slow, any
pose); ``auto``: HOG, then the CNN on a still picture where HOG found no face."""
DETECT_SIDE = 1280
"""Pictures are looked for faces at most this wide or high (a 12-megapixel photograph would take
HOG seconds); the points are then found in the full picture."""
UPSAMPLE_BELOW = 800
"""A picture smaller than this (its longer side) is looked at again, twice as large, when no face
is found at its own size (HOG's smallest face is 80 pixels)."""
CNN_SIDE = 640


@dataclass
class Seen:
    """What the observers saw in one picture. Without a face, only ``detections`` (empty) is set."""

    detections: list[Detection]
    points: np.ndarray | None = None
    measures: FaceMeasures | None = None
    emotions: np.ndarray | None = None
    descriptor: np.ndarray | None = None

    @property
    def faces(self) -> int:
        return len(self.detections)

    @property
    def judged(self) -> str | None:
        """The most probable emotion, or None without a face."""
        return None if self.emotions is None else EMOTIONS[int(np.argmax(self.emotions))]


def look(rgb: np.ndarray, detector: str = "auto", describe: bool = True, still: bool = True,
         eyes: Observers | None = None) -> Seen:
    """The faces in an (H, W, 3) uint8 RGB picture, and everything about the best one.

    ``describe``: compute the identity descriptor (0.1 s a face); ``still``: a still picture (the
    ``auto`` detector then tries the CNN where HOG found nothing; video frames do not)."""
    eyes = eyes or observers()
    detections = find_faces(rgb, detector, still, eyes)
    if not detections:
        return Seen(detections)
    points = eyes.landmarks(rgb, detections[0].box)
    seen = Seen(detections, points=points, measures=face_measures(points),
                emotions=eyes.emotions(emotion_face(rgb, points)))
    if describe:
        seen.descriptor = eyes.descriptor(rgb, points)
    return seen


def find_faces(rgb: np.ndarray, detector: str, still: bool, eyes: Observers) -> list[Detection]:
    """The faces found, best first, boxes in the picture's own pixels."""
    if detector == "cnn":
        return _scaled(rgb, CNN_SIDE, lambda small: eyes.detect(small, "cnn"))
    found = _scaled(rgb, DETECT_SIDE, lambda small: eyes.detect(small, "hog"))
    if not found and max(rgb.shape[:2]) < UPSAMPLE_BELOW:
        found = eyes.detect(rgb, "hog", upsample=1)
    if not found and detector == "auto" and still:
        found = _scaled(rgb, CNN_SIDE, lambda small: eyes.detect(small, "cnn"))
    return found


def emotion_face(rgb: np.ndarray, points: np.ndarray) -> np.ndarray:
    """The 64 × 64 grey face the emotion classifier judges (values 0–255), cut out around the points;
    what lies outside the picture is filled with the picture's mean grey."""
    from PIL import Image

    grey = np.asarray(Image.fromarray(np.ascontiguousarray(rgb)).convert("L"), dtype=np.uint8)
    left, top, right, bottom = (round(v) for v in emotion_box(points))
    height, width = grey.shape
    crop = np.full((bottom - top, right - left), int(grey.mean()), dtype=np.uint8)
    y0, y1, x0, x1 = max(top, 0), min(bottom, height), max(left, 0), min(right, width)
    if y1 > y0 and x1 > x0:
        crop[y0 - top:y1 - top, x0 - left:x1 - left] = grey[y0:y1, x0:x1]
    small = Image.fromarray(crop).resize((EMOTION_INPUT, EMOTION_INPUT), Image.Resampling.BILINEAR)
    return np.asarray(small, dtype=np.uint8)


def _scaled(rgb: np.ndarray, side: int, detect: Callable[[np.ndarray], list[Detection]]) -> list[Detection]:
    """``detect`` run on the picture shrunk to at most ``side`` pixels, boxes scaled back."""
    from PIL import Image

    scale = side / max(rgb.shape[:2])
    if scale >= 1:
        return detect(rgb)
    size = (max(1, round(rgb.shape[1] * scale)), max(1, round(rgb.shape[0] * scale)))
    small = np.asarray(Image.fromarray(np.ascontiguousarray(rgb)).resize(size, Image.Resampling.BILINEAR))
    return [Detection((d.box[0] / scale, d.box[1] / scale, d.box[2] / scale, d.box[3] / scale), d.score, d.detector)
            for d in detect(small)]
