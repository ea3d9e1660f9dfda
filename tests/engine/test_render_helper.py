"""Videos drawn by two processes are the videos one process draws, byte for byte (issue 20: speed).

:mod:`engine.outputs.render_helper` forks a second renderer that draws every
other frame. These tests write the same video with one process and with two
(``AP_RENDER_PROCESSES``) and compare the files' SHA-256, and kill the helper
in the middle of a video: the writer draws the rest itself and the file is
still the same.
"""

from __future__ import annotations

import hashlib
import os
import signal

import numpy as np
import pytest

import engine
from engine.outputs import render_helper
from engine.outputs.render_helper import MIN_FRAMES, RenderHelper, helper_wanted
from engine.outputs.video_writer import write_video

pytestmark = pytest.mark.slow
FRAMES = MIN_FRAMES + 11            # odd: the helper draws one frame fewer than the writer


def sha256(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def speak_a(tmp_path, name, monkeypatch, processes: str):
    monkeypatch.setenv("AP_RENDER_PROCESSES", processes)
    head = engine.load_model()
    times = np.arange(FRAMES) * (1000 / 30)
    values = np.column_stack([0.4 * (1 + np.sin(times / 150)) / 2, 0.2 * np.sin(times / 400)])
    audio = (0.1 * np.sin(np.arange(int(16000 * FRAMES / 30)) / 5)).astype(np.float32)
    path = tmp_path / f"{name}.mp4"
    stats = write_video(path, head, times, values, ["jaw_open", "head_turn"], fps=30, audio=audio,
                        sample_rate=16000, size=(160, 120))
    assert stats.frames == FRAMES
    return path


def test_two_processes_write_the_video_one_process_writes(tmp_path, monkeypatch):
    one = speak_a(tmp_path, "one", monkeypatch, "1")
    two = speak_a(tmp_path, "two", monkeypatch, "2")
    assert sha256(one) == sha256(two)


def test_a_helper_killed_mid_video_leaves_the_rest_to_the_writer(tmp_path, monkeypatch):
    one = speak_a(tmp_path, "one", monkeypatch, "1")
    answers = []
    original = RenderHelper.frame

    def frame(self, n):
        if len(answers) == 10:                                 # the helper is killed after ten of its frames
            os.kill(self.pid, signal.SIGKILL)
        answers.append(original(self, n))
        return answers[-1]

    monkeypatch.setattr(RenderHelper, "frame", frame)
    two = speak_a(tmp_path, "two", monkeypatch, "2")
    # what it had written before it died is used; then it is asked once more (nothing) and never again
    assert answers[-1] is None and all(a is not None for a in answers[:-1]) and len(answers) < FRAMES // 2
    assert sha256(one) == sha256(two)


def test_the_helper_ends_with_the_video(tmp_path, monkeypatch):
    started = []
    original = RenderHelper.__init__

    def init(self, *args, **kwargs):
        original(self, *args, **kwargs)
        started.append(self.pid)

    monkeypatch.setattr(RenderHelper, "__init__", init)
    speak_a(tmp_path, "two", monkeypatch, "2")
    assert len(started) == 1
    with pytest.raises(ChildProcessError):
        os.waitpid(started[0], os.WNOHANG)                     # reaped: no process of ours is left


def test_when_a_helper_is_used(monkeypatch):
    monkeypatch.delenv("AP_RENDER_PROCESSES", raising=False)
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 2)
    assert helper_wanted(MIN_FRAMES) and not helper_wanted(MIN_FRAMES - 1)
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 1)
    assert not helper_wanted(1000)
    monkeypatch.setenv("AP_RENDER_PROCESSES", "1")
    monkeypatch.setattr(render_helper.os, "cpu_count", lambda: 8)
    assert not helper_wanted(1000)
    monkeypatch.setenv("AP_RENDER_PROCESSES", "2")
    assert helper_wanted(2)
