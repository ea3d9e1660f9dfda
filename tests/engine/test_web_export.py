"""``web-export``: the site's files, the compact model, the animation table, and bad input (no browser here:
tests/engine/test_web_browser.py opens the sites in Chromium). Real Festival, real files, the real CLI."""

from __future__ import annotations

import csv
import io
import json
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from engine.outputs.gltf_export import glb_bytes, gltf_document, parameter_targets
from engine.outputs.gltf_skeleton import skeleton_parameters
from engine.speech.say import speak
from engine.web.animation import dequantised
from engine.web.player_bundle import IMPORT
from engine.web.site import SITE_FILES, write_speech_site
from engine.web.web_model import QUANTISATION, dequantised_target, web_glb, web_gltf_document
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, made_set, run

SENTENCE = "Pappa osti mummolle paljon omenoita."
SIZE_LIMIT = 3_000_000
ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def speech(head):
    return speak(SENTENCE, head)


@pytest.mark.slow
def test_a_sentence_becomes_a_small_offline_site(tmp_path):
    site = tmp_path / "site"
    result = run("web-export", "--say", SENTENCE, "-o", site)
    assert result.returncode == 0, result.stderr
    for name in SITE_FILES:
        assert (site / name).is_file(), name
    assert not (site / "three").exists()                     # three.js is in the bundle
    total = sum(f.stat().st_size for f in site.rglob("*") if f.is_file())
    assert total < SIZE_LIMIT, f"the site is {total / 1e6:.2f} MB"
    assert "MB in all" in result.stdout
    reported = result.stdout.split(": ", 1)[1]
    assert all(f"{name} (" in reported for name in SITE_FILES)    # every file written, and only those:
    assert "three.js" not in reported                               # three.js is inside player.js
    page = (site / "index.html").read_text()
    assert "importmap" not in page and 'from "./player.js"' in page   # the bundle needs no import map
    assert IMPORT.search((site / "player.js").read_text()) is None      # and imports nothing itself
    assert (site / "three-LICENSE.txt").read_text() == (ROOT / "engine/web/vendor/three/LICENSE").read_text()
    for name in ("index.html", "player.js"):                 # nothing named on another server
        text = (site / name).read_text().replace('"http://www.w3.org/1999/xhtml"', "")  # a namespace, not a URL
        assert not re.search(r"https?://", text), name


def test_morph_targets_read_back_as_the_engine_moves_the_vertices(head):
    targets_at = {"lower_lip_raise": 0.6, "mouth_widen": -0.4}
    document, data = web_gltf_document(head, targets_at)
    assert QUANTISATION in document["extensionsRequired"]
    assert document["meshes"][0]["extras"]["targetNames"] == list(targets_at)
    joints = [node["name"] for node in document["nodes"] if "extras" in node and "parameter" in node["extras"]]
    assert joints == skeleton_parameters(head) and "jaw_open" in joints
    exact = parameter_targets(head, list(targets_at), targets_at)
    worst = 0.0
    for primitive in document["meshes"][0]["primitives"]:
        vertices = _model_vertices(document, data, primitive)
        for k, entry in enumerate(primitive["targets"]):
            shown = dequantised_target(document, data, entry["POSITION"]) * 1000.0      # mm
            worst = max(worst, float(np.abs(shown - exact[k].displacements[vertices]).max()))
    assert 0 < worst <= 0.5 / 32767 * 1000 + 1e-9, f"{worst} mm"


def test_the_rest_mesh_is_packed_without_moving_a_vertex(head):
    document, data = web_gltf_document(head, {})
    full, full_data = gltf_document(head, [], skeleton=True)
    for packed, dense in zip(document["meshes"][0]["primitives"], full["meshes"][0]["primitives"], strict=True):
        for name, tolerance in (("POSITION", 0.0), ("NORMAL", 0.5 / 127 + 1e-9), ("COLOR_0", 0.5 / 65535 + 1e-9)):
            if name in dense["attributes"]:
                shown = _attribute(document, data, packed, name)
                assert np.abs(shown - _attribute(full, full_data, dense, name)).max() <= tolerance, name
        assert np.all(np.round(_attribute(document, data, packed, "WEIGHTS_0").sum(axis=1) * 255) == 255)
    assert _mesh_bytes(document) < 0.8 * _mesh_bytes(full)       # the images (the skin) are the same in both


def _mesh_bytes(document) -> int:
    """The bytes of a glTF document's buffer views that are not images: what packing makes smaller."""
    images = {image["bufferView"] for image in document.get("images", []) if "bufferView" in image}
    return sum(view["byteLength"] for index, view in enumerate(document["bufferViews"]) if index not in images)


