"""Texture coordinates and material images survive import-mesh (the photograph issue needs them)."""

from __future__ import annotations

import base64
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from engine.formats.mesh_io import read_mesh

DATA = Path(__file__).parent / "data" / "meshes"
SQUARE = "v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\n"


def run_cli(*args: object) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "engine", *map(str, args)], capture_output=True, text=True,
                          check=False)


def test_obj_keeps_corner_uvs_and_the_mtl_image(tmp_path):
    (tmp_path / "skin.mtl").write_text("newmtl skin\nKd 1 1 1\nmap_Kd -s 1 1 1 -o 0 0 photo front.png\n"
                                       "newmtl eyes\nmap_Kd eyes.jpg\n")
    (tmp_path / "face.obj").write_text("mtllib skin.mtl\n" + SQUARE + "v 20 0 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                       "usemtl skin\nf 1/1 2/2 3/3 4/4\nusemtl eyes\nf 2/5 5/5 3/5\n")
    mesh = read_mesh(tmp_path / "face.obj")
    texture = mesh.texture
    np.testing.assert_allclose(texture.corner_uv, [[0, 0], [1, 0], [1, 1], [0, 1], [.5, .5], [.5, .5], [.5, .5]])
    assert [m.name for m in texture.materials] == ["skin", "eyes"]
    assert texture.images() == [str(tmp_path / "photo front.png"), str(tmp_path / "eyes.jpg")]
    np.testing.assert_array_equal(texture.face_material, [0, 1])
    assert texture.vertex_uv(mesh.faces, 5) is None       # vertex 2 has (1, 0) and (0.5, 0.5): a seam
    assert mesh.notes == [f"image '{tmp_path / 'photo front.png'}' is missing",
                          f"image '{tmp_path / 'eyes.jpg'}' is missing"]


def test_obj_without_mtl_file_still_reads(tmp_path):
    (tmp_path / "a.obj").write_text("mtllib gone.mtl\nusemtl skin\n" + SQUARE + "f 1 2 3 4\n")
    mesh = read_mesh(tmp_path / "a.obj")
    assert mesh.texture.materials[0].image is None
    assert not mesh.texture.has_coordinates
    assert mesh.notes == ["material library 'gone.mtl' not found beside the file: its materials have no images"]


@pytest.mark.parametrize("u, v", [("u", "v"), ("s", "t"), ("texture_u", "texture_v"), ("texture_s", "texture_t")])
def test_ply_vertex_uv_names(tmp_path, u, v):
    path = tmp_path / "square.ply"
    path.write_text("ply\nformat ascii 1.0\ncomment TextureFile skin.png\nelement vertex 4\n"
                    f"property float x\nproperty float y\nproperty float z\nproperty float {u}\nproperty float {v}\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0 0 0\n10 0 0 1 0\n10 10 0 1 1\n0 10 0 0 1\n4 0 1 2 3\n")
    mesh = read_mesh(path)
    np.testing.assert_allclose(mesh.texture.vertex_uv(mesh.faces, 4), [[0, 0], [1, 0], [1, 1], [0, 1]])
    assert mesh.texture.images() == [str(tmp_path / "skin.png")]


def test_ply_per_corner_texcoord_binary_big_endian(tmp_path):
    header = (b"ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
              b"property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
              b"property list uchar float texcoord\nend_header\n")
    body = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], ">f8").tobytes()
    body += bytes([3]) + np.array([0, 1, 2], ">i4").tobytes()
    body += bytes([6]) + np.array([0, 0, .5, 0, 0, .5], ">f4").tobytes()
    path = tmp_path / "tri.ply"
    path.write_bytes(header + body)
    mesh = read_mesh(path)
    np.testing.assert_allclose(mesh.texture.corner_uv, [[0, 0], [.5, 0], [0, .5]])


def _textured_gltf(folder: Path, image_uri: str = "skin.png") -> Path:
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], "<f4")
    uv = np.array([[0, 65535], [65535, 65535], [0, 0]], "<u2")       # normalised unsigned shorts
    blob = positions.tobytes() + uv.tobytes()
    document = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"name": "face", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
        "materials": [{"name": "skin", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [{"uri": image_uri}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "normalized": True, "count": 3, "type": "VEC2"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(blob).decode()}],
    }
    path = folder / "face.gltf"
    path.write_text(json.dumps(document))
    return path


def test_gltf_texcoord_and_base_colour_image(tmp_path):
    mesh = read_mesh(_textured_gltf(tmp_path))
    # glTF's v runs down the image: (0, 1) there is the bottom-left corner, (0, 0) here
    np.testing.assert_allclose(mesh.texture.corner_uv, [[0, 0], [1, 0], [0, 1]])
    assert mesh.texture.materials[0].name == "skin"
    assert mesh.texture.images() == [str(tmp_path / "skin.png")]


def test_import_mesh_verb_reports_texture_and_images(tmp_path):
    result = run_cli("import-mesh", DATA / "fuze.obj", "-o", tmp_path / "fuze.xml")
    assert result.returncode == 0, result.stderr
    assert "texture coordinates: yes, per polygon corner" in result.stdout
    assert f"image {DATA / 'fuze uv.jpg'}" in result.stdout
    result = run_cli("import-mesh", _textured_gltf(tmp_path), "-o", tmp_path / "face.xml")
    assert result.returncode == 0, result.stderr
    assert "texture coordinates: yes, one per vertex" in result.stdout
    assert "material skin: image" in result.stdout and "× 1000 to mm" in result.stdout


def test_an_mtllib_that_is_a_device_is_skipped_not_read_for_ever(tmp_path):
    (tmp_path / "a.obj").write_text("mtllib /dev/zero\nusemtl skin\n" + SQUARE + "f 1 2 3 4\n")
    assert read_mesh(tmp_path / "a.obj").texture.materials[0].image is None
