"""Expressions at FACS strength (issue 32, item 4): the action units at intensity E and the EMFACS prototypes.

Each AU at value 1 is FACS intensity E, its maximum (docs/default-head.md, "Action
units at FACS intensity E"): these tests check, on the default head and on the
smallest face of the identity checks, that each moves its landmarks at least the
documented millimetres the way FACS describes, and that it carries the furrows
FACS lists among its appearance changes (the forehead lines of AU1 + 2, the
glabellar furrows of AU4, the lower lid's bag of AU6, the nose root of AU9, the
nasolabial furrow of AU12, the mentolabial sulcus of AU17), measured as how much
deeper a vertex goes than the ring of vertices around it. A relaxed rest lid
covers the top of the iris. The library's prototypes have the AUs EMFACS gives
them (fear with AU4, AU7 and AU20, surprise without), on FACS's A–E scale, and
the real emotion classifier reads the default head's neutral face and smile as
such (docs/validation.md).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import sparse

import engine
import engine.paths
from engine.commands import load_library
from engine.identity import Identity, make_identity_head
from engine.identity.rest_lids import REST_COVER, iris_radius, lower_lid_cover, upper_lid_cover

SMALLEST_FACE = {"sex": 0.0, "age": 28, "asian": 1.0, "african": 0.0, "caucasian": 0.0}   # test_identity_checks
FACS_LEVELS = {0.1, 0.25, 0.5, 0.8, 1.0}            # A, B, C, D, E (docs/expressions.md)


def both(stem, value=1.0, suffix=""):
    return {f"{stem}_left{suffix}": value, f"{stem}_right{suffix}": value}


@pytest.fixture(scope="module", params=["default", "smallest-face"])
def head(request):
    return engine.load_model() if request.param == "default" else make_identity_head(Identity(SMALLEST_FACE))


@pytest.fixture(scope="module")
def rest(head):
    return head.landmark_positions()


@pytest.fixture(scope="module")
def rings(head):
    """Skin normals and the mean over each vertex's neighbours (a sparse averaging matrix)."""
    V = head.vertices
    skin = head.vertex_part == head.parts.index("skin")
    tri = head.triangles()
    tri = tri[skin[tri].all(axis=1)]
    cross = np.cross(V[tri[:, 1]] - V[tri[:, 0]], V[tri[:, 2]] - V[tri[:, 0]])
    normals = np.zeros_like(V)
    for k in range(3):
        np.add.at(normals, tri[:, k], cross)
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    e = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    A = sparse.coo_matrix((np.ones(2 * len(e)), (np.r_[e[:, 0], e[:, 1]], np.r_[e[:, 1], e[:, 0]])),
                          shape=(len(V), len(V))).tocsr()
    A.data[:] = 1.0
    mean = sparse.diags(1.0 / np.maximum(A.sum(axis=1).A1, 1)) @ A
    return normals, mean, skin


def moved(head, rest, values):
    lm = head.landmark_positions(values)
    return {k: lm[k] - rest[k] for k in lm}


def furrow_mm(head, rings, values, where):
    """The deepest furrow the pose makes among the skin vertices ``where(V, landmarks)`` selects: how much
    further in (along the rest normal) a vertex goes than the mean of its neighbours, mm."""
    normals, mean, skin = rings
    d = np.einsum("ij,ij->i", head.deform(values) - head.vertices, normals)
    sel = where(head.vertices, head.landmark_positions()) & skin
    return float((mean @ d - d)[sel].max())


# -- the rest lids ----------------------------------------------------------------------------

def test_the_rest_upper_lid_covers_the_top_of_the_iris(head):
    """A relaxed lid, not AU5: at least REST_COVER of the iris radius (2.2 mm on the default head)."""
    for side in ("left", "right"):
        r = iris_radius(head, side)
        assert upper_lid_cover(head, side) >= REST_COVER * r - 0.03, side
        assert upper_lid_cover(head, side) < r, f"{side}: the pupil's centre shows"
        assert lower_lid_cover(head, side) > 0, f"{side}: no sclera below the iris at rest"


# -- each AU at E -----------------------------------------------------------------------------

