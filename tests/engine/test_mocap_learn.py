"""``mocap learn``: coarticulation learned from phone-labelled capture (issue 22 §2).

The known answer: the shipped Finnish table with a few cells deliberately
changed (:data:`CHANGED`: the jaw of ``a`` and ``t``, the spread of ``i``,
the rounding of ``u``, with their dominances and rates). Real Festival speaks
twelve sentences; ``engine.mocap.synthetic`` turns each into a capture
session of the default head articulating them with the *changed* table (head
motion of a few degrees, 0.2 mm marker noise, dropouts and gaps). Learning
starts from the shipped table and must move the changed cells to the truth,
and on held-out sentences the learned table must follow the recording more
closely than the shipped one.
"""

from __future__ import annotations

import math
import string

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from engine import load_model
from engine.errors import LibraryError
from engine.mocap.articulation_file import save_articulation_file
from engine.mocap.coarticulation_fit import TrainingTrack, _Problem, row_name
from engine.mocap.coarticulation_learning import learn_coarticulation, parse_holdout, utterance_spans
from engine.mocap.errors import MocapError
from engine.mocap.importer import build_session
from engine.mocap.pca import multistage_pca
from engine.mocap.recording import Recording
from engine.mocap.session import save_session
from engine.mocap.synthetic import synthesize_recording
from engine.speech.articulation import DEFAULTS, ArticulationTable, Target, load_articulation, parse_articulation
from engine.speech.articulation_writer import articulation_text
from engine.speech.coarticulation import articulation_tracks
from engine.speech.synthesis import Segment
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.fuzz_support import FUZZ
from tests.engine.mocap_samples import TRAINING_PHONES, parse_phones

SENTENCES = ["Papu ja kala.", "Hyvää päivää, mitä kuuluu?", "Öljyä ja syötävää.", "Tuuli puhaltaa lujaa.",
             "Iita ja Ukko istuvat tuvassa.", "Kuusi pientä poikaa.", "Aamu alkaa aina kahvilla.",
             "Minä tulin tänne tänään.", "Pekka toi tupaan puuta.", "Sisko ui aamulla.",
             "Tapani pitää tuutista.", "Kaikki kalat uivat."]
#: (phone, parameter) → the known cell; the shipped one is in engine/library/articulation/finnish.phones.
CHANGED = {("a", "jaw_open"): Target(0.55, 1.5, 0.05, 0.02),
           ("i", "mouth_widen"): Target(0.7, 2.0, 0.06, 0.06),
           ("u", "lip_protrude"): Target(0.8, 0.5, 0.015, 0.05),
           ("t", "jaw_open"): Target(0.2, 0.3, 0.02, 0.06)}


def known_table() -> ArticulationTable:
    shipped = load_articulation()
    rows = {phone: list(targets) for phone, targets in shipped.rows.items()}
    for (phone, parameter), cell in CHANGED.items():
        rows[phone][shipped.parameters.index(parameter)] = cell
    return ArticulationTable(shipped.parameters, rows, shipped.exponent, "known", dict(shipped.lines),
                             shipped.phoneset, dict(shipped.settings))


@pytest.fixture(scope="module")
def capture():
    from engine.speech.festival import FestivalSynthesizer

    model, known, festival = load_model(), known_table(), FestivalSynthesizer()
    sessions = []
    for k, sentence in enumerate(SENTENCES):
        rec = synthesize_recording(sentence, model=model, table=known, seed=100 + k, synthesizer=festival)
        recording = Recording(labels=list(rec.markers), positions=rec.positions, rate_hz=rec.rate_hz,
                              source=sentence, format="synthetic")
        sessions.append((f"sentence{k + 1}.h5", build_session(recording, phones=rec.phones)))
    return model, sessions, multistage_pca(sessions[0][1])


@pytest.fixture(scope="module")
def learned(capture):
    model, sessions, art = capture
    return learn_coarticulation(sessions, art, model, holdout=0.25)


