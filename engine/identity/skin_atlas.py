"""Where the skin lies in the head's texture atlas: for each texel, the skin triangle under it and where inside it.

The skin of an identity (:mod:`engine.identity.skin`) is painted into an image
on the head's own texture coordinates (MakeHuman's atlas, kept corner by corner:
``engine/data/default-head/head_texture_coordinates.py``). :func:`skin_atlas`
draws the skin polygons' (u, v) triangles into a ``size`` × ``size`` grid once
per mesh (cached on the texture coordinates' bytes); every identity's skin is
then worked out per texel from its vertices' values and the texels' barycentric
weights.

>>> from engine.identity.build import _default_head
>>> atlas = skin_atlas(_default_head(), 256)
>>> atlas.triangles.shape[1], bool(0.2 < atlas.covered.mean() < 0.95)
(3, True)
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

import numpy as np
from scipy.ndimage import distance_transform_edt

from engine.formats.default_head_skin import skin_polygons
from engine.model import Model
from engine.model.cells import cell_sizes, cell_starts

PADDING = 4            # texels round each island given its edge's colours, so filtering shows no seam


@dataclass(frozen=True)
class SkinAtlas:
    """The skin's place in a ``size`` × ``size`` atlas (row 0 at the top, v = 1).

    ``triangles`` (T, 3) vertex indices of the skin's fan triangles, ``faces`` (T,) the polygon each
    comes from; ``texel_triangle`` (K,) and ``texel_weights`` (K, 3) for the K covered texels, whose flat
    indices are ``texel_index``; ``covered`` (size, size) bool; ``skin_faces`` the polygons that show the image.
    """

    size: int
    triangles: np.ndarray
    faces: np.ndarray
    texel_index: np.ndarray
    texel_triangle: np.ndarray
    texel_weights: np.ndarray
    covered: np.ndarray
    skin_faces: np.ndarray
    pad_index: np.ndarray
    pad_source: np.ndarray

    def interpolate(self, per_vertex: np.ndarray) -> np.ndarray:
        """(K, …) a per-vertex array (N, …) at the covered texels."""
        values = np.asarray(per_vertex)[self.triangles[self.texel_triangle]]            # (K, 3, …)
        return np.asarray(np.einsum("kj,kj...->k...", self.texel_weights, values))

    def image(self, texels: np.ndarray, fill: np.ndarray) -> np.ndarray:
        """(size, size, C) float image of (K, C) texel values, ``fill`` elsewhere; the texels within
        :data:`PADDING` of an island take its nearest texel's value."""
        channels = texels.shape[1]
        out = np.empty((self.size * self.size, channels))
        out[:] = fill
        out[self.texel_index] = texels
        out[self.pad_index] = out[self.pad_source]
        return out.reshape(self.size, self.size, channels)


_CACHE: dict[tuple[str, int, tuple[int, ...]], SkinAtlas] = {}


def skin_atlas(model: Model, size: int, parts: tuple[str, ...] = ("skin",)) -> SkinAtlas:
    """The polygons of ``parts`` (the skin) of ``model`` drawn into a ``size`` × ``size`` atlas by their
    texture coordinates (parts the model lacks are left out)."""
    assert model.texture is not None, "the head must have texture coordinates"
    indices = tuple(model.parts.index(p) for p in parts if p in model.parts)
    digest = hashlib.sha256(model.texture.corner_uv.tobytes() + model.faces.tobytes()
                            + model.vertex_part.tobytes()).hexdigest()
    key = (digest, size, indices)
    if key not in _CACHE:
        if len(_CACHE) > 6:
            _CACHE.clear()
        _CACHE[key] = _draw(model, indices, size)
    return _CACHE[key]


def skin_faces(model: Model) -> np.ndarray:
    """The polygons that show the skin image (the ones :func:`skin_atlas` draws), found without drawing it."""
    return skin_polygons(model)


def _draw(model: Model, parts: tuple[int, ...], size: int) -> SkinAtlas:
    assert model.texture is not None
    counts = cell_sizes(model.faces)
    starts = cell_starts(counts)
    corner_start = np.concatenate([[0], np.cumsum(counts)[:-1]])
    uv = model.texture.corner_uv
    tris, tri_uv, tri_face = [], [], []
    for f in np.flatnonzero(np.isin(model.vertex_part[model.faces[starts + 1]], parts)):
        n = int(counts[f])
        idx = model.faces[starts[f] + 1:starts[f] + 1 + n]
        c = uv[corner_start[f]:corner_start[f] + n]
        if np.any(c < 0) or np.any(c > 1):
            continue
        for i in range(1, n - 1):
            tris.append(idx[[0, i, i + 1]])
            tri_uv.append(c[[0, i, i + 1]])
            tri_face.append(f)
    triangles = np.asarray(tris, dtype=np.int64).reshape(-1, 3)
    xy = np.asarray(tri_uv, dtype=float).reshape(-1, 3, 2) * [size, -size] + [0, size]     # pixels, row 0 at top
    owner = np.full(size * size, -1, dtype=np.int64)
    weights = np.zeros((size * size, 3))
    lo = np.clip(np.floor(xy.min(axis=1) - 0.5).astype(int), 0, size - 1)
    hi = np.clip(np.ceil(xy.max(axis=1) - 0.5).astype(int), 0, size - 1)
    for t in range(len(triangles)):
        xs = np.arange(lo[t, 0], hi[t, 0] + 1) + 0.5
        ys = np.arange(lo[t, 1], hi[t, 1] + 1) + 0.5
        X, Y = np.meshgrid(xs, ys)
        a, b, c = xy[t]
        area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
        if abs(area) < 1e-12:
            continue
        w1 = ((X - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (Y - a[1])) / area
        w2 = ((b[0] - a[0]) * (Y - a[1]) - (X - a[0]) * (b[1] - a[1])) / area
        w0 = 1 - w1 - w2
        inside = (w0 >= -1e-9) & (w1 >= -1e-9) & (w2 >= -1e-9)
        flat = (np.floor(Y[inside]).astype(np.int64) * size + np.floor(X[inside]).astype(np.int64))
        owner[flat] = t
        weights[flat] = np.stack([w0[inside], w1[inside], w2[inside]], axis=1)
    texel_index = np.flatnonzero(owner >= 0)
    covered = (owner >= 0).reshape(size, size)
    faces = np.asarray(tri_face, dtype=np.int64)
    distance, nearest = distance_transform_edt(~covered, return_indices=True)
    ring = (distance > 0) & (distance <= PADDING)
    pad_index = np.flatnonzero(ring)
    pad_source = (nearest[0] * size + nearest[1]).reshape(-1)[pad_index]
    return SkinAtlas(size, triangles, faces, texel_index, owner[texel_index], weights[texel_index], covered,
                     np.unique(faces), pad_index, pad_source)
