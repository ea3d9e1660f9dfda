"""glTF 2.0 export (engine/outputs/gltf_export.py, ``export-gltf``): round trip, morph targets, the default head.

A small hand-made model (two parts of quads, a rotation parent with a
rotation, a uniform and a field translation below it) checks the arrays
exactly; the default head checks size, ARKit names, VTK's reading and the CLI.
"""

from __future__ import annotations

import json
import struct

import h5py
import numpy as np
import pytest

from engine import InfluenceRegion, Model, Parameter, ParameterTree, UserError
from engine.formats.gltf_document import quaternion_matrix as _matrix
from engine.model.cells import cells_to_triangles
from engine.outputs.gltf_export import (
    METRES_PER_MM,
    MODEL_VERTEX,
    GltfFileError,
    MorphTarget,
    export_gltf,
    export_summary,
    export_targets,
    glb_bytes,
    gltf_document,
    is_shipped_head,
    parameter_targets,
    pose_group_names,
    pose_targets,
    read_gltf,
    skeleton_parameters,
    target_value,
)
from engine.outputs.gltf_skeleton import quaternion, rotation_from_x
from engine.outputs.part_layout import PartLayout
from engine.paths import default_model_path, reference_poses_path
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

ARKIT_SAMPLE = ("jawOpen", "mouthSmileLeft", "eyeBlinkRight", "browInnerUp", "tongueOut")


# ---------------------------------------------------------------------------
# A small model: a 4×3 grid of quads (skin) and a 2×2 grid (eye), mm
# ---------------------------------------------------------------------------

def _grid(nx: int, ny: int, origin, step: float = 10.0):
    x, y = np.meshgrid(np.arange(nx + 1) * step, np.arange(ny + 1) * step, indexing="xy")
    points = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1) + origin
    at = lambda i, j: j * (nx + 1) + i  # noqa: E731
    faces = [[4, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)] for j in range(ny) for i in range(nx)]
    return points, faces


def small_model() -> Model:
    skin, skin_faces = _grid(4, 3, (0.0, 100.0, 50.0))
    eye, eye_faces = _grid(2, 2, (10.0, 110.0, 60.0), step=5.0)
    n_skin = len(skin)
    vertices = np.vstack([skin, eye])
    eye_offset = np.array([0, n_skin, n_skin, n_skin, n_skin])
    faces = np.concatenate([np.ravel(skin_faces), (np.array(eye_faces) + eye_offset).ravel()])
    n = len(vertices)
    vertex_part = np.r_[np.zeros(n_skin, int), np.ones(len(eye), int)]
    colours = np.tile([227, 180, 156], (n, 1)).astype(np.uint8)
    colours[n_skin:] = [243, 240, 234]
    colours[n_skin + 4] = [20, 16, 16]                  # a pupil: the eye is not one colour
    rng = np.random.default_rng(6)
    tree = ParameterTree([
        Parameter("head_turn", "rotation", axis=(0, 1, 0), pivot=(20, 0, 0), minimum=-0.6, maximum=0.6,
                  degrees_per_unit=57.2958),
        Parameter("brow", "rotation", parent="head_turn", axis=(1, 0, 0), pivot=(0, 110, 0), minimum=-0.5,
                  maximum=1.5, degrees_per_unit=10.0),
        Parameter("slide", "translation", parent="head_turn", direction=(0, 2.5, 1.0), minimum=-1, maximum=0,
                  default=-0.25),
        Parameter("smile", "translation", parent="head_turn", field=True, minimum=0, maximum=1.2),
    ])
    skin_idx = np.arange(n_skin)
    regions = {
        "head_turn": InfluenceRegion(np.arange(n), np.ones(n)),
        "brow": InfluenceRegion(skin_idx[10:], np.linspace(0.2, 1.0, n_skin - 10)),
        "slide": InfluenceRegion(skin_idx[:8], np.full(8, 0.5)),
        "smile": InfluenceRegion(skin_idx[3:12], rng.uniform(0.3, 1, 9), rng.normal(0, 2.0, (9, 3))),
    }
    return Model(vertices, faces, ["skin", "eye_left"], vertex_part, tree, regions, name="small",
                 part_colors={"skin": "#e3b49c", "eye_left": "#f3f0ea"}, vertex_colors=colours)


