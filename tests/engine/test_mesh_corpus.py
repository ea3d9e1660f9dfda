"""Real public meshes (tests/engine/data/meshes, see its README) read as VTK's readers read them, or better.

The reference is pyvista/VTK run in this process on these known-good files.
VTK splits vertices at texture seams; we keep the file's vertex order, so
the comparison is corner by corner: every polygon corner's position and
texture coordinates must be the same pair in both readings.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from engine.formats.mesh_io import import_mesh, read_mesh
from engine.model.cells import cell_sizes, index_mask

pv = pytest.importorskip("pyvista")

DATA = Path(__file__).parent / "data" / "meshes"
#: file → (vertices we keep, polygons, texture coordinates?, material images)
EXPECTED = {
    "BoxTextured.glb": (24, 12, True, ["embedded: image/png, 23516 bytes"]),
    "BoxTextured.ply": (24, 12, True, []),
    "cube_blender_uv.ply": (24, 6, True, []),
    "cube_blender_uv_meshlab.ply": (24, 12, True, []),
    "fuze.ply": (502, 1000, True, [str(DATA / "fuze uv.jpg")]),
    "fuze.obj": (502, 1000, True, [str(DATA / "fuze uv.jpg")]),
    "box.obj": (8, 6, True, []),
    "textured_tetrahedron.obj": (4, 4, True, []),
    "Mesh_PrimitiveMode_04.gltf": (4, 2, False, []),
    "cube.glb": (8, 12, False, []),
}
#: Files VTK reads wrongly or not at all: what is in them, checked against the file's own text.
VTK_FAILS = {
    "cubevt.obj": "VTK's OBJ reader segfaults (a corner names a texture coordinate the file lacks)",
    "fuze_ascii.ply": "VTK's PLY reader finds 5 of the 1000 faces (ASCII with per-corner texcoord lists)",
    "jacked.obj": "VTK's OBJ reader finds no polygons ('f 2/2/' corners, a missing mtllib)",
}


@pytest.mark.parametrize("name", sorted(VTK_FAILS))
def test_files_vtk_fails_on_read_every_polygon_they_hold(name):
    mesh = read_mesh(DATA / name)
    text = (DATA / name).read_text()
    if name.endswith(".obj"):
        expected = sum(line.startswith("f ") for line in text.splitlines())
    else:
        expected = int(text.split("element face ")[1].split()[0])
    assert len(cell_sizes(mesh.faces)) == expected
    has_uv = name != "cubevt.obj"          # its corners name texture coordinates it lacks
    assert (mesh.texture is not None and mesh.texture.has_coordinates) == has_uv


def corners(points: np.ndarray, faces: np.ndarray, uv: np.ndarray | None) -> np.ndarray:
    """Sorted rows (x, y, z, u, v) of every polygon corner."""
    indices = faces[index_mask(faces, cell_sizes(faces))]
    rows = points[indices]
    if uv is not None:
        rows = np.column_stack([rows, uv])
    return np.round(rows[np.lexsort(rows.T[::-1])], 5)


def reference(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Points, polygons (strips as triangles) and per-corner (u, v) as VTK reads the file."""
    data = pv.read(path)
    if isinstance(data, pv.MultiBlock):
        data = data.combine().extract_surface(algorithm="dataset_surface")
    data = data.triangulate() if data.GetNumberOfStrips() else data
    faces = np.asarray(data.faces)
    tcoords = data.active_texture_coordinates
    if tcoords is None:
        names = [n for n in data.point_data if data.point_data[n].ndim == 2 and data.point_data[n].shape[1] == 2]
        tcoords = data.point_data[names[0]] if names else None
    uv = None if tcoords is None else np.asarray(tcoords)[faces[index_mask(faces, cell_sizes(faces))]]
    return np.asarray(data.points, dtype=float), faces, uv


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_public_mesh_reads_like_the_reference_reader(name):
    n_vertices, n_polygons, has_uv, images = EXPECTED[name]
    path = DATA / name
    mesh = read_mesh(path, keep_units=True)
    assert len(mesh.vertices) == n_vertices
    assert len(cell_sizes(mesh.faces)) == n_polygons
    assert (mesh.texture is not None and mesh.texture.has_coordinates) == has_uv
    assert (mesh.texture.images() if mesh.texture else []) == images
    points, faces, uv = reference(path)
    ours_uv = None
    if has_uv and uv is not None:
        ours_uv = mesh.texture.corner_uv.copy()
        if path.suffix in (".glb", ".gltf"):
            ours_uv[:, 1] = 1 - ours_uv[:, 1]    # VTK keeps glTF's v (down the image); we turn it up
    if path.suffix == ".obj":
        # VTK's OBJ reader has no v-per-corner arrays we can compare like this: positions only
        ours_uv, uv = None, None
    expected = corners(points, faces, uv)
    ours = corners(mesh.vertices, mesh.faces, ours_uv if uv is not None else None)
    if path.suffix in (".gltf", ".glb") and name.startswith("Mesh_PrimitiveMode"):
        expected, ours = np.unique(expected, axis=0), np.unique(ours, axis=0)
    np.testing.assert_allclose(ours, expected, atol=1e-5)


