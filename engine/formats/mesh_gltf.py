"""glTF 2.0 (``.gltf`` with its buffers, or ``.glb``) imported as a mesh by our own code.

Every mesh the default scene places is read with its node transforms
applied; triangles, triangle strips and fans are kept (points and lines
dropped); each glTF mesh becomes a part. ``TEXCOORD_0`` gives the texture
coordinates (v turned to run up the image, as in OBJ and PLY) and the
material's ``baseColorTexture`` its image (a file beside the document, or an
image embedded in it). Coordinates stay in metres here
(``units="m"``): :func:`engine.formats.mesh_io.read_mesh` converts them.

A buffer file that is missing, or a Git LFS pointer in its place, is named
plainly; every count, offset and index is checked against the bytes that
exist before anything is read (:func:`engine.formats.gltf_read.decode_accessor`),
every index into the document's arrays must name an element that exists
(:func:`~engine.formats.gltf_read.index_of`: a negative one never wraps), and
every file URI must stay in the document's folder
(:func:`~engine.formats.gltf_read.document_file`).

>>> import json, base64, tempfile, pathlib, numpy as np
>>> blob = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], "<f4").tobytes()
>>> doc = {"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
...        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
...        "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"byteLength": 36,
...        "uri": "data:;base64," + base64.b64encode(blob).decode()}]}
>>> path = pathlib.Path(tempfile.mkdtemp()) / "triangle.gltf"
>>> _ = path.write_text(json.dumps(doc))
>>> mesh = read_gltf_mesh(path)
>>> mesh.faces.tolist(), mesh.units
([3, 0, 1, 2], 'm')
"""

from __future__ import annotations

import json
import struct
from pathlib import Path
from typing import NoReturn

import numpy as np

from engine.errors import MeshImportError
from engine.formats.gltf_document import (
    GLB_MAGIC,
    GltfFileError,
    decode_accessor,
    document_file,
    element,
    index_of,
    integers,
    load_buffer,
    quaternion_matrix,
    split_glb,
)
from engine.formats.mesh_data import MeshMaterial, MeshTexture, RawMesh

_TRIANGLES, _STRIP, _FAN = 4, 5, 6
_NORMALIZED = {5121: 255.0, 5123: 65535.0, 5120: 127.0, 5122: 32767.0}
_UNSUPPORTED = ("KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization")
_MAX_NODES_VISITED = 1_000_000


