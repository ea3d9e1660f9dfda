"""The upper lids' rest height: how much of the iris the upper lid covers, measured, and set for a relaxed face.

In a relaxed, neutral face the upper lid covers the top of the iris by a
millimetre or two (the margin–reflex distance MRD1, pupil centre to lid
margin, is about 4–5 mm on an iris of 5.9 mm radius); a lid that leaves the
top of the iris bare is FACS's AU5, the upper lid raiser of surprise and
fear. :func:`upper_lid_cover` measures it as a front-view photograph shows it
(where the lid skin hides the eyeball, not where the lid's vertices are: the
lid margin tucks behind the eyeball's surface), and :func:`lowered_lids`
lowers an upper lid that covers less than :data:`REST_COVER` of the iris
radius, by the blink's own rotation about the eyeball's centre. The default
head's derivation bakes it into its rest mesh (:func:`lower_rest_lids`) and
every identity's build into the identity's (docs/default-head.md,
docs/identity.md).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

import numpy as np

from engine.identity.carry_over import Similarity
from engine.model import Model

IRIS_DEGREES = 25.0     # the iris edge on the eyeball, from its centre (engine/data/default-head/head_colors.py)
REST_COVER = 0.35       # the rest upper lid covers at least this share of the iris radius (2.2 mm on the default head)
STEP_MM = 0.02          # the vertical sampling of the measure
TOLERANCE_MM = 0.01     # how close the lowered lid comes to its goal


def eyeball(model: Model, side: str) -> tuple[np.ndarray, float]:
    """The centre and radius of an eyeball (a sphere about its gaze pivot) of the rest mesh."""
    eye = model.vertices[model.part_vertices(f"eye_{side}")]
    name = f"eye_{side}_turn"
    centre = np.asarray(model.parameters[name].pivot, dtype=float) if name in model.parameters else eye.mean(axis=0)
    return centre, float(np.linalg.norm(eye - centre, axis=1).max())


def _skin_triangles(model: Model) -> np.ndarray:
    is_skin = model.vertex_part == model.parts.index("skin")
    tri = model.triangles()
    return tri[is_skin[tri].all(axis=1)]


def _visible(P: np.ndarray, tri: np.ndarray, centre: np.ndarray, radius: float) -> tuple[float, float] | None:
    """(top, bottom) of the sphere seen from the front (orthographic, along −Z) through the skin
    triangles ``tri`` of positions ``P``, on the vertical through its centre, mm above the centre;
    None where the skin hides the centre."""
    T = P[tri]
    x = T[:, :, 0] - centre[0]
    keep = (x.min(axis=1) <= 0) & (x.max(axis=1) >= 0) & (np.abs(T[:, :, 1] - centre[1]).min(axis=1) < radius + 5) \
        & (T[:, :, 2].max(axis=1) > centre[2])
    T, x = T[keep], x[keep]
    if not len(T):
        return None
    # where each edge crosses the plane x = centre.x; a triangle's first two crossings bound its cut
    points, hits = [], []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        xa, xb = x[:, a], x[:, b]
        span = xa - xb
        t = np.divide(xa, span, out=np.full(len(T), -1.0), where=span != 0)
        hits.append((t >= 0) & (t <= 1))
        points.append(T[:, a, 1:] + t[:, None] * (T[:, b, 1:] - T[:, a, 1:]))
    H, Q = np.stack(hits, axis=1), np.stack(points, axis=1)          # (m, 3), (m, 3, 2)
    first = np.argmax(H, axis=1)
    second = 2 - np.argmax(H[:, ::-1], axis=1)
    ok = H.sum(axis=1) >= 2
    rows = np.arange(len(T))[ok]
    A, B = Q[rows, first[ok]], Q[rows, second[ok]]                   # (y, z) ends
    ys = np.arange(centre[1] - radius + STEP_MM, centre[1] + radius, STEP_MM)
    z_eye = centre[2] + np.sqrt(np.maximum(radius * radius - (ys - centre[1]) ** 2, 0.0))
    lo, hi = np.minimum(A[:, 0], B[:, 0]), np.maximum(A[:, 0], B[:, 0])
    dy = B[:, 0] - A[:, 0]
    u = (ys[None] - A[:, 0, None]) / np.where(dy != 0, dy, 1.0)[:, None]
    z = A[:, 1, None] + u * (B[:, 1] - A[:, 1])[:, None]
    over = (ys[None] >= lo[:, None]) & (ys[None] <= hi[:, None]) & (hi - lo > 1e-12)[:, None] & (z > z_eye[None])
    visible = ~over.any(axis=0)
    i = int(np.argmin(np.abs(ys - centre[1])))
    if not visible[i]:
        return None
    hidden = np.flatnonzero(~visible)
    above, below = hidden[hidden > i], hidden[hidden < i]
    top = (above[0] - 1) if len(above) else len(ys) - 1
    bottom = (below[-1] + 1) if len(below) else 0
    return float(ys[top] - centre[1]), float(ys[bottom] - centre[1])


def iris_radius(model: Model, side: str) -> float:
    return eyeball(model, side)[1] * float(np.sin(np.radians(IRIS_DEGREES)))


def upper_lid_cover(model: Model, side: str, positions: np.ndarray | None = None) -> float:
    """How far (mm) the upper lid comes down over the iris, seen from the front: 0 at the iris's top,
    negative where sclera shows above the iris (AU5), the iris radius when it reaches the pupil's centre.

    ``positions``: a pose of ``model`` (its rest mesh by default), the eyeball where the pose has it."""
    r, seen = _iris_seen(model, side, positions)
    return r if seen is None else r - seen[0]


def lower_lid_cover(model: Model, side: str, positions: np.ndarray | None = None) -> float:
    """How far (mm) the lower lid comes up over the iris, from the front (negative: sclera below it)."""
    r, seen = _iris_seen(model, side, positions)
    return r if seen is None else r + seen[1]


def _iris_seen(model: Model, side: str,
              positions: np.ndarray | None) -> tuple[float, tuple[float, float] | None]:
    """The iris radius (mm) and what of it the lids leave visible from the front (``_visible``), in a pose
    of ``model`` (its rest mesh by default), the eyeball where the pose has it."""
    P = model.vertices if positions is None else positions
    centre, radius = eyeball(model, side)
    eye = model.part_vertices(f"eye_{side}")
    centre = centre + P[eye].mean(axis=0) - model.vertices[eye].mean(axis=0)
    seen = _visible(P, _skin_triangles(model), centre, radius)
    r = radius * float(np.sin(np.radians(IRIS_DEGREES)))
    return r, seen


def lowered_lids(base: Model, positions: np.ndarray, eyes: Mapping[str, Similarity] | None = None,
                 share: float = REST_COVER) -> tuple[np.ndarray, dict[str, float]]:
    """``positions`` (a new rest shape of ``base``'s mesh) with each upper lid that covers less than
    ``share`` of its iris radius lowered until it covers that much, and the blink value used per side.

    The lid turns down as ``base``'s blink (``eyelid_<side>_close``: its weights, its lashes) does, about
    the eyeball's centre; ``eyes`` says how each eyeball moved from ``base`` (``eye_left`` …: the
    identity's similarity transforms), none for ``base``'s own rest.
    """
    P = np.array(positions, dtype=float)
    tri = _skin_triangles(base)
    baked = {}
    for side in ("left", "right"):
        name, part = f"eyelid_{side}_close", f"eye_{side}"
        if name not in base.regions or part not in base.parts:
            continue
        p, region = base.parameters[name], base.regions[name]
        centre, radius = eyeball(base, side)
        axis = np.asarray(p.axis, dtype=float)
        move = (eyes or {}).get(part)
        if move is not None:
            centre, radius, axis = move.point(centre), move.scale * radius, move.direction(axis)
        goal = share * radius * float(np.sin(np.radians(IRIS_DEGREES)))
        idx, w = region.indices, region.weights[:, None]
        lid = P[idx]
        near = tri[(np.abs(P[tri][:, :, :2] - centre[:2]).max(axis=2) < radius + 10).any(axis=1)]

        def lowered(value: float, lid: np.ndarray = lid, w: np.ndarray = w, axis: np.ndarray = axis,
                    centre: np.ndarray = centre, degrees: float = float(p.degrees_per_unit)) -> np.ndarray:
            # each vertex turned by its share of the angle, so that it keeps its distance to the eyeball
            # (the blink itself blends along chords, which would bring half-weighted lid skin closer)
            return _turned(lid, axis / np.linalg.norm(axis), centre, np.radians(value * degrees) * w[:, 0])

        def cover(value: float, idx: np.ndarray = idx, lowered: Callable[[float], np.ndarray] = lowered,
                  centre: np.ndarray = centre, radius: float = radius, near: np.ndarray = near) -> float:
            Q = P.copy()
            Q[idx] = lowered(value)
            seen = _visible(Q, near, centre, radius)
            r = radius * float(np.sin(np.radians(IRIS_DEGREES)))
            return r if seen is None else r - seen[0]

        lo, hi = 0.0, 0.5
        c_lo = cover(lo) - goal
        if c_lo >= 0:
            continue
        c_hi = cover(hi) - goal
        if c_hi <= 0:
            continue
        value = lo
        for _ in range(30):                     # regula falsi, Illinois variant
            value = hi - c_hi * (hi - lo) / (c_hi - c_lo)
            c = cover(value) - goal
            if abs(c) < TOLERANCE_MM:
                break
            if c < 0:
                lo, c_lo = value, c
                c_hi /= 2
            else:
                hi, c_hi = value, c
                c_lo /= 2
        P[idx] = lowered(value)
        baked[side] = round(float(value), 4)
    return P, baked


def _turned(P: np.ndarray, axis: np.ndarray, centre: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Each point of ``P`` turned about the axis through ``centre`` by its own angle (radians; Rodrigues)."""
    a = P - centre
    cos, sin = np.cos(angles)[:, None], np.sin(angles)[:, None]
    return centre + a * cos + np.cross(axis, a) * sin + axis * (a @ axis)[:, None] * (1 - cos)


def lower_rest_lids(model: Model, share: float = REST_COVER) -> dict[str, float]:
    """Lower ``model``'s rest upper lids as :func:`lowered_lids` says (in place), and make each blink's
    angle smaller by what was baked in, so that 1 still closes the eye. Returns the blink values."""
    P, baked = lowered_lids(model, model.vertices, share=share)
    model.vertices[:] = P
    for side, value in baked.items():
        p = model.parameters[f"eyelid_{side}_close"]
        p.degrees_per_unit = p.degrees_per_unit * (1.0 - value)
    model.changed()
    return baked
