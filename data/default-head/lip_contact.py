"""The two lips of the rest mesh, and whether a pose makes them pass through each other.

A stage of ``derive_default_head.py`` (and of ``articulation_pictures.py``,
which draws the sections :class:`LipContact` checks). Lengths are mm.
"""

from __future__ import annotations

import numpy as np

SECTION_SPAN = 0.75         # lip sections are checked across this fraction of the mouth's half-width
CHECK_SECTIONS = 61


class LipContact:
    """The two lips of the rest mesh, and whether a pose makes them pass through each other.

    The lips are told apart by the rest *mouth line*: in each sagittal section (plane x =
    const) it runs halfway between the lowest point of the upper lip and the highest point of
    the lower lip, found where their jaw share is unambiguous (upper < 0.35, lower > 0.65).
    A pose is checked in sagittal sections across the middle ``SECTION_SPAN`` of the mouth:
    the outlines of the upper and lower lip must not cross, and stay ``clearance`` apart.
    """

    def __init__(self, rest, triangles, skin, jaw_share, landmarks):
        self.rest = rest
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

    def mouth_line(self, x):
        return np.interp(np.abs(x), self.line_x, self.line_y)

    def half_width(self, P) -> float:
        return float(abs(P[self.landmarks["8.3"], 0] - P[self.landmarks["8.4"], 0]) / 2)

    def _cut(self, P, x):
        """Segments (k, 2, 2) in (z, y) where the plane X = x cuts the mouth triangles, and their triangles."""
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

    def section(self, P, x):
        """Upper-lip and lower-lip outlines in the sagittal plane X = x, as (z, y) segments."""
        segments, k = self._cut(P, x)
        up = self.upper_triangle[k]
        return segments[up], segments[~up]

    @staticmethod
    def crossings(A, B) -> int:
        if len(A) == 0 or len(B) == 0:
            return 0
        p, r = A[:, None, 0], (A[:, 1] - A[:, 0])[:, None]
        q, s = B[None, :, 0], (B[:, 1] - B[:, 0])[None]
        cross = lambda u, v: u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]  # noqa: E731
        den = cross(r, s)
        with np.errstate(divide="ignore", invalid="ignore"):
            t, u = cross(q - p, s) / den, cross(q - p, r) / den
        e = 1e-9        # outlines that merely share an end point (at a mouth corner) do not cross
        return int(np.sum((np.abs(den) > 1e-12) & (t > e) & (t < 1 - e) & (u > e) & (u < 1 - e)))

    @staticmethod
    def distance(A, B) -> float:
        if len(A) == 0 or len(B) == 0:
            return np.inf

        def point_to_segments(p, S):
            a, ab = S[:, 0], S[:, 1] - S[:, 0]
            t = np.einsum("pij,pij->pi", p[:, None] - a[None], ab[None]) / np.maximum((ab * ab).sum(-1), 1e-12)
            t = np.clip(t, 0, 1)
            return np.linalg.norm(p[:, None] - (a[None] + t[..., None] * ab[None]), axis=-1).min()
        return float(min(point_to_segments(A.reshape(-1, 2), B), point_to_segments(B.reshape(-1, 2), A)))

    def section_clear(self, P, x, clearance) -> bool:
        U, L = self.section(P, x)
        return self.crossings(U, L) == 0 and self.distance(U, L) >= clearance

    def clear(self, P, clearance, n: int = CHECK_SECTIONS) -> bool:
        """True if the lips keep ``clearance`` mm apart and do not cross in every checked section."""
        half = self.half_width(P)
        return all(self.section_clear(P, x, clearance)
                   for x in np.linspace(-SECTION_SPAN, SECTION_SPAN, n) * half + 1e-4)

    def upper_floor(self, P, points):
        """Lowest y of the (posed) upper lip straight above or below each point's (x, z); nan where none."""
        T = P[self.triangles[self.upper_triangle]]
        a, v0, v1 = T[:, 0][:, [0, 2]], (T[:, 1] - T[:, 0])[:, [0, 2]], (T[:, 2] - T[:, 0])[:, [0, 2]]
        den = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
        dq = points[:, None, [0, 2]] - a[None]
        with np.errstate(divide="ignore", invalid="ignore"):
            s = (dq[..., 0] * v1[:, 1] - dq[..., 1] * v1[:, 0]) / den
            t = (v0[:, 0] * dq[..., 1] - v0[:, 1] * dq[..., 0]) / den
        inside = (np.abs(den) > 1e-12) & (s >= 0) & (t >= 0) & (s + t <= 1)
        y = np.where(inside, T[:, 0, 1] + s * (T[:, 1, 1] - T[:, 0, 1]) + t * (T[:, 2, 1] - T[:, 0, 1]), np.inf)
        floor = y.min(axis=1)
        return np.where(np.isfinite(floor), floor, np.nan)

    SAMPLES = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [.5, .5, 0], [0, .5, .5], [.5, 0, .5],
                        [1 / 3, 1 / 3, 1 / 3], [2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])

    def overlap(self, P, clearance) -> np.ndarray:
        """Per vertex: how far (mm) the lower-lip surface around it rises above ``upper floor − clearance``."""
        tri = self.check_triangles
        points = np.einsum("sk,tkc->tsc", self.SAMPLES, P[tri]).reshape(-1, 3)
        depth = points[:, 1] - (self.upper_floor(P, points) - clearance)
        depth = np.where(np.isfinite(depth), np.maximum(depth, 0.0), 0.0).reshape(len(tri), len(self.SAMPLES))
        owed = np.zeros(len(P))
        for k in range(3):
            np.maximum.at(owed, tri[:, k], (depth * (self.SAMPLES[:, k] > 0)).max(axis=1))
        return owed
