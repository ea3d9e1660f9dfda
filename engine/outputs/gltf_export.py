"""Export to glTF 2.0: the rest mesh with the parameters as morph targets (blendshapes).

The file holds one mesh with one primitive per part (skin, eyes, teeth, …),
each with a material in the part's colour, vertex colours where a part is not
one colour (``COLOR_0``), smooth normals and triangles. A textured part is one
primitive per image it shows, with ``TEXCOORD_0`` and a material whose
``baseColorTexture`` is the image, embedded as PNG in the binary buffer. Every morph target is
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

:func:`engine.formats.gltf_read.read_gltf` reads the files back and checks their
structure; :func:`export_gltf` runs it on every file before writing it.

>>> from engine import load_model
>>> head = load_model()                                              # doctest: +SKIP
>>> targets = parameter_targets(head) + pose_targets(head)           # doctest: +SKIP
>>> export_gltf(head, "head.glb", targets)                           # doctest: +SKIP
>>> read_gltf("head.glb").target_names[:2]                           # doctest: +SKIP
['neck_lean', 'head_turn']

``artificial-person export-gltf`` and the workbench's File → Export → glTF…
choose their targets with one function, :func:`export_targets`, and report
what was written with :func:`export_summary`.
"""

from __future__ import annotations

import json
import math
import struct
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from engine.errors import UserError
from engine.formats.gltf_document import GLB_BIN, GLB_JSON, GLB_MAGIC, split_glb
from engine.formats.gltf_read import (
    _TRIANGLES,
    METRES_PER_MM,
    MODEL_VERTEX,
    GltfFileError,
    GltfMesh,
    _parse,
    read_gltf,
)
from engine.outputs.gltf_buffer import GltfBuffer
from engine.outputs.gltf_skeleton import SkeletonRig, skeleton_parameters

if TYPE_CHECKING:
    from engine.model import Model, Parameter
    from engine.outputs.part_layout import PartLayout

__all__ = ["GltfFileError", "MorphTarget", "export_gltf", "export_summary", "export_targets", "glb_bytes",
           "gltf_document", "is_shipped_head", "parameter_targets", "pose_group_names", "pose_targets", "read_gltf",
           "skeleton_parameters", "target_value"]

SUFFIXES = (".glb", ".gltf")
POSES_FORMAT = "artificial-person-poses"

_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963


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
        out: dict[str, object] = {"name": self.name, "source": self.source}
        if self.value is not None:
            out.update(value=self.value, linearised=self.linearised, chord_error_mm=round(self.chord_error_mm, 4))
        return out


# -- targets -------------------------------------------------------------------

def target_value(parameter: Parameter) -> float:
    """The value a parameter's target shows at weight 1: 1 where 1 is in the parameter's
    range, else its maximum, else (a range that ends at the default) its minimum."""
    if parameter.minimum <= 1.0 <= parameter.maximum:
        return 1.0
    return parameter.maximum if parameter.maximum != parameter.default else parameter.minimum


def parameter_targets(model: Model, names: Iterable[str] | None = None,
                      values: Mapping[str, float] | None = None) -> list[MorphTarget]:
    """Morph targets for the named parameters (default: all, in tree order as ``info`` shows them).

    ``values`` overrides :func:`target_value` per parameter (dimensionless,
    within the parameter's range). Each target is ``model.deform({name: v}) −
    model.deform()`` in mm, the other parameters at their defaults.
    """
    tree = model.parameters
    selected = [n for n, _ in tree.depth_first()] if names is None else list(names)
    values = dict(values or {})
    for name in selected + list(values):
        tree[name]                                   # unknown names raise with a suggestion
    if len(set(selected)) != len(selected):
        raise UserError("a parameter is named twice in the selection")
    stray = sorted(set(values) - set(selected))
    if stray:
        raise UserError(f"a target value is given for '{stray[0]}', which is not exported")
    model.check_values(values)
    rest = model.deform()
    targets = []
    for name in selected:
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


def pose_targets(model: Model, path: str | Path | None = None, group: str = "arkit",
                 names: Iterable[str] | None = None) -> list[MorphTarget]:
    """Morph targets from a file of displacement fields (format ``artificial-person-poses``,
    ``/<group>/<name>/{indices, displacements}`` in mm; default: the shipped
    ``reference-poses.h5``, whose ``arkit`` group is the ARKit-52 set under
    ARKit's names)."""
    import h5py

    from engine.paths import reference_poses_path

    path = Path(path) if path is not None else reference_poses_path()
    n = model.n_vertices
    try:
        with h5py.File(path, "r") as f:
            _check_poses_format(f, path)
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


