"""The points of a face a photograph's landmarks name, as vertices of the head: MPEG-4 and iBUG-68.

A front photograph's landmarks are the model's MPEG-4 feature points
(``model.landmarks``: pupils 3.5/3.6, nose tip 9.3, mouth corners 8.3/8.4, …)
and, where a face detector found them, the points of the iBUG 300-W
68-point annotation that no MPEG-4 point of the model stands for, named
``ibug.N`` (N the annotation's 0-based index, as dlib numbers them): the jaw
line (0 … 16 but the chin, 8), the brows between their ends and their top
(18, 20, 23, 25), the nose's ridge (27, 28, 29) and the nostrils' lower rim
(31, 32, 34, 35). :data:`IBUG_MPEG4` says which of the 68 points give each
MPEG-4 point (an eye's pupil is the middle of its six points).

:func:`point_vertices` gives each id's vertex on a head with the default
head's mesh. The brow, ridge and nostril points lie between MPEG-4 points
(the skin vertex nearest the point between them); the jaw line is
:data:`JAW_VERTICES`, found where dlib's predictor puts the jaw on rendered
heads (:func:`derive_jaw_vertices`; six identities, mirror-symmetric pairs;
about 2 mm from dlib's points on average) because the jaw line of a photograph is the
face's outline, which no MPEG-4 point of the model marks.

>>> from engine.formats.model_files import load_model
>>> head = load_model()
>>> where = point_vertices(head)
>>> where["3.5"] == head.landmarks["3.5"], "ibug.0" in where, len(extra_ids())
(True, True, 27)
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from engine.model import Model

#: MPEG-4 id → the iBUG-68 points (0-based) whose mean it is. Ids of the model with none (2.10, the chin
#: boss; 9.1, 9.2, 9.4, 9.5, the nostrils' outer borders the annotation has no point for) are not found.
IBUG_MPEG4: dict[str, tuple[int, ...]] = {
    "2.1": (8,), "2.2": (62,), "2.3": (66,), "2.4": (64,), "2.5": (60,),
    "3.1": (43, 44), "3.2": (37, 38), "3.3": (46, 47), "3.4": (40, 41),
    "3.5": (42, 43, 44, 45, 46, 47), "3.6": (36, 37, 38, 39, 40, 41),
    "3.7": (45,), "3.11": (42,), "3.8": (39,), "3.12": (36,),
    "4.1": (22,), "4.2": (21,), "4.3": (24,), "4.4": (19,), "4.5": (26,), "4.6": (17,),
    "8.1": (51,), "8.2": (57,), "8.3": (54,), "8.4": (48,), "8.5": (52,), "8.6": (50,), "8.7": (56,), "8.8": (58,),
    "9.3": (30,), "9.15": (33,),
}
#: The jaw line's iBUG points → vertices of the default head's mesh (its 5960 vertices; the subject's right, the
#: viewer's left, first). Made by :func:`derive_jaw_vertices`.
JAW_VERTICES = {0: 88, 1: 1628, 2: 4966, 3: 4743, 4: 5002, 5: 4738, 6: 3376, 7: 5065,
                9: 5079, 10: 3377, 11: 4881, 12: 5045, 13: 4886, 14: 5009, 15: 1656, 16: 787}
JAW_MESH_VERTICES = 5960
#: The other iBUG points: the skin vertex nearest the middle of two points (an MPEG-4 id or another ibug id),
#: or of a point and the ridge's top (27) for the ridge.
BETWEEN: dict[int, tuple[str, str, float]] = {
    18: ("4.6", "4.4", 0.5), 20: ("4.4", "4.2", 0.5), 23: ("4.1", "4.3", 0.5), 25: ("4.3", "4.5", 0.5),
    31: ("9.2", "9.4", 0.5), 35: ("9.1", "9.5", 0.5),
    32: ("9.15", "ibug.31", 0.5), 34: ("9.15", "ibug.35", 0.5),
    28: ("ibug.27", "9.3", 1 / 3), 29: ("ibug.27", "9.3", 2 / 3),
}
RIDGE_HALF_WIDTH = 2.0               # mm either side of the midline that count as the nose's ridge


def extra_ids() -> list[str]:
    """The ``ibug.N`` ids, in the annotation's order."""
    numbers = sorted([*JAW_VERTICES, *BETWEEN, 27])
    return [f"ibug.{n}" for n in numbers]