def test_the_fit_s_tracks_are_articulation_tracks():
    """The fit's own forward model (with its analytic derivatives) is the speech pipeline's coarticulation."""
    table = known_table()
    phones = parse_phones(TRAINING_PHONES)
    times = np.arange(0.0, phones[-1][1], 1000 / 60)
    expected = articulation_tracks([Segment(label, a, b) for a, b, label in phones], table, times)
    track = TrainingTrack(times, [p[2] for p in phones], np.array([p[0] for p in phones]),
                          np.array([p[1] for p in phones]), np.zeros(len(times)), np.ones(len(times), bool))
    names = sorted({row_name(table, p[2]) for p in phones})
    for column, parameter in enumerate(table.parameters):
        problem = _Problem([track], table, column, names)
        x = problem.vector()
        np.testing.assert_allclose(problem.tracks_for(x)[0], expected[:, column], atol=1e-12, err_msg=parameter)
        moved = x + np.random.default_rng(column).normal(0, 0.1, x.shape)
        numeric = np.column_stack([(problem.residuals(moved + 1e-6 * e) - problem.residuals(moved - 1e-6 * e)) / 2e-6
                                   for e in np.eye(len(x))])
        np.testing.assert_allclose(problem.jacobian(moved), numeric, atol=1e-6, err_msg=parameter)


#: The dominance and rates the data can tell: (phone, parameter) → which of them are checked.
IDENTIFIABLE = {("a", "jaw_open"): ("dominance", "anticipation", "carryover"),
                ("u", "lip_protrude"): ("dominance", "anticipation", "carryover"),
                ("t", "jaw_open"): ("dominance", "carryover"),
                ("i", "mouth_widen"): ("anticipation", "carryover")}


@pytest.mark.slow
def test_learning_recovers_the_changed_cells(learned):
    """Tolerances, from the shipped value to the truth: every changed target at least 60 % of the way and
    within 0.08 (parameter units; 0.08 of jaw_open is 1.5°); dominance and rates at least half of the way in
    log terms and not beyond 1.5 times it. Not checked, because these sentences cannot tell them: the
    dominance of i's spread (i sits mostly between consonants whose mouth_widen cells are '-', dominance
    0.04, where a dominance of 1 and of 2 give the same track) and the anticipation of t's jaw (t's dominance
    0.3 is a third of its vowel neighbours': its own rate hardly shows)."""
    shipped, table = load_articulation(), learned.table
    for (phone, parameter), truth in CHANGED.items():
        column = table.parameters.index(parameter)
        start, got = shipped.rows[phone][column], table.rows[phone][column]
        way = (got.value - start.value) / (truth.value - start.value)
        assert way >= 0.6 and abs(got.value - truth.value) < 0.08, (phone, parameter, start, got, truth)
        for kind in IDENTIFIABLE[phone, parameter]:
            before, after, want = (math.log(getattr(c, kind)) for c in (start, got, truth))
            assert 0.5 <= (after - before) / (want - before) <= 1.5, (phone, parameter, kind, start, got, truth)
    # a phone the sessions never show keeps its shipped row; enforced cells stay enforced
    assert table.rows["f"] == shipped.rows["f"]
    assert table.rows["p"][0].enforced and table.rows["p"][4].enforced


@pytest.mark.slow
def test_on_held_out_sentences_the_learned_table_beats_the_shipped_one(learned):
    print("\n" + learned.report())
    rms = learned.lip_rms_mm
    assert learned.held_out == 3 and learned.measured_frames > 100
    assert rms["learned"] < 0.6 * rms["shipped"], learned.report()
    assert rms["learned"] < rms["none"]
    assert rms["capture"] <= rms["learned"]           # no table beats the per-frame fit of the markers
    assert all(f.rms_learned < f.rms_shipped for f in learned.fits)


