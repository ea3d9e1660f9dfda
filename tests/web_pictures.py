"""Measuring pictures of the face: the mouth's opening, and how far the dark features of two pictures lie apart.

Both work on any RGB picture (a browser screenshot, an engine render, an MP4 frame), so the
browser's picture and the engine's are measured the same way.

* :func:`mouth_opening_px`: the mouth's inside (the dark red lining and tongue, the teeth's
  shadow) counted in the columns between the lip corners, per column: the opening's mean
  height in pixels. Closed lips show none of it.
* :func:`feature_distance_px`: the dark features (pupils, iris rims, lashes, brows' and
  nostrils' shadows, the open mouth) of two pictures, each pixel's distance to the nearest one
  of the other picture's; the 95th percentile both ways. A camera placed differently, or a
  different pose, moves these features by more than a pixel or two.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

DARK = 200                      # R+G+B below this: a dark feature
INSIDE_DARK = 330               # R+G+B below this and ...
INSIDE_RED = 0.70               # ... green below this share of red: the mouth's inside (skin, shadows: about 0.8)


def mouth_inside(image: np.ndarray) -> np.ndarray:
    """Pixels showing the mouth's inside (dark and red: the lining, the tongue in shadow)."""
    rgb = image[..., :3].astype(int)
    return (rgb.sum(axis=2) < INSIDE_DARK) & (rgb[..., 1] < INSIDE_RED * rgb[..., 0])


def mouth_opening_px(image: np.ndarray, corners_px: np.ndarray, above: int = 40, below: int = 60) -> float:
    """Mean height (px) of the mouth's inside over the middle half of the columns between the lip
    corners (``corners_px``: the two corners' pixel positions, x right, y down)."""
    left, right = sorted(float(x) for x in corners_px[:, 0])
    quarter = (right - left) / 4
    columns = slice(round(left + quarter), round(right - quarter))
    middle_y = round(float(corners_px[:, 1].mean()))
    rows = slice(max(middle_y - above, 0), middle_y + below)
    inside = mouth_inside(image)[rows, columns]
    return float(inside.sum(axis=0).mean())


def dark_features(image: np.ndarray) -> np.ndarray:
    return image[..., :3].astype(int).sum(axis=2) < DARK


def feature_distance_px(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    """95th percentile of the distances (px) from ``a``'s dark features to ``b``'s, and from ``b``'s to ``a``'s."""
    dark_a, dark_b = dark_features(a), dark_features(b)
    to_a = ndimage.distance_transform_edt(~dark_a)
    to_b = ndimage.distance_transform_edt(~dark_b)
    return float(np.percentile(to_b[dark_a], 95)), float(np.percentile(to_a[dark_b], 95))


def shifted(image: np.ndarray, dx: int, dy: int) -> np.ndarray:
    """The picture moved by (dx, dy) pixels, the edge repeated (a camera moved sideways)."""
    return np.roll(np.roll(image, dy, axis=0), dx, axis=1)
