"""Landmarks found by themselves on a front photograph: dlib's face detector and its 68-point predictor.

The observers of :mod:`engine.validation.observers` (the ``validate`` extra)
find the face (HOG, then the CNN detector where HOG finds none) and its 68
iBUG points; :func:`engine.photofit.face_points.ibug_pixels` turns them into
the ids a landmark file holds (MPEG-4 points and ``ibug.N``).
:func:`write_points` writes them as POINTS.json, the file ``--landmarks``
reads, so a user can correct them and fit again.

What is refused, each as one :class:`~engine.photofit.errors.PhotoFitError`
naming the photograph: no face; more than one face of a usable size (the
fit would not know whose head to make); a face smaller than
:data:`MIN_FACE_PX` (too few pixels to place 68 points on).

dlib's detector and predictor are frontal models: they find no profile, so
a side photograph's points are not found by themselves
(:func:`engine.photofit.fit.find_points` refuses it; ``docs/photofit.md``).
"""

from __future__ import annotations

import json
from collections.abc import Collection
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from engine.formats.atomic import atomic_write_text
from engine.photofit.errors import PhotoFitError
from engine.photofit.face_points import ibug_pixels

MIN_FACE_PX = 80
"""The smallest face box (side, pixels of the photograph) whose points are placed: dlib's HOG detector is trained
on faces of 80 pixels, and below it the 68 points are a few pixels apart."""
HINT = "or place the points yourself (the workbench's photo wizard, or --landmarks POINTS.json)"


@dataclass(frozen=True)
class FoundFace:
    """The face found: dlib's 68 points (68, 2) px, its box (left, top, right, bottom) px, the detector's score
    and detector, and the landmark file's ids → pixels made from the points."""

    points: np.ndarray
    box: tuple[float, float, float, float]
    score: float
    detector: str
    pixels: dict[str, tuple[float, float]]

    @property
    def size(self) -> float:
        """The face box's side, pixels."""
        return float(min(self.box[2] - self.box[0], self.box[3] - self.box[1]))


def find_face_points(photo: np.ndarray, known: Collection[str] | None = None,
                     path: str | Path | None = None, hint: str = HINT) -> FoundFace:
    """The one face in the (H, W, 3) uint8 front ``photo`` and its points (ids in ``known`` only).

    Raises :class:`PhotoFitError` (naming ``path``, ending with ``hint``: what the user can do instead) when
    there is no face, more than one face of at least :data:`MIN_FACE_PX`, or only a smaller one; and when the
    ``validate`` extra is not installed.
    """
    from engine.validation.observers import ObserversMissing, observers

    try:
        eyes = observers()
    except ObserversMissing as exc:
        raise PhotoFitError(f"finding landmarks by themselves needs dlib: {exc.message}; {hint}", file=path) from None
    from engine.validation.faces import find_faces

    rgb = np.ascontiguousarray(photo[..., :3], dtype=np.uint8)
    faces = find_faces(rgb, "auto", True, eyes)
    if not faces:
        raise PhotoFitError("no face found in the photograph (dlib's frontal face detector): use a photograph of "
                            f"one face seen from the front, {hint}", file=path)
    sizes = [min(d.box[2] - d.box[0], d.box[3] - d.box[1]) for d in faces]
    usable = [d for d, s in zip(faces, sizes, strict=True) if s >= MIN_FACE_PX]
    if len(usable) > 1:
        raise PhotoFitError(f"{len(usable)} faces found in the photograph: crop it to the one face to fit, {hint}",
                            file=path)
    if not usable:
        raise PhotoFitError(f"the face is {max(sizes):.0f} px across, too small to place its points on (at least "
                            f"{MIN_FACE_PX} px): use a larger or closer photograph, {hint}", file=path)
    face = usable[0]
    points = eyes.landmarks(rgb, face.box)
    return FoundFace(points, face.box, face.score, face.detector, ibug_pixels(points, known))


def landmarks_path(output: str | Path) -> Path:
    """Where the points found for the model file ``output`` are written: ``PERSON.xml`` → ``PERSON-landmarks.json``."""
    output = Path(output)
    return output.with_name(f"{output.stem}-landmarks.json")


def write_points(path: str | Path, points: dict[str, dict[str, tuple[float, float]]]) -> Path:
    """Write POINTS.json (view → id → [x, y], rounded to 0.01 px) atomically; returns the path."""
    path = Path(path)
    views = [f'  {json.dumps(view)}: {{\n' + ",\n".join(f"    {json.dumps(k)}: [{round(x, 2)}, {round(y, 2)}]"
                                                         for k, (x, y) in pts.items()) + "\n  }"
             for view, pts in points.items()]
    text = "{\n" + ",\n".join(views) + "\n}\n"                  # one point a line, to correct by hand
    atomic_write_text(path, text, PhotoFitError)
    return path
