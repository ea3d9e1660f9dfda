"""The jsPsych plugin and its example experiment (``examples/web/``) in a real headless Chromium.

``examples/web/make_experiment.py`` makes the example's stimulus set (real Festival), its site
(``web-export --stimuli``) and adds the plugin, jsPsych and the experiment; the site is served on
127.0.0.1 and ``experiment.html`` is run through by key presses sent over the DevTools protocol
(``Input.dispatchKeyEvent``): the space bar for the instructions, then for each trial a key while
the face speaks or after it has ended. The data jsPsych holds at the end must have one row per
stimulus with the key, an rt on the player's clock, the stimulus's id and factor levels and its
word onsets in order between the speech's start and the trial's end. ``AP_SCREENSHOT_DIR=DIR``
also writes a screenshot of a trial there (docs/images/web/jspsych-trial.jpg).
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.web_browser import CHROMIUM, Browser, outside, served

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "web"
PLUGIN = ROOT / "engine" / "web" / "jspsych" / "plugin-artificial-person.js"
VENDORED = ROOT / "engine" / "web" / "vendor" / "jspsych"
VIEWPORT = (640, 620)
STAGE = "document.querySelector('#jspsych-artificial-person')"
KEYS = {" ": ("Space", 32), "f": ("KeyF", 70), "j": ("KeyJ", 74)}
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (./bootstrap installs it)")
ENDED = "s.dataset.state === 'ended'"
SLACK_MS = 2.0       # a frame's position and the clock's zero are read a moment apart (sub-ms in practice)


def _make_experiment(*args: str | Path) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    return subprocess.run([sys.executable, str(EXAMPLE / "make_experiment.py"), *map(str, args)], capture_output=True,
                          text=True, env=env, cwd=ROOT, timeout=300, check=False)


@pytest.fixture(scope="module")
def experiment_site(tmp_path_factory):
    folder = tmp_path_factory.mktemp("jspsych")
    made = _make_experiment("-o", folder / "site", "--set", folder / "set")
    assert made.returncode == 0, made.stderr
    return folder / "site", folder / "set"


def test_the_plugin_and_jspsych_point_nowhere_outside_the_site():
    """Nothing an experiment site is given names a server: no http(s) address in the plugin or the example's
    page and script, and no source-map comment (which developer tools would fetch from unpkg) in jsPsych."""
    for path in (PLUGIN, EXAMPLE / "experiment.html", EXAMPLE / "experiment.js"):
        text = path.read_text(encoding="utf-8")
        assert "http://" not in text and "https://" not in text, path
    for path in VENDORED.rglob("*.js"):
        assert "sourceMappingURL" not in path.read_text(encoding="utf-8"), path
    assert (VENDORED / "LICENSE").is_file()


def test_a_design_that_cannot_be_made_stops_with_its_own_error(tmp_path):
    design = tmp_path / "bad.toml"
    design.write_text('[factors]\ntext = ["Pappa."]\n[output]\nkinds = ["wav", "tracks", "movie"]\n')
    made = _make_experiment("-o", tmp_path / "site", "--design", design)
    assert made.returncode == 2, made.stderr
    assert made.stderr.startswith(f"error: {design}:") and "Traceback" not in made.stderr, made.stderr
    assert not (tmp_path / "site").exists()


@pytest.mark.slow
def test_the_site_holds_the_experiment_beside_the_export(experiment_site):
    site, _ = experiment_site
    for name in ("experiment.html", "experiment.js", "embed.html", "head-in-frame.js", "plugin-artificial-person.js",
                 "index.html", "player.js", "stimuli.json", "jspsych/dist/index.browser.min.js",
                 "jspsych/css/jspsych.css", "jspsych/plugin-html-keyboard-response/dist/index.browser.min.js",
                 "jspsych/LICENSE"):
        assert (site / name).is_file(), name
    assert not (site / "jspsych" / "README.md").exists()
    assert (site / "plugin-artificial-person.js").read_bytes() == PLUGIN.read_bytes()


def _press(page, key: str) -> None:
    code, virtual = KEYS[key]
    for kind in ("keyDown", "keyUp"):
        event = {"type": kind, "key": key, "code": code, "windowsVirtualKeyCode": virtual}
        if kind == "keyDown":
            event["text"] = key
        page.browser.call("Input.dispatchKeyEvent", event, page.session)


def _wait_for_stage(page, condition: str) -> None:
    """Wait until the trial's stage (``s``) meets ``condition``; on a timeout, say what state it was in."""
    try:
        page.wait_for(f"(() => {{ const s = {STAGE}; return s !== null && ({condition}); }})()")
    except TimeoutError as exc:
        state = page.evaluate(f"{STAGE} && [{STAGE}.dataset.state, {STAGE}.dataset.words]")
        raise AssertionError(f"the trial's stage stayed {state}: {exc}") from None


