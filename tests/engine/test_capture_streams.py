"""Capture streams (issue 22 §3): the three readers on files in their producers' layouts, the mapping
checked on the default head's geometry, and ``capture animate`` end to end."""

from __future__ import annotations

import json

import numpy as np
import pytest

from engine.capture.arkit_names import ARKIT_BLENDSHAPES
from engine.capture.live_link_face import parse_live_link_face, read_live_link_face
from engine.capture.mapping_tables import ARKIT_LOST
from engine.capture.mediapipe_blendshapes import parse_mediapipe
from engine.capture.openface import parse_openface
from engine.capture.readers import detect_format_of_text, read_capture
from engine.capture.retarget import retarget
from engine.capture.stream import CaptureFileError, CaptureStream
from engine.timeline.tracks import read_tracks_csv
from tests.engine.capture_stream_files import (
    LLF_EYES,
    LLF_MOUTH,
    llf_text,
    mediapipe_csv,
    mediapipe_json,
    openface_text,
)
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run


def pose(head, mapped, frame):
    """Landmark positions of the head in one mapped frame."""
    return head.landmark_positions(dict(zip(mapped.parameters, mapped.values[frame], strict=True)))


def lip_gap(points) -> float:
    return float(points["2.2"][1] - points["2.3"][1])


# -- readers ---------------------------------------------------------------------------------------

def test_live_link_face_take_reads_with_its_timecode_rate():
    take = read_live_link_face(LLF_MOUTH)
    assert take.format == "arkit" and take.frames == 240
    assert take.times_ms[0] == 0 and np.all(np.diff(take.times_ms) > 0)
    # the app's timecode counts 60 frames a second; the take was recorded at every other one
    assert take.rate_hz == pytest.approx(30.0, rel=1e-3)
    assert len(take.channels) == 52 + 7                      # eye rolls are not read
    assert take.channels["jawOpen"].max() == pytest.approx(0.95, abs=0.01)


def test_live_link_face_eye_angles_turn_the_way_the_eye_shapes_look():
    take = read_live_link_face(LLF_EYES)
    c = take.channels
    left = np.corrcoef(c["eye_left_turn_rad"], c["eyeLookOutLeft"] - c["eyeLookInLeft"])[0, 1]
    right = np.corrcoef(c["eye_right_turn_rad"], c["eyeLookInRight"] - c["eyeLookOutRight"])[0, 1]
    up = np.corrcoef(c["eye_left_raise_rad"], c["eyeLookUpLeft"] - c["eyeLookDownLeft"])[0, 1]
    assert left > 0.99 and right > 0.99 and up > 0.98


def test_a_take_shorter_than_a_second_gets_the_apps_rate():
    take = parse_live_link_face(llf_text([{}] * 5, start="10:00:00", step=2))
    assert take.rate_hz == pytest.approx(30.0)


def test_openface_reads_intensities_pose_gaze_and_skips_lost_frames():
    frames = [{"AU12": 2.5}, {"success": 0}, {"AU12": 5.0, "pose_Ry": 0.2}, {"face_id": 1, "AU12": 1.0}]
    take = parse_openface(openface_text(frames), "of.csv")
    assert take.frames == 2 and take.times_ms.tolist() == [0.0, 67.0]   # 3 decimals of s
    assert take.channels["AU12"].tolist() == [2.5, 5.0]
    assert take.channels["head_turn_rad"].tolist() == [0.0, -0.2]
    assert any("success 0" in n for n in take.notes) and any("face(s) 1" in n for n in take.notes)


def test_openface_image_sequence_needs_a_frame_rate():
    text = openface_text([{}, {}, {}], timestamps=False)
    with pytest.raises(CaptureFileError, match="--fps"):
        parse_openface(text, "seq.csv")
    assert parse_openface(text, "seq.csv", fps=25).times_ms.tolist() == [0.0, 40.0, 80.0]


@pytest.mark.parametrize("style", ["js", "python"])
def test_mediapipe_json_in_both_api_shapes(style):
    take = parse_mediapipe(mediapipe_json([{"jawOpen": 0.2}, {"jawOpen": 0.7}], style=style), "mp.json")
    assert take.format == "mediapipe" and take.frames == 2
    assert take.channels["jawOpen"].tolist() == [0.2, 0.7]


