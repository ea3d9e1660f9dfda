"""Everything about a mesh that weight painting asks on every mouse move, built once.

A :class:`PaintContext` holds the rest mesh's edge graph (CSR), edge lengths,
vertex normals, a KD-tree for brush queries, part masks, the connected
components of the surface and (on first use) the X-mirror vertex map. Build
it when a model is opened or its mesh changes (vertices, faces or parts);
weight edits do not need a new one.

>>> from engine import load_model
>>> ctx = PaintContext(load_model())
>>> ctx.n_vertices, ctx.n_components > 1       # eyes, teeth and tongue are separate pieces
(5960, True)
>>> int(ctx.neighbours(0).size) > 0
True
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.cells import cell_sizes, cell_starts
from engine.model.model import Model

if TYPE_CHECKING:
    from engine.painting.mirror import MirrorMap

_SIDE_WORDS = [("left", "right"), ("Left", "Right"), ("LEFT", "RIGHT")]


def mirrored_part_name(name: str) -> str:
    """The part on the other side: ``eye_left`` ↔ ``eye_right``; unchanged when no side is named.

    >>> mirrored_part_name("eyelashes_left"), mirrored_part_name("skin")
    ('eyelashes_right', 'skin')
    """
    for a, b in _SIDE_WORDS:
        if a in name or b in name:
            return _swap_words(name, a, b)
    for a, b in ((".L", ".R"), ("_L", "_R"), ("_l", "_r")):
        if name.endswith(a):
            return name[:-2] + b
        if name.endswith(b):
            return name[:-2] + a
    return name


def _swap_words(name: str, a: str, b: str) -> str:
    swap = {a: b, b: a}
    return re.sub(f"{a}|{b}", lambda m: swap[m.group(0)], name)


def polygon_edges(faces: npt.ArrayLike, n_vertices: int) -> np.ndarray:
    """Unique undirected edges (E, 2), ``a < b``, of the polygons' boundaries (no fan diagonals)."""
    faces = np.asarray(faces, dtype=np.int64).reshape(-1)
    sizes = cell_sizes(faces)
    starts = cell_starts(sizes)
    chunks = []
    for k in np.unique(sizes):
        poly = faces[starts[sizes == k][:, None] + np.arange(1, k + 1)]       # (m, k)
        chunks.append(np.stack([poly, np.roll(poly, -1, axis=1)], axis=-1).reshape(-1, 2))
    if not chunks:
        return np.zeros((0, 2), dtype=np.int64)
    e = np.sort(np.concatenate(chunks), axis=1)
    e = e[e[:, 0] != e[:, 1]]
    key = np.unique(e[:, 0] * n_vertices + e[:, 1])
    return np.stack([key // n_vertices, key % n_vertices], axis=1)


def vertex_normals(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Area-weighted unit normals (N, 3); zero for vertices on no triangle."""
    v = vertices
    fn = np.cross(v[triangles[:, 1]] - v[triangles[:, 0]], v[triangles[:, 2]] - v[triangles[:, 0]])
    n = np.zeros_like(v)
    for c in range(3):
        np.add.at(n, triangles[:, c], fn)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    np.divide(n, length, out=n, where=length > 0)
    return n


class PaintContext:
    """The rest mesh's topology and search structures, for painting one model.

    Parameters
    ----------
    model : Model
        Only its rest vertices (mm), faces and parts are read; they are
        referenced, not copied, so build a new context after editing them.
    mirror_tolerance : float
        Distance (mm) within which a mirrored vertex counts as an exact mirror
        match (see :meth:`mirror`).

    Attributes
    ----------
    vertices : (N, 3) float array, mm
    adjacency : (N, N) CSR matrix
        Symmetric edge graph of the polygons' boundaries; ``data`` holds edge
        lengths in mm (the graph for geodesic distances).
    indptr, indices : int arrays
        ``adjacency``'s CSR arrays (neighbours of ``i`` are
        ``indices[indptr[i]:indptr[i + 1]]``).
    degree : (N,) int array
    normals : (N, 3) float array
        Area-weighted unit vertex normals (outward for the default head).
    tree : scipy.spatial.cKDTree over ``vertices``
    components : (N,) int array
        Label of each vertex's connected piece of surface.
    vertex_part : (N,) int array; parts : list of str
    part_mirror : (P,) int array
        Index of the mirrored part (``eye_left`` → ``eye_right``).
    edge_length : float
        Median edge length, mm (a scale for tolerances).
    """

    def __init__(self, model: Model, *, mirror_tolerance: float = 1e-3):
        from scipy import sparse  # here, not at import: the workbench loads this module at start

        self.vertices = model.vertices
        self.n_vertices = n = len(model.vertices)
        self.parts = list(model.parts)
        self.vertex_part = model.vertex_part
        self.part_mirror = np.array([self.parts.index(mirrored_part_name(p)) if mirrored_part_name(p) in self.parts
                                     else k for k, p in enumerate(self.parts)], dtype=np.int64)
        self.faces = model.faces
        self.triangles = model.triangles()
        self.edges = polygon_edges(model.faces, n)
        a, b = self.edges[:, 0], self.edges[:, 1]
        lengths = np.linalg.norm(self.vertices[a] - self.vertices[b], axis=1)
        self.edge_length = float(np.median(lengths)) if len(lengths) else 1.0
        # zero-length edges would vanish from a sparse matrix; keep them reachable
        lengths = np.maximum(lengths, 1e-9)
        self.adjacency = sparse.csr_matrix((np.concatenate([lengths, lengths]),
                                            (np.concatenate([a, b]), np.concatenate([b, a]))), shape=(n, n))
        self.adjacency.sort_indices()
        self.indptr = self.adjacency.indptr.astype(np.int64)
        self.indices = self.adjacency.indices.astype(np.int64)
        self.degree = np.diff(self.indptr)
        # row-stochastic neighbour average; a vertex without neighbours averages to itself
        rows = np.repeat(np.arange(n), self.degree)
        vals = 1.0 / self.degree[rows]
        lonely = np.flatnonzero(self.degree == 0)
        self.neighbour_mean = sparse.csr_matrix(
            (np.concatenate([vals, np.ones(len(lonely))]),
             (np.concatenate([rows, lonely]), np.concatenate([self.indices, lonely]))), shape=(n, n))
        self.normals = vertex_normals(self.vertices, self.triangles)
        from scipy.spatial import cKDTree  # imported when needed: it costs 0.3 s at launch

        self.tree = cKDTree(self.vertices)
        from scipy.sparse import csgraph  # imported when needed: 0.2 s at launch
        self.n_components, self.components = csgraph.connected_components(self.adjacency, directed=False)
        self.mirror_tolerance = float(mirror_tolerance)
        self._mirror: MirrorMap | None = None
        self._paintable: dict = {}        # (part, view) → mask, filled by brush.paintable_mask

    # -- queries -----------------------------------------------------------------
    def neighbours(self, i: int) -> np.ndarray:
        """Vertex indices sharing a polygon edge with vertex ``i``."""
        return self.indices[self.indptr[i]:self.indptr[i + 1]]

    def part_index(self, part: str) -> int:
        if part not in self.parts:
            raise UserError(f"unknown part '{part}' (parts: {', '.join(self.parts)})")
        return self.parts.index(part)

    def part_mask(self, part: str | None) -> np.ndarray:
        """(N,) bool: the vertices of one part (all vertices for ``None``)."""
        if part is None:
            return np.ones(self.n_vertices, dtype=bool)
        return self.vertex_part == self.part_index(part)

    @property
    def mirror(self) -> MirrorMap:
        """The X-mirror :class:`~engine.painting.mirror.MirrorMap` (computed on first use, then cached)."""
        if self._mirror is None:
            from engine.painting.mirror import mirror_map
            self._mirror = mirror_map(self, tolerance=self.mirror_tolerance)
        return self._mirror

    @mirror.setter
    def mirror(self, value: MirrorMap) -> None:
        self._mirror = value

    def nearest_vertex(self, point: npt.ArrayLike, candidates: np.ndarray | None = None) -> int:
        """The vertex nearest to ``point`` (mm), among ``candidates`` (indices) if given; −1 if none."""
        p = _point(point)
        if candidates is None:
            return int(self.tree.query(p)[1])
        if len(candidates) == 0:
            return -1
        d = self.vertices[candidates] - p
        return int(candidates[np.argmin(np.einsum("ij,ij->i", d, d))])

    def connected_within(self, seed: int, inside: np.ndarray) -> np.ndarray:
        """Vertices reachable from ``seed`` over mesh edges without leaving ``inside``.

        ``inside`` is sorted vertex indices (the brush's ball, say) that
        include ``seed``; the result is the sorted subset reachable from it.
        A breadth-first search on the sub-graph the vertices induce, so the
        cost follows their number, not the mesh size.
        """
        inside = np.asarray(inside, dtype=np.int64)
        pos = int(np.searchsorted(inside, seed))
        if pos >= len(inside) or inside[pos] != seed:
            return np.zeros(0, dtype=np.int64)
        sub = self.adjacency[inside][:, inside]
        from scipy.sparse import csgraph  # imported when needed: 0.2 s at launch
        order = csgraph.breadth_first_order(sub, pos, directed=False, return_predecessors=False)
        return inside[np.sort(order)]


def _point(point: npt.ArrayLike | None) -> np.ndarray:
    """``point`` as a (3,) float array (mm); a :class:`~engine.errors.UserError` for anything else (``None`` too)."""
    try:
        p = np.asarray(point, dtype=float).reshape(3)
    except (TypeError, ValueError):
        raise UserError("a point must be three numbers (x, y, z in mm)") from None
    if not np.all(np.isfinite(p)):
        raise UserError("a point must have finite coordinates")
    return p
