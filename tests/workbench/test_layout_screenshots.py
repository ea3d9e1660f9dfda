"""The documentation screenshots of the task layouts: docs/images/layout-<layout>-<W>x<H>.png.

Each screen size runs ``layout_screenshots.py`` in a child process under an
Xvfb server of that size (one pytest process has one screen). Writes into a
temporary folder; to refresh the pictures in the docs:

    AP_SCREENSHOT_DIR=docs/images ./bootstrap test tests/workbench/test_layout_screenshots.py
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from PySide6.QtGui import QImage

import engine
from tests.workbench.layout_screenshots import SHOTS

PROJECT_ROOT = Path(__file__).resolve().parents[2]
pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("xvfb-run") is None or shutil.which("festival") is None
                                 or not engine.default_model_path().exists(),
                                 reason="needs xvfb-run, Festival and the default head")]


@pytest.mark.parametrize("width, height", [(1366, 768), (1920, 1080)])
def test_screenshots_of_every_task_layout(width, height, tmp_path):
    folder = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path).resolve()
    folder.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    env.pop("DISPLAY", None)
    env.pop("QT_QPA_PLATFORM", None)
    run = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {width}x{height}x24", sys.executable, "-m",
                          "tests.workbench.layout_screenshots", str(folder), str(width), str(height)],
                         cwd=PROJECT_ROOT, env=env, capture_output=True, text=True, timeout=900, check=False)
    assert run.returncode == 0, f"the screenshots failed:\n{run.stdout}\n{run.stderr}"
    for shot in SHOTS:
        image = QImage(str(folder / f"layout-{shot}-{width}x{height}.png"))
        assert not image.isNull(), shot
        assert image.width() <= width and image.height() <= height, f"{shot}: larger than the screen"
