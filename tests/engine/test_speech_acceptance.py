"""Acceptance of the speech pipeline with real Festival and the default head.

Finnish sentences rich in bilabials and in open, spread and rounded vowels
are spoken by the Suopuhe voice; at the middle of every phone the face is
measured through its MPEG-4 landmarks (2.2/2.3 inner lip midpoints, 8.3/8.4
lip corners, 8.1/8.2 outer lip midpoints).
"""

from __future__ import annotations

import csv
import itertools
import subprocess

import numpy as np
import pytest

from engine.speech.say import speak
from tests.engine.cli_runner import run

pytestmark = pytest.mark.slow

SENTENCES = [
    "Pappa osti mummolle paljon uusia omenoita.",
    "Äiti ja isä menevät kauppaan ostamaan maitoa.",
    "Mummo ja pappa pitävät pipareista ja marjapuurosta.",
    "Vaaleanpunainen pallo pomppi pitkin lattiaa.",
    "Tyypillinen kesäpäivä on lämmin ja aurinkoinen.",
    "Iso hiiri juoksi kuusen alle, ja kissa katsoi sitä.",
]
TEXT = " ".join(SENTENCES)



@pytest.fixture(scope="module", params=["cohen-massaro", "none"])
def measured(request, head):
    """Landmarks at the middle of every phone, for both coarticulation methods."""
    speech = speak(TEXT, head, coarticulation=request.param)
    phones = speech.utterance.phones
    middles = np.array([(p.start_ms + p.end_ms) / 2 for p in phones])
    values = speech.timeline.sample(middles)
    names = speech.timeline.parameters
    marks = [head.landmark_positions(dict(zip(names, row, strict=True))) for row in values]
    return phones, marks


def _short(label: str) -> str:
    return label.rstrip(":")


def _gap(mark) -> float:
    return float(np.linalg.norm(mark["2.2"] - mark["2.3"]))


def test_lips_close_at_the_middle_of_every_bilabial(measured):
    phones, marks = measured
    gaps = [(p.label, p.start_ms, _gap(m)) for p, m in zip(phones, marks, strict=True)
            if _short(p.label) in ("p", "b", "m")]
    assert len(gaps) >= 20
    worst = max(gaps, key=lambda g: g[2])
    assert worst[2] <= 1.0, f"lip gap {worst[2]:.2f} mm at '{worst[0]}' ({worst[1]:.0f} ms)"


def test_open_vowels_open_the_mouth(measured):
    phones, marks = measured
    gaps = [_gap(m) for p, m in zip(phones, marks, strict=True) if p.label in ("a", "a:", "@", "@:")]
    assert len(gaps) >= 20
    assert np.mean(gaps) >= 6.0, f"mean gap at a, a:, @, @: is {np.mean(gaps):.2f} mm"


def test_spread_vowels_are_wider_and_rounded_vowels_further_forward(measured):
    phones, marks = measured
    spread = [m for p, m in zip(phones, marks, strict=True) if _short(p.label) in ("i", "e")]
    rounded = [m for p, m in zip(phones, marks, strict=True) if _short(p.label) in ("u", "o", "y")]
    assert len(spread) >= 10 and len(rounded) >= 10

    def width(m):
        return float(np.linalg.norm(m["8.3"] - m["8.4"]))

    def forward(m):
        return float((m["8.1"][2] + m["8.2"][2]) / 2)

    assert np.mean([width(m) for m in spread]) > np.mean([width(m) for m in rounded]) + 2.0
    assert np.mean([forward(m) for m in rounded]) > np.mean([forward(m) for m in spread]) + 1.0