def f32_tolerance(model: Model) -> float:
    """Two float32 roundings (base and target) at the model's size, in metres."""
    return 4 * float(np.spacing(np.float32(np.abs(model.vertices).max() * METRES_PER_MM + 0.05)))


def linear(srgb) -> np.ndarray:
    """8-bit sRGB → linear light (the sRGB standard's curve), as glTF stores colours."""
    c = np.asarray(srgb) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


@pytest.fixture(scope="module")
def model() -> Model:
    return small_model()


@pytest.fixture(scope="module")
def targets(model) -> list[MorphTarget]:
    extra = np.zeros((model.n_vertices, 3))
    extra[model.part_vertices("eye_left")] = (0.0, 0.0, 1.5)        # an extra pose that moves the eye only
    return [*parameter_targets(model), MorphTarget("eyeForward", extra, "poses")]


# ---------------------------------------------------------------------------
# Round trip
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", [".glb", ".gltf"])
def test_round_trip(model, targets, tmp_path, suffix):
    path = tmp_path / f"small{suffix}"
    written = export_gltf(model, path, targets)
    mesh = read_gltf(path)
    if suffix == ".gltf":
        assert (tmp_path / "small.bin").exists()
        assert json.loads(path.read_text())["buffers"][0]["uri"] == "small.bin"
    assert mesh.target_names == written.target_names == ["head_turn", "brow", "slide", "smile", "eyeForward"]
    assert mesh.document["meshes"][0]["extras"]["targetNames"] == mesh.target_names
    assert np.array_equal(mesh.weights, np.zeros(5))
    layout = PartLayout(model)
    rest = model.deform()
    _, normals = layout.points_and_normals(rest)
    assert [p.name for p in mesh.primitives] == ["skin", "eye_left"]
    for k, prim in enumerate(mesh.primitives):
        used = layout.used(k)
        start, stop = layout.slices[k]
        assert np.array_equal(prim.model_vertex, used)
        assert np.array_equal(prim.positions, (rest[used] * METRES_PER_MM).astype(np.float32))
        assert np.array_equal(prim.normals, normals[start:stop].astype(np.float32))
        part = model.parts.index(prim.name)
        part_cells = model.faces.reshape(-1, 5)[model.vertex_part[model.faces.reshape(-1, 5)[:, 1]] == part]
        assert np.array_equal(used[prim.triangles], cells_to_triangles(part_cells.ravel()))
        for t, target in zip(targets, prim.targets, strict=True):
            assert np.array_equal(target["POSITION"], (t.displacements[used] * METRES_PER_MM).astype(np.float32))
            assert target["NORMAL"].shape == prim.positions.shape
    skin, eye = mesh.primitives
    assert skin.colors is None and eye.colors is not None         # COLOR_0 only where a part is not one colour
    assert skin.material["pbrMetallicRoughness"]["baseColorFactor"][:3] == pytest.approx(
        linear([227, 180, 156]), abs=1e-6)
    assert eye.material["pbrMetallicRoughness"]["baseColorFactor"] == [1.0, 1.0, 1.0, 1.0]
    assert eye.colors[4] == pytest.approx(linear([20, 16, 16]), abs=1e-6)
    assert eye.colors[0] == pytest.approx(linear([243, 240, 234]), abs=1e-6)
    assert not skin.targets[4]["POSITION"].any()                # the eye pose leaves the skin alone


