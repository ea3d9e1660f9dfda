"""Stimulus sets from design files (issue 20): designs, every example, checks, reproducibility, resume, Dask.

Real Festival, real ffmpeg, real processes; the Dask cluster is one of local
worker processes on 127.0.0.1.
"""

from __future__ import annotations

import csv
import itertools
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from engine.stimuli import DesignError, load_design, make_set, parse_design
from engine.stimuli.make import RECORDS, sha256_of
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.test_festival import needs_festival

EXAMPLES = Path(__file__).parents[2] / "examples" / "stimuli"
SMALL = """
[factors]
text = ["Pappa ampui pallon.", "Maija meni kotiin."]
av_offset_ms = [-150, 0, 250]

[output]
kinds = ["mp4", "wav"]
size = "96x72"
fps = 25
"""


def rows(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


# ---------------------------------------------------------------------------
# Design files
# ---------------------------------------------------------------------------

def test_crossing_lists_and_blocks():
    design = parse_design(SMALL, "d.toml")
    assert [(s.id, s.levels["av_offset_ms"]) for s in design.stimuli][:3] == [("0001", -150), ("0002", 0),
                                                                              ("0003", 250)]
    listed = parse_design('combine = "list"\n[factors]\ntext = ["a.", "b."]\nx = [1, 2]\n'
                          '[[rows]]\ntext = "b."\nx = 2\n', "l.toml")
    assert [s.levels for s in listed.stimuli] == [{"text": "b.", "x": 2}]
    blocks = load_design(EXAMPLES / "blocks.toml")
    assert [(s.levels["av_offset_ms"], s.levels["expression"]) for s in blocks.stimuli] == [
        (-300, "none"), (0, "none"), (300, "none"), (0, "Happy")]


@pytest.mark.parametrize("text, line, message", [
    ('[factors]\ntext = ["a."]\n\n[output]\nkinds = ["avi"]\n', 5, "kinds: kinds must list some of"),
    ('[factors]\ntext = ["a."]\nintensity = [150]\n', 3, "'intensity' level 150: must be a number from 0 to 100"),
    ('[factors]\ntext = ["a."]\ncolour = 3\n', 3, "factor 'colour' must be a list"),
    ('[factors]\ntext = ["a."]\n[output]\nsize = "320x241"\n', 4, "size must be WIDTHxHEIGHT"),
    ('[factors]\ntext = ["a."]\nmodel = ["nosuch.xml"]\n', 3, "no such model file"),
    ('[factors]\ntext = ["a."]\n[output]\nfps = 30\nsped = 2\n', 5, "unknown output key 'sped'"),
    ('[factors\ntext = ["a."]\n', 1, "not a TOML file"),
    ('seed = -1\n[factors]\ntext = ["a."]\n', 1, "seed must be a whole number"),
    ('[output]\nfps = 30\n', 1, "no [factors] table"),
    ('[factors]\ntext = ["a."]\nidentity = [{age = 120}]\n', 3, "'age' = 120 is outside its range [1, 90]"),
    ('[factors]\ntext = ["a."]\nidentity = [{nose = 1}]\n', 3, "unknown identity parameter 'nose'"),
    ('[factors]\ntext = ["a."]\nidentity = [3]\n', 3, "must be a table of identity parameters"),
    ('[factors]\ntext = ["a."]\nidentity_b = [{sex = 1}]\n', 3, "needs identity_morph"),
    ('[factors]\ntext = ["a."]\nviseme = ["p"]\nviseme_b = ["t"]\n', 3, "viseme_morph is missing"),
])
def test_a_bad_design_names_file_line_and_key(tmp_path, text, line, message):
    design = tmp_path / "bad.toml"
    design.write_text(text, encoding="utf-8")
    error = assert_user_error(run_in_process("stimuli", design, "-o", tmp_path / "out"))
    assert error.startswith(f"error: {design}:{line}: ") and message in error, error
    assert not (tmp_path / "out").exists()                               # nothing is written


def test_the_estimate_scales_with_the_length_spoken():
    from engine.stimuli.estimate import relative_length

    design = parse_design('[factors]\ntext = ["Aa.", "Pappa osti mummolle paljon uusia omenoita."]\n', "d.toml")
    short, long = (relative_length(design, s) for s in design.stimuli)
    assert long > 3 * short


def test_identity_levels_are_tables_and_the_manifest_writes_them_readably():
    design = load_design(EXAMPLES / "identity_continuum.toml")
    assert [s.levels["identity_morph"] for s in design.stimuli] == [0, 25, 50, 75, 100]
    assert design.stimuli[0].levels["identity_b"] == {"sex": 1.0, "age": 60}
    from engine.stimuli.manifest import level_text

    assert level_text({"sex": 1.0, "age": 60}) == "sex=1;age=60"


@needs_festival
@pytest.mark.slow
def test_a_viseme_continuum_opens_the_lips_step_by_step(tmp_path, head):
    """p → t in five steps: at the middle of the p the inner lip gap grows from closed to a t's opening."""
    out = tmp_path / "set"
    assert run("stimuli", EXAMPLES / "viseme_continuum.toml", "-o", out, "--workers", "2").returncode == 0
    gaps = []
    for row in rows(out / "manifest.csv"):
        phones = rows(out / row["file_phones"])
        p = next(ph for ph in phones if ph["phone"] == "p")
        middle = (float(p["start_ms"]) + float(p["end_ms"])) / 2
        tracks = rows(out / row["file_tracks"])
        times = np.array([float(r["time_ms"]) for r in tracks])
        names = [n for n in tracks[0] if n != "time_ms"]
        values = {n: float(np.interp(middle, times, [float(r[n]) for r in tracks])) for n in names}
        lm = head.landmark_positions(values)
        gaps.append(float(np.linalg.norm(lm["2.2"] - lm["2.3"])))
    assert gaps[0] <= 1.2, f"the p at 0 % is closed ({gaps[0]:.2f} mm)"
    assert all(b > a for a, b in itertools.pairwise(gaps)), gaps
    assert gaps[-1] >= gaps[0] + 2.0, gaps


@needs_festival
def test_dry_run_lists_and_estimates(tmp_path):
    """The estimate comes from one stimulus made here (in a temporary folder), scaled to the others."""
    result = run("stimuli", EXAMPLES / "minimal.toml", "-o", tmp_path / "out", "--dry-run")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("0001  to make") and "av_offset_ms=-200" in lines[0]
    assert lines[-1].startswith("6 stimuli, 6 to make, about ") and "stimulus 0001 made here in" in lines[-1]
    assert not (tmp_path / "out").exists()


# ---------------------------------------------------------------------------
# Making sets
# ---------------------------------------------------------------------------

@needs_festival
@pytest.mark.slow
@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_every_example_design_runs(example, tmp_path):
    out = tmp_path / "set"
    result = run("stimuli", EXAMPLES / example, "-o", out, "--workers", "2")
    assert result.returncode == 0, result.stderr
    design = load_design(EXAMPLES / example)
    manifest = rows(out / "manifest.csv")
    assert [r["id"] for r in manifest] == [s.id for s in design.stimuli]
    for row in manifest:
        for kind in design.output.kinds:
            path = out / row[f"file_{kind}"]
            assert path.is_file() and sha256_of(path) == row[f"sha256_{kind}"]
    conditions = rows(out / "conditions.csv")
    assert all((out / r["stimulus"]).is_file() for r in conditions)
    assert all(r["ok"] == "yes" for r in rows(out / "check.csv"))
    assert (out / "contact-sheet.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    provenance = json.loads((out / "provenance.json").read_text())
    assert provenance["design"]["sha256"] == design.sha256 and provenance["festival"]["voices"]


@needs_festival
@pytest.mark.slow
def test_offsets_and_snr_are_what_the_files_hold(tmp_path, head):
    """Measured here from the files, independently of the set's own checks: the audio starts where the
    manifest says (to the sample), the video's mouth moves where it says, the noise is at its SNR."""
    from engine.outputs.video_probe import read_audio
    from engine.speech.say import speak
    from engine.speech.synthesis import read_wav
    from engine.stimuli.audio import measured_offset_ms

    design = tmp_path / "d.toml"
    design.write_text(SMALL.replace('"Maija meni kotiin."', "") .replace(", ]", "]")
                      .replace('kinds = ["mp4", "wav"]', 'kinds = ["mp4", "wav", "tracks"]'), encoding="utf-8")
    out = tmp_path / "set"
    assert run("stimuli", design, "-o", out, "--workers", "1").returncode == 0
    clean = speak("Pappa ampui pallon.", head).utterance
    jaw = None
    for row in rows(out / "manifest.csv"):
        offset = float(row["av_offset_ms"])
        wav, rate = read_wav(out / row["file_wav"])
        start = measured_offset_ms(clean.samples, wav, rate, 600)
        assert start == pytest.approx(max(0.0, offset), abs=1000 / rate)
        audio, _ = read_audio(out / row["file_mp4"], rate)
        assert measured_offset_ms(clean.samples, audio, rate, 600) == pytest.approx(max(0.0, offset), abs=1000 / rate)
        table = np.genfromtxt(out / row["file_tracks"], delimiter=",", names=True)
        moving = table["time_ms"][np.abs(table["jaw_open"]) > 0.05]
        video_start = float(row["video_start_ms"])
        assert video_start == pytest.approx(max(0.0, -offset))
        first = moving[0] - video_start                    # the mouth's first opening, on the speech's clock
        jaw = first if jaw is None else jaw
        assert first == pytest.approx(jaw, abs=1000 / 25 + 1e-6)


@needs_festival
@pytest.mark.slow
def test_a_missed_specification_fails_the_run(tmp_path, monkeypatch, capsys):
    import engine.stimuli.make as make
    from engine.cli import main

    design = tmp_path / "d.toml"
    design.write_text('[factors]\ntext = ["Moi."]\nsnr_db = [3]\n[output]\nkinds = ["wav"]\n', encoding="utf-8")
    monkeypatch.setattr(make, "SNR_TOLERANCE_DB", {"wav": -1.0, "mp4": -1.0})    # nothing can meet it
    code = main(["stimuli", str(design), "-o", str(tmp_path / "out"), "--workers", "1"])
    assert code == 1
    assert "stimulus 0001 misses its specification: the SNR in the wav" in capsys.readouterr().err
    assert rows(tmp_path / "out" / "check.csv")[0]["ok"] == "NO"


@needs_festival
@pytest.mark.slow
def test_the_same_design_makes_bit_identical_files_and_resume_after_kill_finishes_it(tmp_path):
    design = tmp_path / "d.toml"
    design.write_text(SMALL, encoding="utf-8")
    first = tmp_path / "first"
    assert run("stimuli", design, "-o", first, "--workers", "2").returncode == 0
    second = tmp_path / "second"
    process = subprocess.Popen([sys.executable, "-m", "engine", "stimuli", str(design), "-o", str(second),
                                "--workers", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not list((second / RECORDS).glob("*.json")):
        time.sleep(0.05)
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    made_before = len(list((second / RECORDS).glob("*.json")))
    assert 1 <= made_before < 6 and not (second / "manifest.csv").exists()
    for path in second.iterdir():                         # nothing half-made under a final name
        if path.suffix in (".mp4", ".wav"):
            assert (second / RECORDS / f"{path.stem}.json").exists() or path.stat().st_size > 0
    assert_user_error(run("stimuli", design, "-o", second))          # not without --resume
    result = run("stimuli", design, "-o", second, "--resume", "--workers", "2")
    assert result.returncode == 0, result.stderr
    assert f"{6 - made_before} made, {made_before} already there" in result.stdout
    assert not [p for p in second.iterdir() if p.name.endswith((".tmp", ".journal"))]
    a, b = rows(first / "manifest.csv"), rows(second / "manifest.csv")
    assert [r["sha256_mp4"] for r in a] == [r["sha256_mp4"] for r in b]       # bit-identical, resumed or not
    assert [r["sha256_wav"] for r in a] == [r["sha256_wav"] for r in b]
    (second / "0003.wav").write_bytes(b"damaged")                            # a damaged file is made again
    result = run("stimuli", design, "-o", second, "--resume", "--workers", "1")
    assert "1 made, 5 already there" in result.stdout
    assert sha256_of(second / "0003.wav") == a[2]["sha256_wav"]


# ---------------------------------------------------------------------------
# A Dask cluster of local worker processes (127.0.0.1 only)
# ---------------------------------------------------------------------------

@needs_festival
@pytest.mark.slow
def test_a_dask_cluster_makes_the_set_even_when_a_worker_is_killed(tmp_path):
    from distributed import Client, LocalCluster

    design = load_design(_write(tmp_path / "d.toml", SMALL))
    out = tmp_path / "set"
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None, silence_logs=50) as cluster, Client(cluster) as client:
        outcome: dict[str, object] = {}

        def make() -> None:
            try:
                outcome["result"] = make_set(design, out, scheduler=cluster.scheduler_address)
            except BaseException as error:          # reported below
                outcome["error"] = error

        worker = threading.Thread(target=make)
        worker.start()
        killed = None
        deadline = time.monotonic() + 120
        while killed is None and time.monotonic() < deadline:
            busy = [address for address, tasks in client.processing().items() if tasks]
            if busy and list((out / RECORDS).glob("*.json")):
                pids = client.run(os.getpid)
                killed = pids[busy[0]]
                os.kill(killed, signal.SIGKILL)          # mid-task: it holds a stimulus
            time.sleep(0.05)
        worker.join(300)
    assert killed is not None, "no worker was ever busy"
    assert "error" not in outcome, outcome.get("error")
    manifest = rows(out / "manifest.csv")
    assert [r["id"] for r in manifest] == [s.id for s in design.stimuli]
    for row in manifest:
        assert sha256_of(out / row["file_mp4"]) == row["sha256_mp4"]


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_design_errors_are_user_errors():
    with pytest.raises(DesignError, match=r"d\.toml:2: text"):
        parse_design('[factors]\ntext = [""]\n', "d.toml")


@needs_festival
@pytest.mark.slow
def test_mcgurk_pairs_are_aligned_at_the_vowel(tmp_path, head):
    """Heard /kaa/ over seen /paa/: the vowel begins at the same moment in the audio and on the face, the
    lips close for the seen p, and the manifest names both sources and the shift."""
    from engine.speech.say import speak

    out = tmp_path / "set"
    assert run("stimuli", EXAMPLES / "mcgurk.toml", "-o", out, "--workers", "1").returncode == 0
    row = next(r for r in rows(out / "manifest.csv") if r["text"] == "Paa." and r["audio_text"] == "Kaa.")
    seen, heard = speak("Paa.", head).utterance, speak("Kaa.", head).utterance
    vowel = next(p for p in seen.phones if p.label.startswith("a")).start_ms
    heard_vowel = next(p for p in heard.phones if p.label.startswith("a")).start_ms
    assert float(row["alignment_ms"]) == pytest.approx(vowel - heard_vowel, abs=1e-3)
    assert float(row["audio_start_ms"]) + heard_vowel == pytest.approx(float(row["video_start_ms"]) + vowel,
                                                                        abs=1e-3)
    table = np.genfromtxt(out / row["file_tracks"], delimiter=",", names=True)
    p = next(s for s in seen.phones if s.label == "p")
    closed = table["lower_lip_raise"][np.abs(table["time_ms"] - float(row["video_start_ms"]) - p.mid_ms) <= 20]
    assert closed.max() > 0.9                                         # the face says p, whatever is heard


@needs_festival
@pytest.mark.slow
def test_the_video_check_sees_frames_shifted_off_the_face(tmp_path, head):
    """The check measures the file: frames that moved two frames off the face are caught."""
    from engine.stimuli.make import _check_video, vertex_motion

    design = _write(tmp_path / "d.toml", '[factors]\ntext = ["Pappa ampui pallon."]\n[output]\n'
                    'kinds = ["silent-mp4", "tracks"]\nsize = "96x72"\nfps = 25\n')
    out = tmp_path / "set"
    assert run("stimuli", design, "-o", out).returncode == 0
    row = rows(out / "manifest.csv")[0]
    table = np.genfromtxt(out / row["file_tracks"], delimiter=",", names=True)
    values = np.column_stack([table[name] for name in table.dtype.names[1:]])
    video = {"silent-mp4": out / row["file_silent-mp4"]}
    assert list(table.dtype.names[1:]) == head.parameters.names
    assert _check_video(video, vertex_motion(head, values), 25.0, 0.0) == {"measured_video_lag_frames": 0,
                                                                            "video_ok": True}
    late = np.vstack([np.repeat(values[:1], 2, axis=0), values[:-2]])        # the face two frames later
    assert _check_video(video, vertex_motion(head, late), 25.0, 0.0) == {"measured_video_lag_frames": -2,
                                                                         "video_ok": False}


_FAILS_AT = """
[factors]
text = [{texts}]
audio_text = ["Tiili."]
align_phone = ["i"]

[output]
kinds = ["wav"]
"""


@needs_festival
def test_a_stimulus_that_fails_first_leaves_no_empty_set_folder(tmp_path):
    """'Pappa.' has no i to align at: found only when the stimulus is made, before anything is finished."""
    (tmp_path / "d.toml").write_text(_FAILS_AT.format(texts='"Pappa."'))
    line = assert_user_error(run_in_process("stimuli", tmp_path / "d.toml", "-o", tmp_path / "set", "--workers", "1"))
    assert "stimulus 0001: 'Pappa.' has no 'i'" in line
    assert not (tmp_path / "set").exists()


@needs_festival
def test_a_stimulus_that_fails_later_keeps_the_finished_ones_and_says_how_to_go_on(tmp_path):
    (tmp_path / "d.toml").write_text(_FAILS_AT.format(texts='"Tiili.", "Pappa."'))
    out = tmp_path / "set"
    made = run("stimuli", tmp_path / "d.toml", "-o", out, "--workers", "1")
    assert made.returncode == 2 and "Traceback" not in made.stderr, made.stderr
    line = made.stderr.splitlines()[-1]            # after the progress line of the stimulus that was made
    assert line.startswith("error: ") and "stimulus 0002" in line
    assert f"1 of 2 stimuli were finished and are kept in {out}" in line
    assert "--resume" in line and (out / "0001.wav").is_file()
    (tmp_path / "d.toml").write_text(_FAILS_AT.format(texts='"Tiili.", "Tipi."'))
    resumed = run("stimuli", tmp_path / "d.toml", "-o", out, "--workers", "1", "--resume")
    assert resumed.returncode == 0, resumed.stderr
    assert [r["text"] for r in rows(out / "manifest.csv")] == ["Tiili.", "Tipi."]


@needs_festival
def test_a_failing_stimulus_leaves_a_folder_the_user_made_in_place(tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (tmp_path / "d.toml").write_text(_FAILS_AT.format(texts='"Pappa."'))
    assert_user_error(run_in_process("stimuli", tmp_path / "d.toml", "-o", out, "--workers", "1"))
    assert out.is_dir()


@needs_festival
def test_a_silent_video_beside_the_sound_one_is_not_drawn_again(tmp_path, monkeypatch):
    """Issue 35 §4, each result computed once: with mp4 and silent-mp4, the face is drawn once per frame (a
    counter of the renderer's draws, not a timer) and the silent file holds the very same frames."""
    from engine.outputs import render
    from engine.outputs.render_helper import ENVIRONMENT
    from engine.outputs.video_probe import probe, read_frames
    from engine.stimuli.make import make_stimulus

    monkeypatch.setenv(ENVIRONMENT, "1")                 # one process draws every frame, so all are counted here
    draws = []
    original = render.FrameRenderer.render
    monkeypatch.setattr(render.FrameRenderer, "render", lambda self, positions: (draws.append(1),
                                                                                  original(self, positions))[1])
    counts = {}
    for kinds in ('["mp4"]', '["silent-mp4", "mp4"]'):
        design = parse_design(f'[factors]\ntext = ["Pappa."]\n[output]\nkinds = {kinds}\nsize = "64x48"\n',
                              str(tmp_path / "d.toml"))
        out = tmp_path / str(len(counts))
        out.mkdir()
        draws.clear()
        make_stimulus(design, design.stimuli[0], out)
        counts[kinds] = len(draws)
    assert counts['["silent-mp4", "mp4"]'] == counts['["mp4"]'] > 0
    silent, sound = tmp_path / "1" / "0001-silent.mp4", tmp_path / "1" / "0001.mp4"
    assert probe(silent).audio_codec is None and probe(sound).audio_codec == "aac"
    np.testing.assert_array_equal(read_frames(silent), read_frames(sound))
