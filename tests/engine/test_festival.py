"""The synthesizer interface and its Festival backend (§2.1).

Two kinds of tests: unit tests of text preparation, parsing (on Festival
output recorded in ``data/festival/``), WAV and phones-CSV files, which need
no Festival; and tests that run the real Festival with both Finnish Suopuhe
voices (marked ``slow``, but part of the normal suite). Error paths — Festival
missing, a voice not installed, a Festival that hangs — use fake programs.
"""

from __future__ import annotations

import itertools
import os
import shutil
import subprocess
import time
import wave
from pathlib import Path

import numpy as np
import pytest

from engine.errors import UserError
from engine.speech.festival import (
    DEFAULT_VOICE,
    MALE_FINNISH_VOICE,
    TRANSLITERATION,
    FestivalSynthesizer,
    fit_to_duration,
    missing_voice_message,
    parse_segments,
    parse_voices,
    prepare_text,
    scheme_string,
    synthesis_script,
)
from engine.speech.synthesis import (
    Segment,
    SynthesisError,
    Synthesizer,
    Utterance,
    format_ms,
    phones_csv,
    read_phones_csv,
    read_wav,
    wav_bytes,
    write_phones_csv,
    write_wav,
)

DATA = Path(__file__).parent / "data" / "festival"
FINNISH_VOICES = [DEFAULT_VOICE, MALE_FINNISH_VOICE]
HAVE_FESTIVAL = shutil.which("festival") is not None
needs_festival = pytest.mark.skipif(not HAVE_FESTIVAL, reason="Festival is not installed (./bootstrap installs it)")

GREETING = "Hyvää päivää, mitä kuuluu?"
GREETING_PHONES = ["#", "h", "y", "v", "@:", "p", "@", "i", "v", "@:", "#", "m", "i", "t", "@", "k", "u:", "l", "u:",
                   "#", "#"]
#: Every label the two Suopuhe voices emitted for a broad Finnish test set (docs/speech-synthesis.md).
SUOPUHE_PHONES = {
    "a", "e", "i", "o", "u", "y", "@", "7", "a:", "e:", "i:", "o:", "u:", "y:", "@:", "7:", "b", "d", "f", "g", "h",
    "j", "k", "l", "m", "n", "p", "r", "s", "t", "v", "N", "S", "T", "b:", "d:", "f:", "g:", "h:", "j:", "k:", "l:",
    "m:", "n:", "p:", "r:", "s:", "t:", "v:", "N:", "S:", "#", "##",
}


def recorded(name: str) -> str:
    """Festival's stdout for a synthesis script, as recorded (Latin-1)."""
    return (DATA / name).read_bytes().decode("latin-1")


def utterance_of(phones, words, rate=22050) -> Utterance:
    n = round(phones[-1].end_ms * rate / 1000)
    return Utterance("", "test", np.zeros(n, dtype=np.float32), rate, phones, words)


def assert_well_formed(utterance: Utterance, tolerance_ms: float = 1.0) -> None:
    """Phones contiguous from 0 to the waveform's end; words span exactly their phones."""
    phones = utterance.phones
    assert phones[0].start_ms == 0
    for before, after in itertools.pairwise(phones):
        assert after.start_ms == before.end_ms
    assert all(p.end_ms >= p.start_ms for p in phones)
    assert abs(phones[-1].end_ms - utterance.duration_ms) <= tolerance_ms
    starts = {p.start_ms for p in phones}
    ends = {p.end_ms for p in phones}
    for word in utterance.words:
        assert word.start_ms in starts and word.end_ms in ends
        inside = [p for p in phones if word.start_ms <= p.start_ms and p.end_ms <= word.end_ms
                  and p.end_ms > p.start_ms]
        assert inside and all(p.word == word.label for p in inside), word
    for before, after in itertools.pairwise(utterance.words):
        assert before.end_ms <= after.start_ms
    spoken = {w.label for w in utterance.words}
    assert all(p.word in spoken for p in phones if p.word)
    assert all(p.word == "" for p in phones if p.label in ("#", "##"))


