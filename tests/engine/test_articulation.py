"""Articulation without Festival: the phone table, coarticulation, inline commands, prosody."""

from __future__ import annotations

import itertools
from collections import namedtuple

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.errors import CommandError, LibraryError, UserError
from engine.script.inline_commands import anchored_commands, parse_script, word_start_times
from engine.speech.articulation import load_articulation, parse_articulation
from engine.speech.coarticulation import articulate, articulation_tracks, closure_window, key_times
from engine.speech.prosody import prosody_commands, split_phrases, syllables

Seg = namedtuple("Seg", "label start_ms end_ms")

SUOPUHE_PHONES = ["#", "##", "a", "e", "i", "o", "u", "y", "@", "7", "p", "t", "k", "b", "d", "g", "f", "h", "j",
                  "l", "m", "n", "N", "r", "s", "v", "S", "T"]


@pytest.fixture(scope="module")
def table():
    return load_articulation()


def sentence(labels_and_durations, start=0.0):
    out, t = [], start
    for label, d in labels_and_durations:
        out.append(Seg(label, t, t + d))
        t += d
    return out


# -- the table ----------------------------------------------------------------------

def test_the_table_covers_every_suopuhe_phone_and_long_forms(table):
    for phone in SUOPUHE_PHONES:
        assert table.row(phone)
        if phone not in ("#", "##"):
            assert table.row(phone + ":") == table.row(phone)


def test_bilabials_and_labiodentals_are_enforced_closures(table):
    lower = table.parameters.index("lower_lip_raise")
    jaw = table.parameters.index("jaw_open")
    for phone in "pbm":
        assert table.row(phone)[lower].enforced and table.row(phone)[lower].value == 1
        assert table.row(phone)[jaw].enforced and table.row(phone)[jaw].value == 0
    for phone in "fv":
        assert table.row(phone)[lower].enforced


def test_cell_syntax_and_comments():
    t = parse_articulation("$parameters = a b\n$anticipation = 0.5\n# phone a b\n"
                           "x,y  1!/3/0.1/0.2  -    # trailing comment\n#  0/2  0\n##  0 0\n", "t.phones")
    x = t.row("x")
    assert (x[0].value, x[0].dominance, x[0].anticipation, x[0].carryover, x[0].enforced) == (1, 3, 0.1, 0.2, True)
    assert x[1].dominance == 0.05 and x[1].anticipation == 0.5          # '-' uses $weak
    assert t.row("y") == x and t.row("#")[0].dominance == 2 and set(t.rows) == {"x", "y", "#", "##"}
    assert t.row("x:") == x


@pytest.mark.parametrize("text, line, words", [
    ("x 1\n", 1, "before $parameters"),
    ("$parameters = a b\nx 1\n", 2, "has 1 targets for 2 parameters"),
    ("$parameters = a\nx one\n", 2, "cannot read target 'one'"),
    ("$parameters = a\nx 1/0\n", 2, "must be positive"),
    ("$parameters = a\nx -!\n", 2, "cannot be enforced"),
    ("$parameters = a\nx 1\nx 2\n", 3, "two rows"),
    ("$parameters = a\n$speed = 3\nx 1\n", 2, "unknown directive $speed"),
    ("$parameters = a\n", 1, "no phone rows"),
])
def test_table_errors_name_file_and_line(text, line, words):
    with pytest.raises(LibraryError) as caught:
        parse_articulation(text, "t.phones")
    assert caught.value.line == line and words in caught.value.message


def test_an_unknown_phone_and_a_parameter_the_model_lacks_are_clear_errors(table):
    with pytest.raises(LibraryError, match="no row for phone 'q'"):
        table.row("q")
    from engine import load_model

    other = parse_articulation("$parameters = jaw_open smile\nx 1 1\n", "t.phones")
    with pytest.raises(LibraryError, match="'smile' does not exist"):
        other.check(load_model())


# -- coarticulation -----------------------------------------------------------------

PAPPA = sentence([("##", 200), ("p", 80), ("a", 90), ("p:", 160), ("a", 110), ("#", 60), ("u", 100),
                  ("m", 70), ("i", 120), ("##", 200)])


@pytest.mark.parametrize("method", ["cohen-massaro", "none"])
def test_closure_is_reached_at_the_middle_of_every_bilabial(table, method):
    middles = np.array([(s.start_ms + s.end_ms) / 2 for s in PAPPA])
    tracks = articulation_tracks(PAPPA, table, middles, method)
    lower, jaw = table.parameters.index("lower_lip_raise"), table.parameters.index("jaw_open")
    for k, seg in enumerate(PAPPA):
        if seg.label.rstrip(":") in "pbm":
            assert tracks[k, lower] == pytest.approx(1) and tracks[k, jaw] == pytest.approx(0)


