"""The meshes a renderer draws, one per part (and per texture image), and their smooth normals.

:class:`PartLayout` says where each part's mesh takes its points from (a
vertex used by two parts appears in both; a textured vertex appears once for
each texture coordinate its corners have, so seams stay sharp in the image
but not in the shading) and sums the triangles' normals around each vertex
of a part with one sparse product. The offscreen renderer
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
    normal). A part of a textured model is drawn as one mesh for its
    polygons without an image and one per image its polygons show
    (``image[k]``: the image index, or −1); a textured mesh has one point for
    each distinct (vertex, u, v) of its corners, with its (u, v) in
    ``uv[k]`` (``None`` for meshes without an image). The meshes are listed
    in ``parts`` (a part's name once per mesh). The meshes' points, stacked
    mesh after mesh, are ``positions[gather]``; mesh ``k`` is rows
    ``slices[k]`` of that stack. Smooth normals are the area-weighted sum of
    the fan triangles' normals around each vertex of a part (the same for
    every point of that vertex in that part, so a texture seam does not
    show in the shading), one sparse product for all meshes at once.
    """

    def __init__(self, model: Model) -> None:
        from scipy import sparse

        from engine.model.cells import cell_sizes, cell_starts, cells_to_triangles, index_mask

        faces = model.faces
        counts = cell_sizes(faces)
        starts = cell_starts(counts)
        face_part = model.vertex_part[faces[starts + 1]] if len(counts) else counts
        texture = model.texture
        face_image = texture.face_image if texture is not None else np.full(len(counts), -1, dtype=np.int64)
        corner_of_cell = np.full(len(faces), -1, dtype=np.int64)       # cell-array position → corner number
        corner_of_cell[index_mask(faces, counts)] = np.arange(int(counts.sum()))
        self.parts: list[str] = []
        self.image: list[int] = []
        self.uv: list[np.ndarray | None] = []
        self.slices: list[tuple[int, int]] = []
        self.cells: list[np.ndarray] = []
        gather: list[np.ndarray] = []
        group: list[np.ndarray] = []         # each point's (part, vertex) group: the points sharing a normal
        triangles: list[np.ndarray] = []
        offset = groups = 0
        for part_index, part in enumerate(model.parts):
            in_part = face_part == part_index
            if not in_part.any():
                continue
            part_vertices = np.unique(faces[index_mask(faces, counts)][np.repeat(in_part, counts)])
            group_of = np.full(model.n_vertices, -1, dtype=np.int64)
            group_of[part_vertices] = np.arange(groups, groups + len(part_vertices))
            for image in np.unique(face_image[in_part]).tolist():
                keep = in_part & (face_image == image)
                taken = np.repeat(keep, counts + 1)
                cells = faces[taken].copy()
                mask = index_mask(cells, counts[keep])
                if image < 0 or texture is None:
                    used = np.unique(cells[mask])
                    remap = np.full(model.n_vertices, -1, dtype=np.int64)
                    remap[used] = np.arange(len(used))
                    cells[mask] = remap[cells[mask]]
                    uv = None
                else:                          # one point per distinct (vertex, u, v)
                    corner_uv = texture.corner_uv[corner_of_cell[taken][mask]]
                    keys = np.column_stack([cells[mask].astype(float), corner_uv])
                    _, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
                    used = cells[mask][first]
                    uv = corner_uv[first]
                    cells[mask] = inverse.reshape(-1)
                self.parts.append(part)
                self.image.append(int(image))
                self.uv.append(uv)
                self.slices.append((offset, offset + len(used)))
                self.cells.append(cells)
                gather.append(used)
                group.append(group_of[used])
                triangles.append(cells_to_triangles(cells) + offset)
                offset += len(used)
            groups += len(part_vertices)
        self.gather = np.concatenate(gather) if gather else np.zeros(0, dtype=np.int64)
        point_group = np.concatenate(group) if group else np.zeros(0, dtype=np.int64)
        tris = np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)
        self.n_triangles = n_tris = tris.shape[0]
        self._corners = np.ascontiguousarray(tris.T).ravel()   # corner 0 of every triangle, then 1, then 2
        # point × triangle incidence: normals = incidence @ triangle normals, summed over a vertex's group
        group_incidence = sparse.csr_matrix(
            (np.ones(3 * n_tris), (point_group[self._corners], np.tile(np.arange(n_tris), 3))),
            shape=(groups, n_tris))
        point_of_group = sparse.csr_matrix((np.ones(offset), (np.arange(offset), point_group)),
                                           shape=(offset, groups))
        self.incidence = (point_of_group @ group_incidence).tocsr()
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
