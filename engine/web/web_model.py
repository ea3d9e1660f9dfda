"""The head of a web site as a small binary glTF: a skeleton for the rigid parameters, and only the
morph targets an animation moves, stored sparse and quantised.

:func:`engine.outputs.gltf_export.gltf_document` writes every morph target as a dense float32
array of every vertex (12 bytes per vertex, and as much again for its normals): the default
head's 52 parameters would be some 30 MB. A web page needs far less:

* the rigid group-1 parameters (head, jaw, eyes) are joints of a skin (``skeleton=True``), exact
  at every value and a few bytes each;
* only the leaves the animation moves become morph targets, each at the value farthest from the
  default that the animation reaches (so a target is exact at its peak);
* each target keeps only the vertices it moves (a glTF *sparse* accessor), their displacements
  as normalised 16-bit integers (``KHR_mesh_quantization``: 1/32767 m, 0.03 mm per step), the
  normals' changes as normalised 16-bit integers too (clipped to ±1);
* the rest mesh's normals are normalised bytes (``KHR_mesh_quantization``), its vertex colours
  normalised 16-bit integers and its skin weights normalised bytes (four summing to 255); the
  positions stay float32;
* in a physically based look, every point's baked occlusion (:mod:`engine.outputs.occlusion`) as
  the application-specific attribute ``_OCCLUSION`` (float32, the very numbers the engine's
  renderer draws with; three.js names it ``_occlusion``).

>>> from engine import load_model
>>> head = load_model()                                                     # doctest: +SKIP
>>> blob = web_glb(head, {"lower_lip_raise": 0.8})                          # doctest: +SKIP
>>> len(blob) < 600_000                                                     # doctest: +SKIP
True
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from engine.outputs.gltf_export import glb_bytes, gltf_document, parameter_targets
from engine.outputs.gltf_skeleton import skeleton_parameters
from engine.outputs.looks import Look, look_from

if TYPE_CHECKING:
    from engine.model import Model

__all__ = ["OCCLUSION", "QUANTISATION", "dequantised_target", "morph_parameters", "web_glb", "web_gltf_document"]

QUANTISATION = "KHR_mesh_quantization"
OCCLUSION = "_OCCLUSION"
_BYTE, _UBYTE, _SHORT, _USHORT, _UINT, _FLOAT = 5120, 5121, 5122, 5123, 5125, 5126
_ARRAY_BUFFER = 34962
_STEPS = 32767.0
_TYPE_SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def morph_parameters(model: Model, moving: Mapping[str, float]) -> dict[str, float]:
    """The moving parameters that become morph targets (the leaves: the rigid group-1 ones are
    joints), each with the value its target shows at weight 1 (``moving``: name → value)."""
    joints = set(skeleton_parameters(model))
    return {name: value for name, value in moving.items() if name not in joints}


def web_gltf_document(model: Model, targets_at: Mapping[str, float],
                      look: str | Look | None = None) -> tuple[dict[str, Any], bytes]:
    """The compact glTF document and its buffer: ``model`` with a skeleton, one morph target per
    entry of ``targets_at`` (parameter → its value at weight 1; leaves only), and the baked occlusion
    of ``look`` (default ``portrait``; none for the ``legacy`` look)."""
    targets = parameter_targets(model, list(targets_at), dict(targets_at)) if targets_at else []
    document, data = gltf_document(model, targets, target_normals=True, skeleton=True)
    look = look_from(look)
    occlusion = None
    if look.shading != "legacy":
        from engine.outputs.occlusion import model_occlusion

        occlusion = model_occlusion(model, look.occlusion_radius_mm)
    return _compacted(document, data, occlusion)


def web_glb(model: Model, targets_at: Mapping[str, float], look: str | Look | None = None) -> bytes:
    """The binary glTF (``.glb``) of :func:`web_gltf_document`."""
    return glb_bytes(*web_gltf_document(model, targets_at, look))


def _compacted(document: dict[str, Any], data: bytes,
               occlusion: np.ndarray | None = None) -> tuple[dict[str, Any], bytes]:
    """Every morph target accessor re-encoded sparse and quantised; the other arrays copied as they are;
    ``occlusion`` (one value per point of every part's mesh, in :class:`PartLayout` order, which is the
    primitives' order) added to each primitive."""
    in_targets = {index for mesh in document["meshes"] for primitive in mesh["primitives"]
                  for entry in primitive.get("targets", []) for index in entry.values()}
    by_attribute = {index: name for mesh in document["meshes"] for primitive in mesh["primitives"]
                    for name, index in primitive["attributes"].items() if name in _PACKED}
    packer = _Packer()
    accessors: list[dict[str, Any]] = []
    copied_views: dict[int, int] = {}
    for index, accessor in enumerate(document["accessors"]):
        array = _accessor_array(document, data, accessor)
        if index in in_targets:
            accessors.append(_sparse_quantised(array, packer))
            continue
        if index in by_attribute:
            accessors.append(_PACKED[by_attribute[index]](array, packer))
            continue
        view = accessor["bufferView"]
        if view not in copied_views:
            original = document["bufferViews"][view]
            copied_views[view] = packer.add(_view_bytes(data, original), original.get("target"))
        accessors.append({**accessor, "bufferView": copied_views[view]})
    for image in document.get("images", []):
        original = document["bufferViews"][image["bufferView"]]
        image["bufferView"] = packer.add(_view_bytes(data, original), None)
    if occlusion is not None:
        start = 0
        for primitive in document["meshes"][0]["primitives"]:
            count = accessors[primitive["attributes"]["POSITION"]]["count"]
            values = np.asarray(occlusion[start:start + count], dtype="<f4")
            start += count
            primitive["attributes"][OCCLUSION] = len(accessors)
            accessors.append({"bufferView": packer.add(values.tobytes(), _ARRAY_BUFFER), "componentType": _FLOAT,
                              "count": count, "type": "SCALAR",
                              "min": [float(values.min())], "max": [float(values.max())]})
    out = dict(document)
    out["accessors"] = accessors
    out["bufferViews"] = packer.views
    blob = packer.data()
    out["buffers"] = [{"byteLength": len(blob)}]
    if any("targets" in p or "NORMAL" in p["attributes"] for mesh in document["meshes"] for p in mesh["primitives"]):
        out["extensionsUsed"] = sorted({*document.get("extensionsUsed", []), QUANTISATION})
        out["extensionsRequired"] = sorted({*document.get("extensionsRequired", []), QUANTISATION})
    return out, blob


def _sparse_quantised(array: np.ndarray, packer: _Packer) -> dict[str, Any]:
    """A normalised SHORT VEC3 accessor holding ``array`` (N×3 floats in [-1, 1]) as sparse rows."""
    quantised = np.round(np.clip(array, -1.0, 1.0) * _STEPS).astype(np.int16)
    rows = np.flatnonzero(np.any(quantised != 0, axis=1))
    accessor: dict[str, Any] = {"componentType": _SHORT, "normalized": True, "count": len(array),
                                "type": "VEC3",
                                "min": np.minimum(quantised.min(axis=0), 0).astype(int).tolist(),
                                "max": np.maximum(quantised.max(axis=0), 0).astype(int).tolist()}
    if len(rows):
        index_type, index_dtype = (_USHORT, "<u2") if len(array) <= 65535 else (_UINT, "<u4")
        accessor["sparse"] = {
            "count": len(rows),
            "indices": {"bufferView": packer.add(rows.astype(index_dtype).tobytes(), None),
                        "componentType": index_type},
            "values": {"bufferView": packer.add(quantised[rows].astype("<i2").tobytes(), None)},
        }
    return accessor


def _packed_normals(array: np.ndarray, packer: _Packer) -> dict[str, Any]:
    """Unit normals as normalised signed bytes (``KHR_mesh_quantization``), each padded to 4 bytes."""
    padded = np.zeros((len(array), 4), dtype=np.int8)
    padded[:, :3] = np.round(np.clip(array, -1.0, 1.0) * 127.0)
    return {"bufferView": packer.add(padded.tobytes(), _ARRAY_BUFFER, stride=4), "componentType": _BYTE,
            "normalized": True, "count": len(array), "type": "VEC3"}


def _packed_colours(array: np.ndarray, packer: _Packer) -> dict[str, Any]:
    """Linear colours as normalised 16-bit integers (core glTF; 8 bits would band in the darks), padded to 8 bytes."""
    padded = np.zeros((len(array), 4), dtype="<u2")
    padded[:, :3] = np.round(np.clip(array, 0.0, 1.0) * 65535.0)
    return {"bufferView": packer.add(padded.tobytes(), _ARRAY_BUFFER, stride=8), "componentType": _USHORT,
            "normalized": True, "count": len(array), "type": "VEC3"}


def _packed_weights(array: np.ndarray, packer: _Packer) -> dict[str, Any]:
    """Skin weights as normalised bytes (core glTF), each vertex's four still summing to exactly 255."""
    weights = np.round(np.asarray(array, dtype=float) * 255.0).astype(int)
    largest = np.argmax(weights, axis=1)
    weights[np.arange(len(weights)), largest] += 255 - weights.sum(axis=1)
    return {"bufferView": packer.add(weights.astype(np.uint8).tobytes(), _ARRAY_BUFFER), "componentType": _UBYTE,
            "normalized": True, "count": len(array), "type": "VEC4"}


_PACKED = {"NORMAL": _packed_normals, "COLOR_0": _packed_colours, "WEIGHTS_0": _packed_weights}


def dequantised_target(document: dict[str, Any], data: bytes, accessor_index: int) -> np.ndarray:
    """A morph target accessor of a compact document read back as floats (N×3): what a viewer sees."""
    accessor = document["accessors"][accessor_index]
    out = np.zeros((accessor["count"], 3))
    sparse = accessor.get("sparse")
    if sparse is not None:
        views = document["bufferViews"]
        dtype = "<u2" if sparse["indices"]["componentType"] == _USHORT else "<u4"
        rows = np.frombuffer(_view_bytes(data, views[sparse["indices"]["bufferView"]]), dtype=dtype)
        values = np.frombuffer(_view_bytes(data, views[sparse["values"]["bufferView"]]), dtype="<i2")
        out[rows] = values.reshape(-1, 3) / _STEPS
    return out


def _accessor_array(document: dict[str, Any], data: bytes, accessor: dict[str, Any]) -> np.ndarray:
    view = document["bufferViews"][accessor["bufferView"]]
    dtype = {5120: "<i1", 5121: "<u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}[accessor["componentType"]]
    size = _TYPE_SIZES[accessor["type"]]
    start = view["byteOffset"] + accessor.get("byteOffset", 0)
    flat = np.frombuffer(data, dtype=dtype, count=accessor["count"] * size, offset=start)
    return flat.reshape(accessor["count"], size) if size > 1 else flat


def _view_bytes(data: bytes, view: dict[str, Any]) -> bytes:
    start = view.get("byteOffset", 0)
    return data[start:start + view["byteLength"]]


class _Packer:
    """Byte blocks packed into one buffer, each a bufferView aligned to 4 bytes."""

    def __init__(self) -> None:
        self.views: list[dict[str, int]] = []
        self.chunks: list[bytes] = []
        self.length = 0

    def add(self, block: bytes, target: int | None, stride: int | None = None) -> int:
        view = {"buffer": 0, "byteOffset": self.length, "byteLength": len(block)}
        if target is not None:
            view["target"] = target
        if stride is not None:
            view["byteStride"] = stride
        self.views.append(view)
        padded = block + b"\0" * (-len(block) % 4)
        self.chunks.append(padded)
        self.length += len(padded)
        return len(self.views) - 1

    def data(self) -> bytes:
        return b"".join(self.chunks)
