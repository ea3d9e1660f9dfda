"""The animated object: rest mesh, parts, parameter tree, influence regions, landmarks.

A :class:`Model` is plain data plus the deformation of §2.2. Lengths are
millimetres; the default head faces +Z with +Y up.

>>> from engine import load_model
>>> head = load_model()                                  # the shipped default head
>>> moved = head.deform({"jaw_open": 0.5})               # (N, 3) vertex positions, mm
>>> moved.shape == head.vertices.shape
True
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.errors import ParameterError, UserError
from engine.model.cells import cell_sizes, cells_to_triangles, check_cell_array, index_mask, split_cells
from engine.model.identity_record import IdentityRecord
from engine.model.parameters import NAME_PATTERN, Parameter, ParameterTree
from engine.model.texture import ModelTexture

if TYPE_CHECKING:
    from engine.deform.deformer import Deformer

COLOR_PATTERN = re.compile(r"#[0-9a-fA-F]{6}")
LANDMARK_PATTERN = re.compile(r"[A-Za-z0-9_.\-]+")


@dataclass
class InfluenceRegion:
    """The vertices a parameter moves, with one weight each (sparse).

    ``indices`` are unique vertex indices (sorted on construction),
    ``weights`` the matching weights in [0, 1]. A field translation also
    carries ``displacements`` (len(indices) × 3, mm for value 1).
    """

    indices: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    weights: np.ndarray = field(default_factory=lambda: np.zeros(0))
    displacements: np.ndarray | None = None

    def __post_init__(self) -> None:
        idx = np.asarray(self.indices, dtype=np.int64).reshape(-1)
        w = np.asarray(self.weights, dtype=float).reshape(-1)
        if idx.shape != w.shape:
            raise UserError(f"influence region: {len(idx)} indices but {len(w)} weights")
        if not np.all(np.isfinite(w)) or np.any(w < 0) or np.any(w > 1):
            raise UserError("influence region: weights must be finite numbers in [0, 1]")
        d = None if self.displacements is None else np.asarray(self.displacements, dtype=float).reshape(-1, 3)
        if d is not None and len(d) != len(idx):
            raise UserError(f"influence region: {len(idx)} indices but {len(d)} displacement vectors")
        order = np.argsort(idx, kind="stable")
        idx, w = idx[order], w[order]
        if len(idx) > 1 and np.any(idx[1:] == idx[:-1]):
            raise UserError("influence region: a vertex index is listed twice")
        self.indices, self.weights = idx, w
        self.displacements = None if d is None else d[order]

    def dense(self, n_vertices: int) -> np.ndarray:
        """Weights as a dense array of length ``n_vertices`` (zeros outside)."""
        out = np.zeros(n_vertices)
        out[self.indices] = self.weights
        return out

    def copy(self) -> InfluenceRegion:
        return InfluenceRegion(self.indices.copy(), self.weights.copy(),
                               None if self.displacements is None else self.displacements.copy())


class Model:
    """A deformable polygon mesh with a parameter tree (§2.2).

    Parameters
    ----------
    vertices : (N, 3) array
        Rest positions, mm.
    faces : 1-D int array
        Polygons as a flat VTK/pyvista cell array ``[n, i0, …, i(n-1), n, …]``.
    parts : list of str
        Part names (e.g. ``skin``, ``eye_left``, ``teeth_lower``).
    vertex_part : (N,) int array
        Index into ``parts`` for every vertex.
    parameters : ParameterTree
    regions : dict name → InfluenceRegion
        One per parameter (empty regions allowed).
    landmarks : dict id → vertex index
        MPEG-4 feature points, e.g. ``{"2.1": 812}``.
    part_colors : dict part → ``"#rrggbb"``, optional
    vertex_colors : (N, 3) uint8 array, optional
        sRGB colour per vertex (e.g. iris and pupil painted on the eyeballs);
        renderers prefer it to ``part_colors``.
    texture : ModelTexture, optional
        Texture coordinates of every polygon corner, the images and the
        image each polygon shows (:mod:`engine.model.texture`); renderers
        draw textured polygons with their image, the others as above.
    """

    def __init__(self, vertices: npt.ArrayLike, faces: npt.ArrayLike, parts: Sequence[str] | None = None,
                 vertex_part: npt.ArrayLike | None = None, parameters: ParameterTree | None = None,
                 regions: Mapping[str, InfluenceRegion] | None = None, landmarks: Mapping[str, int] | None = None,
                 name: str = "model", description: str = "",
                 part_colors: Mapping[str, str] | None = None, vertex_colors: npt.ArrayLike | None = None,
                 texture: ModelTexture | None = None) -> None:
        self.vertices = np.ascontiguousarray(np.asarray(vertices, dtype=float).reshape(-1, 3))
        self.faces = np.asarray(faces, dtype=np.int64).reshape(-1)
        n = len(self.vertices)
        self.parts = list(parts) if parts else ["surface"]
        self.vertex_part = (np.zeros(n, dtype=np.int64) if vertex_part is None
                            else np.asarray(vertex_part, dtype=np.int64).reshape(-1))
        self.parameters = parameters if parameters is not None else ParameterTree()
        self.regions: dict[str, InfluenceRegion] = dict(regions or {})
        for p in self.parameters:
            self.regions.setdefault(p.name, InfluenceRegion())
        self.landmarks: dict[str, int] = {str(k): int(v) for k, v in (landmarks or {}).items()}
        self.name = name
        self.description = description
        self.part_colors = dict(part_colors or {})
        self.vertex_colors = None if vertex_colors is None else np.asarray(vertex_colors, dtype=np.uint8)
        self.texture = texture
        self.identity: IdentityRecord | None = None       # who the head is (engine.identity), if made as one
        self.revision = 0
        self._deformer: Deformer | None = None
        self.validate()

    # -- validation ------------------------------------------------------
    def validate(self) -> None:
        """Check that arrays, parts, regions and landmarks fit together."""
        n = len(self.vertices)
        if not np.all(np.isfinite(self.vertices)):
            raise UserError("the rest mesh has non-finite vertex coordinates")
        check_cell_array(self.faces, n)
        if len(self.vertex_part) != n:
            raise UserError(f"{len(self.vertex_part)} part labels for {n} vertices")
        if n and (self.vertex_part.min() < 0 or self.vertex_part.max() >= len(self.parts)):
            raise UserError("a vertex's part index is outside the list of parts")
        if len(set(self.parts)) != len(self.parts):
            raise UserError("part names must be unique")
        for part in self.parts:
            if not isinstance(part, str) or not NAME_PATTERN.fullmatch(part):
                raise UserError(f"part name {part!r} is not allowed: use letters, digits, '_', '.' and '-', "
                                "starting with a letter or '_'")
        for part, color in self.part_colors.items():
            if part not in self.parts:
                raise UserError(f"colour given for unknown part '{part}'")
            if not isinstance(color, str) or not COLOR_PATTERN.fullmatch(color):
                raise UserError(f"part '{part}': colour {color!r} must be written #rrggbb")
        for key in self.landmarks:
            if not LANDMARK_PATTERN.fullmatch(key):
                raise UserError(f"landmark id {key!r} is not allowed: use letters, digits, '.', '_' and '-'")
        for name, region in self.regions.items():
            if name not in self.parameters:
                raise ParameterError(f"influence region for unknown parameter '{name}'")
            if len(region.indices) and (region.indices[0] < 0 or region.indices[-1] >= n):
                raise UserError(f"parameter '{name}': influence region names a vertex outside 0..{n - 1}")
            p = self.parameters[name]
            if p.field and region.displacements is None and len(region.indices):
                raise UserError(f"parameter '{name}' is a field translation but has no displacements")
            if not p.field and region.displacements is not None:
                raise UserError(f"parameter '{name}' has displacements but is not a field translation")
        if self.vertex_colors is not None and self.vertex_colors.shape != (n, 3):
            raise UserError(f"vertex colours have shape {self.vertex_colors.shape}, expected ({n}, 3)")
        for key, v in self.landmarks.items():
            if not 0 <= v < n:
                raise UserError(f"landmark {key}: vertex {v} is outside 0..{n - 1}")
        if self.texture is not None:
            self.texture.check(self.faces)

    # -- queries ---------------------------------------------------------
    @property
    def n_vertices(self) -> int:
        return len(self.vertices)

    def triangles(self) -> np.ndarray:
        """All polygons fan-triangulated, (T, 3) int array."""
        return cells_to_triangles(self.faces)

    def polygons(self) -> list[np.ndarray]:
        """Polygons as a list of index arrays."""
        return split_cells(self.faces)

    def part_vertices(self, part: str) -> np.ndarray:
        """Indices of the vertices of one part."""
        if part not in self.parts:
            raise UserError(f"unknown part '{part}' (parts: {', '.join(self.parts)})")
        return np.flatnonzero(self.vertex_part == self.parts.index(part))

    def default_values(self) -> dict[str, float]:
        return {p.name: p.default for p in self.parameters}

    def check_values(self, values: Mapping[str, float]) -> None:
        """Raise :class:`ParameterError` for unknown names or values out of range."""
        for name, v in values.items():
            p = self.parameters[name]
            if not np.isfinite(v):
                raise ParameterError(f"parameter '{name}': value {v} is not a finite number")
            if not p.minimum <= v <= p.maximum:
                raise ParameterError(
                    f"parameter '{name}': value {v:g} is outside its range [{p.minimum:g}, {p.maximum:g}]")

    # -- deformation -----------------------------------------------------
    def deform(self, values: Mapping[str, float] | None = None, **named: float) -> np.ndarray:
        """Vertex positions (N, 3, mm) for the given parameter values.

        Parameters not named take their default. Values outside a
        parameter's range are applied as given (use :meth:`check_values` to
        refuse them). Unknown names raise :class:`ParameterError`.
        """
        return self.deformer().deform(self.values_array(values, **named))

    def landmark_positions(self, values: Mapping[str, float] | None = None) -> dict[str, np.ndarray]:
        """Landmark id → (3,) position in mm for the given values."""
        P = self.deform(values)
        return {k: P[v] for k, v in self.landmarks.items()}

    def values_array(self, values: Mapping[str, float] | None = None, **named: float) -> np.ndarray:
        """Parameter values in tree order as an array (defaults filled in)."""
        merged = dict(values or {})
        merged.update(named)
        names = self.parameters.names
        index = {n: i for i, n in enumerate(names)}
        out = np.array([p.default for p in self.parameters], dtype=float)
        for name, v in merged.items():
            if name not in index:
                self.parameters[name]  # raises with a suggestion
            out[index[name]] = float(v)
        return out

    def deformer(self) -> Deformer:
        """The cached :class:`~engine.deform.Deformer`, rebuilt after edits."""
        from engine.deform.deformer import Deformer

        if self._deformer is None or self._deformer.revision != self.revision:
            self._deformer = Deformer(self)
        return self._deformer

    # -- edits (each bumps ``revision``) ------------------------------------
    def changed(self) -> None:
        """Declare an edit made in place, so cached structures are rebuilt."""
        self.revision += 1

    def add_parameter(self, parameter: Parameter, region: InfluenceRegion | None = None) -> None:
        self.parameters.add(parameter)
        self.regions[parameter.name] = region if region is not None else InfluenceRegion()
        try:
            self.validate()
        except UserError:
            self.parameters.remove(parameter.name)
            del self.regions[parameter.name]
            raise
        self.changed()

    def remove_parameter(self, name: str) -> tuple[Parameter, InfluenceRegion]:
        p = self.parameters.remove(name)
        region = self.regions.pop(name)
        self.changed()
        return p, region

    def set_region(self, name: str, region: InfluenceRegion) -> None:
        self.parameters[name]
        old = self.regions.get(name)
        self.regions[name] = region
        try:
            self.validate()
        except UserError:
            if old is None:
                del self.regions[name]
            else:
                self.regions[name] = old
            raise
        self.changed()

    def reordered(self, order: npt.ArrayLike) -> Model:
        """A copy with vertex ``i`` taken from old vertex ``order[i]``; faces, regions and
        landmarks renumbered. ``order`` must be a permutation of ``range(n_vertices)``."""
        order = np.asarray(order, dtype=np.int64)
        n = self.n_vertices
        if order.shape != (n,) or not np.array_equal(np.sort(order), np.arange(n)):
            raise UserError(f"a vertex order must be a permutation of 0..{n - 1}")
        new_index = np.empty(n, dtype=np.int64)
        new_index[order] = np.arange(n)
        faces = self.faces.copy()
        mask = index_mask(faces, cell_sizes(faces))
        faces[mask] = new_index[faces[mask]]
        regions = {name: InfluenceRegion(new_index[r.indices], r.weights, r.displacements)
                   for name, r in self.regions.items()}
        return Model(self.vertices[order], faces, list(self.parts), self.vertex_part[order],
                     self.parameters.copy(), regions, {k: int(new_index[v]) for k, v in self.landmarks.items()},
                     self.name, self.description, dict(self.part_colors),
                     None if self.vertex_colors is None else self.vertex_colors[order],
                     None if self.texture is None else self.texture.copy())   # corners keep their order

    def copy(self) -> Model:
        copied = Model(self.vertices.copy(), self.faces.copy(), list(self.parts), self.vertex_part.copy(),
                       self.parameters.copy(), {k: r.copy() for k, r in self.regions.items()},
                       dict(self.landmarks), self.name, self.description, dict(self.part_colors),
                       None if self.vertex_colors is None else self.vertex_colors.copy(),
                       None if self.texture is None else self.texture.copy())
        copied.identity = self.identity
        return copied
