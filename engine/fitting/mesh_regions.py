"""The mesh's edges and the region a fit may use: vertex indices, masks or part names, and the rings around the motion.

>>> mesh_edges([4, 0, 1, 2, 3]).tolist()
[[0, 1], [0, 3], [1, 2], [2, 3]]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
from scipy import sparse

from engine.fitting.errors import FittingError, suggest_name

if TYPE_CHECKING:
    from engine.model.model import Model


def mesh_edges(faces: npt.ArrayLike) -> np.ndarray:
    """The unique edges (E, 2), smaller index first, of a flat polygon cell array."""
    from engine.model.cells import cell_sizes, cell_starts

    cells = np.asarray(faces, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(cells)
    starts = cell_starts(sizes)
    pairs = []
    for k in np.unique(sizes):
        poly = cells[starts[sizes == k][:, None] + np.arange(1, k + 1)]
        pairs.append(np.stack([poly, np.roll(poly, -1, axis=1)], axis=-1).reshape(-1, 2))
    if not pairs:
        return np.zeros((0, 2), dtype=np.int64)
    e = np.sort(np.concatenate(pairs), axis=1)
    return np.unique(e[e[:, 0] != e[:, 1]], axis=0)


def vertices_near(seed: np.ndarray, allowed: np.ndarray, edges: npt.ArrayLike | None, n: int,
                  rings: int) -> np.ndarray:
    """``seed`` and the vertices of ``allowed`` within ``rings`` edges of it (walking inside ``allowed``)."""
    if rings == 0 or edges is None:
        return seed
    e = _checked_edges(edges, n)
    inside = np.zeros(n, dtype=bool)
    inside[allowed] = True
    e = e[inside[e].all(axis=1)]
    A = sparse.coo_matrix((np.ones(2 * len(e)), (e.ravel(), e[:, ::-1].ravel())), shape=(n, n)).tocsr()
    reached = np.zeros(n, dtype=bool)
    reached[seed] = True
    for _ in range(rings):
        reached |= (A @ reached.astype(float)) > 0
    return np.flatnonzero(reached)


def _checked_edges(edges: npt.ArrayLike, n: int) -> np.ndarray:
    e = np.asarray(edges)
    if e.ndim != 2 or e.shape[1] != 2 or (len(e) and (not np.issubdtype(e.dtype, np.integer)
                                                      or e.min() < 0 or e.max() >= n)):
        raise FittingError(f"edges must be an (E, 2) array of vertex indices in 0..{n - 1}")
    return e.astype(np.int64)


def edge_incidence(edges: npt.ArrayLike | None, allowed: np.ndarray, n: int) -> sparse.csr_matrix:
    """Signed edge–vertex incidence matrix over the region's vertices (edges with both ends inside)."""
    if edges is None:
        return sparse.csr_matrix((0, len(allowed)))
    e = _checked_edges(edges, n)
    local = np.full(n, -1)
    local[allowed] = np.arange(len(allowed))
    e = local[e]
    e = e[(e >= 0).all(axis=1)]
    m = len(e)
    rows = np.repeat(np.arange(m), 2)
    vals = np.tile([1.0, -1.0], m)
    return sparse.csr_matrix((vals, (rows, e.ravel())), shape=(m, len(allowed)))


def region_indices(region: npt.ArrayLike | None, n: int) -> np.ndarray:
    """Sorted vertex indices of a region given as indices or an (n,) boolean mask; all vertices for None."""
    if region is None:
        return np.arange(n)
    r = np.asarray(region)
    if r.dtype == bool:
        if r.shape != (n,):
            raise FittingError(f"a region mask needs one entry per vertex ({n}), not shape {r.shape}")
        r = np.flatnonzero(r)
    elif r.size and not np.issubdtype(r.dtype, np.integer):
        raise FittingError("a region is vertex indices, a boolean mask or part names")
    r = np.unique(r.astype(np.int64).reshape(-1))
    if len(r) == 0:
        raise FittingError("the region is empty")
    if r[0] < 0 or r[-1] >= n:
        raise FittingError(f"the region names a vertex outside 0..{n - 1}")
    return r


def resolve_region(model: Model, region: str | Sequence[str] | npt.ArrayLike | None) -> npt.ArrayLike | None:
    """Part name(s) to vertex indices; anything else is checked by :func:`region_indices`."""
    if isinstance(region, str):
        region = [region]
    if isinstance(region, (list, tuple)) and region and all(isinstance(r, str) for r in region):
        for part in region:
            if part not in model.parts:
                raise FittingError(f"unknown part '{part}'{suggest_name(part, model.parts)}")
        return np.concatenate([model.part_vertices(p) for p in region])
    return region
