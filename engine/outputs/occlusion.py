"""Ambient occlusion baked per vertex: how much of the sky each point of the head sees (soft shadow in creases).

The eye sockets, the folds beside the nose and mouth, the groove under the nose
and the inside of the ears are darker in a real face under soft light because
the face itself hides part of the sky from them. :func:`model_occlusion`
computes that once per model, on the rest pose, with no OpenGL: the model's
triangles are marked in a grid of ``voxel_mm`` cells, and from every point of
every part's mesh (:class:`~engine.outputs.part_layout.PartLayout` order) a
fixed set of cosine-weighted directions over its normal's hemisphere is
marched through the grid up to ``radius_mm``. A direction that meets the
surface after ``t`` mm hides ``1 − (t / radius)²`` of its share of the sky
(an obscurance: near folds count fully, far surfaces fade out, so the neck
under the chin is not black); the point's value is what is left, from 0
(shut in) to 1 (open sky), smoothed once over the mesh's edges.

The result depends only on the mesh and the settings: the directions come
from a golden-angle spiral turned about each normal by a fixed amount per
point, so two computations of one model give the same values to the bit.
The renderer (:mod:`engine.outputs.render`), the workbench viewport and the
web player (``engine/web``) all darken with these same numbers, which is
why it is baked and not screen-space (VTK's SSAO pass; docs/looks.md
compares the two).

The lips touch at rest, so the mouth's inside and the lips' meeting surfaces
are shut in then, and open when the mouth opens: each point takes the more
open of its values at rest and with the jaw half open (``jaw_open`` at 60 % of
its range, where the model has one), so the teeth and the tongue are not black
in an open mouth and closed lips do not show a dark band where they meet.

The teeth (issue 32): MakeHuman's dentition has three rows of vertices up an
incisor, and the upper ones lie behind the upper lip at rest and half-way
through the jaw's opening, so between lips parted with the jaw nearly closed
(AU10, Disgust, Anger) the incisors' faces were shut in and drew as a grey
slab. A tooth's face turned to the front is seen only through the lips'
opening, which is where the front lights come from too, so it keeps at least
:data:`TEETH_FRONT_OPEN`. And since nothing here casts the key light's shadow,
a tooth's value then falls with its depth behind the front teeth
(:data:`TEETH_SHADE_MM`, down to :data:`TEETH_DEEPEST` of it): the side teeth
lie in the mouth's shadow (the buccal corridor) instead of shining at its
corners like two fangs.

>>> from engine import load_model
>>> from engine.outputs.part_layout import PartLayout
>>> head = load_model()
>>> values = model_occlusion(head)                  # one value per point of every part's mesh
>>> values.shape == (len(PartLayout(head).gather),), float(values.min()) >= 0.0, float(values.max()) <= 1.0
(True, True, True)
"""

from __future__ import annotations

import weakref
from collections import OrderedDict
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from engine.model import Model
    from engine.outputs.part_layout import PartLayout

__all__ = ["DIRECTIONS", "VOXEL_MM", "forget_computed", "mesh_occlusion", "model_occlusion",
           "part_vertex_occlusion", "settings"]

DIRECTIONS = 40                  # rays per point
VOXEL_MM = 1.5                   # the grid the surface is marked in
_JAW, _JAW_SHARE = "jaw_open", 0.6
TEETH_FRONT_OPEN = 1.0          # the least a tooth's face turned to the front keeps (it is seen only when lit)
TEETH_SHADE_MM = (8.0, 12.0)     # a tooth's light falls from this depth behind the front teeth, over this far
TEETH_DEEPEST = 0.25
_LIFT = 2.0                      # rays start this many cells above the surface (clear of its own cells)
_FIRST = 1.5                     # and take their first sample this many cells further
_STEPS = 14                      # samples along each ray
_CHUNK = 512                     # points marched at once (memory: CHUNK × DIRECTIONS × steps)
_cache: weakref.WeakKeyDictionary[Model, tuple[tuple[str, float], np.ndarray]] = weakref.WeakKeyDictionary()
#: Values by what they are computed from (the posed meshes and the layout), for another model object of the
#: same head: a file loaded again, a workbench window's model replaced by the same file. At most this many.
_BY_CONTENT_SIZE = 8
_by_content: OrderedDict[str, np.ndarray] = OrderedDict()


