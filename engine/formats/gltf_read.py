"""Reading glTF 2.0 files back: structure checks and arrays (the other half of :mod:`engine.outputs.gltf_export`).

:func:`read_gltf` reads a ``.glb`` or ``.gltf`` (with its ``.bin`` or embedded
data), checks the structure — asset version 2.0, buffer lengths, accessor
bounds and exact min/max, every index below the vertex count, consistent
morph target counts, the skin — and returns the arrays, so the exporter can
verify every file before it is written and tests can compare round trips.

>>> from engine.formats.gltf_read import read_gltf
>>> read_gltf("head.glb").target_names[:2]                           # doctest: +SKIP
['neck_lean', 'head_turn']
"""

from __future__ import annotations

import json
import struct
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import NoReturn

import numpy as np

from engine.errors import UserError
from engine.formats.gltf_document import (
    GLB_MAGIC,
    GltfFileError,
    decode_accessor,
    element,
    index_of,
    integers,
    load_buffer,
    quaternion_matrix,
    split_glb,
)

METRES_PER_MM = 0.001
_TRIANGLES = 4
MODEL_VERTEX = "_MODEL_VERTEX"   # application-specific attribute: each point's vertex index in the model


# -- reading ---------------------------------------------------------------------

@dataclass
class GltfPrimitive:
    """One primitive as read back: arrays as stored (metres, linear colours)."""

    name: str
    positions: np.ndarray
    triangles: np.ndarray
    normals: np.ndarray | None = None
    colors: np.ndarray | None = None
    model_vertex: np.ndarray | None = None
    targets: list[dict[str, np.ndarray]] = field(default_factory=list)
    material: dict = field(default_factory=dict)
    joints: np.ndarray | None = None
    weights: np.ndarray | None = None


@dataclass
class GltfMesh:
    """The first mesh of a glTF file: its primitives, target names and default weights."""

    name: str
    primitives: list[GltfPrimitive]
    target_names: list[str]
    weights: np.ndarray
    document: dict
    skin: GltfSkin | None = None

    @property
    def n_points(self) -> int:
        return sum(len(p.positions) for p in self.primitives)

    def model_positions(self, n_vertices: int, weights: Mapping[str, float] | None = None,
                        joints: Mapping[str, float] | None = None) -> np.ndarray:
        """Posed positions (metres) in the model's vertex order via ``_MODEL_VERTEX``; NaN for
        model vertices no primitive holds.

        ``weights`` are morph target weights by name; ``joints`` parameter values
        of a skeleton's joints (``value × degrees_per_unit`` degrees about the
        joint's +X, or ``value × mm_per_unit`` along it), applied by linear blend
        skinning after the morph targets, as glTF does.
        """
        skinning = None
        if joints:
            if self.skin is None:
                raise UserError("the file has no skeleton to pose")
            skinning = self.skin.matrices(joints)
        w = np.zeros(len(self.target_names))
        for name, v in (weights or {}).items():
            if name not in self.target_names:
                raise UserError(f"no morph target named '{name}'")
            w[self.target_names.index(name)] = v
        out = np.full((n_vertices, 3), np.nan)
        for p in self.primitives:
            if p.model_vertex is None:
                raise UserError(f"primitive '{p.name}' has no {MODEL_VERTEX} attribute")
            if len(p.model_vertex) and not (p.model_vertex.min() >= 0 and p.model_vertex.max() < n_vertices):
                raise UserError(f"primitive '{p.name}': {MODEL_VERTEX} is not a vertex of the {n_vertices}")
            P = p.positions.astype(np.float64)
            for weight, target in zip(w, p.targets, strict=True):
                if weight:
                    P = P + weight * target["POSITION"]
            if skinning is not None:
                if p.joints is None or p.weights is None:
                    raise UserError(f"primitive '{p.name}' has no JOINTS_0 and WEIGHTS_0 to skin with")
                blended = np.einsum("vk,vkij->vij", p.weights, skinning[p.joints])
                P = np.einsum("vij,vj->vi", blended[:, :3, :3], P) + blended[:, :3, 3]
            out[p.model_vertex] = P
        return out


