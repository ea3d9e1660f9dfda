"""Mesh import (any surface pyvista reads, OBJ with our own reader) and the OBJ/PLY/NPZ writers."""

from __future__ import annotations

import base64
import json

import numpy as np
import pytest

from engine.errors import MeshImportError, UserError
from engine.formats.mesh_io import import_mesh, write_mesh

pv = pytest.importorskip("pyvista")

MIXED_POINTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2.5, 1, 0], [2, 2, 0.5]],
                        dtype=float) * 10.0 + 0.123456789
MIXED_FACES = np.array([4, 0, 1, 2, 3, 3, 1, 4, 2, 5, 4, 5, 6, 3, 2])   # quad, triangle, pentagon


def polygon_sizes(faces: np.ndarray) -> list[int]:
    sizes, i = [], 0
    while i < len(faces):
        sizes.append(int(faces[i]))
        i += faces[i] + 1
    return sizes


# ---------------------------------------------------------------------------
# Import of files written by pyvista
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", [".obj", ".ply", ".vtp", ".vtk"])
def test_sphere_keeps_points_and_triangles(tmp_path, suffix):
    sphere = pv.Sphere(radius=50.0)
    path = tmp_path / f"sphere{suffix}"
    sphere.save(path)
    model = import_mesh(path)
    assert len(model.parameters) == 0
    assert model.parts == ["surface"] and model.name == "sphere"
    np.testing.assert_allclose(model.vertices, sphere.points, atol=1e-5)
    np.testing.assert_array_equal(model.faces, sphere.faces)


def test_sphere_from_stl_has_the_same_surface(tmp_path):
    sphere = pv.Sphere(radius=50.0)
    path = tmp_path / "sphere.stl"
    sphere.save(path)
    model = import_mesh(path)
    assert len(model.triangles()) == sphere.n_cells
    # STL stores triangles, not shared vertices; the reader merges them again
    assert model.n_vertices == sphere.n_points
    np.testing.assert_allclose(np.sort(model.vertices, axis=0), np.sort(sphere.points, axis=0), atol=1e-4)


@pytest.mark.parametrize("suffix", [".obj", ".ply"])
def test_quads_are_preserved(tmp_path, suffix):
    plane = pv.Plane(i_resolution=3, j_resolution=2)
    path = tmp_path / f"plane{suffix}"
    plane.save(path)
    model = import_mesh(path)
    assert polygon_sizes(model.faces) == [4] * 6
    np.testing.assert_allclose(model.vertices, plane.points, atol=1e-6)


def test_scale_converts_to_millimetres(tmp_path):
    path = tmp_path / "sphere.ply"
    pv.Sphere(radius=0.05).save(path)
    model = import_mesh(path, scale=1000)
    assert np.isclose(np.linalg.norm(model.vertices, axis=1).max(), 50.0, atol=1e-3)


def test_strips_are_triangulated_and_lines_dropped(tmp_path):
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 2, 0], [5, 5, 5], [6, 6, 6]], float)
    mesh = pv.PolyData(points, strips=[5, 0, 1, 2, 3, 4], lines=[2, 5, 6])
    path = tmp_path / "strip.vtp"
    mesh.save(path)
    model = import_mesh(path)
    assert polygon_sizes(model.faces) == [3, 3, 3]
    assert model.n_vertices == 5, "points used only by lines are dropped"
    normals = [np.cross(*np.diff(model.vertices[t], axis=0)) for t in model.triangles()]
    assert all(n[2] > 0 for n in normals), "strip triangles keep one orientation"


def test_volume_mesh_gives_its_boundary(tmp_path):
    grid = pv.UnstructuredGrid({pv.CellType.TETRA: np.array([[0, 1, 2, 3]])},
                               np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float))
    path = tmp_path / "tet.vtu"
    grid.save(path)
    model = import_mesh(path)
    assert polygon_sizes(model.faces) == [3, 3, 3, 3]