def test_every_bound_is_exact_and_every_view_aligned(model, targets):
    document, data = gltf_document(model, targets)
    mesh = document["meshes"][0]
    positions = {p["attributes"]["POSITION"] for p in mesh["primitives"]}
    positions |= {t["POSITION"] for p in mesh["primitives"] for t in p["targets"]}
    for index in positions:
        assert "min" in document["accessors"][index] and "max" in document["accessors"][index]
    for view in document["bufferViews"]:
        assert view["byteOffset"] % 4 == 0
    reread = read_gltf_from(document, data)
    for index, accessor in enumerate(document["accessors"]):
        if "min" in accessor:
            values = reread[index].reshape(accessor["count"], -1)
            assert np.array_equal(values.min(axis=0), np.float32(accessor["min"]))
            assert np.array_equal(values.max(axis=0), np.float32(accessor["max"]))


def read_gltf_from(document: dict, data: bytes) -> dict[int, np.ndarray]:
    """Every accessor's data, decoded independently of the module's reader."""
    types = {5126: "<f4", 5123: "<u2", 5125: "<u4"}
    out = {}
    for i, a in enumerate(document["accessors"]):
        view = document["bufferViews"][a["bufferView"]]
        width = {"SCALAR": 1, "VEC3": 3}[a["type"]]
        out[i] = np.frombuffer(data, types[a["componentType"]], a["count"] * width, view["byteOffset"])
    return out


def test_glb_container_layout(model, targets):
    document, data = gltf_document(model, targets)
    blob = glb_bytes(document, data)
    magic, version, length = struct.unpack_from("<III", blob)
    assert (magic, version, length) == (0x46546C67, 2, len(blob))
    json_length, json_kind = struct.unpack_from("<II", blob, 12)
    assert json_kind == 0x4E4F534A and json_length % 4 == 0
    assert json.loads(blob[20:20 + json_length]) == json.loads(json.dumps(document))
    bin_length, bin_kind = struct.unpack_from("<II", blob, 20 + json_length)
    assert bin_kind == 0x004E4942 and bin_length == len(data) and bin_length % 4 == 0


# ---------------------------------------------------------------------------
# Morph targets against model.deform
# ---------------------------------------------------------------------------

def test_translation_targets_reproduce_deform(model, tmp_path):
    mesh = export_gltf(model, tmp_path / "t.glb", parameter_targets(model, ["slide", "smile"]))
    tol = f32_tolerance(model)
    smile = model.parameters["smile"]
    for weight in (1.0, 0.37, -0.5):          # a field translation is linear in its value: exact at any weight
        value = weight * target_value(smile)
        np.testing.assert_allclose(mesh.model_positions(model.n_vertices, {"smile": weight}),
                                   model.deform({"smile": value}) * METRES_PER_MM, rtol=0, atol=tol)
    slide = model.parameters["slide"]         # default −0.25, range [−1, 0]: weight w ↔ value −0.25 + 0.25 w
    assert target_value(slide) == 0.0
    for weight in (1.0, 0.5, -3.0):
        value = slide.default + weight * (target_value(slide) - slide.default)
        np.testing.assert_allclose(mesh.model_positions(model.n_vertices, {"slide": weight}),
                                   model.deform({"slide": value}) * METRES_PER_MM, rtol=0, atol=tol)
    np.testing.assert_allclose(mesh.model_positions(model.n_vertices), model.deform() * METRES_PER_MM,
                               rtol=0, atol=tol)


@pytest.mark.parametrize("name", ["head_turn", "brow"])
def test_rotation_targets_are_their_chord(model, tmp_path, name):
    target, = parameter_targets(model, [name])
    assert target.linearised and target.value == target_value(model.parameters[name])
    mesh = export_gltf(model, tmp_path / "r.glb", [target])
    tol = f32_tolerance(model)
    rest, pose = model.deform(), model.deform({name: target.value})
    np.testing.assert_allclose(mesh.model_positions(model.n_vertices, {name: 1.0}), pose * METRES_PER_MM,
                               rtol=0, atol=tol)
    chord = mesh.model_positions(model.n_vertices, {name: 0.5})
    np.testing.assert_allclose(chord, (rest + pose) / 2 * METRES_PER_MM, rtol=0, atol=tol)
    arc = model.deform({name: target.value / 2})
    error = np.linalg.norm(chord / METRES_PER_MM - arc, axis=1).max()
    assert error > 0.01 and error == pytest.approx(target.chord_error_mm, abs=1e-3)
    assert mesh.document["meshes"][0]["extras"]["targets"][0]["linearised"] is True


