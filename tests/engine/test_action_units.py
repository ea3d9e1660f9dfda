"""The FACS action units of Table 1 on the default head (§3.2).

``engine/data/default-head/derive_default_head.py`` fits one leaf per row and side
of Table 1 to the artist's reference poses (``action_units.py`` is the
recipe). These tests check the parameter set against the table, what each
AU does to the MPEG-4 landmarks, that left AUs move only the left side, that
each reproduces the artist's pose, and that no AU pushes the lids into the
eyeballs or the lips through each other.
"""

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from engine.fitting import reference_pose
from tests.engine.face_geometry import Lips, assert_lips_apart, eyeball_entry_mm

HEAD_DIR = Path(__file__).resolve().parents[2] / "engine" / "data" / "default-head"

# Table 1: the AU row, its number of parameters, and the parameters that model it on the default head.
TABLE_1 = [
    ("AU1", 2, ["AU1_left", "AU1_right"]),
    ("AU2", 2, ["AU2_left", "AU2_right"]),
    ("AU4", 2, ["AU4_left", "AU4_right"]),
    ("AU5/41", 2, ["AU5_left", "AU5_right"]),
    ("AU6", 2, ["AU6_left", "AU6_right"]),
    ("AU7", 2, ["AU7_left", "AU7_right"]),
    ("AU9", 4, ["AU9_left_nose", "AU9_right_nose", "AU9_left_brow", "AU9_right_brow"]),
    ("AU10", 3, ["AU10_left", "AU10_right", "AU10_middle"]),
    ("AU11", 2, ["AU11_left", "AU11_right"]),
    ("AU12", 2, ["AU12_left", "AU12_right"]),
    ("AU15", 2, ["AU15_left", "AU15_right"]),
    ("AU16/17", 3, ["AU16_left", "AU16_right", "AU17"]),
    ("AU20", 2, ["AU20_left", "AU20_right"]),
    ("AU23/24", 3, ["AU23", "AU24_left", "AU24_right"]),
    ("AU25/26/27", 1, ["jaw_open"]),
    ("AU38/39", 2, ["AU38_left", "AU38_right"]),
]
AU_PARAMETERS = [name for _, _, names in TABLE_1 for name in names if name != "jaw_open"]
ROTATIONS = {"AU1", "AU2", "AU4", "AU5", "AU7"}             # plus AU9's brow part (fitted motion)
ON_THE_JAW = {"AU15", "AU16", "AU17"}                      # muscles that pull from the mandible
LEFT = [n for n in AU_PARAMETERS if "_left" in n]


def mirror_name(name):
    return name.replace("_left", "_RIGHT").replace("_right", "_left").replace("_RIGHT", "_right")


def mirror_landmark(key):
    pairs = {"8.3": "8.4", "8.5": "8.6", "8.7": "8.8", "2.4": "2.5", "3.1": "3.2", "3.3": "3.4", "3.5": "3.6",
             "3.7": "3.12", "3.11": "3.8", "4.1": "4.2", "4.3": "4.4", "4.5": "4.6", "9.1": "9.2", "9.5": "9.4"}
    pairs.update({b: a for a, b in pairs.items()})
    return pairs.get(key, key)



@pytest.fixture(scope="module")
def rest(head):
    return head.landmark_positions()


@pytest.fixture(scope="module")
def lips(head):
    return Lips(head)


