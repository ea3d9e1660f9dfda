"""glTF import: metres to millimetres by default, --up, node transforms, and missing or LFS buffers named."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from engine.errors import MeshImportError
from engine.formats.mesh_io import import_mesh

DATA = Path(__file__).parent / "data" / "meshes"
STRIP = "Mesh_PrimitiveMode_04"


def copy_strip(folder: Path) -> Path:
    for suffix in (".gltf", ".bin"):
        shutil.copy(DATA / f"{STRIP}{suffix}", folder / f"{STRIP}{suffix}")
    return folder / f"{STRIP}.gltf"


def run_cli(*args: object) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "engine", *map(str, args)], capture_output=True, text=True,
                          check=False)


def test_gltf_is_in_metres_and_becomes_millimetres(tmp_path):
    path = copy_strip(tmp_path)
    model = import_mesh(path)
    np.testing.assert_allclose(model.vertices.min(axis=0), [-500, -500, 0])
    np.testing.assert_allclose(model.vertices.max(axis=0), [500, 500, 0])
    kept = import_mesh(path, keep_units=True)
    np.testing.assert_allclose(kept.vertices.max(axis=0), [0.5, 0.5, 0])
    np.testing.assert_allclose(import_mesh(path, scale=10).vertices.max(axis=0), [5, 5, 0])


def test_strip_triangles_keep_one_orientation(tmp_path):
    model = import_mesh(copy_strip(tmp_path))
    normals = [np.cross(*np.diff(model.vertices[t], axis=0)) for t in model.triangles()]
    assert len(normals) == 2 and all(n[2] > 0 for n in normals)


@pytest.mark.parametrize("up, expected_up_vector", [
    ("+Y", [0, 1, 0]), ("+Z", [0, 0, 1]), ("-Z", [0, 0, -1]), ("Z", [0, 0, 1]), ("-Y", [0, -1, 0]),
    ("+X", [1, 0, 0]), ("-x", [-1, 0, 0]), ("Z-", [0, 0, -1]), ("y+", [0, 1, 0]),
])
def test_up_option_turns_the_files_up_to_plus_y(tmp_path, up, expected_up_vector):
    path = tmp_path / "arrow.obj"
    tip = np.array(expected_up_vector, dtype=float) * 100       # the file's "up" is where the tip points
    side = np.array([1.0, 0, 0]) if expected_up_vector[0] == 0 else np.array([0, 0, 1.0])
    path.write_text(f"v 0 0 0\nv {' '.join(map(str, tip))}\nv {' '.join(map(str, side * 10))}\nf 1 2 3\n")
    model = import_mesh(path, up=up)
    np.testing.assert_allclose(model.vertices[1], [0, 100, 0], atol=1e-9)
    # a rotation, not a mirror: lengths and handedness are kept
    before = np.cross(tip, side * 10)
    after = np.cross(model.vertices[1], model.vertices[2])
    assert np.isclose(np.linalg.norm(before), np.linalg.norm(after))


def test_z_up_scan_facing_minus_y_ends_facing_plus_z(tmp_path):
    path = tmp_path / "nose.obj"
    path.write_text("v 0 0 0\nv 10 0 0\nv 0 -30 5\nf 1 2 3\n")     # the nose (vertex 3) points along −Y
    model = import_mesh(path, up="+Z")
    np.testing.assert_allclose(model.vertices[2], [0, 5, 30])


def test_bad_up_is_a_user_error(tmp_path):
    with pytest.raises(MeshImportError, match="up must be one of"):
        import_mesh(copy_strip(tmp_path), up="sideways")


def test_missing_bin_is_named_plainly(tmp_path):
    path = copy_strip(tmp_path)
    (tmp_path / f"{STRIP}.bin").unlink()
    result = run_cli("import-mesh", path, "-o", tmp_path / "out.xml")
    assert result.returncode == 2
    assert result.stderr == (f"error: {path}: buffer 0: cannot read '{STRIP}.bin': the file is missing "
                             f"(it belongs beside {STRIP}.gltf)\n")


def test_git_lfs_pointer_instead_of_the_bin_is_named_plainly(tmp_path):
    path = copy_strip(tmp_path)
    (tmp_path / f"{STRIP}.bin").write_text("version https://git-lfs.github.com/spec/v1\n"
                                           "oid sha256:4d7a214614ab2935c943f9e0ff69d22e\n"
                                           "size 48\n")
    with pytest.raises(MeshImportError, match=r"'Mesh_PrimitiveMode_04\.bin' is a Git LFS pointer, not the data") \
            as info:
        import_mesh(path)
    assert str(info.value).startswith(str(path))


def test_a_mesh_file_that_is_itself_an_lfs_pointer(tmp_path):
    path = tmp_path / "head.glb"
    path.write_text("version https://git-lfs.github.com/spec/v1\noid sha256:00\nsize 123456\n")
    with pytest.raises(MeshImportError, match="is a Git LFS pointer, not the mesh itself"):
        import_mesh(path)


def test_node_transforms_are_applied_and_mirrors_keep_faces_outward(tmp_path):
    path = copy_strip(tmp_path)
    document = json.loads(path.read_text())
    document["scenes"] = [{"nodes": [0]}]
    document["nodes"] = [{"children": [1], "translation": [1, 0, 0]},
                         {"mesh": 0, "scale": [2, 2, -1]}]     # a mirror in z
    path.write_text(json.dumps(document))
    model = import_mesh(path)
    np.testing.assert_allclose(model.vertices.min(axis=0), [0, -1000, 0])
    np.testing.assert_allclose(model.vertices.max(axis=0), [2000, 1000, 0])
    normals = [np.cross(*np.diff(model.vertices[t], axis=0)) for t in model.triangles()]
    # glTF: a transform with a negative determinant turns the front face over, so the strip's front
    # (+z in the file) is the mirror image's −z; the winding is reversed to say so
    assert all(n[2] < 0 for n in normals)


def test_a_node_cycle_is_refused(tmp_path):
    path = copy_strip(tmp_path)
    document = json.loads(path.read_text())
    document["scenes"] = [{"nodes": [0]}]
    document["nodes"] = [{"children": [1]}, {"mesh": 0, "children": [0]}]
    path.write_text(json.dumps(document))
    with pytest.raises(MeshImportError, match="cycle"):
        import_mesh(path)


def test_cli_takes_a_negative_up_axis_in_both_spellings(tmp_path):
    path = tmp_path / "nose.obj"
    path.write_text("v 0 0 0\nv 10 0 0\nv 0 5 -30\nf 1 2 3\n")
    for spelling in (["--up", "Z-"], ["--up=-Z"]):
        result = run_cli("import-mesh", path, "-o", tmp_path / "m.xml", *spelling)
        assert result.returncode == 0, result.stderr
        assert "the file's -Z turned to +Y" in result.stdout


def test_cli_up_and_keep_units(tmp_path):
    path = copy_strip(tmp_path)
    result = run_cli("import-mesh", path, "-o", tmp_path / "m.xml", "--up", "+Z", "--keep-units")
    assert result.returncode == 0, result.stderr
    assert "coordinates × 1 to mm" in result.stdout and "the file's +Z turned to +Y" in result.stdout
    from engine.formats.model_files import load_model

    np.testing.assert_allclose(load_model(tmp_path / "m.xml").vertices.max(axis=0), [0.5, 0, 0.5])
