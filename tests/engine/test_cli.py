"""The command line, run as users run it: in a fresh interpreter, without a display.

Every error path must end with status 2 and exactly one ``error:`` line on
stderr, never a traceback. Most tests use a small
synthetic head saved into a temporary folder; tests of the shipped default
head skip until ``engine/data/default-head/head.xml`` exists.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from engine import InfluenceRegion, Model, Parameter, ParameterTree, load_model, save_model
from engine.paths import default_model_path
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

DEFAULT_HEAD_PARAMETERS = {
    "neck_lean", "head_turn", "head_nod", "head_tilt", "jaw_open", "tongue_raise", "eye_left_turn",
    "eye_left_raise", "eye_right_turn", "eye_right_raise", "eyelid_left_close", "eyelid_right_close",
    "brow_raise", "mouth_widen", "lip_protrude", "upper_lip_raise", "lower_lip_raise",
}
SKIN = np.array([0xE2, 0xAD, 0x8F])


# ---------------------------------------------------------------------------
# A synthetic head: numpy only, ~250 mm tall, facing +Z, +Y up
# ---------------------------------------------------------------------------

def _ellipsoid(centre, radii, n_lat: int, n_lon: int):
    """Latitude-longitude ellipsoid (mm): quads between the rings, triangles at the poles."""
    theta = np.linspace(0, np.pi, n_lat + 1)[1:-1]
    phi = np.linspace(0, 2 * np.pi, n_lon, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    ring = np.stack([np.sin(t) * np.sin(p), np.cos(t), np.sin(t) * np.cos(p)], axis=-1).reshape(-1, 3)
    points = np.vstack([[0, 1, 0], ring, [0, -1, 0]]) * radii + centre

    def at(i, j):
        return 1 + i * n_lon + j % n_lon

    bottom = len(points) - 1
    faces = [[3, 0, at(0, j + 1), at(0, j)] for j in range(n_lon)]
    faces += [[4, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]
              for i in range(n_lat - 2) for j in range(n_lon)]
    faces += [[3, bottom, at(n_lat - 2, j), at(n_lat - 2, j + 1)] for j in range(n_lon)]
    return points, faces


def synthetic_head() -> Model:
    """An ellipsoid head with two eyeballs, three parameters (rotation, rotation leaf, translation leaf)."""
    pieces = [
        _ellipsoid((0.0, 150.0, 0.0), (75.0, 100.0, 90.0), 18, 24),
        _ellipsoid((32.0, 165.0, 72.0), (12.0, 12.0, 12.0), 10, 16),
        _ellipsoid((-32.0, 165.0, 72.0), (12.0, 12.0, 12.0), 10, 16),
    ]
    vertices, faces, vertex_part = [], [], []
    offset = 0
    for k, (points, polygons) in enumerate(pieces):
        faces += [[poly[0]] + [i + offset for i in poly[1:]] for poly in polygons]
        vertices.append(points)
        vertex_part.append(np.full(len(points), k))
        offset += len(points)
    vertices = np.vstack(vertices)
    vertex_part = np.concatenate(vertex_part)
    n = len(vertices)
    tree = ParameterTree([
        Parameter("head_turn", "rotation", axis=(0, 1, 0), pivot=(0, 60, 0), degrees_per_unit=40),
        Parameter("eye_left_turn", "rotation", parent="head_turn", axis=(0, 1, 0), pivot=(32, 165, 72),
                  degrees_per_unit=30),
        Parameter("brow_raise", "translation", parent="head_turn", minimum=0, maximum=1, direction=(0, 8, 0)),
    ])
    eye = np.flatnonzero(vertex_part == 1)
    brow = np.flatnonzero((vertex_part == 0) & (vertices[:, 1] > 180) & (vertices[:, 2] > 40))
    regions = {
        "head_turn": InfluenceRegion(np.arange(n), np.ones(n)),
        "eye_left_turn": InfluenceRegion(eye, np.ones(len(eye))),
        "brow_raise": InfluenceRegion(brow, np.full(len(brow), 0.5)),
    }
    skin = np.flatnonzero(vertex_part == 0)
    nose_tip = int(skin[np.argmax(vertices[skin, 2])])
    return Model(vertices, np.concatenate(faces), ["skin", "eye_left", "eye_right"], vertex_part, tree, regions,
                 {"9.3": nose_tip}, name="synthetic-head")


@pytest.fixture(scope="module")
def model_path(tmp_path_factory) -> Path:
    return save_model(synthetic_head(), tmp_path_factory.mktemp("model") / "synthetic.xml")


@pytest.fixture
def default_head() -> Path:
    path = default_model_path()
    if not path.exists():
        pytest.skip("the default head (engine/data/default-head/head.xml) is not built yet")
    return path


# ---------------------------------------------------------------------------
# Running the command line
# ---------------------------------------------------------------------------

def read_png(path: Path) -> np.ndarray:
    from PIL import Image  # installed with pyvista

    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"))


# ---------------------------------------------------------------------------
# info
# ---------------------------------------------------------------------------

def test_info_json_has_exactly_the_documented_schema(model_path):
    result = run_in_process("info", "-m", model_path, "--json")
    assert result.returncode == 0, result.stderr
    info = json.loads(result.stdout)
    assert set(info) == {"parameters", "landmarks", "vertices"}
    model = load_model(model_path)
    assert info["vertices"] == model.n_vertices
    assert info["landmarks"] == {"9.3": model.landmarks["9.3"]}
    assert [p["name"] for p in info["parameters"]] == ["head_turn", "eye_left_turn", "brow_raise"]
    for entry in info["parameters"]:
        assert set(entry) == {"name", "type", "group", "parent", "min", "max", "default"}
    head_turn, eye, brow = info["parameters"]
    assert head_turn == {"name": "head_turn", "type": "rotation", "group": 1, "parent": None,
                         "min": -1.0, "max": 1.0, "default": 0.0}
    assert (eye["group"], eye["parent"], eye["type"]) == (2, "head_turn", "rotation")
    assert (brow["type"], brow["min"], brow["max"]) == ("translation", 0.0, 1.0)


def test_info_text_shows_the_tree_indented_with_parts_and_landmarks(model_path):
    result = run_in_process("info", "-m", model_path)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    root = next(line for line in lines if "head_turn" in line)
    child = next(line for line in lines if "eye_left_turn" in line)
    indent = lambda line: len(line) - len(line.lstrip())  # noqa: E731
    assert indent(child) > indent(root)
    assert "group 1" in root and "group 2" in child and "rotation" in root and "[-1, 1]" in root
    assert any(line.startswith("parts:") and "eye_left" in line for line in lines)
    assert any(line.startswith("landmarks: 1") for line in lines)


def test_console_script_runs(model_path):
    script = Path(sys.executable).with_name("artificial-person")
    if not script.exists():
        pytest.skip("the console script is not installed in this environment")
    result = run("info", "-m", model_path, "--json", command=[str(script)])
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["vertices"] == load_model(model_path).n_vertices


def test_help_exits_zero():
    result = run_in_process("--help")
    assert result.returncode == 0
    for verb in ("workbench", "info", "render", "pose", "import-mesh"):
        assert verb in result.stdout


def test_importing_the_cli_loads_no_vtk_or_qt():
    code = ("import sys, engine, engine.cli, engine.formats.mesh_io, engine.outputs.render; "
            "print([m for m in sys.modules if m.split('.')[0] in ('vtk', 'vtkmodules', 'pyvista', 'PySide6')])")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=False)
    assert result.stdout.strip() == "[]", result.stdout + result.stderr


# ---------------------------------------------------------------------------
# Errors: status 2, one line, no traceback
# ---------------------------------------------------------------------------

ERROR_CASES = {
    "no verb": [],
    "unknown verb": ["frobnicate"],
    "unknown option": ["info", "--bogus"],
    "missing model": ["info", "-m", "no-such-model.xml"],
    "set without value": ["render", "-m", "{model}", "--set", "jaw", "-o", "out.png"],
    "set value not a number": ["render", "-m", "{model}", "--set", "jaw=abc", "-o", "out.png"],
    "set value infinite": ["pose", "-m", "{model}", "--set", "head_turn=inf", "-o", "out.obj"],
    "unknown parameter": ["pose", "-m", "{model}", "--set", "jaw_open=0.5", "-o", "out.obj"],
    "value out of range": ["pose", "-m", "{model}", "--set", "head_turn=0.5", "brow_raise=3", "-o", "out.obj"],
    "unknown pose extension": ["pose", "-m", "{model}", "-o", "out.stl"],
    "unknown render extension": ["render", "-m", "{model}", "-o", "out.jpg"],
    "missing output": ["render", "-m", "{model}"],
    "bad size": ["render", "-m", "{model}", "--size", "big", "-o", "out.png"],
    "zero size": ["render", "-m", "{model}", "--size", "0x100", "-o", "out.png"],
    "unknown view": ["render", "-m", "{model}", "--view", "top", "-o", "out.png"],
    "output folder missing": ["pose", "-m", "{model}", "-o", "no/such/folder/out.npz"],
    "import missing file": ["import-mesh", "nothing.obj", "-o", "out.xml"],
    "import bad scale": ["import-mesh", "nothing.obj", "-o", "out.xml", "--scale", "-2"],
    "import output not xml": ["import-mesh", "nothing.obj", "-o", "out.h5"],
    "workbench missing model": ["workbench", "no-such-model.xml"],
}


@pytest.mark.parametrize("args", list(ERROR_CASES.values()), ids=list(ERROR_CASES))
def test_user_errors_give_one_line_and_status_2(args, model_path, tmp_path):
    real_process = args[:1] == ["workbench"]          # in a real process: it must not bring Qt into this one
    result = (run if real_process else run_in_process)(*[str(model_path) if a == "{model}" else a for a in args],
                                                       cwd=tmp_path)
    assert_user_error(result)
    assert not list(tmp_path.glob("out.*")), "nothing is written when the command fails"


def test_error_messages_say_what_is_wrong(model_path, tmp_path):
    line = assert_user_error(run_in_process("pose", "-m", model_path, "--set", "brow_raise=3",
                                            "-o", tmp_path / "a.obj"))
    assert "brow_raise" in line and "[0, 1]" in line
    line = assert_user_error(run_in_process("pose", "-m", model_path, "--set", "browraise=1",
                                            "-o", tmp_path / "a.obj"))
    assert "unknown parameter 'browraise'" in line and "brow_raise" in line
    line = assert_user_error(run_in_process("render", "-m", model_path, "--set", "jaw", "-o", tmp_path / "a.png"))
    assert "NAME=VALUE" in line


def test_malformed_xml_is_reported_with_file_and_line(tmp_path):
    bad = tmp_path / "bad.xml"
    bad.write_text('<?xml version="1.0"?>\n<model format="artificial-person-model">\n  <parts>\n</model>\n')
    line = assert_user_error(run_in_process("info", "-m", bad))
    assert re.match(rf"error: {re.escape(str(bad))}:\d+: ", line), line


def test_model_failing_the_schema_is_reported_with_file_and_line(model_path, tmp_path):
    text = model_path.read_text().replace('type="rotation"', 'type="twist"', 1)
    (tmp_path / "synthetic.h5").write_bytes(model_path.with_suffix(".h5").read_bytes())
    bad = tmp_path / "synthetic.xml"
    bad.write_text(text)
    line = assert_user_error(run_in_process("info", "-m", bad, "--json"))
    assert re.match(rf"error: {re.escape(str(bad))}:\d+: ", line), line


def test_entity_reference_in_the_model_is_one_error_line(model_path, tmp_path):
    # load_model lets lxml's schema error escape here (see test_model_files.py); the CLI must not
    text = model_path.read_text().replace("<model ", '<!DOCTYPE model [<!ENTITY hello "hi">]>\n<model ', 1)
    text = text.replace("<parts>", "<description>&hello;</description>\n  <parts>", 1)
    bad = tmp_path / "synthetic.xml"
    bad.write_text(text)
    (tmp_path / "synthetic.h5").write_bytes(model_path.with_suffix(".h5").read_bytes())
    line = assert_user_error(run_in_process("info", "-m", bad))
    assert str(bad) in line


def test_missing_hdf5_dataset_is_reported(model_path, tmp_path):
    xml = tmp_path / "synthetic.xml"
    xml.write_text(model_path.read_text())
    arrays = tmp_path / "synthetic.h5"
    arrays.write_bytes(model_path.with_suffix(".h5").read_bytes())
    with h5py.File(arrays, "r+") as f:
        del f["mesh/part"]
    line = assert_user_error(run_in_process("pose", "-m", xml, "-o", tmp_path / "out.npz"))
    assert "mesh/part" in line and "synthetic.h5" in line


def test_unreadable_arrays_file_is_reported(model_path, tmp_path):
    xml = tmp_path / "synthetic.xml"
    xml.write_text(model_path.read_text())
    (tmp_path / "synthetic.h5").write_text("this is not HDF5")
    line = assert_user_error(run_in_process("info", "-m", xml))
    assert "synthetic.h5" in line


def test_import_of_a_damaged_mesh_is_a_user_error(tmp_path):
    damaged = tmp_path / "scan.ply"
    damaged.write_text("ply\nformat ascii 1.0\nthis is not a header\n")
    line = assert_user_error(run_in_process("import-mesh", damaged, "-o", tmp_path / "out.xml"))
    assert "scan.ply" in line


# ---------------------------------------------------------------------------
# pose and import-mesh
# ---------------------------------------------------------------------------

POSE = {"head_turn": 0.3, "eye_left_turn": -0.5, "brow_raise": 1.0}


def _set_args() -> list[str]:
    return ["--set", *(f"{k}={v}" for k, v in list(POSE.items())[:2]), "--set", "brow_raise=1"]


def test_pose_npz_keeps_the_model_vertex_order(model_path, tmp_path):
    out = tmp_path / "pose.npz"
    result = run("pose", "-m", model_path, *_set_args(), "-o", out)
    assert result.returncode == 0, result.stderr
    model = load_model(model_path)
    with np.load(out) as data:
        np.testing.assert_array_equal(data["vertices"], model.deform(POSE))
        np.testing.assert_array_equal(data["faces"], model.faces)
        np.testing.assert_array_equal(data["triangles"], model.triangles())
        assert data["vertices"].dtype == np.float64


def test_pose_obj_reads_back_with_quads_and_parts(model_path, tmp_path):
    from engine.formats.mesh_io import import_mesh

    out = tmp_path / "pose.obj"
    assert run("pose", "-m", model_path, *_set_args(), "-o", out).returncode == 0
    model = load_model(model_path)
    back = import_mesh(out)
    np.testing.assert_array_equal(back.vertices, model.deform(POSE))
    np.testing.assert_array_equal(back.faces, model.faces)
    assert back.parts == model.parts
    np.testing.assert_array_equal(back.vertex_part, model.vertex_part)


@pytest.mark.slow
def test_pose_ply_reads_back_with_pyvista(model_path, tmp_path):
    pv = pytest.importorskip("pyvista")
    out = tmp_path / "pose.ply"
    assert run("pose", "-m", model_path, *_set_args(), "-o", out).returncode == 0
    model = load_model(model_path)
    mesh = pv.read(out)
    # VTK's PLY reader keeps float32 points; the file itself holds doubles (see test_mesh_io)
    np.testing.assert_allclose(np.asarray(mesh.points, dtype=float), model.deform(POSE), rtol=0, atol=1e-4)
    np.testing.assert_array_equal(np.asarray(mesh.faces), model.faces)


def test_import_mesh_makes_a_model_without_parameters(tmp_path):
    obj = tmp_path / "plate.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n")
    out = tmp_path / "plate.xml"
    result = run("import-mesh", obj, "-o", out, "--scale", "10")
    assert result.returncode == 0, result.stderr
    model = load_model(out)
    assert len(model.parameters) == 0 and model.parts == ["surface"]
    np.testing.assert_array_equal(model.faces, [4, 0, 1, 2, 3, 3, 1, 4, 2])
    assert model.vertices[4].tolist() == [20.0, 0.0, 0.0]
    info = json.loads(run("info", "-m", out, "--json").stdout)
    assert info == {"parameters": [], "landmarks": {}, "vertices": 5}


# ---------------------------------------------------------------------------
# render
# ---------------------------------------------------------------------------

def _assert_face_in_picture(image: np.ndarray) -> None:
    """The centre differs from the background and holds skin-coloured pixels."""
    h, w = image.shape[:2]
    corner = image[2, 2].astype(int)
    centre = image[h // 3:2 * h // 3, w // 3:2 * w // 3].reshape(-1, 3).astype(int)
    differs = np.abs(centre - corner).sum(axis=1) > 40
    assert differs.mean() > 0.9
    r, g, b = centre.T
    skin_like = (r > 90) & (r > g + 10) & (g > b) & (r - b > 30)
    assert skin_like.mean() > 0.5


@pytest.mark.slow
def test_render_writes_a_png_with_the_face_in_it_and_no_noise(model_path, tmp_path):
    out = tmp_path / "face.png"
    result = run("render", "-m", model_path, "--set", "head_turn=0.2", "--size", "160x200", "-o", out)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""  # in particular no "bad X server connection" from VTK
    image = read_png(out)
    assert image.shape == (200, 160, 3)
    _assert_face_in_picture(image)


@pytest.mark.slow
def test_render_model_views_in_process(model_path, tmp_path):
    from engine.outputs.render import render_model

    model = load_model(model_path)
    pictures = {view: render_model(model, view=view, size=(120, 150)) for view in ("front", "side", "three-quarter")}
    for image in pictures.values():
        assert image.shape == (150, 120, 3) and image.dtype == np.uint8
        _assert_face_in_picture(image)
    assert not np.array_equal(pictures["front"], pictures["side"])
    # the eyes get a dark pupil: the front view holds near-black pixels, the back of the head none
    assert (pictures["front"].sum(axis=2) < 120).any()
    path = tmp_path / "again.png"
    again = render_model(model, view="front", size=(120, 150), path=path)
    np.testing.assert_array_equal(read_png(path), again)


# ---------------------------------------------------------------------------
# The shipped default head (skips until it is built)
# ---------------------------------------------------------------------------

def test_default_head_info_lists_its_parameters(default_head):
    result = run("info", "--json")
    assert result.returncode == 0, result.stderr
    info = json.loads(result.stdout)
    names = {p["name"] for p in info["parameters"]}
    assert names >= DEFAULT_HEAD_PARAMETERS
    assert info["vertices"] == load_model(default_head).n_vertices
    roots = [p for p in info["parameters"] if p["parent"] is None]
    assert roots and all(p["group"] in (1, 2) for p in info["parameters"])


def test_default_head_pose_npz(default_head, tmp_path):
    out = tmp_path / "pose.npz"
    result = run("pose", "--set", "jaw_open=0.5", "head_turn=0.2", "-o", out)
    assert result.returncode == 0, result.stderr
    with np.load(out) as data:
        np.testing.assert_array_equal(data["vertices"], load_model(default_head).deform(jaw_open=0.5, head_turn=0.2))


@pytest.mark.slow
def test_default_head_renders_with_the_face_in_it(default_head, tmp_path):
    out = tmp_path / "head.png"
    result = run("render", "--set", "jaw_open=0.3", "--view", "three-quarter", "--size", "240x300", "-o", out)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    _assert_face_in_picture(read_png(out))


#: A command run with the memory it may still take capped at 8 MB more than it had once imported: loading the
#: default head then fails with a real MemoryError, as a damaged count in an input makes it fail.
_OUT_OF_MEMORY = """
import resource, sys
import engine.cli
engine.cli.build_parser()
with open("/proc/self/statm") as statm:
    used = int(statm.read().split()[0]) * resource.getpagesize()
resource.setrlimit(resource.RLIMIT_AS, (used + 8 * 2**20, resource.RLIM_INFINITY))
sys.exit(engine.cli.main(["pose", "-o", sys.argv[1]]))
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/self/statm and caps RLIMIT_AS")
def test_running_out_of_memory_is_one_error_line_not_a_traceback(tmp_path):
    result = subprocess.run([sys.executable, "-c", _OUT_OF_MEMORY, str(tmp_path / "pose.npz")],
                            capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith("error: out of memory:") and result.stderr.count("\n") == 1, result.stderr
    assert not (tmp_path / "pose.npz").exists()