@dataclass
class GltfSkin:
    """A skin as read back: joint names, parents (index into ``names``, −1 for none),
    rest local transforms, inverse bind matrices and the joints' ``extras``."""

    names: list[str]
    parents: list[int]
    rest: list[np.ndarray]
    inverse_bind: np.ndarray
    extras: list[dict]

    def matrices(self, values: Mapping[str, float]) -> np.ndarray:
        """Skinning matrix ``G · IBM`` of every joint (4×4, column convention) for parameter values."""
        for name in values:
            if name not in self.names:
                raise UserError(f"no joint named '{name}' (joints: {', '.join(self.names)})")
        world: list[np.ndarray] = []
        for i, name in enumerate(self.names):       # the writer lists parents before children
            motion = np.eye(4)
            value = float(values.get(name, 0.0))
            extras = self.extras[i]
            if value and "degrees_per_unit" in extras:
                a = np.radians(value * extras["degrees_per_unit"])
                motion[1:3, 1:3] = [[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]
            elif value and "mm_per_unit" in extras:
                motion[0, 3] = value * extras["mm_per_unit"] * METRES_PER_MM
            local = self.rest[i] @ motion
            world.append(local if self.parents[i] < 0 else world[self.parents[i]] @ local)
        return np.stack(world) @ self.inverse_bind


def read_gltf(path: str | Path) -> GltfMesh:
    """Read a ``.glb`` or ``.gltf`` file, check its structure, return its first mesh.

    Checks: asset version 2.0; buffer and bufferView lengths; every accessor
    inside its bufferView, with ``min``/``max`` (required on positions)
    equal to its data; triangle indices below the vertex count; the same
    number of morph targets in every primitive, matching ``weights`` and
    ``extras.targetNames``. Sparse accessors are refused (this writer never
    makes them). Raises :class:`GltfFileError`.
    """
    path = Path(path)
    try:
        blob = path.read_bytes()
    except OSError as exc:
        raise GltfFileError(f"cannot read: {exc.strerror or exc}", file=path) from None
    if blob[:4] == struct.pack("<I", GLB_MAGIC):
        return _parse(path, *split_glb(blob, path))
    try:
        document = json.loads(blob.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise GltfFileError(f"neither a binary glTF nor JSON: {exc}", file=path) from None
    return _parse(path, document, {})


def _parse(path: Path, document: dict, embedded: dict[int, bytes]) -> GltfMesh:
    def fail(what: str) -> NoReturn:
        raise GltfFileError(what, file=path)

    try:
        return _Reader(path, document, embedded, fail).mesh()
    except (KeyError, IndexError, TypeError, ValueError, AttributeError) as exc:
        fail(f"malformed glTF document: {type(exc).__name__}: {exc}")


class _Reader:
    def __init__(self, path: Path, document: dict, embedded: dict[int, bytes],
                 fail: Callable[[str], NoReturn]) -> None:
        self.path, self.doc, self.fail = path, document, fail
        if not isinstance(document, dict) or str(document.get("asset", {}).get("version")) != "2.0":
            fail("not a glTF 2.0 document (asset.version must be \"2.0\")")
        self.buffers = [load_buffer(path, i, b, embedded, fail) for i, b in enumerate(document.get("buffers", []))]
        self.cache: dict[int, np.ndarray] = {}

    def accessor(self, index: int) -> np.ndarray:
        if index not in self.cache:
            self.cache[index] = decode_accessor(self.doc, self.buffers.__getitem__, index, self.fail)
        return self.cache[index]

    def mesh(self) -> GltfMesh:
        doc = self.doc
        meshes = doc.get("meshes", [])
        if not meshes:
            self.fail("the file holds no mesh")
        for n, node in enumerate(doc.get("nodes", [])):
            if "mesh" in node:
                index_of(node["mesh"], "meshes", len(meshes), f"node {n}", self.fail)
        spec = meshes[0]
        prims = [self.primitive(i, p) for i, p in enumerate(spec["primitives"])]
        counts = {len(p.targets) for p in prims}
        if len(counts) > 1:
            self.fail(f"mesh 0: primitives have different numbers of morph targets ({sorted(counts)})")
        n_targets = counts.pop() if counts else 0
        weights = np.asarray(spec.get("weights", [0.0] * n_targets), dtype=float)
        names = list(spec.get("extras", {}).get("targetNames", [f"target_{i}" for i in range(n_targets)]))
        if len(weights) != n_targets or len(names) != n_targets:
            self.fail(f"mesh 0: {n_targets} morph targets but {len(weights)} weights and {len(names)} target names")
        return GltfMesh(spec.get("name", ""), prims, names, weights, doc, self.skin(prims))

    def skin(self, prims: list[GltfPrimitive]) -> GltfSkin | None:
        doc = self.doc
        holder = [n for n in doc.get("nodes", []) if n.get("mesh") == 0 and "skin" in n]
        if not holder:
            return None
        skin = element(doc, "skins", holder[0]["skin"], "the mesh's node", self.fail)
        joints = [index_of(j, "nodes", len(doc["nodes"]), "skin", self.fail) for j in skin["joints"]]
        ibm = self.accessor(skin["inverseBindMatrices"])
        if ibm.shape != (len(joints), 16):
            self.fail(f"skin: {len(ibm)} inverse bind matrices for {len(joints)} joints")
        parent_of = {c: i for i, n in enumerate(doc["nodes"]) for c in n.get("children", [])}
        parents, rest = [], []
        for j in joints:
            node = doc["nodes"][j]
            parent = parent_of.get(j)
            if parent is not None and parent in joints and joints.index(parent) > joints.index(j):
                self.fail(f"skin: joint '{node.get('name')}' is listed before its parent")
            parents.append(joints.index(parent) if parent in joints else -1)
            local = np.eye(4)
            local[:3, :3] = quaternion_matrix(node.get("rotation", [0, 0, 0, 1]))
            local[:3, 3] = node.get("translation", [0, 0, 0])
            rest.append(local)
        for p in prims:
            if p.joints is None or p.weights is None:
                self.fail(f"primitive '{p.name}' of a skinned mesh has no JOINTS_0 and WEIGHTS_0")
            if p.joints.max(initial=0) >= len(joints) or p.joints.min(initial=0) < 0:
                self.fail(f"primitive '{p.name}': JOINTS_0 names a joint past the {len(joints)} of the skin")
            if np.any(np.abs(p.weights.sum(axis=1) - 1) > 2e-3):
                self.fail(f"primitive '{p.name}': skin weights do not sum to 1")
        names = [doc["nodes"][j].get("name", f"joint_{j}") for j in joints]
        return GltfSkin(names, parents, rest, ibm.reshape(-1, 4, 4).transpose(0, 2, 1).astype(float),
                        [doc["nodes"][j].get("extras", {}) for j in joints])

    def primitive(self, i: int, spec: dict) -> GltfPrimitive:
        attributes = spec["attributes"]
        name = spec.get("extras", {}).get("part", f"primitive_{i}")
        if spec.get("mode", _TRIANGLES) != _TRIANGLES:
            self.fail(f"primitive '{name}': only triangles are supported")
        if "POSITION" not in attributes:
            self.fail(f"primitive '{name}' has no POSITION")
        positions = self.accessor(attributes["POSITION"])
        n = len(positions)
        if "min" not in self.doc["accessors"][attributes["POSITION"]]:
            self.fail(f"primitive '{name}': POSITION needs min and max")
        arrays = {key: self.accessor(index) for key, index in attributes.items()}
        for key, array in arrays.items():
            if len(array) != n:
                self.fail(f"primitive '{name}': {key} has {len(array)} elements for {n} vertices")
        if "indices" in spec:
            flat = integers(self.accessor(spec["indices"]), f"primitive '{name}': indices", self.fail)
        else:
            flat = np.arange(n)
        if len(flat) % 3 or (len(flat) and (flat.max() >= n or flat.min() < 0)):
            self.fail(f"primitive '{name}': indices must be triangles of vertices below {n}")
        targets = []
        for j, target in enumerate(spec.get("targets", [])):
            entry = {key: self.accessor(index).astype(np.float32) for key, index in target.items()}
            if "POSITION" in target and "min" not in self.doc["accessors"][target["POSITION"]]:
                self.fail(f"primitive '{name}', morph target {j}: POSITION needs min and max")
            for key, array in entry.items():
                if array.shape != (n, 3):
                    self.fail(f"primitive '{name}', morph target {j}: {key} has shape {array.shape}, "
                              f"expected ({n}, 3)")
            targets.append(entry)
        material = (element(self.doc, "materials", spec["material"], f"primitive '{name}'", self.fail)
                    if "material" in spec else {})
        vertex = arrays.get(MODEL_VERTEX)
        joints = arrays.get("JOINTS_0")
        return GltfPrimitive(name, positions, flat.reshape(-1, 3), arrays.get("NORMAL"), arrays.get("COLOR_0"),
                             None if vertex is None else integers(vertex, f"primitive '{name}': {MODEL_VERTEX}",
                                                                  self.fail),
                             targets, material,
                             None if joints is None else integers(joints, f"primitive '{name}': JOINTS_0", self.fail),
                             arrays.get("WEIGHTS_0"))


# -- pieces shared with the mesh importer (:mod:`engine.formats.mesh_gltf`) ------------

#: The first line of a Git LFS pointer file, which a clone without LFS holds instead of the data.
