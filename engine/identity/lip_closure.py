"""Lip closure refitted on a new face: the lower lip still just meets the upper lip at ``lower_lip_raise`` 1.

A new identity has other lips: thicker, wider, further apart at rest. The
carried-over closure field (:mod:`engine.identity.carry_over`) then leaves a
gap or pushes one lip through the other. :func:`refit_closure` adds a
vertical lift to the field, section by section across the mouth (sagittal
planes x = const), until the lips are :data:`CLEARANCE` mm apart and do not
cross, as the default head's derivation fits it (``data/default-head``).

:class:`LipSections` tells the two lips apart on the rest mesh by the jaw's
share of each vertex and cuts them in sagittal planes.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from engine.model import InfluenceRegion, Model

CLEARANCE = 0.15        # mm between the lips where they meet
SPAN = 0.75             # sections across this fraction of the mouth's half-width
NODES = 13
CHECKS = 31


class LipSections:
    """The two lips of a rest mesh, and their outlines in sagittal sections of any pose."""

    def __init__(self, model: Model) -> None:
        P, lm, n = model.vertices, model.landmarks, model.n_vertices
        self.rest = P
        self.landmarks = lm
        jaw = model.regions["jaw_open"].dense(n)
        total = sum(model.regions[name].dense(n) for name in ("jaw_open", "head_tilt", "neck_lean")
                    if name in model.regions)
        share = np.divide(jaw, total, out=np.zeros(n), where=total > 0)
        skin = model.vertex_part == model.parts.index("skin")
        tri = model.triangles()
        tri = tri[np.all(skin[tri], axis=1)]
        corners = P[[lm["8.3"], lm["8.4"]]]
        centre = (P[lm["2.2"]] + P[lm["2.3"]]) / 2
        half = self.half_width(P)
        c = P[tri].mean(axis=1)
        zone = (np.abs(c[:, 0]) < 1.3 * half) & (np.abs(c[:, 1] - centre[1]) < 15) & (c[:, 2] > corners[:, 2].min() - 8)
        self.triangles, c = tri[zone], c[zone]
        tri_share = share[self.triangles].mean(axis=1)
        xs, ys = [], []
        for x in np.arange(0.0, 0.95 * half, 0.5):
            segments, k = self._cut(P, x + 1e-4)
            up, lo = segments[tri_share[k] < 0.35].reshape(-1, 2), segments[tri_share[k] > 0.65].reshape(-1, 2)
            up, lo = up[up[:, 1] > centre[1] - 6], lo[lo[:, 1] < centre[1] + 6]
            if len(up) and len(lo):
                xs.append(x)
                ys.append((up[:, 1].min() + lo[:, 1].max()) / 2)
        self.line_x, self.line_y = np.array(xs), np.array(ys)
        self.upper_triangle = c[:, 1] > np.interp(np.abs(c[:, 0]), self.line_x, self.line_y)
        self.upper_vertex = P[:, 1] > np.interp(np.abs(P[:, 0]), self.line_x, self.line_y)

    def half_width(self, P: np.ndarray) -> float:
        return float(abs(P[self.landmarks["8.3"], 0] - P[self.landmarks["8.4"], 0]) / 2)

    def _cut(self, P: np.ndarray, x: float) -> tuple[np.ndarray, np.ndarray]:
        """Segments (k, 2, 2) in (z, y) where the plane X = x cuts the mouth's triangles, and which triangles."""
        pts = P[self.triangles]
        d = pts[:, :, 0] - x
        below = d < 0
        segments = np.zeros((len(pts), 2, 2))
        count = np.zeros(len(pts), dtype=int)
        for a, b in ((0, 1), (1, 2), (2, 0)):
            crossing = below[:, a] != below[:, b]
            t = np.where(crossing, d[:, a] / np.where(crossing, d[:, a] - d[:, b], 1.0), 0.0)
            q = pts[:, a] + t[:, None] * (pts[:, b] - pts[:, a])
            for slot in (0, 1):
                put = crossing & (count == slot)
                segments[put, slot] = q[put][:, [2, 1]]
                count[put] += 1
                crossing &= ~put
        keep = np.flatnonzero(count == 2)
        return segments[keep], keep

    def outlines(self, P: np.ndarray, x: float) -> tuple[np.ndarray, np.ndarray]:
        """The upper and lower lip's outlines in the plane X = x, as (z, y) segments."""
        segments, k = self._cut(P, x)
        up = self.upper_triangle[k]
        return segments[up], segments[~up]

    def distance_at(self, P: np.ndarray, x: float) -> float:
        """The lips' smallest distance in the plane X = x, negative where they cross."""
        U, L = self.outlines(P, x)
        return -1.0 if _crossings(U, L) else _distance(U, L)

    def clear_at(self, P: np.ndarray, x: float, clearance: float) -> bool:
        """True if in the plane X = x the lips' outlines do not cross and stay ``clearance`` apart."""
        return self.distance_at(P, x) >= clearance

    def clear(self, P: np.ndarray, clearance: float, n: int = CHECKS) -> bool:
        half = self.half_width(P)
        return all(self.clear_at(P, x, clearance) for x in np.linspace(-SPAN, SPAN, n) * half + 1e-4)


