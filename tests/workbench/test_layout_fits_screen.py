"""The window fits laptop and desktop screens, whatever docks are open.

One pytest process has one screen, so each size runs the workbench in a child
process under an Xvfb server of that size (``layout_fit_probe.py``), with
fresh settings: it opens every dock in every task layout and reopens the
window from a larger screen's geometry, and every time the window's frame must
lie inside the screen's available geometry.
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
SCREENS = [(1366, 768), (1600, 1000), (1920, 1080)]


def _outside(frame: list[int], available: list[int]) -> bool:
    x, y, w, h = frame
    ax, ay, aw, ah = available
    return x < ax or y < ay or x + w > ax + aw or y + h > ay + ah


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="needs xvfb-run for a screen of each size")
@pytest.mark.parametrize("width, height", SCREENS)
def test_every_dock_in_every_layout_fits_the_screen(width, height, tmp_path):
    report = tmp_path / "report.json"
    env = dict(os.environ, XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    env.pop("DISPLAY", None)
    env.pop("QT_QPA_PLATFORM", None)
    run = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {width}x{height}x24", sys.executable, "-m",
                          "tests.workbench.layout_fit_probe", str(report)], cwd=PROJECT_ROOT, env=env,
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, f"the probe failed:\n{run.stdout}\n{run.stderr}"
    found = json.loads(report.read_text())
    available, steps = found["available"], found["steps"]
    assert available[2:] == [width, height]
    outside = [f"{what}: frame {w}×{h} at {x},{y}" for what, (x, y, w, h) in steps
               if _outside([x, y, w, h], available)]
    assert not outside, f"off a {width}×{height} screen:\n" + "\n".join(outside)
    assert len(steps) > 5 * 4, "every layout was tried, and every dock opened in it"
