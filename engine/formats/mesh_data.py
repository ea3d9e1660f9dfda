"""What a mesh reader hands back: polygons, parts, and the texture a photograph can be fitted to.

Every reader of :mod:`engine.formats.mesh_io` (OBJ, PLY, glTF, and VTK's
readers in a child process) returns a :class:`RawMesh` in the file's own
units and axes; :func:`engine.formats.mesh_io.read_mesh` turns it into an
:class:`ImportedMesh` in millimetres with +Y up, in the vertex order the
model will have.

Texture coordinates are kept **per polygon corner** (one (u, v) pair for each
vertex index in the flat cell array ``faces``, in the same order), because an
OBJ file gives a vertex different coordinates on either side of a texture
seam while the model keeps one vertex there. :meth:`MeshTexture.vertex_uv`
gives one pair per vertex where the file has no seams. (u, v) follow OBJ's
convention: u from the image's left edge, v from its **bottom** edge, both
0..1 (glTF's v, which runs down from the top, is turned over when read).

>>> import numpy as np
>>> texture = MeshTexture(np.array([[0, 0], [1, 0], [0, 1.0]]), [MeshMaterial("skin", "skin.png")],
...                       np.array([0]))
>>> texture.vertex_uv(np.array([3, 2, 0, 1]), 3).tolist()
[[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]
>>> texture.images()
['skin.png']
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from engine.errors import MeshImportError, UserError
from engine.model.cells import cell_sizes, index_mask
from engine.model.model import Model


@dataclass
class MeshMaterial:
    """A material as the file names it, and its colour image (a path as resolved beside the
    file, ``"embedded: image/png, 1234 bytes"`` for an image inside a glTF, or ``None``)."""

    name: str
    image: str | None = None


@dataclass
class MeshTexture:
    """Texture coordinates of every polygon corner and the material of every polygon.

    ``corner_uv`` is (K, 2), one row for each vertex index of the flat cell
    array, NaN where the file gives that corner none; ``face_material`` is
    (F,), an index into ``materials`` or −1.
    """

    corner_uv: np.ndarray
    materials: list[MeshMaterial] = field(default_factory=list)
    face_material: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    def vertex_uv(self, faces: np.ndarray, n_vertices: int) -> np.ndarray | None:
        """One (u, v) per vertex when every corner of a vertex has the same pair (no seams),
        otherwise ``None``; vertices no corner names get NaN."""
        indices = np.asarray(faces, dtype=np.int64)[index_mask(faces, cell_sizes(faces))]
        out = np.full((n_vertices, 2), np.nan)
        out[indices] = self.corner_uv
        if not np.allclose(out[indices], self.corner_uv, equal_nan=True, atol=1e-7, rtol=0):
            return None
        return out

    def images(self) -> list[str]:
        """The distinct material images, in material order."""
        seen: list[str] = []
        for material in self.materials:
            if material.image and material.image not in seen:
                seen.append(material.image)
        return seen

    @property
    def has_coordinates(self) -> bool:
        return bool(len(self.corner_uv)) and not np.all(np.isnan(self.corner_uv))


@dataclass
class RawMesh:
    """A reader's result, in the file's units and axes: vertices (N, 3), the flat cell array,
    part names and each polygon's part, the texture if the file has one, and notes for the user
    (what was dropped or assumed)."""

    vertices: np.ndarray
    faces: np.ndarray
    part_names: list[str]
    face_part: np.ndarray
    texture: MeshTexture | None = None
    notes: list[str] = field(default_factory=list)
    #: The file's length unit per its format's specification ("m" for glTF), else ``None`` (taken as mm).
    units: str | None = None


@dataclass
class ImportedMesh:
    """A mesh ready to become a model: millimetres, +Y up, unused vertices dropped.

    ``faces`` and ``texture.corner_uv`` line up corner by corner; the vertex
    order is the one :class:`~engine.model.Model` gets, so a photograph
    fitted to ``texture`` applies to the model's vertices directly.
    """

    vertices: np.ndarray
    faces: np.ndarray
    part_names: list[str]
    vertex_part: np.ndarray
    texture: MeshTexture | None
    scale: float
    up: str
    notes: list[str] = field(default_factory=list)

    def to_model(self, name: str, source: str) -> Model:
        """A :class:`Model` with no parameters on these vertices and polygons (the texture stays here)."""
        try:
            return Model(self.vertices, self.faces, self.part_names, self.vertex_part, name=name,
                         description=f"imported from {source}")
        except UserError as exc:
            raise MeshImportError(exc.message, file=source) from None