def test_target_value_rule():
    def p(lo, hi, default=0.0):
        return Parameter("p", "rotation", minimum=lo, maximum=hi, default=default)

    assert target_value(p(-1, 1)) == 1.0
    assert target_value(p(-0.5, 1.2)) == 1.0
    assert target_value(p(-0.6, 0.6)) == 0.6
    assert target_value(p(-1, 0)) == -1.0


def test_selection_and_values(model):
    chosen = parameter_targets(model, ["smile", "brow"], {"brow": -0.5})
    assert [t.name for t in chosen] == ["smile", "brow"] and chosen[1].value == -0.5
    assert [t.name for t in parameter_targets(model)] == ["head_turn", "brow", "slide", "smile"]
    with pytest.raises(UserError, match="unknown parameter 'smil'"):
        parameter_targets(model, ["smil"])
    with pytest.raises(UserError, match="named twice"):
        parameter_targets(model, ["brow", "brow"])
    with pytest.raises(UserError, match="outside its range"):
        parameter_targets(model, ["brow"], {"brow": 2.0})
    with pytest.raises(UserError, match="its default"):
        parameter_targets(model, ["slide"], {"slide": -0.25})
    with pytest.raises(UserError, match="not exported"):
        parameter_targets(model, ["smile"], {"brow": 1.0})
    twice = parameter_targets(model, ["brow"]) * 2
    with pytest.raises(UserError, match="both named 'brow'"):
        gltf_document(model, twice)


def test_a_model_without_targets_exports(model, tmp_path):
    mesh = export_gltf(model, tmp_path / "plain.glb")
    assert mesh.target_names == [] and all(p.targets == [] for p in mesh.primitives)
    assert "targets" not in mesh.document["meshes"][0]["primitives"][0]


# ---------------------------------------------------------------------------
# Skeleton: group-1 parameters as joints
# ---------------------------------------------------------------------------

def test_skeleton_reproduces_deform(model, tmp_path):
    assert skeleton_parameters(model) == ["head_turn"]
    leaves = parameter_targets(model, ["brow", "slide", "smile"])
    mesh = export_gltf(model, tmp_path / "rig.glb", leaves, skeleton=True)
    assert mesh.skin.names == ["root", "head_turn"] and mesh.skin.parents == [-1, 0]
    tol = f32_tolerance(model)
    for turn in (0.0, 0.4, -0.6):
        for smile in (0.0, 0.5):                 # leaf motion authored at rest, carried by the joint
            np.testing.assert_allclose(
                mesh.model_positions(model.n_vertices, {"smile": smile / target_value(model.parameters["smile"])},
                                     joints={"head_turn": turn}),
                model.deform({"head_turn": turn, "smile": smile}) * METRES_PER_MM, rtol=0, atol=tol)
    with pytest.raises(UserError, match="is a joint of the skeleton"):
        gltf_document(model, parameter_targets(model, ["head_turn"]), skeleton=True)
    with pytest.raises(UserError, match="no joint named 'brow'"):
        mesh.model_positions(model.n_vertices, joints={"brow": 0.1})


def test_skeleton_needs_rigid_parameters_at_rest_at_zero(model):
    shifted = model.copy()
    shifted.parameters.replace(shifted.parameters["head_turn"].copy(default=0.1))
    with pytest.raises(UserError, match=r"rests at 0\.1"):
        gltf_document(shifted, skeleton=True)