def test_mediapipe_frames_without_a_face_are_bridged():
    frames = json.loads(mediapipe_json([{"jawOpen": 0.1}, {}, {"jawOpen": 0.3}]))
    frames[1]["faceBlendshapes"] = []                      # MediaPipe found no face in that frame
    take = parse_mediapipe("[\n" + ",\n".join(json.dumps(f) for f in frames) + "\n]", "mp.json")
    assert take.frames == 2 and take.times_ms.tolist() == [0.0, 66.0]
    assert take.channels["jawOpen"].tolist() == [0.1, 0.3]
    assert any("without a face" in n for n in take.notes)


def test_mediapipe_csv():
    take = parse_mediapipe(mediapipe_csv([{"eyeBlinkLeft": 1.0}, {}]), "mp.csv")
    assert take.channels["eyeBlinkLeft"].tolist() == [1.0, 0.0] and take.times_ms.tolist() == [0.0, 33.0]


def test_formats_are_told_apart_by_their_headers():
    assert detect_format_of_text(LLF_MOUTH.read_text()) == "arkit"
    assert detect_format_of_text(openface_text([{}])) == "openface"
    assert detect_format_of_text(mediapipe_json([{}])) == "mediapipe"
    assert detect_format_of_text(mediapipe_csv([{}])) == "mediapipe"
    assert detect_format_of_text("time_ms,jaw_open\n0,0\n") is None


@pytest.mark.parametrize(("text", "line", "what"), [
    ("Timecode,BlendShapeCount,EyeBlinkLeft\n", 1, "missing"),
    (None, 4, "not a number"),
    ("frame, face_id, timestamp, confidence, success, AU12_r\n1, 0, 0.000, 0.9, 1, 7.5\n", 2, "outside 0–5"),
    ("face, confidence, AU12_r\n0, 0.9, 1.0\n", 1, "single images"),
    ("[{\"timestampMs\": 0, \"faceBlendshapes\": [[{\"categoryName\": \"smile\", \"score\": 1}]]}]", 1, "unknown"),
])
def test_bad_files_are_refused_naming_file_and_line(text, line, what):
    if text is None:
        rows = LLF_MOUTH.read_text().splitlines()
        rows[3] = rows[3].replace(",0.", ",x.", 1)
        text = "\n".join(rows)
    fmt = detect_format_of_text(text)
    parse = {"arkit": parse_live_link_face, "openface": parse_openface, "mediapipe": parse_mediapipe}[fmt]
    with pytest.raises(CaptureFileError) as caught:
        parse(text, "bad.txt")
    assert str(caught.value).startswith(f"bad.txt:{line}: "), str(caught.value)
    assert what in str(caught.value)


# -- the mapping on the head's geometry ----------------------------------------------------------------

def test_jaw_open_one_opens_the_mouth_as_far_as_the_heads_full_jaw(head):
    mapped = retarget(parse_live_link_face(llf_text([{}, {"JawOpen": 1.0}])), head)
    opened = lip_gap(pose(head, mapped, 1))
    assert opened - lip_gap(head.landmark_positions()) > 10.0                          # mm
    assert opened == pytest.approx(lip_gap(head.landmark_positions({"jaw_open": 1.0})), abs=1e-6)


def test_mouth_close_seals_the_lips_over_an_open_jaw_as_the_reference_poses_do(head):
    """ARKit's mouthClose only means something with jawOpen: the head's own poses give the rest lip gap for
    jawOpen + mouthClose; the mapping gives it back by closing the jaw by as much."""
    from engine.fitting.reference_poses import reference_pose
    from engine.paths import reference_poses_path

    frames = [{"JawOpen": 0.6, "MouthClose": 0.6}, {"JawOpen": 0.6, "MouthClose": 0.2}, {"JawOpen": 0.6}]
    mapped = retarget(parse_live_link_face(llf_text(frames)), head)
    rest = lip_gap(head.landmark_positions())
    assert lip_gap(pose(head, mapped, 0)) == pytest.approx(rest, abs=1e-6)
    assert rest < lip_gap(pose(head, mapped, 1)) < lip_gap(pose(head, mapped, 2))
    if reference_poses_path().exists():
        vertices = head.deform()
        sealed = vertices + 0.6 * reference_pose("jawOpen") + 0.6 * reference_pose("mouthClose")
        upper, lower = (int(np.argmin(np.linalg.norm(vertices - head.landmark_positions()[k], axis=1)))
                        for k in ("2.2", "2.3"))
        assert sealed[upper, 1] - sealed[lower, 1] == pytest.approx(rest, abs=0.1)