# ---------------------------------------------------------------------------
# Text → Latin-1
# ---------------------------------------------------------------------------

def test_finnish_letters_pass_unchanged():
    text = "Hyvää päivää! Öljyä, Åbo, ÄÖÅ äöå. Café Müller"
    assert prepare_text(text) == text
    prepared = prepare_text(text)
    assert prepared.encode("latin-1").decode("latin-1") == text


def test_decomposed_letters_are_composed():
    decomposed = "pa\u0308iva\u0308a\u0308"                  # a + combining diaeresis
    assert prepare_text(decomposed) == "päivää"


@pytest.mark.parametrize("raw, prepared", [
    ("\u201cLainaus\u201d ja \u2018toinen\u2019 \u201ejoo\u201d", "\"Lainaus\" ja 'toinen' \"joo\""),
    ("sivut 1\u20132 ja Helsinki\u2014Turku", "sivut 1-2 ja Helsinki-Turku"),
    ("odota\u2026", "odota..."),
    ("odota \u2026 nyt", "odota... nyt"),
    ("tule \u2013 nyt", "tule, nyt"),
    ("\u2013 Mitä kuuluu?\n\u2014 Hyvää.", "Mitä kuuluu?\nHyvää."),
    ("kymmenen\u00a0euroa 5\u202f000", "kymmenen euroa 5 000"),
    ("sana\u200bsana\u00adsana\ufeff", "sanasanasana"),
    ("\u0161akki \u017dukov", "shakki Zhukov"),
    ("5 \u20ac", "5  euroa"),
    ("a\u2212b", "a-b"),
])
def test_transliteration(raw, prepared):
    assert prepare_text(raw) == prepared
    prepared.encode("latin-1")


def test_transliteration_table_maps_to_latin1():
    for replacement in TRANSLITERATION.values():
        replacement.encode("latin-1")


@pytest.mark.parametrize("text, char, code", [
    ("Hyvää 🙂", "🙂", "U+1F642"),
    ("Привет", "П", "U+041F"),
    ("日本", "日", "U+65E5"),
    ("smörgås\u0107", "ć", "U+0107"),
])
def test_characters_latin1_cannot_carry_are_named(text, char, code):
    with pytest.raises(SynthesisError) as caught:
        prepare_text(text)
    message = str(caught.value)
    assert isinstance(caught.value, UserError)
    assert char in message and code in message and "Latin-1" in message


def test_error_says_where_the_character_is():
    with pytest.raises(SynthesisError) as caught:
        prepare_text("Ensimmäinen rivi\ntoinen ★ rivi", source="puhe.txt")
    assert str(caught.value).startswith("puhe.txt:2: ")
    assert "column 8" in str(caught.value) and "BLACK STAR" in str(caught.value)


def test_control_characters_become_spaces_newlines_stay():
    assert prepare_text("a\x00b\x07c\r\nd\re\tf\x85g") == "a b c\nd\ne\tf g"


@pytest.mark.parametrize("text", ["", "   ", "\n\t ", "\u200b\ufeff"])
def test_empty_text_is_an_error(text):
    with pytest.raises(SynthesisError, match="nothing to say"):
        prepare_text(text)


def test_text_must_be_str():
    with pytest.raises(TypeError):
        prepare_text(b"moi")


def test_scheme_string_escapes_quotes_and_backslashes():
    assert scheme_string('a "b" c\\d') == '"a \\"b\\" c\\\\d"'
    assert scheme_string("\\") == '"\\\\"'
    assert scheme_string('"') == '"\\""'
    assert scheme_string("(car nil) ; x") == '"(car nil) ; x"'


def test_script_is_latin1_and_names_the_voice():
    script = synthesis_script(prepare_text('Hyvää "päivää"'), "hy_fi_mv_diphone")
    data = script.encode("latin-1")
    assert "Hyv\xe4\xe4 \\\"p\xe4iv\xe4\xe4\\\"".encode("latin-1") in data
    assert "(voice_hy_fi_mv_diphone)" in script
    assert '(member_string "hy_fi_mv_diphone" (voice.list))' in script


