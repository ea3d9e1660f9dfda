"""The meshes a renderer draws, one per part, and their smooth normals.

:class:`PartLayout` says where each part's mesh takes its points from (a
vertex used by two parts appears in both) and sums the triangles' normals
around each point with one sparse product. The offscreen renderer
(:mod:`engine.outputs.render`) and the glTF export
(:mod:`engine.outputs.gltf_export`) draw and write the same meshes.
Lengths are mm.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from engine.model import Model


class PartLayout:
    """Where each part's mesh takes its points from, and how normals are summed.

    Every part is drawn as its own mesh over the model vertices its polygons
    use (a vertex used by two parts appears in both, with each part's own
    normal). The meshes' points, stacked part after part, are ``positions[gather]``;
    part ``k`` is rows ``slices[k]`` of that stack. Smooth normals are the
    area-weighted sum of the fan triangles' normals around each point, one
    sparse product for all parts at once.
    """

    def __init__(self, model: Model) -> None:
        from scipy import sparse

        from engine.model.cells import cell_sizes, cell_starts, cells_to_triangles, index_mask

        faces = model.faces
        counts = cell_sizes(faces)
        starts = cell_starts(counts)
        face_part = model.vertex_part[faces[starts + 1]] if len(counts) else counts
        self.parts: list[str] = []
        self.slices: list[tuple[int, int]] = []
        self.cells: list[np.ndarray] = []
        gather: list[np.ndarray] = []
        triangles: list[np.ndarray] = []
        offset = 0
        for part_index, part in enumerate(model.parts):
            keep = face_part == part_index
            if not keep.any():
                continue
            cells = faces[np.repeat(keep, counts + 1)].copy()
            mask = index_mask(cells, counts[keep])
            used = np.unique(cells[mask])
            remap = np.full(model.n_vertices, -1, dtype=np.int64)
            remap[used] = np.arange(len(used))
            cells[mask] = remap[cells[mask]]
            self.parts.append(part)
            self.slices.append((offset, offset + len(used)))
            self.cells.append(cells)
            gather.append(used)
            triangles.append(cells_to_triangles(cells) + offset)
            offset += len(used)
        self.gather = np.concatenate(gather) if gather else np.zeros(0, dtype=np.int64)
        tris = np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)
        self.n_triangles = n_tris = tris.shape[0]
        self._corners = np.ascontiguousarray(tris.T).ravel()   # corner 0 of every triangle, then 1, then 2
        # point × triangle incidence: normals = incidence @ triangle normals
        self.incidence = sparse.csr_matrix(
            (np.ones(3 * n_tris), (self._corners, np.tile(np.arange(n_tris), 3))), shape=(offset, n_tris))
        self._points = np.empty((offset, 3))
        self._cross = np.empty((3, n_tris))

    def used(self, k: int) -> np.ndarray:
        """Model vertex indices of part ``k``'s mesh points."""
        start, stop = self.slices[k]
        return self.gather[start:stop]

    def points_and_normals(self, positions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The stacked mesh points for ``positions`` and their unit normals (zero where undefined)."""
        points = np.take(positions, self.gather, axis=0, out=self._points)
        # one gather of every corner's coordinates, laid out (xyz, corner, triangle)
        corners = points.T[:, self._corners].reshape(3, 3, self.n_triangles)
        a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
        b -= a                                              # edge vectors, in place
        c -= a
        cross = self._cross                                 # (b − a) × (c − a), by component
        for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
            np.multiply(b[j], c[k], out=cross[i])
            cross[i] -= b[k] * c[j]
        normals = self.incidence @ cross.T
        length = np.sqrt(np.einsum("ij,ij->i", normals, normals))[:, None]
        return points, np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