def test_eye_blink_left_closes_the_left_lid_not_the_right(head):
    mapped = retarget(parse_live_link_face(llf_text([{}, {"EyeBlinkLeft": 1.0}])), head)
    rest, shut = head.landmark_positions(), pose(head, mapped, 1)
    assert shut["3.1"][1] - rest["3.1"][1] < -5.0            # 3.1: the subject's left upper lid (at +X)
    assert shut["3.2"][1] == pytest.approx(rest["3.2"][1], abs=1e-9)
    assert rest["3.1"][0] > 0                                # +X is the subject's left on the head


def test_head_yaw_turns_the_head_the_way_the_same_eye_yaw_turns_the_eyes(head):
    """The take shows a negative eye yaw looks to the subject's left; the head's yaw is read alike."""
    frame = {"HeadYaw": -0.3, "LeftEyeYaw": -0.3, "RightEyeYaw": -0.3}
    mapped = retarget(parse_live_link_face(llf_text([{}, frame])), head)
    rest, moved = head.landmark_positions(), pose(head, mapped, 1)
    assert moved["9.3"][0] - rest["9.3"][0] > 20.0            # the nose tip swings to +X, the subject's left
    eyes_only = retarget(parse_live_link_face(llf_text([{}, {"LeftEyeYaw": -0.3}])), head)
    pupil = eyes_only.values[1][eyes_only.parameters.index("eye_left_turn")]
    assert pupil > 0 and mapped.values[1][mapped.parameters.index("head_turn")] > 0


def test_openface_turn_to_the_right_turns_the_head_to_its_right(head):
    """OpenFace: turning to one's own right gives a positive pose_Ry (OpenFace issue #966)."""
    mapped = retarget(parse_openface(openface_text([{}, {"pose_Ry": 0.3, "pose_Rx": -0.2}])), head)
    rest, moved = head.landmark_positions(), pose(head, mapped, 1)
    assert moved["9.3"][0] - rest["9.3"][0] < -20.0           # the nose tip to −X, the subject's right
    assert moved["9.3"][1] > rest["9.3"][1]                   # negative Rx: the head tips up


def test_openface_au12_at_five_raises_both_lip_corners(head):
    mapped = retarget(parse_openface(openface_text([{}, {"AU12": 5.0}])), head)
    rest, smile = head.landmark_positions(), pose(head, mapped, 1)
    for corner in ("8.3", "8.4"):
        assert smile[corner][1] - rest[corner][1] > 5.0
    assert mapped.values[1][mapped.parameters.index("AU12_left")] == pytest.approx(1.0)


def test_openface_blink_closes_both_lids(head):
    mapped = retarget(parse_openface(openface_text([{}, {"AU45": 5.0}])), head)
    rest, shut = head.landmark_positions(), pose(head, mapped, 1)
    assert shut["3.1"][1] - rest["3.1"][1] < -5.0 and shut["3.2"][1] - rest["3.2"][1] < -5.0


def test_mediapipe_eye_shapes_turn_both_eyes_to_the_subjects_left(head):
    frame = {"eyeLookOutLeft": 0.5, "eyeLookInRight": 0.5}
    mapped = retarget(parse_mediapipe(mediapipe_json([{}, frame])), head)
    left = head.part_vertices("eye_left")
    front = left[np.argmax(head.deform()[left, 2])]
    moved = head.deform(dict(zip(mapped.parameters, mapped.values[1], strict=True)))
    assert moved[front, 0] - head.deform()[front, 0] > 2.0
    values = dict(zip(mapped.parameters, mapped.values[1], strict=True))
    assert values["eye_left_turn"] == pytest.approx(values["eye_right_turn"]) == pytest.approx(0.5 * 0.607)


def rotation(axis: str, angle: float) -> np.ndarray:
    """A 4×4 right-handed rotation about a head-frame axis, with the face 45 cm in front of the camera."""
    c, s = np.cos(angle), np.sin(angle)
    m = {"x": [[1, 0, 0], [0, c, -s], [0, s, c]], "y": [[c, 0, s], [0, 1, 0], [-s, 0, c]],
         "z": [[c, -s, 0], [s, c, 0], [0, 0, 1]]}[axis]
    out = np.eye(4)
    out[:3, :3] = m
    out[:3, 3] = [1.5, -2.0, -45.0]
    return out