def _keep_screenshot(page) -> None:
    folder = os.environ.get("AP_SCREENSHOT_DIR")
    if folder:
        from PIL import Image

        Path(folder).mkdir(parents=True, exist_ok=True)
        Image.fromarray(page.screenshot(VIEWPORT)).save(Path(folder) / "jspsych-trial.jpg", quality=90)


@pytest.fixture(scope="module")
def run_through(experiment_site):
    """Run the experiment: the odd trials answered while the face speaks (after its first word), the even ones
    after it has ended; returns the keys pressed, jsPsych's data, the page's problems and what it requested."""
    site, _ = experiment_site
    pressed = []
    with served(site) as base, Browser() as chromium:
        page = chromium.open(f"{base}/experiment.html", VIEWPORT)
        page.wait_for("document.querySelector('#jspsych-html-keyboard-response-stimulus') !== null")
        _press(page, " ")
        trials = len(json.loads((site / "stimuli.json").read_text())["stimuli"])
        for number in range(trials):
            if number % 2 == 0:      # a word shown (or, on a machine too busy to draw between them, the end)
                _wait_for_stage(page, f"(s.dataset.state === 'playing' && Number(s.dataset.words) >= 1) || {ENDED}")
                if number == 0:
                    _keep_screenshot(page)
                    box = f"{STAGE}.querySelector('canvas').getBoundingClientRect()"
                    shown = page.evaluate(f"(() => {{ const r = {box}; return [r.width, r.height]; }})()")
                    assert shown == [300, 400]           # the example's canvas_size
                    # the sound runs without a gesture here, so the head shows with no "Click to start" over it
                    assert page.evaluate(f"getComputedStyle({STAGE}.querySelector('button')).display") == "none"
            else:
                _wait_for_stage(page, ENDED)
            key = "fj"[number % 2]
            _press(page, key)
            pressed.append(key)
            page.wait_for(f"{STAGE} === null || {STAGE}.dataset.state === 'done'")
        page.wait_for("document.querySelector('#data') !== null")
        # every player's frame loop has ended with its trial: no frame is asked for once the data are shown
        frames_asked = page.evaluate("""new Promise((resolve) => {
            let asked = 0;
            const ask = window.requestAnimationFrame.bind(window);
            window.requestAnimationFrame = (callback) => { asked += 1; return ask(callback); };
            setTimeout(() => resolve(asked), 1500);
        })""")
        data = json.loads(page.evaluate("jsPsych.data.get().json()"))
        shown_csv = page.evaluate("document.querySelector('#data').textContent")
        warnings = [e["args"] for e in page.mine("Runtime.consoleAPICalled") if e["type"] == "warning"]
        return {"pressed": pressed, "data": data, "csv": shown_csv, "problems": page.problems(), "warnings": warnings,
                "requested": page.requested(), "base": base, "frames_asked": frames_asked}


@pytest.mark.slow
@needs_chromium
def test_the_experiment_loads_only_from_its_site_and_logs_no_error(run_through):
    assert run_through["problems"] == [] and run_through["warnings"] == []
    requested = run_through["requested"]
    base = run_through["base"]
    assert outside(requested, base) == []
    assert f"{base}/jspsych/dist/index.browser.min.js" in requested and f"{base}/head.glb" in requested
    assert run_through["frames_asked"] == 0


