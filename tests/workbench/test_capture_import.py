"""File → Import capture stream…: a real Live Link Face take plays on the timeline as ``capture animate`` maps it."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtWidgets import QMessageBox

import engine
from engine.capture.readers import read_capture
from engine.capture.retarget import retarget
from tests.engine.capture_stream_files import LLF_MOUTH
from workbench.capture_import import import_capture_stream

DEFAULT_HEAD = engine.default_model_path()
needs_default_head = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="default head not built")


@pytest.fixture
def boxes(monkeypatch):
    shown: dict[str, list[str]] = {"warning": [], "information": []}
    for kind in shown:
        def box(parent, title, text, *args, _kind=kind, **kwargs):
            shown[_kind].append(text)
            return QMessageBox.StandardButton.Ok
        monkeypatch.setattr(QMessageBox, kind, staticmethod(box))
    return shown


@needs_default_head
def test_a_live_link_face_take_loads_into_the_player(make_window, boxes):
    window = make_window(DEFAULT_HEAD)
    file_menu = [a.objectName() or a.text() for a in window.menus["&File"].actions()]
    action = window.actions_by_id["file.import_capture"]
    assert action in window.menus["&File"].actions()
    assert window.menus["&File"].actions().index(action) < window.menus["&File"].actions().index(
        window.actions_by_id["file.quit"]), file_menu
    assert import_capture_stream(window, LLF_MOUTH)
    assert "jaw_open" in window.player.driven and "eyelid_left_close" in window.player.driven
    assert window.playhead.fps == pytest.approx(30.0)
    assert window.playhead.duration == pytest.approx(239 / 30, abs=1 / 30)
    assert any("cheekPuff" in text for text in boxes["information"])
    mapped = retarget(read_capture(LLF_MOUTH), window.document.model)
    j = mapped.parameters.index("jaw_open")
    window.playhead.set_time(4.0)
    expected = np.interp(4000.0, mapped.times_ms, mapped.values[:, j])
    assert window.document.value("jaw_open") == pytest.approx(expected, abs=1e-9)


@needs_default_head
def test_a_bad_file_is_refused_and_nothing_changes(make_window, boxes, tmp_path):
    window = make_window(DEFAULT_HEAD)
    bad = tmp_path / "bad.csv"
    bad.write_text("Timecode,BlendShapeCount,EyeBlinkLeft\n")
    assert not import_capture_stream(window, bad)
    assert len(boxes["warning"]) == 1 and "bad.csv" in boxes["warning"][0]
    assert window.player.driven == []