@pytest.mark.parametrize("style", ["js", "python"])
def test_mediapipe_transformation_matrix_turns_and_nods_the_head(head, style):
    """The canonical face is the head frame; a turn about +Y swings the face to the subject's left."""
    matrices = [np.eye(4), rotation("y", 0.3), rotation("x", 0.2), rotation("y", 0.2) @ rotation("x", 0.1)]
    take = parse_mediapipe(mediapipe_json([{}] * 4, style=style, matrices=matrices), "mp.json")
    assert take.channels["head_turn_rad"] == pytest.approx([0.0, 0.3, 0.0, 0.2])
    assert take.channels["head_nod_rad"] == pytest.approx([0.0, 0.0, 0.2, 0.1])
    mapped = retarget(take, head)
    rest = head.landmark_positions()
    assert pose(head, mapped, 1)["9.3"][0] - rest["9.3"][0] > 20.0      # the nose to +X, the subject's left
    assert pose(head, mapped, 2)["9.3"][1] - rest["9.3"][1] < -10.0     # chin down: the nose drops


def test_values_beyond_a_range_are_clamped_and_reported(head):
    mapped = retarget(parse_live_link_face(llf_text([{}, {"LeftEyeYaw": -1.0}])), head)
    assert mapped.clamped["eye_left_turn"].frames == 1
    assert mapped.clamped["eye_left_turn"].highest == pytest.approx(1.0)
    assert mapped.values[1][mapped.parameters.index("eye_left_turn")] == head.parameters["eye_left_turn"].maximum


def test_a_parameter_the_model_lacks_is_skipped_with_a_warning(head_copy):
    head_copy.remove_parameter("AU12_left")
    mapped = retarget(parse_live_link_face(llf_text([{"MouthSmileLeft": 1.0}])), head_copy)
    assert "AU12_left" not in mapped.parameters
    assert any("'AU12_left'" in w and "mouthSmileLeft" in w for w in mapped.warnings)


# -- the command line ---------------------------------------------------------------------------

def test_cli_writes_the_tracks_table_of_a_real_take(tmp_path, head):
    out = tmp_path / "take.csv"
    result = run("capture", "animate", LLF_MOUTH, "-o", out)
    assert result.returncode == 0, result.stderr
    assert "warning: cheekPuff" in result.stderr or "warning:" in result.stderr
    table = read_tracks_csv(out, head)
    assert table.fps == pytest.approx(30.0) and len(table.times) == 240
    direct = retarget(read_capture(LLF_MOUTH), head)
    j = direct.parameters.index("jaw_open")
    assert table.values_at(table.times[10])["jaw_open"] == pytest.approx(
        np.interp(table.times[10], direct.times_ms, direct.values[:, j]), abs=1e-9)


def test_cli_writes_a_video_with_one_frame_per_output_frame(tmp_path):
    from engine.outputs.video_probe import probe

    source = tmp_path / "take.json"
    source.write_text(mediapipe_json([{"jawOpen": i / 9} for i in range(10)], step_ms=40.0))
    out = tmp_path / "take.mp4"
    result = run("capture", "animate", source, "--size", "160x120", "-o", out)
    assert result.returncode == 0, result.stderr
    assert probe(out).frames == 10


@pytest.mark.parametrize("content", ["", "Timecode,BlendShapeCount\n", "time_ms,x\n0,1\n", "[{]", "{\"frames\": 3}"])
def test_cli_bad_files_end_with_one_line_and_status_2(tmp_path, content):
    source = tmp_path / "bad.csv"
    source.write_text(content)
    line = assert_user_error(run_in_process("capture", "animate", source, "-o", tmp_path / "out.csv"))
    assert "bad.csv" in line
    assert not (tmp_path / "out.csv").exists()


def test_cli_refuses_an_unknown_output_kind(tmp_path):
    line = assert_user_error(run_in_process("capture", "animate", LLF_MOUTH, "-o", tmp_path / "out.gif"))
    assert "out.gif" in line


def test_openface_gaze_to_the_subjects_left_turns_both_eyes_there(head):
    """OpenFace: gaze_angle_x grows as the eyes look to the subject's left (x right in the image)."""
    mapped = retarget(parse_openface(openface_text([{}, {"gaze_angle_x": 0.3, "gaze_angle_y": -0.2}])), head)
    values = dict(zip(mapped.parameters, mapped.values[1], strict=True))
    assert values["eye_left_turn"] == pytest.approx(0.3) and values["eye_right_turn"] == pytest.approx(0.3)
    assert values["eye_left_raise"] == pytest.approx(0.2)                 # negative y: looking up