@pytest.fixture(scope="module")
def recipe():
    if str(HEAD_DIR) not in sys.path:
        sys.path.append(str(HEAD_DIR))                 # its stage facs_creases.py lies beside it
    spec = importlib.util.spec_from_file_location("action_units", HEAD_DIR / "action_units.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("action_units", module)     # dataclasses look their module up there
    spec.loader.exec_module(sys.modules["action_units"])
    return sys.modules["action_units"]


def moved(head, rest, values):
    """Landmark displacements (mm) for ``values``."""
    lm = head.landmark_positions(values)
    return {k: lm[k] - rest[k] for k in lm}


def cheek_point(head, rest):
    """The skin vertex on the left cheek's apex: 8 mm inside the outer eye corner, halfway
    between the lower lid and the nose tip."""
    P, skin = head.vertices, head.part_vertices("skin")
    front = skin[P[skin, 2] > rest["3.7"][2] - 5]
    goal = np.array([rest["3.7"][0] - 8, (rest["3.3"][1] + rest["9.3"][1]) / 2])
    return front[np.argmin(np.linalg.norm(P[front, :2] - goal, axis=1))]


# -- the parameter set ------------------------------------------------------------------

def test_every_row_of_table_1_has_its_number_of_parameters(head):
    assert len(TABLE_1) == 16
    for row, count, names in TABLE_1:
        assert len(names) == count, row
        for name in names:
            assert name in head.parameters, f"{row}: the default head has no '{name}'"
    assert len(AU_PARAMETERS) == 35


def test_action_units_are_leaves_under_the_right_parent(head):
    tree = head.parameters
    for name in AU_PARAMETERS:
        p, au = tree[name], name.split("_")[0]
        assert tree.is_leaf(name) and tree.group(name) == 2, name
        assert p.parent == ("jaw_open" if au in ON_THE_JAW else "head_tilt"), name
        assert "head_tilt" in tree.ancestors(name), f"{name} must move with the head"
        assert p.default == 0.0 and p.maximum == 1.0, name
        assert p.minimum == (-1.0 if au == "AU38" else 0.0), name
        assert p.description.startswith(au + " "), name


def test_brows_and_lids_rotate_the_rest_translate(head, recipe):
    """§2.2.1: rotations for motion along a curved surface (brows over the forehead, lids over the eye).

    An AU that carries furrows (AU1, AU2, AU4, AU6, AU9's nose, AU10's sides, AU12, AU15, AU17) is a
    field: its motion is fitted as before (the brows' as rotations) and kept, with the furrows, as a
    displacement field; the lids keep their rotations about the eyeball."""
    units = {u.name: u for u in recipe.ACTION_UNITS}
    for name in AU_PARAMETERS:
        p, au, unit = head.parameters[name], name.split("_")[0], units[name]
        curved = au in ROTATIONS or name.endswith("_brow")
        assert unit.kind == ("rotation" if curved else unit.kind), name
        if curved:
            assert unit.kind == "rotation", f"{name}: its motion is fitted as a rotation"
        if unit.appearance_key in recipe.APPEARANCE:
            assert p.kind == "translation" and p.field, f"{name} carries its furrows as a field"
        else:
            assert p.kind == ("rotation" if curved else "translation"), name


def test_action_units_move_only_skin_and_lashes(head):
    allowed = {head.parts.index(p) for p in ("skin", "eyelashes_left", "eyelashes_right")}
    for name in AU_PARAMETERS:
        region = head.regions[name]
        assert len(region.indices) > 50, name
        assert set(np.unique(head.vertex_part[region.indices])) <= allowed, f"{name} moves eyes, teeth or tongue"
        assert region.weights.min() > 0 and region.weights.max() == pytest.approx(1.0), name


# -- left and right -----------------------------------------------------------------------

@pytest.mark.parametrize("name", LEFT)
def test_a_left_action_unit_moves_only_the_left_side(head, name):
    d = np.linalg.norm(head.deform({name: head.parameters[name].maximum}) - head.vertices, axis=1)
    x = head.vertices[:, 0]
    assert d.max() > 1.0, name
    assert d[x < -10.0].max() < 0.05, f"{name} moves the right side by {d[x < -10.0].max():.3f} mm"
    right = mirror_name(name)
    d = np.linalg.norm(head.deform({right: head.parameters[right].maximum}) - head.vertices, axis=1)
    assert d[x > 10.0].max() < 0.05, f"{right} moves the left side"


@pytest.mark.parametrize("name", LEFT)
def test_left_and_right_are_mirror_images(head, rest, name):
    left, right = moved(head, rest, {name: 1.0}), moved(head, rest, {mirror_name(name): 1.0})
    flip = np.array([-1.0, 1.0, 1.0])
    for key, d in left.items():
        # ARKit's mouthSmileLeft and Right differ by up to 0.6 mm; the others are exact mirrors
        np.testing.assert_allclose(right[mirror_landmark(key)], d * flip, atol=0.7, err_msg=f"{name} {key}")


# -- what each action unit does (the geometric check) -------------------------------------

def test_au1_raises_the_inner_brows(head, rest):
    m = moved(head, rest, {"AU1_left": 1, "AU1_right": 1})
    assert m["4.1"][1] > 3.0 and m["4.2"][1] > 3.0
    assert m["4.1"][1] > 3 * abs(m["4.5"][1]), "the inner end rises, the outer end hardly"


def test_au2_raises_the_outer_brows(head, rest):
    m = moved(head, rest, {"AU2_left": 1, "AU2_right": 1})
    assert m["4.5"][1] > 4.0 and m["4.6"][1] > 4.0
    assert m["4.5"][1] > 3 * abs(m["4.1"][1]), "the outer end rises, the inner end hardly"


def test_au4_lowers_the_brows_and_draws_them_together(head, rest):
    lm = head.landmark_positions({"AU4_left": 1, "AU4_right": 1})
    for key in ("4.1", "4.2", "4.3", "4.4"):
        assert lm[key][1] < rest[key][1] - 3.0, key
    inner = np.linalg.norm(rest["4.1"] - rest["4.2"]) - np.linalg.norm(lm["4.1"] - lm["4.2"])
    assert inner > 3.0, f"the inner brows come only {inner:.1f} mm closer"


def test_au5_raises_the_upper_lid_and_au41_lowers_it(head, rest):
    m = moved(head, rest, {"AU5_left": 1})
    assert m["3.1"][1] > 2.0 and abs(m["3.3"][1]) < 0.2, "the upper lid rises, the lower lid stays"
    assert abs(m["3.2"][1]) < 0.01, "the left lid only"
    droop = moved(head, rest, {"eyelid_left_close": 0.4})        # AU41 is the blink's rotation, part way
    assert droop["3.1"][1] < -2.0 and abs(droop["3.3"][1]) < 0.2


def test_au6_raises_the_cheek(head, rest):
    cheek = cheek_point(head, rest)
    d = head.deform({"AU6_left": 1}) - head.vertices
    assert d[cheek, 1] > 4.0, f"the cheek rises only {d[cheek, 1]:.1f} mm"
    assert moved(head, rest, {"AU6_left": 1})["3.3"][1] > 0.5, "and pushes the lower lid up"


def test_au7_raises_the_lower_lid(head, rest):
    m = moved(head, rest, {"AU7_left": 1})
    assert m["3.3"][1] > 2.0 and abs(m["3.1"][1]) < 0.3, "the lower lid rises, the upper lid stays"


def test_au9_raises_the_nose_wings_and_lowers_the_inner_brows(head, rest):
    m = moved(head, rest, {"AU9_left_nose": 1, "AU9_right_nose": 1})
    for key in ("9.1", "9.2", "9.4", "9.5"):
        assert m[key][1] > 1.0, key
    m = moved(head, rest, {"AU9_left_brow": 1})
    assert m["4.1"][1] < -3.0 and m["4.1"][0] < -1.5, "the left inner brow goes down and in"


def test_au10_raises_the_upper_lip(head, rest):
    m = moved(head, rest, {"AU10_left": 1})
    assert m["8.5"][1] > 3.0 and abs(m["8.7"][1]) < 0.3, "upper lip up, lower lip stays"
    m = moved(head, rest, {"AU10_middle": 1})
    assert m["8.1"][1] > 3.0 and abs(m["8.2"][1]) < 0.3
    assert m["8.1"][1] > 2 * m["8.5"][1], "the middle of the upper lip"


def test_au11_lifts_the_nose_wing_and_the_top_of_the_furrow(head, rest):
    m = moved(head, rest, {"AU11_left": 1})
    assert m["9.5"][1] > 3.0 and m["9.5"][0] > 0.5, "the wing's base up and out: the furrow deepens"
    assert np.linalg.norm(m["8.3"]) < 0.3, "without moving the lip corner"


def test_au12_pulls_the_lip_corners_up_and_out(head, rest):
    m = moved(head, rest, {"AU12_left": 1, "AU12_right": 1})
    assert m["8.3"][1] > 8.0 and m["8.4"][1] > 8.0, "corners up"
    assert m["8.3"][0] > 5.0 and m["8.4"][0] < -5.0, "and out"


def test_au15_pulls_the_lip_corners_down(head, rest):
    m = moved(head, rest, {"AU15_left": 1, "AU15_right": 1})
    assert m["8.3"][1] < -4.0 and m["8.4"][1] < -4.0
    assert m["8.3"][1] < m["8.7"][1] - 3.0, "the corners more than the lower lip"


def test_au16_lowers_the_lower_lip(head, rest):
    m = moved(head, rest, {"AU16_left": 1, "AU16_right": 1})
    assert m["8.7"][1] < -3.0 and m["8.8"][1] < -3.0 and m["8.2"][1] < -1.0
    assert abs(m["8.1"][1]) < 0.2, "the upper lip stays"


def test_au17_raises_the_chin_and_the_lower_lip(head, rest):
    m = moved(head, rest, {"AU17": 1})
    assert m["2.10"][1] > 1.0, "the chin boss rises"
    assert m["8.2"][1] > 3.0, "and pushes the lower lip up"


def test_au20_stretches_the_lips_sideways(head, rest):
    lm = head.landmark_positions({"AU20_left": 1, "AU20_right": 1})
    wider = np.linalg.norm(lm["8.3"] - lm["8.4"]) - np.linalg.norm(rest["8.3"] - rest["8.4"])
    assert wider > 8.0, f"the corners move only {wider:.1f} mm apart"
    assert lm["8.3"][1] <= rest["8.3"][1], "sideways and a little down, not up (that would be AU12)"


def test_au23_and_au24_narrow_and_press_the_lips(head, rest):
    def red(lm):
        return lm["8.1"][1] - lm["8.2"][1]
    for values in ({"AU23": 1}, {"AU24_left": 1, "AU24_right": 1}):
        lm = head.landmark_positions(values)
        assert red(lm) < red(rest) - 1.0, f"{values}: the lips' red narrows by {red(rest) - red(lm):.1f} mm"
        assert np.linalg.norm(lm["2.2"] - lm["2.3"]) < 4.0, f"{values}: the lips stay together"


def test_au26_is_the_jaw_and_lowers_the_chin(head, rest):
    """AU25/26/27 are one parameter in Table 1: jaw_open (0.1 parts the lips, 0.5 drops the jaw, 1 stretches)."""
    gaps = [np.linalg.norm(head.landmark_positions({"jaw_open": v})["2.2"] - head.landmark_positions(
        {"jaw_open": v})["2.3"]) for v in (0.1, 0.5, 1.0)]
    assert 3.5 < gaps[0] < 7 and gaps[1] > 12 and gaps[2] > 25
    assert moved(head, rest, {"jaw_open": 0.5})["2.1"][1] < -4.0


def test_au38_dilates_and_au39_compresses_the_nostril(head, rest):
    assert moved(head, rest, {"AU38_left": 1})["9.1"][0] > 1.0
    assert moved(head, rest, {"AU38_left": -1})["9.1"][0] < -1.0


# -- against the artist's poses ---------------------------------------------------------

def test_each_action_unit_reproduces_its_artist_pose(head, recipe):
    """Value 1 against the pose the derivation fitted it to (its sources added, scaled to FACS
    intensity E and masked, and its furrows added).

    The bounds are those documented in docs/default-head.md with a margin: RMS over the moved
    vertices below 0.9 mm, and at least 85 % of the pose.
    """
    names = {u.name for u in recipe.ACTION_UNITS}
    assert names == set(AU_PARAMETERS)
    skin = recipe.creases.Skin.of(head)
    lids = np.concatenate([head.regions[f"eyelid_{side}_close"].indices for side in ("left", "right")])
    for unit in recipe.ACTION_UNITS:
        target = recipe.unit_target(unit, reference_pose, head, skin=skin)
        got = head.deform({unit.name: 1.0}) - head.vertices
        residual = target - got
        moved_ = np.linalg.norm(target, axis=1) > 1e-9
        rms = np.sqrt(np.mean(np.sum(residual[moved_] ** 2, axis=1)))
        explained = 1 - np.sum(residual ** 2) / np.sum(target ** 2)
        assert rms < 0.9 and explained > 0.85, f"{unit.name}: RMS {rms:.3f} mm, {explained:.1%} of the pose"
        if unit.kind == "field" and not unit.lips:      # the pose itself, bar a few lashes kept off the eye
            off = np.linalg.norm(got - target, axis=1)
            # the rest upper lids were lowered after the fit (rest_lids.py): their skin moved a few hundredths
            # of a mm, and with it the band mask there (the target is recomputed on the lowered lids)
            off[lids] = np.where(off[lids] < 0.01, 0.0, off[lids])
            assert np.sum(off > 1e-3) <= 5 and off.max() < 0.2, unit.name


def test_left_and_right_add_up_to_the_bilateral_pose(head, recipe):
    """The midline mask shares the artist's bilateral pose out: the two fields of AU9's nose add up to it
    (and to all of its furrows)."""
    eye_level = head.landmark_positions()["3.5"][1]
    unit = next(u for u in recipe.ACTION_UNITS if u.name == "AU9_left_nose")
    both = head.deform({"AU9_left_nose": 1, "AU9_right_nose": 1}) - head.vertices
    lower = recipe.band_mask(head.vertices[:, 1], eye_level, "lower")
    whole = recipe.source_pose(unit, reference_pose) * lower[:, None] \
        + recipe.APPEARANCE["AU9_nose"](recipe.creases.Skin.of(head))
    off = np.linalg.norm(both - whole, axis=1)
    lids = np.concatenate([head.regions[f"eyelid_{side}_close"].indices for side in ("left", "right")])
    off[lids] = np.where(off[lids] < 0.01, 0.0, off[lids])     # the rest lids lowered after the fit (rest_lids.py)
    assert np.sum(off > 1e-3) <= 5 and off.max() < 0.2, "equal, bar a few lashes kept off the eyeball"


# -- nothing passes through anything -----------------------------------------------------




@pytest.mark.parametrize("values", [
    {"AU5_left": 1}, {"AU6_left": 1}, {"AU7_left": 1}, {"AU4_left": 1}, {"AU9_left_brow": 1},
    {"AU5_left": 1, "AU7_left": 1}, {"AU4_left": 1, "AU6_left": 1, "AU7_left": 1, "AU9_left_brow": 1},
    {"eyelid_left_close": 0.4, "AU6_left": 1, "AU7_left": 1}, {"AU1_left": 1, "AU2_left": 1, "AU5_left": 1},
    {"eyelid_left_close": 1, "AU6_left": 1}, {"AU12_left": 1, "AU6_left": 1},
], ids=lambda v: "+".join(f"{k}={v:g}" for k, v in v.items()))
def test_the_lids_stay_off_the_eyeball(head, values):
    """The lids slide over the eyeball: at most 0.05 mm in, the blink's own (eyelid_left_close 1: 0.04 mm)."""
    assert eyeball_entry_mm(head, head.deform(values)) < 0.05, values


LIP_POSES = [{"AU12_left": v, "AU12_right": v} for v in (0.3, 0.6, 1.0)] + [
    {"AU12_left": 1}, {"AU17": 0.5}, {"AU17": 1}, {"AU23": 0.5}, {"AU23": 1}, {"AU24_left": 1, "AU24_right": 1},
    {"AU24_left": 1}, {"AU23": 1, "AU24_left": 1, "AU24_right": 1}, {"AU17": 1, "AU23": 1},
    {"AU17": 1, "AU24_left": 1, "AU24_right": 1}, {"AU15_left": 1, "AU15_right": 1, "AU17": 1},
    {"AU12_left": 1, "AU12_right": 1, "AU6_left": 1, "AU6_right": 1}, {"AU20_left": 1, "AU20_right": 1},
    {"AU10_left": 1, "AU10_right": 1, "AU10_middle": 1}, {"AU16_left": 1, "AU16_right": 1},
]


@pytest.mark.parametrize("values", LIP_POSES, ids=lambda v: "+".join(f"{k}={v:g}" for k, v in v.items()))
def test_the_lips_never_pass_through_each_other(head, lips, values):
    """The artist's smile, chin raiser, lip roll and press push the lower lip through the upper one on
    this mesh; the derivation lowers it (docs/default-head.md) so that they, and their combinations, do not."""
    assert_lips_apart(lips, head.deform(values), str(values))
