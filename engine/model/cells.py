"""Polygons stored as a flat cell array ``[n, i0, …, i(n-1), n, …]`` (VTK's and pyvista's layout).

Every walk over that layout lives here, so the model, the file readers and
writers, the renderer and the workbench read polygons the same way.

>>> faces = np.array([3, 0, 1, 2, 4, 0, 2, 3, 4])
>>> cell_sizes(faces)
array([3, 4])
>>> cells_to_triangles(faces)
array([[0, 1, 2],
       [0, 2, 3],
       [0, 3, 4]])
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from engine.errors import UserError


def cell_sizes(cells: npt.ArrayLike) -> np.ndarray:
    """Vertex count of every polygon; :class:`UserError` if the array is not a valid cell list."""
    cells = np.asarray(cells, dtype=np.int64).reshape(-1)
    if len(cells) == 0:
        return np.zeros(0, dtype=np.int64)
    k = int(cells[0])
    if k >= 3 and len(cells) % (k + 1) == 0 and np.all(cells[::k + 1] == k):   # one size throughout
        return np.full(len(cells) // (k + 1), k, dtype=np.int64)
    starts = _walk_starts(cells)
    sizes = cells[starts]
    bad = (sizes < 3) | (starts + sizes >= len(cells))
    if bad.any():
        raise UserError(f"face {int(np.argmax(bad))}: malformed polygon list (a polygon needs at least 3 vertices)")
    return sizes


def _walk_starts(cells: np.ndarray) -> np.ndarray:
    """Where the walk ``i → i + cells[i] + 1`` from 0 steps, up to the first count that cannot be one.

    The walk is found by pointer doubling, a few whole-array steps instead of one Python step per
    polygon: after round r, ``on`` holds the walk's first 2^r positions and ``jump`` leaps 2^r steps.
    Counts below 1 step as 1 and counts past the end stop at the end, so a malformed list still gives
    the walk up to (and including) its first bad count, which :func:`cell_sizes` then reports.
    """
    n = len(cells)
    jump = np.empty(n + 1, dtype=np.int64)
    jump[:n] = np.minimum(np.arange(n) + np.clip(cells, 1, n) + 1, n)
    jump[n] = n
    on = np.zeros(n + 1, dtype=bool)
    on[0] = True
    while True:
        reached = jump[on]
        if on[reached].all():
            break
        on[reached] = True
        jump = jump[jump]
    return np.flatnonzero(on[:n])


def cell_starts(sizes: np.ndarray) -> np.ndarray:
    """Position of each polygon's vertex count in the flat array."""
    sizes = np.asarray(sizes, dtype=np.int64)
    return np.concatenate([[0], np.cumsum(sizes[:-1] + 1)]).astype(np.int64) if len(sizes) else sizes


def index_mask(cells: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """True where the flat array holds a vertex index, False at the counts."""
    mask = np.ones(len(cells), dtype=bool)
    mask[cell_starts(sizes)] = False
    return mask


def split_cells(cells: npt.ArrayLike) -> list[np.ndarray]:
    """The polygons as a list of index arrays."""
    cells = np.asarray(cells, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(cells)
    return [cells[s + 1:s + 1 + k] for s, k in zip(cell_starts(sizes), sizes, strict=True)]


def check_cell_array(cells: npt.ArrayLike, n_vertices: int) -> None:
    """Raise :class:`UserError` unless ``cells`` is a valid cell array over ``n_vertices`` vertices."""
    cells = np.asarray(cells, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(cells)
    if len(sizes):
        idx = cells[index_mask(cells, sizes)]
        if idx.min() < 0 or idx.max() >= n_vertices:
            raise UserError(f"a face names a vertex outside 0..{n_vertices - 1}")


def cells_to_triangles(cells: npt.ArrayLike) -> np.ndarray:
    """Fan-triangulate every polygon into (T, 3) indices, in polygon order."""
    cells = np.asarray(cells, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(cells)
    starts = cell_starts(sizes)
    first = np.concatenate([[0], np.cumsum(sizes - 2)])            # first triangle of each polygon
    out = np.empty((int(first[-1]), 3), dtype=np.int64)
    for k in np.unique(sizes):
        which = np.flatnonzero(sizes == k)
        poly = cells[starts[which][:, None] + np.arange(1, k + 1)]   # (m, k)
        fan = np.stack([poly[:, [0, j, j + 1]] for j in range(1, k - 1)], axis=1)   # (m, k-2, 3)
        out[(first[which][:, None] + np.arange(k - 2)).ravel()] = fan.reshape(-1, 3)
    return out
