"""Export to glTF 2.0: the rest mesh with the parameters as morph targets (blendshapes).

The file holds one mesh with one primitive per part (skin, eyes, teeth, …),
each with a material in the part's colour, vertex colours where a part is not
one colour (``COLOR_0``), smooth normals and triangles. Every morph target is
a per-vertex displacement: for a parameter, ``model.deform({name: value}) −
rest`` at one chosen value (:func:`target_value`); for a pose from a file of
displacement fields (the ARKit-52 set of the default head), the pose itself.
glTF blends targets linearly, so a rotation's target is its straight-line
(secant) linearisation through the rest pose and the pose at the chosen value:
exact at weights 0 and 1, a chord in between (docs/export.md).

With ``skeleton=True`` the rigid group-1 parameters become joints of a glTF
skin instead (:func:`skeleton_parameters`), which reproduces ``model.deform``
exactly, leaves riding on the joints as in the engine.

Units: the model is in mm, glTF in metres, so coordinates are scaled by
0.001; both use +Y up with the face toward +Z, so no axes are swapped.

:func:`read_gltf` reads the files back, checks their structure (buffer
lengths, accessor bounds, indices, morph target counts) and returns the
arrays; :func:`export_gltf` runs it on every file before writing it.

>>> from engine import load_model
>>> head = load_model()                                              # doctest: +SKIP
>>> targets = parameter_targets(head) + pose_targets(head)           # doctest: +SKIP
>>> export_gltf(head, "head.glb", targets)                           # doctest: +SKIP
>>> read_gltf("head.glb").target_names[:2]                           # doctest: +SKIP
['neck_lean', 'head_turn']
"""

from __future__ import annotations

import base64
import json
import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Mapping

import numpy as np

from .errors import UserError

METRES_PER_MM = 0.001
GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
SUFFIXES = (".glb", ".gltf")
POSES_FORMAT = "artificial-person-poses"

_FLOAT, _UBYTE, _USHORT, _UINT = 5126, 5121, 5123, 5125
_COMPONENTS = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_TRIANGLES = 4
MODEL_VERTEX = "_MODEL_VERTEX"   # application-specific attribute: each point's vertex index in the model


class GltfFileError(UserError):
    """A glTF file is malformed, or is not one this module can read."""


@dataclass
class MorphTarget:
    """One blendshape: per-vertex displacements in mm, model vertex order.

    ``source`` is ``"parameter"`` or the pose group (e.g. ``"arkit"``); for a
    parameter, ``value`` is its value at weight 1 and ``linearised`` says that
    the parameter is a rotation, so weights between 0 and 1 follow the chord,
    not the arc; ``chord_error_mm`` is how far the chord's midpoint (weight
    0.5) lies from the true pose at half the value, at most over the vertices.
    """

    name: str
    displacements: np.ndarray
    source: str = "parameter"
    value: float | None = None
    linearised: bool = False
    chord_error_mm: float = 0.0

    def metadata(self) -> dict:
        out = {"name": self.name, "source": self.source}
        if self.value is not None:
            out.update(value=self.value, linearised=self.linearised, chord_error_mm=round(self.chord_error_mm, 4))
        return out


# -- targets -------------------------------------------------------------------

def target_value(parameter) -> float:
    """The value a parameter's target shows at weight 1: 1 where 1 is in the parameter's
    range, else its maximum, else (a range that ends at the default) its minimum."""
    if parameter.minimum <= 1.0 <= parameter.maximum:
        return 1.0
    return parameter.maximum if parameter.maximum != parameter.default else parameter.minimum