def test_au1_and_au2_raise_the_brows_high_and_crease_the_forehead(head, rest, rings):
    assert moved(head, rest, both("AU1"))["4.1"][1] > 6.0, "AU1: the inner brow 8.5 mm up on the default head"
    assert moved(head, rest, both("AU2"))["4.5"][1] > 5.5, "AU2: the outer brow 8.4 mm up"
    raised = {**both("AU1"), **both("AU2")}
    assert moved(head, rest, raised)["4.3"][1] > 5.5, "1+2: the brow over the pupil 7.1 mm up (people: 7.6-9)"
    forehead = furrow_mm(head, rings, raised, lambda V, lm: (V[:, 1] > lm["4.3"][1] + 5)
                         & (V[:, 1] < lm["4.3"][1] + 40) & (np.abs(V[:, 0]) < 40) & (V[:, 2] > lm["4.3"][2] - 10))
    assert forehead > 0.5, f"1+2: forehead lines only {forehead:.2f} mm deep"


def test_au4_lowers_and_draws_the_brows_with_furrows_between_them(head, rest, rings):
    lm = head.landmark_positions(both("AU4"))
    assert rest["4.1"][1] - lm["4.1"][1] > 5.0 and rest["4.3"][1] - lm["4.3"][1] > 5.0, "the brows down"
    closer = np.linalg.norm(rest["4.1"] - rest["4.2"]) - np.linalg.norm(lm["4.1"] - lm["4.2"])
    assert closer > 4.5, f"the inner brows only {closer:.1f} mm closer"
    glabella = furrow_mm(head, rings, both("AU4"), lambda V, lm: (np.abs(V[:, 0]) < lm["4.1"][0])
                         & (V[:, 1] > lm["3.11"][1]) & (V[:, 1] < lm["4.1"][1] + 8) & (V[:, 2] > lm["4.1"][2] - 8))
    assert glabella > 0.7, f"the vertical furrows between the brows only {glabella:.2f} mm deep"


def test_au5_raises_the_upper_lid_over_the_iris(head):
    for side in ("left", "right"):
        rise = upper_lid_cover(head, side) - upper_lid_cover(head, side, head.deform(both("AU5")))
        assert rise > 3.5, f"{side}: the lid rises {rise:.1f} mm over the iris"
        assert upper_lid_cover(head, side, head.deform(both("AU5"))) < -0.5, f"{side}: sclera above the iris"


def test_au6_pushes_the_lower_lid_up_and_bags_the_skin_below_it(head, rings):
    lift = lower_lid_cover(head, "left", head.deform(both("AU6"))) - lower_lid_cover(head, "left")
    assert lift > 1.8, f"the lower lid rises {lift:.1f} mm over the iris"
    bag = furrow_mm(head, rings, both("AU6"), lambda V, lm: (np.abs(V[:, 0] - lm["3.3"][0]) < 15)
                    & (V[:, 1] < lm["3.3"][1] - 3) & (V[:, 1] > lm["3.3"][1] - 16) & (V[:, 0] > 0))
    assert bag > 0.6, f"the furrow under the lower lid's bag only {bag:.2f} mm deep"


def test_au7_raises_the_lower_lid(head):
    lift = lower_lid_cover(head, "left", head.deform(both("AU7"))) - lower_lid_cover(head, "left")
    assert lift > 2.0, f"the lower lid rises {lift:.1f} mm"


def test_au9_wrinkles_the_root_of_the_nose_and_lifts_its_wings(head, rest, rings):
    nose = both("AU9", suffix="_nose")
    assert moved(head, rest, {**nose, **both("AU9", suffix="_brow")})["9.1"][1] > 1.6, "the wings up"
    root = furrow_mm(head, rings, nose, lambda V, lm: (np.abs(V[:, 0]) < 10) & (V[:, 1] < lm["3.11"][1] + 4)
                     & (V[:, 1] > lm["3.11"][1] - 12) & (V[:, 2] > lm["3.11"][2]))
    assert root > 0.3, f"the lines across the root of the nose only {root:.2f} mm deep"


def test_au10_raises_the_upper_lip(head, rest):
    assert moved(head, rest, {**both("AU10"), "AU10_middle": 1.0})["8.1"][1] > 6.5


def test_au12_pulls_the_corners_up_and_back_and_deepens_the_nasolabial_furrow(head, rest, rings):
    m = moved(head, rest, both("AU12"))
    assert m["8.3"][1] > 9.0 and m["8.3"][0] > 5.5 and m["8.3"][2] < -3.0, "the corner up, out and back"
    fold = furrow_mm(head, rings, both("AU12"), lambda V, lm: (V[:, 0] > lm["9.5"][0])
                     & (V[:, 0] < lm["8.3"][0] + 12) & (V[:, 1] < lm["9.5"][1] + 4) & (V[:, 1] > lm["8.3"][1] - 10)
                     & (V[:, 2] > lm["8.3"][2] - 15))
    assert fold > 3.0, f"the nasolabial furrow only {fold:.2f} mm deep"