@pytest.mark.slow
def test_the_cli_writes_a_table_say_speaks_with(capture, tmp_path):
    _, sessions, art = capture
    files = []
    for name, session in sessions[:6]:
        save_session(session, tmp_path / name)
        files.append(tmp_path / name)
    save_articulation_file(art, tmp_path / "art.h5")
    out = tmp_path / "learned.phones"
    result = run("mocap", "learn", *files, "--articulation", tmp_path / "art.h5", "--holdout", "20%", "-o", out)
    assert result.returncode == 0, result.stderr
    assert "plain target interpolation" in result.stdout and "learned table" in result.stdout
    text = out.read_text(encoding="utf-8")
    assert text.startswith("# Learned by 'artificial-person mocap learn'") and "sentence1.h5" in text
    table = parse_articulation(text, str(out))
    assert table.rows["a"][0] != load_articulation().rows["a"][0]
    spoken = run("say", "Papu ja kala.", "--articulation", out, "--tracks", tmp_path / "tracks.csv",
                 "-o", tmp_path / "say.xml")
    assert spoken.returncode == 0, spoken.stderr
    assert "jaw_open" in (tmp_path / "tracks.csv").read_text().splitlines()[0]


@pytest.mark.slow
def test_bad_inputs_are_refused_in_one_line(capture, tmp_path):
    _, sessions, art = capture
    save_articulation_file(art, tmp_path / "art.h5")
    session = sessions[0][1]
    unlabelled = session.__class__(**{**session.__dict__, "phones": []})
    save_session(unlabelled, tmp_path / "unlabelled.h5")
    short = session.__class__(**{**session.__dict__, **{k: getattr(session, k)[:10] for k in
                                                        ("positions", "raw", "missing", "alignment", "filled")}})
    save_session(short, tmp_path / "short.h5")
    save_session(session, tmp_path / "one.h5")
    foreign = session.__class__(**{**session.__dict__, "phones": [*session.phones[:-1], (0.0, 50.0, "ae")]})
    save_session(foreign, tmp_path / "foreign.h5")

    def learn(*args):
        return run_in_process("mocap", "learn", *args, "--articulation", tmp_path / "art.h5", "-o",
                              tmp_path / "x.phones")

    assert "no phone labels" in assert_user_error(learn(tmp_path / "unlabelled.h5"))
    assert "unlabelled.h5" in assert_user_error(learn(tmp_path / "unlabelled.h5"))
    assert "too few" in assert_user_error(learn(tmp_path / "short.h5"))
    line = assert_user_error(learn(tmp_path / "foreign.h5"))
    assert "foreign.h5" in line and "no row" in line and "ae" in line
    assert "120%" in assert_user_error(learn(tmp_path / "one.h5", "--holdout", "120%"))
    assert "percentage" in assert_user_error(learn(tmp_path / "one.h5", "--holdout", "a lot"))
    assert "cannot hold out" in assert_user_error(learn(tmp_path / "one.h5", "--holdout", "95%"))
    bad_out = run_in_process("mocap", "learn", tmp_path / "one.h5", "--articulation", tmp_path / "art.h5",
                             "-o", tmp_path / "x.txt")
    assert ".phones" in assert_user_error(bad_out)
    assert not (tmp_path / "x.phones").exists()


def test_holdout_text_and_utterances():
    assert parse_holdout("20%") == 0.2 and parse_holdout("0") == 0.0 and parse_holdout("12.5%") == 0.125
    for bad in ("120%", "100%", "-5%", "", "20%%", "one fifth"):
        with pytest.raises(MocapError, match="percentage"):
            parse_holdout(bad)
    assert utterance_spans([(0, 30, "#"), (30, 60, "p"), (60, 140, "a"), (140, 340, "#"), (340, 400, "u"),
                            (400, 450, "##")]) == [(30.0, 140.0), (340.0, 400.0)]


# -- the writer ---------------------------------------------------------------------------

_PHONES = st.text(string.ascii_letters + string.digits + "@:_", min_size=1, max_size=4)
_POSITIVE = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False, allow_infinity=False)
_VALUES = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