def parameter_targets(model, names: Iterable[str] | None = None,
                      values: Mapping[str, float] | None = None) -> list[MorphTarget]:
    """Morph targets for the named parameters (default: all, in tree order as ``info`` shows them).

    ``values`` overrides :func:`target_value` per parameter (dimensionless,
    within the parameter's range). Each target is ``model.deform({name: v}) −
    model.deform()`` in mm, the other parameters at their defaults.
    """
    tree = model.parameters
    names = [n for n, _ in tree.depth_first()] if names is None else list(names)
    values = dict(values or {})
    for name in list(names) + list(values):
        tree[name]                                   # unknown names raise with a suggestion
    if len(set(names)) != len(names):
        raise UserError("a parameter is named twice in the selection")
    stray = sorted(set(values) - set(names))
    if stray:
        raise UserError(f"a target value is given for '{stray[0]}', which is not exported")
    model.check_values(values)
    rest = model.deform()
    targets = []
    for name in names:
        p = tree[name]
        value = float(values.get(name, target_value(p)))
        if value == p.default:
            raise UserError(f"parameter '{name}': its target value {value:g} is its default, which moves nothing")
        pose = model.deform({name: value})
        delta = pose - rest
        error = 0.0
        if p.kind == "rotation":
            middle = model.deform({name: (p.default + value) / 2})
            error = float(np.max(np.linalg.norm(middle - (rest + delta / 2), axis=1), initial=0.0))
        targets.append(MorphTarget(name, delta, "parameter", value, p.kind == "rotation", error))
    return targets


def pose_targets(model, path: str | Path | None = None, group: str = "arkit",
                 names: Iterable[str] | None = None) -> list[MorphTarget]:
    """Morph targets from a file of displacement fields (format ``artificial-person-poses``,
    ``/<group>/<name>/{indices, displacements}`` in mm; default: the shipped
    ``reference-poses.h5``, whose ``arkit`` group is the ARKit-52 set under
    ARKit's names)."""
    import h5py

    from .paths import reference_poses_path

    path = Path(path) if path is not None else reference_poses_path()
    n = model.n_vertices
    try:
        with h5py.File(path, "r") as f:
            kind, version = f.attrs.get("format"), f.attrs.get("version")
            if isinstance(kind, bytes):
                kind = kind.decode()
            if kind != POSES_FORMAT:
                raise UserError(f"not a poses file (format {kind!r}, expected '{POSES_FORMAT}')", file=path)
            if version != 1:
                raise UserError(f"poses format version {version} is not known (this program reads version 1)",
                                file=path)
            if "source_vertex" in f and len(f["source_vertex"]) != n:
                raise UserError(f"these poses were made for a model of {len(f['source_vertex'])} vertices, "
                                f"not this one of {n}", file=path)
            if group not in f or not isinstance(f[group], h5py.Group):
                known = ", ".join(k for k in f if isinstance(f[k], h5py.Group))
                raise UserError(f"no pose group '{group}' (groups: {known})", file=path)
            wanted = list(f[group]) if names is None else list(names)
            targets = []
            for name in wanted:
                if name not in f[group]:
                    raise UserError(f"no pose '{name}' in group '{group}'", file=path)
                g = f[group][name]
                idx = np.asarray(g["indices"][()], dtype=np.int64).reshape(-1)
                disp = np.asarray(g["displacements"][()], dtype=float)
                if disp.shape != (len(idx), 3) or (len(idx) and (idx.min() < 0 or idx.max() >= n)):
                    raise UserError(f"pose '{group}/{name}': indices and displacements do not fit a model "
                                    f"of {n} vertices", file=path)
                delta = np.zeros((n, 3))
                delta[idx] = disp
                targets.append(MorphTarget(name, delta, group))
    except OSError as exc:
        raise UserError(f"cannot read the poses: {exc}", file=path) from None
    except KeyError as exc:
        raise UserError(f"damaged poses file: {exc}", file=path) from None
    return targets


# -- writing ---------------------------------------------------------------------