def test_au15_turns_the_corners_down(head, rest):
    m = moved(head, rest, both("AU15"))
    assert m["8.3"][1] < -6.0 and m["8.4"][1] < -6.0


def test_au17_pushes_the_chin_boss_up_under_a_deeper_sulcus(head, rest, rings):
    m = moved(head, rest, {"AU17": 1.0})
    assert m["2.10"][1] > 2.8, "the chin boss up"
    assert m["8.2"][1] > 3.5, "and the lower lip with it"
    sulcus = furrow_mm(head, rings, {"AU17": 1.0}, lambda V, lm: (np.abs(V[:, 0]) < 15)
                       & (V[:, 1] < lm["2.3"][1] - 5) & (V[:, 1] > lm["2.10"][1]) & (V[:, 2] > lm["2.10"][2] - 12))
    assert sulcus > 1.5, f"the mentolabial sulcus only {sulcus:.2f} mm deep"


def test_au20_stretches_the_lips_sideways(head, rest):
    lm = head.landmark_positions(both("AU20"))
    wider = np.linalg.norm(lm["8.3"] - lm["8.4"]) - np.linalg.norm(rest["8.3"] - rest["8.4"])
    assert wider > 12.0, f"the corners only {wider:.1f} mm further apart"
    assert lm["8.3"][1] < rest["8.3"][1], "sideways and down, not up"


# -- the appearance masks ------------------------------------------------------------------------

def test_the_facs_appearance_file_holds_each_aus_furrows():
    """engine/data/default-head/facs-appearance.h5: per AU parameter, where its furrows and bulges lie (for
    wrinkle maps); AU4's deepest furrow lies between the brows, AU12's beside the mouth."""
    import h5py

    head = engine.load_model()
    lm = head.landmark_positions()
    with h5py.File(engine.paths.DEFAULT_HEAD_DIR / "facs-appearance.h5", "r") as f:
        assert f.attrs["format"] == "artificial-person-poses"
        group = f["facs_appearance"]
        assert {"AU1_left", "AU2_left", "AU4_left", "AU6_left", "AU9_left_nose", "AU12_left", "AU17"} <= set(group)
        for name, g in group.items():
            idx = g["indices"][()]
            assert idx.max() < head.n_vertices and len(idx) == len(g["depth"]), name
            depth = g["depth"][()]
            assert np.abs(depth).max() > 0.5, f"{name}'s appearance moves the skin"
            if not name.startswith("AU15"):                 # AU15's is a pouch, the others' furrows
                assert depth.min() < -0.5, f"{name} has a furrow"
        for name, where in (("AU4_left", lambda p: 0 < p[0] < lm["4.1"][0] and lm["3.11"][1] < p[1] < lm["4.1"][1] + 8),
                            ("AU12_left", lambda p: lm["8.3"][0] < p[0] < lm["8.3"][0] + 14
                             and lm["8.3"][1] - 12 < p[1] < lm["9.5"][1] + 5)):
            g = group[name]
            deepest = g["indices"][int(np.argmin(g["depth"][()]))]
            assert where(head.vertices[deepest]), f"{name}'s deepest furrow at {head.vertices[deepest].round(1)}"


# -- the prototypes ---------------------------------------------------------------------------------

def levels(library, name):
    defaults = library[name].optional
    return {c.name: c.values[0] * (defaults[c.scale] if c.scale else 1.0) for c in library[name].curves}


def aus(library, name):
    """The AUs an expression raises: ``AU4`` for AU4_left …, ``AU26`` and the like for jaw_open."""
    out = set()
    for parameter, level in levels(library, name).items():
        if level > 0:
            out.add("AU25/26/27" if parameter == "jaw_open" else parameter.split("_")[0])
    return out


def test_fear_has_au4_au7_and_au20_and_surprise_none_of_them():
    library = load_library()
    fear, surprise = aus(library, "Fear"), aus(library, "Surprise")
    assert {"AU1", "AU2", "AU4", "AU5", "AU7", "AU20", "AU25/26/27"} <= fear
    assert {"AU1", "AU2", "AU5", "AU25/26/27"} <= surprise
    assert not {"AU4", "AU7", "AU20"} & surprise
    assert levels(library, "Fear")["AU5_left"] > levels(library, "Surprise")["AU5_left"], "fear's eyes wider"


def test_sadness_has_its_oblique_brows_and_its_pout():
    library = load_library()
    assert {"AU1", "AU4", "AU15", "AU17"} <= aus(library, "Sad")
    sad = levels(library, "Sad")
    assert sad["AU1_left"] > 2 * sad["AU4_left"], "the inner brows raised more than lowered: oblique"


