"""A whole working session on a 1366×768 laptop screen, fresh settings, without moving a dock.

Painting weights with the live preview on show; importing a recording,
selecting frames by phones, running the multistage PCA and applying it;
previewing HeadNod in the library editor; playing an expression from the
gallery; saying a sentence and exporting the MP4 — each through the layout
switcher, the tools' commands and clicks on buttons that must be on show in
full (``laptop_session.py``, in a child process on an Xvfb screen of that size).
The pictures of each step are kept when ``AP_SCREENSHOT_DIR`` names a folder.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

PROJECT_ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="needs xvfb-run for a laptop-sized screen")
def test_a_whole_session_on_a_laptop_screen(tmp_path):
    folder = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path / "pictures") / "laptop-session"
    folder.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    env.pop("DISPLAY", None)
    env.pop("QT_QPA_PLATFORM", None)
    run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1366x768x24", sys.executable, "-m",
                          "tests.workbench.laptop_session", str(folder)], cwd=PROJECT_ROOT, env=env,
                         capture_output=True, text=True, timeout=900, check=False)
    assert run.returncode == 0, f"the session failed:\n{run.stdout[-3000:]}\n{run.stderr[-5000:]}"
    report = json.loads((folder / "report.json").read_text())
    assert report["screen"] == [1366, 768]
    assert set(report) >= {"painting", "mocap", "library", "gallery", "speech"}
    assert report["mocap"]["added"] and report["speech"]["mp4"][:2] == [320, 240]