def _attribute(document, data, primitive, name) -> np.ndarray:
    """A vertex attribute as a viewer reads it (normalised integers as floats, padding dropped)."""
    accessor = document["accessors"][primitive["attributes"][name]]
    view = document["bufferViews"][accessor["bufferView"]]
    dtype = np.dtype({5120: "<i1", 5121: "<u1", 5123: "<u2", 5126: "<f4"}[accessor["componentType"]])
    width = {"VEC3": 3, "VEC4": 4}[accessor["type"]]
    stride = view.get("byteStride", 0) // dtype.itemsize or width
    rows = np.frombuffer(data, dtype, accessor["count"] * stride, view["byteOffset"]).reshape(-1, stride)[:, :width]
    scale = {5120: 127.0, 5121: 255.0, 5123: 65535.0}.get(accessor["componentType"], 1.0)
    return rows / scale if accessor.get("normalized") else rows.astype(float)


def test_the_compact_targets_are_a_small_part_of_dense_ones(head):
    moving = {"lower_lip_raise": 0.6, "mouth_widen": 0.4, "lip_protrude": 0.7, "upper_lip_raise": 0.2,
              "tongue_raise": 0.8}
    bare = len(web_glb(head, {}))
    compact = len(web_glb(head, moving)) - bare
    dense = len(glb_bytes(*gltf_document(head, parameter_targets(head, list(moving), moving), skeleton=True))) - bare
    assert 0 < compact < dense / 4, (compact, dense)


def test_the_animation_table_is_the_timeline_to_its_step(head, speech, tmp_path):
    write_speech_site(speech, head, tmp_path, fps=60.0)
    animation = json.loads((tmp_path / "animation.json").read_text())
    times = speech.frame_times(60.0)
    values = speech.timeline.sample(times)
    names = list(speech.timeline.parameters)
    channels = {c["parameter"]: c for c in animation["channels"]}
    moving = {n for j, n in enumerate(names) if np.any(values[:, j] != head.parameters[n].default)}
    assert set(channels) == moving and "jaw_open" in moving
    assert channels["jaw_open"]["kind"] == "joint" and channels["lower_lip_raise"]["kind"] == "morph"
    for name, channel in channels.items():
        column = values[:, names.index(name)]
        assert np.abs(dequantised(channel) - column).max() <= channel["step"] / 2 + 1e-12, name
    assert [w["word"] for w in animation["words"]] == ["Pappa", "osti", "mummolle", "paljon", "omenoita"]
    assert animation["frames"] == len(times) and animation["frame_ms"] == pytest.approx(1000 / 60)


@pytest.mark.slow
def test_tracks_and_audio_make_the_same_animation_as_the_sentence(tmp_path):
    made = run("say", SENTENCE, "--fps", "60", "-o", tmp_path / "s.wav", "--tracks", tmp_path / "s.csv",
               "--phones", tmp_path / "s-phones.csv")
    assert made.returncode == 0, made.stderr
    assert run("web-export", "--say", SENTENCE, "-o", tmp_path / "a").returncode == 0
    result = run("web-export", "--tracks", tmp_path / "s.csv", "--audio", tmp_path / "s.wav",
                 "--phones", tmp_path / "s-phones.csv", "-o", tmp_path / "b")
    assert result.returncode == 0, result.stderr
    a, b = (json.loads((tmp_path / x / "animation.json").read_text()) for x in ("a", "b"))
    assert [c["parameter"] for c in a["channels"]] == [c["parameter"] for c in b["channels"]]
    for ca, cb in zip(a["channels"], b["channels"], strict=True):
        n = min(len(ca["values"]), len(cb["values"]))
        # the CSV holds its numbers to six digits: the two tables agree to that
        assert np.abs(dequantised(ca)[:n] - dequantised(cb)[:n]).max() < 2e-3, ca["parameter"]
    assert a["words"] == b["words"]
    assert (tmp_path / "b" / "speech.wav").read_bytes() == (tmp_path / "s.wav").read_bytes()


def test_a_site_is_written_again_over_an_earlier_one(head, speech, tmp_path):
    write_speech_site(speech, head, tmp_path / "site")
    write_speech_site(speech, head, tmp_path / "site")
    assert sorted(p.name for p in (tmp_path / "site").iterdir()) == sorted(SITE_FILES)


# -- bad input: one line, status 2 --------------------------------------------------------------------------