def test_phones_csv_equals_festivals_own_segments_to_the_millisecond(tmp_path):
    out = tmp_path / "phones.csv"
    text = SENTENCES[0]
    result = run("say", text, "--phones", out)
    assert result.returncode == 0, result.stderr
    with out.open() as fh:
        rows = list(csv.DictReader(fh))
    ends = [float(r["end_ms"]) for r in rows]
    # Festival itself, asked directly for its segment relation.
    script = tmp_path / "segs.scm"
    script.write_bytes(("(voice_suo_fi_lj_diphone)\n"
                        f'(set! utt (SynthText "{text}"))\n'
                        "(mapcar (lambda (s) (format t \"%s %f\\n\" (item.name s) (item.feat s \"end\")))"
                        " (utt.relation.items utt 'Segment))\n").encode("latin-1"))
    festival = subprocess.run(["festival", "-b", str(script)], capture_output=True, timeout=120, check=False)
    segments = [line.split() for line in festival.stdout.decode("latin-1").splitlines()
                if len(line.split()) == 2 and not line.startswith("UniSyn")]
    assert [r["phone"] for r in rows] == [s[0] for s in segments]
    np.testing.assert_allclose(ends, [float(s[1]) * 1000 for s in segments], atol=0.5)
    assert float(rows[0]["start_ms"]) == 0
    assert all(float(a["end_ms"]) == float(b["start_ms"]) for a, b in itertools.pairwise(rows))


def test_inline_commands_merge_with_speech_on_one_timeline(head):
    speech = speak('Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä kuuluu?', head)
    mita = next(w for w in speech.utterance.words if w.label.lower() == "mitä")
    nod = [a for a in speech.activations if a.command == "HeadNod"]
    assert len(nod) == 1 and nod[0].times[0] == pytest.approx(mita.start_ms, abs=1e-6)
    assert speech.timeline.values_at(nod[0].times[1])["head_nod"] == pytest.approx(0.09)
    assert any(a.command == "speech" and a.parameter == "jaw_open" for a in speech.activations)


def test_say_writes_the_tables_and_low_level_commands(tmp_path):
    text = "Hyvää päivää <Blink/> mitä kuuluu?"
    result = run("say", text, "--fps", "25", "--tracks", tmp_path / "t.csv", "--landmarks", tmp_path / "l.csv",
                 "-o", tmp_path / "low.xml", "--prosody", "--seed", "3")
    assert result.returncode == 0, result.stderr
    tracks = list(csv.reader((tmp_path / "t.csv").read_text().splitlines()))
    marks = list(csv.reader((tmp_path / "l.csv").read_text().splitlines()))
    assert tracks[0][0] == "time_ms" and "lower_lip_raise" in tracks[0]
    assert marks[0][:5] == ["frame", "time_ms", "2.1_x", "2.1_y", "2.1_z"]
    assert len(tracks) == len(marks)
    assert [float(r[0]) for r in tracks[1:4]] == [0, 40, 80]
    low = (tmp_path / "low.xml").read_text()
    assert 'command="Blink"' in low and 'command="speech"' in low


@pytest.mark.parametrize("args, words", [
    (("moi <Blinkk/>", "--phones", "x.csv"), "unknown command <Blinkk>"),
    (("moi", "--voice", "no_such_voice", "--phones", "x.csv"), "no_such_voice"),
    (("moi",), "nothing to write"),
    (("<Blink/>", "--phones", "x.csv"), "no text to speak"),
    (("moi", "-o", "x.avi"), "unknown output extension"),
])
def test_say_errors_are_one_line(tmp_path, args, words):
    result = run("say", *args, cwd=tmp_path)
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr and words in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_say_mp4_has_audio_and_video_that_agree_within_one_frame(tmp_path):
    from engine.outputs.video_probe import probe, read_frames

    text_file = tmp_path / "talk.txt"
    text_file.write_text("Pappa ja mummo <BrowRaise/> ostivat omenoita.\n", encoding="utf-8")
    out = tmp_path / "talk.mp4"
    result = run("say", "--file", text_file, "--voice", "hy_fi_mv_diphone", "--fps", "25", "--size", "320x240",
                 "-o", out, "--quiet")
    assert result.returncode == 0, result.stderr
    info = probe(out)
    assert info.video_start == pytest.approx(0, abs=1e-3) and info.audio_start == pytest.approx(0, abs=1e-3)
    assert abs(info.video_duration - info.audio_duration) <= 1 / 25
    assert (info.width, info.height) == (320, 240) and info.fps == pytest.approx(25)
    frames = read_frames(out, [0, info.frames // 2])
    assert frames.shape[1:] == (240, 320, 3) and np.abs(frames[0].astype(int) - frames[1]).max() > 30