def read_gltf_mesh(path: Path) -> RawMesh:
    """Every mesh instance of the default scene (metres, the file's axes) with texture
    coordinates and base-colour images. :class:`MeshImportError` naming the file otherwise."""
    try:
        blob = path.read_bytes()
    except OSError as exc:
        raise MeshImportError(f"cannot read file: {exc.strerror or exc}", file=path) from None
    try:
        if blob[:4] == struct.pack("<I", GLB_MAGIC):
            document, embedded = split_glb(blob, path, strict=False)
        else:
            try:
                document = json.loads(blob.decode("utf-8"))
            except (UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
                raise MeshImportError(f"neither a binary glTF nor JSON: {exc}", file=path) from None
            embedded = {}
        return _Importer(path, document, embedded).mesh()
    except GltfFileError as exc:
        raise MeshImportError(exc.message, file=path) from None
    except (KeyError, IndexError, TypeError, ValueError, AttributeError, OverflowError, RecursionError) as exc:
        raise MeshImportError(f"malformed glTF document: {type(exc).__name__}: {str(exc)[:200]}",
                              file=path) from None


class _Importer:
    def __init__(self, path: Path, document: object, embedded: dict[int, bytes]) -> None:
        self.path = path
        if not isinstance(document, dict) or not str(document.get("asset", {}).get("version", "")).startswith("2"):
            self.fail("not a glTF 2.0 document (asset.version must be \"2.0\")")
        self.doc: dict = document
        needed = [e for e in document.get("extensionsRequired", []) if e in _UNSUPPORTED]
        if needed:
            self.fail(f"needs the extension {needed[0]}, which this reader does not support "
                      "(export the mesh without compression)")
        self.embedded = embedded
        self.buffers: dict[int, bytes] = {}
        self.accessors: dict[int, np.ndarray] = {}
        self.materials: dict[int, int] = {}      # glTF material index → our material slot
        self.material_list: list[MeshMaterial] = []
        self.notes: set[str] = set()

    def fail(self, what: str) -> NoReturn:
        raise MeshImportError(what, file=self.path)

    def buffer(self, i: int) -> bytes:
        if i not in self.buffers:
            spec = element(self.doc, "buffers", i, "a bufferView", self.fail)
            self.buffers[i] = load_buffer(self.path, i, spec, self.embedded, self.fail)
        return self.buffers[i]

    def accessor(self, index: object, where: str) -> np.ndarray:
        """Accessor ``index`` (normalised integers as numbers from −1 or 0 to 1), named by ``where``."""
        i = index_of(index, "accessors", len(self.doc.get("accessors", [])), where, self.fail)
        if i not in self.accessors:
            array = decode_accessor(self.doc, self.buffer, i, self.fail, check_bounds=False)
            spec = self.doc["accessors"][i]
            if spec.get("normalized") and spec["componentType"] in _NORMALIZED:
                array = np.maximum(array / _NORMALIZED[spec["componentType"]], -1.0)
            self.accessors[i] = array
        return self.accessors[i]

    def indices(self, index: object, where: str) -> np.ndarray:
        """A primitive's vertex indices: an accessor of integers (never normalised), as int64."""
        i = index_of(index, "accessors", len(self.doc.get("accessors", [])), f"{where}: indices", self.fail)
        return integers(decode_accessor(self.doc, self.buffer, i, self.fail, check_bounds=False),
                        f"{where}: indices", self.fail)

    def mesh(self) -> RawMesh:
        meshes = self.doc.get("meshes", [])
        if not meshes:
            self.fail("the file holds no mesh")
        vertices: list[np.ndarray] = []
        faces: list[np.ndarray] = []
        corner_uv: list[np.ndarray] = []
        face_material: list[np.ndarray] = []
        face_part: list[np.ndarray] = []
        part_names: list[str] = []
        notes: set[str] = set()
        offset = 0
        for mesh_index, label, matrix in self.instances(len(meshes)):
            if label not in part_names:
                part_names.append(label)
            for p, spec in enumerate(meshes[mesh_index]["primitives"]):
                piece = self.primitive(spec, matrix, f"mesh {mesh_index} primitive {p}", notes)
                if piece is None:
                    continue
                points, triangles, uv, material = piece
                vertices.append(points)
                faces.append(np.column_stack([np.full(len(triangles), 3), triangles + offset]).reshape(-1))
                corner_uv.append(uv[triangles].reshape(-1, 2) if uv is not None
                                 else np.full((3 * len(triangles), 2), np.nan))
                face_material.append(np.full(len(triangles), material, dtype=np.int64))
                face_part.append(np.full(len(triangles), part_names.index(label), dtype=np.int64))
                offset += len(points)
        notes |= self.notes
        if not faces:
            return RawMesh(np.zeros((0, 3)), np.zeros(0, dtype=np.int64), [], np.zeros(0, dtype=np.int64),
                           units="m", notes=sorted(notes))
        uv_all = np.concatenate(corner_uv)
        texture = None
        if not np.all(np.isnan(uv_all)) or self.material_list:
            texture = MeshTexture(uv_all, self.material_list, np.concatenate(face_material))
        return RawMesh(np.concatenate(vertices), np.concatenate(faces).astype(np.int64), part_names,
                       np.concatenate(face_part), texture, sorted(notes), units="m")

    def instances(self, n_meshes: int) -> list[tuple[int, str, np.ndarray]]:
        """(mesh index, part label, world matrix) for every mesh the default scene places; every mesh
        once, untransformed, when the file has no scene."""
        nodes = self.doc.get("nodes", [])
        scenes = self.doc.get("scenes", [])
        if not scenes:
            return [(i, self.mesh_label(i, None), np.eye(4)) for i in range(n_meshes)]
        roots = element(self.doc, "scenes", self.doc.get("scene", 0), "'scene'", self.fail).get("nodes", [])
        out = []
        stack: list[tuple[int, np.ndarray, tuple[int, ...]]] = [
            (index_of(r, "nodes", len(nodes), f"scene {self.doc.get('scene', 0)}", self.fail), np.eye(4), ())
            for r in reversed(roots)]
        visited = 0
        while stack:
            index, parent, ancestors = stack.pop()
            visited += 1
            if index in ancestors or visited > _MAX_NODES_VISITED:
                self.fail(f"node {index} is its own ancestor (the node tree has a cycle)")
            node = element(self.doc, "nodes", index, "a scene", self.fail)
            with np.errstate(all="ignore"):         # huge scales multiplied down a tree: checked just below
                world = parent @ _local_matrix(node)
            if not np.all(np.isfinite(world)):
                self.fail(f"node {index}: its transform (with its parents') is too large for numbers")
            if "mesh" in node:
                mesh_index = index_of(node["mesh"], "meshes", n_meshes, f"node {index}", self.fail)
                out.append((mesh_index, self.mesh_label(mesh_index, node), world))
            stack.extend((index_of(c, "nodes", len(nodes), f"node {index}'s children", self.fail), world,
                          (*ancestors, index)) for c in reversed(node.get("children", [])))
        return out

    def mesh_label(self, index: int, node: dict | None) -> str:
        name = self.doc["meshes"][index].get("name") or (node or {}).get("name")
        return str(name) if name else f"mesh_{index}"

    def primitive(self, spec: dict, matrix: np.ndarray, where: str,
                  notes: set[str]) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, int] | None:
        mode = int(spec.get("mode", _TRIANGLES))
        if mode not in (_TRIANGLES, _STRIP, _FAN):
            notes.add("points and lines dropped")
            return None
        attributes = spec["attributes"]
        if "POSITION" not in attributes:
            self.fail(f"{where} has no POSITION")
        positions = np.asarray(self.accessor(attributes["POSITION"], f"{where}: POSITION"), dtype=float)
        if positions.ndim != 2 or positions.shape[1] != 3:
            self.fail(f"{where}: POSITION is not a list of 3-vectors")
        if not np.all(np.isfinite(positions)):
            self.fail(f"{where}: POSITION holds numbers that are not finite")
        n = len(positions)
        order = self.indices(spec["indices"], where) if "indices" in spec else np.arange(n, dtype=np.int64)
        if order.ndim != 1 or (len(order) and (order.min() < 0 or order.max() >= n)):
            self.fail(f"{where}: an index is not one of its {n} vertices")
        triangles = _triangles(order, mode)
        if len(triangles) == 0:
            return None
        if np.linalg.slogdet(matrix[:3, :3])[0] < 0:     # a mirror turns faces inside out (slogdet: no overflow)
            triangles = triangles[:, ::-1]
        with np.errstate(all="ignore"):                  # a finite transform can still overflow: checked below
            points = positions @ matrix[:3, :3].T + matrix[:3, 3]
        if not np.all(np.isfinite(points)):
            self.fail(f"{where}: its node transform takes vertices beyond the range of numbers")
        uv = None
        if "TEXCOORD_0" in attributes:
            uv = np.asarray(self.accessor(attributes["TEXCOORD_0"], f"{where}: TEXCOORD_0"), dtype=float)
            if uv.ndim != 2 or uv.shape != (n, 2):
                self.fail(f"{where}: TEXCOORD_0 is not one (u, v) pair per vertex")
            uv = np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])     # glTF's v runs down the image; ours up
        material = self.material(spec["material"], where) if "material" in spec else -1
        return points, triangles, uv, material

    def material(self, value: object, where: str) -> int:
        index = index_of(value, "materials", len(self.doc.get("materials", [])), where, self.fail)
        if index not in self.materials:
            spec = element(self.doc, "materials", index, where, self.fail)
            name = str(spec.get("name") or f"material_{index}")
            texture = spec.get("pbrMetallicRoughness", {}).get("baseColorTexture")
            image = self.image(texture["index"], f"material {index}") if texture is not None else None
            self.materials[index] = len(self.material_list)
            self.material_list.append(MeshMaterial(name, image))
        return self.materials[index]

    def image(self, texture_index: object, where: str) -> str | None:
        """The base-colour image: a file in the document's folder (:func:`document_file`; one elsewhere is
        left out with a note), or a description of an image embedded in the document."""
        texture = element(self.doc, "textures", texture_index, where, self.fail)
        if "source" not in texture:
            return None
        image = element(self.doc, "images", texture["source"], f"texture {texture_index}", self.fail)
        uri = image.get("uri")
        if isinstance(uri, str) and uri.startswith("data:"):
            return f"embedded: {uri[5:].split(';', 1)[0].split(',', 1)[0] or 'image'}"
        if isinstance(uri, str):
            try:
                return str(document_file(self.path, uri))
            except GltfFileError as exc:
                self.notes.add(f"image left out: {exc.message}")
                return None
        view = element(self.doc, "bufferViews", image.get("bufferView"), f"image {texture['source']}", self.fail)
        index_of(view.get("buffer"), "buffers", len(self.doc.get("buffers", [])), "the image's bufferView", self.fail)
        return f"embedded: {image.get('mimeType', 'image')}, {int(view['byteLength'])} bytes"


