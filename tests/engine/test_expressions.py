"""The expression commands of the shipped library on the default head (§3.2).

Neutral and the six basic emotions (plus contempt and a happy-surprise blend)
are ``engine/library/*.lib`` files built from the action units of Table 1, played by
``attack-hold-release``. These tests translate each like any script, sample it
on a timeline, deform the head, and check the landmarks at the apex; and the
timing, intensity, one-sided variants and additive blends.
"""

import numpy as np
import pytest

from engine.commands import load_library, parse_commands_text, translate
from engine.timeline.timeline import Timeline
from tests.engine.cli_runner import run
from tests.engine.face_geometry import Lips, assert_lips_apart, eyeball_entry_mm

EXPRESSIONS = ["Neutral", "Happy", "Sad", "Surprise", "Fear", "Anger", "Disgust", "Contempt", "HappySurprise",
               "HappyBroad"]



@pytest.fixture(scope="module")
def library():
    return load_library()


@pytest.fixture(scope="module")
def rest(head):
    return head.landmark_positions()


@pytest.fixture(scope="module")
def lips(head):
    return Lips(head)


def play(head, library, script):
    """The timeline of a one-line script."""
    return Timeline(translate(parse_commands_text(f"<commands>{script}</commands>"), library, head), head)


def apex_time(library, name, **given):
    args = {**library[name].optional, **given}
    return given.get("at", 0.0) + args["onset"] + args["apex"] / 2


def at_apex(head, library, name, **given):
    """Parameter values in the middle of the apex of ``<name at="0" …/>``."""
    attributes = " ".join(f'{k}="{v}"' for k, v in given.items())
    return play(head, library, f'<{name} at="0" {attributes}/>').values_at(apex_time(library, name, **given))


def moved(head, rest, values):
    lm = head.landmark_positions(values)
    return {k: lm[k] - rest[k] for k in lm}


# -- the library --------------------------------------------------------------------------

def test_the_expressions_are_in_the_shipped_library_and_bind_to_the_default_head(head, library):
    for name in EXPRESSIONS:
        assert name in library, name
        definition = library[name]
        assert definition.procedure == "attack-hold-release", name
        assert {"amplitude", "onset", "apex", "offset"} <= set(definition.optional), name
        assert definition.description, name
    assert library.check(head) == []


def test_the_cli_lists_them(head):
    result = run("library")
    assert result.returncode == 0, result.stderr
    for name in EXPRESSIONS:
        assert f"\n{name} " in "\n" + result.stdout, name


def test_expressions_drive_action_units_only(head, library):
    """Built from Table 1: every line is an AU parameter or jaw_open (AU25/26/27)."""
    for name in EXPRESSIONS:
        for parameter in library.parameters_of(name, head):
            assert parameter.startswith("AU") or parameter == "jaw_open", (name, parameter)


# -- what each expression does at its apex --------------------------------------------------

def test_neutral_leaves_the_face_at_rest(head, library):
    values = at_apex(head, library, "Neutral")
    np.testing.assert_array_equal(head.deform(values), head.deform())


