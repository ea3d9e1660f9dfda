"""What the 68 landmarks of a face say: lip aperture, mouth width, eye opening, brow height.

Every measure is a length in the picture divided by the inter-ocular distance (between the
centres of the two eyes), so it does not depend on the picture's size or the face's distance
(an adult's inter-ocular distance is about 63 mm: an aperture of 0.2 is about 13 mm). The
points are dlib's iBUG 300-W scheme, numbered from 0: jaw 0–16, brows 17–26, nose 27–35,
eyes 36–47, outer lips 48–59, inner lips 60–67.

>>> import numpy as np
>>> points = np.zeros((68, 2))
>>> points[36:42] = [[0, 0], [1, -1], [2, -1], [3, 0], [2, 1], [1, 1]]     # one eye, 3 wide, 2 open
>>> points[42:48] = points[36:42] + [10, 0]                               # the other, 10 to the right
>>> points[62], points[66] = [5, 20], [5, 22]                             # inner lips 2 apart
>>> m = face_measures(points)
>>> round(m.interocular, 3), round(m.lip_aperture, 3), round(m.eye_opening, 3)
(10.0, 0.2, 0.667)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

LEFT_EYE = slice(36, 42)       # the subject's right eye (left in the picture)
RIGHT_EYE = slice(42, 48)
INNER_UPPER_LIP, INNER_LOWER_LIP = 62, 66
MOUTH_CORNERS = (48, 54)
BROWS = (slice(17, 22), slice(22, 27))

EMOTION_BOX_SIDE = 1.2 * (1 + 2 * 0.033)
EMOTION_BOX_RAISE = 0.21
CLOSED_APERTURE = 0.04
"""Inner lips this close (in inter-ocular distances, about 2.5 mm on an adult) count as closed."""


@dataclass(frozen=True)
class FaceMeasures:
    """Sizes of one face, each in inter-ocular distances (``interocular`` itself in pixels)."""

    interocular: float
    lip_aperture: float
    mouth_width: float
    eye_opening: float
    brow_height: float


def face_measures(points: np.ndarray) -> FaceMeasures:
    """The measures of a face from its 68 points (68, 2)."""
    p = np.asarray(points, dtype=float)
    left, right = p[LEFT_EYE], p[RIGHT_EYE]
    iod = float(np.linalg.norm(left.mean(axis=0) - right.mean(axis=0))) or 1.0
    aperture = float(np.linalg.norm(p[INNER_UPPER_LIP] - p[INNER_LOWER_LIP]))
    width = float(np.linalg.norm(p[MOUTH_CORNERS[0]] - p[MOUTH_CORNERS[1]]))
    brows = [float(np.linalg.norm(p[brow].mean(axis=0) - eye.mean(axis=0)))
             for brow, eye in zip(BROWS, (left, right), strict=True)]
    return FaceMeasures(interocular=iod, lip_aperture=aperture / iod, mouth_width=width / iod,
                        eye_opening=(_eye_aspect(left) + _eye_aspect(right)) / 2,
                        brow_height=float(np.mean(brows)) / iod)


def emotion_box(points: np.ndarray) -> tuple[float, float, float, float]:
    """The square the emotion classifier looks at (left, top, right, bottom), placed from the points
    where the classifier's own face finder would put it.

    The classifier was trained on FER2013's faces and is run (by its authors) on the boxes of
    OpenCV's Haar face detector grown by 10 pixels a side. On 15 faces in 14 real photographs
    (docs/validation.md) that box is, against the box of the jaw line (0–16) across and the brows
    (17–26) to the chin (8) down: centred across, its centre 0.21 of the height higher, its side
    1.20 times the box's mean side; the 10 pixels are about 3.3 % of a side more each side.
    """
    p = np.asarray(points, dtype=float)
    left, right = p[0:17, 0].min(), p[0:17, 0].max()
    top, bottom = p[17:27, 1].min(), p[8, 1]
    width, height = right - left, bottom - top
    side = EMOTION_BOX_SIDE * (width + height) / 2
    cx, cy = (left + right) / 2, (top + bottom) / 2 - EMOTION_BOX_RAISE * height
    return (cx - side / 2, cy - side / 2, cx + side / 2, cy + side / 2)


def _eye_aspect(eye: np.ndarray) -> float:
    """Lid opening over eye width (the 'eye aspect ratio'): about 0.3 open, under 0.1 shut."""
    width = float(np.linalg.norm(eye[0] - eye[3])) or 1.0
    opening = (np.linalg.norm(eye[1] - eye[5]) + np.linalg.norm(eye[2] - eye[4])) / 2
    return float(opening) / width
