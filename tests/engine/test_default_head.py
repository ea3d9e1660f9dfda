"""The shipped default head: geometry, landmarks, the baseline rig and the reference poses.

The rig (§2.2) is fitted to the artist's poses shipped beside it; these tests
check that it reproduces them, that the jaw opens without tearing more than
the artist's own pose does, that rigid parts stay rigid, and that every
parameter moves the face the way its name says.
"""

import h5py
import numpy as np
import pytest

from engine.paths import reference_poses_path


@pytest.fixture(scope="module")
def poses():
    with h5py.File(reference_poses_path(), "r") as f:
        yield f


def pose(head, poses, name):
    D = np.zeros((head.n_vertices, 3))
    D[poses[name]["indices"][()]] = poses[name]["displacements"][()]
    return D


def displacement(head, **values):
    return head.deform(values) - head.vertices


def edges(head):
    pairs = set()
    for poly in head.polygons():
        for i in range(len(poly)):
            a, b = sorted((int(poly[i]), int(poly[(i + 1) % len(poly)])))
            pairs.add((a, b))
    return np.array(sorted(pairs))


# -- geometry -------------------------------------------------------------------

def test_parts_and_units(head):
    assert head.parts == ["skin", "eye_left", "eye_right", "eyelashes_left", "eyelashes_right",
                          "teeth_upper", "teeth_lower", "tongue"]
    skin = head.vertices[head.part_vertices("skin")]
    height = skin[:, 1].max() - skin[:, 1].min()
    assert 200 < height < 320, "head and neck should be a life-size few hundred millimetres"
    eye = head.vertices[head.part_vertices("eye_left")]
    radius = np.linalg.norm(eye - head.parameters["eye_left_turn"].pivot, axis=1)
    assert 10 < radius.mean() < 16 and np.ptp(radius) < 1e-6, "eyeballs are spheres of human size (mm)"


def test_faces_plus_z_with_y_up(head):
    lm = head.landmark_positions()
    skin = head.vertices[head.part_vertices("skin")]
    assert lm["9.3"][2] == pytest.approx(skin[:, 2].max(), abs=15), "the nose tip is the frontmost point (+Z)"
    assert lm["4.3"][1] > lm["3.5"][1] > lm["9.3"][1] > lm["8.1"][1] > lm["2.1"][1], "+Y is up"
    assert lm["3.5"][0] > 0 > lm["3.6"][0], "the subject's left eye is on +X"


def test_landmarks_named_by_the_issue(head):
    required = {"2.1", "2.2", "2.3", "3.5", "3.6", "4.1", "4.2", "4.3", "4.4", "4.5", "4.6",
                "9.3", "9.15"} | {f"8.{i}" for i in range(1, 9)}
    assert required <= set(head.landmarks)
    assert head.landmarks["3.5"] in head.part_vertices("eye_left")
    assert head.landmarks["3.6"] in head.part_vertices("eye_right")


def test_landmarks_are_mirror_images(head):
    lm = head.landmark_positions()
    for left, right in [("8.3", "8.4"), ("8.5", "8.6"), ("8.7", "8.8"), ("3.5", "3.6"), ("4.1", "4.2"),
                        ("4.3", "4.4"), ("4.5", "4.6"), ("9.1", "9.2")]:
        np.testing.assert_allclose(lm[left] * [-1, 1, 1], lm[right], atol=0.5, err_msg=f"{left}/{right}")
    for mid in ("2.1", "2.2", "2.3", "8.1", "8.2", "9.3", "9.15"):
        assert abs(lm[mid][0]) < 1e-6, f"{mid} lies on the midline"


def test_lip_landmarks_in_anatomical_order(head):
    lm = head.landmark_positions()
    assert lm["9.15"][1] > lm["8.1"][1] > lm["2.2"][1] >= lm["2.3"][1] > lm["8.2"][1] > lm["2.1"][1]
    assert np.linalg.norm(lm["2.2"] - lm["2.3"]) < 4, "lips closed at rest"
    assert lm["8.3"][0] > lm["8.5"][0] > 0 and lm["8.3"][0] > lm["8.7"][0] > 0


