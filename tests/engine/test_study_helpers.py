"""What the study tests share: a tiny real stimulus set, a human comparison, a study design, and a participant.

The set is made by the real stimulus maker (Festival, the renderer, ffmpeg): "Moi." with Happy, Sad and no
expression, as a still, a video, and tracks and sound for the live player, at 160×120 (about ten seconds).
The human comparison is scikit-image's astronaut (NASA, public domain), smiling: a photograph and a
one-second video made of it with ffmpeg. A :class:`Participant` answers a study in headless Chromium by key
presses only, sent over the DevTools protocol, following a fixed policy.

This module holds no tests.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from tests.engine.cli_runner import made_set

SET_DESIGN = """[factors]
text = ["Moi."]
expression = ["Happy", "Sad", "none"]

[output]
kinds = ["png", "mp4", "tracks", "wav"]
size = "160x120"
fps = 25
"""

STUDY_DESIGN = """name = "tiny"
title = "Faces (a test)"
seed = 2003

[stimuli]
set = "set"

[human]
table = "actors.csv"

[procedure]
practice = 1
attention_checks = 1
fixation_ms = 200
gap_ms = 100

[pages]
consent = "consent.md"
instructions = "Choose the emotion the face shows, then rate it."
"""

CONSENT = "# Consent\n\nYou will see a few faces. You may stop **at any time**.\n\n- no names are kept\n"

KEYS: dict[str, tuple[str, int]] = {" ": ("Space", 32)}
KEYS.update({c: (f"Digit{c}", 48 + int(c)) for c in "0123456789"})
KEYS.update({c: (f"Key{c.upper()}", ord(c.upper())) for c in "abcdefghijklmnopqrstuvwxyz"})

STATE = """(() => {
  const s = document.querySelector('#ap-stage'), q = document.querySelector('#ap-question');
  const p = document.querySelector('#ap-page'), f = document.querySelector('#ap-participant');
  const j = window.APStudy && window.APStudy.jsPsych, e = document.querySelector('.ap-error');
  return {trial: j ? j.getProgress().current_trial_global : -1, page: p ? p.dataset.page : null,
          form: Boolean(f), task: q ? q.dataset.task || null : null, ask: q ? q.dataset.ask || null : null,
          expected: q ? q.dataset.expected || null : null, stimulus: s ? s.dataset.stimulus : null,
          presentation: s ? s.dataset.presentation : null, state: s ? s.dataset.state : null,
          ended: s ? s.dataset.ended === "1" : false,
          done: (document.body && document.body.dataset.apDone) || null, error: e ? e.textContent : null};
})()"""


def make_study_inputs(folder: Path) -> Path:
    """The set (``folder/set``), the human comparison (``folder/actors/``, ``actors.csv``), the consent page and
    the study design (``folder/study.toml``); returns the design."""
    made_set(folder, SET_DESIGN)
    human_files(folder)
    (folder / "consent.md").write_text(CONSENT)
    (folder / "study.toml").write_text(STUDY_DESIGN)
    return folder / "study.toml"


def human_files(folder: Path) -> None:
    """``folder/actors/``: the astronaut smiling, a photograph and a one-second video; ``folder/actors.csv``."""
    actors = folder / "actors"
    actors.mkdir()
    from PIL import Image
    from skimage import data

    Image.fromarray(data.astronaut()).resize((240, 240)).save(actors / "astronaut-happy.png")
    subprocess.run([shutil.which("ffmpeg") or "ffmpeg", "-v", "error", "-y", "-loop", "1", "-i",
                    str(actors / "astronaut-happy.png"), "-t", "1", "-r", "25", "-pix_fmt", "yuv420p",
                    "-c:v", "libx264", str(actors / "astronaut-happy.mp4")], check=True, timeout=60)
    (folder / "actors.csv").write_text("file,emotion,presentation,actor\n"
                                       "actors/astronaut-happy.png,happy,static,astronaut\n"
                                       "actors/astronaut-happy.mp4,Happy,dynamic,astronaut\n")


Policy = Callable[[dict[str, Any], dict[str, Any]], str]
"""``policy(state, study) → the answer's value`` (a choice's value, or a scale point as text)."""


def intended(state: dict[str, Any], study: dict[str, Any]) -> str:
    """The emotion the stimulus was meant to show; 4 on every scale; the answer an attention check asks for."""
    if state.get("expected"):
        return state["expected"]
    if state["task"] == "identification":
        spec = next(t for t in study["trials"] if t["stimulus"] == state["stimulus"]
                    and t["presentation"] == state["presentation"])
        return spec["intended"]
    return "4"


def always_happy(state: dict[str, Any], study: dict[str, Any]) -> str:
    """Happy for every face, 6 on every scale; the answer an attention check asks for."""
    if state.get("expected"):
        return state["expected"]
    return "happy" if state["task"] == "identification" else "6"


class Participant:
    """Answers the study open in ``page`` by key presses, one per question or page, until its debrief."""

    def __init__(self, page: Any, study: dict[str, Any], policy: Policy, shots: Path | None = None,
                 after_the_end: bool = False) -> None:
        self.page = page
        self.after_the_end = after_the_end
        """Answer a dynamic stimulus only once it has played to its end (else as soon as it shows)."""
        self.study = study
        self.policy = policy
        self.keys = {c["value"]: c["key"] for c in study["choices"]}
        self.pressed: list[str] = []
        self.shots = shots
        self.shot: set[str] = set()

    def press(self, key: str) -> None:
        code, virtual = KEYS[key]
        for kind in ("keyDown", "keyUp"):
            event: dict[str, Any] = {"type": kind, "key": key, "code": code, "windowsVirtualKeyCode": virtual}
            if kind == "keyDown":
                event["text"] = key
            self.page.browser.call("Input.dispatchKeyEvent", event, self.page.session)
        self.pressed.append(key)

    def run(self, participant: str | None = None, seconds: float = 600.0) -> dict[str, Any]:
        """Answer everything; returns the last state (its ``done``: how the data were saved)."""
        handled: set[tuple[Any, ...]] = set()
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            state = self.page.evaluate(STATE)
            if state.get("error"):
                raise AssertionError(f"the study shows an error: {state['error']}; {self.page.problems()}")
            if state.get("page") in ("debrief", "declined") and state.get("done"):
                self._keep(state)
                return state
            if state.get("form") and participant is not None and ("form",) not in handled:
                handled.add(("form",))
                self.page.evaluate(f"(() => {{ const f = document.querySelector('#ap-participant'); "
                                   f"f.querySelector('input').value = {json.dumps(participant)}; "
                                   f"f.requestSubmit(); }})()")
                continue
            ident = (state.get("trial"), state.get("page"), state.get("ask"))
            key = self._key(state)
            if key is None or ident in handled:
                time.sleep(0.03)
                continue
            self._keep(state)
            handled.add(ident)
            self.press(key)
        raise AssertionError(f"the study did not end within {seconds:g} s: {self.page.evaluate(STATE)}")

    def _key(self, state: dict[str, Any]) -> str | None:
        page = state.get("page")
        if page == "consent":
            return "y"
        if page in ("instructions", "practice_end"):
            return " "
        task = state.get("task")
        if not task or state.get("state") not in ("showing", "hidden"):
            return None
        if self.after_the_end and state.get("presentation") == "dynamic" and not state.get("ended"):
            return None
        answer = self.policy(state, self.study)
        if task == "identification":
            return self.keys[answer]
        scale = next(s for s in self.study["scales"] if s["name"] == task.split(":", 1)[1])
        return scale["keys"][int(answer) - scale["min"]]

    def _keep(self, state: dict[str, Any]) -> None:
        """Screenshots of what the participant sees, once each (AP_SCREENSHOT_DIR)."""
        if self.shots is None:
            return
        name = None
        if (state.get("stimulus") or "").startswith("human"):
            return
        if state.get("page") in ("consent", "debrief"):
            name = state["page"]
        elif state.get("task") == "identification" and not state.get("expected") and state.get("presentation"):
            name = f"trial-{state['presentation']}"
        elif (state.get("task") or "").startswith("rating:"):
            name = "rating"
        if name is None or name in self.shot:
            return
        self.shot.add(name)
        from PIL import Image

        if name.startswith("trial-dynamic"):
            time.sleep(0.4)                   # a frame or two into the clip
        self.shots.mkdir(parents=True, exist_ok=True)
        Image.fromarray(self.page.screenshot(SCREEN)).save(self.shots / f"study-{name}.png")


SCREEN = (960, 640)