def test_a_broken_tracks_file_is_named_with_its_line(tmp_path):
    tracks = tmp_path / "t.csv"
    tracks.write_text("time_ms,jaw_open\n0,0.1\n33.3,lots\n")
    (tmp_path / "a.wav").write_bytes(_silent_wav())
    line = assert_user_error(run_in_process("web-export", "--tracks", tracks, "--audio", tmp_path / "a.wav", "-o",
                                 tmp_path / "site"))
    assert line.startswith(f"error: {tracks}:3:"), line
    assert not (tmp_path / "site").exists()


def test_an_audio_file_that_is_not_a_wav_is_named(tmp_path):
    tracks = tmp_path / "t.csv"
    tracks.write_text("time_ms,jaw_open\n0,0.1\n33.3,0.2\n")
    audio = tmp_path / "a.wav"
    audio.write_bytes(b"ID3\x03 not a wave at all")
    line = assert_user_error(run_in_process("web-export", "--tracks", tracks, "--audio", audio, "-o",
                                            tmp_path / "site"))
    assert f"{audio}" in line, line


@pytest.mark.parametrize(("args", "says"), [
    ((), "nothing to play"),
    (("--tracks", "t.csv"), "--tracks needs --audio"),
    (("--say", "Hei.", "--audio", "a.wav"), "--audio goes with --tracks"),
    (("--tracks", "t.csv", "--audio", "a.wav", "--voice", "x"), "--voice applies to --say"),
    (("--say", "Hei.", "--design", "d.toml"), "--design goes with --stimuli"),
])
def test_options_that_do_not_go_together_are_refused(tmp_path, args, says):
    line = assert_user_error(run_in_process("web-export", *args, "-o", tmp_path / "site", cwd=tmp_path))
    assert says in line, line


def test_a_folder_holding_other_files_is_not_overwritten(tmp_path):
    keep = tmp_path / "mine.txt"
    keep.write_text("my notes")
    line = assert_user_error(run_in_process("web-export", "--say", "Hei.", "-o", tmp_path))
    assert line.startswith(f"error: {tmp_path}:") and "not empty" in line, line
    assert keep.read_text() == "my notes" and not (tmp_path / "index.html").exists()


def _model_vertices(document, data, primitive) -> np.ndarray:
    from engine.formats.gltf_read import MODEL_VERTEX

    accessor = document["accessors"][primitive["attributes"][MODEL_VERTEX]]
    view = document["bufferViews"][accessor["bufferView"]]
    return np.frombuffer(data, "<f4", accessor["count"], view["byteOffset"]).astype(int)


def _silent_wav() -> bytes:
    from engine.speech.synthesis import wav_bytes

    return wav_bytes(np.zeros(1600, dtype=np.float32), 16000)


# -- a stimulus set: --stimuli OUTDIR --------------------------------------------------------------------------

DESIGN = """[factors]
text = ["Pappa ampui pallon.", "Maija meni kotiin."]
av_offset_ms = [0, 200]
[output]
kinds = ["wav", "tracks", "phones"]
fps = 30
"""


@pytest.fixture(scope="module")
def stimulus_set(tmp_path_factory):
    return made_set(tmp_path_factory.mktemp("stimuli"), DESIGN) / "set"


@pytest.mark.slow
def test_a_stimulus_set_becomes_one_site_with_one_head(stimulus_set, tmp_path):
    site = tmp_path / "site"
    result = run("web-export", "--stimuli", stimulus_set, "-o", site)
    assert result.returncode == 0, result.stderr
    manifest = list(csv.DictReader(io.StringIO((stimulus_set / "manifest.csv").read_text())))
    listing = json.loads((site / "stimuli.json").read_text())
    assert [s["id"] for s in listing["stimuli"]] == [row["id"] for row in manifest] == ["0001", "0002", "0003", "0004"]
    glb = (site / "head.glb").read_bytes()
    document = json.loads(glb[20:20 + int.from_bytes(glb[12:16], "little")])
    target_values = {t["name"]: t["value"] for t in document["meshes"][0]["extras"]["targets"]}
    for row in manifest:
        animation = json.loads((site / "stimuli" / f"{row['id']}.json").read_text())
        assert (site / "stimuli" / f"{row['id']}.wav").read_bytes() == (stimulus_set / row["file_wav"]).read_bytes()
        for channel in animation["channels"]:
            if channel["kind"] == "morph":              # every stimulus drives the one head's targets
                assert channel["target_value"] == target_values[channel["parameter"]]
        onsets = [float(t) for t in row["word_onsets_ms"].split(";")]
        assert [w["start_ms"] for w in animation["words"]] == pytest.approx(onsets, abs=1e-3)
        assert animation["model"] == "../head.glb" and animation["audio"] == f"{row['id']}.wav"
    # the face starts 200 ms before the sound in 0002: its first motion is 200 ms before 0001's, on the clip's clock
    first, second = (json.loads((site / "stimuli" / f"{i}.json").read_text()) for i in ("0001", "0002"))
    assert second["words"][0]["start_ms"] == pytest.approx(first["words"][0]["start_ms"] + 200, abs=1e-3)
    assert _first_motion_ms(second) == pytest.approx(_first_motion_ms(first), abs=1.0)