@pytest.mark.slow
@needs_chromium
def test_each_trial_records_its_key_stimulus_levels_and_times(run_through, experiment_site):
    _, stimulus_set = experiment_site
    with (stimulus_set / "manifest.csv").open(newline="") as table:
        manifest = {row["id"]: row for row in csv.DictReader(table)}
    rows = [row for row in run_through["data"] if row["trial_type"] == "artificial-person"]
    assert sorted(row["stimulus"] for row in rows) == sorted(manifest)              # each stimulus once
    assert [row["response"] for row in rows] == run_through["pressed"]
    print(f"\n{sum(r['ended_t'] is None for r in rows)} of {len(rows)} trials answered while the face spoke; "
          f"frames drawn per trial: {[r['frames'] for r in rows]}; the sound's clock against the page's, spread "
          f"per trial (ms): {[round(r['clock_spread_ms'], 2) for r in rows]}; play() to the clip's start heard "
          f"(ms): {[round(r['clip_start_t'] - r['play_t'], 1) for r in rows]}")
    for number, row in enumerate(rows):
        listed = manifest[row["stimulus"]]
        assert (row["text"], row["av_offset_ms"]) == (listed["text"], listed["av_offset_ms"])
        assert row["sound"] is True and row["frames"] >= 1
        assert row["speech_onset_ms"] == float(listed["speech_onset_ms"])
        assert row["rt_speech"] == pytest.approx(row["rt"] - row["speech_onset_ms"])
        assert row["speech_onset_t"] == pytest.approx(row["clip_start_t"] + row["speech_onset_ms"])
        end = row["ended_t"] if row["ended_t"] is not None else row["response_t"]
        words = row["word_onsets"]
        onsets = [float(ms) for ms in listed["word_onsets_ms"].split(";")]
        assert words and [w["word"] for w in words] == listed["words"].split(";")[:len(words)]
        assert [w["start_ms"] for w in words] == pytest.approx(onsets[:len(words)], abs=1e-3)
        times = [w["t"] for w in words]
        assert row["play_t"] <= times[0] and times == sorted(times) and times[-1] <= end
        # the key came after the last word shown: on the player's clock too
        assert row["rt"] >= words[-1]["start_ms"] - SLACK_MS
        if row["ended_t"] is None:                       # answered while the face spoke: the key ended the trial
            assert number % 2 == 0
            assert 0 <= row["rt"] < row["duration_ms"]
        else:                                            # answered after the end: every word seen, rt after it
            assert len(words) == len(onsets)
            assert row["response_t"] >= row["ended_t"]
            assert row["rt"] >= row["duration_ms"] - SLACK_MS
        assert row["correct"] == (row["response"] == row["correct_key"])


@pytest.mark.slow
@needs_chromium
def test_the_data_are_shown_as_csv_at_the_end(run_through):
    shown = list(csv.DictReader(run_through["csv"].splitlines()))
    assert len(shown) == len([r for r in run_through["data"] if r["trial_type"] == "artificial-person"])
    assert {"stimulus", "response", "rt", "text", "av_offset_ms", "word_onsets", "clip_start_t"} <= set(shown[0])
    assert json.loads(shown[0]["word_onsets"])[0]["word"]