def test_happy_pulls_the_lip_corners_up_and_raises_the_cheeks(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Happy"))
    assert m["8.3"][1] > 8.0 and m["8.4"][1] > 8.0, "lip corners up"
    assert m["8.3"][0] > 5.0 and m["8.4"][0] < -5.0, "and out"
    assert m["3.3"][1] > 0.3 and m["3.4"][1] > 0.3, "the cheeks push the lower lids up (AU6)"


def test_sad_raises_the_inner_brows_and_pulls_the_corners_down(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Sad"))
    assert m["4.1"][1] > 2.0 and m["4.2"][1] > 2.0, "inner brows up"
    assert m["4.1"][1] > m["4.5"][1] + 2.0, "more than the outer brows: the oblique brow of sadness"
    assert m["8.3"][1] < -4.0 and m["8.4"][1] < -4.0, "lip corners down"


def test_surprise_raises_the_brows_and_drops_the_jaw(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Surprise"))
    for key in ("4.1", "4.2", "4.5", "4.6"):
        assert m[key][1] > 4.0, key
    assert m["3.1"][1] > 0.8, "upper lids up (AU5B)"
    assert m["2.1"][1] < -3.0 and m["2.3"][1] < -8.0, "jaw down"


def test_fear_raises_and_draws_the_brows_widens_the_eyes_and_stretches_the_mouth(head, library, rest):
    values = at_apex(head, library, "Fear")
    lm, m = head.landmark_positions(values), moved(head, rest, values)
    assert m["4.1"][1] > 1.0 and m["4.5"][1] > 2.0, "brows up"
    assert np.linalg.norm(lm["4.1"] - lm["4.2"]) < np.linalg.norm(rest["4.1"] - rest["4.2"]) - 1.5, "drawn together"
    assert m["3.1"][1] > 2.0, "upper lids up (AU5)"
    assert m["3.3"][1] > 0.5, "lower lids tense (AU7)"
    assert m["8.3"][0] > 3.0 and m["8.4"][0] < -3.0 and m["8.3"][1] < 0, "lips stretched sideways (AU20)"
    assert m["2.1"][1] < -1.5, "jaw dropped a little"


def test_fear_and_surprise_differ_where_ekman_says(head, library, rest):
    """The paper's still pictures confused the two (§4): here fear's brows are lower and closer together,
    its lower lids tenser and its mouth wider."""
    fear, surprise = (head.landmark_positions(at_apex(head, library, n)) for n in ("Fear", "Surprise"))
    assert fear["4.1"][1] < surprise["4.1"][1] - 1.0
    assert np.linalg.norm(fear["4.1"] - fear["4.2"]) < np.linalg.norm(surprise["4.1"] - surprise["4.2"]) - 1.5
    assert fear["3.3"][1] > surprise["3.3"][1] + 0.5
    assert np.linalg.norm(fear["8.3"] - fear["8.4"]) > np.linalg.norm(surprise["8.3"] - surprise["8.4"]) + 5


def test_anger_lowers_and_draws_the_brows_and_narrows_the_lips(head, library, rest):
    values = at_apex(head, library, "Anger")
    lm, m = head.landmark_positions(values), moved(head, rest, values)
    assert m["4.1"][1] < -3.0 and m["4.3"][1] < -3.0, "brows down"
    assert np.linalg.norm(lm["4.1"] - lm["4.2"]) < np.linalg.norm(rest["4.1"] - rest["4.2"]) - 3.0, "and together"
    assert m["3.3"][1] > 1.5, "lower lids tense (AU7)"
    assert (lm["8.1"][1] - lm["8.2"][1]) < (rest["8.1"][1] - rest["8.2"][1]) - 1.5, "lips narrowed (AU23)"


def test_disgust_wrinkles_the_nose_and_raises_the_upper_lip(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Disgust"))
    anger = moved(head, rest, at_apex(head, library, "Anger"))
    assert m["9.1"][1] > 2.0 and m["9.2"][1] > 2.0, "nose wings up (AU9)"
    assert m["8.5"][1] > 2.0 and m["8.6"][1] > 2.0, "upper lip up (AU9, AU10)"
    assert m["8.5"][1] > anger["8.5"][1] + 2.0, "more than anger's"
    assert m["8.7"][1] > 1.0 and m["8.8"][1] > 1.0, "the lower lip pushed up under it (AU17: 9 + 10 + 17)"
    assert m["4.1"][1] > anger["4.1"][1] + 2.0, "the brows lowered far less than anger's (AU9's pull, no AU4)"
    lm, angry = (head.landmark_positions(at_apex(head, library, n)) for n in ("Disgust", "Anger"))
    assert np.linalg.norm(lm["4.1"] - lm["4.2"]) > np.linalg.norm(angry["4.1"] - angry["4.2"]) + 1.0, \
        "drawn together less than anger's"


def test_contempt_is_one_sided(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Contempt"))
    assert m["8.3"][1] > 3.0 and m["8.3"][0] > 2.0, "the left corner tightens up and out"
    assert np.linalg.norm(m["8.4"]) < 0.05, "the right corner stays"
    m = moved(head, rest, at_apex(head, library, "Contempt", left=0, right=1))
    assert m["8.4"][1] > 3.0 and np.linalg.norm(m["8.3"]) < 0.05


def test_happy_surprise_blends_surprised_brows_with_a_smile(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "HappySurprise"))
    assert m["4.1"][1] > 3.0 and m["4.5"][1] > 3.0, "surprised brows"
    assert m["8.3"][1] > 5.0 and m["8.4"][1] > 5.0, "a smile"
    assert m["2.1"][1] < -2.0, "and the jaw dropped"


# -- timing, intensity, sides, blends -----------------------------------------------------------

@pytest.mark.parametrize("name", EXPRESSIONS[1:])
def test_onset_apex_offset(head, library, name):
    """Rest before ``at``, full levels through the apex, rest again after the offset."""
    t = play(head, library, f'<{name} at="1000" onset="200" apex="600" offset="300"/>')
    parameters = library.parameters_of(name, head)
    defaults = library[name].optional
    levels = {c.name: c.values[0] * (defaults[c.scale] if c.scale else 1.0) for c in library[name].curves}

    def level(time, p):
        return t.values_at(time)[p]
    for p in parameters:
        assert level(999, p) == 0.0 and level(2101, p) == 0.0, p
        assert level(1200, p) == pytest.approx(levels[p]) and level(1800, p) == pytest.approx(levels[p]), p
        assert abs(level(1100, p)) < abs(levels[p]) or levels[p] == 0.0, p


@pytest.mark.parametrize("name", EXPRESSIONS[1:])
def test_amplitude_scales_the_intensity(head, library, name):
    full, half = at_apex(head, library, name), at_apex(head, library, name, amplitude=50)
    for p in library.parameters_of(name, head):
        assert half[p] == pytest.approx(full[p] / 2), p


def test_one_sided_happy_moves_only_the_left_corner(head, library, rest):
    m = moved(head, rest, at_apex(head, library, "Happy", right=0))
    assert m["8.3"][1] > 8.0
    assert np.linalg.norm(m["8.4"]) < 0.05 and np.linalg.norm(m["3.4"]) < 0.01


def test_one_sided_open_smile_leaves_the_other_corner_where_the_jaw_alone_puts_it(head, library, rest):
    """HappyBroad's jaw is a midline parameter and opens on both sides; the right corner moves with it only."""
    values = at_apex(head, library, "HappyBroad", right=0)
    jaw_only = moved(head, rest, {"jaw_open": values["jaw_open"]})
    m = moved(head, rest, values)
    assert values["jaw_open"] > 0.2 and m["8.3"][1] > 8.0
    assert np.linalg.norm(m["8.4"] - jaw_only["8.4"]) < 0.05 and np.linalg.norm(m["3.4"]) < 0.01


def test_two_expressions_at_half_amplitude_blend(head, library):
    """Activations of one parameter add on the timeline, so two commands at 50 % are an even blend."""
    t = play(head, library, '<Happy at="0" amplitude="50" onset="300" apex="1000" offset="300"/>'
                            '<Surprise at="0" amplitude="50" onset="300" apex="1000" offset="300"/>')
    blend = t.values_at(800)
    happy = play(head, library, '<Happy at="0" onset="300" apex="1000" offset="300"/>').values_at(800)
    surprise = play(head, library, '<Surprise at="0" onset="300" apex="1000" offset="300"/>').values_at(800)
    for p in blend:
        assert blend[p] == pytest.approx((happy[p] + surprise[p]) / 2), p
    lm = head.landmark_positions(blend)
    rest = head.landmark_positions()
    assert lm["8.3"][1] > rest["8.3"][1] + 3 and lm["4.5"][1] > rest["4.5"][1] + 2 and lm["2.1"][1] < rest["2.1"][1]


# -- nothing passes through anything -------------------------------------------------------------

@pytest.mark.parametrize("name", EXPRESSIONS)
def test_expressions_keep_lips_and_lids_where_they_belong(head, library, lips, name):
    values = at_apex(head, library, name)
    P = head.deform(values)
    assert eyeball_entry_mm(head, P) < 0.05, name
    if values["jaw_open"] < 0.05:            # with the jaw open the lips are apart anyway
        assert_lips_apart(lips, P, name)