def test_none_reproduces_plain_target_interpolation(table):
    middles = np.array([(s.start_ms + s.end_ms) / 2 for s in PAPPA])
    tracks = articulation_tracks(PAPPA, table, middles, "none")
    for k, seg in enumerate(PAPPA):
        np.testing.assert_allclose(tracks[k], [t.value for t in table.row(seg.label)])
    between = articulation_tracks(PAPPA, table, [(middles[4] + middles[5]) / 2], "none")[0]
    np.testing.assert_allclose(between, (tracks[4] + tracks[5]) / 2)


def test_cohen_massaro_spreads_rounding_across_a_consonant_but_keeps_vowels_distinct(table):
    protrude = table.parameters.index("lip_protrude")
    plain = sentence([("##", 200), ("i", 120), ("k", 60), ("i", 120), ("##", 200)])
    rounded = sentence([("##", 200), ("i", 120), ("k", 60), ("u", 120), ("##", 200)])
    k_middle = [350.0]
    assert articulation_tracks(rounded, table, k_middle)[0, protrude] > \
        articulation_tracks(plain, table, k_middle)[0, protrude] + 0.2       # anticipation of the u
    u = articulation_tracks(rounded, table, [440.0])[0]
    i = articulation_tracks(rounded, table, [260.0])[0]
    widen = table.parameters.index("mouth_widen")
    assert u[protrude] > 0.7 and i[widen] > 0.6 and u[widen] < i[widen]


def test_articulation_gives_one_activation_per_parameter_with_exact_middles(table):
    acts = articulate(PAPPA, table)
    assert [a.parameter for a in acts] == table.parameters
    times = acts[0].times
    assert times[0] == 0 and times[-1] == PAPPA[-1].end_ms and np.all(np.diff(times) > 0)
    for seg in PAPPA:
        assert (seg.start_ms + seg.end_ms) / 2 in set(times.tolist())
    assert np.all(np.diff(key_times(PAPPA, 5.0)) <= 5.0 + 1e-9)


def test_unknown_coarticulation_is_refused(table):
    with pytest.raises(UserError, match="unknown coarticulation"):
        articulation_tracks(PAPPA, table, [0.0], "magic")


def test_closure_window_shape():
    w = closure_window(np.array([0, 10, 25, 50, 75, 90, 100, 110.0]), 0, 100)
    np.testing.assert_allclose(w[[0, 3, 6, 7]], [0, 1, 0, 0])
    assert w[2] == 1 and w[4] == 1 and 0 < w[1] < 1 and 0 < w[5] < 1


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(SUOPUHE_PHONES), st.floats(20, 300)), min_size=1, max_size=15))
def test_tracks_stay_within_the_targets_range(labels_and_durations):
    table = load_articulation()
    phones = sentence(labels_and_durations)
    times = key_times(phones)
    tracks = articulation_tracks(phones, table, times)
    values = np.array([[t.value for t in table.row(p.label)] for p in phones])
    assert np.all(tracks >= values.min(axis=0) - 1e-9) and np.all(tracks <= values.max(axis=0) + 1e-9)


# -- text with inline commands --------------------------------------------------------

Word = namedtuple("Word", "label start_ms end_ms")


def test_inline_commands_anchor_at_the_next_word():
    script = parse_script('Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä kuuluu? <Blink/>')
    assert script.text == "Hyvää päivää mitä kuuluu?"
    spoken = [Word("hyvää", 100, 400), Word("päivää", 400, 800), Word("mitä", 900, 1100), Word("kuuluu", 1100, 1500)]
    nod, blink = anchored_commands(script, spoken)
    assert nod.name == "HeadNod" and nod.arguments == {"at": 900.0, "amplitude": 60.0, "count": 2.0}
    assert blink.arguments["at"] == 1500.0                  # after the last word: when it ends


def test_an_explicit_at_is_kept_and_numbers_spoken_as_several_words_still_anchor():
    script = parse_script('Minulla on 25 <Blink/> kissaa <BrowRaise at="40"/>.')
    spoken = [Word("minulla", 0, 300), Word("on", 300, 400), Word("kaksikymmentä", 400, 900),
              Word("viisi", 900, 1200), Word("kissaa", 1200, 1600)]
    assert word_start_times(script.words, spoken) == [0, 300, 400, 1200]
    blink, brow = anchored_commands(script, spoken)
    assert blink.arguments["at"] == 1200 and brow.arguments["at"] == 40


def test_a_command_between_words_without_spaces_does_not_glue_them():
    assert parse_script("yksi<Blink/>kaksi").text == "yksi kaksi"


@pytest.mark.parametrize("text, line, words", [
    ("moi\nmoi <Blink", 2, "column 5"),
    ('moi <Blink at="soon"/>', 1, "not a number"),
    ("a < b", 1, "does not belong"),
    ("<Blink>hei</Blink>", 1, "self-closing"),
])
def test_script_errors_name_line_and_column(text, line, words):
    with pytest.raises(CommandError) as caught:
        parse_script(text, "talk.txt")
    assert caught.value.file == "talk.txt" and caught.value.line == line and words in caught.value.message