def test_reader_refuses_a_broken_skin(model, tmp_path):
    document, data = gltf_document(model, skeleton=True)
    document["skins"][0]["joints"].pop()
    path = tmp_path / "skin.glb"
    path.write_bytes(glb_bytes(document, data))
    with pytest.raises(GltfFileError, match="2 inverse bind matrices for 1 joints"):
        read_gltf(path)


@pytest.mark.parametrize("seed", range(4))
def test_joint_frames_and_quaternions(seed):
    rng = np.random.default_rng(seed)
    axes = [rng.normal(size=3) for _ in range(20)] + [np.array(a, float) for a in
                                                      ([1, 0, 0], [-1, 0, 0], [0, -1, 0], [0, 0, 1], [-1, 1e-9, 0])]
    for axis in axes:
        a = axis / np.linalg.norm(axis)
        r = rotation_from_x(a)
        assert np.allclose(r @ [1, 0, 0], a, atol=1e-12) and np.allclose(r.T @ r, np.eye(3), atol=1e-12)
        assert np.linalg.det(r) == pytest.approx(1.0)
        assert np.allclose(_matrix(quaternion(r)), r, atol=1e-12)
    for angle, direction in ((np.pi, (1, 1, 0)), (np.pi, (0, 1, 1)), (np.pi - 1e-9, (1, 2, 3))):
        axis = np.array(direction) / np.linalg.norm(direction)
        k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        r = np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k
        assert np.allclose(_matrix(quaternion(r)), r, atol=1e-9)


# ---------------------------------------------------------------------------
# Pose files
# ---------------------------------------------------------------------------

def write_poses(path, n_vertices: int, *, kind="artificial-person-poses", version=1) -> None:
    with h5py.File(path, "w") as f:
        f.attrs.update(format=kind, version=version, units="mm")
        f["source_vertex"] = np.arange(n_vertices)
        g = f.create_group("arkit/jawOpen")
        g["indices"] = np.array([1, 3], dtype=np.int32)
        g["displacements"] = np.array([[0, -1, 0], [0, -2, 0.5]], dtype=np.float32)


def test_pose_targets_from_a_file(model, tmp_path):
    path = tmp_path / "poses.h5"
    write_poses(path, model.n_vertices)
    target, = pose_targets(model, path)
    assert target.name == "jawOpen" and target.source == "arkit"
    expected = np.zeros((model.n_vertices, 3))
    expected[[1, 3]] = [[0, -1, 0], [0, -2, 0.5]]
    assert np.array_equal(target.displacements, expected)


@pytest.mark.parametrize("change, message", [
    (dict(kind="something-else"), "not a poses file"),
    (dict(version=2), "version 2 is not known"),
    (dict(n=7), "made for a model of 7 vertices"),
])
def test_bad_pose_files(model, tmp_path, change, message):
    path = tmp_path / "poses.h5"
    write_poses(path, change.pop("n", model.n_vertices), **change)
    with pytest.raises(UserError, match=message):
        pose_targets(model, path)


def test_unknown_pose_group(model, tmp_path):
    path = tmp_path / "poses.h5"
    write_poses(path, model.n_vertices)
    with pytest.raises(UserError, match=r"no pose group 'expressions' \(groups: arkit"):
        pose_targets(model, path, "expressions")


def test_pose_group_names(model, tmp_path):
    path = tmp_path / "poses.h5"
    write_poses(path, model.n_vertices)
    assert pose_group_names(path) == ["arkit"]
    write_poses(path, model.n_vertices, kind="something-else")
    with pytest.raises(UserError, match="not a poses file"):
        pose_group_names(path)
    with pytest.raises(UserError, match="cannot read the poses"):
        pose_group_names(tmp_path / "missing.h5")


# ---------------------------------------------------------------------------
# Choosing the targets of an export (the CLI's and the workbench's one decision)
# ---------------------------------------------------------------------------

