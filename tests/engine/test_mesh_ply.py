"""Our PLY reader: triangle strips, and damaged files named with what is wrong."""

from __future__ import annotations

import numpy as np
import pytest

from engine.errors import MeshImportError
from engine.formats.mesh_io import import_mesh, write_mesh

HEADER = "ply\nformat ascii 1.0\nelement vertex {n}\nproperty float x\nproperty float y\nproperty float z\n"
GRID = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 2 0\n1 2 0\n"


def test_tristrips_with_restarts_become_triangles_of_one_orientation(tmp_path):
    path = tmp_path / "strips.ply"
    path.write_text(HEADER.format(n=6) + "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                    + GRID + "9 0 1 2 3 -1 2 3 4 5\n")
    model = import_mesh(path)
    np.testing.assert_array_equal(model.triangles(), [[0, 1, 2], [2, 1, 3], [2, 3, 4], [4, 3, 5]])
    normals = [np.cross(*np.diff(model.vertices[t], axis=0)) for t in model.triangles()]
    assert all(n[2] > 0 for n in normals)


def test_binary_tristrips_and_faces_together(tmp_path):
    header = (b"ply\nformat binary_little_endian 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
              b"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              b"element tristrips 1\nproperty list int int vertex_indices\nend_header\n")
    points = np.array([[float(w) for w in line.split()] for line in GRID.splitlines()], "<f4")
    body = points.tobytes() + bytes([3]) + np.array([0, 1, 2], "<i4").tobytes()
    body += np.array([4], "<i4").tobytes() + np.array([2, 3, 4, 5], "<i4").tobytes()
    path = tmp_path / "both.ply"
    path.write_bytes(header + body)
    model = import_mesh(path)
    np.testing.assert_array_equal(model.triangles(), [[0, 1, 2], [2, 3, 4], [4, 3, 5]])


def _ascii_square(tmp_path, text_after_header: str, faces: int = 1):
    path = tmp_path / "square.ply"
    path.write_text(HEADER.format(n=4) + f"element face {faces}\nproperty list uchar int vertex_indices\n"
                    "end_header\n" + text_after_header)
    return path


@pytest.mark.parametrize("body, words, line", [
    ("0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1\n", "face 0: the list 'vertex_indices' says 4 values", 14),
    ("0 0 0\n1 0 0\n1 1 0\n0 1 0\n", "the file ends after 0 of 1 'face' rows (truncated)", None),
    ("0 0 0\n1 0 0\n", "promises 4 'vertex' rows", 3),
    ("0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 9\n", "vertex index 9 is not one of the 4 vertices", None),
    ("0 0 0\n1 zero 0\n1 1 0\n0 1 0\n3 0 1 2\n", "vertex 1: expected 3 value(s) (x, y, z)", 11),
])
def test_damaged_ascii_ply_names_the_file_and_what_is_wrong(tmp_path, body, words, line):
    path = _ascii_square(tmp_path, body)
    with pytest.raises(MeshImportError) as info:
        import_mesh(path)
    where = f"{path}:{line}: " if line else f"{path}: "
    assert str(info.value).startswith(where) and words in str(info.value)


def test_truncated_binary_ply_says_so(tmp_path):
    path = write_mesh(tmp_path / "m.ply", np.eye(3) * 10, [3, 0, 1, 2])
    data = path.read_bytes()
    for cut in (len(data) - 5, len(data) - 13, len(data) - 40):
        path.write_bytes(data[:cut])
        with pytest.raises(MeshImportError, match="truncated") as info:
            import_mesh(path)
        assert str(info.value).startswith(str(path))


def test_huge_counts_are_refused_before_anything_is_allocated(tmp_path):
    path = tmp_path / "huge.ply"
    path.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty double x\n"
                     b"property double y\nproperty double z\nend_header\n" + bytes(48))
    with pytest.raises(MeshImportError, match="promises 4000000000 'vertex' rows"):
        import_mesh(path)


def test_degenerate_faces_are_dropped_with_a_note(tmp_path):
    from engine.formats.mesh_io import read_mesh

    path = _ascii_square(tmp_path, "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n2 0 1\n", faces=2)
    mesh = read_mesh(path)
    assert mesh.faces.tolist() == [4, 0, 1, 2, 3]
    assert mesh.notes == ["dropped 1 face(s) with fewer than 3 corners"]


def test_cli_prints_one_line_naming_file_and_line_for_a_cut_ascii_ply(tmp_path):
    import subprocess
    import sys

    path = _ascii_square(tmp_path, "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1")      # cut inside the face
    result = subprocess.run([sys.executable, "-m", "engine", "import-mesh", str(path), "-o", str(tmp_path / "m.xml")],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2
    assert result.stderr == (f"error: {path}:14: face 0: the list 'vertex_indices' says 4 values but the line "
                             "holds 2 after it (a cut line?), found '4 0 1'\n")
