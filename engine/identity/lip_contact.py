"""The two lips of a rest mesh, whether a pose makes them pass through each other, and fields that respect it.

The default head's derivation (``engine/data/default-head``) fits its articulatory
fields (§3.1.2) with these, and :mod:`engine.identity` fits them again on
every new face, so both use this one implementation:

* :class:`LipContact` tells the lips apart on the rest mesh by the rest
  *mouth line* (in each sagittal plane x = const, halfway between the lowest
  point of the upper lip and the highest point of the lower lip, found where
  the jaw's share is unambiguous) and checks a pose in sagittal sections: the
  outlines must not cross and stay ``clearance`` apart;
* :func:`fit_closure` makes the lower-lip closure field, lifted section by
  section until the lips just meet;
* :func:`follow_upper_lip` makes the lower lip near the mouth line move like
  the upper lip it touches when closed;
* :func:`keep_lips_apart` lowers the lower lip wherever a field (alone, or
  added to companion fields) would push it into the upper lip.

Lengths are mm.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from scipy import sparse
from scipy.spatial import cKDTree

SECTION_SPAN = 0.75         # lip sections are checked across this fraction of the mouth's half-width
CHECK_SECTIONS = 61
FOLLOW_DEPTH = 4.5          # mm below the mouth line over which the lower lip follows the upper lip


def smoothstep(x: np.ndarray | float) -> np.ndarray:
    x = np.clip(x, 0.0, 1.0)
    return np.asarray(x * x * (3 - 2 * x))


class LipContact:
    """The two lips of the rest mesh, and whether a pose makes them pass through each other."""

    SAMPLES = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, .5, 0], [0, .5, .5], [.5, 0, .5],
                        [1 / 3, 1 / 3, 1 / 3], [2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])

    def __init__(self, rest: np.ndarray, triangles: np.ndarray, skin: np.ndarray, jaw_share: np.ndarray,
                 landmarks: dict[str, int], span: float = SECTION_SPAN, touching_from: float | None = None) -> None:
        self.rest = rest
        #: Sections are checked across this fraction of the mouth's half-width …
        self.span = span
        #: … and from this |x| (mm) outwards the lips touch at rest (None: they are apart across the span).
        self.touching_from = touching_from
        self.landmarks = landmarks
        corners = rest[[landmarks["8.3"], landmarks["8.4"]]]
        centre = (rest[landmarks["2.2"]] + rest[landmarks["2.3"]]) / 2
        half = self.half_width(rest)
        tri = triangles[np.all(skin[triangles], axis=1)]
        c = rest[tri].mean(axis=1)
        zone = ((np.abs(c[:, 0]) < 1.3 * half) & (np.abs(c[:, 1] - centre[1]) < 15)
                & (c[:, 2] > corners[:, 2].min() - 8))
        self.triangles, c = tri[zone], c[zone]
        share = jaw_share[self.triangles].mean(axis=1)
        xs, ys = [], []
        for x in np.arange(0.0, 0.95 * half, 0.5):
            segments, k = self._cut(rest, x + 1e-4)
            up, lo = segments[share[k] < 0.35].reshape(-1, 2), segments[share[k] > 0.65].reshape(-1, 2)
            up, lo = up[up[:, 1] > centre[1] - 6], lo[lo[:, 1] < centre[1] + 6]
            if len(up) and len(lo):
                xs.append(x)
                ys.append((up[:, 1].min() + lo[:, 1].max()) / 2)
        self.line_x, self.line_y = np.array(xs), np.array(ys)
        self.upper_triangle = c[:, 1] > self.mouth_line(c[:, 0])
        self.upper_vertex = rest[:, 1] > self.mouth_line(rest[:, 0])
        in_zone = (skin & (np.abs(rest[:, 0]) < 1.3 * half) & (np.abs(rest[:, 1] - centre[1]) < 15)
                   & (rest[:, 2] > corners[:, 2].min() - 8))
        self.lower_lip = np.flatnonzero(in_zone & ~self.upper_vertex)
        self.upper_contact = np.flatnonzero(in_zone & self.upper_vertex
                                            & (rest[:, 1] - self.mouth_line(rest[:, 0]) < 1.5))
        # lower-lip triangles in the contact check: away from the corners, not sharing a vertex with the upper lip
        shared = np.zeros(len(rest), bool)
        shared[self.triangles[self.upper_triangle].ravel()] = True
        front = np.zeros(len(rest), bool)
        front[self.lower_lip] = ~shared[self.lower_lip] & (np.abs(rest[self.lower_lip, 0]) < 0.85 * half)
        lower = self.triangles[~self.upper_triangle]
        self.check_triangles = lower[np.all(front[lower], axis=1)]

    def mouth_line(self, x: np.ndarray) -> np.ndarray:
        return np.interp(np.abs(x), self.line_x, self.line_y)

    def half_width(self, P: np.ndarray) -> float:
        return float(abs(P[self.landmarks["8.3"], 0] - P[self.landmarks["8.4"], 0]) / 2)

    def _cut(self, P: np.ndarray, x: float) -> tuple[np.ndarray, np.ndarray]:
        """Segments (k, 2, 2) in (z, y) where the plane X = x cuts the mouth triangles, and their triangles."""
        segments, keep, _ = self.cut_with(P, x, np.zeros(len(P)))
        return segments, keep

    def cut_with(self, P: np.ndarray, x: float, values: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """As :meth:`_cut`, and a per-vertex ``values`` interpolated to the segments' ends (k, 2)."""
        tx = P[self.triangles, 0]
        near = np.flatnonzero((tx.min(axis=1) < x) & (tx.max(axis=1) >= x))   # only these can be cut
        pts = np.concatenate([P[self.triangles[near]], values[self.triangles[near]][..., None]], axis=2)
        d = pts[:, :, 0] - x
        below = d < 0
        segments = np.zeros((len(pts), 2, 3))
        count = np.zeros(len(pts), dtype=int)
        for a, b in ((0, 1), (1, 2), (2, 0)):
            crossing = below[:, a] != below[:, b]
            t = np.where(crossing, d[:, a] / np.where(crossing, d[:, a] - d[:, b], 1.0), 0.0)
            q = pts[:, a] + t[:, None] * (pts[:, b] - pts[:, a])
            for slot in (0, 1):
                put = crossing & (count == slot)
                segments[put, slot] = q[put][:, [2, 1, 3]]
                count[put] += 1
                crossing &= ~put
        keep = np.flatnonzero(count == 2)
        return segments[keep, :, :2], near[keep], segments[keep, :, 2]

    def section(self, P: np.ndarray, x: float) -> tuple[np.ndarray, np.ndarray]:
        """Upper-lip and lower-lip outlines in the sagittal plane X = x, as (z, y) segments."""
        segments, k = self._cut(P, x)
        up = self.upper_triangle[k]
        return segments[up], segments[~up]

    @staticmethod
    def crossings(A: np.ndarray, B: np.ndarray) -> int:
        if len(A) == 0 or len(B) == 0:
            return 0
        p, r = A[:, None, 0], (A[:, 1] - A[:, 0])[:, None]
        q, s = B[None, :, 0], (B[:, 1] - B[:, 0])[None]

        def cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
            return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]

        den = cross(r, s)
        with np.errstate(divide="ignore", invalid="ignore"):
            t, u = cross(q - p, s) / den, cross(q - p, r) / den
        e = 1e-9        # outlines that merely share an end point (at a mouth corner) do not cross
        return int(np.sum((np.abs(den) > 1e-12) & (t > e) & (t < 1 - e) & (u > e) & (u < 1 - e)))

    @staticmethod
    def distance(A: np.ndarray, B: np.ndarray) -> float:
        """The smallest distance between two outlines of (z, y) segments (inf if one is empty)."""
        if len(A) == 0 or len(B) == 0:
            return float(np.inf)
        return float(np.sqrt(min(_nearest_squared(A.reshape(-1, 2), B), _nearest_squared(B.reshape(-1, 2), A))))

    def section_clear(self, P: np.ndarray, x: float, clearance: float) -> bool:
        U, L = self.section(P, x)
        return self.crossings(U, L) == 0 and self.distance(U, L) >= clearance

    def clear(self, P: np.ndarray, clearance: float, n: int = CHECK_SECTIONS) -> bool:
        """True if the lips keep ``clearance`` mm apart and do not cross in every checked section."""
        half = self.half_width(P)
        return all(self.section_clear(P, x, clearance)
                   for x in np.linspace(-self.span, self.span, n) * half + 1e-4)

    def first_touch(self, P: np.ndarray, clearance: float, n: int = CHECK_SECTIONS) -> float | None:
        """The smallest |x| (mm) within the span where the lips of ``P`` are not ``clearance`` apart."""
        half = self.half_width(P)
        for x in np.linspace(0.0, self.span, (n + 1) // 2) * half + 1e-4:
            if not (self.section_clear(P, x, clearance) and self.section_clear(P, -x, clearance)):
                return float(x)
        return None

    def upper_floor(self, P: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Lowest y of the (posed) upper lip straight above or below each point's (x, z); nan where none."""
        T = P[self.triangles[self.upper_triangle]]
        floor = np.full(len(points), np.inf)
        if len(T) == 0 or len(points) == 0:
            return np.where(np.isfinite(floor), floor, np.nan)
        # Only triangles whose (x, z) bounding box holds the point can hold it: test those pairs.
        lo, hi = T[:, :, [0, 2]].min(axis=1), T[:, :, [0, 2]].max(axis=1)
        order = np.argsort(lo[:, 0])
        lo, hi, T = lo[order], hi[order], T[order]
        reach = float((hi[:, 0] - lo[:, 0]).max())
        first = np.searchsorted(lo[:, 0], points[:, 0] - reach, side="left")
        last = np.searchsorted(lo[:, 0], points[:, 0], side="right")
        counts = last - first
        pi = np.repeat(np.arange(len(points)), counts)
        ti = np.repeat(first - np.cumsum(np.r_[0, counts[:-1]]), counts) + np.arange(counts.sum())
        box = ((points[pi, 0] >= lo[ti, 0]) & (points[pi, 0] <= hi[ti, 0])
               & (points[pi, 2] >= lo[ti, 1]) & (points[pi, 2] <= hi[ti, 1]))
        pi, ti = pi[box], ti[box]
        Tt = T[ti]
        a, v0, v1 = Tt[:, 0][:, [0, 2]], (Tt[:, 1] - Tt[:, 0])[:, [0, 2]], (Tt[:, 2] - Tt[:, 0])[:, [0, 2]]
        den = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
        dq = points[pi][:, [0, 2]] - a
        with np.errstate(divide="ignore", invalid="ignore"):
            s = (dq[:, 0] * v1[:, 1] - dq[:, 1] * v1[:, 0]) / den
            t = (v0[:, 0] * dq[:, 1] - v0[:, 1] * dq[:, 0]) / den
        inside = (np.abs(den) > 1e-12) & (s >= 0) & (t >= 0) & (s + t <= 1)
        y = Tt[:, 0, 1] + s * (Tt[:, 1, 1] - Tt[:, 0, 1]) + t * (Tt[:, 2, 1] - Tt[:, 0, 1])
        np.minimum.at(floor, pi[inside], y[inside])
        return np.where(np.isfinite(floor), floor, np.nan)

    def overlap(self, P: np.ndarray, clearance: float) -> np.ndarray:
        """Per vertex: how far (mm) the lower-lip surface around it rises above ``upper floor − clearance``."""
        tri = self.check_triangles
        points = np.einsum("sk,tkc->tsc", self.SAMPLES, P[tri]).reshape(-1, 3)
        depth = points[:, 1] - (self.upper_floor(P, points) - clearance)
        depth = np.where(np.isfinite(depth), np.maximum(depth, 0.0), 0.0).reshape(len(tri), len(self.SAMPLES))
        owed = np.zeros(len(P))
        for k in range(3):
            np.maximum.at(owed, tri[:, k], (depth * (self.SAMPLES[:, k] > 0)).max(axis=1))
        return owed


def _nearest_squared(points: np.ndarray, segments: np.ndarray) -> float:
    """The smallest squared distance from any of ``points`` to any of ``segments``."""
    a = segments[:, 0]
    ab = segments[:, 1] - a
    apx = points[:, None, 0] - a[None, :, 0]
    apy = points[:, None, 1] - a[None, :, 1]
    den = np.maximum(ab[:, 0] * ab[:, 0] + ab[:, 1] * ab[:, 1], 1e-12)
    t = np.clip((apx * ab[:, 0] + apy * ab[:, 1]) / den, 0.0, 1.0)
    dx = apx - t * ab[:, 0]
    dy = apy - t * ab[:, 1]
    return float((dx * dx + dy * dy).min())


def _largest(predicate: Callable[[float], bool], lo: float, hi: float, steps: int = 25) -> float:
    """The largest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``lo``)."""
    if not predicate(lo):
        raise LipContactError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if predicate(mid) else (lo, mid)
    return lo


def _smallest(predicate: Callable[[float], bool], lo: float, hi: float, steps: int = 14) -> float:
    """The smallest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``hi``)."""
    if predicate(lo):
        return lo
    if not predicate(hi):
        raise LipContactError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if predicate(mid) else (mid, hi)
    return hi


class LipContactError(RuntimeError):
    """No field of the searched family keeps the lips apart (a face whose lips cross at rest)."""


def _lowering_needed(holds: Callable[[float], bool]) -> float:
    """How far a section's lower lip must come down (0 … 3 mm) for ``holds`` to hold."""
    return _smallest(lambda s: holds(-s), 0.0, 3.0)


def smooth_nodes(values: Sequence[float] | np.ndarray, passes: int = 1) -> np.ndarray:
    """[1 2 1]/4 smoothing of values on nodes x = 0, h, 2h, … (mirrored at 0, flat at the end)."""
    v = np.asarray(values, dtype=float)
    for _ in range(passes):
        p = np.r_[v[1], v, v[-1]]
        v = (p[:-2] + 2 * p[1:-1] + p[2:]) / 4
    return v


def fit_closure(contact: LipContact, region: np.ndarray, forward: float, clearance: float, nodes: int = 25,
                iterations: int = 4, steps: int = 25, local_rounds: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """The lower-lip closure field: ``region · (0, lift(|x|), forward)``, ``lift`` fitted section by
    section so that the lower lip just meets the upper lip (``clearance`` apart, never crossing).

    Between the nodes a section can need less lift than the nodes around it
    (where the lift changes fast, near lips that already touch at rest). The
    default head's derivation lowers the whole closure by one common shift for
    it; ``local_rounds`` > 0 first lowers only the two nodes around each such
    section, for up to that many rounds, so the rest of the mouth still closes.
    """
    rest = contact.rest
    xs = np.linspace(0, contact.span * contact.half_width(rest), nodes)
    x_abs = np.abs(rest[:, 0])
    if contact.touching_from is not None:
        # beyond the span the lips already touch: the closure fades out there, forward motion too
        fade = (x_abs - xs[-1]) / max(contact.touching_from + 2.0 - xs[-1], 1e-6)
        region = region * (1.0 - smoothstep(fade))
    up = region[:, None] * np.array([0.0, 1.0, 0.0])
    # Where the lips touch at rest (a narrower mouth opening), the lift fades to nothing there.
    ends = ([], []) if contact.touching_from is None else ([contact.touching_from], [0.0])

    def field(lift: np.ndarray, shift: float = 0.0) -> np.ndarray:
        T = np.zeros((len(rest), 3))
        T[:, 1] = np.interp(x_abs, np.r_[xs, ends[0]], np.r_[lift, ends[1]]) - shift
        T[:, 2] = forward
        return region[:, None] * T

    def clears(P: np.ndarray, x: float) -> Callable[[float], bool]:
        """Whether the section at ``x`` is clear with the lower lip lifted by v (cut once, then only lifted)."""
        segments, k, lift_at = contact.cut_with(P, x, up[:, 1])
        upper = contact.upper_triangle[k]
        U, L0, U_lift, L_lift = segments[upper], segments[~upper], lift_at[upper], lift_at[~upper]

        def holds(v: float) -> bool:
            Uv = U.copy()
            Uv[..., 1] += v * U_lift
            Lv = L0.copy()
            Lv[..., 1] += v * L_lift
            return contact.crossings(Uv, Lv) == 0 and contact.distance(Uv, Lv) >= clearance
        return holds

    lift = np.zeros(nodes)
    for _ in range(iterations):
        P = rest + field(lift)
        extra = [_largest(clears(P, x + 1e-4), -6.0, 6.0, steps) for x in xs]
        lift = lift + smooth_nodes(extra)
    spacing = xs[1] - xs[0] if nodes > 1 else 1.0
    for _ in range(local_rounds):
        P = rest + field(lift)
        section_xs = np.linspace(0.0, contact.span, (CHECK_SECTIONS + 1) // 2) * contact.half_width(P) + 1e-4
        lowered = np.zeros(nodes)
        for x in section_xs:
            need = max(_lowering_needed(clears(P, sign * x)) for sign in (1, -1))
            k = min(int(x / spacing), nodes - 1)
            lowered[k] = max(lowered[k], need)
            lowered[min(k + 1, nodes - 1)] = max(lowered[min(k + 1, nodes - 1)], need)
        if not lowered.any():
            break
        lift = lift - lowered
    # one common downward shift, if needed, so that the sections between the nodes clear as well
    # (the shift lowers the region as a lift of −s does: each checked section is cut once)
    P = rest + field(lift)
    half = contact.half_width(P)
    checks = [clears(P, x) for x in np.linspace(-contact.span, contact.span, CHECK_SECTIONS) * half + 1e-4]
    shift = _smallest(lambda s: all(holds(-s) for holds in checks), 0.0, 3.0)
    return field(lift, shift), lift


def follow_upper_lip(contact: LipContact, D: np.ndarray, closed: np.ndarray, depth: float = FOLLOW_DEPTH,
                     k: int = 3) -> np.ndarray:
    """``D`` with the lower lip near the mouth line moving like the upper lip it touches when closed."""
    rest, lower, upper = contact.rest, contact.lower_lip, contact.upper_contact
    dist, idx = cKDTree(closed[upper]).query(closed[lower], k=list(range(1, k + 1)))
    w = 1.0 / np.maximum(dist, 0.3)
    w /= w.sum(axis=1, keepdims=True)
    partner = np.einsum("nk,nkc->nc", w, D[upper][idx])
    b = 1.0 - smoothstep((contact.mouth_line(rest[lower, 0]) - rest[lower, 1]) / depth)
    out = D.copy()
    out[lower] = (1 - b[:, None]) * D[lower] + b[:, None] * partner
    return out


def keep_lips_apart(contact: LipContact, D: np.ndarray, clearance: float, companions: Sequence[np.ndarray],
                    adjacency: sparse.csr_matrix, lower_side: np.ndarray,
                    rounds: int = 20, sections: int = CHECK_SECTIONS) -> tuple[np.ndarray, float]:
    """``D`` with the lower lip lowered wherever ``D`` (alone, and added to each companion field)
    would push it into the upper lip; the lowering spreads over three rings of neighbours."""
    rest = contact.rest
    lowered = np.zeros(len(rest))
    for _ in range(rounds):
        out = D.copy()
        out[:, 1] -= lowered
        owed = np.zeros(len(rest))
        for extra in companions:
            owed = np.maximum(owed, contact.overlap(rest + out + extra, clearance))
        if owed.max() < 1e-3 and all(contact.clear(rest + out + extra, 0.0, sections) for extra in companions):
            return out, float(lowered.max())
        step = owed + 0.02 * (owed > 0)
        for _ in range(3):
            neighbours = adjacency.multiply(step[None, :]).max(axis=1).toarray().ravel()
            step = np.where(lower_side, np.maximum(step, 0.7 * neighbours), 0.0)
        lowered += step
    raise LipContactError("lip contact: could not keep the lips apart")


def vertex_adjacency(polygons: Sequence[np.ndarray], n: int) -> sparse.csr_matrix:
    edges = np.array([(poly[i], poly[(i + 1) % len(poly)]) for poly in polygons for i in range(len(poly))])
    A = sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
    A = ((A + A.T) > 0).astype(float)
    return A.tocsr()