def test_export_targets_for_another_model(model, tmp_path):
    assert [t.name for t in export_targets(model)] == ["head_turn", "brow", "slide", "smile"]   # no ARKit
    assert [t.name for t in export_targets(model, skeleton=True)] == ["brow", "slide", "smile"]  # no joints
    chosen = export_targets(model, ["smile", "brow"], {"brow": -0.5}, skeleton=True)
    assert [(t.name, t.value) for t in chosen] == [("smile", 1.0), ("brow", -0.5)]
    with pytest.raises(UserError, match="'head_turn' is a joint of the skeleton"):
        export_targets(model, ["brow", "head_turn"], skeleton=True)
    for choice in (dict(arkit=True), dict(pose_groups=["expression_units"])):
        with pytest.raises(UserError, match="the shipped poses fit the shipped head only"):
            export_targets(model, **choice)
    path = tmp_path / "poses.h5"
    write_poses(path, model.n_vertices)
    with_poses = export_targets(model, ["smile"], arkit=True, poses=path, pose_groups=["arkit"])
    assert [(t.name, t.source) for t in with_poses] == [("smile", "parameter"), ("jawOpen", "arkit")]
    assert not is_shipped_head(None) and not is_shipped_head(tmp_path / "head.xml")


def test_export_targets_for_the_shipped_head(head):
    if not default_model_path().exists():
        pytest.skip("the default head is not built")
    assert is_shipped_head(default_model_path())
    arkit = export_targets(head, [], model_file=default_model_path())       # ARKit by default
    assert len(arkit) == 52 and {t.source for t in arkit} == {"arkit"}
    assert export_targets(head, [], arkit=False, model_file=default_model_path()) == []
    assert pose_group_names()[0] == "arkit"


@pytest.mark.parametrize("suffix", [".glb", ".gltf"])
def test_export_summary_names_parts_vertices_targets_joints_and_size(model, tmp_path, suffix):
    path = tmp_path / f"rig{suffix}"
    mesh = export_gltf(model, path, export_targets(model, skeleton=True), skeleton=True)
    size = path.stat().st_size + (path.with_suffix(".bin").stat().st_size if suffix == ".gltf" else 0)
    assert export_summary(path, mesh) == (f"2 parts, {mesh.n_points} vertices, 3 morph targets, 2 joints, "
                                          f"{-(-size // 1000)} kB")
    with pytest.raises(UserError, match="cannot read the poses"):
        pose_targets(model, tmp_path / "missing.h5")


# ---------------------------------------------------------------------------
# The reader refuses broken files
# ---------------------------------------------------------------------------

def tampered(model, targets, tmp_path, edit) -> object:
    document, data = gltf_document(model, targets)
    edit(document)
    path = tmp_path / "broken.glb"
    path.write_bytes(glb_bytes(document, data))
    return path


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["asset"].update(version="1.0"), "not a glTF 2.0 document"),
    (lambda d: d["buffers"][0].update(byteLength=d["buffers"][0]["byteLength"] + 64), "byteLength"),
    (lambda d: d["accessors"][0].update(count=10 ** 6), "do not fit in bufferView"),
    (lambda d: d["accessors"][0].update(max=[1.0, 1.0, 1.0]), "max .* does not match"),
    (lambda d: d["meshes"][0]["primitives"][1]["targets"].pop(), "different numbers of morph targets"),
    (lambda d: d["meshes"][0].update(weights=[0.0]), "morph targets but 1 weights"),
    (lambda d: d["meshes"][0]["primitives"][0].update(mode=1), "only triangles"),
    (lambda d: d["meshes"].clear(), "no mesh"),
    (lambda d: d["meshes"][0]["primitives"][0].pop("attributes"), "malformed glTF document"),
])
def test_reader_refuses_broken_documents(model, targets, tmp_path, edit, message):
    with pytest.raises(GltfFileError, match=message):
        read_gltf(tampered(model, targets, tmp_path, edit))


