"""Measuring the face: where the lips are in sagittal sections, whether the lids enter the eyeballs.

Shared by the tests of the articulatory parameters, the action units and the expressions.
"""

from __future__ import annotations

import numpy as np


class Lips:
    """Upper and lower lip told apart on the rest mesh, and their outlines in sagittal sections.

    The rest mouth line runs, in each plane x = const, halfway between the lowest point of the
    clearly-upper lip and the highest point of the clearly-lower lip (jaw share < 0.35 / > 0.65);
    a triangle belongs to the upper lip if its rest centroid lies above that line.
    """

    def __init__(self, head):
        self.head = head
        P, lm = head.vertices, head.landmarks
        n = head.n_vertices
        jaw = head.regions["jaw_open"].dense(n)
        total = jaw + head.regions["head_tilt"].dense(n) + head.regions["neck_lean"].dense(n)
        share = np.divide(jaw, total, out=np.zeros(n), where=total > 0)
        skin = head.vertex_part == head.parts.index("skin")
        tri = head.triangles()
        tri = tri[np.all(skin[tri], axis=1)]
        centre = (P[lm["2.2"]] + P[lm["2.3"]]) / 2
        half = self.half_width(P)
        c = P[tri].mean(axis=1)
        zone = (np.abs(c[:, 0]) < 1.3 * half) & (np.abs(c[:, 1] - centre[1]) < 15) & (c[:, 2] > P[lm["8.3"], 2] - 8)
        self.tri, c = tri[zone], c[zone]
        tri_share = share[self.tri].mean(axis=1)
        xs, ys = [], []
        for x in np.arange(0.0, 0.9 * half, 1.0):
            seg, k = self._cut(P, x + 1e-4)
            up = seg[tri_share[k] < 0.35].reshape(-1, 2)
            lo = seg[tri_share[k] > 0.65].reshape(-1, 2)
            up, lo = up[up[:, 1] > centre[1] - 6], lo[lo[:, 1] < centre[1] + 6]
            xs.append(x)
            ys.append((up[:, 1].min() + lo[:, 1].max()) / 2)
        self.line = (np.array(xs), np.array(ys))
        self.upper = c[:, 1] > np.interp(np.abs(c[:, 0]), *self.line)

    def half_width(self, P):
        lm = self.head.landmarks
        return abs(P[lm["8.3"], 0] - P[lm["8.4"], 0]) / 2

    def _cut(self, P, x):
        segs, keep = [], []
        for k, t in enumerate(self.tri):
            p = P[t]
            d = p[:, 0] - x
            pts = [p[a] + d[a] / (d[a] - d[b]) * (p[b] - p[a]) for a, b in ((0, 1), (1, 2), (2, 0))
                   if (d[a] < 0) != (d[b] < 0)]
            if len(pts) == 2:
                segs.append(np.array(pts)[:, [2, 1]])
                keep.append(k)
        return np.array(segs).reshape(-1, 2, 2), np.array(keep, dtype=int)

    def sections(self, P, span=0.75, n=31):
        """(x, crossings, smallest distance) of the upper and lower lip outlines in planes x = const."""
        out = []
        for x in np.linspace(-span, span, n) * self.half_width(P) + 1e-4:
            seg, k = self._cut(P, x)
            U, L = seg[self.upper[k]], seg[~self.upper[k]]
            out.append((x, _crossings(U, L), _distance(U, L)))
        return out


def _crossings(A, B):
    count = 0
    for a0, a1 in A:
        for b0, b1 in B:
            r, s, q = a1 - a0, b1 - b0, b0 - a0
            den = r[0] * s[1] - r[1] * s[0]
            if abs(den) < 1e-12:
                continue
            t = (q[0] * s[1] - q[1] * s[0]) / den
            u = (q[0] * r[1] - q[1] * r[0]) / den
            count += 1e-9 < t < 1 - 1e-9 and 1e-9 < u < 1 - 1e-9
    return count


def _distance(A, B):
    def point_segments(p, S):
        a, ab = S[:, 0], S[:, 1] - S[:, 0]
        t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum((ab * ab).sum(1), 1e-12), 0, 1)
        return np.linalg.norm(p - (a + t[:, None] * ab), axis=1).min()
    return min(*(point_segments(p, B) for p in A.reshape(-1, 2)),
               *(point_segments(p, A) for p in B.reshape(-1, 2)))


def assert_lips_apart(lips, P, what):
    crossed = [round(x, 1) for x, c, _ in lips.sections(P) if c]
    assert not crossed, f"{what}: the lips pass through each other at x = {crossed} mm"


def eyeball_entry_mm(head, P):
    """How deep (mm) lid skin or lashes that are outside an eyeball at rest go into it in ``P``."""
    worst = 0.0
    for side in ("left", "right"):
        centre = head.parameters[f"eye_{side}_turn"].pivot
        radius = np.linalg.norm(head.vertices[head.part_vertices(f"eye_{side}")] - centre, axis=1).max()
        near = np.flatnonzero(np.isin(head.vertex_part, [head.parts.index("skin"),
                                                          head.parts.index(f"eyelashes_{side}")]))
        near = near[head.vertices[near, 2] > centre[2] + 3]
        before = np.linalg.norm(head.vertices[near] - centre, axis=1) - radius
        after = np.linalg.norm(P[near] - centre, axis=1) - radius
        entered = (before > 0) & (after < 0)
        worst = max(worst, float(-after[entered].min()) if entered.any() else 0.0)
    return worst