def _local_matrix(node: dict) -> np.ndarray:
    if "matrix" in node:
        m = np.asarray(node["matrix"], dtype=float)
        if m.shape != (16,) or not np.all(np.isfinite(m)):
            raise ValueError("a node matrix must be 16 finite numbers")
        return m.reshape(4, 4).T                   # glTF stores matrices column by column
    local = np.eye(4)
    scale = np.asarray(node.get("scale", [1, 1, 1]), dtype=float).reshape(3)
    rotation = np.asarray(node.get("rotation", [0, 0, 0, 1]), dtype=float).reshape(4)
    translation = np.asarray(node.get("translation", [0, 0, 0]), dtype=float).reshape(3)
    if not (np.all(np.isfinite(scale)) and np.all(np.isfinite(rotation)) and np.all(np.isfinite(translation))):
        raise ValueError("a node transform holds a number that is not finite")
    if np.linalg.norm(rotation) == 0:
        raise ValueError("a node rotation is the zero quaternion")
    local[:3, :3] = quaternion_matrix(rotation) * scale
    local[:3, 3] = translation
    return local


def _triangles(order: np.ndarray, mode: int) -> np.ndarray:
    """Triangles (T, 3) of a primitive's index list in the given mode, same orientation throughout."""
    if mode == _TRIANGLES:
        if len(order) % 3:
            raise ValueError(f"{len(order)} triangle indices is not a multiple of 3")
        return order.reshape(-1, 3)
    k = np.arange(max(len(order) - 2, 0))
    if mode == _STRIP:
        even = k % 2 == 0
        return np.column_stack([np.where(even, order[k], order[k + 1]),
                                np.where(even, order[k + 1], order[k]), order[k + 2]]).astype(np.int64)
    return np.column_stack([np.full(len(k), order[0] if len(order) else 0), order[k + 1], order[k + 2]])
