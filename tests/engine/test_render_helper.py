"""Videos drawn by two processes are the videos one process draws, byte for byte (issue 20: speed).

:mod:`engine.outputs.render_helper` forks a second renderer that draws every
other frame, only from a process with one thread and no Qt — not this test
runner, so each video is written by ``tests/engine/render_helper_run.py`` in
a fresh process: with one process and with two (``AP_RENDER_PROCESSES``),
compared by the files' SHA-256, and with the helper killed in the middle of
the video (the writer draws the rest itself; the file is still the same).
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
import threading

import pytest

from engine.outputs import render_helper
from engine.outputs.render_helper import MIN_FRAMES, helper_wanted
from tests.engine.render_helper_run import FRAMES

pytestmark = pytest.mark.slow
ROOT = __file__.rsplit("/tests/", 1)[0]


def write(tmp_path, mode: str) -> tuple[str, dict]:
    path = tmp_path / f"{mode}.mp4"
    env = {k: v for k, v in os.environ.items() if k != "AP_RENDER_PROCESSES"}
    run = subprocess.run([sys.executable, "-m", "tests.engine.render_helper_run", str(path), mode], cwd=ROOT,
                         env=env, capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr
    seen = json.loads(run.stdout.strip().splitlines()[-1])
    assert seen["frames"] == FRAMES
    return hashlib.sha256(path.read_bytes()).hexdigest(), seen


def test_two_processes_write_the_video_one_process_writes(tmp_path):
    one, alone = write(tmp_path, "one")
    two, helped = write(tmp_path, "two")
    assert alone["pids"] == [] and len(helped["pids"]) == 1
    assert helped["answers"] == [True] * (FRAMES // 2)          # the helper drew every other frame
    assert one == two
    with pytest.raises(ProcessLookupError):
        os.kill(helped["pids"][0], 0)                            # reaped by the writer: no such process


def test_a_helper_killed_mid_video_leaves_the_rest_to_the_writer(tmp_path):
    one, _ = write(tmp_path, "one")
    killed, seen = write(tmp_path, "kill")
    answers = seen["answers"]
    # what it wrote before it died is used; asked once more it has nothing, and is asked no more
    assert answers[-1] is False and all(answers[:-1]) and 10 <= len(answers) < FRAMES // 2
    assert one == killed


def test_when_a_helper_is_used(monkeypatch):
    monkeypatch.delenv("AP_RENDER_PROCESSES", raising=False)
    monkeypatch.setattr(threading, "active_count", lambda: 1)
    monkeypatch.delitem(sys.modules, "PySide6.QtCore", raising=False)
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 2)
    assert helper_wanted(MIN_FRAMES) and not helper_wanted(MIN_FRAMES - 1)
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 1)
    assert not helper_wanted(1000)
    monkeypatch.setenv("AP_RENDER_PROCESSES", "1")
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 8)
    assert not helper_wanted(1000)
    monkeypatch.setenv("AP_RENDER_PROCESSES", "2")
    assert helper_wanted(2)
    monkeypatch.setattr(threading, "active_count", lambda: 2)     # another thread: never fork
    assert not helper_wanted(1000)
    monkeypatch.setattr(threading, "active_count", lambda: 1)
    monkeypatch.setitem(sys.modules, "PySide6.QtCore", object())  # a Qt application: never fork
    assert not helper_wanted(1000)
