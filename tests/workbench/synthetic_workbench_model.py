"""A small synthetic head for the workbench tests, built with numpy alone.

An ellipsoid of skin (triangle fans at the poles, quads elsewhere, so the
viewport meets mixed polygon sizes) with two spherical eyes, and a
three-parameter tree: ``head_turn`` (rigid, group 1) carrying the leaves
``jaw_open`` (rotation) and ``brow_raise`` (translation). Millimetres; the
face looks along +Z with +Y up, like the default head.

(The name is unique on purpose: test folders are on ``sys.path`` side by side.)
"""

from __future__ import annotations

import numpy as np

import engine

SYNTHETIC_PARAMETERS = ["head_turn", "jaw_open", "brow_raise"]


def _ellipsoid(center, radii, n_lat: int, n_lon: int):
    """Vertices and polygons (triangle fans at the poles, quads elsewhere), wound outwards."""
    center, radii = np.asarray(center, float), np.asarray(radii, float)
    verts = [(0.0, 1.0, 0.0)]
    for i in range(1, n_lat):
        theta = np.pi * i / n_lat
        for j in range(n_lon):
            phi = 2 * np.pi * j / n_lon
            verts.append((np.sin(theta) * np.sin(phi), np.cos(theta), np.sin(theta) * np.cos(phi)))
    verts.append((0.0, -1.0, 0.0))
    unit = np.array(verts)
    bottom = len(unit) - 1

    def ring(i, j):
        return 1 + (i - 1) * n_lon + j % n_lon

    polys = [[0, ring(1, j), ring(1, j + 1)] for j in range(n_lon)]
    for i in range(1, n_lat - 1):
        polys += [[ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)] for j in range(n_lon)]
    polys += [[bottom, ring(n_lat - 1, j + 1), ring(n_lat - 1, j)] for j in range(n_lon)]
    # Wind every polygon so its normal points away from the centre.
    for k, poly in enumerate(polys):
        a, b, c = unit[poly[0]], unit[poly[1]], unit[poly[2]]
        if np.dot(np.cross(b - a, c - a), a + b + c) < 0:
            polys[k] = poly[::-1]
    return center + unit * radii, polys


def build_synthetic_model(name: str = "synthetic-head", painted: bool = False) -> engine.Model:
    """~650 vertices, parts skin/eye_left/eye_right, tree head_turn → (jaw_open, brow_raise).

    ``painted=True`` adds per-vertex colours: dark pupils on the eyes' front poles.
    """
    pieces = [("skin", (0, 0, 0), (75, 100, 85), 16, 32),
              ("eye_left", (32, 20, 68), (12, 12, 12), 8, 12),
              ("eye_right", (-32, 20, 68), (12, 12, 12), 8, 12)]
    vertices, faces, vertex_part = [], [], []
    for part_index, (_part, center, radii, n_lat, n_lon) in enumerate(pieces):
        v, polys = _ellipsoid(center, radii, n_lat, n_lon)
        offset = sum(len(x) for x in vertices)
        for poly in polys:
            faces += [len(poly)] + [offset + i for i in poly]
        vertices.append(v)
        vertex_part.append(np.full(len(v), part_index))
    vertices = np.concatenate(vertices)
    vertex_part = np.concatenate(vertex_part)
    skin = np.flatnonzero(vertex_part == 0)
    _x, y, z = vertices[skin].T

    tree = engine.ParameterTree([
        engine.Parameter("head_turn", "rotation", axis=(0, 1, 0), pivot=(0, -100, 0), degrees_per_unit=30,
                         description="Turn the head to its left (+) or right (−)."),
        engine.Parameter("jaw_open", "rotation", parent="head_turn", minimum=0, maximum=1,
                         axis=(1, 0, 0), pivot=(0, -10, -20), degrees_per_unit=20,
                         description="Open the jaw."),
        engine.Parameter("brow_raise", "translation", parent="head_turn", minimum=-0.5, maximum=1,
                         direction=(0, 8, 0), description="Raise both brows."),
    ])
    jaw = (y < -20) & (z > 0)
    brow = (y > 30) & (y < 80) & (z > 40)
    regions = {
        "head_turn": engine.InfluenceRegion(np.arange(len(vertices)), np.ones(len(vertices))),
        "jaw_open": engine.InfluenceRegion(skin[jaw], np.clip((-20 - y[jaw]) / 30, 0.05, 1)),
        "brow_raise": engine.InfluenceRegion(skin[brow], 1 - np.abs(y[brow] - 55) / 25),
    }
    colors = None
    if painted:
        colors = np.tile(np.array([226, 176, 150], dtype=np.uint8), (len(vertices), 1))
        eyes = vertex_part > 0
        colors[eyes] = (243, 240, 234)
        colors[eyes & (vertices[:, 2] > 78)] = (20, 17, 16)
    return engine.Model(vertices, np.array(faces), [p[0] for p in pieces], vertex_part, tree, regions,
                        name=name, description="A synthetic test head: an ellipsoid with two eyes.",
                        vertex_colors=colors)