def test_reader_refuses_an_index_past_the_vertices(model, tmp_path):
    document, data = gltf_document(model)
    primitive = document["meshes"][0]["primitives"][1]             # the eye: 9 points
    view = document["bufferViews"][document["accessors"][primitive["indices"]]["bufferView"]]
    data = bytearray(data)
    struct.pack_into("<H", data, view["byteOffset"], 9)
    path = tmp_path / "index.glb"
    path.write_bytes(glb_bytes(document, bytes(data)))
    with pytest.raises(GltfFileError, match="triangles of vertices below 9"):
        read_gltf(path)


def test_reader_refuses_broken_containers(model, tmp_path):
    blob = glb_bytes(*gltf_document(model))
    path = tmp_path / "cut.glb"
    path.write_bytes(blob[:-8])
    with pytest.raises(GltfFileError, match="the header says"):
        read_gltf(path)
    path.write_bytes(b"not a glTF")
    with pytest.raises(GltfFileError, match="neither a binary glTF nor JSON"):
        read_gltf(path)
    export_gltf(model, tmp_path / "a.gltf")
    (tmp_path / "a.bin").unlink()
    with pytest.raises(GltfFileError, match=r"cannot read 'a\.bin'"):
        read_gltf(tmp_path / "a.gltf")
    with pytest.raises(UserError, match=r"use \.glb or \.gltf"):
        export_gltf(model, tmp_path / "a.obj")


# ---------------------------------------------------------------------------
# The default head
# ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def head_export(head, tmp_path_factory):
    path = tmp_path_factory.mktemp("head") / "head.glb"
    mesh = export_gltf(head, path, parameter_targets(head) + pose_targets(head))
    return head, path, mesh


def test_default_head_exports(head_export):
    head, path, mesh = head_export
    size = path.stat().st_size
    assert 1e6 < size < 20e6                     # 7.5 MB with 17 parameters and ARKit-52 (docs/export.md)
    assert mesh.n_points >= head.n_vertices - 10
    assert len(mesh.target_names) == len(head.parameters) + 52
    assert set(ARKIT_SAMPLE) <= set(mesh.target_names)
    assert [p.name for p in mesh.primitives] == head.parts
    with h5py.File(reference_poses_path()) as f:
        g = f["arkit/mouthSmileLeft"]
        idx, disp = g["indices"][()], g["displacements"][()]
    moved = mesh.model_positions(head.n_vertices, {"mouthSmileLeft": 1.0})
    expected = head.vertices.copy()
    expected[idx] += disp
    np.testing.assert_allclose(moved, expected * METRES_PER_MM, rtol=0, atol=f32_tolerance(head))
    np.testing.assert_allclose(mesh.model_positions(head.n_vertices, {"jaw_open": 1.0}),
                               head.deform(jaw_open=1.0) * METRES_PER_MM, rtol=0, atol=f32_tolerance(head))


def test_vtk_reads_the_default_head(head_export):
    pv = pytest.importorskip("pyvista")
    _head, path, mesh = head_export
    blocks = list(pv.read(str(path))[0][0])
    assert [b.n_points for b in blocks] == [len(p.positions) for p in mesh.primitives]
    assert [b.n_cells for b in blocks] == [len(p.triangles) for p in mesh.primitives]
    skin, skin_prim = blocks[0], mesh.primitives[0]
    assert np.allclose(skin.points, skin_prim.positions, rtol=0, atol=1e-9)
    index = mesh.target_names.index("jawOpen")
    assert np.array_equal(skin.point_data[f"target{index}_position"], skin_prim.targets[index]["POSITION"])
    assert np.array_equal(skin.point_data[MODEL_VERTEX], skin_prim.model_vertex)


