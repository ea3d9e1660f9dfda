"""The default head's colours: each part's colour, pupil and iris on the eyeballs, and painted brows.

A stage of ``derive_default_head.py``. Colours are sRGB bytes.
"""

from __future__ import annotations

import numpy as np
from head_geometry import smoothstep
from makehuman_assets import PARTS

IRIS_DEGREES, PUPIL_DEGREES = 25.0, 8.5


def eye_colors(rest, centre) -> np.ndarray:
    """sRGB colours for an eyeball: dark pupil, blue-grey iris, white sclera (by angle from +Z)."""
    u = rest - centre
    angle = np.degrees(np.arccos(np.clip(u[:, 2] / np.linalg.norm(u, axis=1), -1, 1)))
    colors = np.tile([243, 240, 234], (len(rest), 1))
    colors[angle <= IRIS_DEGREES + 0.5] = [86, 112, 132]
    colors[angle <= PUPIL_DEGREES + 0.5] = [18, 16, 16]
    return colors.astype(np.uint8)


BROW_COLOR = np.array([92, 64, 46])


def segment_distance(points, a, b) -> np.ndarray:
    ab = b - a
    t = np.clip((points - a) @ ab / (ab @ ab), 0, 1)
    return np.linalg.norm(points - (a + t[:, None] * ab), axis=1)


def brow_strength(vertices, skin, landmarks, inner, top, outer, thickness=(4.0, 3.2, 1.8)) -> np.ndarray:
    """How much each skin vertex belongs to the brow band through the landmarks inner → top → outer."""
    a, b, c = (vertices[landmarks[k]] for k in (inner, top, outer))
    P = vertices[skin]
    d1, d2 = segment_distance(P, a, b), segment_distance(P, b, c)
    # half-width tapers from the inner end to the outer end
    along = np.where(d1 <= d2, 0.5 * np.clip((P - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1),
                     0.5 + 0.5 * np.clip((P - b) @ (c - b) / ((c - b) @ (c - b)), 0, 1))
    width = np.interp(along, [0, 0.5, 1], thickness)
    return 1 - smoothstep(np.minimum(d1, d2) / width)


def vertex_colors(vertices, vertex_part, eye_rest, landmarks) -> np.ndarray:
    """Per-vertex sRGB colours: each part's colour, pupil and iris on the eyeballs, painted brows."""
    names = [p for p, _, _ in PARTS]
    palette = np.array([[int(c[i:i + 2], 16) for i in (1, 3, 5)] for _, _, c in PARTS], dtype=np.uint8)
    colors = palette[vertex_part]
    skin = np.flatnonzero(vertex_part == 0)
    for inner, top, outer in (("4.1", "4.3", "4.5"), ("4.2", "4.4", "4.6")):
        k = 0.85 * brow_strength(vertices, skin, landmarks, inner, top, outer)[:, None]
        colors[skin] = np.rint((1 - k) * colors[skin] + k * BROW_COLOR).astype(np.uint8)
    for part, (_helper, centre, _radius) in eye_rest.items():
        idx = np.flatnonzero(vertex_part == names.index(part))
        colors[idx] = eye_colors(vertices[idx], centre)
    return colors
