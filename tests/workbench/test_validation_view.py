"""Validate from the workbench: the gallery judges a face it plays, the script panel the utterance it said.

Real windows, real clicks, the real observers (dlib, FER2013) and, for the script panel, real Festival.
"""

from __future__ import annotations

import shutil

import pytest
from PySide6.QtCore import Qt

import engine
from tests.workbench.test_script_panel import say_and_wait

DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built")


@pytest.fixture
def head_window(make_window):
    return make_window(DEFAULT_HEAD)


def _verdict_dialog(qtbot, owner):
    qtbot.waitUntil(lambda: getattr(owner, "verdict_dialog", None) is not None, timeout=120000)
    dialog = owner.verdict_dialog
    assert dialog.isVisible()
    return dialog


@pytest.mark.slow
def test_the_gallery_judges_the_face_it_played(head_window, qtbot, tmp_path):
    window = head_window
    window.actions_by_id["library.gallery"].trigger()
    gallery = window.expression_gallery
    item = gallery.items["Happy"]
    view = item.listWidget()
    view.scrollToItem(item)
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=view.visualItemRect(item).center())
    assert gallery.last_preview == "Happy"
    qtbot.mouseClick(gallery.validate_button, Qt.MouseButton.LeftButton)
    dialog = _verdict_dialog(qtbot, gallery)
    verdict = dialog.verdict
    assert verdict.status == "ok" and verdict.faces == 1
    assert verdict.intended.emotion == "happy"
    assert sum(bar.value() for bar in dialog.bars.values()) == pytest.approx(1000, abs=8)
    assert dialog.bars[verdict.judged].value() == max(bar.value() for bar in dialog.bars.values())
    assert "judged" in dialog.summary.text() and "face found" in dialog.summary.text()
    report = dialog.save_report(str(tmp_path / "happy.html"))
    assert report is not None and "data:image/png;base64," in report.read_text(encoding="utf-8")
    dialog.grab().save(str(tmp_path / "verdict.png"))


def test_validate_without_a_face_played_says_what_to_do(head_window):
    gallery = head_window.expression_gallery
    assert gallery.validate() is None
    assert "Click a face first" in head_window.statusBar().currentMessage()


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
def test_the_script_panel_judges_the_utterance_frame_by_frame(head_window, qtbot):
    panel = say_and_wait(qtbot, head_window, "Pappa ampui pallon.")
    assert panel.validate_button.isEnabled()
    qtbot.mouseClick(panel.validate_button, Qt.MouseButton.LeftButton)
    dialog = _verdict_dialog(qtbot, panel)
    verdict = dialog.verdict
    assert verdict.kind == "video" and verdict.frames > 20 and verdict.frames_lost == 0
    assert verdict.intended.emotion == "neutral"                   # no expression in the text
    assert verdict.lips is not None and verdict.lips.closures_intended >= 2   # p, p, p
    assert verdict.lips.closures_seen == verdict.lips.closures_intended
    assert verdict.lips.r > 0.7
    assert "lips against the engine's" in dialog.summary.text()
