"""Brushes: one dab of add / subtract / set / smooth at a 3-D point, the gradient tool, sampling.

A dab is computed, not applied: :func:`compute_dab` returns a
:class:`~engine.painting.change.Change` (indices, before, after) for the
caller to apply (``change.redo(weights)``) or gather into a
:class:`~engine.painting.strokes.Stroke`. All positions are rest-mesh
coordinates in mm; the workbench maps a pick on a posed mesh back to the
rest mesh before calling.

For vertex ``i`` at distance ``d`` from the hit point, the dab's strength is
``a = strength · pressure · falloff(d / radius)`` and the new weight is

* add:      ``w + a · value``
* subtract: ``w − a · value``
* set:      ``w + a · (value − w)``   (towards ``value``; ``a = 1`` replaces)
* smooth:   ``w + a · (mean of the neighbours' weights − w)``

clipped to [0, 1].

>>> import numpy as np
>>> from engine import load_model
>>> from engine.painting import PaintContext, Brush, compute_dab
>>> head = load_model(); ctx = PaintContext(head)
>>> w = np.zeros(head.n_vertices)
>>> tip = head.vertices[head.landmarks["9.3"]]              # the nose tip
>>> change = compute_dab(ctx, w, Brush("add", radius=15, strength=0.5), tip, view_direction=(0, 0, -1))
>>> change.redo(w)
>>> bool(w[head.landmarks["9.3"]] == 0.5), len(change) > 10
(True, True)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.painting.change import Change
from engine.painting.mirror import mirrored_points, mirrored_vectors
from engine.painting.topology import PaintContext, _point
from engine.painting.weights import clip01

MODES = ("add", "subtract", "set", "smooth")


def _smooth(t: np.ndarray) -> np.ndarray:
    return 1.0 - t * t * (3.0 - 2.0 * t)


def _linear(t: np.ndarray) -> np.ndarray:
    return 1.0 - t


def _constant(t: np.ndarray) -> np.ndarray:
    return np.ones_like(t)


def _sharp(t: np.ndarray) -> np.ndarray:
    return (1.0 - t) ** 2


def _sphere(t: np.ndarray) -> np.ndarray:
    return np.sqrt(np.maximum(1.0 - t * t, 0.0))


FALLOFFS: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "smooth": _smooth, "linear": _linear, "constant": _constant, "sharp": _sharp, "sphere": _sphere,
}
"""Falloff curves ``f(t)``, ``t = distance / radius`` in [0, 1]; 1 at the centre."""

Falloff = str | Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Brush:
    """A brush's settings (the tool-options panel).

    Attributes
    ----------
    mode : ``"add"``, ``"subtract"``, ``"set"`` or ``"smooth"``
    radius : float
        mm.
    strength : float
        0–1, scales every dab.
    falloff : str or callable
        A name in :data:`FALLOFFS` or ``f(t) -> array`` with ``t = d / radius``
        in [0, 1] (values outside [0, 1] are clipped).
    value : float
        The weight added, subtracted, or set towards (0–1).
    front_faces_only : bool
        Paint only vertices whose normal faces the viewer.
    part : str or None
        Paint only this part (``"skin"``, ``"tongue"``, …).
    mirror : bool
        Also paint the mirror image (through the context's mirror map).
    connected : bool
        Only vertices joined to the hit vertex over the surface without
        leaving the brush's ball; ``False`` paints across gaps such as the
        lips.
    """

    mode: str = "add"
    radius: float = 10.0
    strength: float = 0.5
    falloff: Falloff = "smooth"
    value: float = 1.0
    front_faces_only: bool = False
    part: str | None = None
    mirror: bool = False
    connected: bool = True

    def __post_init__(self) -> None:
        if self.mode not in MODES:
            raise UserError(f"unknown brush mode '{self.mode}' (modes: {', '.join(MODES)})")
        if not (np.isfinite(self.radius) and self.radius > 0):
            raise UserError(f"brush radius must be a positive number of mm, not {self.radius!r}")
        if not 0 <= self.strength <= 1:
            raise UserError(f"brush strength must be in [0, 1], not {self.strength!r}")
        if not 0 <= self.value <= 1:
            raise UserError(f"brush value must be in [0, 1], not {self.value!r}")
        if isinstance(self.falloff, str) and self.falloff not in FALLOFFS:
            raise UserError(f"unknown falloff '{self.falloff}' (falloffs: {', '.join(FALLOFFS)})")
        if not isinstance(self.falloff, str) and not callable(self.falloff):
            raise UserError("a falloff is a name or a function of t = distance / radius")

    def falloff_values(self, t: np.ndarray) -> np.ndarray:
        """The falloff at ``t = d / radius`` (clipped to [0, 1])."""
        f = FALLOFFS[self.falloff] if isinstance(self.falloff, str) else self.falloff
        v = np.asarray(f(np.clip(t, 0.0, 1.0)), dtype=float)
        if v.shape != np.shape(t):
            raise UserError("a falloff function must return one value per distance")
        return np.clip(v, 0.0, 1.0)


def _facing(ctx: PaintContext, idx: np.ndarray, view_direction: npt.ArrayLike | None,
            camera_position: npt.ArrayLike | None) -> np.ndarray:
    """True where the vertex normal faces the viewer."""
    n = ctx.normals[idx]
    if camera_position is not None:
        look = ctx.vertices[idx] - _point(camera_position)
        return np.einsum("ij,ij->i", n, look) < 0
    v = _point(view_direction)
    return n[:, 0] * v[0] + n[:, 1] * v[1] + n[:, 2] * v[2] < 0     # not n @ v: BLAS set-up costs more here


def paintable_mask(ctx: PaintContext, part: str | None = None, front_faces_only: bool = False,
                   view_direction: npt.ArrayLike | None = None,
                   camera_position: npt.ArrayLike | None = None) -> np.ndarray | None:
    """(N,) bool: vertices of ``part`` facing the viewer, or None when nothing is excluded.

    Cached on the context for the last few (part, view) combinations: the
    camera does not move during a stroke, so every dab after the first
    reads the mask instead of testing normals again.
    """
    if front_faces_only and view_direction is None and camera_position is None:
        raise UserError("front-faces-only painting needs the view direction or the camera position")
    if part is None and not front_faces_only:
        return None
    view = None
    if front_faces_only:
        view = ("eye", *_point(camera_position)) if camera_position is not None else ("dir", *_point(view_direction))
    key = (part, view)
    cache = ctx._paintable
    mask = cache.get(key)
    if mask is None:
        mask = ctx.part_mask(part)
        if front_faces_only:
            mask &= _facing(ctx, np.arange(ctx.n_vertices), view_direction, camera_position)
        if len(cache) >= 8:
            cache.pop(next(iter(cache)))
        cache[key] = mask
    return mask


def brush_footprint(ctx: PaintContext, brush: Brush, point: npt.ArrayLike,
                    view_direction: npt.ArrayLike | None = None, *, camera_position: npt.ArrayLike | None = None,
                    pressure: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """The vertices a dab reaches and the strength it has at each: ``(indices, a)``, indices sorted.

    ``view_direction`` is the direction the camera looks (rest-mesh frame;
    needed for ``front_faces_only`` unless ``camera_position`` is given,
    which handles perspective exactly). ``pressure`` (0–1, a tablet's)
    scales the strength. With ``brush.mirror`` the footprint includes the
    mirror images (strength the larger of the two where they overlap).
    """
    p = _point(point)
    ok = paintable_mask(ctx, brush.part, brush.front_faces_only, view_direction, camera_position)
    found = ctx.tree.query_ball_point(p, brush.radius, return_sorted=False)
    idx = np.fromiter(found, dtype=np.int64, count=len(found))
    if ok is not None:
        idx = idx[ok[idx]]
    idx = _sorted_unique(ctx, idx)
    if brush.connected and len(idx):
        seed = int(ctx.tree.query(p)[1])                # usually the nearest vertex passes the filters…
        pos = np.searchsorted(idx, seed)
        if pos >= len(idx) or idx[pos] != seed:
            seed = ctx.nearest_vertex(p, idx)           # …else the nearest one that does
        idx = ctx.connected_within(seed, idx)
    diff = ctx.vertices[idx] - p
    d = np.sqrt(np.einsum("ij,ij->i", diff, diff))
    a = brush.falloff_values(d / brush.radius) * (brush.strength * float(np.clip(pressure, 0.0, 1.0)))
    if brush.mirror and len(idx):
        idx, a = _with_mirror(ctx, idx, a)
    nz = a > 0
    return idx[nz], a[nz]


def _sorted_unique(ctx: PaintContext, idx: np.ndarray) -> np.ndarray:
    """Sorted distinct indices: a scan of an N-byte mask beats sorting once a dab reaches a few thousand vertices."""
    if len(idx) < 2048:
        return np.unique(idx)
    mark = np.zeros(ctx.n_vertices, dtype=bool)
    mark[idx] = True
    return np.flatnonzero(mark)


def _with_mirror(ctx: PaintContext, idx: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The footprint and its mirror image; where they overlap, the stronger of the two strengths."""
    m = ctx.mirror.map[idx]
    ok = m >= 0
    strength = np.zeros(ctx.n_vertices)
    strength[m[ok]] = a[ok]
    np.maximum(strength[idx], a, out=a)
    strength[idx] = a
    both = _sorted_unique(ctx, np.concatenate([idx, m[ok]]))
    return both, strength[both]


def _blend(ctx: PaintContext, weights: np.ndarray, mode: str, idx: np.ndarray, a: np.ndarray,
           target: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
    """New weights of ``idx`` for strengths ``a`` and the mode's target (value or neighbour mean)."""
    w = weights[idx]
    if mode == "add":
        new = w + a * target
    elif mode == "subtract":
        new = w - a * target
    else:
        new = w + a * (target - w)
    return w, clip01(new)


def compute_dab(ctx: PaintContext, weights: np.ndarray, brush: Brush, point: npt.ArrayLike,
                view_direction: npt.ArrayLike | None = None, *,
                camera_position: npt.ArrayLike | None = None, pressure: float = 1.0) -> Change:
    """One dab of ``brush`` at ``point`` (mm) on dense ``weights`` (not modified).

    Returns the vertices whose weight changes with their old and new values.
    """
    if weights.shape != (ctx.n_vertices,):
        raise UserError(f"expected {ctx.n_vertices} weights (one per vertex), got shape {weights.shape}")
    idx, a = brush_footprint(ctx, brush, point, view_direction, camera_position=camera_position,
                             pressure=pressure)
    if len(idx) == 0:
        return Change.empty()
    target = ctx.neighbour_mean[idx] @ weights if brush.mode == "smooth" else brush.value
    before, after = _blend(ctx, weights, brush.mode, idx, a, target)
    moved = before.view(np.uint64) != after.view(np.uint64)
    return Change(idx[moved], before[moved], after[moved])


def compute_gradient(ctx: PaintContext, weights: np.ndarray, start: npt.ArrayLike, end: npt.ArrayLike, *,
                     start_value: float = 1.0, end_value: float = 0.0, mode: str = "set", strength: float = 1.0,
                     part: str | None = None, front_faces_only: bool = False,
                     view_direction: npt.ArrayLike | None = None, camera_position: npt.ArrayLike | None = None,
                     connected: bool = False, mirror: bool = False, mask: npt.ArrayLike | None = None) -> Change:
    """A linear weight ramp from ``start`` to ``end`` (points in mm), flat beyond both ends.

    The ramp value at vertex ``P`` is ``start_value`` before ``start``,
    ``end_value`` past ``end`` (measured along ``end − start``), linear in
    between; it is blended into the weights by ``mode`` (``"set"`` moves
    towards it by ``strength``; ``"add"``/``"subtract"`` add or remove
    ``strength ·`` ramp) and clipped to [0, 1]. The restrictions are the
    brushes': ``part``, ``front_faces_only``, ``connected`` (only the piece of
    surface under ``start``), ``mirror`` (the side of ``start`` is copied onto
    the other through the mirror map), and an optional vertex ``mask``.
    """
    if mode not in ("set", "add", "subtract"):
        raise UserError(f"gradient mode must be set, add or subtract, not '{mode}'")
    if not 0 <= strength <= 1 or not 0 <= start_value <= 1 or not 0 <= end_value <= 1:
        raise UserError("gradient strength and values must be in [0, 1]")
    s, e = _point(start), _point(end)
    axis = e - s
    length2 = float(axis @ axis)
    if length2 == 0:
        raise UserError("a gradient needs two different points")
    ok = paintable_mask(ctx, part, front_faces_only, view_direction, camera_position)
    ok = np.ones(ctx.n_vertices, dtype=bool) if ok is None else ok.copy()
    if mask is not None:
        ok &= np.asarray(mask, dtype=bool)
    if connected:
        ok &= ctx.components == ctx.components[ctx.nearest_vertex(s, np.flatnonzero(ok))]
    if mirror and s[0] != ctx.mirror.center:
        # the ramp is drawn on the side of ``start`` and copied onto the other side
        x = ctx.vertices[:, 0] - ctx.mirror.center
        ok &= (np.sign(x) == np.sign(s[0] - ctx.mirror.center)) | (x == 0)
    idx = np.flatnonzero(ok)
    t = np.clip((ctx.vertices[idx] - s) @ axis / length2, 0.0, 1.0)
    ramp = start_value + t * (end_value - start_value)
    w = weights[idx]
    if mode == "set":
        new = w + strength * (ramp - w)
    elif mode == "add":
        new = w + strength * ramp
    else:
        new = w - strength * ramp
    new = clip01(new)
    if mirror:
        m = ctx.mirror.map[idx]
        keep = (m >= 0) & (m != idx)
        extra, extra_new = m[keep], new[keep]
        fresh = ~np.isin(extra, idx)
        idx = np.concatenate([idx, extra[fresh]])
        new = np.concatenate([new, extra_new[fresh]])
        order = np.argsort(idx)
        idx, new = idx[order], new[order]
    before = weights[idx]
    moved = before.view(np.uint64) != new.view(np.uint64)
    return Change(idx[moved], before[moved].copy(), new[moved])


def sample_weight(ctx: PaintContext, weights: np.ndarray, point: npt.ArrayLike, *, part: str | None = None,
                  radius: float | None = None) -> float:
    """The weight under ``point`` (mm): the nearest vertex's, or with ``radius`` the mean within it
    weighted by the smooth falloff (the eyedropper)."""
    p = _point(point)
    if radius is None:
        if part is None:
            return float(weights[ctx.nearest_vertex(p)])
        cand = np.flatnonzero(ctx.part_mask(part))
        i = ctx.nearest_vertex(p, cand)
        return float(weights[i]) if i >= 0 else 0.0
    idx = np.asarray(ctx.tree.query_ball_point(p, radius), dtype=np.int64)
    if part is not None and len(idx):
        idx = idx[ctx.vertex_part[idx] == ctx.part_index(part)]
    if len(idx) == 0:
        return sample_weight(ctx, weights, p, part=part)
    f = _smooth(np.linalg.norm(ctx.vertices[idx] - p, axis=1) / radius) + 1e-12
    return float(weights[idx] @ f / f.sum())


def mirrored_dab_point(ctx: PaintContext, point: npt.ArrayLike,
                       view_direction: npt.ArrayLike | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """The mirror image of a hit point and view direction (for drawing the second brush cursor)."""
    p = mirrored_points(_point(point), ctx.mirror.center)
    return p, None if view_direction is None else mirrored_vectors(_point(view_direction))
