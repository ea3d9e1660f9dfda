"""Distances and interpolation along the skin: the region and the displacement fields of ``mocap apply`` (§3.1.2).

Upper and lower lip are a few millimetres apart through the mouth but far
apart along the skin, so the region around the markers and the interpolation
of their displacements use *surface* (geodesic) distances: shortest paths
along the mesh edges (Dijkstra), slightly longer than true surface distances
on a coarse mesh. :func:`surface_graph` is the mesh as a weighted graph,
:func:`articulation_region` the influence region, :func:`surface_coordinates`
coordinates whose straight-line distances approximate surface distances and
:func:`surface_rbf` the thin-plate interpolation in them. Lengths are mm.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.mocap.errors import MocapError

if TYPE_CHECKING:
    from scipy import sparse

    from engine.model.model import Model

def surface_graph(model: Model, part: str = "skin") -> sparse.csr_matrix:
    """The edges of ``part``'s polygons as a sparse (N × N) graph weighted by length, mm."""
    from scipy import sparse  # here, not at import: scipy.sparse costs the workbench 0.15 s at start

    tris = model.triangles()
    on = model.vertex_part == model.parts.index(part)
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = edges[on[edges[:, 0]] & on[edges[:, 1]]]
    length = np.linalg.norm(model.vertices[edges[:, 0]] - model.vertices[edges[:, 1]], axis=1)
    n = model.n_vertices
    graph = sparse.coo_matrix((length, (edges[:, 0], edges[:, 1])), shape=(n, n)).tocsr()
    return graph.maximum(graph.T).tocsr()


def articulation_region(graph: sparse.csr_matrix, vertices: npt.ArrayLike, inner_mm: float, outer_mm: float,
                        neighbour_ratio: float = 1.3) -> tuple[np.ndarray, np.ndarray]:
    """The influence region: vertex indices and weights (1 near the markers, 0 beyond ``outer_mm``).

    The markers are joined by shortest paths along ``graph`` (each to every
    marker no farther than ``neighbour_ratio`` × its nearest one); weights
    fall with the surface distance ``d`` from those paths: 1 for ``d ≤
    inner_mm``, smoothstep down to 0 at ``outer_mm``.
    """
    from scipy.sparse.csgraph import dijkstra  # here, not at import: it pulls in scipy.linalg (0.1–0.2 s)

    vertices = np.asarray(vertices, dtype=np.int64)
    dist, pred = dijkstra(graph, directed=False, indices=vertices, return_predecessors=True)
    between = dist[:, vertices]
    if not np.all(np.isfinite(between)):
        i, j = np.argwhere(~np.isfinite(between))[0]
        raise MocapError(f"marker vertices {vertices[i]} and {vertices[j]} are not connected on the surface")
    nearest = np.where(np.eye(len(vertices), dtype=bool), np.inf, between).min(axis=1)
    skeleton = set(vertices.tolist())
    for i in range(len(vertices)):
        for j in range(len(vertices)):
            if i != j and between[i, j] <= neighbour_ratio * nearest[i]:
                v = vertices[j]
                while v != vertices[i] and v >= 0:
                    skeleton.add(int(v))
                    v = pred[i, v]
    to_skeleton = dijkstra(graph, directed=False, indices=sorted(skeleton), min_only=True, limit=outer_mm)
    t = np.clip((to_skeleton - inner_mm) / (outer_mm - inner_mm), 0.0, 1.0)
    weight = 1.0 - t * t * (3.0 - 2.0 * t)                                  # smoothstep 1 → 0
    weight[~np.isfinite(to_skeleton)] = 0.0
    indices = np.flatnonzero(weight > 0)
    return indices, weight[indices]


def surface_coordinates(graph: sparse.csr_matrix, region: npt.ArrayLike, dims: int = 3) -> np.ndarray:
    """(len(region), dims) coordinates whose straight-line distances approximate surface distances.

    Classical multidimensional scaling of the shortest-path distances
    between the region's vertices (Isomap): upper and lower lip, 2–3 mm apart
    through the mouth but some 60 mm apart along the skin, come out far
    apart. Paths stay inside the region where it is connected.
    """
    from scipy.sparse.csgraph import dijkstra

    region = np.asarray(region, dtype=np.int64)
    inside = graph[region][:, region]
    dist = dijkstra(inside, directed=False)
    if not np.all(np.isfinite(dist)):
        dist = dijkstra(graph, directed=False, indices=region)[:, region]
    if not np.all(np.isfinite(dist)):
        raise MocapError("part of the region is not connected to the rest along the surface")
    sq = dist ** 2
    centred = sq - sq.mean(axis=0) - sq.mean(axis=1)[:, None] + sq.mean()
    from scipy.linalg import eigh

    n = len(region)
    dims = min(dims, n)
    eigenvalues, eigenvectors = eigh(-0.5 * centred, subset_by_index=[n - dims, n - 1])   # the largest only
    top = np.argsort(eigenvalues)[::-1]
    return eigenvectors[:, top] * np.sqrt(np.maximum(eigenvalues[top], 0.0))


def surface_rbf(graph: sparse.csr_matrix, vertices: np.ndarray, region: np.ndarray,
                displacements: np.ndarray) -> np.ndarray:
    """(C, len(region), 3) thin-plate RBF of marker displacements in surface coordinates, mm.

    ``vertices`` (K,) are the marker vertices (all inside ``region``) and
    ``displacements`` (C, K, 3) their displacement for each of C components,
    mm; the result is every region vertex's displacement, exact at the markers.
    """
    from scipy.interpolate import RBFInterpolator

    coords = surface_coordinates(graph, region)
    at = np.searchsorted(region, vertices)
    c = displacements.shape[0]
    values = displacements.transpose(1, 0, 2).reshape(len(vertices), 3 * c)
    try:
        fit = RBFInterpolator(coords[at], values, kernel="thin_plate_spline", degree=1)
    except (ValueError, np.linalg.LinAlgError) as exc:
        raise MocapError(f"cannot interpolate the marker displacements over the surface ({exc})") from None
    return fit(coords).reshape(len(region), c, 3).transpose(1, 0, 2)