def settings() -> dict[str, object]:
    """How the occlusion is computed (the radius is the look's): a stimulus set's provenance records it."""
    return {"method": "rays marched through the surface marked in a grid; each point the more open of the rest "
                      "pose and the jaw half open", "directions": DIRECTIONS, "voxel_mm": VOXEL_MM, "steps": _STEPS,
            "falloff": "1 - (t / radius)^2", "jaw_open_share": _JAW_SHARE,
            "teeth": {"front_open": TEETH_FRONT_OPEN, "shade_mm": list(TEETH_SHADE_MM), "deepest": TEETH_DEEPEST}}


def model_occlusion(model: Model, radius_mm: float = 30.0, layout: PartLayout | None = None) -> np.ndarray:
    """Each point's open sky (0..1) in ``layout``'s stacked order (``PartLayout(model)`` if not given).

    Kept per model and radius until the model's mesh or rig changes: a stimulus set or a video computes
    it once, and a forked render helper inherits it. Kept too by what it is computed from (the rest and
    jaw-open positions, the layout, the radius), so another model object of the same head (the file
    loaded again, a workbench window's model replaced by the same file) takes the same values at once.
    """
    from engine.outputs.part_layout import PartLayout

    key = (_fingerprint(model), float(radius_mm))
    cached = _cache.get(model)
    if cached is not None and cached[0] == key:
        return cached[1]
    layout = layout if layout is not None else PartLayout(model)
    poses = [model.deform()]
    if _JAW in model.parameters:
        jaw = model.parameters[_JAW]
        poses.append(model.deform({_JAW: jaw.default + _JAW_SHARE * (jaw.maximum - jaw.default)}))
    teeth = _teeth_points(layout)
    content = _content_key(layout, poses, radius_mm)
    values = _by_content.get(content)
    if values is None:
        values = _layout_occlusion(layout, poses[0], radius_mm)
        for opened in poses[1:]:
            np.maximum(values, _layout_occlusion(layout, opened, radius_mm), out=values)
        if len(teeth):
            values[teeth] = _teeth_light(layout, poses[0], teeth, values[teeth])
        values.setflags(write=False)
        _by_content[content] = values
        while len(_by_content) > _BY_CONTENT_SIZE:
            _by_content.popitem(last=False)
    else:
        _by_content.move_to_end(content)
    _cache[model] = (key, values)
    return values


def _teeth_points(layout: PartLayout) -> np.ndarray:
    """The layout's points that belong to a teeth part (``teeth…``, ``tooth…``)."""
    ranges = [np.arange(*layout.slices[k]) for k, part in enumerate(layout.parts)
              if part.lower().startswith(("teeth", "tooth"))]
    return np.concatenate(ranges) if ranges else np.zeros(0, dtype=np.int64)


def _teeth_light(layout: PartLayout, positions: np.ndarray, teeth: np.ndarray, values: np.ndarray) -> np.ndarray:
    """The teeth points' values: at least :data:`TEETH_FRONT_OPEN` where a tooth faces the front, then
    falling with the depth (mm, +Z forward) behind the front-most tooth (see the module's docstring)."""
    _, normals = layout.points_and_normals(positions)
    facing = np.clip((normals[teeth, 2] - 0.1) / 0.4, 0.0, 1.0)
    z = positions[layout.gather[teeth], 2]
    t = np.clip((float(z.max()) - z - TEETH_SHADE_MM[0]) / TEETH_SHADE_MM[1], 0.0, 1.0)
    shade = 1.0 - (1.0 - TEETH_DEEPEST) * t * t * (3 - 2 * t)
    return np.asarray(np.maximum(values, TEETH_FRONT_OPEN * facing * facing * (3 - 2 * facing)) * shade)


def forget_computed() -> None:
    """Drop every value kept, so the next call computes afresh (to check that it gives the same)."""
    _cache.clear()
    _by_content.clear()


def _content_key(layout: PartLayout, poses: list[np.ndarray], radius_mm: float) -> str:
    """Everything the values are computed from: the positions of each pose, the parts' meshes as laid
    out (points, polygons), the radius and the method's settings."""
    import hashlib

    digest = hashlib.sha1(usedforsecurity=False)
    for positions in poses:
        digest.update(np.ascontiguousarray(positions, dtype=float).tobytes())
    digest.update(np.ascontiguousarray(layout.gather).tobytes())
    for k in range(len(layout.parts)):
        digest.update(np.ascontiguousarray(layout.cells[k]).tobytes())
    digest.update(repr((list(layout.parts), list(layout.slices), float(radius_mm), settings())).encode())
    return digest.hexdigest()