def test_happiness_is_the_cheeks_and_the_corners_and_nothing_of_the_brows():
    library = load_library()
    for name in ("Happy", "HappyOpen", "HappyBroad"):
        happy = aus(library, name)
        assert {"AU6", "AU12"} <= happy, name
        assert not {"AU1", "AU2", "AU4", "AU15", "AU20"} & happy, name


def test_anger_has_4_5_7_23_and_disgust_9_10_with_less_of_anger_s_brows():
    """Disgust is told from anger by the nose and the upper lip, not the brows (EMFACS 9, 10 against
    4 + 5 + 7 + 23): less AU4, more AU9's nose part and AU10 than anger, and no glare (AU5)."""
    library = load_library()
    for name in ("Anger", "AngerOpen"):
        assert {"AU4", "AU5", "AU7", "AU23"} <= aus(library, name), name
    assert {"AU9", "AU10"} <= aus(library, "Disgust")
    assert "AU5" not in aus(library, "Disgust")
    anger, disgust = levels(library, "Anger"), levels(library, "Disgust")
    assert disgust.get("AU4_left", 0) < anger["AU4_left"], "less AU4 than anger"
    assert disgust["AU9_left_nose"] > anger.get("AU9_left_nose", 0), "more of the nose wrinkled"
    assert disgust["AU10_left"] > anger.get("AU10_left", 0), "more of the upper lip raised"


def test_surprise_has_the_whole_brow_raised_and_fear_the_stretched_lips():
    library = load_library()
    surprise, fear = levels(library, "Surprise"), levels(library, "Fear")
    assert surprise["AU1_left"] >= 0.8 and surprise["AU2_left"] >= 0.8, "1 + 2 at D or E"
    assert fear["AU20_left"] >= 0.8 and fear["AU4_left"] >= 0.25, "fear's 20 at D or E, its 4 at least B"
    assert surprise["jaw_open"] >= 0.2, "surprise's jaw dropped (AU26)"


def test_the_open_variants_part_the_lips():
    library = load_library()
    assert aus(library, "HappyOpen") == {"AU6", "AU12", "AU25/26/27"}
    assert {"AU4", "AU5", "AU7", "AU10", "AU23", "AU25/26/27"} <= aus(library, "AngerOpen")
    head = engine.load_model()
    assert aus(library, "HappyBroad") == {"AU6", "AU12", "AU16", "AU25/26/27"}
    for name, gap in (("HappyBroad", 8.0), ("HappyOpen", 4.0), ("AngerOpen", 5.0), ("Surprise", 12.0),
                      ("SurpriseWide", 20.0)):
        lm = head.landmark_positions(levels(library, name))
        assert np.linalg.norm(lm["2.2"] - lm["2.3"]) > gap, name


@pytest.mark.parametrize("name", ["Happy", "HappyOpen", "HappyBroad", "Sad", "Surprise", "SurpriseWide", "Fear",
                                  "Anger", "AngerOpen", "Disgust", "Contempt", "HappySurprise"])
def test_levels_are_facs_intensities(name):
    """Every AU level is one of A–E (0.1, 0.25, 0.5, 0.8, 1); jaw_open, AU25/26/27, is millimetres of opening."""
    for parameter, level in levels(load_library(), name).items():
        if parameter != "jaw_open" and level:
            assert level in FACS_LEVELS, f"{name}: {parameter} at {level}"


# -- read by the classifier ---------------------------------------------------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("name, emotion", [("Neutral", "neutral"), ("Happy", "happy"), ("HappyOpen", "happy"),
                                                 ("HappyBroad", "happy")])
def test_the_classifier_reads_the_default_heads_face(name, emotion):
    """The FER2013 classifier (docs/validation.md) on the front picture at the middle of the apex."""
    pytest.importorskip("dlib")
    from engine.commands import parse_commands_text, translate
    from engine.outputs.render import render_model
    from engine.timeline.timeline import Timeline
    from engine.validation.faces import look
    from engine.validation.observers import EMOTIONS

    head, library = engine.load_model(), load_library()
    commands = parse_commands_text(f'<commands><{name} at="0"/></commands>')
    args = library[name].optional
    values = Timeline(translate(commands, library, head), head).values_at(args["onset"] + args["apex"] / 2)
    seen = look(render_model(head, values, view="front", size=(640, 480)), describe=False)
    scores = dict(zip(EMOTIONS, seen.emotions.round(2), strict=True))
    assert seen.judged == emotion, f"{name} read as {seen.judged} ({scores})"
