"""The documentation screenshot of the script panel after Say: docs/images/workbench-script-panel.png.

Writes into a temporary folder; to refresh the picture in the docs:

    AP_SCREENSHOT_DIR=docs/images ./bootstrap test tests/workbench/test_script_panel_screenshot.py
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractScrollArea

import engine

SCREENSHOT_NAME = "workbench-script-panel.png"
DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists() or shutil.which("festival") is None,
                                reason="needs the default head and Festival")


def test_screenshot_of_the_script_panel_after_say(make_window, qtbot, tmp_path):
    path = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / SCREENSHOT_NAME
    window = make_window(DEFAULT_HEAD, size=(1400, 1000))
    panel = window.script_panel
    panel.editor.setPlainText("Hyvää <Happy/> huomenta!\nMitä kuuluu? <HeadNod amplitude=\"60\"/>")
    with qtbot.waitSignal(panel.busy_changed, timeout=60000, check_params_cb=lambda busy: not busy):
        qtbot.mouseClick(panel.say_button, Qt.MouseButton.LeftButton)
    assert panel.result is not None, panel.info.text()
    player = window.player
    player.pause()
    vowel = next(p for p in player.phones if p.label == "@:")      # the long ä of "Hyvää": mouth open
    window.playhead.set_time(vowel.mid_ms / 1000 + 0.4)
    assert window.script_dock.isVisible() and player.phones
    timeline = getattr(window, "timeline_dock", None)
    if timeline is not None:                  # tall, and scrolled down to the phones under the tracks
        window.resizeDocks([timeline], [360], Qt.Orientation.Vertical)
        qtbot.wait(50)
        for area in timeline.findChildren(QAbstractScrollArea):
            bar = area.verticalScrollBar()
            bar.setValue(bar.maximum())
    window.viewport.render_now()
    qtbot.wait(100)
    path.parent.mkdir(parents=True, exist_ok=True)
    assert window.grab().save(str(path))
