"""Hostile glTF files: URIs that leave the document's folder, indices that wrap, numbers that overflow.

A glTF names its buffers and images by URI. Whatever encoding a URI uses (``../``, ``%2e%2e/``,
``%2F``, a backslash, a symbolic link planted beside the file), the reader opens only files inside
the document's folder, so a downloaded model cannot carry a file of the user's into the model it
makes. Every index the reader follows (accessor, bufferView, buffer, mesh, material, node, scene,
texture, image) must name an element that exists: a negative one used to wrap to the last element.
Inputs that made numpy print ``RuntimeWarning`` lines before the error (non-finite positions, float
indices, huge node transforms) now end in one ``error:`` line, or read cleanly.
"""

from __future__ import annotations

import base64
import json
import os
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from engine.errors import MeshImportError
from engine.formats.gltf_read import GltfFileError, read_gltf
from engine.formats.mesh_io import import_mesh, read_mesh
from engine.formats.texture_images import png_bytes
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

TRIANGLE = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], "<f4")
#: the user's file outside the model's folder, made to read as a valid buffer: were it read, the import would succeed
SECRET = (TRIANGLE + 7).tobytes() + np.array([0, 1, 2], "<u4").tobytes()
PNG = png_bytes(np.array([[[255, 0, 0], [0, 255, 0]]], dtype=np.uint8))       # 2 × 1 pixels


def gltf(folder: Path, uri: str = "tri.bin", edit: Callable[[dict], None] | None = None,
         positions: np.ndarray = TRIANGLE, name: str = "tri.gltf") -> Path:
    """A one-triangle glTF in ``folder`` whose buffer is ``uri`` (tri.bin written beside it), edited by ``edit``."""
    blob = np.asarray(positions, "<f4").tobytes() + np.array([0, 1, 2], "<u4").tobytes()
    (folder / "tri.bin").write_bytes(blob)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3"},
                         {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
           "bufferViews": [{"buffer": 0, "byteLength": 12 * len(positions)},
                           {"buffer": 0, "byteOffset": 12 * len(positions), "byteLength": 12}],
           "buffers": [{"uri": uri, "byteLength": len(blob)}]}
    if edit is not None:
        edit(doc)
    path = folder / name
    path.write_text(json.dumps(doc))
    return path