class _Buffer:
    """The binary buffer, one bufferView per array, each aligned to 4 bytes."""

    def __init__(self):
        self.chunks, self.length, self.views, self.accessors = [], 0, [], []

    def add(self, array: np.ndarray, target: int | None, bounds: bool = True, kind: str | None = None) -> int:
        array = np.ascontiguousarray(array)
        data = array.astype(array.dtype.newbyteorder("<"), copy=False).tobytes()
        view = {"buffer": 0, "byteOffset": self.length, "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.views.append(view)
        pad = -len(data) % 4
        self.chunks.append(data + b"\0" * pad)
        self.length += len(data) + pad
        component = {np.dtype(np.float32): _FLOAT, np.dtype(np.uint8): _UBYTE, np.dtype(np.uint16): _USHORT,
                     np.dtype(np.uint32): _UINT}[array.dtype]
        accessor = {"bufferView": len(self.views) - 1, "componentType": component, "count": int(array.shape[0]),
                    "type": kind or ("SCALAR" if array.ndim == 1 else f"VEC{array.shape[1]}")}
        if bounds and len(array):
            flat = array.reshape(len(array), -1)
            # float32 values written as Python floats: the JSON numbers round-trip to the same float32
            accessor["min"] = [_number(v) for v in flat.min(axis=0)]
            accessor["max"] = [_number(v) for v in flat.max(axis=0)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def data(self) -> bytes:
        return b"".join(self.chunks)


def _number(v):
    return int(v) if isinstance(v, np.integer) else float(v)


def gltf_document(model, targets: Iterable[MorphTarget] = (), target_normals: bool = True,
                  skeleton: bool = False) -> tuple[dict, bytes]:
    """The glTF JSON document (without ``buffers[0].uri``) and its binary buffer.

    Positions and displacements are scaled from mm to metres. ``target_normals``
    adds each target's change of the smooth normals (renderers that shade
    morphs with them, e.g. three.js and Unity, then light a turned head right).
    ``skeleton`` exports the rigid group-1 parameters as joints instead (see
    :func:`skeleton_parameters`); their morph targets must then be left out.
    """
    from .render import _PartLayout, part_material

    targets = list(targets)
    names = [t.name for t in targets]
    if len(set(names)) != len(names):
        twice = sorted({n for n in names if names.count(n) > 1})
        raise UserError(f"two morph targets are both named '{twice[0]}'")
    for t in targets:
        if np.shape(t.displacements) != (model.n_vertices, 3) or not np.all(np.isfinite(t.displacements)):
            raise UserError(f"morph target '{t.name}': expected {model.n_vertices}×3 finite displacements")
    rig = _Rig(model) if skeleton else None
    for t in targets:
        if rig is not None and t.source == "parameter" and t.name in rig.names:
            raise UserError(f"parameter '{t.name}' is a joint of the skeleton, so it cannot also be a morph target")
    layout = _PartLayout(model)
    if not layout.parts:
        raise UserError("the model has no polygons to export")
    rest = model.deform()
    points, normals = layout.points_and_normals(rest)
    points = points.copy()                  # the layout hands out one buffer, refilled on every call
    moved = [layout.points_and_normals(rest + t.displacements)[1] for t in targets] if target_normals else []
    buf = _Buffer()
    primitives, materials = [], []
    for k, part in enumerate(layout.parts):
        start, stop = layout.slices[k]
        used = layout.used(k)
        colour, _, _, _, power = part_material(part, model.part_colors)
        rgb = None if model.vertex_colors is None else model.vertex_colors[used]
        if rgb is not None and np.all(rgb == rgb[0]):
            colour, rgb = "#%02x%02x%02x" % tuple(int(c) for c in rgb[0]), None
        base = [1.0, 1.0, 1.0] if rgb is not None else _srgb_to_linear(_hex_rgb(colour)).tolist()
        materials.append({"name": part, "doubleSided": True,
                          "pbrMetallicRoughness": {"baseColorFactor": [round(c, 6) for c in base] + [1.0],
                                                   "metallicFactor": 0.0,
                                                   "roughnessFactor": round(float(np.sqrt(2 / (power + 2))), 4)}})
        attributes = {"POSITION": buf.add((points[start:stop] * METRES_PER_MM).astype(np.float32), _ARRAY_BUFFER),
                      "NORMAL": buf.add(normals[start:stop].astype(np.float32), _ARRAY_BUFFER)}
        if rgb is not None:
            attributes["COLOR_0"] = buf.add(_srgb_to_linear(rgb / 255.0).astype(np.float32), _ARRAY_BUFFER)
        attributes[MODEL_VERTEX] = buf.add(used.astype(np.float32), _ARRAY_BUFFER)
        if rig is not None:
            attributes["JOINTS_0"] = buf.add(rig.joints[used], _ARRAY_BUFFER, bounds=False)
            attributes["WEIGHTS_0"] = buf.add(rig.weights[used], _ARRAY_BUFFER, bounds=False)
        triangles = np.asarray(_triangles(layout, k), dtype=np.uint16 if stop - start < 65535 else np.uint32)
        primitive = {"attributes": attributes, "indices": buf.add(triangles.reshape(-1), _ELEMENT_ARRAY_BUFFER,
                                                                  bounds=False),
                     "material": k, "mode": _TRIANGLES, "extras": {"part": part}}
        if targets:
            zero = None
            primitive["targets"] = []
            for i, t in enumerate(targets):
                entry = {}
                arrays = {"POSITION": (t.displacements[used] * METRES_PER_MM).astype(np.float32)}
                if target_normals:
                    arrays["NORMAL"] = (moved[i][start:stop] - normals[start:stop]).astype(np.float32)
                for key, array in arrays.items():
                    if not array.any():       # parts a target leaves alone share one accessor of zeros
                        if zero is None:
                            zero = buf.add(np.zeros((stop - start, 3), dtype=np.float32), _ARRAY_BUFFER)
                        entry[key] = zero
                    else:
                        entry[key] = buf.add(array, _ARRAY_BUFFER)
                primitive["targets"].append(entry)
        primitives.append(primitive)
    mesh = {"name": model.name, "primitives": primitives}
    if targets:
        mesh["weights"] = [0.0] * len(targets)
        mesh["extras"] = {"targetNames": names, "targets": [t.metadata() for t in targets]}
    from . import __version__

    nodes, roots = [{"name": model.name, "mesh": 0}], [0]
    skins = []
    if rig is not None:
        nodes[0]["skin"] = 0
        roots.append(len(nodes))
        skins.append(rig.skin(nodes, buf))
    data = buf.data()
    document = {
        "asset": {"version": "2.0", "generator": f"Artificial Person {__version__}",
                  "extras": {"model": model.name, "description": model.description, "units": "metres"}},
        "scene": 0, "scenes": [{"name": model.name, "nodes": roots}],
        "nodes": nodes, "meshes": [mesh], "materials": materials,
        "accessors": buf.accessors, "bufferViews": buf.views, "buffers": [{"byteLength": len(data)}],
    }
    if skins:
        document["skins"] = skins
    return document, data


def skeleton_parameters(model) -> list[str]:
    """The parameters a skeleton exports as joints: the rigid group-1 (non-leaf) ones, in tree order."""
    tree = model.parameters
    return [name for name, _ in tree.depth_first() if tree.group(name) == 1]


class _Rig:
    """Group-1 parameters as glTF joints: a ``root`` joint (vertices no rigid parameter carries),
    then one joint per parameter, nested as the parameter tree.

    A joint rests at its pivot (translations: at the origin) with its local +X
    along the rotation axis (translation direction), so a parameter value is a
    turn about, or a slide along, the joint's own X. Each joint's skinning
    matrix ``G · G_rest⁻¹`` is then the engine's propagated ``T'`` (column
    convention ``T'_c = T'_parent · T_c``), and the skin weights are the
    engine's normalised group-1 weights (at most four per vertex: more are cut
    to the four largest and renormalised).
    """

    def __init__(self, model):
        tree = model.parameters
        self.names = skeleton_parameters(model)
        for name in self.names:
            if tree[name].default != 0:
                raise UserError(f"parameter '{name}' rests at {tree[name].default:g}: a skeleton needs "
                                "its rigid parameters to rest at 0")
        n = model.n_vertices
        w = np.stack([model.regions[name].dense(n) for name in self.names], axis=1) if self.names \
            else np.zeros((n, 0))
        total = w.sum(axis=1)
        w = np.hstack([(total == 0)[:, None].astype(float), np.divide(w, total[:, None], out=np.zeros_like(w),
                                                                       where=total[:, None] > 0)])
        order = np.argsort(-w, axis=1, kind="stable")[:, :4]
        top = np.take_along_axis(w, order, axis=1)
        if top.shape[1] < 4:
            order = np.hstack([order, np.zeros((n, 4 - top.shape[1]), dtype=order.dtype)])
            top = np.hstack([top, np.zeros((n, 4 - top.shape[1]))])
        top /= top.sum(axis=1, keepdims=True)
        order[top == 0] = 0
        dtype = np.uint8 if len(self.names) < 255 else np.uint16
        self.joints, self.weights = order.astype(dtype), top.astype(np.float32)
        self.frames = {name: _joint_frame(tree[name]) for name in self.names}
        self.tree = tree

    def skin(self, nodes: list[dict], buf: _Buffer) -> dict:
        """Append the joint nodes to ``nodes``; return the skin."""
        first = len(nodes)
        index = {name: first + 1 + i for i, name in enumerate(self.names)}
        nodes.append({"name": "root", "children": []})
        ibm = [np.eye(4)]
        for name in self.names:
            p = self.tree[name]
            rotation, origin = self.frames[name]
            parent_rotation, parent_origin = self.frames.get(p.parent, (np.eye(3), np.zeros(3)))
            local = parent_rotation.T @ rotation
            node = {"name": name, "translation": (parent_rotation.T @ (origin - parent_origin)).tolist(),
                    "rotation": _quaternion(local).tolist(),
                    "extras": {"parameter": name, "minimum": p.minimum, "maximum": p.maximum}}
            if p.kind == "rotation":
                node["extras"].update(motion="rotation about the joint's +X", degrees_per_unit=p.degrees_per_unit)
            else:
                node["extras"].update(motion="translation along the joint's +X",
                                      mm_per_unit=float(np.linalg.norm(p.direction)))
            nodes[index.get(p.parent, first)].setdefault("children", []).append(len(nodes))
            nodes.append(node)
            inverse = np.eye(4)
            inverse[:3, :3], inverse[:3, 3] = rotation.T, -rotation.T @ origin
            ibm.append(inverse)
        matrices = np.stack([m.T.reshape(16) for m in ibm]).astype(np.float32)   # glTF matrices are column-major
        return {"name": "parameters", "skeleton": first, "joints": list(range(first, len(nodes))),
                "inverseBindMatrices": buf.add(matrices, None, bounds=False, kind="MAT4")}


def _joint_frame(p) -> tuple[np.ndarray, np.ndarray]:
    """Rest orientation (local +X along the axis or direction) and origin (the pivot, metres) of a joint."""
    if p.kind == "rotation":
        return _rotation_from_x(p.axis), p.pivot * METRES_PER_MM
    length = np.linalg.norm(p.direction)
    return _rotation_from_x(p.direction / length if length else np.array([1.0, 0, 0])), np.zeros(3)


def _rotation_from_x(a: np.ndarray) -> np.ndarray:
    """The smallest rotation taking +X to the unit vector ``a`` (Rodrigues)."""
    x = np.array([1.0, 0.0, 0.0])
    v, c = np.cross(x, a), float(x @ a)
    s2 = float(v @ v)
    if s2 < 1e-24:
        return np.eye(3) if c > 0 else np.diag([-1.0, 1.0, -1.0])
    k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + k + k @ k * ((1 - c) / s2)


def _quaternion(r: np.ndarray) -> np.ndarray:
    """Unit quaternion (x, y, z, w), glTF's order, of a rotation matrix (from its largest component)."""
    t = np.trace(r)
    options = [1 + t, 1 + r[0, 0] - r[1, 1] - r[2, 2], 1 - r[0, 0] + r[1, 1] - r[2, 2], 1 - r[0, 0] - r[1, 1] + r[2, 2]]
    k = int(np.argmax(options))
    s = 2 * np.sqrt(options[k])
    if k == 0:
        q = [(r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s, s / 4]
    elif k == 1:
        q = [s / 4, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s, (r[2, 1] - r[1, 2]) / s]
    elif k == 2:
        q = [(r[0, 1] + r[1, 0]) / s, s / 4, (r[1, 2] + r[2, 1]) / s, (r[0, 2] - r[2, 0]) / s]
    else:
        q = [(r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, s / 4, (r[1, 0] - r[0, 1]) / s]
    q = np.array(q)
    return q / np.linalg.norm(q)


def _matrix(q) -> np.ndarray:
    """Rotation matrix of a unit quaternion (x, y, z, w)."""
    x, y, z, w = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _triangles(layout, k: int) -> np.ndarray:
    from .cells import cells_to_triangles

    return cells_to_triangles(layout.cells[k])


def _hex_rgb(colour: str) -> np.ndarray:
    return np.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255.0


def _srgb_to_linear(c) -> np.ndarray:
    """sRGB in [0, 1] → linear light, as glTF's colour factors and COLOR_0 are."""
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def glb_bytes(document: dict, data: bytes) -> bytes:
    """The binary container: a 12-byte header, the JSON chunk (padded with spaces), the BIN chunk."""
    text = json.dumps(document, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return (struct.pack("<III", GLB_MAGIC, 2, total) + struct.pack("<II", len(text), GLB_JSON) + text
            + struct.pack("<II", len(data), GLB_BIN) + data)


def export_gltf(model, path: str | Path, targets: Iterable[MorphTarget] = (),
                target_normals: bool = True, skeleton: bool = False) -> "GltfMesh":
    """Write ``model`` with ``targets`` as ``path`` (``.glb``, or ``.gltf`` with a ``.bin`` beside it).

    The file is read back with :func:`read_gltf` before it is written (both
    atomically), so a file on disk has passed those checks; returns what was read.
    """
    from .files import atomic_write_bytes

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise UserError(f"unknown glTF extension '{path.suffix or path.name}' (use .glb or .gltf)", file=path)
    document, data = gltf_document(model, targets, target_normals=target_normals, skeleton=skeleton)
    if suffix == ".glb":
        blob = glb_bytes(document, data)
        mesh = _parse(path, *_split_glb(blob, path))
        atomic_write_bytes(path, blob)
        return mesh
    bin_path = path.with_suffix(".bin")
    document["buffers"][0]["uri"] = bin_path.name
    text = json.dumps(document, indent=1).encode("utf-8")
    mesh = _parse(path, json.loads(text), {0: data})
    atomic_write_bytes(bin_path, data)
    atomic_write_bytes(path, text)
    return mesh


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
    skin: "GltfSkin | None" = None

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
            P = p.positions.astype(np.float64)
            for weight, target in zip(w, p.targets):
                if weight:
                    P = P + weight * target["POSITION"]
            if skinning is not None:
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


def _split_glb(blob: bytes, path: Path) -> tuple[dict, dict[int, bytes]]:
    def fail(what):
        raise GltfFileError(f"not a valid binary glTF: {what}", file=path)

    if len(blob) < 20:
        fail("shorter than its header")
    magic, version, length = struct.unpack_from("<III", blob)
    if magic != GLB_MAGIC or version != 2:
        fail(f"magic {magic:#x}, container version {version} (expected glTF, 2)")
    if length != len(blob):
        fail(f"the header says {length} bytes, the file has {len(blob)}")
    chunks, offset = [], 12
    while offset < length:
        if offset + 8 > length:
            fail("a chunk header runs past the end")
        size, kind = struct.unpack_from("<II", blob, offset)
        if size % 4 or offset + 8 + size > length:
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
    def fail(what):
        raise GltfFileError(what, file=path)

    try:
        return _Reader(path, document, embedded, fail).mesh()
    except (KeyError, IndexError, TypeError, ValueError, AttributeError) as exc:
        fail(f"malformed glTF document: {type(exc).__name__}: {exc}")


class _Reader:
    def __init__(self, path, document, embedded, fail):
        self.path, self.doc, self.fail = path, document, fail
        if not isinstance(document, dict) or str(document.get("asset", {}).get("version")) != "2.0":
            fail("not a glTF 2.0 document (asset.version must be \"2.0\")")
        self.buffers = [self._buffer(i, b, embedded) for i, b in enumerate(document.get("buffers", []))]
        self.cache: dict[int, np.ndarray] = {}

    def _buffer(self, i: int, spec: dict, embedded: dict[int, bytes]) -> bytes:
        """Buffer ``i``: the GLB's binary chunk, data handed in (a file being checked before it is
        written), a data: URI or a file beside the document."""
        uri, length = spec.get("uri"), int(spec["byteLength"])
        if i in embedded:
            data, slack = embedded[i], 3 if uri is None else 0     # the BIN chunk is padded to 4 bytes
        elif uri is None:
            self.fail(f"buffer {i} has no uri and there is no binary chunk")
        elif uri.startswith("data:"):
            data, slack = base64.b64decode(uri.partition(",")[2]), 0
        else:
            try:
                data, slack = (self.path.parent / uri).read_bytes(), 0
            except OSError as exc:
                self.fail(f"buffer {i}: cannot read '{uri}': {exc.strerror or exc}")
        if not length <= len(data) <= length + slack:
            self.fail(f"buffer {i}: byteLength {length} but its data hold {len(data)} bytes")
        return data[:length]

    def accessor(self, index: int) -> np.ndarray:
        if index in self.cache:
            return self.cache[index]
        a = self.doc["accessors"][index]
        where = f"accessor {index}"
        if "sparse" in a or "bufferView" not in a:
            self.fail(f"{where}: sparse or buffer-less accessors are not supported")
        dtype = np.dtype(_COMPONENTS[a["componentType"]]).newbyteorder("<")
        width, count = _WIDTHS[a["type"]], int(a["count"])
        view = self.doc["bufferViews"][a["bufferView"]]
        buffer = self.buffers[view["buffer"]]
        start, length = int(view.get("byteOffset", 0)), int(view["byteLength"])
        if start + length > len(buffer):
            self.fail(f"bufferView {a['bufferView']} runs past the end of buffer {view['buffer']}")
        item = dtype.itemsize * width
        stride = int(view.get("byteStride", item))
        offset = int(a.get("byteOffset", 0))
        if count < 1 or offset % dtype.itemsize or stride < item:
            self.fail(f"{where}: bad count, offset or stride")
        if offset + stride * (count - 1) + item > length:
            self.fail(f"{where}: {count} elements do not fit in bufferView {a['bufferView']} ({length} bytes)")
        raw = np.frombuffer(buffer, dtype=np.uint8, count=stride * (count - 1) + item, offset=start + offset)
        rows = np.lib.stride_tricks.as_strided(raw, shape=(count, item), strides=(stride, 1))
        array = np.ascontiguousarray(rows).view(dtype).reshape(count, width).astype(dtype.newbyteorder("="))
        for key, reduce in (("min", np.min), ("max", np.max)):
            if key in a:
                bound = np.asarray(a[key], dtype=float)
                # other writers may print bounds in decimal: allow float32 rounding, no more
                if bound.shape != (width,) or not np.allclose(reduce(array, axis=0), bound, rtol=1e-6, atol=0):
                    self.fail(f"{where}: {key} {a[key]} does not match its data")
        array = array[:, 0] if width == 1 else array
        self.cache[index] = array
        return array

    def mesh(self) -> GltfMesh:
        doc = self.doc
        meshes = doc.get("meshes", [])
        if not meshes:
            self.fail("the file holds no mesh")
        for node in doc.get("nodes", []):
            if "mesh" in node and not 0 <= node["mesh"] < len(meshes):
                self.fail(f"node '{node.get('name', '')}' names mesh {node['mesh']}, which does not exist")
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
        skin = doc["skins"][holder[0]["skin"]]
        joints = list(skin["joints"])
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
            local[:3, :3] = _matrix(node.get("rotation", [0, 0, 0, 1]))
            local[:3, 3] = node.get("translation", [0, 0, 0])
            rest.append(local)
        for p in prims:
            if p.joints is None or p.weights is None:
                self.fail(f"primitive '{p.name}' of a skinned mesh has no JOINTS_0 and WEIGHTS_0")
            if p.joints.max(initial=0) >= len(joints):
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
            flat = self.accessor(spec["indices"]).astype(np.int64)
        else:
            flat = np.arange(n)
        if len(flat) % 3 or (len(flat) and flat.max() >= n):
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
        material = self.doc["materials"][spec["material"]] if "material" in spec else {}
        vertex = arrays.get(MODEL_VERTEX)
        joints = arrays.get("JOINTS_0")
        return GltfPrimitive(name, positions, flat.reshape(-1, 3), arrays.get("NORMAL"), arrays.get("COLOR_0"),
                             None if vertex is None else vertex.astype(np.int64), targets, material,
                             None if joints is None else joints.astype(np.int64), arrays.get("WEIGHTS_0"))
