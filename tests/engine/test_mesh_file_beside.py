"""Files a mesh names (OBJ material libraries and their images, a PLY's texture file) are read only from
the mesh's own folder or folders inside it, as glTF URIs are (issue 30 §2): a downloaded mesh cannot carry
a user's other files into the model they share."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

from engine.formats.file_beside import FileOutside, file_beside
from engine.formats.mesh_io import read_mesh

SQUARE = "v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"


@pytest.fixture
def outside(tmp_path):
    """A folder beside the mesh's folder holding a 'private' image and material library."""
    secret = tmp_path / "private"
    secret.mkdir()
    Image.fromarray(np.full((4, 4, 3), 200, np.uint8)).save(secret / "holiday.png")
    (secret / "other.mtl").write_text("newmtl skin\nmap_Kd holiday.png\n")
    (tmp_path / "mesh").mkdir()
    return secret


@pytest.mark.parametrize("name", ["../private/holiday.png", "sub/../../private/holiday.png"])
def test_an_mtl_image_outside_the_folder_is_not_read(tmp_path, outside, name):
    folder = tmp_path / "mesh"
    (folder / "skin.mtl").write_text(f"newmtl skin\nmap_Kd {name}\n")
    (folder / "face.obj").write_text("mtllib skin.mtl\n" + SQUARE + "usemtl skin\nf 1/1 2/2 3/3 4/4\n")
    mesh = read_mesh(folder / "face.obj")
    assert mesh.texture.materials[0].image is None and mesh.texture.images() == []
    assert any(note.startswith("skin.mtl line 2: image '") and "leaves the document's folder" in note
               for note in mesh.notes), mesh.notes


def test_an_absolute_image_and_an_absolute_library_are_not_read(tmp_path, outside):
    folder = tmp_path / "mesh"
    (folder / "skin.mtl").write_text(f"newmtl skin\nmap_Kd {outside / 'holiday.png'}\n")
    (folder / "face.obj").write_text(f"mtllib skin.mtl\nmtllib {outside / 'other.mtl'}\n" + SQUARE
                                     + "usemtl skin\nf 1/1 2/2 3/3 4/4\n")
    mesh = read_mesh(folder / "face.obj")
    assert mesh.texture.images() == []
    assert any(note.startswith("line 2: material library '") and "absolute path" in note for note in mesh.notes)


def test_a_link_beside_the_obj_pointing_out_is_not_followed(tmp_path, outside):
    folder = tmp_path / "mesh"
    (folder / "skin.mtl").symlink_to(outside / "other.mtl")
    (folder / "face.obj").write_text("mtllib skin.mtl\n" + SQUARE + "usemtl skin\nf 1/1 2/2 3/3 4/4\n")
    mesh = read_mesh(folder / "face.obj")
    assert mesh.texture.images() == []
    assert any("leaves the document's folder" in note for note in mesh.notes), mesh.notes


def test_files_in_a_folder_inside_are_read(tmp_path):
    folder = tmp_path / "mesh"
    (folder / "textures").mkdir(parents=True)
    Image.fromarray(np.full((4, 4, 3), 90, np.uint8)).save(folder / "textures" / "skin.png")
    (folder / "skin.mtl").write_text("newmtl skin\nmap_Kd textures\\skin.png\n")
    (folder / "face.obj").write_text("mtllib skin.mtl\n" + SQUARE + "usemtl skin\nf 1/1 2/2 3/3 4/4\n")
    mesh = read_mesh(folder / "face.obj")
    assert mesh.texture.images() == [str((folder / "textures" / "skin.png").resolve())]
    assert mesh.notes == []


@pytest.mark.parametrize("image", ["../private/holiday.png", "/etc/passwd"])
def test_a_ply_texture_file_outside_the_folder_is_not_read(tmp_path, outside, image):
    path = tmp_path / "mesh" / "square.ply"
    path.write_text(f"ply\nformat ascii 1.0\ncomment TextureFile {image}\nelement vertex 4\n"
                    "property float x\nproperty float y\nproperty float z\nproperty float u\nproperty float v\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0 0 0\n10 0 0 1 0\n10 10 0 1 1\n0 10 0 0 1\n4 0 1 2 3\n")
    mesh = read_mesh(path)
    assert mesh.texture.images() == []
    assert any(note.startswith("texture file '") for note in mesh.notes), mesh.notes


def test_import_mesh_keeps_the_private_image_out_of_the_model(tmp_path, outside):
    folder = tmp_path / "mesh"
    (folder / "skin.mtl").write_text("newmtl skin\nmap_Kd ../private/holiday.png\n")
    (folder / "face.obj").write_text("mtllib skin.mtl\n" + SQUARE + "usemtl skin\nf 1/1 2/2 3/3 4/4\n")
    result = subprocess.run([sys.executable, "-m", "engine", "import-mesh", str(folder / "face.obj"), "-o",
                             str(tmp_path / "out" / "face.xml")], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    assert "leaves the document's folder" in result.stdout + result.stderr
    # the model keeps the images it read in its HDF5 file, and says so: "images: skin (4×4)"
    assert "(4×4)" not in result.stdout, result.stdout
    assert (tmp_path / "out" / "face.h5").read_bytes().count(b"holiday") == 0


def test_the_check_itself(tmp_path):
    document = tmp_path / "a" / "doc.obj"
    assert file_beside(document, "b/c.png") == (tmp_path / "a" / "b" / "c.png").resolve()
    for name in ("../x.png", "/etc/passwd", "b/../../x.png", "x\0.png"):
        with pytest.raises(FileOutside):
            file_beside(document, name)

