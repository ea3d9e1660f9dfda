"""Edit → Undo / Redo in the real window: menu texts, shortcuts, redraws and the modified marker."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QKeySequence

from tests.workbench.workbench_model_state import model_state
from workbench.document.undo_commands import RemoveParameterCommand, RenameParameterCommand, WeightsChangedCommand


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window


def _paint(window, name="jaw_open", weight=1.0, stroke_id=None):
    """Scripted stroke: every skin vertex below the eyes gets ``weight``."""
    model = window.document.model
    skin = model.part_vertices("skin")
    dab = skin[model.vertices[skin, 1] < 0]
    window.document.push(WeightsChangedCommand(window.document, name, dab, np.full(len(dab), weight),
                                               stroke_id=stroke_id))
    return dab


def test_undo_and_redo_actions_name_the_edit(window):
    undo, redo = window.actions_by_id["edit.undo"], window.actions_by_id["edit.redo"]
    assert undo.shortcut() == QKeySequence(QKeySequence.StandardKey.Undo)
    assert redo.shortcut() == QKeySequence(QKeySequence.StandardKey.Redo)
    assert undo in window.menus["&Edit"].actions() and redo in window.menus["&Edit"].actions()
    assert not undo.isEnabled() and not redo.isEnabled()
    assert undo.text() == "&Undo"

    _paint(window)
    assert undo.isEnabled() and undo.text() == "&Undo Paint weights"
    assert not redo.isEnabled()
    undo.trigger()
    assert redo.isEnabled() and redo.text() == "&Redo Paint weights"
    assert not undo.isEnabled() and undo.text() == "&Undo"
    assert window.statusBar().currentMessage() == "Undone: Paint weights"
    redo.trigger()
    assert window.statusBar().currentMessage() == "Redone: Paint weights"


def test_undo_redraws_the_viewport_exactly(window):
    document = window.document
    model = document.model
    original = model_state(model)
    document.set_values({"jaw_open": 0.8})
    shown_before = window.viewport.displayed_points()
    np.testing.assert_array_equal(shown_before, model.deform(document.values))

    _paint(window)
    painted = window.viewport.displayed_points()
    assert not np.array_equal(painted, shown_before)          # more of the face follows the jaw now
    np.testing.assert_array_equal(painted, model.deform(document.values))

    window.actions_by_id["edit.undo"].trigger()
    assert model_state(model) == original
    np.testing.assert_array_equal(window.viewport.displayed_points(), shown_before)
    window.actions_by_id["edit.redo"].trigger()
    np.testing.assert_array_equal(window.viewport.displayed_points(), painted)


def test_keyboard_shortcuts_undo_and_redo(window, qtbot):
    model = window.document.model
    original = model_state(model)
    _paint(window)
    painted = model_state(model)
    window.activateWindow()
    qtbot.waitActive(window)
    # Through the QWindow, as the window system delivers keys, so Qt's shortcut map sees them.
    qtbot.keyClick(window.windowHandle(), Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier)
    assert model_state(model) == original
    qtbot.keyClick(window.windowHandle(), Qt.Key.Key_Z,
                   Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier)
    assert model_state(model) == painted


def test_the_parameter_panel_follows_tree_edits_and_their_undo(window):
    document = window.document
    panel = window.parameter_panel
    document.set_value("jaw_open", 0.5)
    document.push(RenameParameterCommand(document, "jaw_open", "jaw_drop"))
    assert list(panel.rows) == ["head_turn", "jaw_drop", "brow_raise"]
    assert panel.row("jaw_drop").slider.value() == panel.row("jaw_drop").position_of(0.5)
    document.push(RemoveParameterCommand(document, "head_turn"))
    assert list(panel.rows) == ["jaw_drop", "brow_raise"]
    assert not panel.row("jaw_drop").label.font().bold()
    assert "2 parameters" in window.statusBar().model_label.text()
    np.testing.assert_array_equal(window.viewport.displayed_points(), document.model.deform(document.values))

    window.undo()
    window.undo()
    assert list(panel.rows) == ["head_turn", "jaw_open", "brow_raise"]
    assert panel.row("head_turn").label.font().bold()
    assert panel.row("jaw_open").label.indent() > 0
    # The rows drive the model again after the rebuild.
    panel.row("jaw_open").slider.setValue(300)
    assert document.value("jaw_open") == 0.3
    np.testing.assert_array_equal(window.viewport.displayed_points(), document.model.deform(document.values))


def test_window_modified_marker_follows_the_clean_state(window, tmp_path):
    assert window.windowTitle() == "synthetic-head.xml[*] — Artificial Person"
    assert not window.isWindowModified()
    window.document.set_value("brow_raise", 0.4)               # a pose change does not modify the model
    assert not window.isWindowModified()
    _paint(window)
    assert window.isWindowModified()
    window.undo()
    assert not window.isWindowModified()
    window.redo()
    assert window.isWindowModified()
    assert window.files.save_model(tmp_path / "painted.xml")
    assert not window.isWindowModified()
    assert window.windowTitle() == "painted.xml[*] — Artificial Person"
    window.undo()                                              # differs from the file just saved
    assert window.isWindowModified()