def _first_motion_ms(animation) -> float:
    moved = [int(np.flatnonzero(np.asarray(c["values"]) != 0)[0]) for c in animation["channels"] if any(c["values"])]
    return min(moved) * animation["frame_ms"]


def _edited_set(stimulus_set, tmp_path, edit) -> Path:
    copy = tmp_path / "set"
    shutil.copytree(stimulus_set, copy)
    manifest = copy / "manifest.csv"
    manifest.write_text(edit(manifest.read_text()))
    return copy


def test_a_set_without_tracks_is_refused_by_its_manifest(stimulus_set, tmp_path):
    def without_tracks(text: str) -> str:
        rows = list(csv.reader(io.StringIO(text)))
        keep = [i for i, name in enumerate(rows[0]) if name not in ("file_tracks", "sha256_tracks")]
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerows([[row[i] for i in keep] for row in rows])
        return out.getvalue()

    copy = _edited_set(stimulus_set, tmp_path, without_tracks)
    line = assert_user_error(run_in_process("web-export", "--stimuli", copy, "-o", tmp_path / "site"))
    assert line.startswith(f"error: {copy / 'manifest.csv'}:1:") and '"tracks"' in line, line


def test_a_set_of_several_heads_needs_its_design_and_is_refused_with_the_row(stimulus_set, tmp_path):
    def with_models(text: str) -> str:
        lines = text.splitlines()
        return "\n".join([lines[0] + ",model"] + [line + ",other-head.xml" for line in lines[1:]]) + "\n"

    copy = _edited_set(stimulus_set, tmp_path, with_models)
    line = assert_user_error(run_in_process("web-export", "--stimuli", copy, "-o", tmp_path / "site"))
    assert line.startswith(f"error: {copy / 'manifest.csv'}:2:") and "'model'" in line and "--design" in line, line


IDENTITIES = """[factors]
text = ["Pappa ampui pallon."]
identity = [{sex = 0.0, age = 30}, {sex = 1.0, age = 60, weight = 0.8}]
av_offset_ms = [0, 100]
[output]
kinds = ["wav", "tracks"]
fps = 30
"""


@pytest.fixture(scope="module")
def identity_set(tmp_path_factory):
    return made_set(tmp_path_factory.mktemp("identities"), IDENTITIES)


@pytest.mark.slow
def test_a_set_of_identities_becomes_one_site_with_each_head(identity_set, tmp_path):
    from engine.stimuli.design import load_design
    from engine.stimuli.heads import stimulus_head

    site = tmp_path / "site"
    refused = assert_user_error(run_in_process("web-export", "--stimuli", identity_set / "set", "-o", site))
    assert "factor 'identity'" in refused and "--design" in refused, refused
    result = run("web-export", "--stimuli", identity_set / "set", "--design", identity_set / "design.toml", "-o", site)
    assert result.returncode == 0, result.stderr
    assert "4 stimuli, 2 heads" in result.stdout, result.stdout
    listing = json.loads((site / "stimuli.json").read_text())
    assert listing["heads"] == 2
    # the design crosses identity × offset: 0001, 0002 the first identity, 0003, 0004 the second
    assert [s["model"] for s in listing["stimuli"]] == ["head.glb", "head.glb", "head-2.glb", "head-2.glb"]
    design = load_design(identity_set / "design.toml")
    for stimulus, glb_name in zip(design.stimuli, ("head.glb", "head.glb", "head-2.glb", "head-2.glb"), strict=True):
        animation = json.loads((site / "stimuli" / f"{stimulus.id}.json").read_text())
        assert animation["model"] == f"../{glb_name}"
        head = stimulus_head(design, stimulus.levels)
        glb = (site / glb_name).read_bytes()
        document = json.loads(glb[20:20 + int.from_bytes(glb[12:16], "little")])
        data = glb[28 + int.from_bytes(glb[12:16], "little"):]
        dense, dense_data = gltf_document(head, [], skeleton=True)
        for packed, full in zip(document["meshes"][0]["primitives"], dense["meshes"][0]["primitives"], strict=True):
            assert np.array_equal(_attribute(document, data, packed, "POSITION"),
                                  _attribute(dense, dense_data, full, "POSITION")), "each head is its identity's"
    first, second = ((site / name).read_bytes() for name in ("head.glb", "head-2.glb"))
    assert first != second