# -- the rig against the artist's poses ------------------------------------------------

@pytest.mark.parametrize("values, target, rms_mm", [
    ({"jaw_open": 1.0}, ["arkit/jawOpen"], 4.0),
    ({"eyelid_left_close": 1.0}, ["arkit/eyeBlinkLeft"], 3.0),
    ({"eyelid_right_close": 1.0}, ["arkit/eyeBlinkRight"], 3.0),
    ({"brow_raise": 1.0}, ["arkit/browInnerUp", "arkit/browOuterUpLeft", "arkit/browOuterUpRight"], 1.5),
])
def test_rig_reproduces_the_artist_pose(head, poses, values, target, rms_mm):
    wanted = sum(pose(head, poses, t) for t in target)
    got = displacement(head, **values)
    moved = np.linalg.norm(wanted, axis=1) > 0.5
    err = np.linalg.norm(got - wanted, axis=1)[moved]
    assert np.sqrt(np.mean(err ** 2)) < rms_mm
    # and it moves a comparable amount, not nothing
    assert np.linalg.norm(got, axis=1).max() > 0.6 * np.linalg.norm(wanted, axis=1).max()


def test_jaw_opens_without_tearing(head, poses):
    E = edges(head)
    skin = head.vertex_part[E[:, 0]] == 0
    rest = np.linalg.norm(head.vertices[E[:, 0]] - head.vertices[E[:, 1]], axis=1)

    def stretch(P):
        return np.linalg.norm(P[E[:, 0]] - P[E[:, 1]], axis=1)[skin] / rest[skin]

    rig = stretch(head.deform({"jaw_open": 1.0}))
    artist = stretch(head.vertices + pose(head, poses, "arkit/jawOpen"))
    assert np.percentile(rig, 99.9) <= 1.15 * np.percentile(artist, 99.9)
    assert rig.max() <= 1.15 * artist.max()


def test_jaw_opens_the_mouth_and_leaves_the_upper_lip(head):
    lm0 = head.landmark_positions()
    lm = head.landmark_positions({"jaw_open": 1.0})
    assert np.linalg.norm(lm["2.2"] - lm["2.3"]) > 25, "inner lip gap at full opening"
    assert lm["2.1"][1] < lm0["2.1"][1] - 8, "the chin drops"
    assert np.linalg.norm(lm["8.1"] - lm0["8.1"]) < 2.5, "the upper lip stays (at most the artist's 1-2 mm)"
    assert np.linalg.norm(lm["9.3"] - lm0["9.3"]) < 0.2, "the nose does not move"


@pytest.mark.parametrize("part, moving", [("teeth_lower", True), ("tongue", True), ("teeth_upper", False)])
def test_teeth_move_rigidly_with_their_bone(head, part, moving):
    idx = head.part_vertices(part)
    P0, P = head.vertices[idx], head.deform({"jaw_open": 0.8})[idx]
    if not moving:
        np.testing.assert_array_equal(P, P0)
        return
    assert np.abs(P - P0).max() > 5
    d0 = np.linalg.norm(P0[:, None] - P0[None], axis=-1)
    d1 = np.linalg.norm(P[:, None] - P[None], axis=-1)
    np.testing.assert_allclose(d1, d0, atol=1e-9)