def pose_group_names(path: str | Path | None = None) -> list[str]:
    """The pose groups of a poses file (default: the shipped ``reference-poses.h5``), in file order."""
    import h5py

    from engine.paths import reference_poses_path

    path = Path(path) if path is not None else reference_poses_path()
    try:
        with h5py.File(path, "r") as f:
            _check_poses_format(f, path)
            return [name for name in f if isinstance(f[name], h5py.Group)]
    except OSError as exc:
        raise UserError(f"cannot read the poses: {exc}", file=path) from None


def _check_poses_format(f: Any, path: Path) -> None:
    kind, version = f.attrs.get("format"), f.attrs.get("version")
    if isinstance(kind, bytes):
        kind = kind.decode()
    if kind != POSES_FORMAT:
        raise UserError(f"not a poses file (format {kind!r}, expected '{POSES_FORMAT}')", file=path)
    if version != 1:
        raise UserError(f"poses format version {version} is not known (this program reads version 1)", file=path)


def is_shipped_head(model_file: str | Path | None) -> bool:
    """Whether ``model_file`` is the shipped default head's description, the model the shipped
    poses (``reference-poses.h5``, the ARKit-52 set among them) were made for."""
    from engine.paths import default_model_path

    return model_file is not None and Path(model_file).resolve() == default_model_path().resolve()


def export_targets(model: Model, names: Iterable[str] | None = None, values: Mapping[str, float] | None = None,
                   arkit: bool | None = None, poses: str | Path | None = None, pose_groups: Iterable[str] = (),
                   skeleton: bool = False, *, model_file: str | Path | None = None) -> list[MorphTarget]:
    """The morph targets of one export, as ``artificial-person export-gltf`` and the workbench's
    File → Export → glTF… choose them (one decision, two faces).

    ``names``: the parameters exported as targets (default: all in tree
    order; with ``skeleton``, all but the joints, :func:`skeleton_parameters`,
    which ``export_gltf(..., skeleton=True)`` exports as a skin instead).
    ``values``: a parameter's value at weight 1 (see :func:`parameter_targets`).
    ``arkit``: add the ARKit-52 targets, group ``arkit`` of the poses file
    (default: for the shipped head only). ``poses``: the file of displacement
    fields (default: the shipped ``reference-poses.h5``, which fits the
    shipped head only). ``pose_groups``: more groups of that file, each
    exported whole. ``model_file``: the file ``model`` was loaded from
    (``None``: none), which says whether it is the shipped head.

    The choices are checked before any target is computed; a bad one raises
    :class:`engine.errors.UserError` with a one-line message.

    >>> from engine import load_model                                 # doctest: +SKIP
    >>> from engine.paths import default_model_path                   # doctest: +SKIP
    >>> targets = export_targets(load_model(), skeleton=True, model_file=default_model_path())  # doctest: +SKIP
    >>> targets[0].source, targets[-1].source                          # doctest: +SKIP
    ('parameter', 'arkit')
    """
    shipped = is_shipped_head(model_file)
    groups = list(pose_groups)
    if (shipped if arkit is None else arkit) and "arkit" not in groups:
        groups.insert(0, "arkit")
    if groups and poses is None and not shipped:
        raise UserError("the shipped poses fit the shipped head only: give a poses file made for this model "
                        "(--poses POSES.h5)")
    joints = skeleton_parameters(model) if skeleton else []
    if names is None:
        names = [name for name, _ in model.parameters.depth_first() if name not in joints]
    else:
        names = list(names)
        for name in names:
            if name in joints:
                raise joint_target_error(name)
    targets = parameter_targets(model, names, values)
    for group in groups:
        targets += pose_targets(model, poses, group)
    return targets


def joint_target_error(name: str) -> UserError:
    """The error for a parameter asked to be both a joint of the skeleton and a morph target."""
    return UserError(f"parameter '{name}' is a joint of the skeleton, so it cannot also be a morph target")


def export_summary(path: str | Path, mesh: GltfMesh) -> str:
    """What an export wrote, in one line: parts, vertices, morph targets, joints, size on disk
    (a ``.gltf`` with its ``.bin``), e.g. ``8 parts, 5960 vertices, 69 morph targets, 7.5 MB``."""
    path = Path(path)
    size = path.stat().st_size
    if path.suffix.lower() == ".gltf":
        size += path.with_suffix(".bin").stat().st_size
    megabytes = f"{size / 1e6:.1f} MB" if size >= 1e5 else f"{math.ceil(size / 1e3)} kB"
    joints = f", {len(mesh.skin.names)} joints" if mesh.skin is not None else ""
    return (f"{len(mesh.primitives)} parts, {mesh.n_points} vertices, {len(mesh.target_names)} morph targets"
            f"{joints}, {megabytes}")


# -- writing ---------------------------------------------------------------------

