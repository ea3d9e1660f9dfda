"""Carrying a rig over to a new shape of the same mesh: pivots, axes, directions and fields follow the surface.

A new identity moves every vertex of the head (``moved = rest + D``). The
rig (§2.2) was made for the rest shape; here each piece of it is moved with
the surface around it:

* a rotation's pivot and axis go through the *local affine map* of the
  surface near the pivot: the affine map that best carries the nearest rest
  vertices to their new places (weighted least squares, Gaussian in the
  distance; regularised towards a pure scaling where the neighbourhood is
  flat); a pivot inside a rigid part (an eyeball) moves with that part's own
  similarity transform exactly;
* a uniform translation's direction and a blendshape's per-vertex field go
  through the local linear map at the vertices they move, so a wider mouth
  opens wider and a longer nose wrinkles longer;
* influence regions, weights, landmarks, parts and the tree are kept.

The deformation of every vertex is therefore the default head's, moved and
stretched with the face: the same parameter values make the same expression
on a different person.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from engine.model import InfluenceRegion, Model
from engine.model.parameters import ROTATION

NEIGHBOURS = 32          # rest vertices in a local affine fit
REGULARISE = 1e-2        # towards a pure scaling, relative to the neighbourhood's spread


@dataclass(frozen=True)
class Similarity:
    """``x ↦ scale · R (x − centre) + new_centre``: how a rigid part (an eyeball) moved, and grew."""

    scale: float
    rotation: np.ndarray
    centre: np.ndarray
    new_centre: np.ndarray

    def point(self, x: np.ndarray) -> np.ndarray:
        return self.scale * (np.asarray(x) - self.centre) @ self.rotation.T + self.new_centre

    def direction(self, v: np.ndarray) -> np.ndarray:
        return np.asarray(v) @ self.rotation.T


def similarity(rest: np.ndarray, moved: np.ndarray) -> Similarity:
    """The similarity transform that best carries ``rest`` points to ``moved`` (Umeyama's least squares)."""
    a, b = rest.mean(axis=0), moved.mean(axis=0)
    A, B = rest - a, moved - b
    U, S, Vt = np.linalg.svd(B.T @ A)
    d = np.sign(np.linalg.det(U @ Vt)) or 1.0
    R = U @ np.diag([1.0, 1.0, d]) @ Vt
    scale = float((S * [1.0, 1.0, d]).sum() / max((A * A).sum(), 1e-12))
    return Similarity(scale, R, a, b)


class LocalMaps:
    """Local affine maps of a deformation ``rest → moved`` of a point cloud, at any point."""

    def __init__(self, rest: np.ndarray, moved: np.ndarray) -> None:
        self.rest, self.moved = rest, moved
        self.tree = cKDTree(rest)
        self.k = min(NEIGHBOURS, len(rest))

    def at(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(A, t) per point, shapes (m, 3, 3) and (m, 3): ``x ↦ A x + t`` near each point."""
        points = np.atleast_2d(points)
        dist, idx = self.tree.query(points, k=self.k)
        dist, idx = dist.reshape(len(points), -1), idx.reshape(len(points), -1)
        sigma = np.maximum(np.median(dist, axis=1, keepdims=True), 1e-6)
        w = np.exp(-((dist / sigma) ** 2))
        w /= w.sum(axis=1, keepdims=True)
        X, Y = self.rest[idx], self.moved[idx]
        xm = np.einsum("mk,mkd->md", w, X)
        ym = np.einsum("mk,mkd->md", w, Y)
        Xc, Yc = X - xm[:, None], Y - ym[:, None]
        XX = np.einsum("mk,mki,mkj->mij", w, Xc, Xc)
        YX = np.einsum("mk,mki,mkj->mij", w, Yc, Xc)
        lam = REGULARISE * np.trace(XX, axis1=1, axis2=2)[:, None, None] / 3 + 1e-12
        # Towards the neighbourhood's overall scaling where it is flat (the normal direction is unseen).
        scale = np.sqrt(np.einsum("mk,mkd,mkd->m", w, Yc, Yc) / np.maximum(np.trace(XX, axis1=1, axis2=2), 1e-12))
        eye = np.eye(3)[None]
        A = np.linalg.solve((XX + lam * eye).transpose(0, 2, 1),
                            (YX + lam * scale[:, None, None] * eye).transpose(0, 2, 1)).transpose(0, 2, 1)
        t = ym - np.einsum("mij,mj->mi", A, xm)
        return A, t


def carry_rig_over(model: Model, moved: np.ndarray, rigid: Mapping[str, Similarity] | None = None) -> Model:
    """A copy of ``model`` whose rest shape is ``moved``, its rig carried over (see the module text).

    ``rigid`` names parts that moved as a whole (the eyeballs) and how; a
    rotation pivot inside such a part follows it exactly.
    """
    rigid = dict(rigid or {})
    moved = np.asarray(moved, dtype=float)
    rest = model.vertices
    rigid_vertices = np.isin(model.vertex_part, [model.parts.index(p) for p in rigid if p in model.parts])
    maps = LocalMaps(rest[~rigid_vertices], moved[~rigid_vertices])
    out = model.copy()
    out.vertices = np.ascontiguousarray(moved)
    regions = dict(out.regions)
    for p in out.parameters:
        region = model.regions[p.name]
        if p.kind == ROTATION:
            inside = _rigid_part_at(model, rigid, p.pivot)
            if inside is not None:
                p.pivot = inside.point(p.pivot)
                p.axis = _unit(inside.direction(p.axis))
            else:
                A, t = maps.at(p.pivot)
                p.pivot = A[0] @ p.pivot + t[0]
                p.axis = _unit(A[0] @ p.axis)
        elif p.field and region.displacements is not None and len(region.indices):
            A, _ = maps.at(rest[region.indices])
            regions[p.name] = InfluenceRegion(region.indices.copy(), region.weights.copy(),
                                              np.einsum("mij,mj->mi", A, region.displacements))
        elif not p.field and len(region.indices) and np.any(p.direction):
            centre = np.average(rest[region.indices], axis=0, weights=np.maximum(region.weights, 1e-12))
            A, _ = maps.at(centre)
            p.direction = A[0] @ p.direction
    for name, region in regions.items():
        out.regions[name] = region
    out.changed()
    return out


def _rigid_part_at(model: Model, rigid: Mapping[str, Similarity], point: np.ndarray) -> Similarity | None:
    for part, transform in rigid.items():
        if part not in model.parts:
            continue
        pts = model.vertices[model.part_vertices(part)]
        radius = np.linalg.norm(pts - pts.mean(axis=0), axis=1).max()
        if np.linalg.norm(point - transform.centre) < 0.5 * radius:
            return transform
    return None


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)