@pytest.mark.parametrize("text, line, words", [
    ("Hei\nmoi <Blink/> <Smiley/> moi", 2, "column 14: unknown command <Smiley>"),
    ('Hei <HeadNod amplitud="3"/>', 1, "column 5: <HeadNod> has no argument 'amplitud'"),
    ("Hei <Blink/> <Blink/> 漢 moi", 1, "column 23"),                 # counted in the text as written
])
def test_speak_names_the_file_line_and_column_before_synthesis(text, line, words):
    """Errors found in a script name where they stand in the text as typed (commands included), before
    any synthesis: the synthesizer given here fails the test if it is reached."""
    from engine import load_model
    from engine.speech.say import speak

    class Unreachable:
        def synthesize(self, *args):
            raise AssertionError("synthesis started before the script was checked")

    with pytest.raises(UserError) as caught:
        speak(text, load_model(), synthesizer=Unreachable(), name="talk.txt")
    assert caught.value.file == "talk.txt" and caught.value.line == line
    assert words in caught.value.message, caught.value.message


# -- prosody ------------------------------------------------------------------------------

def test_prosody_is_seeded_and_uses_library_commands():
    words = [Word("hyvää", 100, 400), Word("päivää", 400, 800), Word("mitä", 1000, 1200), Word("kuuluu", 1200, 1600)]
    phones = [Seg("#", 800, 1000)]
    a = prosody_commands(words, phones, 9000, seed=3)
    b = prosody_commands(words, phones, 9000, seed=3)
    c = prosody_commands(words, phones, 9000, seed=4)
    assert a == b and a != c
    names = [x.name for x in a]
    assert names.count("BrowRaise") == 2 and names.count("HeadNod") == 2 and names.count("Blink") >= 1
    blinks = sorted(x.arguments["at"] for x in a if x.name == "Blink")
    assert all(later - earlier >= 1200 for earlier, later in itertools.pairwise(blinks))
    assert [len(p) for p in split_phrases(words, phones)] == [2, 2]


def test_syllables():
    assert [syllables(w) for w in ("ja", "hyvää", "päivää", "kuuluu", "vaaleanpunainen")] == [1, 2, 2, 2, 5]


def test_frames_cover_a_command_that_outlasts_the_audio():
    """An expression after the last word fades out after the audio: the frames (video, tracks,
    landmarks) cover it; a command ending within the audio leaves the length to the audio."""
    from engine import load_model
    from engine.speech.say import speak
    from engine.speech.synthesis import Segment, Utterance

    class Recorded:
        """Festival's interface with fixed timings: "moi" in 400 ms of silence-padded audio."""

        def synthesize(self, text, voice=None):
            phones = [Segment("#", 0.0, 100.0, ""), Segment("m", 100.0, 180.0, "moi"),
                      Segment("o", 180.0, 300.0, "moi"), Segment("i", 300.0, 400.0, "moi")]
            return Utterance(text, "recorded", np.zeros(8820, dtype=np.float32), 22050, phones,
                             [Segment("moi", 100.0, 400.0, "moi")])

    model = load_model()
    inside = speak("moi <Blink at=\"0\"/>", model, synthesizer=Recorded())
    assert inside.end_ms == inside.duration_ms == 400.0
    assert len(inside.frame_times(25)) == 10
    after = speak("moi <Happy/>", model, synthesizer=Recorded())
    assert after.timeline.end > after.duration_ms + 100
    assert after.end_ms == after.timeline.end
    times = after.frame_times(25)
    assert times[-1] < after.end_ms <= times[-1] + 40.0


def test_a_long_story_anchors_every_word_across_match_blocks():
    """Words are matched block by block (linear in the story's length); a number spoken as two words at
    a block's edge still leaves every later word on its own spoken word."""
    from engine.script.inline_commands import MATCH_BLOCK

    base = ["Pappa", "ampui", "pallon", "ja", "Maija", "meni", "kotiin", "kauniina"]
    written = base * (3 * MATCH_BLOCK // len(base))
    written.insert(MATCH_BLOCK - 1, "25")
    spoken_labels = list(written)
    at = spoken_labels.index("25")
    spoken_labels[at:at + 1] = ["kaksikymmentä", "viisi"]
    spoken = [Word(label, 10.0 * i, 10.0 * i + 9) for i, label in enumerate(spoken_labels)]
    starts = word_start_times(written, spoken)
    assert starts[MATCH_BLOCK - 1] == spoken[at].start_ms                  # "25" at "kaksikymmentä"
    assert starts[MATCH_BLOCK:] == [w.start_ms for w in spoken[at + 2:]]   # every later word on its own
    assert starts[:MATCH_BLOCK - 1] == [w.start_ms for w in spoken[:at]]