# ---------------------------------------------------------------------------
# Parsing recorded Festival output
# ---------------------------------------------------------------------------

def test_parse_recorded_greeting():
    phones, words = parse_segments(recorded("lj_hyvaa_paivaa.out"))
    assert [p.label for p in phones] == GREETING_PHONES
    assert phones[0] == Segment("#", 0.0, 30.0, "")
    assert phones[1] == Segment("h", 30.0, 88.273, "Hyvää")          # AP-SEG 0.088273
    assert phones[9] == Segment("@:", 725.151, 917.63, "päivää")      # AP-SEG 0.917630
    assert phones[10] == Segment("#", 917.63, 1117.63, "")
    assert phones[-1].end_ms == 2124.298
    assert words == [Segment("Hyvää", 30.0, 328.563), Segment("päivää", 328.563, 917.63),
                     Segment("mitä", 1117.63, 1342.137), Segment("kuuluu", 1342.137, 1894.298)]
    assert_well_formed(utterance_of(phones, words))


def test_parse_recorded_numbers_words_with_spaces_and_commas():
    phones, words = parse_segments(recorded("mv_numbers.out"))
    labels = [w.label for w in words]
    assert labels == ["Vuonna", "kaksituhatta kolme", "hinta", "oli", "3,5", "euroa", "ei", "paljon"]
    assert "".join(p.label for p in phones if p.word == "kaksituhatta kolme") == "kaksituhat:akolme"
    assert_well_formed(utterance_of(phones, words))


@pytest.mark.parametrize("name", ["lj_hyvaa_paivaa", "mv_numbers"])
def test_phones_csv_of_recorded_output(name):
    phones, words = parse_segments(recorded(f"{name}.out"))
    expected = (DATA / f"{name}.phones.csv").read_text(encoding="utf-8")
    assert phones_csv(utterance_of(phones, words)) == expected


def test_every_boundary_equals_festivals_to_the_microsecond():
    out = recorded("mv_numbers.out")
    festival_ends = [float(line.split("\t")[1]) for line in out.splitlines() if line.startswith("AP-SEG")]
    phones, _ = parse_segments(out)
    assert len(phones) == len(festival_ends)
    for phone, end_s in zip(phones, festival_ends, strict=True):
        assert abs(phone.end_ms - end_s * 1000) < 1e-6


def test_parse_ignores_what_festival_or_the_voice_print_around_the_segments():
    out = recorded("lj_hyvaa_paivaa.out")
    noisy = ("Pause after PSP \"mitä\".\n\nInserted pause after in N#V postition after x."
             + out.replace("\nAP-BEGIN", "\nsome voice chatter\nAP-BEGIN") + "closing a file left open\n")
    assert parse_segments(noisy) == parse_segments(out)


def test_parse_missing_voice_output():
    out = recorded("missing_voice.out")
    assert parse_voices(out) == ["suo_fi_lj_diphone", "hy_fi_mv_diphone"]
    with pytest.raises(SynthesisError, match="no segment list"):
        parse_segments(out)


@pytest.mark.parametrize("body, message", [
    ("AP-SEG\tzero\t0\t#\n", "unreadable segment"),
    ("AP-SEG\t0.1\t0\n", "unreadable segment"),
    ("AP-SEG\t0.2\t0\t#\nAP-SEG\t0.1\t0\t#\n", "before it starts"),
    ("AP-UTT\tone\n", "unreadable utterance"),
    ("AP-GARBAGE\tx\n", "unexpected line"),
    ("garbage\n", "no phones"),                      # not an AP- line: the voice's chatter, skipped
    ("", "no phones"),
])
def test_parse_rejects_malformed_output(body, message):
    with pytest.raises(SynthesisError, match=message):
        parse_segments(f"AP-VOICES\tx\nAP-BEGIN\n{body}AP-END\n")


