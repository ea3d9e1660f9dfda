"""The documentation screenshot of the timeline dock: docs/images/workbench-timeline.png.

Written into a temporary folder; to refresh the picture in the docs:

    AP_SCREENSHOT_DIR=docs/images ./bootstrap test -q tests/workbench/test_timeline_screenshot.py
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from PySide6.QtCore import Qt

import engine
from engine.speech.synthesis import Segment

SCREENSHOT_NAME = "workbench-timeline.png"
DEMO = """<commands>
  <HeadNod at="300" amplitude="60" count="2"/>
  <BrowRaise at="200" onset="250" apex="600" offset="300"/>
  <Blink at="1500"/>
  <activate parameter="jaw_open" interp="cosine">
    <key at="400" value="0"/><key at="550" value="0.35"/><key at="700" value="0.05"/>
    <key at="850" value="0.4"/><key at="1050" value="0"/>
  </activate>
</commands>
"""
PHONES = [("#", 0, 400), ("m", 400, 480), ("a", 480, 640), ("t", 640, 700), ("o", 700, 900),
          ("#", 900, 2000)]


@pytest.mark.skipif(not engine.default_model_path().exists(), reason="default head not built")
def test_screenshot_of_the_timeline_dock(make_window, qtbot, tmp_path):
    shot = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / SCREENSHOT_NAME
    window = make_window(engine.default_model_path(), size=(1280, 1000))
    demo = tmp_path / "demo.xml"
    demo.write_text(DEMO)
    assert window.timeline_dock.open_animation(demo)
    window.player.load(window.player.timeline, phones=[Segment(*p) for p in PHONES], title="demo")
    qtbot.wait(50)
    window.resizeDocks([window.timeline_dock], [340], Qt.Orientation.Vertical)
    window.playhead.set_time(0.62)
    view = window.timeline_dock.track_view
    assert set(view.track_names) == {"head_nod", "brow_raise", "eyelid_left_close", "eyelid_right_close", "jaw_open"}
    qtbot.wait(100)
    window.viewport.render_now()
    shot.parent.mkdir(parents=True, exist_ok=True)
    assert window.grab().toImage().save(str(shot))