def known_ids(model: Model) -> set[str]:
    """Every id a landmark file may name for ``model``: its MPEG-4 landmarks, and the iBUG points where it has
    the default head's mesh."""
    return set(point_vertices(model))


def point_vertices(model: Model) -> dict[str, int]:
    """Id → vertex index of every point a photograph's landmarks may name on ``model`` (see the module)."""
    out = dict(model.landmarks)
    if model.n_vertices != JAW_MESH_VERTICES or not all(k in out for k in ("4.1", "4.6", "9.1", "9.15", "9.3")):
        return out
    vertices = model.vertices
    skin = np.flatnonzero(model.vertex_part == model.parts.index("skin")) if "skin" in model.parts \
        else np.arange(model.n_vertices)
    out.update({f"ibug.{n}": v for n, v in JAW_VERTICES.items()})
    out["ibug.27"] = _ridge_top(model, skin)
    for n in sorted(BETWEEN, key=lambda n: n in (32, 34, 28, 29)):      # the ones built on others last
        a, b, t = BETWEEN[n]
        point = (1 - t) * vertices[out[a]] + t * vertices[out[b]]
        if n in (28, 29):
            out[f"ibug.{n}"] = _ridge_at(vertices, skin, float(point[1]))
        else:
            out[f"ibug.{n}"] = int(skin[np.linalg.norm(vertices[skin] - point, axis=1).argmin()])
    return out


def point_index(model: Model, ids: Iterable[str]) -> np.ndarray:
    """(len(ids),) the vertex index of each id (:func:`point_vertices`)."""
    where = point_vertices(model)
    return np.array([where[k] for k in ids], dtype=np.int64)


def ibug_pixels(points: np.ndarray, known: Iterable[str] | None = None) -> dict[str, tuple[float, float]]:
    """The ids' pixels from dlib's (68, 2) points: the MPEG-4 ids of :data:`IBUG_MPEG4` and the ``ibug.N``
    ids, those in ``known`` only (all without)."""
    points = np.asarray(points, dtype=float)
    if points.shape != (68, 2):
        raise ValueError(f"expected (68, 2) points, got {points.shape}")
    out = {k: tuple(float(c) for c in points[list(idx)].mean(axis=0)) for k, idx in IBUG_MPEG4.items()}
    for key in extra_ids():
        out[key] = tuple(float(c) for c in points[int(key.split(".")[1])])
    allowed = None if known is None else set(known)
    return {k: (x, y) for k, (x, y) in out.items() if allowed is None or k in allowed}


def _ridge_top(model: Model, skin: np.ndarray) -> int:
    """iBUG 27, the top of the nose's ridge: the midline at the height of the upper lids' middle (3.1, 3.2)."""
    height = float(np.mean([model.vertices[model.landmarks[k], 1] for k in ("3.1", "3.2") if k in model.landmarks]
                           or [model.vertices[model.landmarks["9.3"], 1] + 40.0]))
    return _ridge_at(model.vertices, skin, height)


def _ridge_at(vertices: np.ndarray, skin: np.ndarray, height: float) -> int:
    """The most forward skin vertex on the midline (within :data:`RIDGE_HALF_WIDTH`) nearest ``height``."""
    middle = skin[np.abs(vertices[skin, 0]) < RIDGE_HALF_WIDTH]
    near = middle[np.abs(vertices[middle, 1] - height) < 3.0]
    if not len(near):
        return int(middle[np.abs(vertices[middle, 1] - height).argmin()])
    return int(near[vertices[near, 2].argmax()])