def _gltf_two_meshes() -> dict:
    """A glTF 2.0 document with two one-triangle meshes, 'ball' and 'box' (inline buffer)."""
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0], [3, 0, 0], [2, 1, 0]], dtype="<f4")
    indices = np.array([0, 1, 2, 0, 1, 2], dtype="<u2")
    blob = positions.tobytes() + indices.tobytes()
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
             {"buffer": 0, "byteOffset": 72, "byteLength": 6}, {"buffer": 0, "byteOffset": 78, "byteLength": 6}]
    accessors = []
    for k in range(2):
        p = positions[3 * k:3 * k + 3]
        accessors.append({"bufferView": k, "componentType": 5126, "count": 3, "type": "VEC3",
                          "min": p.min(axis=0).tolist(), "max": p.max(axis=0).tolist()})
    accessors += [{"bufferView": 2 + k, "componentType": 5123, "count": 3, "type": "SCALAR"} for k in range(2)]
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "name": "ball"}, {"mesh": 1, "name": "box"}],
        "meshes": [{"name": "ball", "primitives": [{"attributes": {"POSITION": 0}, "indices": 2}]},
                   {"name": "box", "primitives": [{"attributes": {"POSITION": 1}, "indices": 3}]}],
        "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }


def test_gltf_gives_one_part_per_mesh(tmp_path):
    path = tmp_path / "pair.gltf"
    path.write_text(json.dumps(_gltf_two_meshes()))
    model = import_mesh(path)
    assert model.n_vertices == 6 and polygon_sizes(model.faces) == [3, 3]
    assert len(model.parts) == 2
    assert sorted(np.bincount(model.vertex_part).tolist()) == [3, 3]


# ---------------------------------------------------------------------------
# Our OBJ reader
# ---------------------------------------------------------------------------

def test_obj_groups_become_parts_and_texture_seams_do_not_split_vertices(tmp_path):
    path = tmp_path / "head.obj"
    path.write_text(
        "# comment\nmtllib head.mtl\no head\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 9 9 9\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
        "g skin\nusemtl skin\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"
        "g eye left\nf -5/5 -4//1 -2\n"
        "l 1 6\n")
    model = import_mesh(path)
    assert model.parts == ["skin", "eye_left"]
    np.testing.assert_array_equal(model.faces, [4, 0, 1, 2, 3, 3, 1, 2, 4])
    assert model.n_vertices == 5, "the vertex used only by a line is dropped, the order kept"
    np.testing.assert_array_equal(model.vertex_part, [0, 0, 0, 0, 1])