def test_gaze_turns_the_eyes_and_not_the_lashes(head):
    P = head.deform({"eye_left_turn": 0.4, "eye_left_raise": 0.2})
    eye = head.part_vertices("eye_left")
    centre = head.parameters["eye_left_turn"].pivot
    np.testing.assert_allclose(np.linalg.norm(P[eye] - centre, axis=1),
                               np.linalg.norm(head.vertices[eye] - centre, axis=1), atol=1e-9)
    pupil = P[head.landmarks["3.5"]] - head.vertices[head.landmarks["3.5"]]
    assert pupil[0] > 3 and pupil[1] > 1, "positive turn looks to the subject's left, positive raise looks up"
    lashes = head.part_vertices("eyelashes_left")
    np.testing.assert_array_equal(P[lashes], head.vertices[lashes])
    skin = head.part_vertices("skin")
    np.testing.assert_array_equal(P[skin], head.vertices[skin])


def test_eyelid_closes_onto_the_lower_lid(head):
    lm0 = head.landmark_positions()
    lm = head.landmark_positions({"eyelid_left_close": 1.0})
    assert np.linalg.norm(lm0["3.1"] - lm0["3.3"]) > 6, "open at rest"
    assert np.linalg.norm(lm["3.1"] - lm["3.3"]) < 3, "closed at 1"
    assert np.linalg.norm(lm["3.2"] - lm0["3.2"]) == 0, "the right eye stays open"


def test_brow_raise_lifts_both_brows(head):
    lm0 = head.landmark_positions()
    lm = head.landmark_positions({"brow_raise": 1.0})
    for key in ("4.1", "4.2", "4.3", "4.4", "4.5", "4.6"):
        assert lm[key][1] - lm0[key][1] > 2.5, key


def test_head_motion_directions_and_fixed_neck_base(head):
    lm0 = head.landmark_positions()
    nod = head.landmark_positions({"head_nod": 0.2})
    turn = head.landmark_positions({"head_turn": 0.3})
    tilt = head.landmark_positions({"head_tilt": 0.2})
    assert nod["2.1"][1] < lm0["2.1"][1] - 3, "positive nod brings the chin down (HeadNod, §2.3)"
    assert turn["9.3"][0] > 15, "positive turn faces the subject's left"
    assert tilt["3.5"][1] > tilt["3.6"][1] + 5, "positive tilt lowers the right side"
    skin = head.part_vertices("skin")
    base = skin[head.vertices[skin, 1] < head.vertices[skin, 1].min() + 3]
    P = head.deform({"head_nod": 0.4, "head_turn": 0.8, "head_tilt": 0.3})
    np.testing.assert_array_equal(P[base], head.vertices[base])


def test_every_parameter_moves_something(head):
    for p in head.parameters:
        value = p.maximum if p.maximum != 0 else p.minimum
        assert np.abs(displacement(head, **{p.name: value})).max() > 1.0, p.name


# -- the reference poses ------------------------------------------------------------

def test_reference_poses_file(head, poses):
    assert poses.attrs["format"] == "artificial-person-poses" and poses.attrs["version"] == 1
    assert len(poses["arkit"]) == 52
    assert {"jawOpen", "eyeBlinkLeft", "mouthSmileLeft", "tongueOut"} <= set(poses["arkit"])
    assert len(poses["expression_units"]) == 34
    assert len(poses["source_vertex"]) == head.n_vertices
    for group in ("arkit", "expression_units"):
        for name, g in poses[group].items():
            idx = g["indices"][()]
            assert idx.min() >= 0 and idx.max() < head.n_vertices, name
            assert g["displacements"].shape == (len(idx), 3), name
            assert 0 < np.abs(g["displacements"][()]).max() < 60, f"{name}: mm-sized displacements"


def test_eye_look_poses_rotate_the_new_eyeballs(head, poses):
    D = pose(head, poses, "arkit/eyeLookOutLeft")
    eye = head.part_vertices("eye_left")
    centre = head.parameters["eye_left_turn"].pivot
    r0 = np.linalg.norm(head.vertices[eye] - centre, axis=1)
    r1 = np.linalg.norm(head.vertices[eye] + D[eye] - centre, axis=1)
    np.testing.assert_allclose(r1, r0, atol=1e-3)
    assert D[head.landmarks["3.5"], 0] > 1, "looking out moves the left pupil to +X"