def test_cli_video_carries_the_audio_given(tmp_path):
    import wave

    from engine.outputs.video_probe import probe

    source = tmp_path / "take.json"
    source.write_text(mediapipe_json([{"jawOpen": i / 14} for i in range(15)], step_ms=40.0))
    sound = tmp_path / "take.wav"
    with wave.open(str(sound), "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(16000)
        tone = (8000 * np.sin(np.arange(9600) * 2 * np.pi * 440 / 16000)).astype("<i2")
        out.writeframes(tone.tobytes())
    video = tmp_path / "take.mp4"
    result = run("capture", "animate", source, "--audio", sound, "--size", "160x120", "-o", video)
    assert result.returncode == 0, result.stderr
    facts = probe(video)
    assert facts.frames == 15 and facts.audio_duration == pytest.approx(15 / 25, abs=0.03)


def test_cli_named_format_that_does_not_fit_is_refused(tmp_path):
    line = assert_user_error(run_in_process("capture", "animate", LLF_MOUTH, "--format", "openface", "-o",
                                            tmp_path / "o.csv"))
    assert "llf_rom_mouth.csv:1:" in line and "OpenFace" in line


MAPPED_SHAPES = [s for s in ARKIT_BLENDSHAPES if s not in ARKIT_LOST and s != "mouthClose"]   # see below


@pytest.mark.parametrize("shape", MAPPED_SHAPES)
def test_each_blendshape_moves_the_head_as_the_heads_own_reference_pose_of_it(head, shape):
    """The default head ships an artist's pose for each ARKit shape: the mapping at 1 must move the face the
    same way (cosine of the displacement fields), on the same side, by about as much (least-squares scale)."""
    from engine.fitting.reference_poses import reference_pose
    from engine.paths import reference_poses_path

    if not reference_poses_path().exists():
        pytest.skip("the default head's reference poses are not built")
    take = CaptureStream("one.csv", "arkit", np.array([0.0]),
                         {s: np.array([1.0 if s == shape else 0.0]) for s in ARKIT_BLENDSHAPES})
    mapped = retarget(take, head)
    moved = (head.deform(dict(zip(mapped.parameters, mapped.values[0], strict=True))) - head.deform()).ravel()
    reference = reference_pose(shape).ravel()
    cosine = moved @ reference / np.linalg.norm(moved) / np.linalg.norm(reference)
    assert cosine >= 0.7
    mirror = shape.replace("Left", "@").replace("Right", "Left").replace("@", "Right")
    if mirror != shape:
        other = reference_pose(mirror).ravel()
        assert cosine > moved @ other / np.linalg.norm(moved) / np.linalg.norm(other) + 0.5
    if not shape.startswith("eyeLook"):          # eye turns follow the recorded angles (docs/capture-streams.md)
        assert 0.8 <= moved @ reference / (moved @ moved) <= 1.25


def test_a_model_with_its_own_arkit_targets_is_driven_through_them(head):
    """A head made for ARKit capture (parameters named after the blendshapes, any capitalisation) takes each
    channel as is; channels it has no target for still go through the tables (issue 22 §3)."""
    from engine.fitting.reference_poses import reference_pose
    from engine.model import InfluenceRegion, Parameter
    from engine.paths import reference_poses_path

    if not reference_poses_path().exists():
        pytest.skip("the default head's reference poses are not built")
    rig = head.copy()
    for name in ("mouthSmileLeft", "TongueOut"):
        field = reference_pose(name[0].lower() + name[1:])
        moved = np.flatnonzero(np.abs(field).max(axis=1) > 0)
        rig.add_parameter(Parameter(name, "translation", field=True, minimum=0.0, maximum=1.0),
                          InfluenceRegion(moved, np.ones(len(moved)), field[moved]))
    take = parse_live_link_face(llf_text([{}, {"MouthSmileLeft": 0.8, "MouthSmileRight": 0.5, "TongueOut": 0.4}]))
    mapped = retarget(take, rig)
    values = dict(zip(mapped.parameters, mapped.values[1], strict=True))
    assert values["mouthSmileLeft"] == pytest.approx(0.8) and values["TongueOut"] == pytest.approx(0.4)
    assert "AU12_left" not in values or values["AU12_left"] == 0.0        # not also through the table
    assert values["AU12_right"] > 0.0                                       # no target of its own: the table
    assert not any("TongueOut" in w or "tongueOut" in w for w in mapped.warnings)
    plain = dict(zip(*(lambda m: (m.parameters, m.values[1]))(retarget(take, head)), strict=True))
    assert plain["AU12_left"] > 0.0 and "mouthSmileLeft" not in plain      # the default head: the tables
