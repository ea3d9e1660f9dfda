"""Linear subdivision of a whole model: mesh, weights, displacement fields, landmarks.

Every polygon is split into a k × k grid (quads bilinearly, triangles
barycentrically). New vertices are fixed linear combinations of the old ones,
written as one sparse matrix ``S`` (new × old), so weights and displacement
fields are carried by the same ``S`` and the subdivided model deforms like
the original at every old vertex. Used for benchmarks at ~100k vertices and
for smoother renders.

>>> from engine import load_model
>>> from engine.model.subdivide import subdivide
>>> fine = subdivide(load_model(), 5)           # doctest: +SKIP
>>> fine.n_vertices                             # doctest: +SKIP
127016
"""

from __future__ import annotations

import numpy as np
from scipy import sparse

from engine.model.cells import cell_sizes
from engine.model.model import InfluenceRegion, Model
from engine.model.texture import ModelTexture


def subdivision_matrix(polygons: list[np.ndarray], n_vertices: int,
                       k: int) -> tuple[sparse.csr_matrix, list[list[int]]]:
    """Sparse ``S`` (new × old) and the new polygons for a k × k split of every polygon.

    Old vertex ``i`` keeps index ``i``; shared edge points are created once.
    """
    if k < 1:
        raise ValueError("k must be at least 1")
    keys: dict[tuple[tuple[int, int], ...], int] = {}
    rows, cols, vals = list(range(n_vertices)), list(range(n_vertices)), [1.0] * n_vertices
    for i in range(n_vertices):
        keys[((i, k * k),)] = i

    def point(combo: dict[int, int]) -> int:
        # combo: old vertex -> weight numerator over k*k (exact integers, so shared points match)
        key = tuple(sorted((v, w) for v, w in combo.items() if w))
        if key in keys:
            return keys[key]
        idx = len(keys)
        keys[key] = idx
        for v, w in key:
            rows.append(idx)
            cols.append(v)
            vals.append(w / (k * k))
        return idx

    new_polys: list[list[int]] = []
    for poly in polygons:
        corners = [int(v) for v in poly]
        if len(corners) == 4:
            a, b, c, d = corners
            grid = [[point({a: (k - i) * (k - j), b: i * (k - j), c: i * j, d: (k - i) * j})
                     for j in range(k + 1)] for i in range(k + 1)]
            new_polys.extend([grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]]
                             for i in range(k) for j in range(k))
        elif len(corners) == 3:
            a, b, c = corners
            tri_grid = {(i, j): point({a: (k - i - j) * k, b: i * k, c: j * k})
                        for i in range(k + 1) for j in range(k + 1 - i)}
            for i in range(k):
                for j in range(k - i):
                    new_polys.append([tri_grid[i, j], tri_grid[i + 1, j], tri_grid[i, j + 1]])
                    if i + j < k - 1:
                        new_polys.append([tri_grid[i + 1, j], tri_grid[i + 1, j + 1], tri_grid[i, j + 1]])
        else:
            raise ValueError("subdivision handles triangles and quads only")
    S = sparse.csr_matrix((vals, (rows, cols)), shape=(len(keys), n_vertices))
    return S, new_polys


def subdivide(model: Model, k: int = 2) -> Model:
    """A copy of ``model`` with every polygon split into k × k; weights and fields carried linearly."""
    S, polys = subdivision_matrix(model.polygons(), model.n_vertices, k)
    vertices = S @ model.vertices
    faces = np.concatenate([[len(p), *p] for p in polys])
    # part of a new vertex: the part of the old vertex that contributes most
    owner = np.asarray(S.argmax(axis=1)).ravel()
    regions = {}
    for p in model.parameters:
        r = model.regions[p.name]
        w = S @ r.dense(model.n_vertices)
        idx = np.flatnonzero(w > 0)
        disp = None
        if r.displacements is not None:
            D = np.zeros((model.n_vertices, 3))
            D[r.indices] = r.displacements
            disp = (S @ D)[idx]
        regions[p.name] = InfluenceRegion(idx, np.clip(w[idx], 0.0, 1.0), disp)
    colors = None if model.vertex_colors is None else np.clip(
        np.rint(S @ model.vertex_colors.astype(float)), 0, 255).astype(np.uint8)
    return Model(vertices, faces, list(model.parts), model.vertex_part[owner], model.parameters.copy(),
                 regions, dict(model.landmarks), f"{model.name}-subdivided-{k}", model.description,
                 dict(model.part_colors), colors, subdivided_texture(model, k))


def subdivided_texture(model: Model, k: int) -> ModelTexture | None:
    """The texture of :func:`subdivide`'s result: every new corner's (u, v) interpolated inside its old
    polygon with the weights that place its vertex (so seams stay seams), each new polygon showing its
    old polygon's image."""
    texture = model.texture
    if texture is None:
        return None
    counts = cell_sizes(model.faces)
    new_uv: list[np.ndarray] = []
    start = 0
    for count in counts.tolist():
        corners = texture.corner_uv[start:start + count]
        start += count
        new_uv.append(_split_polygon_uv(corners, k))
    pieces = np.repeat(texture.face_image, k * k)
    corner_uv = np.concatenate(new_uv) if new_uv else np.zeros((0, 2))
    return ModelTexture(corner_uv, [image.copy() for image in texture.images], pieces)


def _split_polygon_uv(uv: np.ndarray, k: int) -> np.ndarray:
    """Corner (u, v) of the k × k pieces of one polygon, in the order :func:`subdivision_matrix` makes them."""
    if len(uv) == 4:
        a, b, c, d = uv

        def quad(i: int, j: int) -> np.ndarray:
            return ((k - i) * (k - j) * a + i * (k - j) * b + i * j * c + (k - i) * j * d) / (k * k)

        return np.array([quad(i + di, j + dj) for i in range(k) for j in range(k)
                         for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))])
    a, b, c = uv

    def tri(i: int, j: int) -> np.ndarray:
        return ((k - i - j) * a + i * b + j * c) / k

    out: list[np.ndarray] = []
    for i in range(k):
        for j in range(k - i):
            out += [tri(i, j), tri(i + 1, j), tri(i, j + 1)]
            if i + j < k - 1:
                out += [tri(i + 1, j), tri(i + 1, j + 1), tri(i, j + 1)]
    return np.array(out)
