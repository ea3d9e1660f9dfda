"""A built study answered in real headless Chromium, on every host's layout, and its data analysed.

The study (``test_study_helpers``: a real three-stimulus set as stills and videos, the astronaut as the
human comparison, a practice trial, an attention check, static and dynamic blocks counterbalanced) is
built by the CLI and answered by key presses alone (DevTools ``Input.dispatchKeyEvent``), by participants
who follow a fixed policy, each on one layout:

1. **lab**: ``run-lab.py`` serves the folder on 127.0.0.1; participant 1 always answers the intended emotion;
   the data arrive in ``data/tiny_1.csv``;
2. **JATOS**: the ``.jzip`` unpacked and served with a stand-in ``jatos.js`` (records what the study sends);
   participant 2 (the study result id) always answers "happy";
3. **Cognition.run**: ``task.js`` run after jsPsych on a page of its own, the stimuli flat beside it (as
   Cognition serves them); participant 3, the intended emotion; jsPsych's own CSV of every trial is what
   Cognition exports;
4. **Pavlovia**: the repository's files served with a stand-in for Pavlovia's plugin in ``lib/vendors/``;
   participant 4, "happy";
5. **a folder opened as a file** (``file://``, no server): the participant's number typed into the first
   page; participant 5, the intended emotion; the browser downloads the CSV.

``study-analyse`` on the five files gives Hu = 1 and a recognition rate of 1 for the intended-emotion
participants, and for the "happy" ones the Hu their policy implies (Hu_happy = pc_happy = share of happy
stimuli in the condition, 0 for every other emotion). ``AP_SCREENSHOT_DIR=DIR`` keeps pictures of the
pages (docs/images/study/).
"""

from __future__ import annotations

import csv
import io
import json
import os
import shutil
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

from engine.study.compile import participant_sequence
from tests.engine.cli_runner import run
from tests.engine.test_study_helpers import Participant, always_happy, intended, make_study_inputs
from tests.web_browser import CHROMIUM, Browser, outside, served

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (./bootstrap installs it)")]
SIZE = (960, 640)
SHOTS = Path(os.environ["AP_SCREENSHOT_DIR"]) if os.environ.get("AP_SCREENSHOT_DIR") else None
JATOS_STUB = """window.jatos = { studyResultId: 2, urlQueryParameters: {}, files: {}, submitted: null, ended: false,
  onLoad(callback) { setTimeout(callback, 0); },
  uploadResultFile(data, name) { this.files[name] = data; return Promise.resolve(); },
  submitResultData(data) { this.submitted = data; return Promise.resolve(); },
  endStudy() { this.ended = true; } };
"""
PAVLOVIA_STUB = """var jsPsychPavlovia = (function (jspsych) {
  class Stand { constructor(jsPsych) { this.jsPsych = jsPsych; }
    trial(display, trial) {
      (window.pavlovia = window.pavlovia || []).push(trial.command);
      if (trial.command === "finish") window.pavloviaData = trial.dataFilter(this.jsPsych.data.get().csv());
      this.jsPsych.finishTrial({});
    } }
  Stand.info = { name: "pavlovia", version: "0", parameters: {
    command: { type: jspsych.ParameterType.STRING, default: "init" },
    participantId: { type: jspsych.ParameterType.STRING, default: null },
    dataFilter: { type: jspsych.ParameterType.FUNCTION, default: null } } };
  return Stand;
})(jsPsychModule);
"""
COGNITION_PAGE = """<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,">
<link rel="stylesheet" href="jspsych.css"><script src="jspsych.js"></script><script src="task.js"></script>
</head><body></body></html>"""


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    design = make_study_inputs(folder)
    made = run("study", design, "-o", folder / "study")
    assert made.returncode == 0, made.stderr
    study = folder / "study"
    return folder, study, json.loads((study / "study.json").read_text())