def with_image(uri: str) -> Callable[[dict], None]:
    def edit(doc: dict) -> None:
        doc["meshes"][0]["primitives"][0]["material"] = 0
        doc["materials"] = [{"name": "skin", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        doc["textures"] = [{"source": 0}]
        doc["images"] = [{"uri": uri}]
        doc["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"})
        doc["bufferViews"].append({"buffer": 1, "byteLength": 24})
        uv = np.array([[0, 0], [1, 0], [0, 1]], "<f4").tobytes()
        doc["buffers"].append({"uri": "data:application/octet-stream;base64," + base64.b64encode(uv).decode(),
                               "byteLength": 24})
        doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2
    return edit


@pytest.fixture
def layout(tmp_path) -> Path:
    """``home/secret.bin`` and ``home/secret.png`` (the user's) next to ``home/models/``, where the glTF goes."""
    models = tmp_path / "home" / "models"
    (models / "sub").mkdir(parents=True)
    (tmp_path / "home" / "secret.bin").write_bytes(SECRET)
    (tmp_path / "home" / "secret.png").write_bytes(PNG)
    return models


# -- buffers: one path check for every URI -----------------------------------------------------------------

HOSTILE = ["../secret.bin", "%2e%2e/secret.bin", "%2E%2E%2Fsecret.bin", "sub/../../secret.bin",
           "sub%2F..%2F..%2Fsecret.bin", "./sub/%2e./../../secret.bin", "..%5Csecret.bin", "..\\secret.bin",
           "link.bin", "sub-link/secret.bin", "%2e%2e/%2e%2e/" * 20 + "etc/passwd", "/etc/passwd",
           "%2Fetc%2Fpasswd", "file:///etc/passwd", "file:/etc/passwd", "http://example.org/x.bin",
           "tri.bin%00.png", "%ff%fe.bin"]


@pytest.mark.parametrize("uri", HOSTILE)
def test_a_buffer_uri_that_leaves_the_documents_folder_is_refused(layout, uri):
    (layout / "link.bin").symlink_to(layout.parent / "secret.bin")
    (layout / "sub-link").symlink_to(layout.parent)
    path = gltf(layout, uri)
    with pytest.raises(MeshImportError) as raised:
        read_mesh(path)
    message = str(raised.value)
    assert message.startswith(f"{path}: buffer 0: "), message
    assert "missing" not in message, message            # refused as what it is, not looked for


def test_the_cli_says_so_in_one_line(layout):
    path = gltf(layout, "%2e%2e/secret.bin")
    line = assert_user_error(run_in_process("import-mesh", path, "-o", layout / "out.xml"))
    assert line.startswith(f"error: {path}: buffer 0: ") and "folder" in line, line
    assert not (layout / "out.xml").exists()


@pytest.mark.parametrize("uri", ["tri.bin", "sub/../tri.bin", "./tri.bin", "%74ri.bin", "inner.bin",
                                 "sub/in%20sub.bin"])
def test_files_inside_the_folder_are_read_whatever_the_spelling(layout, uri):
    (layout / "inner.bin").symlink_to(layout / "tri.bin")          # a link that stays inside is fine
    path = gltf(layout, uri)
    (layout / "sub" / "in sub.bin").write_bytes((layout / "tri.bin").read_bytes())
    assert read_mesh(path).vertices.shape == (3, 3)


def test_the_checker_of_our_own_files_refuses_them_too(layout):
    with pytest.raises(GltfFileError, match=r"buffer 0: .*folder"):
        read_gltf(gltf(layout, "%2e%2e/secret.bin"))


def test_a_document_reached_through_a_linked_folder_reads_beside_itself(layout, tmp_path):
    """The folder is the one the user named, links resolved: a linked models folder works."""
    gltf(layout, "tri.bin")
    (tmp_path / "alias").symlink_to(layout)
    assert read_mesh(tmp_path / "alias" / "tri.gltf").vertices.shape == (3, 3)


# -- images: the same check; an image outside is left out with a note -------------------------------------

@pytest.mark.parametrize("uri", ["../secret.png", "%2e%2e/secret.png", "sub%2F..%2F..%2Fsecret.png",
                                 "..%5Csecret.png", "link.png", "/etc/passwd", "file:///etc/passwd"])
def test_an_image_uri_that_leaves_the_folder_is_never_read(layout, uri):
    (layout / "link.png").symlink_to(layout.parent / "secret.png")
    path = gltf(layout, edit=with_image(uri))
    mesh = read_mesh(path)
    assert [m.image for m in mesh.texture.materials] == [None]
    assert any(note.startswith("image left out: ") for note in mesh.notes), mesh.notes
    model = import_mesh(path)
    assert model.texture is None or not model.texture.images


def test_an_image_inside_the_folder_is_kept(layout):
    (layout / "sub" / "skin.png").write_bytes(PNG)
    model = import_mesh(gltf(layout, edit=with_image("sub/sk%69n.png")))
    assert model.texture is not None and [i.pixels.shape for i in model.texture.images] == [(1, 2, 3)]


# -- indices: negative and out-of-range ones are refused, never wrapped ------------------------------------

def _set(*keys_and_value):
    *keys, value = keys_and_value

    def edit(doc: dict) -> None:
        node = doc
        for key in keys[:-1]:
            node = node[key]
        node[keys[-1]] = value
    return edit


def _with_material(index):
    def edit(doc: dict) -> None:
        doc["materials"] = [{"name": "only"}]
        doc["meshes"][0]["primitives"][0]["material"] = index
    return edit


def _with_texture(field, index):
    def edit(doc: dict) -> None:
        with_image("sub/skin.png")(doc)
        if field == "texture":
            doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = index
        else:
            doc["textures"][0]["source"] = index
    return edit


PRIMITIVE = ("meshes", 0, "primitives", 0)
BAD_INDICES = {
    "accessor": lambda i: _set(*PRIMITIVE, "attributes", "POSITION", i),
    "indices accessor": lambda i: _set(*PRIMITIVE, "indices", i),
    "bufferView": lambda i: _set("accessors", 0, "bufferView", i),
    "buffer": lambda i: _set("bufferViews", 0, "buffer", i),
    "mesh": lambda i: _set("nodes", 0, "mesh", i),
    "node": lambda i: _set("scenes", 0, "nodes", [i]),
    "child node": lambda i: _set("nodes", 0, "children", [i]),
    "scene": lambda i: _set("scene", i),
    "material": _with_material,
    "texture": lambda i: _with_texture("texture", i),
    "image": lambda i: _with_texture("image", i),
}


@pytest.mark.parametrize("index", [-1, -2, 7, 2**40, True, 0.5, "0", None])
@pytest.mark.parametrize("what", sorted(BAD_INDICES))
def test_an_index_that_names_no_element_is_refused(layout, what, index):
    (layout / "sub" / "skin.png").write_bytes(PNG)
    path = gltf(layout, edit=BAD_INDICES[what](index))
    with pytest.raises(MeshImportError) as raised:
        read_mesh(path)
    assert str(raised.value).startswith(f"{path}: "), raised.value


def test_a_negative_index_is_named_in_one_line(layout):
    path = gltf(layout, edit=_set(*PRIMITIVE, "attributes", "POSITION", -1))
    line = assert_user_error(run_in_process("import-mesh", path, "-o", layout / "out.xml"))
    assert "accessor -1" in line and "does not exist" in line, line


@pytest.mark.parametrize("component, values", [(5120, [0, 1, -1]), (5122, [0, -3, 1])])
def test_negative_vertex_indices_are_refused(layout, component, values):
    def edit(doc: dict) -> None:
        dtype = {5120: "<i1", 5122: "<i2"}[component]
        data = np.array(values, dtype).tobytes()
        doc["buffers"].append({"uri": "data:;base64," + base64.b64encode(data).decode(), "byteLength": len(data)})
        doc["bufferViews"].append({"buffer": 1, "byteLength": len(data)})
        doc["accessors"][1] = {"bufferView": 2, "componentType": component, "count": 3, "type": "SCALAR"}
    with pytest.raises(MeshImportError, match="index is not one of its 3 vertices"):
        read_mesh(gltf(layout, edit=edit))


# -- numbers: no RuntimeWarning before the error line ------------------------------------------------------

def _float_indices(values):
    def edit(doc: dict) -> None:
        data = np.array(values, "<f4").tobytes()
        doc["buffers"].append({"uri": "data:;base64," + base64.b64encode(data).decode(), "byteLength": len(data)})
        doc["bufferViews"].append({"buffer": 1, "byteLength": len(data)})
        doc["accessors"][1] = {"bufferView": 2, "componentType": 5126, "count": 3, "type": "SCALAR"}
    return edit


NUMBERS = {
    "infinite position": dict(positions=np.array([[np.inf, 0, 0], [1, 0, 0], [0, 1, 0]])),
    "nan position": dict(positions=np.array([[np.nan, 0, 0], [1, 0, 0], [0, 1, 0]])),
    "float indices holding nan": dict(edit=_float_indices([0, 1, np.nan])),
    "float indices past int64": dict(edit=_float_indices([0, 1, 1e30])),
    "huge node scale": dict(edit=_set("nodes", 0, "scale", [1e300, 1e300, 1e300])),
    "huge node rotation": dict(edit=_set("nodes", 0, "rotation", [1e300, 1e300, 0, 0])),
    "huge node matrix": dict(edit=_set("nodes", 0, "matrix", [1e300, 0, 0, 0, 0, 1e300, 0, 0, 0, 0, 1e300, 0,
                                                                0, 0, 0, 1])),
    "translation that overflows in millimetres": dict(edit=_set("nodes", 0, "translation", [1e308, 0, 0])),
    "nested scales that overflow": dict(edit=lambda doc: doc.update(
        nodes=[{"scale": [1e200] * 3, "children": [1]}, {"scale": [1e200] * 3, "mesh": 0}])),
}


@pytest.mark.parametrize("case", sorted(NUMBERS))
def test_hostile_numbers_end_in_one_line_or_read_cleanly(layout, case):
    path = gltf(layout, **NUMBERS[case])
    result = run("import-mesh", path, "-o", layout / "out.xml")
    assert "Warning" not in result.stderr, result.stderr
    if result.returncode == 0:
        assert result.stderr == "", result.stderr
        assert read_mesh(path).vertices.shape == (3, 3)
    else:
        assert assert_user_error(result).startswith(f"error: {path}: ")


def test_coordinates_that_overflow_when_scaled_are_one_line(tmp_path):
    """Not glTF alone: any format whose numbers overflow when turned into millimetres (--scale)."""
    path = tmp_path / "big.ply"
    path.write_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                    "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "1e308 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    line = assert_user_error(run_in_process("import-mesh", path, "--scale", "1000", "-o", tmp_path / "out.xml"))
    assert line.startswith(f"error: {path}: "), line


def test_nothing_is_left_behind_by_a_refusal(layout):
    before = sorted(os.listdir(layout))
    run("import-mesh", gltf(layout, "../secret.bin"), "-o", layout / "out.xml")
    assert sorted(os.listdir(layout)) == sorted({*before, "tri.bin", "tri.gltf"})
