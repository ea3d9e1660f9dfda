"""The skin's fine detail: pores, a mottle of melanin and blood, and lines that deepen with age.

Synthesised (no image is shipped): every pattern is drawn with a fixed seed
(:data:`SEED`) in the atlas of :mod:`engine.identity.skin_atlas`, so the same
identity gives the same texels on every run, and people differ in how deep
their lines are and where their face puts them, not in noise: a morph
continuum changes smoothly. Lines are placed on the head's own surface (mm,
by the MPEG-4 feature points): horizontal forehead lines above the brows,
crow's feet fanning from the eyes' outer corners, a fold under each lower
lid, and the nasolabial fold from the nose's wing past the mouth's corner.

:func:`detail_heights` returns, per covered texel, the depth (0 … −0.45,
the fraction of light a pit or line keeps to itself, so the image darkens
there and the physically based shader bumps its normal there), and two
zero-mean noise fields (melanin mottle, redness) that :mod:`engine.identity.skin`
scales by age.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache

import numpy as np
from scipy.ndimage import gaussian_filter, uniform_filter

from engine.identity.skin_atlas import SkinAtlas
from engine.model import Model

SEED = 20030401           # the fixed seed of every pattern (the paper's year)
PORE_SHARE = 0.14         # the share of texels that are the bottom of a pore
PORE_DEPTH = 0.10
LINE_MM = 0.55            # a fine line's half-width


@cache
def _noise(size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pores (0 … 1), mottle and redness (zero mean, unit spread) over the whole ``size`` × ``size`` atlas."""
    rng = np.random.Generator(np.random.PCG64(SEED))
    white = rng.random((3, size, size))
    pit = np.clip((white[0] - (1 - PORE_SHARE)) / PORE_SHARE, 0, 1)
    pores = uniform_filter(pit, 2, mode="wrap")
    scale = size / 1024
    mottle = gaussian_filter(white[1] - 0.5, 5 * scale, mode="wrap") \
        + 0.5 * gaussian_filter(white[1] - 0.5, 1.6 * scale, mode="wrap")
    redness = gaussian_filter(white[2] - 0.5, 9 * scale, mode="wrap")
    return (pores, mottle / max(float(mottle.std()), 1e-12), redness / max(float(redness.std()), 1e-12))


def _groove(distance: np.ndarray, half_width: float = LINE_MM) -> np.ndarray:
    return np.asarray(np.exp(-((distance / half_width) ** 2)))


def _fade(t: np.ndarray) -> np.ndarray:
    t = np.clip(t, 0.0, 1.0)
    return np.asarray(t * t * (3 - 2 * t))


def _segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ab = b - a
    t = np.clip((p - a) @ ab / (ab @ ab), 0, 1)
    return np.asarray(np.linalg.norm(p - (a + t[:, None] * ab), axis=1))


def age_lines(P: np.ndarray, lm: Mapping[str, np.ndarray], age: float) -> np.ndarray:
    """(K,) depth 0 … 1 of the fine lines at surface points ``P`` (K, 3) of a face of ``age`` years."""
    old = float(np.clip((age - 25) / 45, 0, 1)) ** 1.2
    adult = float(np.clip((age - 12) / 10, 0, 1))
    x, y, z = P[:, 0], P[:, 1], P[:, 2]
    front = _fade((z - (lm["8.3"][2] - 15)) / 15)
    lines = np.zeros(len(P))
    # forehead: waving horizontal lines every 8 mm above the brows
    brow_y = (lm["4.3"][1] + lm["4.4"][1]) / 2 if "4.4" in lm else lm["4.3"][1]
    wavy = y + 1.2 * np.sin(x / 17.0) + 0.6 * np.sin(x / 7.3 + 1.0)
    start = brow_y + 9.0
    d = np.mod(wavy - start + 4.0, 8.0) - 4.0
    band = _fade((wavy - start + 3) / 4) * _fade((start + 34 - wavy) / 8) * _fade((48 - np.abs(x)) / 12)
    index = np.floor((wavy - start + 4.0) / 8.0)
    broken = np.clip(0.75 + 0.6 * np.sin(x / 9.0 + 2.3 * index) * np.sin(x / 23.0 + 1.1 * index), 0, 1)
    lines += (0.05 * adult + 0.75 * old) * _groove(d, 0.7) * band * broken * front
    for corner_key, side in (("3.7", 1.0), ("3.12", -1.0)):
        corner = lm[corner_key]
        dx, dy = side * (x - corner[0]), y - corner[1]
        r = np.hypot(dx, dy)
        angle = np.arctan2(dy, np.maximum(dx, 1e-6))
        fan = np.zeros(len(P))
        for k in np.radians([-42.0, -24.0, -8.0, 9.0, 25.0]):
            fan = np.maximum(fan, _groove(r * np.sin(angle - k - 0.04 * r * np.sin(3 * k + 1)), 0.5))
        reach = _fade((r - 4) / 3) * _fade((22 - r) / 6) * (dx > 0)
        lines += 0.9 * old * fan * reach * front
        # the fold under the lower lid, curving up towards the outer corner
        eye_x = (lm["3.7"][0] + lm["3.11"][0]) / 2 if side > 0 else (lm["3.12"][0] + lm["3.8"][0]) / 2
        u = side * (x - eye_x)
        lid = corner[1] - 8.0 - 0.012 * (14 - u) ** 2 + 4
        lines += (0.1 * adult + 0.6 * old) * _groove(y - lid, 0.8) * _fade((16 - np.abs(u)) / 5) * front
    for wing_key, mouth_key, side in (("9.1", "8.3", 1.0), ("9.2", "8.4", -1.0)):
        wing, mouth = lm[wing_key], lm[mouth_key]
        a = wing + np.array([side * 5.0, -2.0, 0.0])
        b = mouth + np.array([side * 7.0, -8.0, 0.0])
        d2 = _segment_distance(P[:, :2], a[:2], b[:2])
        lines += (0.25 * adult + 0.6 * old) * _groove(d2, 1.2) * front
    return np.clip(lines, 0, 1)


def detail_heights(atlas: SkinAtlas, positions: np.ndarray, regions: Mapping[str, np.ndarray], model: Model,
                   age: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per covered texel of ``atlas`` (``positions`` their points on ``model``'s surface): the depth of
    pores and lines (0 … −0.45), the melanin mottle and the redness noise (see the module's docstring)."""
    pores, mottle, redness = (field.reshape(-1)[atlas.texel_index] for field in _noise(atlas.size))
    lm = {k: model.vertices[v] for k, v in model.landmarks.items()}
    oily = atlas.interpolate(np.clip(regions["nose"] + 0.6 * regions["cheeks"] + 0.3 * regions["forehead"], 0, 1))
    lips = atlas.interpolate(regions["lips"])
    pore_depth = PORE_DEPTH * pores * (0.55 + 0.8 * oily) * (1 - lips)
    # lips: fine vertical furrows instead of pores
    lip_lines = lips * 0.08 * (0.5 + 0.5 * np.cos(positions[:, 0] * 2.1 + 0.8 * np.sin(positions[:, 1])))
    lines = np.zeros(len(positions))
    face = positions[:, 2] > lm["8.3"][2] - 32          # lines only on the face
    lines[face] = age_lines(positions[face], lm, age)
    depth = pore_depth + 0.35 * lines + lip_lines
    return -np.clip(depth, 0, 0.45), mottle, redness
