"""Points held by the skin: where on a skin triangle each hair vertex hangs, and how it moves with the rig (§2.2).

Every hair vertex is written as an *anchor* — a point of a skin triangle,
three vertex indices and barycentric weights — plus an *offset* in that
triangle's own frame (its first edge, its normal, and their cross product).
On the head the hair was grown on, anchor + offset is the vertex itself; on
another head of the same mesh (an identity) the same anchors and offsets put
the hair on that person's skin (:func:`place`). In the rig every hair vertex
takes its anchor's weight in every parameter, blended barycentrically from
the triangle's three vertices, and the anchor's displacement in every field
(:func:`rig_for_anchors`), so a brow hair moves with AU1, AU2 and AU4 and the
scalp with the head exactly as the skin under it does.

>>> import numpy as np
>>> tri = np.array([[0, 1, 2]]); V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
>>> surface = SkinSurface(V, tri)
>>> anchors = surface.closest(np.array([[0.25, 0.25, 2.0]]))
>>> anchors.bary.round(2).tolist(), place(V, anchors).round(6).tolist()
([[0.5, 0.25, 0.25]], [[0.25, 0.25, 2.0]])
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from engine.model import InfluenceRegion, Model

CANDIDATES = 12          # nearest triangles (by centroid) searched for each point's closest point


@dataclass
class Anchors:
    """Per hair vertex: the skin triangle's vertex indices ``corners`` (m, 3), ``bary`` (m, 3), ``offset`` (m, 3)."""

    corners: np.ndarray
    bary: np.ndarray
    offset: np.ndarray

    def __len__(self) -> int:
        return len(self.corners)

    @staticmethod
    def concatenate(items: list[Anchors]) -> Anchors:
        if not items:
            return Anchors(np.zeros((0, 3), np.int64), np.zeros((0, 3)), np.zeros((0, 3)))
        return Anchors(np.concatenate([a.corners for a in items]), np.concatenate([a.bary for a in items]),
                       np.concatenate([a.offset for a in items]))


def frames(vertices: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """(m, 3, 3): rows e1 (first edge), e2, n (the triangle's unit normal) of each triangle ``corners``."""
    a, b, c = (vertices[corners[:, k]] for k in range(3))
    e1 = b - a
    n = np.cross(e1, c - a)
    e1 /= np.maximum(np.linalg.norm(e1, axis=1, keepdims=True), 1e-12)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)
    return np.stack([e1, np.cross(n, e1), n], axis=1)


def place(vertices: np.ndarray, anchors: Anchors) -> np.ndarray:
    """(m, 3): the hair vertices on the skin ``vertices`` (the head's rest shape, or any identity's)."""
    base = np.einsum("mk,mkd->md", anchors.bary, vertices[anchors.corners])
    return base + np.einsum("mi,mid->md", anchors.offset, frames(vertices, anchors.corners))


class SkinSurface:
    """Closest points on a set of triangles, and their smooth normals."""

    def __init__(self, vertices: np.ndarray, triangles: np.ndarray) -> None:
        self.vertices = np.asarray(vertices, float)
        self.triangles = np.asarray(triangles, np.int64).reshape(-1, 3)
        self.tree = cKDTree(self.vertices[self.triangles].mean(axis=1))
        face_n = np.cross(self.vertices[self.triangles[:, 1]] - self.vertices[self.triangles[:, 0]],
                          self.vertices[self.triangles[:, 2]] - self.vertices[self.triangles[:, 0]])
        vn = np.zeros_like(self.vertices)
        for k in range(3):
            np.add.at(vn, self.triangles[:, k], face_n)
        self.vertex_normals = vn / np.maximum(np.linalg.norm(vn, axis=1, keepdims=True), 1e-12)

    def closest(self, points: np.ndarray) -> Anchors:
        """Each point's closest point on the triangles, as anchors with the point's offset from it."""
        points = np.atleast_2d(np.asarray(points, float))
        k = min(CANDIDATES, len(self.triangles))
        _, cand = self.tree.query(points, k=k)
        cand = cand.reshape(len(points), k)
        tri = self.triangles[cand]                                   # (m, k, 3)
        q, bary = _closest_on_triangles(points[:, None, :], *(self.vertices[tri[..., i]] for i in range(3)))
        best = np.argmin(np.linalg.norm(q - points[:, None, :], axis=2), axis=1)
        rows = np.arange(len(points))
        corners, bary = tri[rows, best], bary[rows, best]
        base = np.einsum("mk,mkd->md", bary, self.vertices[corners])
        offset = np.einsum("mid,md->mi", frames(self.vertices, corners), points - base)
        return Anchors(corners, bary, offset)

    def normals_at(self, anchors: Anchors) -> np.ndarray:
        """Smooth (vertex-blended) unit normals at the anchors' skin points."""
        n = np.einsum("mk,mkd->md", anchors.bary, self.vertex_normals[anchors.corners])
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)

    def drape(self, points: np.ndarray, height: np.ndarray | float) -> tuple[np.ndarray, Anchors]:
        """``points`` moved to ``height`` mm above their closest skin points (along the smooth normal)."""
        anchors = self.closest(points)
        on_skin = np.einsum("mk,mkd->md", anchors.bary, self.vertices[anchors.corners])
        moved = on_skin + np.asarray(height, float).reshape(-1, 1) * self.normals_at(anchors)
        return moved, anchors