Rendering = tuple[np.ndarray, np.ndarray, np.ndarray]
"""A head rendered for the jaw line: its vertices' pixels (N, 2), its skin vertices seen, dlib's (68, 2) points."""


def jaw_renderings(heads: Sequence[Model], eyes: Any = None, size: tuple[int, int] = (600, 800)) -> list[Rendering]:
    """Each of ``heads`` (identities of the default head) rendered from the front: the pixels of its vertices
    (the renderer's perspective camera), its skin vertices no other skin hides, and dlib's 68 points there.
    Needs the ``validate`` extra and VTK."""
    from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
    from engine.outputs.render import render_model
    from engine.photofit.raster import rasterize
    from engine.photofit.texture import all_triangles
    from engine.validation.faces import find_faces
    from engine.validation.observers import observers

    eyes = eyes or observers()
    width, height = size
    triangles = all_triangles(heads[0])
    skin = np.flatnonzero(heads[0].vertex_part == heads[0].parts.index("skin"))
    seen = []
    for head in heads:
        picture = render_model(head, size=size)
        faces = find_faces(picture, "hog", True, eyes)
        focal, position, up, _ = camera_pose(framed_points(head), VIEWS["front"], width, height)
        back = (position - focal) / np.linalg.norm(position - focal)
        right = np.cross(up, back)
        d = head.vertices - position
        f = (height / 2) / np.tan(np.radians(VIEW_ANGLE) / 2)
        depth = -(d @ back)
        pixels = np.stack([width / 2 + f * (d @ right) / depth, height / 2 - f * (d @ up) / depth], axis=1)
        _, _, nearest = rasterize(pixels[triangles], width, height, -depth[triangles])
        cell = np.clip(pixels.astype(int), 0, [width - 1, height - 1])
        front = skin[-depth[skin] >= nearest[cell[skin, 1], cell[skin, 0]] - 2.0]     # not behind other skin
        seen.append((pixels, front, eyes.landmarks(picture, faces[0].box)))
    return seen


def jaw_line_error(seen: Sequence[Rendering], table: Mapping[int, int]) -> float:
    """Mean distance, px, from dlib's jaw points to the ``table``'s vertices over :func:`jaw_renderings`."""
    return float(np.mean([np.linalg.norm(px[v] - pts[k]) for px, _, pts in seen for k, v in table.items()]))


def derive_jaw_vertices(seen: Sequence[Rendering], base: Model) -> dict[int, int]:
    """:data:`JAW_VERTICES` again from :func:`jaw_renderings` of identities of ``base`` (the default head): for
    each mirror pair of dlib's jaw points the skin vertex (and its mirror image) whose projections are nearest
    them over all the renderings."""
    from scipy.spatial import cKDTree

    skin = np.flatnonzero(base.vertex_part == base.parts.index("skin"))
    tree = cKDTree(base.vertices[skin])

    def mirror(v: int) -> int:
        return int(skin[tree.query(base.vertices[v] * [-1, 1, 1])[1]])

    out: dict[int, int] = {}
    for k in range(8):
        j = 16 - k
        options: set[int] = set()
        for pixels, front, points in seen:
            options.add(int(front[np.linalg.norm(pixels[front] - points[k], axis=1).argmin()]))
            options.add(mirror(int(front[np.linalg.norm(pixels[front] - points[j], axis=1).argmin()])))

        def cost(v: int, k: int = k, j: int = j) -> float:
            m = mirror(v)
            return float(sum(np.linalg.norm(px[v] - pts[k]) + np.linalg.norm(px[m] - pts[j]) for px, _, pts in seen))

        best = min(sorted(options), key=cost)
        out[k], out[j] = best, mirror(best)
    return dict(sorted(out.items()))