def gltf_document(model: Model, targets: Iterable[MorphTarget] = (), target_normals: bool = True,
                  skeleton: bool = False) -> tuple[dict, bytes]:
    """The glTF JSON document (without ``buffers[0].uri``) and its binary buffer.

    Positions and displacements are scaled from mm to metres. ``target_normals``
    adds each target's change of the smooth normals (renderers that shade
    morphs with them, e.g. three.js and Unity, then light a turned head right).
    ``skeleton`` exports the rigid group-1 parameters as joints instead (see
    :func:`skeleton_parameters`); their morph targets must then be left out.
    """
    from engine.outputs.part_layout import PartLayout
    from engine.outputs.part_materials import part_material

    targets = list(targets)
    names = [t.name for t in targets]
    if len(set(names)) != len(names):
        twice = sorted({n for n in names if names.count(n) > 1})
        raise UserError(f"two morph targets are both named '{twice[0]}'")
    for t in targets:
        if np.shape(t.displacements) != (model.n_vertices, 3) or not np.all(np.isfinite(t.displacements)):
            raise UserError(f"morph target '{t.name}': expected {model.n_vertices}×3 finite displacements")
    rig = SkeletonRig(model) if skeleton else None
    for t in targets:
        if rig is not None and t.source == "parameter" and t.name in rig.names:
            raise joint_target_error(t.name)
    layout = PartLayout(model)
    if not layout.parts:
        raise UserError("the model has no polygons to export")
    rest = model.deform()
    points, normals = layout.points_and_normals(rest)
    points = points.copy()                  # the layout hands out one buffer, refilled on every call
    moved = [layout.points_and_normals(rest + t.displacements)[1] for t in targets] if target_normals else []
    buf = GltfBuffer()
    primitives: list[dict[str, object]] = []
    materials: list[dict[str, object]] = []
    embedded_images = _embedded_images(model, layout, buf)
    for k, part in enumerate(layout.parts):
        start, stop = layout.slices[k]
        used = layout.used(k)
        colour, _, _, _, power = part_material(part, model.part_colors)
        rgb = None if model.vertex_colors is None else model.vertex_colors[used]
        if rgb is not None and np.all(rgb == rgb[0]):
            red, green, blue = (int(c) for c in rgb[0])
            colour, rgb = f"#{red:02x}{green:02x}{blue:02x}", None
        uv, image = layout.uv[k], layout.image[k]
        if uv is not None:
            rgb = None
        base = [1.0, 1.0, 1.0] if rgb is not None or uv is not None else _srgb_to_linear(_hex_rgb(colour)).tolist()
        pbr: dict[str, object] = {"baseColorFactor": [round(c, 6) for c in base] + [1.0], "metallicFactor": 0.0,
                                  "roughnessFactor": round(float(np.sqrt(2 / (power + 2))), 4)}
        if uv is not None:
            pbr["baseColorTexture"] = {"index": embedded_images[image][0], "texCoord": 0}
        material_name = part if uv is None or model.texture is None else f"{part}.{model.texture.images[image].name}"
        materials.append({"name": material_name, "doubleSided": True, "pbrMetallicRoughness": pbr})
        attributes = {"POSITION": buf.add((points[start:stop] * METRES_PER_MM).astype(np.float32), _ARRAY_BUFFER),
                      "NORMAL": buf.add(normals[start:stop].astype(np.float32), _ARRAY_BUFFER)}
        if rgb is not None:
            attributes["COLOR_0"] = buf.add(_srgb_to_linear(rgb / 255.0).astype(np.float32), _ARRAY_BUFFER)
        if uv is not None:          # glTF's v runs down from the image's top; ours up from its bottom
            flipped = np.column_stack([uv[:, 0], 1.0 - uv[:, 1]]).astype(np.float32)
            attributes["TEXCOORD_0"] = buf.add(flipped, _ARRAY_BUFFER, bounds=False)
        attributes[MODEL_VERTEX] = buf.add(used.astype(np.float32), _ARRAY_BUFFER)
        if rig is not None:
            attributes["JOINTS_0"] = buf.add(rig.joints[used], _ARRAY_BUFFER, bounds=False)
            attributes["WEIGHTS_0"] = buf.add(rig.weights[used], _ARRAY_BUFFER, bounds=False)
        triangles = np.asarray(_triangles(layout, k), dtype=np.uint16 if stop - start < 65535 else np.uint32)
        indices = buf.add(triangles.reshape(-1), _ELEMENT_ARRAY_BUFFER, bounds=False)
        primitive: dict[str, object] = {"attributes": attributes, "indices": indices,
                                        "material": k, "mode": _TRIANGLES, "extras": {"part": part}}
        if targets:
            zero: int | None = None
            entries: list[dict[str, int]] = []
            primitive["targets"] = entries
            for i, t in enumerate(targets):
                entry: dict[str, int] = {}
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
                entries.append(entry)
        primitives.append(primitive)
    mesh: dict[str, object] = {"name": model.name, "primitives": primitives}
    if targets:
        mesh["weights"] = [0.0] * len(targets)
        mesh["extras"] = {"targetNames": names, "targets": [t.metadata() for t in targets]}
    from engine import __version__

    nodes: list[dict[str, Any]] = [{"name": model.name, "mesh": 0}]
    roots = [0]
    skins = []
    if rig is not None:
        nodes[0]["skin"] = 0
        roots.append(len(nodes))
        skins.append(rig.skin(nodes, buf))
    data = buf.data()
    document: dict[str, object] = {
        "asset": {"version": "2.0", "generator": f"Artificial Person {__version__}",
                  "extras": {"model": model.name, "description": model.description, "units": "metres"}},
        "scene": 0, "scenes": [{"name": model.name, "nodes": roots}],
        "nodes": nodes, "meshes": [mesh], "materials": materials,
        "accessors": buf.accessors, "bufferViews": buf.views, "buffers": [{"byteLength": len(data)}],
    }
    if skins:
        document["skins"] = skins
    if embedded_images and model.texture is not None:
        # one glTF image and texture per model image shown, in the order of first use
        document["samplers"] = [{"magFilter": _LINEAR, "minFilter": _LINEAR_MIPMAP_LINEAR,
                                 "wrapS": _REPEAT, "wrapT": _REPEAT}]
        document["images"] = [{"name": model.texture.images[i].name, "mimeType": "image/png", "bufferView": view}
                              for i, (_, view) in embedded_images.items()]
        document["textures"] = [{"sampler": 0, "source": texture} for texture, _ in embedded_images.values()]
    return document, data