def _closest_on_triangles(p: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray
                          ) -> tuple[np.ndarray, np.ndarray]:
    """Closest points of ``p`` on triangles ``abc`` (broadcast) and their barycentric weights (Ericson, 5.1.5)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
    bp = p - b
    d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
    cp = p - c
    d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    denom = np.where(np.abs(va + vb + vc) > 1e-18, va + vb + vc, 1e-18)
    v, w = vb / denom, vc / denom                                   # inside the face
    # edges and corners, the later cases overriding where they hold
    with np.errstate(divide="ignore", invalid="ignore"):
        t_ab = np.clip(d1 / np.where(d1 - d3 != 0, d1 - d3, 1e-18), 0, 1)
        t_ac = np.clip(d2 / np.where(d2 - d6 != 0, d2 - d6, 1e-18), 0, 1)
        t_bc = np.clip((d4 - d3) / np.where((d4 - d3) + (d5 - d6) != 0, (d4 - d3) + (d5 - d6), 1e-18), 0, 1)
    on_ab = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
    on_ac = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
    on_bc = (va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0)
    v = np.where(on_ab, t_ab, v)
    w = np.where(on_ab, 0.0, w)
    v = np.where(on_ac, 0.0, v)
    w = np.where(on_ac, t_ac, w)
    v = np.where(on_bc, 1 - t_bc, v)
    w = np.where(on_bc, t_bc, w)
    at_a, at_b, at_c = (d1 <= 0) & (d2 <= 0), (d3 >= 0) & (d4 <= d3), (d6 >= 0) & (d5 <= d6)
    v = np.where(at_a, 0.0, np.where(at_b, 1.0, np.where(at_c, 0.0, v)))
    w = np.where(at_a, 0.0, np.where(at_b, 0.0, np.where(at_c, 1.0, w)))
    bary = np.stack([1 - v - w, v, w], axis=-1)
    return a + v[..., None] * ab + w[..., None] * ac, bary


def rig_for_anchors(model: Model, anchors: Anchors, first: int) -> dict[str, InfluenceRegion]:
    """Every parameter's region extended to the hair vertices ``first …`` (one per anchor).

    A hair vertex's weight is its anchor's, blended from the triangle's three
    vertices; in a displacement field its displacement is chosen so that
    weight × displacement is the blend of the vertices' own products, so the
    hair moves as the skin point under it does.
    """
    n = model.n_vertices
    hair = np.arange(first, first + len(anchors))
    out: dict[str, InfluenceRegion] = {}
    for p in model.parameters:
        region = model.regions[p.name]
        w = region.dense(n)
        wa = w[anchors.corners]                                       # (m, 3)
        weight = np.einsum("mk,mk->m", anchors.bary, wa)
        add = weight > 1e-6
        idx = np.concatenate([region.indices, hair[add]])
        weights = np.concatenate([region.weights, np.clip(weight[add], 0.0, 1.0)])
        disp = None
        if region.displacements is not None:
            D = np.zeros((n, 3))
            D[region.indices] = region.displacements
            product = np.einsum("mk,mkd->md", anchors.bary * wa, D[anchors.corners])
            disp = np.concatenate([region.displacements, product[add] / weight[add, None]])
        out[p.name] = InfluenceRegion(idx, weights, disp)
    return out
