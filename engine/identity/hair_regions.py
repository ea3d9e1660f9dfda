"""Where hair grows on the default head: the scalp, the beard, the moustache and the brows, per skin vertex.

Regions are found on the default head's rest shape from its landmarks
(MPEG-4 feature points, :mod:`engine.model.landmarks`) and a head frame:
a vertical axis through the skull (``x = 0``, ``z`` :data:`AXIS_Z` mm) and
the azimuth about it (0° ahead, 180° behind). Each region is a strength per
skin vertex in [0, 1] (0 outside, rising to 1 a few mm inside its edge), so
hair thins out at the hairline and the beard's edge. Regions are made once,
on the default head, and carried to every identity through the skin's
triangles (:mod:`engine.identity.hair_surface`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from engine.model import Model

AXIS_Z = 45.0
#: The hairline's height (mm, default head) at each azimuth (degrees from straight ahead).
HAIRLINE_AZIMUTH = (0.0, 25.0, 38.0, 50.0, 62.0, 72.0, 80.0, 88.0, 102.0, 114.0, 130.0, 155.0, 180.0)
HAIRLINE_Y = (206.0, 203.0, 196.0, 178.0, 160.0, 146.0, 136.0, 156.0, 157.0, 148.0, 124.0, 108.0, 104.0)
FEATHER_MM = 9.0          # hair reaches full strength this far inside its edge


@dataclass(frozen=True)
class HairRegions:
    """Per skin vertex (model indices ``skin``) the strength of each region, and the skin's triangles."""

    skin: np.ndarray
    triangles: np.ndarray
    scalp: np.ndarray
    beard: np.ndarray
    moustache: np.ndarray
    brow_left: tuple[np.ndarray, np.ndarray, np.ndarray]
    brow_right: tuple[np.ndarray, np.ndarray, np.ndarray]


def azimuth(points: np.ndarray) -> np.ndarray:
    """Degrees about the head's vertical axis, 0 ahead (+Z) … 180 behind, the same on both sides."""
    return np.degrees(np.arctan2(np.abs(points[:, 0]), points[:, 2] - AXIS_Z))


def _feather(inside: np.ndarray, points: np.ndarray, width: float = FEATHER_MM) -> np.ndarray:
    """1 deep inside, falling to 0 at the edge of ``inside`` over ``width`` mm (distance to the outside)."""
    from scipy.spatial import cKDTree

    out = np.zeros(len(points))
    if not inside.any() or inside.all():
        return inside.astype(float)
    dist, _ = cKDTree(points[~inside]).query(points[inside])
    t = np.clip(dist / width, 0.0, 1.0)
    out[inside] = t * t * (3 - 2 * t)
    return out


def _ears(points: np.ndarray) -> np.ndarray:
    """The ears: skin standing out sideways around the ear canal's level (default head)."""
    return (np.abs(points[:, 0]) > 74.0) & (points[:, 1] > 100.0) & (points[:, 1] < 155.0) \
        & (points[:, 2] > 18.0) & (points[:, 2] < 62.0)


@cache
def default_regions() -> HairRegions:
    """The regions on the shipped default head (made once)."""
    from engine.formats.model_files import load_model

    return regions_of(load_model())


def regions_of(model: Model) -> HairRegions:
    """The regions of a head with the default head's skin and landmarks."""
    skin = model.part_vertices("skin")
    P = model.vertices[skin]
    tri = model.triangles()
    is_skin = np.zeros(model.n_vertices, bool)
    is_skin[skin] = True
    tri = tri[is_skin[tri].all(axis=1)]
    lm = {k: model.vertices[v] for k, v in model.landmarks.items()}
    a = azimuth(P)
    scalp = (P[:, 1] > np.interp(a, HAIRLINE_AZIMUTH, HAIRLINE_Y)) & ~_ears(P)
    # the beard: below the cheek line (mouth corner out to the sideburn), down under the chin to the throat
    x, y, z = np.abs(P[:, 0]), P[:, 1], P[:, 2]
    corner, chin = lm["8.3"], lm["2.1"]
    cheek_y = np.interp(x, [0.0, corner[0] + 8.0, 62.0, 80.0], [corner[1] + 14.0, corner[1] + 10.0, 104.0, 134.0])
    throat_y = chin[1] - 22.0 + 0.25 * np.clip(chin[2] - z, 0, None)
    beard = (y < cheek_y) & (y > throat_y) & (a < 100.0) & (z > 20.0) & ~_ears(P)
    lips = _lips(P, lm)
    moustache = (x < corner[0] + 6.0) & (y < lm["9.15"][1] - 1.0) & (y > np.interp(
        x, [0.0, corner[0] - 6.0, corner[0] + 6.0], [lm["8.1"][1] + 1.0, corner[1] + 1.5, corner[1] - 9.0])) \
        & (z > corner[2] - 12.0) & ~lips & ~_nostrils(P, lm)
    beard &= ~lips
    return HairRegions(skin, tri, _feather(scalp, P, FEATHER_MM), _feather(beard | moustache, P, 6.0),
                       _feather(moustache, P, 2.0), _brow(lm, "4.1", "4.3", "4.5"), _brow(lm, "4.2", "4.4", "4.6"))


def _lips(P: np.ndarray, lm: dict[str, np.ndarray]) -> np.ndarray:
    """The lips (red of the lips and a margin): inside the ellipse through the mouth corners and lip midpoints."""
    left, right, top, bottom = lm["8.3"], lm["8.4"], lm["8.1"], lm["8.2"]
    centre = (left + right) / 2
    half_w = np.linalg.norm(left - right) / 2 + 2.0
    up, down = top[1] - centre[1] + 1.5, centre[1] - bottom[1] + 2.0
    dy = P[:, 1] - centre[1]
    half_h = np.where(dy > 0, up, down)
    return ((P[:, 0] - centre[0]) / half_w) ** 2 + (dy / half_h) ** 2 < 1.0


def _nostrils(P: np.ndarray, lm: dict[str, np.ndarray]) -> np.ndarray:
    """The nose's underside and wings: within 6 mm of the nostril borders and the subnasale, above the lip."""
    near = np.zeros(len(P), bool)
    for key in ("9.1", "9.2", "9.15", "9.4", "9.5"):
        near |= np.linalg.norm(P - lm[key], axis=1) < 5.0
    return near


def _brow(lm: dict[str, np.ndarray], inner: str, top: str, outer: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A brow's inner end, top and outer end (the painted brow's landmarks)."""
    return lm[inner], lm[top], lm[outer]