_LINEAR, _LINEAR_MIPMAP_LINEAR, _REPEAT = 9729, 9987, 10497


def _embedded_images(model: Model, layout: PartLayout, buf: GltfBuffer) -> dict[int, tuple[int, int]]:
    """Model image index → (glTF texture index, bufferView of its PNG) for every image a mesh shows,
    the PNGs added to ``buf``."""
    from engine.formats.texture_images import png_bytes

    shown: dict[int, tuple[int, int]] = {}
    if model.texture is None:
        return shown
    for k, uv in enumerate(layout.uv):
        image = layout.image[k]
        if uv is not None and image not in shown:
            shown[image] = (len(shown), buf.add_bytes(png_bytes(model.texture.images[image].pixels)))
    return shown


def _triangles(layout: PartLayout, k: int) -> np.ndarray:
    from engine.model.cells import cells_to_triangles

    return cells_to_triangles(layout.cells[k])


def _hex_rgb(colour: str) -> np.ndarray:
    return np.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255.0


def _srgb_to_linear(c: ArrayLike) -> np.ndarray:
    """sRGB in [0, 1] → linear light, as glTF's colour factors and COLOR_0 are."""
    srgb = np.asarray(c, dtype=float)
    return np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4)


def glb_bytes(document: dict, data: bytes) -> bytes:
    """The binary container: a 12-byte header, the JSON chunk (padded with spaces), the BIN chunk."""
    text = json.dumps(document, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return (struct.pack("<III", GLB_MAGIC, 2, total) + struct.pack("<II", len(text), GLB_JSON) + text
            + struct.pack("<II", len(data), GLB_BIN) + data)


def export_gltf(model: Model, path: str | Path, targets: Iterable[MorphTarget] = (),
                target_normals: bool = True, skeleton: bool = False) -> GltfMesh:
    """Write ``model`` with ``targets`` as ``path`` (``.glb``, or ``.gltf`` with a ``.bin`` beside it).

    The file is read back with :func:`read_gltf` before it is written (a
    ``.gltf`` and its ``.bin`` together, atomically), so a file on disk has
    passed those checks; returns what was read.
    """
    from engine.formats.atomic import atomic_files, atomic_write_bytes

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise UserError(f"unknown glTF extension '{path.suffix or path.name}' (use .glb or .gltf)", file=path)
    document, data = gltf_document(model, targets, target_normals=target_normals, skeleton=skeleton)
    if suffix == ".glb":
        blob = glb_bytes(document, data)
        mesh = _parse(path, *split_glb(blob, path))
        atomic_write_bytes(path, blob)
        return mesh
    bin_path = path.with_suffix(".bin")
    document["buffers"][0]["uri"] = bin_path.name
    text = json.dumps(document, indent=1).encode("utf-8")
    mesh = _parse(path, json.loads(text), {0: data})
    with atomic_files([bin_path, path]) as temporary:
        temporary[bin_path].write_bytes(data)
        temporary[path].write_bytes(text)
    return mesh