def _answer(url: str, document: dict, policy, participant: str | None = None, download: Path | None = None,
            shots: Path | None = None, after_the_end: bool = False) -> dict:
    with Browser() as chromium:
        if download is not None:
            chromium.call("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(download)})
        page = chromium.open(url, SIZE)
        end = Participant(page, document, policy, shots, after_the_end).run(participant)
        return {"page": page, "end": end, "problems": page.problems(), "requested": page.requested(),
                "rows": page.evaluate("window.APStudy.csv()"),
                "all_trials_csv": page.evaluate("window.APStudy.jsPsych.data.get().csv()"),
                "jatos": page.evaluate("window.jatos ? {submitted: jatos.submitted, files: jatos.files, "
                                       "ended: jatos.ended} : null"),
                "pavlovia": page.evaluate("window.pavlovia ? {commands: window.pavlovia, data: window.pavloviaData}"
                                          " : null")}


@pytest.fixture(scope="module")
def sessions(built, tmp_path_factory):
    _, study, document = built
    out: dict[str, dict] = {}
    # 1. the lab computer: run-lab.py
    lab = subprocess.Popen([sys.executable, str(study / "run-lab.py"), "--port", "0", "--no-browser", "--participant",
                            "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = lab.stdout.readline()
        url = line.split(" at ", 1)[1].split(" ", 1)[0]
        out["lab"] = _answer(url, document, intended, shots=SHOTS)
        out["lab"]["base"] = url.split("/index.html")[0]
    finally:
        lab.terminate()
        lab.wait(timeout=30)
        lab.stdout.close()
        lab.stderr.close()
    out["lab"]["saved"] = (study / "data" / "tiny_1.csv").read_bytes().decode("utf-8")
    # 2. JATOS: the archive unpacked, a stand-in jatos.js beside the component page
    jatos = tmp_path_factory.mktemp("jatos")
    with zipfile.ZipFile(study / "hosts" / "jatos" / "tiny.jzip") as archive:
        archive.extractall(jatos)
    (jatos / "tiny" / "jatos.js").write_text(JATOS_STUB)
    with served(jatos) as base:
        out["jatos"] = _answer(f"{base}/tiny/index.html", document, always_happy)
        out["jatos"]["base"] = base
    # 3. Cognition.run: jsPsych, then task.js; the stimuli flat beside the page
    cognition = tmp_path_factory.mktemp("cognition")
    for path in (study / "hosts" / "cognition" / "stimuli").iterdir():
        shutil.copyfile(path, cognition / path.name)
    shutil.copyfile(study / "hosts" / "cognition" / "task.js", cognition / "task.js")
    shutil.copyfile(study / "jspsych" / "dist" / "index.browser.min.js", cognition / "jspsych.js")
    shutil.copyfile(study / "jspsych" / "css" / "jspsych.css", cognition / "jspsych.css")
    (cognition / "index.html").write_text(COGNITION_PAGE)
    with served(cognition) as base:
        out["cognition"] = _answer(f"{base}/index.html?participant=3", document, intended)
        out["cognition"]["base"] = base
    # 4. Pavlovia: the repository's files, a stand-in plugin in lib/vendors/
    pavlovia = tmp_path_factory.mktemp("pavlovia") / "repo"
    shutil.copytree(study / "hosts" / "pavlovia", pavlovia)
    (pavlovia / "lib" / "vendors" / "jspsych-7-pavlovia-2022.1.1.js").write_text(PAVLOVIA_STUB)
    with served(pavlovia) as base:
        out["pavlovia"] = _answer(f"{base}/index.html?participant=4", document, always_happy)
        out["pavlovia"]["base"] = base
    # 5. the folder opened as a file: the number typed in, the CSV downloaded
    downloads = tmp_path_factory.mktemp("downloads")
    out["file"] = _answer((study / "index.html").as_uri(), document, intended, participant="5", download=downloads)
    target = downloads / "tiny_5.csv"
    deadline = time.monotonic() + 30
    while not target.exists() and time.monotonic() < deadline:
        time.sleep(0.1)
    out["file"]["saved"] = target.read_bytes().decode("utf-8")
    return out


def _rows(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


def test_every_host_runs_the_study_and_saves_the_data_its_own_way(sessions):
    assert sessions["lab"]["end"]["done"] == "lab"
    assert sessions["lab"]["saved"] == sessions["lab"]["rows"]
    jatos = sessions["jatos"]["jatos"]
    assert sessions["jatos"]["end"]["done"] == "jatos"
    assert jatos["submitted"] == sessions["jatos"]["rows"] and jatos["files"] == {"tiny_2.csv": jatos["submitted"]}
    assert sessions["cognition"]["end"]["done"] == "cognition"
    pavlovia = sessions["pavlovia"]["pavlovia"]
    assert pavlovia["commands"] == ["init", "finish"] and pavlovia["data"] == sessions["pavlovia"]["rows"]
    assert sessions["file"]["end"]["done"] == "download" and sessions["file"]["saved"] == sessions["file"]["rows"]
    for name, session in sessions.items():
        assert session["problems"] == [], (name, session["problems"])
        if name != "file":
            assert outside(session["requested"], session["base"], lambda u: u.startswith("blob:")) == [], name
        else:
            assert all(u.startswith(("file://", "data:", "blob:")) for u in session["requested"])


def test_the_participants_are_who_each_host_says(sessions):
    expected = {"lab": ("1", "url"), "jatos": ("2", "host"), "cognition": ("3", "url"), "pavlovia": ("4", "url"),
                "file": ("5", "entered")}
    for name, (participant, source) in expected.items():
        rows = _rows(sessions[name]["rows"])
        assert {(r["participant"], r["participant_source"], r["host"]) for r in rows} == {
            (participant, source, "folder" if name in ("lab", "file") else name)}, name


def test_the_order_is_drawn_from_the_recorded_seed(sessions, built):
    _, _, document = built
    for name, participant in (("lab", "1"), ("jatos", "2"), ("file", "5")):
        rows = _rows(sessions[name]["rows"])
        seed, order, sequence = participant_sequence(document, participant)
        assert {int(r["participant_seed"]) for r in rows} == {seed}
        assert {int(r["order"]) for r in rows} == {order}
        trials = document["trials"]
        assert [(r["phase"], r["stimulus"], r["presentation"]) for r in rows] == [
            (item.phase, trials[item.spec]["stimulus"], trials[item.spec]["presentation"]) for item in sequence]
        assert [int(r["trial"]) for r in rows] == list(range(1, len(rows) + 1))
    # the two block orders are both used: participant 1 sees static first, participant 2 dynamic first
    first = {name: _rows(sessions[name]["rows"])[1]["block"] for name in ("lab", "jatos")}
    assert first == {"lab": "static", "jatos": "dynamic"}


def test_each_row_holds_its_levels_its_answers_and_the_players_times(sessions, built):
    folder, _, document = built
    with (folder / "set" / "manifest.csv").open(newline="") as table:
        manifest = {row["id"]: row for row in csv.DictReader(table)}
    rows = _rows(sessions["lab"]["rows"])
    assert len(rows) == 1 + 8 + 1              # practice, 3 stimuli × 2 + 2 human, the attention check
    for row in rows:
        assert row["study"] == "tiny" and row["study_id"] == document["study_id"]
        assert row["set_manifest_sha256"] == document["set_manifest_sha256"]
        assert row["response_method"] == "key" and row["correct"] == "1"
        assert float(row["response_t"]) >= float(row["onset_t"])
        if row["source"] == "synthetic":
            listed = manifest[row["stimulus"]]
            assert (row["text"], row["expression"]) == (listed["text"], listed["expression"])
            assert float(row["duration_ms"]) == pytest.approx(float(listed["duration_ms"]))
        else:
            assert row["actor"] == "astronaut" and row["intended"] == "happy"
        if row["phase"] != "attention":
            assert row["rating_intensity"] == "4" and row["rating_naturalness"] == "4"
            assert float(row["rating_intensity_rt"]) >= 0
        if row["presentation"] == "static":
            assert row["media"] == "image"
            assert float(row["rt"]) == pytest.approx(float(row["response_t"]) - float(row["onset_t"]), abs=0.002)
        else:
            assert row["media"] == "video" and int(row["frames"]) >= 1 and row["sound"] == "1"
            assert float(row["play_t"]) <= float(row["first_frame_t"]) <= float(row["response_t"])
            assert float(row["rt"]) >= 0
            if row["source"] == "synthetic":
                assert float(row["audio_start_t"]) == pytest.approx(float(row["clip_start_t"]) +
                                                                     float(row["audio_start_ms"]), abs=0.002)
                words = json.loads(row["word_onsets"])
                assert [w["word"] for w in words] == manifest[row["stimulus"]]["words"].split(";")
    attention = [r for r in rows if r["phase"] == "attention"]
    assert attention and attention[0]["response"] == attention[0]["expected"]


def test_the_analysis_gives_the_numbers_the_policies_imply(sessions, built, tmp_path):
    folder, _, _ = built
    files = {"lab.csv": sessions["lab"]["saved"], "jatos-export.txt": sessions["jatos"]["jatos"]["submitted"],
             "cognition-export.csv": sessions["cognition"]["all_trials_csv"],
             "pavlovia.csv": sessions["pavlovia"]["pavlovia"]["data"], "tiny_5.csv": sessions["file"]["saved"]}
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    report = tmp_path / "report"
    done = run("study-analyse", *sorted(tmp_path.glob("*.*")), "--set", folder / "set", "-o", report)
    assert done.returncode == 0, done.stderr
    hu = _rows((report / "hu.csv").read_text())
    assert {r["participant"] for r in hu} == {"1", "2", "3", "4", "5"}
    for row in hu:
        if row["participant"] in ("1", "3", "5"):                  # always the intended emotion
            assert float(row["hu"]) == 1.0 and float(row["hit_rate"]) == 1.0, row
            continue
        condition = [r for r in hu if (r["participant"], r["source"], r["presentation"]) ==
                     (row["participant"], row["source"], row["presentation"])]
        total = sum(int(r["stimuli"]) for r in condition)
        happy = next(int(r["stimuli"]) for r in condition if r["emotion"] == "happy")
        if row["emotion"] == "happy":                              # every answer "happy": Hu = pc = share of happy
            assert float(row["hu"]) == pytest.approx(happy / total) and float(row["pc"]) == pytest.approx(happy / total)
            assert int(row["responses"]) == total
        else:
            assert float(row["hu"]) == 0.0 and int(row["responses"]) == 0
    recognition = {(r["source"], r["presentation"], r["emotion"]): r for r in _rows((report / "recognition.csv")
                                                                                  .read_text())}
    static = recognition[("synthetic", "static", "all")]
    assert (int(static["trials"]), int(static["hits"])) == (15, 3 * 3 + 2 * 1)     # 5 participants × 3 stimuli
    assert float(recognition[("synthetic", "static", "sad")]["rate"]) == pytest.approx(3 / 5)
    assert float(recognition[("human", "static", "happy")]["rate"]) == 1.0
    participants = _rows((report / "participants.csv").read_text())
    assert all(p["included"] == "1" and p["attention_passed"] == "1" for p in participants)
    assert (report / "report.html").is_file() and (report / "figures" / "hu.png").is_file()
    comparison = _rows((report / "validate-vs-people.csv").read_text())
    assert {(r["stimulus"], r["presentation"]) for r in comparison} == {(s, p) for s in ("0001", "0002", "0003")
                                                                         for p in ("static", "dynamic")}
    assert all(int(r["people_answers"]) == 5 for r in comparison)
    if SHOTS is not None:
        _report_picture(report)


def _report_picture(report: Path, name: str = "study-report.png") -> None:
    from PIL import Image

    with Browser() as chromium:
        page = chromium.open((report / "report.html").as_uri(), (1180, 1500))
        page.wait_for("document.readyState === 'complete' && [...document.images].every((i) => i.complete)")
        Image.fromarray(page.screenshot((1180, 1500))).save(SHOTS / name)


LIVE_DESIGN = """name = "tiny-live"
seed = 5

[stimuli]
set = "set"

[conditions]
presentation = ["dynamic"]
dynamic = "live"

[procedure]
tasks = ["identification"]
fixation_ms = 0
"""


def test_the_live_player_condition_plays_each_stimulus_and_times_the_answer_on_its_clock(built):
    """dynamic = "live": the web player (web-export --stimuli's site, in live/) draws each stimulus in the trial;
    rt is where the heard sound was at the key press, and the words are the player's word events."""
    folder, _, _ = built
    (folder / "live.toml").write_text(LIVE_DESIGN)
    made = run("study", folder / "live.toml", "-o", folder / "live-study")
    assert made.returncode == 0, made.stderr
    study = folder / "live-study"
    document = json.loads((study / "study.json").read_text())
    assert document["live"] and (study / "live" / "player.js").is_file() and (study / "live" / "stimuli.json").is_file()
    assert "importmap" not in (study / "index.html").read_text()          # the player is one bundled module
    assert not (study / "hosts" / "cognition").exists()
    lab = subprocess.Popen([sys.executable, str(study / "run-lab.py"), "--port", "0", "--no-browser", "--participant",
                            "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        url = lab.stdout.readline().split(" at ", 1)[1].split(" ", 1)[0]
        session = _answer(url, document, intended, after_the_end=True)
    finally:
        lab.terminate()
        lab.wait(timeout=30)
        lab.stdout.close()
        lab.stderr.close()
    assert session["problems"] == []
    assert outside(session["requested"], url.split("/index.html")[0], lambda u: u.startswith("blob:")) == []
    rows = _rows((study / "data" / "tiny-live_1.csv").read_bytes().decode("utf-8"))
    assert sorted(r["stimulus"] for r in rows) == ["0001", "0002", "0003"]
    for row in rows:
        assert row["media"] == "live" and row["correct"] == "1" and row["sound"] == "1" and int(row["frames"]) >= 1
        assert float(row["play_t"]) <= float(row["first_frame_t"]) <= float(row["response_t"])
        assert float(row["speech_onset_t"]) == pytest.approx(float(row["clip_start_t"]) + float(row["speech_onset_ms"]),
                                                             abs=0.002)
        words = json.loads(row["word_onsets"])            # every word shown, in time, before the key
        assert [w["word"] for w in words] == ["Moi"]
        assert float(row["play_t"]) <= words[0]["t"] <= float(row["ended_t"]) <= float(row["response_t"])
        assert float(row["rt"]) >= float(row["duration_ms"]) - 2.0


EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "study"


def _confuses_static_fear(state: dict, study: dict) -> str:
    """The paper's finding as a policy: static fear read as surprise and static surprise as fear, else the
    intended emotion; 3 for a still's intensity and 5 for a video's; naturalness 6 for people, 3 for the head."""
    if state.get("expected") or state["task"] == "identification":
        answer = intended(state, study)
        if not state.get("expected") and state["presentation"] == "static":
            answer = {"fear": "surprise", "surprise": "fear"}.get(answer, answer)
        return answer
    spec = next(t for t in study["trials"] if t["stimulus"] == state["stimulus"]
                and t["presentation"] == state["presentation"])
    if state["task"] == "rating:intensity":
        return "3" if spec["presentation"] == "static" else "5"
    return "6" if spec["source"] == "human" else "3"


def test_the_worked_example_runs_and_its_analysis_finds_what_its_participants_did(tmp_path):
    """docs/study.md's worked example (examples/study/katsyri2003.toml, with the astronaut as a human actor):
    built (its set made first), answered by four scripted participants, analysed: the static-fear confusion
    of two of them is in the confusion matrix and the dynamic − static contrast."""
    for path in EXAMPLE.iterdir():
        shutil.copyfile(path, tmp_path / path.name)
    from tests.engine.test_study_helpers import human_files

    human_files(tmp_path)
    design = tmp_path / "katsyri2003.toml"
    design.write_text(design.read_text().replace('# [human]\n# table = "actors.csv"', '[human]\ntable = "actors.csv"'))
    made = run("study", design, "-o", tmp_path / "study", "--workers", "1")
    assert made.returncode == 0, made.stderr
    study = tmp_path / "study"
    document = json.loads((study / "study.json").read_text())
    assert [c["value"] for c in document["choices"]] == ["happy", "sad", "surprise", "fear", "angry", "disgust",
                                                          "neutral", "other"]
    policies = {"1": intended, "2": _confuses_static_fear, "3": _confuses_static_fear, "4": intended}
    for participant, policy in policies.items():
        lab = subprocess.Popen([sys.executable, str(study / "run-lab.py"), "--port", "0", "--no-browser",
                                "--participant", participant], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
        try:
            url = lab.stdout.readline().split(" at ", 1)[1].split(" ", 1)[0]
            session = _answer(url, document, policy, shots=SHOTS if participant == "2" else None)
        finally:
            lab.terminate()
            lab.wait(timeout=30)
            lab.stdout.close()
            lab.stderr.close()
        assert session["problems"] == [] and session["end"]["done"] == "lab"
    report = tmp_path / "report"
    done = run("study-analyse", study / "data", "--set", study / "set", "-o", report)
    assert done.returncode == 0, done.stderr
    contrasts = {(r["contrast"], r["within"], r["emotion"], r["measure"]): r
                 for r in _rows((report / "contrasts.csv").read_text())}
    fear = contrasts[("dynamic − static", "synthetic", "fear", "hit_rate")]
    assert (float(fear["a_value"]), float(fear["b_value"])) == (0.5, 1.0)
    assert float(contrasts[("dynamic − static", "synthetic", "happy", "hit_rate")]["difference"]) == 0.0
    confusion = {(r["source"], r["presentation"], r["intended"], r["response"]): int(r["count"])
                 for r in _rows((report / "confusion.csv").read_text())}
    assert confusion[("synthetic", "static", "fear", "surprise")] == 2
    assert confusion[("synthetic", "dynamic", "fear", "fear")] == 4
    naturalness = contrasts[("synthetic − human", "static", "happy", "rating_naturalness")]
    assert float(naturalness["a_value"]) == pytest.approx(5.0) and float(naturalness["b_value"]) == pytest.approx(3.5)
    if SHOTS is not None:
        _report_picture(report, "study-example-report.png")
        for name in ("recognition.png", "confusion.png", "hu.png", "ratings.png", "validate-vs-people.png"):
            shutil.copyfile(report / "figures" / name, SHOTS / f"study-{name}")