def part_vertex_occlusion(model: Model, radius_mm: float = 30.0) -> dict[str, np.ndarray]:
    """Per part, each model vertex's open sky in that part (1 where the part draws no polygon over it):
    for views whose meshes are laid out otherwise (the workbench viewport)."""
    from engine.outputs.part_layout import PartLayout

    layout = PartLayout(model)
    values = model_occlusion(model, radius_mm, layout)
    out: dict[str, np.ndarray] = {}
    for k, part in enumerate(layout.parts):
        dense = out.setdefault(part, np.ones(model.n_vertices))
        start, stop = layout.slices[k]
        dense[layout.used(k)] = values[start:stop]
    return out


def _fingerprint(model: Model) -> str:
    """What the values depend on: the rest mesh, its parts, the rig's revision."""
    import hashlib

    digest = hashlib.sha1(usedforsecurity=False)
    for array in (model.vertices, model.faces, model.vertex_part):
        digest.update(np.ascontiguousarray(array).tobytes())
    digest.update(repr((list(model.parts), int(getattr(model, "revision", 0)))).encode())
    return digest.hexdigest()


def _layout_occlusion(layout: PartLayout, positions: np.ndarray, radius_mm: float,
                      receivers: np.ndarray | None = None) -> np.ndarray:
    points, normals = layout.points_and_normals(positions)
    points = points.copy()
    triangles = np.concatenate([_mesh_triangles(layout, k) for k in range(len(layout.parts))]) \
        if layout.parts else np.zeros((0, 3), dtype=np.int64)
    return mesh_occlusion(points, normals, triangles, radius_mm, receivers=receivers)


def _mesh_triangles(layout: PartLayout, k: int) -> np.ndarray:
    from engine.model.cells import cells_to_triangles

    return cells_to_triangles(layout.cells[k]) + layout.slices[k][0]


def mesh_occlusion(points: np.ndarray, normals: np.ndarray, triangles: np.ndarray, radius_mm: float = 30.0,
                   directions: int = DIRECTIONS, voxel_mm: float = VOXEL_MM,
                   receivers: np.ndarray | None = None) -> np.ndarray:
    """Open sky (0..1) at each of ``points`` (N × 3, mm) over its unit ``normals``, the ``triangles``
    (T × 3 indices into ``points``) hiding it; only at the points ``receivers`` if given (the others: 1).

    >>> square = np.array([[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0]], dtype=float)
    >>> wall = square[:, [2, 0, 1]] + [10, 0, 50]          # a wall standing 10 mm beside the floor's middle
    >>> points = np.vstack([square, wall, [[0, 0, 0], [-40, 0, 0]]])
    >>> up = np.tile([0.0, 0.0, 1.0], (len(points), 1))
    >>> floor_and_wall = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]])
    >>> open_sky = mesh_occlusion(points, up, floor_and_wall)[-2:]
    >>> bool(open_sky[0] < open_sky[1] < 1.0 + 1e-9)       # nearer the wall: less sky
    True
    """
    points = np.asarray(points, dtype=float)
    normals = np.asarray(normals, dtype=float)
    out = np.ones(len(points))
    if len(points) == 0 or len(triangles) == 0:
        return out
    grid, origin = _surface_grid(points, np.asarray(triangles, dtype=np.int64), voxel_mm, radius_mm)
    flat = grid.ravel()
    strides = np.array([grid.shape[1] * grid.shape[2], grid.shape[2], 1], dtype=np.int64)
    pattern = _hemisphere(directions)
    # steps growing geometrically out to the radius: near folds finely, far walls coarsely
    distances = np.geomspace(_FIRST * voxel_mm, radius_mm, _STEPS)
    falloff = np.append(1.0 - (distances / radius_mm) ** 2, 0.0)     # last entry: nothing met
    valid = np.linalg.norm(normals, axis=1) > 0.5
    todo = np.flatnonzero(valid) if receivers is None else np.intersect1d(receivers, np.flatnonzero(valid))
    for start in range(0, len(todo), _CHUNK):
        rows = todo[start:start + _CHUNK]
        rays = _oriented(pattern, normals[rows], rows).astype(np.float32)      # (n, D, 3)
        starts = ((points[rows] + _LIFT * voxel_mm * normals[rows] - origin) / voxel_mm).astype(np.float32)
        samples = starts[:, None, None, :] + (distances / voxel_mm).astype(np.float32)[None, None, :, None] \
            * rays[:, :, None, :]                                               # (n, D, S, 3) in cells
        index = np.floor(samples).astype(np.int64) @ strides
        hit = flat[index]
        first = np.where(hit.any(axis=-1), np.argmax(hit, axis=-1), _STEPS)      # first step that meets the surface
        out[rows] = 1.0 - falloff[first].mean(axis=1)
    smoothed = _smoothed(out, triangles, len(points))
    if receivers is not None:
        out[receivers] = smoothed[receivers]
        return out
    return smoothed