def test_a_design_the_set_was_not_made_from_is_refused(identity_set, tmp_path):
    other = tmp_path / "other.toml"
    other.write_text(IDENTITIES.replace("age = 60", "age = 61"))
    line = assert_user_error(run_in_process("web-export", "--stimuli", identity_set / "set", "--design", other,
                                 "-o", tmp_path / "site"))
    assert line.startswith(f"error: {other}:") and "not the design this set was made from" in line, line
    line = assert_user_error(run_in_process("web-export", "--stimuli", identity_set / "set", "--design",
                                 identity_set / "design.toml", "-m", "x.xml", "-o", tmp_path / "site"))
    assert "-m does not go with --design" in line, line
    assert not (tmp_path / "site").exists()


def test_a_missing_stimulus_file_is_named_with_its_row(stimulus_set, tmp_path):
    copy = _edited_set(stimulus_set, tmp_path, lambda text: text)
    (copy / "0003.wav").unlink()
    line = assert_user_error(run_in_process("web-export", "--stimuli", copy, "-o", tmp_path / "site"))
    assert line.startswith(f"error: {copy / 'manifest.csv'}:4:") and "0003.wav" in line, line
    assert not (tmp_path / "site").exists()


def test_a_folder_that_is_no_set_is_refused(tmp_path):
    line = assert_user_error(run_in_process("web-export", "--stimuli", tmp_path, "-o", tmp_path / "site"))
    assert line.startswith(f"error: {tmp_path / 'manifest.csv'}:") and "no manifest.csv" in line, line


def test_the_player_and_three_js_are_package_data():
    """An installed toolkit (a wheel) carries the player, its bundle and the vendored three.js: pyproject's
    package-data patterns reach every file under engine/web/player, engine/web/dist and engine/web/vendor."""
    import tomllib

    root = Path(__file__).resolve().parents[2]
    patterns = tomllib.loads((root / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["engine"]
    shipped = {path for pattern in patterns for path in (root / "engine").glob(pattern) if path.is_file()}
    needed = {path for folder in ("player", "dist", "vendor") for path in (root / "engine" / "web" / folder).rglob("*")
              if path.is_file()}
    assert needed and needed <= shipped, sorted(str(p) for p in needed - shipped)


def test_the_size_sets_the_camera_as_render_size_does(head, speech, tmp_path):
    from engine.outputs.camera import VIEWS, camera_pose, framed_points

    write_speech_site(speech, head, tmp_path, size=(320, 240))
    camera = json.loads((tmp_path / "animation.json").read_text())["camera"]
    focal, position, _, _ = camera_pose(framed_points(head), VIEWS["front"], 320, 240)
    assert (camera["width"], camera["height"]) == (320, 240)
    assert np.allclose(np.array(camera["position"]) * 1000, position, atol=1e-3)
    assert np.allclose(np.array(camera["target"]) * 1000, focal, atol=1e-3)
    page = (tmp_path / "index.html").read_text()
    assert "{{" not in page and "width: 100%; height: 100%" in page    # the page itself fills its window


@pytest.mark.slow
def test_a_text_file_is_spoken_like_the_same_text(tmp_path):
    text = tmp_path / "sentence.txt"
    text.write_text(SENTENCE + "\n", encoding="utf-8")
    assert run("web-export", "--file", text, "-o", tmp_path / "a").returncode == 0
    assert run("web-export", "--say", SENTENCE, "-o", tmp_path / "b").returncode == 0
    a, b = (json.loads((tmp_path / x / "animation.json").read_text()) for x in ("a", "b"))
    assert a["channels"] == b["channels"] and a["words"] == b["words"]
    broken = tmp_path / "latin1.txt"
    broken.write_bytes("Hyvää päivää".encode("latin-1"))
    line = assert_user_error(run_in_process("web-export", "--file", broken, "-o", tmp_path / "c"))
    assert line.startswith(f"error: {broken}"), line