def test_obj_texture_coordinates_are_the_files_per_corner():
    mesh = read_mesh(DATA / "textured_tetrahedron.obj")
    # f 1/1/1 3/2/2 2/3/3 is the first face: vt 1, 2, 3
    np.testing.assert_allclose(mesh.texture.corner_uv[:3], [[0.5440, 0.7206], [0.1650, 0.9789], [0.1620, 0.5]])
    assert mesh.texture.vertex_uv(mesh.faces, 4) is None, "the file has seams: vertex 3 has two (u, v)"


def test_obj_and_ply_of_the_same_scan_agree_corner_by_corner():
    """MeshLab wrote fuze.obj and fuze.ply from one mesh: same vertices, faces and (u, v)."""
    obj, ply = read_mesh(DATA / "fuze.obj"), read_mesh(DATA / "fuze.ply")
    np.testing.assert_allclose(obj.vertices, ply.vertices, atol=1e-6)
    np.testing.assert_array_equal(obj.faces, ply.faces)
    np.testing.assert_allclose(obj.texture.corner_uv, ply.texture.corner_uv, atol=1e-6)


def test_gltf_sample_is_converted_to_millimetres_and_keeps_the_texture():
    model = import_mesh(DATA / "BoxTextured.glb")
    np.testing.assert_allclose(model.vertices.max(axis=0), [500, 500, 500])
    mesh = read_mesh(DATA / "BoxTextured.glb", keep_units=True)
    np.testing.assert_allclose(mesh.vertices.max(axis=0), [0.5, 0.5, 0.5])
    assert mesh.texture.materials[0].name == "Texture"


def test_a_file_that_segfaults_vtk_reads_with_a_note():
    mesh = read_mesh(DATA / "cubevt.obj")
    text = (DATA / "cubevt.obj").read_text()
    assert len(mesh.vertices) == text.count("\nv ") + text.startswith("v ")
    assert len(cell_sizes(mesh.faces)) == text.count("\nf ")
    assert mesh.notes == ["line 50: face corner '1/1/1' names a texture coordinate that is not defined; "
                          "such corners have none"]


def test_ascii_ply_that_vtk_misreads_equals_its_binary_twin():
    """MeshLab wrote fuze.ply and fuze_ascii.ply from one mesh; VTK reads 5 faces of the ASCII one."""
    ascii_mesh, binary_mesh = read_mesh(DATA / "fuze_ascii.ply"), read_mesh(DATA / "fuze.ply")
    np.testing.assert_allclose(ascii_mesh.vertices, binary_mesh.vertices, atol=1e-5)
    np.testing.assert_array_equal(ascii_mesh.faces, binary_mesh.faces)
    np.testing.assert_allclose(ascii_mesh.texture.corner_uv, binary_mesh.texture.corner_uv, atol=1e-5)