def test_parse_pause_outside_words_and_word_without_phones():
    out = ("AP-BEGIN\nAP-WORD\t_1\tkas\nAP-WORD\t_2\t-\nAP-WORD\t_3\tno\n"
           "AP-SEG\t0.030000\t0\t#\nAP-SEG\t0.100000\t_1\tk\nAP-SEG\t0.200000\t_1\ta\nAP-SEG\t0.250000\t_1\ts\n"
           "AP-SEG\t0.300000\t0\t##\nAP-SEG\t0.400000\t_3\tn\nAP-SEG\t0.400000\t_3\to\nAP-END\n")
    phones, words = parse_segments(out)
    assert [w.label for w in words] == ["kas", "no"]                  # "-" had no phones
    assert phones[4] == Segment("##", 250.0, 300.0, "")
    assert phones[-1] == Segment("o", 400.0, 400.0, "no")             # zero length kept as given
    assert words[1] == Segment("no", 300.0, 400.0)


def test_parse_voices_needs_the_list():
    with pytest.raises(SynthesisError, match="voices"):
        parse_voices("nothing here\n")
    assert parse_voices("x\nAP-VOICES\n") == []


@pytest.mark.parametrize("voice, package", [
    ("suo_fi_lj_diphone", "festvox-suopuhe-lj"), ("hy_fi_mv_diphone", "festvox-suopuhe-mv"),
    ("kal_diphone", "festvox-kallpc16k"),
])
def test_missing_voice_message_names_the_package(voice, package):
    message = missing_voice_message(voice, ["a_diphone"])
    assert voice in message and f"apt-get install {package}" in message and "a_diphone" in message


def test_missing_unknown_voice_message():
    message = missing_voice_message("xx_zz_diphone", [])
    assert "xx_zz_diphone" in message and "apt-cache search festvox" in message and "none" in message


# ---------------------------------------------------------------------------
# Waveforms and phones CSV
# ---------------------------------------------------------------------------

def test_fit_to_duration_trims_and_pads():
    samples = np.arange(100, dtype=np.float32)
    assert len(fit_to_duration(samples, 1000, 50.0)) == 50
    padded = fit_to_duration(samples, 1000, 120.4)
    assert len(padded) == 120 and padded.dtype == np.float32 and not padded[100:].any()
    assert np.array_equal(fit_to_duration(samples, 1000, 100.0), samples)


