"""Geometry helpers of the derivation: mesh adjacency and smoothing, the eyeball sphere, and the rig's fits.

A stage of ``derive_default_head.py``. Lengths are mm, angles degrees.
"""

from __future__ import annotations

import numpy as np
from scipy import sparse
from scipy.optimize import minimize_scalar

from engine.deform.transforms import apply, rotation_about_axis


def vertex_adjacency(polygons, n: int) -> sparse.csr_matrix:
    edges = np.array([(poly[i], poly[(i + 1) % len(poly)]) for poly in polygons for i in range(len(poly))])
    A = sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
    A = ((A + A.T) > 0).astype(float)
    return A.tocsr()


def smooth(values: np.ndarray, adjacency: sparse.csr_matrix, mask: np.ndarray, iterations: int,
           alpha: float = 0.5) -> np.ndarray:
    """Laplacian smoothing of a per-vertex scalar, only where ``mask`` is true."""
    deg = np.asarray(adjacency.sum(axis=1)).ravel()
    v = values.copy()
    for _ in range(iterations):
        mean = np.divide(adjacency @ v, deg, out=v.copy(), where=deg > 0)
        v = np.where(mask, (1 - alpha) * v + alpha * mean, v)
    return v


def eye_sphere(centre, radius, longitudes: int = 32):
    """A latitude-longitude sphere with its pole on +Z (the pupil) and rings on the iris edges.

    Returns vertices (mm) and polygons (lists of local indices): triangles at the poles, quads between.
    """
    # polar angles in degrees: pupil edge ~8.5°, iris edge ~25° (12 mm iris on a ~14 mm eyeball)
    rings = [4.0, 8.5, 13.0, 19.0, 25.0, 29.0, 36.0, 48.0, 62.0, 76.0, 90.0, 104.0, 118.0, 132.0, 146.0, 160.0]
    phi = np.linspace(0, 2 * np.pi, longitudes, endpoint=False)
    pts = [[0.0, 0.0, 1.0]]
    for theta in np.radians(rings):
        pts += [[np.sin(theta) * np.cos(a), np.sin(theta) * np.sin(a), np.cos(theta)] for a in phi]
    pts.append([0.0, 0.0, -1.0])
    pts = np.asarray(centre) + radius * np.array(pts)
    polys = [np.array([0, 1 + j, 1 + (j + 1) % longitudes]) for j in range(longitudes)]
    for r in range(len(rings) - 1):
        a, b = 1 + r * longitudes, 1 + (r + 1) * longitudes
        for j in range(longitudes):
            k = (j + 1) % longitudes
            polys.append(np.array([a + j, b + j, b + k, a + k]))
    last, south = 1 + (len(rings) - 1) * longitudes, len(pts) - 1
    polys.extend(np.array([last + j, south, last + (j + 1) % longitudes]) for j in range(longitudes))
    return pts, polys


def kabsch(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Rotation R (column convention) minimising |a R^T - b| for centred point sets."""
    U, _, Vt = np.linalg.svd(a.T @ b)
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    return Vt.T @ np.diag([1, 1, d]) @ U.T


def smoothstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3 - 2 * x)


def fit_angle(points, targets, axis, pivot) -> float:
    """Angle (degrees) of the rotation about axis/pivot that best maps points onto targets."""
    cost = lambda a: float(np.sum((apply(rotation_about_axis(axis, pivot, a), points) - targets) ** 2))  # noqa: E731
    return float(minimize_scalar(cost, bounds=(-90, 90), method="bounded", options={"xatol": 1e-6}).x)


def projection_weights(rest, displacement, axis, pivot, degrees, eps_mm=1.0):
    """Per-vertex weights w minimising |w·(P·T − P) − d| for the full rotation T, clipped to [0, 1].

    Regularised by ``eps_mm`` so vertices near the pivot (which barely move
    at full rotation) do not get arbitrary weights.
    """
    r = apply(rotation_about_axis(axis, pivot, degrees), rest) - rest
    w = np.einsum("ij,ij->i", displacement, r) / (np.einsum("ij,ij->i", r, r) + eps_mm ** 2)
    return np.clip(w, 0.0, 1.0)


def fit_circle(points: np.ndarray) -> np.ndarray:
    """Centre of the least-squares circle through 2-D points (Kåsa's algebraic fit)."""
    A = np.column_stack([2 * points, np.ones(len(points))])
    b = np.sum(points ** 2, axis=1)
    (cx, cy, _), *_ = np.linalg.lstsq(A, b, rcond=None)
    return np.array([cx, cy])


def fit_pivot_yz(rest, displacement) -> np.ndarray:
    """Centre (y, z) of the sagittal-plane rotation whose circles the displacements are tangent to."""
    A = displacement[:, 1:]
    b = np.einsum("ij,ij->i", displacement[:, 1:], rest[:, 1:])
    wts = np.linalg.norm(displacement, axis=1)
    c, *_ = np.linalg.lstsq(A * wts[:, None], b * wts, rcond=None)
    return c