@st.composite
def tables(draw):
    parameters = draw(st.lists(st.from_regex(r"[a-z][a-z_0-9]{0,10}", fullmatch=True), min_size=1, max_size=5,
                               unique=True))
    settings = {name: draw(_POSITIVE) for name in DEFAULTS}
    phones = draw(st.lists(_PHONES, min_size=1, max_size=8, unique=True))
    if draw(st.booleans()):
        phones += ["#", "##"]
    dash = Target(0.0, settings["weak"], settings["anticipation"], settings["carryover"])
    cell = st.one_of(st.just(dash), st.builds(Target, _VALUES, _POSITIVE, _POSITIVE, _POSITIVE, st.booleans()),
                     st.builds(Target, _VALUES, st.just(settings["dominance"]), st.just(settings["anticipation"]),
                               _POSITIVE, st.booleans()))
    shared = draw(st.lists(cell, min_size=len(parameters), max_size=len(parameters)))
    rows = {p: (list(shared) if draw(st.booleans()) else draw(st.lists(cell, min_size=len(parameters),
                                                                          max_size=len(parameters))))
            for p in phones}
    phoneset = draw(st.sampled_from(["", "finnish", "radio_phones"]))
    return ArticulationTable(parameters, rows, settings["exponent"], "<drawn>", {}, phoneset, settings)


@FUZZ
@given(table=tables(), comment=st.text(max_size=80))
def test_the_writer_round_trips_any_table(table, comment):
    """AP_FUZZ_EXAMPLES random tables (shared rows, '-' cells, enforced cells, pause rows, any comment)
    read back exactly: the same parameters, settings, phone set and every target to the last bit."""
    text = articulation_text(table, comment)
    again = parse_articulation(text, "<written>")
    assert again.parameters == table.parameters and again.phoneset == table.phoneset
    assert again.rows == table.rows and again.exponent == table.exponent
    assert all(again.settings[k] == v for k, v in table.settings.items())
    assert all(math.isfinite(t.value) for row in again.rows.values() for t in row)


def test_the_writer_refuses_a_phone_the_format_cannot_hold():
    shipped = load_articulation()
    for name in ("a b", "x,y", "#x"):
        rows = {**shipped.rows, name: shipped.rows["a"]}
        table = ArticulationTable(shipped.parameters, rows, shipped.exponent, "odd.phones", {}, "",
                                  dict(shipped.settings))
        with pytest.raises(LibraryError, match="cannot be written") as error:
            articulation_text(table)
        assert error.value.file == "odd.phones"


def _repeated(phone: str, times: int) -> TrainingTrack:
    """``# k PHONE k PHONE … #`` with 120 ms phones, its jaw tracks spoken by a table whose PHONE opens 0.3 more."""
    labels = ["#"] + ["k", phone] * times + ["k", "#"]
    starts = np.arange(len(labels)) * 120.0
    frames = np.arange(0.0, starts[-1] + 120.0, 1000 / 60)
    shipped = load_articulation()
    rows = {p: list(t) for p, t in shipped.rows.items()}
    rows[phone][0] = Target(rows[phone][0].value + 0.3, 1.0, 0.03, 0.035)
    truth = ArticulationTable(shipped.parameters, rows, 1.0, "truth", {}, "", dict(shipped.settings))
    values = articulation_tracks([Segment(p, s, s + 120.0) for p, s in zip(labels, starts, strict=True)], truth,
                                 frames)[:, 0]
    return TrainingTrack(frames, labels, starts, starts + 120.0, values, np.ones(len(frames), bool))


def test_a_phone_seen_once_stays_near_the_shipped_row_and_one_seen_often_follows_the_data():
    from engine.mocap.coarticulation_fit import fit_parameter

    shipped = load_articulation().target("o", "jaw_open")
    once = fit_parameter([_repeated("o", 1)], load_articulation(), "jaw_open").table.target("o", "jaw_open")
    often = fit_parameter([_repeated("o", 40)], load_articulation(), "jaw_open").table.target("o", "jaw_open")
    # the data say +0.3; the prior (3 occurrences at full sensitivity, docs/mocap-learn.md) lets one
    # occurrence move the target less than a third of the way, forty more than four fifths
    assert 0 < (once - shipped) / 0.3 < 1 / 3 and (often - shipped) / 0.3 > 0.8