def test_wav_round_trip(tmp_path):
    rate = 16000
    t = np.arange(rate // 4) / rate
    samples = (0.8 * np.sin(2 * np.pi * 440 * t)).astype(np.float32)
    utterance = Utterance("x", "v", samples, rate, [Segment("#", 0, 250.0)], [])
    path = tmp_path / "out.wav"
    write_wav(path, utterance)
    with wave.open(str(path)) as wav:
        assert (wav.getnchannels(), wav.getsampwidth(), wav.getframerate()) == (1, 2, rate)
    back, back_rate = read_wav(path)
    assert back_rate == rate and back.dtype == np.float32 and len(back) == len(samples)
    assert np.max(np.abs(back - samples)) < 2 / 32768
    assert [p.name for p in tmp_path.iterdir()] == ["out.wav"]      # no temporary left behind


def test_wav_clips_out_of_range():
    data = wav_bytes(np.array([2.0, -2.0, np.nan, 0.5]), 8000)
    path_samples = np.frombuffer(data[-8:], dtype="<i2")
    assert list(path_samples) == [32767, -32768, 0, 16384]


@pytest.mark.parametrize("width, channels", [(1, 1), (2, 2), (3, 1), (4, 2)])
def test_read_wav_other_layouts(tmp_path, width, channels):
    values = np.array([0.0, 0.5, -0.5, 0.25])
    scale = float(1 << (8 * width - 1))
    ints = np.round(values * scale).astype(np.int64)
    if width == 1:
        frames = (ints + 128).astype(np.uint8).tobytes()
    else:
        raw = ints.astype("<i8").view(np.uint8).reshape(-1, 8)[:, :width]
        frames = raw.tobytes()
    frames = b"".join(frames[i * width:(i + 1) * width] * channels for i in range(len(values)))
    path = tmp_path / "x.wav"
    with wave.open(str(path), "wb") as wav:
        wav.setnchannels(channels)
        wav.setsampwidth(width)
        wav.setframerate(11025)
        wav.writeframes(frames)
    samples, rate = read_wav(path)
    assert rate == 11025
    assert np.allclose(samples, values, atol=1 / 128)


def test_read_wav_errors(tmp_path):
    bad = tmp_path / "bad.wav"
    bad.write_bytes(b"not a wave at all")
    with pytest.raises(SynthesisError, match=r"bad\.wav: not a PCM WAV"):
        read_wav(bad)
    with pytest.raises(SynthesisError, match=r"missing\.wav: no such file"):
        read_wav(tmp_path / "missing.wav")


def test_phones_csv_layout_and_quoting(tmp_path):
    phones = [Segment("#", 0, 30), Segment("k", 30, 88.2730000001, "3,5"), Segment("o", 88.273, 100, 'sa"na')]
    utterance = utterance_of(phones, [Segment("3,5", 30, 88.273)])
    text = phones_csv(utterance)
    assert text.splitlines() == ["start_ms,end_ms,phone,word", "0,30,#,", '30,88.273,k,"3,5"',
                                 '88.273,100,o,"sa""na"']
    path = tmp_path / "phones.csv"
    write_phones_csv(path, utterance)
    assert path.read_text(encoding="utf-8") == text
    assert read_phones_csv(path) == [Segment("#", 0, 30), Segment("k", 30, 88.273, "3,5"),
                                     Segment("o", 88.273, 100, 'sa"na')]


def test_read_phones_csv_errors(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("a,b\n")
    with pytest.raises(SynthesisError, match=r"p\.csv:1: not a phones CSV"):
        read_phones_csv(path)
    path.write_text("start_ms,end_ms,phone,word\n0,x,#,\n")
    with pytest.raises(SynthesisError, match=r"p\.csv:2:"):
        read_phones_csv(path)


def test_format_ms():
    assert format_ms(0.0) == "0"
    assert format_ms(1117.6300000001) == "1117.63"
    assert format_ms(88.2734999) == "88.273"
    assert format_ms(12345.6789) == "12345.679"


def test_utterance_duration_and_protocol():
    utterance = Utterance("t", "v", np.zeros(441, dtype=np.float32), 22050, [Segment("#", 0, 20)], [])
    assert utterance.duration_ms == 20.0
    assert isinstance(FestivalSynthesizer(), Synthesizer)
    assert Segment("a", 10, 30).mid_ms == 20 and Segment("a", 10, 30).duration_ms == 20


# ---------------------------------------------------------------------------
# Errors without Festival: missing program, bad voice name, hangs, crashes
# ---------------------------------------------------------------------------

def fake_festival(tmp_path: Path, body: str) -> str:
    program = tmp_path / "festival"
    program.write_text("#!/bin/sh\n" + body)
    program.chmod(0o755)
    return str(program)


def test_missing_festival_binary_path(tmp_path):
    synthesizer = FestivalSynthesizer(festival=str(tmp_path / "nowhere" / "festival"))
    with pytest.raises(SynthesisError) as caught:
        synthesizer.synthesize("Hyvää päivää")
    message = str(caught.value)
    assert "Festival is not installed" in message and "apt-get install festival" in message
    with pytest.raises(SynthesisError, match="apt-get install festival"):
        synthesizer.voices()


def test_missing_festival_on_path():
    with pytest.raises(SynthesisError,
                       match=r"no program 'no-such-festival-program' on PATH.*apt-get install festival"):
        FestivalSynthesizer(festival="no-such-festival-program").synthesize("moi")


def test_festival_path_not_executable(tmp_path):
    program = tmp_path / "festival"
    program.write_text("not a program")
    with pytest.raises(SynthesisError, match="not installed at"):
        FestivalSynthesizer(festival=str(program)).synthesize("moi")


@pytest.mark.parametrize("voice", ["", "kal diphone", "x)(system \"rm\")", "../x"])
def test_bad_voice_names_never_reach_festival(tmp_path, voice):
    marker = tmp_path / "ran"
    program = fake_festival(tmp_path, f"touch {marker}\n")
    with pytest.raises(SynthesisError, match="not a Festival voice name"):
        FestivalSynthesizer(festival=program).synthesize("moi", voice)
    assert not marker.exists()


def test_empty_text_never_reaches_festival(tmp_path):
    marker = tmp_path / "ran"
    program = fake_festival(tmp_path, f"touch {marker}\n")
    with pytest.raises(SynthesisError, match="nothing to say"):
        FestivalSynthesizer(festival=program).synthesize("  \n ")
    assert not marker.exists()


def test_hanging_festival_times_out_and_is_stopped(tmp_path):
    pid_file = tmp_path / "pid"
    program = fake_festival(tmp_path, f"echo $$ > {pid_file}\nexec sleep 60\n")
    synthesizer = FestivalSynthesizer(festival=program, timeout=1)
    started = time.monotonic()
    with pytest.raises(SynthesisError, match=r"did not finish within 1 s"):
        synthesizer.synthesize("Hyvää päivää")
    assert time.monotonic() - started < 10
    pid = int(pid_file.read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)
    with pytest.raises(SynthesisError, match="did not finish"):
        synthesizer.voices()


def test_crashing_festival_reports_its_stderr(tmp_path):
    program = fake_festival(tmp_path, "echo 'ALSA lib noise' >&2\necho 'SIOD ERROR: something broke' >&2\nexit 3\n")
    with pytest.raises(SynthesisError) as caught:
        FestivalSynthesizer(festival=program).synthesize("moi")
    message = str(caught.value)
    assert "exit status 3" in message and "SIOD ERROR: something broke" in message and "ALSA" not in message


def test_festival_that_stops_half_way(tmp_path):
    program = fake_festival(tmp_path, "printf 'AP-VOICES\\tsuo_fi_lj_diphone\\n'\necho 'SIOD ERROR: oops' >&2\n")
    with pytest.raises(SynthesisError, match=r"failed to synthesize.*SIOD ERROR: oops"):
        FestivalSynthesizer(festival=program).synthesize("moi")


def test_festival_without_wave(tmp_path):
    program = fake_festival(tmp_path, f"cat {DATA / 'lj_hyvaa_paivaa.out'}\n")
    with pytest.raises(SynthesisError, match="no wave"):
        FestivalSynthesizer(festival=program).synthesize("moi")


def test_missing_voice_with_recorded_output(tmp_path):
    program = fake_festival(tmp_path, f"cat {DATA / 'missing_voice.out'}\n")
    with pytest.raises(SynthesisError) as caught:
        FestivalSynthesizer(festival=program).synthesize("moi", "kal_diphone")
    message = str(caught.value)
    assert "kal_diphone is not installed" in message and "festvox-kallpc16k" in message
    assert "suo_fi_lj_diphone, hy_fi_mv_diphone" in message


# ---------------------------------------------------------------------------
# Real Festival
# ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def festival():
    if not HAVE_FESTIVAL:
        pytest.skip("Festival is not installed (./bootstrap installs it)")
    return FestivalSynthesizer()


@needs_festival
@pytest.mark.slow
def test_voices_lists_both_finnish_voices(festival):
    voices = festival.voices()
    assert set(FINNISH_VOICES) <= set(voices)


@needs_festival
@pytest.mark.slow
@pytest.mark.parametrize("voice", FINNISH_VOICES)
def test_greeting_with_each_finnish_voice(festival, voice):
    utterance = festival.synthesize(GREETING, voice)
    assert utterance.voice == voice and utterance.text == GREETING
    assert [p.label for p in utterance.phones] == GREETING_PHONES
    assert [w.label for w in utterance.words] == ["Hyvää", "päivää", "mitä", "kuuluu"]
    assert utterance.sample_rate == 22050
    assert utterance.samples.dtype == np.float32 and utterance.samples.ndim == 1
    assert np.all(np.abs(utterance.samples) <= 1.0)
    assert np.abs(utterance.samples).max() > 0.1                       # it actually speaks
    assert_well_formed(utterance, tolerance_ms=1000 / utterance.sample_rate)
    assert 1500 < utterance.duration_ms < 3500


@needs_festival
@pytest.mark.slow
def test_default_voice_is_the_female_finnish_one(festival):
    assert festival.synthesize("Moi").voice == "suo_fi_lj_diphone"


@needs_festival
@pytest.mark.slow
def test_both_voices_share_the_front_end(festival):
    text = "Kuningas ja kuningatar söivät äyriäisiä Åbossa."
    female = festival.synthesize(text, DEFAULT_VOICE)
    male = festival.synthesize(text, MALE_FINNISH_VOICE)
    assert [p.label for p in female.phones] == [p.label for p in male.phones]
    assert not np.array_equal(female.samples[:len(male.samples)], male.samples[:len(female.samples)])


@needs_festival
@pytest.mark.slow
def test_finnish_letters_reach_festival(festival):
    utterance = festival.synthesize("Öljyä ja äyriäisiä, pää ja yö, Åbo.")
    assert [w.label for w in utterance.words] == ["Öljyä", "ja", "äyriäisiä", "pää", "ja", "yö", "Åbo"]
    assert [p.label for p in utterance.phones if p.word == "Öljyä"] == ["7", "l", "j", "y", "@"]
    assert [p.label for p in utterance.phones if p.word == "pää"] == ["p", "@:"]
    assert [p.label for p in utterance.phones if p.word == "yö"] == ["y", "7"]
    assert [p.label for p in utterance.phones if p.word == "Åbo"] == ["o", "b", "o"]


@needs_festival
@pytest.mark.slow
def test_quotes_backslashes_and_scheme_characters_in_text(festival):
    utterance = festival.synthesize('Hän sanoi "moi" \\ ja (hei) ; lähti. ")')
    labels = [w.label for w in utterance.words]
    assert "moi" in labels and "lähti" in labels and "\\" in labels
    assert_well_formed(utterance, tolerance_ms=0.05)


@needs_festival
@pytest.mark.slow
def test_transliterated_text_is_spoken(festival):
    utterance = festival.synthesize("\u201cTule t\u00e4nne\u201d h\u00e4n sanoi\u2026 \u0161akki")
    assert [w.label for w in utterance.words] == ["Tule", "tänne", "hän", "sanoi", "shakki"]
    assert "S" in [p.label for p in utterance.phones]
    # a dash between spaces is a pause (a comma), not the word "viiva"
    utterance = festival.synthesize("Tule t\u00e4nne \u2013 nyt heti")
    assert [w.label for w in utterance.words] == ["Tule", "tänne", "nyt", "heti"]
    assert [p.label for p in utterance.phones if p.word == ""][1:-2] == ["#"]


@needs_festival
@pytest.mark.slow
def test_untransliterable_text_is_refused_before_festival(festival):
    with pytest.raises(SynthesisError, match=r"U\+1F642"):
        festival.synthesize("Hyvää päivää 🙂")


@needs_festival
@pytest.mark.slow
def test_voice_not_installed(festival):
    from engine.speech.festival import VOICE_PACKAGES

    missing = [voice for voice in VOICE_PACKAGES if voice not in festival.voices()]
    if not missing:
        pytest.skip("every well-known Festival voice is installed here")
    voice = missing[0]
    with pytest.raises(SynthesisError) as caught:
        festival.synthesize("Hello", voice)
    message = str(caught.value)
    assert f"{voice} is not installed" in message and f"apt-get install {VOICE_PACKAGES[voice]}" in message
    assert "suo_fi_lj_diphone" in message
    with pytest.raises(SynthesisError, match="apt-cache search festvox"):
        festival.synthesize("Hello", "no_such_voice")


@needs_festival
@pytest.mark.slow
def test_english_voice_works_the_same_way_if_installed(festival):
    if "kal_diphone" not in festival.voices():
        pytest.skip("kal_diphone (festvox-kallpc16k) is not installed")
    utterance = festival.synthesize("Hello world.", "kal_diphone")
    assert [w.label.lower() for w in utterance.words] == ["hello", "world"]
    assert_well_formed(utterance, tolerance_ms=0.1)


@needs_festival
@pytest.mark.slow
def test_phone_boundaries_equal_festivals_own_label_file(festival, tmp_path):
    """Festival's own ``utt.save.segs`` (0.1 ms resolution) of each utterance its tts mode makes, run
    independently and laid end to end, agrees with the phones (the ';' and '.' end utterances)."""
    text = "Pappa ja mummo ampuivat pumpulla; sää oli kaunis, vaikka tuuli. Mitä kuuluu?"
    for voice in FINNISH_VOICES:
        script = tmp_path / f"{voice}.scm"
        script.write_bytes(
            f'(voice_{voice})\n(set! n 0)\n'
            f'(define (save utt) (set! n (+ n 1))\n'
            f'  (utt.save.segs utt (format nil "{tmp_path}/{voice}-%d.segs" n)) utt)\n'
            f'(set! tts_hooks (list utt.synth save))\n(tts_text "{text}" nil)\n'.encode("latin-1"))
        subprocess.run(["festival", "--batch", str(script)], check=True, timeout=120, capture_output=True)
        labels, ends, offset = [], [], 0.0
        for number in range(1, 4):
            rows = [line.split() for line in
                    (tmp_path / f"{voice}-{number}.segs").read_text(encoding="latin-1").splitlines()]
            rows = rows[rows.index(["#"]) + 1:]
            labels += [r[2] for r in rows]
            ends += [offset + 1000 * float(r[0]) for r in rows]
            offset = ends[-1]
        assert not (tmp_path / f"{voice}-4.segs").exists()
        utterance = festival.synthesize(text, voice)
        assert [p.label for p in utterance.phones] == labels
        for phone, end in zip(utterance.phones, ends, strict=True):
            assert abs(phone.end_ms - end) <= 0.05 * 3 + 1e-9
        assert_well_formed(utterance, tolerance_ms=1000 / utterance.sample_rate)


@needs_festival
@pytest.mark.slow
def test_ten_second_utterance(festival, tmp_path):
    text = ("Sää on kaunis tänään, vaikka eilen satoi vettä koko päivän. Huomenna aurinko paistaa taas "
            "ja lämpötila nousee yli kahdenkymmenen asteen. Lähdemme silloin mökille järven rannalle.")
    utterance = festival.synthesize(text)
    assert 8000 < utterance.duration_ms < 14000
    assert_well_formed(utterance, tolerance_ms=1000 / utterance.sample_rate)
    assert {p.label for p in utterance.phones} <= SUOPUHE_PHONES
    assert festival.last_run_seconds < 30

    wav_path, csv_path = tmp_path / "say.wav", tmp_path / "say.csv"
    write_wav(wav_path, utterance)
    samples, rate = read_wav(wav_path)
    assert rate == utterance.sample_rate and len(samples) == len(utterance.samples)
    assert np.max(np.abs(samples - utterance.samples)) < 2 / 32768
    write_phones_csv(csv_path, utterance)
    back = read_phones_csv(csv_path)
    assert [(p.label, p.word) for p in back] == [(p.label, p.word) for p in utterance.phones]
    assert all(abs(a.start_ms - b.start_ms) < 5e-4 and abs(a.end_ms - b.end_ms) < 5e-4
               for a, b in zip(back, utterance.phones, strict=True))


@needs_festival
@pytest.mark.slow
def test_phone_set_of_a_broad_sample(festival):
    text = ("Kenkä, kengät, Helsinki. Aamu, eetteri, iiris, oopperan, uuni, yö, pyy, ääliö, kööri. "
            "Kukka kissa tuttu lappu mämmi kallis sanna marraskuu reppu. Bussi, dieselauto, golf, "
            "šakki, Thomas, lobbari, Eddie, bloggari, ahha, ajjaa, evvi, giraffi, Aššur.")
    for voice in FINNISH_VOICES:
        labels = {p.label for p in festival.synthesize(text, voice).phones}
        assert labels <= SUOPUHE_PHONES
        assert {"@", "7", "@:", "7:", "N", "N:", "S", "S:", "##", "#", "k:", "b:", "f:"} <= labels