def test_obj_objects_are_parts_when_there_are_no_groups(tmp_path):
    path = tmp_path / "two.obj"
    path.write_text("o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                    "o 2nd\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n")
    model = import_mesh(path)
    assert model.parts == ["first", "part_2nd"]


@pytest.mark.parametrize("text, line, words", [
    ("v 0 0 0\nv 1 zero 0\n", 2, "not a number"),
    ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "not defined"),
    ("v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "at least 3"),
    ("v 0 0\n", 1, "three coordinates"),
])
def test_obj_mistakes_name_file_and_line(tmp_path, text, line, words):
    path = tmp_path / "bad.obj"
    path.write_text(text)
    with pytest.raises(MeshImportError) as info:
        import_mesh(path)
    assert str(info.value).startswith(f"{path}:{line}: ") and words in str(info.value)


# ---------------------------------------------------------------------------
# Files that are not surfaces
# ---------------------------------------------------------------------------

def _write_points_only(path):
    pv.PolyData(np.random.default_rng(0).random((5, 3))).save(path)


def _write_png(path):
    from engine.outputs.png_file import write_png

    write_png(path, np.zeros((4, 4, 3), dtype=np.uint8))


BAD_FILES = {
    "garbage ply": ("scan.ply", lambda p: p.write_text("ply\nformat ascii 1.0\nnonsense\n")),
    "garbage stl": ("scan.stl", lambda p: p.write_bytes(b"hello")),
    "empty obj": ("empty.obj", lambda p: p.write_text("")),
    "obj with lines only": ("lines.obj", lambda p: p.write_text("v 0 0 0\nv 1 0 0\nl 1 2\n")),
    "points only": ("cloud.vtp", _write_points_only),
    "an image": ("picture.png", _write_png),
    "unknown format": ("notes.xyz", lambda p: p.write_text("1 2 3\n")),
    "binary junk as obj": ("junk.obj", lambda p: p.write_bytes(bytes(range(256)) * 4)),
}


@pytest.mark.parametrize("name, write", list(BAD_FILES.values()), ids=list(BAD_FILES))
def test_bad_files_raise_mesh_import_error_naming_the_file(tmp_path, capfd, name, write):
    path = tmp_path / name
    write(path)
    with pytest.raises(MeshImportError) as info:
        import_mesh(path)
    assert str(info.value).startswith(str(path))
    _out, err = capfd.readouterr()
    assert err == "", "VTK's own complaints are silenced"


def test_missing_file_and_folder(tmp_path):
    with pytest.raises(MeshImportError, match="no such file"):
        import_mesh(tmp_path / "none.ply")
    with pytest.raises(MeshImportError, match="folder"):
        import_mesh(tmp_path)
    with pytest.raises(MeshImportError, match="scale"):
        import_mesh(tmp_path / "none.ply", scale=0)


# ---------------------------------------------------------------------------
# Writers
# ---------------------------------------------------------------------------

def test_obj_round_trip_is_exact_with_groups(tmp_path):
    path = write_mesh(tmp_path / "m.obj", MIXED_POINTS, MIXED_FACES, parts=["skin", "teeth"],
                      vertex_part=[0, 0, 0, 0, 1, 1, 1], name="mixed")
    text = path.read_text()
    assert "o mixed\n" in text and "g skin\n" in text and "g teeth\n" in text
    back = import_mesh(path)
    np.testing.assert_array_equal(back.vertices, MIXED_POINTS)
    np.testing.assert_array_equal(back.faces, MIXED_FACES)
    assert back.parts == ["skin", "teeth"]


def _read_binary_ply(path):
    data = path.read_bytes()
    header, body = data.split(b"end_header\n", 1)
    assert b"format binary_little_endian 1.0" in header
    n = int(header.split(b"element vertex ")[1].split(b"\n")[0])
    vertices = np.frombuffer(body[:n * 24], dtype="<f8").reshape(n, 3)
    rest, faces = body[n * 24:], []
    i = 0
    while i < len(rest):
        k = rest[i]
        faces += [k, *np.frombuffer(rest[i + 1:i + 1 + 4 * k], dtype="<i4").tolist()]
        i += 1 + 4 * k
    return vertices, np.array(faces)


@pytest.mark.parametrize("binary", [True, False])
def test_ply_round_trip_with_mixed_polygons(tmp_path, binary):
    path = write_mesh(tmp_path / "m.ply", MIXED_POINTS, MIXED_FACES, binary=binary)
    mesh = pv.read(path)
    np.testing.assert_allclose(mesh.points, MIXED_POINTS, atol=1e-5)
    np.testing.assert_array_equal(mesh.faces, MIXED_FACES)
    if binary:
        vertices, faces = _read_binary_ply(path)
        np.testing.assert_array_equal(vertices, MIXED_POINTS)   # doubles: exact
        np.testing.assert_array_equal(faces, MIXED_FACES)
    else:
        assert path.read_text().startswith("ply\nformat ascii 1.0\n")


def test_npz_holds_vertices_faces_and_triangles(tmp_path):
    path = write_mesh(tmp_path / "m.npz", MIXED_POINTS, MIXED_FACES, parts=["a"], vertex_part=np.zeros(7))
    with np.load(path) as data:
        assert data["vertices"].dtype == np.float64
        np.testing.assert_array_equal(data["vertices"], MIXED_POINTS)
        np.testing.assert_array_equal(data["faces"], MIXED_FACES)
        np.testing.assert_array_equal(data["triangles"],
                                      [[0, 1, 2], [0, 2, 3], [1, 4, 2], [4, 5, 6], [4, 6, 3], [4, 3, 2]])
        assert data["parts"].tolist() == ["a"]


def test_writer_refuses_bad_input_and_leaves_no_temporary_files(tmp_path):
    with pytest.raises(UserError, match="unknown mesh format"):
        write_mesh(tmp_path / "m.stl", MIXED_POINTS, MIXED_FACES)
    with pytest.raises(UserError, match=r"\(N, 3\)"):
        write_mesh(tmp_path / "m.obj", MIXED_POINTS[:, :2], MIXED_FACES)
    with pytest.raises(UserError, match="outside"):
        write_mesh(tmp_path / "m.obj", MIXED_POINTS[:5], MIXED_FACES)
    with pytest.raises(UserError, match="folder does not exist"):
        write_mesh(tmp_path / "no" / "m.obj", MIXED_POINTS, MIXED_FACES)
    write_mesh(tmp_path / "ok.obj", MIXED_POINTS, MIXED_FACES)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ok.obj"]
