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

import base64
import json
import os
import re
import struct
import urllib.parse
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import NoReturn

import numpy as np
import numpy.typing as npt

from engine.errors import UserError

METRES_PER_MM = 0.001
GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
_COMPONENTS = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
_TRIANGLES = 4
MODEL_VERTEX = "_MODEL_VERTEX"   # application-specific attribute: each point's vertex index in the model


class GltfFileError(UserError):
    """A glTF file is malformed, or is not one this module can read."""


def _quaternion_matrix(q: npt.ArrayLike) -> np.ndarray:
    """Rotation matrix of a unit quaternion (x, y, z, w); any length but zero (scaled first, so that
    a quaternion of huge or tiny numbers neither overflows nor underflows its length)."""
    scaled = np.asarray(q, dtype=float) / np.max(np.abs(np.asarray(q, dtype=float)))
    x, y, z, w = scaled / np.linalg.norm(scaled)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


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
        return _parse(path, *_split_glb(blob, path))
    try:
        document = json.loads(blob.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise GltfFileError(f"neither a binary glTF nor JSON: {exc}", file=path) from None
    return _parse(path, document, {})


def _split_glb(blob: bytes, path: Path, strict: bool = True) -> tuple[dict, dict[int, bytes]]:
    """The JSON document and the binary chunk of a GLB. ``strict=False`` (importing other programs'
    files) accepts chunks not padded to 4 bytes and a header length that disagrees with the file,
    as other readers do; every chunk must still lie inside the file."""
    def fail(what: str) -> NoReturn:
        raise GltfFileError(f"not a valid binary glTF: {what}", file=path)

    if len(blob) < 20:
        fail("shorter than its header")
    magic, version, length = struct.unpack_from("<III", blob)
    if magic != GLB_MAGIC or version != 2:
        fail(f"magic {magic:#x}, container version {version} (expected glTF, 2)")
    if length != len(blob) and (strict or length > len(blob)):
        fail(f"the header says {length} bytes, the file has {len(blob)}")
    chunks: list[tuple[int, bytes]] = []
    offset = 12
    while offset < length:
        if offset + 8 > length:
            fail("a chunk header runs past the end")
        size, kind = struct.unpack_from("<II", blob, offset)
        if (strict and size % 4) or offset + 8 + size > length:
            fail("a chunk is misaligned or runs past the end")
        chunks.append((kind, blob[offset + 8:offset + 8 + size]))
        offset += 8 + size
    if not chunks or chunks[0][0] != GLB_JSON:
        fail("the first chunk is not JSON")
    try:
        document = json.loads(chunks[0][1].decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        fail(f"the JSON chunk does not parse: {exc}")
    binary = {0: chunks[1][1]} if len(chunks) > 1 and chunks[1][0] == GLB_BIN else {}
    return document, binary


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
            local[:3, :3] = _quaternion_matrix(node.get("rotation", [0, 0, 0, 1]))
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
LFS_POINTER = b"version https://git-lfs.github.com/spec/v1"
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def whole(value: object, what: str, fail: Callable[[str], NoReturn]) -> int:
    """``value`` as an int if it is a JSON whole number (``3`` or ``3.0``; not ``true``, ``2.5`` or ``"3"``)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
            isinstance(value, float) and not value.is_integer()):
        fail(f"{what} must be a whole number, not {json.dumps(value)[:40]}")
    if abs(value) > 2**53:
        fail(f"{what} is {json.dumps(value)[:40]}, too large for any file")
    return int(value)


def index_of(value: object, kind: str, count: int, where: str, fail: Callable[[str], NoReturn]) -> int:
    """``value`` as an index into the document's array ``kind`` of ``count`` elements: a whole number from 0
    to ``count − 1``. A negative index would wrap to the end of a Python list, so it is refused like any
    index past the end."""
    singular = kind.removesuffix("es" if kind == "meshes" else "s")
    index = whole(value, f"{where}: {'an' if singular[0] in 'aeiou' else 'a'} {singular} index", fail)
    if not 0 <= index < count:
        fail(f"{where} names {singular} {index}, which does not exist (the file has {count})")
    return index


def element(doc: dict, kind: str, value: object, where: str, fail: Callable[[str], NoReturn]) -> dict:
    """The element of the document's array ``kind`` (``"accessors"``, ``"nodes"`` …) that ``value`` names,
    checked by :func:`index_of`; it must be a JSON object."""
    items = doc.get(kind, [])
    if not isinstance(items, list):
        fail(f"'{kind}' is not a list")
    item = items[index_of(value, kind, len(items), where, fail)]
    if not isinstance(item, dict):
        fail(f"{kind} {value} is not a JSON object")
    return item


def integers(array: np.ndarray, what: str, fail: Callable[[str], NoReturn]) -> np.ndarray:
    """An accessor's values as int64 indices; values that are not whole numbers within int64 (float data
    holding NaN, 1e30 or 0.5) are refused before the cast, which would make them garbage with a warning."""
    if array.dtype.kind == "f" and not (np.all(np.isfinite(array)) and np.all(np.abs(array) <= 2.0**53)
                                        and np.all(array == np.round(array))):
        fail(f"{what} must be whole numbers")
    return array.astype(np.int64)


def document_file(path: Path, uri: str) -> Path:
    """The file a relative ``uri`` of the glTF document at ``path`` names, percent-decoded and with links
    resolved, which must lie in the document's folder or one inside it: the one check for every file a glTF
    reader opens (buffers, images), so that a downloaded model cannot carry a user's file into a model.

    :class:`GltfFileError` (no file: the caller says whose URI) for another scheme (``http://``, ``file:``),
    an absolute path, a backslash (a separator on Windows only), a NUL, bytes that are not UTF-8, and a name
    that leads out of the folder (``../``, ``%2e%2e%2f``, a link pointing elsewhere)."""
    shown = uri[:200]
    try:
        name = urllib.parse.unquote(uri, errors="strict")
    except UnicodeDecodeError:
        raise GltfFileError(f"'{shown}' is not UTF-8 once percent-decoded") from None
    if _SCHEME.match(name) or Path(name).is_absolute():
        raise GltfFileError(f"'{shown}' is not a file beside the document (only relative file names are read)")
    if "\\" in name or "\0" in name:
        raise GltfFileError(f"'{shown}' holds a {'backslash' if chr(92) in name else 'NUL'}, which a file URI "
                            "does not (write '/' between folders)")
    folder = Path(os.path.realpath(path.parent))
    target = Path(os.path.realpath(folder / name))
    if not target.is_relative_to(folder):
        raise GltfFileError(f"'{shown}' leaves the document's folder (only files in {path.parent}, or in folders "
                            "inside it, are read)")
    return target


def load_buffer(path: Path, i: int, spec: dict, embedded: dict[int, bytes], fail: Callable[[str], NoReturn]) -> bytes:
    """Buffer ``i`` of the document at ``path``: the GLB's binary chunk, data handed in (a file
    being checked before it is written), a ``data:`` URI or a file beside the document. A
    missing file or a Git LFS pointer in its place is said so plainly."""
    uri, length = spec.get("uri"), whole(spec["byteLength"], f"buffer {i}: byteLength", fail)
    if length < 0:
        fail(f"buffer {i}: byteLength {length} is negative")
    if i in embedded:
        data, slack = embedded[i], 3 if uri is None else 0     # the BIN chunk is padded to 4 bytes
    elif uri is None:
        fail(f"buffer {i} has no uri and there is no binary chunk")
    elif not isinstance(uri, str):
        fail(f"buffer {i}: its uri is not a string")
    elif uri.startswith("data:"):
        try:
            data, slack = base64.b64decode(uri.partition(",")[2], validate=True), 0
        except ValueError:
            fail(f"buffer {i}: its data: URI is not valid base64")
    else:
        data, slack = _buffer_file(path, i, uri, length, fail), 0
    if not length <= len(data) <= length + slack:
        fail(f"buffer {i}: byteLength {length} but its data hold {len(data)} bytes")
    return data[:length]


def _buffer_file(path: Path, i: int, uri: str, length: int, fail: Callable[[str], NoReturn]) -> bytes:
    """The bytes of buffer ``i``'s file (:func:`document_file`), read only when it has the length the
    document gives (a Git LFS pointer named as such)."""
    try:
        target = document_file(path, uri)
    except GltfFileError as exc:
        fail(f"buffer {i}: {exc.message}")
    name = urllib.parse.unquote(uri)
    if not target.is_file():
        fail(f"buffer {i}: cannot read '{name}': the file is missing (it belongs beside {path.name})")
    try:
        with target.open("rb") as stream:
            size = os.fstat(stream.fileno()).st_size
            if stream.read(len(LFS_POINTER)) == LFS_POINTER:
                fail(f"buffer {i}: '{name}' is a Git LFS pointer, not the data (fetch it with 'git lfs pull')")
            if size != length:
                fail(f"buffer {i}: byteLength {length} but its data hold {size} bytes")
            stream.seek(0)
            return stream.read(length + 1)
    except OSError as exc:
        fail(f"buffer {i}: cannot read '{name}': {exc.strerror or exc}")


def decode_accessor(doc: dict, buffer: Callable[[int], bytes], index: int, fail: Callable[[str], NoReturn],
                    check_bounds: bool = True) -> np.ndarray:
    """Accessor ``index`` as an array (N, width), or (N,) for scalars; ``buffer(i)`` gives buffer ``i``.

    Every offset, stride and count is checked against the bytes that exist
    before anything is read. With ``check_bounds`` the accessor's ``min`` and
    ``max`` must match its data (to float32 rounding)."""
    a = element(doc, "accessors", index, "the document", fail)
    where = f"accessor {index}"
    if "sparse" in a or "bufferView" not in a:
        fail(f"{where}: sparse or buffer-less accessors are not supported")
    if a.get("componentType") not in _COMPONENTS or a.get("type") not in _WIDTHS:
        fail(f"{where}: unknown componentType or type")
    dtype = np.dtype(_COMPONENTS[a["componentType"]]).newbyteorder("<")
    width, count = _WIDTHS[a["type"]], whole(a["count"], f"{where}: count", fail)
    view = element(doc, "bufferViews", a["bufferView"], where, fail)
    data = buffer(index_of(view["buffer"], "buffers", len(doc.get("buffers", [])), f"bufferView {a['bufferView']}",
                           fail))
    start = whole(view.get("byteOffset", 0), f"bufferView {a['bufferView']}: byteOffset", fail)
    length = whole(view["byteLength"], f"bufferView {a['bufferView']}: byteLength", fail)
    if start < 0 or length < 0 or start + length > len(data):
        fail(f"bufferView {a['bufferView']} runs past the end of buffer {view['buffer']}")
    item = dtype.itemsize * width
    stride = whole(view.get("byteStride", item), f"bufferView {a['bufferView']}: byteStride", fail)
    offset = whole(a.get("byteOffset", 0), f"{where}: byteOffset", fail)
    if count < 1 or offset < 0 or offset % dtype.itemsize or stride < item:
        fail(f"{where}: bad count, offset or stride")
    if offset + stride * (count - 1) + item > length:
        fail(f"{where}: {count} elements do not fit in bufferView {a['bufferView']} ({length} bytes)")
    raw = np.frombuffer(data, dtype=np.uint8, count=stride * (count - 1) + item, offset=start + offset)
    rows = np.lib.stride_tricks.as_strided(raw, shape=(count, item), strides=(stride, 1))
    array = np.ascontiguousarray(rows).view(dtype).reshape(count, width).astype(dtype.newbyteorder("="))
    for key, reduce in (("min", np.min), ("max", np.max)):
        if check_bounds and key in a:
            bound = np.asarray(a[key], dtype=float)
            # other writers may print bounds in decimal: allow float32 rounding, no more
            if bound.shape != (width,) or not np.allclose(reduce(array, axis=0), bound, rtol=1e-6, atol=0):
                fail(f"{where}: {key} {a[key]} does not match its data")
    return array[:, 0] if width == 1 else array
