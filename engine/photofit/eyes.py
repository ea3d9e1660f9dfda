"""The eyes' iris colour read from the front photograph around the pupils the user marked.

The default head paints each eyeball with three colours (sclera, iris,
pupil). The iris is recoloured with the median colour of the photograph in
a ring :data:`IRIS_RING` mm around each marked pupil, leaving out
highlights and sclera (bright pixels); with too few pixels left the
default colour stays.

>>> import numpy as np
>>> photo = np.full((40, 40, 3), 250, dtype=np.uint8)
>>> photo[10:30, 10:30] = (40, 90, 60)
>>> iris_colour(photo, (20.0, 20.0), 2.0).tolist()
[40, 90, 60]
"""

from __future__ import annotations

import numpy as np

from engine.model import Model

IRIS_RING = (2.5, 4.5)                 # mm from the pupil's centre: outside the pupil, inside the iris's rim
BRIGHT = 200                           # luminance above which a pixel is a highlight or sclera
FEWEST_PIXELS = 4
PUPILS = {"eye_left": "3.5", "eye_right": "3.6"}


def iris_colour(photo: np.ndarray, pupil: tuple[float, float], px_per_mm: float) -> np.ndarray | None:
    """(3,) uint8 median colour of the iris ring around ``pupil`` (x, y px), or None if too little is seen."""
    height, width = photo.shape[:2]
    inner, outer = IRIS_RING[0] * px_per_mm, IRIS_RING[1] * px_per_mm
    x0, x1 = max(int(pupil[0] - outer), 0), min(int(pupil[0] + outer) + 1, width)
    y0, y1 = max(int(pupil[1] - outer), 0), min(int(pupil[1] + outer) + 1, height)
    if x1 <= x0 or y1 <= y0:
        return None
    ys, xs = np.mgrid[y0:y1, x0:x1]
    distance = np.hypot(xs + 0.5 - pupil[0], ys + 0.5 - pupil[1])
    ring = photo[y0:y1, x0:x1][(distance >= inner) & (distance <= outer)].astype(float)
    ring = ring[ring @ np.array([0.299, 0.587, 0.114]) < BRIGHT]
    if len(ring) < FEWEST_PIXELS:
        return None
    return np.asarray(np.round(np.median(ring, axis=0)), dtype=np.uint8)


def recolour_irises(head: Model, photo: np.ndarray, pupils: dict[str, tuple[float, float]],
                    px_per_mm: float) -> None:
    """Paint each eyeball's iris (its middle colour of three) with the colour seen around its marked pupil."""
    if head.vertex_colors is None:
        return
    for part, landmark in PUPILS.items():
        if part not in head.parts or landmark not in pupils:
            continue
        colour = iris_colour(photo, pupils[landmark], px_per_mm)
        inside = np.flatnonzero(head.vertex_part == head.parts.index(part))
        colours, which = np.unique(head.vertex_colors[inside], axis=0, return_inverse=True)
        if colour is None or len(colours) != 3:
            continue
        middle = int(np.argsort(colours.astype(float).sum(axis=1))[1])
        head.vertex_colors[inside[which.reshape(-1) == middle]] = colour