def _surface_grid(points: np.ndarray, triangles: np.ndarray, voxel_mm: float,
                  margin_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """A boolean grid marking every cell a triangle passes through (sampled at a third of a cell) and its
    six neighbours, and the grid's corner (mm). The margin keeps every ray's samples inside."""
    origin = points.min(axis=0) - margin_mm - voxel_mm
    shape = np.ceil((points.max(axis=0) + margin_mm + voxel_mm - origin) / voxel_mm).astype(int) + 1
    grid = np.zeros(tuple(shape), dtype=bool)
    a, b, c = points[triangles[:, 0]], points[triangles[:, 1]], points[triangles[:, 2]]
    longest = np.max([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1), np.linalg.norm(a - c, axis=1)],
                     axis=0)
    splits = np.maximum(1, np.ceil(longest / (voxel_mm / 3.0))).astype(int)
    for n in np.unique(splits):
        chosen = splits == n
        i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
        keep = i + j <= n
        u, v = (i[keep] / n)[:, None], (j[keep] / n)[:, None]               # barycentric samples
        ta, tb, tc = a[chosen][:, None], b[chosen][:, None], c[chosen][:, None]
        samples = (ta + u[None] * (tb - ta) + v[None] * (tc - ta)).reshape(-1, 3)
        cells = np.floor((samples - origin) / voxel_mm).astype(np.int64)
        grid[cells[:, 0], cells[:, 1], cells[:, 2]] = True
    thick = grid.copy()                            # one cell thicker each way: no ray slips between cells
    for axis in range(3):
        thick[(slice(None),) * axis + (slice(1, None),)] |= grid[(slice(None),) * axis + (slice(None, -1),)]
        thick[(slice(None),) * axis + (slice(None, -1),)] |= grid[(slice(None),) * axis + (slice(1, None),)]
    return thick, origin


def _hemisphere(count: int) -> np.ndarray:
    """``count`` cosine-weighted directions about +Z: a golden-angle spiral on the disc, lifted onto the
    hemisphere (equal areas on the disc are equal shares of cosine-weighted sky)."""
    k = np.arange(count) + 0.5
    radius = np.sqrt(k / count)
    angle = k * np.pi * (3.0 - np.sqrt(5.0))
    x, y = radius * np.cos(angle), radius * np.sin(angle)
    return np.column_stack([x, y, np.sqrt(np.maximum(0.0, 1.0 - x * x - y * y))])


def _oriented(pattern: np.ndarray, normals: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """The pattern turned so its +Z is each normal, and about it by a fixed angle per point (no banding)."""
    helper = np.where(np.abs(normals[:, [0]]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    tangent = np.cross(helper, normals)
    tangent /= np.maximum(np.linalg.norm(tangent, axis=1, keepdims=True), 1e-12)
    bitangent = np.cross(normals, tangent)
    turn = (rows * 0.6180339887498949 % 1.0) * 2 * np.pi
    cos, sin = np.cos(turn)[:, None], np.sin(turn)[:, None]
    t, b = cos * tangent + sin * bitangent, -sin * tangent + cos * bitangent
    return (pattern[None, :, 0, None] * t[:, None] + pattern[None, :, 1, None] * b[:, None]
            + pattern[None, :, 2, None] * normals[:, None])


def _smoothed(values: np.ndarray, triangles: np.ndarray, count: int) -> np.ndarray:
    """Each value averaged with its edge neighbours' (once, half and half): the rays' noise evened out."""
    from scipy import sparse

    rows = np.concatenate([triangles[:, 0], triangles[:, 1], triangles[:, 2], triangles[:, 1], triangles[:, 2],
                           triangles[:, 0]])
    cols = np.concatenate([triangles[:, 1], triangles[:, 2], triangles[:, 0], triangles[:, 0], triangles[:, 1],
                           triangles[:, 2]])
    adjacency = sparse.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(count, count))
    adjacency.data[:] = 1.0                       # an edge shared by two triangles counts once
    degree = np.asarray(adjacency.sum(axis=1)).ravel()
    neighbours = np.divide(adjacency @ values, degree, out=values.copy(), where=degree > 0)
    return np.clip(0.5 * values + 0.5 * neighbours, 0.0, 1.0)