def jspsych_page(title: str, script: str) -> str:
    """A page of the site running ``script`` with jsPsych and the plugin loaded."""
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title><link rel="icon" href="data:,">
<link rel="stylesheet" href="jspsych/css/jspsych.css">
<script src="jspsych/dist/index.browser.min.js"></script>
<script src="plugin-artificial-person.js"></script>
</head><body><script>
{script}
</script></body></html>
"""


NO_GESTURE_PAGE = jspsych_page("a trial first", """const jsPsych = initJsPsych();
jsPsych.run([{ type: jsPsychArtificialPerson, stimulus: "0001", choices: ["f"], trial_ends_after_stimulus: true }]);""")


def _click(page, selector: str) -> None:
    x, y = page.evaluate(f"(() => {{ const r = document.querySelector({json.dumps(selector)}).getBoundingClientRect();"
                         " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
    for kind in ("mousePressed", "mouseReleased"):
        page.browser.call("Input.dispatchMouseEvent",
                          {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1}, page.session)


@pytest.mark.slow
@needs_chromium
def test_where_sound_needs_a_gesture_the_head_waits_for_a_click_or_plays_after_the_instructions_key(
        experiment_site, monkeypatch):
    """Chromium's own autoplay policy (the tests' flag that lifts it left out): a trial on a page the participant
    has not touched waits, still, under "Click to start", and plays with sound once clicked; in the example the
    key that leaves the instructions is the gesture, and the first trial plays at once."""
    import tests.web_browser

    monkeypatch.setattr(tests.web_browser, "FLAGS", [f for f in tests.web_browser.FLAGS
                                                     if not f.startswith("--autoplay-policy")])
    site, _ = experiment_site
    (site / "no-gesture.html").write_text(NO_GESTURE_PAGE, encoding="utf-8")
    with served(site) as base, Browser() as chromium:
        page = chromium.open(f"{base}/no-gesture.html", VIEWPORT)
        _wait_for_stage(page, "s.dataset.state === 'waiting'")
        assert page.evaluate(f"getComputedStyle({STAGE}.querySelector('button')).display") == "block"
        _click(page, "#jspsych-artificial-person button")
        page.wait_for("jsPsych.data.get().count() === 1")
        row = json.loads(page.evaluate("jsPsych.data.get().json()"))[0]
        assert row["sound"] is True and row["response"] is None and row["rt"] is None
        assert row["ended_t"] is not None and len(row["word_onsets"]) == 3
        assert row["play_t"] <= row["word_onsets"][0]["t"]       # the play that counts is the one after the click
        assert page.problems() == []

        page = chromium.open(f"{base}/experiment.html", VIEWPORT)
        page.wait_for("document.querySelector('#jspsych-html-keyboard-response-stimulus') !== null")
        _press(page, " ")
        _wait_for_stage(page, "s.dataset.state === 'playing' || s.dataset.state === 'ended'")
        assert page.evaluate(f"getComputedStyle({STAGE}.querySelector('button')).display") == "none"
        assert page.problems() == []


@pytest.mark.slow
@needs_chromium
def test_a_page_of_another_framework_plays_a_stimulus_in_a_frame_on_its_own_clock(experiment_site):
    """The pattern docs/web-jspsych.md gives for PsychoJS: ``examples/web/head-in-frame.js`` opens a stimulus
    in a same-origin iframe and plays it; its events come back on the outer page's ``performance.now()``
    (the frame's own clock starts later: without the shift they would fall before the call)."""
    site, _ = experiment_site
    listed = json.loads((site / "stimuli.json").read_text())["stimuli"][1]
    with served(site) as base, Browser() as chromium:
        page = chromium.open(f"{base}/embed.html?stimulus={listed['id']}", VIEWPORT)
        page.wait_for("window.headReady !== undefined")
        shift = page.evaluate("window.headReady.then((head) => head.ours(0))")
        played = page.evaluate("(async () => { const before = performance.now(); const record = await head.play();"
                               " return { before, record, after: performance.now() }; })()")
        assert page.problems() == []
        assert outside(page.requested(), base) == [] and f"{base}/stimuli/{listed['id']}.json" in page.requested()
    record = played["record"]
    words = listed["manifest"]["words"].split(";")
    assert record["sound"] is True and [w["word"] for w in record["word_onsets"]] == words
    times = [record["play_t"], *(w["t"] for w in record["word_onsets"]), record["ended_t"]]
    assert played["before"] <= times[0] and times == sorted(times) and times[-1] <= played["after"]
    assert shift > 0 and record["play_t"] - shift < played["before"]        # the shift is what puts them inside


def test_the_plugin_and_jspsych_are_package_data():
    """An installed toolkit carries the plugin and the vendored jsPsych (make_experiment.py copies them from the
    package): pyproject's package-data patterns reach every file under engine/web/jspsych and its vendor folder."""
    import tomllib

    patterns = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["engine"]
    shipped = {path for pattern in patterns for path in (ROOT / "engine").glob(pattern) if path.is_file()}
    needed = {path for folder in (PLUGIN.parent, VENDORED) for path in folder.rglob("*") if path.is_file()}
    assert PLUGIN in needed and needed <= shipped, sorted(str(p) for p in needed - shipped)


OPTIONS_PAGE = jspsych_page("the plugin's options", """const jsPsych = initJsPsych();
jsPsych.run([
  { type: jsPsychArtificialPerson, stimulus: "0001", choices: "NO_KEYS", trial_duration: 600 },
  { type: jsPsychArtificialPerson, stimulus: "0003", choices: ["f"], response_ends_trial: false },
  { type: jsPsychArtificialPerson, stimulus: "no-such-stimulus" },
]);""")


@pytest.mark.slow
@needs_chromium
def test_trial_duration_a_response_that_does_not_end_the_trial_and_a_missing_stimulus(experiment_site):
    site, _ = experiment_site
    (site / "options.html").write_text(OPTIONS_PAGE, encoding="utf-8")
    with served(site) as base, Browser() as chromium:
        page = chromium.open(f"{base}/options.html", VIEWPORT)
        _wait_for_stage(page, "Number(s.dataset.words) >= 1 && jsPsych.getProgress().current_trial_global === 1")
        _press(page, "f")
        page.wait_for("jsPsych.data.get().count() === 3")
        timed, answered, missing = json.loads(page.evaluate("jsPsych.data.get().json()"))
        problems = page.problems()
    # NO_KEYS and no end after the stimulus: only trial_duration can have ended the first trial
    assert timed["stimulus"] == "0001" and timed["response"] is None and timed["rt"] is None
    # the key did not end the second: it ran to the stimulus's end, every word shown
    assert answered["response"] == "f" and answered["ended_t"] is not None and len(answered["word_onsets"]) == 3
    assert answered["rt"] >= answered["word_onsets"][0]["start_ms"] - SLACK_MS
    # an id the site does not list: the trial ends at once, saying so in its data and on the console
    assert "no-such-stimulus" in missing["error"]
    assert len(problems) == 1 and "no-such-stimulus" in problems[0], problems