def test_default_head_with_a_skeleton_is_exact_where_morphs_are_not(head_export, tmp_path):
    head = head_export[0]
    joints = skeleton_parameters(head)
    assert {"head_turn", "jaw_open", "eye_left_turn"} <= set(joints)
    leaves = [n for n, _ in head.parameters.depth_first() if n not in joints]
    mesh = export_gltf(head, tmp_path / "rig.glb", parameter_targets(head, leaves), skeleton=True)
    pose = {"head_turn": 0.3, "jaw_open": 0.5, "neck_lean": -0.2, "eye_left_turn": 0.4}
    expected = head.deform({**pose, "lower_lip_raise": 1.0, "mouth_widen": 0.6})
    rigged = mesh.model_positions(head.n_vertices, {"lower_lip_raise": 1.0, "mouth_widen": 0.6}, joints=pose)
    np.testing.assert_allclose(rigged, expected * METRES_PER_MM, rtol=0, atol=f32_tolerance(head))
    morphs = head_export[2]                        # the same pose as a sum of morph targets is centimetres off
    chord = morphs.model_positions(head.n_vertices, {
        **{k: v / target_value(head.parameters[k]) for k, v in pose.items()},
        "lower_lip_raise": 1.0, "mouth_widen": 0.6})
    assert np.linalg.norm(chord / METRES_PER_MM - expected, axis=1).max() > 5.0


@pytest.mark.slow
def test_cli_exports_a_selection(tmp_path):
    if not default_model_path().exists():
        pytest.skip("the default head is not built")
    result = run("export-gltf", "--parameters", "jaw_open,brow_raise", "--value", "jaw_open=0.5", "--no-arkit",
                 "-o", tmp_path / "sel.gltf")
    assert result.returncode == 0, result.stderr
    assert "2 morph targets" in result.stdout
    mesh = read_gltf(tmp_path / "sel.gltf")
    assert mesh.target_names == ["jaw_open", "brow_raise"]
    assert mesh.document["meshes"][0]["extras"]["targets"][0]["value"] == 0.5
    result = run("export-gltf", "--skeleton", "--no-arkit", "-o", tmp_path / "rig.glb")
    assert result.returncode == 0, result.stderr
    assert ", 8 joints, " in result.stdout
    rig = read_gltf(tmp_path / "rig.glb")
    assert "jaw_open" in rig.skin.names and "jaw_open" not in rig.target_names and "mouth_widen" in rig.target_names


@pytest.mark.slow
@pytest.mark.parametrize("arguments, message", [
    (["-o", "head.obj"], "unknown output extension '.obj'"),
    (["--parameters", "jaw_opn", "-o", "x.glb"], "unknown parameter 'jaw_opn'"),
    (["--value", "jaw_open=5", "-o", "x.glb"], "outside its range"),
    (["--value", "jaw_open", "-o", "x.glb"], "is not NAME=VALUE"),
    (["--pose-group", "nope", "-o", "x.glb"], "no pose group 'nope'"),
    (["--arkit", "--no-arkit", "-o", "x.glb"], "not allowed with argument"),
    (["--skeleton", "--parameters", "head_nod", "-o", "x.glb"], "'head_nod' is a joint of the skeleton"),
])
def test_cli_errors(tmp_path, arguments, message):
    if not default_model_path().exists():
        pytest.skip("the default head is not built")
    line = assert_user_error(run_in_process("export-gltf", *arguments, cwd=tmp_path))
    assert message in line, line
    assert not list(tmp_path.iterdir())


@pytest.mark.slow
def test_cli_needs_a_poses_file_for_another_model(tmp_path):
    from engine import save_model

    save_model(small_model(), tmp_path / "small.xml")
    line = assert_user_error(run_in_process("export-gltf", "-m", tmp_path / "small.xml", "--arkit", "-o",
                                            tmp_path / "s.glb"))
    assert "the shipped poses fit the shipped head only" in line and "--poses" in line
    result = run("export-gltf", "-m", tmp_path / "small.xml", "-o", tmp_path / "s.glb")
    assert result.returncode == 0, result.stderr
    assert read_gltf(tmp_path / "s.glb").target_names == ["head_turn", "brow", "slide", "smile"]