def _crossings(A: np.ndarray, B: np.ndarray) -> int:
    if len(A) == 0 or len(B) == 0:
        return 0
    p, r = A[:, None, 0], (A[:, 1] - A[:, 0])[:, None]
    q, s = B[None, :, 0], (B[:, 1] - B[:, 0])[None]

    def cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
        return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]

    den = cross(r, s)
    with np.errstate(divide="ignore", invalid="ignore"):
        t, u = cross(q - p, s) / den, cross(q - p, r) / den
    e = 1e-9
    return int(np.sum((np.abs(den) > 1e-12) & (t > e) & (t < 1 - e) & (u > e) & (u < 1 - e)))


def _distance(A: np.ndarray, B: np.ndarray) -> float:
    if len(A) == 0 or len(B) == 0:
        return float("inf")

    def point_to_segments(p: np.ndarray, S: np.ndarray) -> float:
        a, ab = S[:, 0], S[:, 1] - S[:, 0]
        t = np.einsum("pij,pij->pi", p[:, None] - a[None], ab[None]) / np.maximum((ab * ab).sum(-1), 1e-12)
        t = np.clip(t, 0, 1)
        return float(np.linalg.norm(p[:, None] - (a[None] + t[..., None] * ab[None]), axis=-1).min())

    return min(point_to_segments(A.reshape(-1, 2), B), point_to_segments(B.reshape(-1, 2), A))


def _largest(holds: Callable[[float], bool], lo: float, hi: float, steps: int = 12) -> float:
    """The largest value in [lo, hi] where ``holds`` (bisection); ``lo`` when it never holds."""
    if not holds(lo):
        return 0.0
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if holds(mid) else (lo, mid)
    return lo


def _smooth(values: np.ndarray) -> np.ndarray:
    p = np.r_[values[1], values, values[-1]]
    return (p[:-2] + 2 * p[1:-1] + p[2:]) / 4


def refit_closure(model: Model, name: str = "lower_lip_raise", iterations: int = 2) -> None:
    """Add a vertical lift to ``model``'s closure field so that its lips just meet at value 1 (in place)."""
    if name not in model.regions or model.regions[name].displacements is None:
        return
    region = model.regions[name]
    lips = LipSections(model)
    P0 = model.vertices
    idx = region.indices
    D = np.array(region.displacements, dtype=float)
    at_mid = np.flatnonzero(idx == model.landmarks["2.3"])
    if not len(at_mid):
        return
    weight = np.clip(np.linalg.norm(D, axis=1) / np.linalg.norm(D[at_mid[0]]), 0.0, 1.0)
    weight[lips.upper_vertex[idx]] = 0.0
    # The lower lip's midpoint goes forward under the upper lip's, as on the default head (2.3 under 2.2).
    forward = P0[model.landmarks["2.2"], 2] - P0[model.landmarks["2.3"], 2]
    D[:, 2] += weight * (forward - D[at_mid[0], 2])
    xs = np.linspace(0, SPAN * lips.half_width(P0), NODES)
    x_abs = np.abs(P0[idx, 0])

    def pose(lift: np.ndarray, shift: float = 0.0) -> np.ndarray:
        P = P0.copy()
        P[idx] += D
        P[idx, 1] += weight * (np.interp(x_abs, xs, lift) - shift)
        return P

    # Where a new face's lips already touch at rest (thin, old lips at the corners), they may stay as close.
    clearance = np.array([min(CLEARANCE, 0.5 * lips.distance_at(P0, x + 1e-4)) for x in xs])
    lift = np.zeros(NODES)
    up = np.zeros_like(P0)
    up[idx, 1] = weight
    def clears(P: np.ndarray, x: float, c: float) -> Callable[[float], bool]:
        return lambda v: lips.clear_at(P + v * up, x + 1e-4, c)

    for _ in range(iterations):
        P = pose(lift)
        extra = np.array([_largest(clears(P, x, c), -6.0, 6.0) if c >= 0 else 0.0
                          for x, c in zip(xs, clearance, strict=True)])
        lift = lift + _smooth(extra)
        if np.abs(extra).max() < 0.02:
            break
    shift = 0.0
    floor = max(0.0, min(CLEARANCE, float(clearance.min())))
    while shift < 3.0 and not lips.clear(pose(lift, shift), floor):
        shift += 0.05
    if shift >= 3.0:        # lips that touch at rest (some old faces): no shift clears them; keep the lift
        shift = 0.0
    D[:, 1] += weight * (np.interp(x_abs, xs, lift) - shift)
    model.regions[name] = InfluenceRegion(idx.copy(), region.weights.copy(), D)
    model.changed()
