"""The Identity panel in the real window on the default head: live drags, one undo step per drag, files.

Heads are made with the real engine (:func:`engine.identity.make_identity_head`,
a few hundred ms to seconds on a busy machine) on the panel's worker thread;
the tests wait for them through the Qt event loop (``qtbot.waitUntil``), never
``QTest.qWait``, which holds the GIL and starves the worker.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QFileDialog, QStyle, QStyleOptionSlider

import engine
from engine.identity import Identity, identity_vertices
from workbench.document.undo_commands import ReplaceModelCommand, WeightsChangedCommand
from workbench.window.layouts import fresh_window_size

LAPTOP = fresh_window_size(QRect(0, 0, 1366, 768))
HEAD_TIMEOUT_MS = 240_000         # a head on a loaded 2-core machine; normally under 2 s
SCREENSHOT_NAME = "identity-panel.png"


@pytest.fixture
def head_window(make_window):
    return make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))


def open_panel(window, qtbot):
    window.actions_by_id["view.identity"].trigger()           # View → Identity
    qtbot.waitUntil(lambda: window.identity_panel.built and window.identity_dock.isVisible())
    return window.identity_panel


def wait_for_head(qtbot, panel) -> None:
    qtbot.waitUntil(lambda: not panel.heads.busy, timeout=HEAD_TIMEOUT_MS)


def handle_center(slider) -> QPoint:
    option = QStyleOptionSlider()
    slider.initStyleOption(option)
    rect = slider.style().subControlRect(QStyle.ComplexControl.CC_Slider, option,
                                         QStyle.SubControl.SC_SliderHandle, slider)
    return rect.center()


def press_and_drag(qtbot, slider, to_x: int) -> QPoint:
    """Press the slider's handle with the mouse and drag it to ``to_x`` (widget pixels); not released."""
    start = handle_center(slider)
    QTest.mousePress(slider, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start)
    assert slider.isSliderDown()
    end = QPoint(to_x, start.y())
    for step in range(1, 6):
        QTest.mouseMove(slider, start + (end - start) * step / 5)
        qtbot.wait(5)
    return end


def drawn(window) -> np.ndarray:
    return window.viewport.displayed_points()


def assert_drawn(window, expected: np.ndarray, atol: float = 1e-6) -> None:
    points = drawn(window)
    shown = ~np.isnan(points[:, 0])
    assert shown.sum() > 0.9 * len(points)
    np.testing.assert_allclose(points[shown], expected[shown], atol=atol)


def test_a_drag_reshapes_the_face_live_and_its_release_is_one_undo_step(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    default = document.model
    assert default.identity is None and panel.rows["sex"].value() == 0.5
    row = panel.rows["sex"]

    end = press_and_drag(qtbot, row.slider, row.slider.width() - 4)           # towards male, held
    qtbot.waitUntil(lambda: len(panel.heads.preview_ms) > 0)
    qtbot.wait(20)
    sex = row.value()
    assert sex > 0.8
    assert document.model is default and document.undo_stack.count() == 0   # nothing made or undoable yet
    assert_drawn(window, identity_vertices(Identity({"sex": sex})))          # the viewport shows that face
    assert np.nanmax(np.abs(drawn(window) - default.vertices)) > 1.0         # mm: it did move

    QTest.mouseRelease(row.slider, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, end)
    assert panel.heads.busy                                                  # made off the GUI thread
    wait_for_head(qtbot, panel)
    made = document.model
    assert made is not default and made.identity.value("sex") == sex
    assert document.undo_stack.count() == 1 and "sex" in document.undo_stack.undoText()
    assert isinstance(document.undo_stack.command(0), ReplaceModelCommand)
    assert document.is_modified and window.isWindowModified()
    assert_drawn(window, made.vertices)
    assert row.value() == sex and row.label.font().bold()

    window.undo()                                                           # Edit → Undo
    assert document.model is default and document.model.identity is None
    assert row.value() == 0.5 and not row.label.font().bold()
    assert_drawn(window, default.vertices)
    assert not document.is_modified

    window.redo()
    assert document.model is made and row.value() == sex
    assert_drawn(window, made.vertices)


def test_closing_the_window_while_a_head_is_being_made_drops_it(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    heads = panel.heads
    panel.rows["age"].spin.setValue(40.0)
    assert heads.busy
    future = heads._build.future
    assert window.close()                                     # nothing unsaved yet: no question
    qtbot.waitUntil(future.done, timeout=HEAD_TIMEOUT_MS)
    qtbot.wait(3 * 20)                                        # a few poll intervals: nothing may arrive
    assert not heads.busy and window.document.undo_stack.count() == 0
    assert window.document.model.identity is None


def test_the_preview_wears_the_pose_the_document_shows(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    document.set_value("jaw_open", 0.6)
    posed_offset = document.vertices() - document.model.vertices
    row = panel.rows["nose-scale-horiz-decr-incr"]
    row.group.set_expanded(True)
    row.slider.setSliderDown(True)                                           # a drag in progress
    row.slider.setValue(row.position_of(1.0))
    qtbot.waitUntil(lambda: len(panel.heads.preview_ms) > 0)
    expected = identity_vertices(Identity({"nose-scale-horiz-decr-incr": 1.0})) + posed_offset
    assert_drawn(window, expected)
    panel.heads.end_preview()                                                # dropped: the document again
    assert_drawn(window, document.vertices())
    row.slider.setSliderDown(False)
    wait_for_head(qtbot, panel)
    assert document.value("jaw_open") == 0.6                                 # the new head keeps the pose
    assert_drawn(window, document.vertices())


def test_save_identity_as_and_reopen_shows_the_identity(head_window, qtbot, tmp_path, monkeypatch):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    age = panel.rows["age"]
    age.spin.setValue(62.0)                                                  # typed value: one step
    wait_for_head(qtbot, panel)
    assert document.model.identity.value("age") == 62.0 and document.undo_stack.count() == 1

    proposed = []
    target = tmp_path / "older.xml"

    def save_name(parent, title, start, filters):
        proposed.append(start)
        return str(target), filters

    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(save_name))
    assert panel.save_identity_as()
    assert Path(proposed[0]).name.startswith("person-age62")
    assert document.path == target and not document.is_modified
    assert engine.load_model(target).identity.values == {"age": 62.0}

    assert window.files.open_model(engine.default_model_path())
    assert age.value() == 25.0
    assert window.files.open_model(target)                                  # File → Open
    assert age.value() == 62.0 and age.label.font().bold()
    assert "1 value differs" in panel.note.text() and "33% african" in panel.note.text()

    # A saved identity whose rig is the default head's: the next change asks nothing.
    panel.ask_discard = panel.heads.ask_discard = lambda reason: pytest.fail(f"asked: {reason}")
    panel.rows["weight"].spin.setValue(0.8)
    wait_for_head(qtbot, panel)
    assert document.model.identity.values == {"age": 62.0, "weight": 0.8}


def test_painted_weights_carry_over_and_edits_on_a_made_head_are_asked_about(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    name = "jaw_open"
    region = document.model.regions[name]
    painted = np.clip(region.weights * 0.5, 0, 1)
    document.push(WeightsChangedCommand(document, name, region.indices, painted))   # an edit of the default head

    asked: list[str] = []
    answers = [True]
    panel.heads.ask_discard = lambda reason: (asked.append(reason), answers[0])[1]
    panel.rows["sex"].spin.setValue(0.0)
    wait_for_head(qtbot, panel)
    first = document.model
    assert not asked                                          # the default head's own edits are carried over
    np.testing.assert_array_equal(first.regions[name].weights, painted)
    assert first.identity.values == {"sex": 0.0}

    region = first.regions[name]
    document.push(WeightsChangedCommand(document, name, region.indices, np.zeros_like(region.weights)))
    edited = document.model
    answers[0] = False                                        # Cancel: nothing changes, the slider goes back
    panel.rows["age"].spin.setValue(70.0)
    wait_for_head(qtbot, panel)
    assert len(asked) == 1 and "edited since it was made" in asked[0]
    assert document.model is edited and panel.rows["age"].value() == 25.0
    assert document.undo_stack.count() == 3

    answers[0] = True                                         # Yes: made from the edited default head again
    panel.rows["age"].spin.setValue(70.0)
    wait_for_head(qtbot, panel)
    assert len(asked) == 2 and document.model.identity.values == {"sex": 0.0, "age": 70.0}
    np.testing.assert_array_equal(document.model.regions[name].weights, painted)
    window.undo()
    assert document.model is edited                           # undo brings the edited head back
    assert panel.rows["age"].value() == 25.0 and panel.rows["sex"].value() == 0.0


def test_group_reset_and_reset_all_are_one_step_each(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    nose = panel.groups["nose"]
    nose.set_expanded(True)
    panel.rows["nose-flaring-decr-incr"].spin.setValue(0.7)
    wait_for_head(qtbot, panel)
    panel.rows["age"].spin.setValue(50.0)
    wait_for_head(qtbot, panel)
    assert "1 changed" in nose.header.text()
    nose.reset_button.click()
    wait_for_head(qtbot, panel)
    assert document.model.identity.values == {"age": 50.0} and "1 changed" not in nose.header.text()
    panel.reset_all_button.click()
    wait_for_head(qtbot, panel)
    assert document.model.identity.values == {} and document.undo_stack.count() == 4
    assert not panel.reset_all_button.isEnabled()
    window.undo()
    assert document.model.identity.values == {"age": 50.0} and panel.rows["age"].value() == 50.0


def test_an_impossible_identity_is_refused_in_the_panel(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    for race in ("african", "asian"):
        panel.rows[race].spin.setValue(0.0)
        wait_for_head(qtbot, panel)
    count = window.document.undo_stack.count()
    panel.rows["caucasian"].spin.setValue(0.0)                # all three shares 0: not a person
    assert "cannot all be 0" in panel.note.text()
    assert not panel.heads.busy and window.document.undo_stack.count() == count
    assert panel.rows["caucasian"].value() == pytest.approx(1 / 3, abs=1e-3)


def test_the_search_field_shows_matching_rows_and_opens_their_groups(head_window, qtbot):
    panel = open_panel(head_window, qtbot)
    panel.search.setText("lowerlip")
    visible = [name for name, row in panel.rows.items() if row.label.isVisibleTo(panel)]
    assert visible and all("lowerlip" in name for name in visible)
    assert panel.groups["mouth"].expanded and not panel.groups["nose"].isVisibleTo(panel)
    panel.search.clear()
    assert all(box.isVisibleTo(panel) for box in panel.groups.values())


def test_a_model_on_another_mesh_gets_no_identity(window, qtbot):
    panel = open_panel(window, qtbot)                          # the synthetic test head
    assert "default head's mesh" in panel.note.text()
    assert not any(box.isEnabled() for box in panel.groups.values())
    assert not panel.save_button.isEnabled()


def test_screenshot_of_the_identity_panel_on_a_laptop_screen(head_window, qtbot, tmp_path):
    """docs/identity-panel.png: ``AP_SCREENSHOT_DIR=docs xvfb-run -a .venv/bin/pytest`` this test."""
    window = head_window
    panel = open_panel(window, qtbot)
    panel.groups["nose"].set_expanded(True)
    for name, value in (("sex", 0.9), ("age", 55.0), ("african", 0.8), ("nose-flaring-decr-incr", 0.7)):
        panel.rows[name].spin.setValue(value)
        wait_for_head(qtbot, panel)
    row = panel.rows["nose-flaring-decr-incr"]
    panel.scroll.verticalScrollBar().setValue(0)             # the macro rows at the top, the nose's below
    panel.scroll.ensureWidgetVisible(row.slider)
    qtbot.wait(50)
    window.viewport.render_now()
    image = window.grab().toImage()
    folder = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    assert image.save(str(folder / SCREENSHOT_NAME))

    dock = window.identity_dock
    centre = dock.mapTo(window, dock.rect().center())
    assert dock.isAncestorOf(window.childAt(centre))                        # in front, not behind a tab
    assert window.rect().contains(QRect(dock.mapTo(window, QPoint(0, 0)), dock.size()))
    assert window.frameGeometry().width() <= 1366 and window.frameGeometry().height() <= 768
    viewport = panel.scroll.viewport()
    right = row.reset_button.mapTo(viewport, QPoint(row.reset_button.width(), 0)).x()
    assert right <= viewport.width(), "the rows are cut off on the right: no room for the reset buttons"
    assert row.slider.width() >= 80
    assert window.viewport.width() >= 0.3 * window.width()                  # and the face is still there


def test_the_mouse_wheel_passes_a_value_it_is_not_meant_for_on_to_the_scrolling_panel(head_window, qtbot):
    from PySide6.QtCore import QPointF
    from PySide6.QtGui import QWheelEvent
    from PySide6.QtWidgets import QApplication

    panel = open_panel(head_window, qtbot)
    row = panel.rows["muscle"]

    def wheel(widget) -> QWheelEvent:
        event = QWheelEvent(QPointF(widget.rect().center()), QPointF(widget.mapToGlobal(widget.rect().center())),
                            QPoint(0, 0), QPoint(0, -120), Qt.MouseButton.NoButton, Qt.KeyboardModifier.NoModifier,
                            Qt.ScrollPhase.NoScrollPhase, False)
        QApplication.sendEvent(widget, event)
        return event

    for widget in (row.slider, row.spin):                      # the pointer passes over them while scrolling
        assert not wheel(widget).isAccepted()                  # ignored: Qt hands it to the scroll area
        assert row.value() == 0.5 and not panel.heads.busy and not panel.heads.preview_ms
    head_window.activateWindow()
    qtbot.waitUntil(head_window.isActiveWindow)
    row.slider.setFocus()                                      # clicked or tabbed to: now the wheel is its own
    qtbot.waitUntil(row.slider.hasFocus)
    assert wheel(row.slider).isAccepted() and row.value() < 0.5
    wait_for_head(qtbot, panel)
    assert head_window.document.model.identity.value("muscle") == row.value()


def test_undoing_past_an_identity_change_undoes_earlier_edits_on_the_model_they_were_made_on(head, qtbot):
    """The document keeps its undo stack across a replaced model: each command edits ``document.model``,
    which undo has put back by the time an earlier command is undone."""
    from engine.identity import make_identity_head
    from workbench.document.model_document import ModelDocument

    default = head.copy()
    document = ModelDocument(default)
    replaced: list[object] = []
    document.model_replaced.connect(replaced.append)
    document.set_value("jaw_open", 0.4)
    name = "jaw_open"
    original = default.regions[name].weights.copy()
    document.push(WeightsChangedCommand(document, name, default.regions[name].indices, original * 0.5))
    made = make_identity_head(Identity({"age": 70.0}), default.copy())
    document.push(ReplaceModelCommand(document, made, "Identity: age 25 → 70", default))
    assert document.model is made and replaced == [made] and document.undo_stack.count() == 2
    assert document.value("jaw_open") == 0.4                     # the pose stays
    np.testing.assert_allclose(document.vertices(), made.deform(document.values))
    document.undo_stack.undo()
    assert document.model is default and replaced == [made, default]
    np.testing.assert_array_equal(default.regions[name].weights, original * 0.5)
    document.undo_stack.undo()                                  # the paint, on the model it was made on
    np.testing.assert_array_equal(default.regions[name].weights, original)
    document.undo_stack.redo()
    document.undo_stack.redo()
    assert document.model is made and made.identity.values == {"age": 70.0}
    np.testing.assert_array_equal(default.regions[name].weights, original * 0.5)


def test_a_model_whose_identity_this_version_does_not_know_is_shown_as_such(head_window, qtbot):
    from engine.model.identity_record import IdentityRecord

    window = head_window
    panel = open_panel(window, qtbot)
    strange = window.document.model.copy()
    strange.identity = IdentityRecord({"nose-made-up-decr-incr": 0.4}, "anny-9.9")   # e.g. newer shape data
    window.document.replace_model(strange)
    assert "cannot be shown" in panel.note.text() and "nose-made-up-decr-incr" in panel.note.text()
    assert not any(box.isEnabled() for box in panel.groups.values()) and not panel.reset_all_button.isEnabled()


def test_an_opened_identity_whose_rig_was_edited_is_asked_about(head_window, qtbot, tmp_path):
    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    panel.rows["age"].spin.setValue(40.0)
    wait_for_head(qtbot, panel)
    region = document.model.regions["jaw_open"]
    document.push(WeightsChangedCommand(document, "jaw_open", region.indices, region.weights * 0.25))
    assert window.files.save_model(tmp_path / "edited.xml")
    assert window.files.open_model(tmp_path / "edited.xml")
    opened = document.model
    asked: list[str] = []
    panel.heads.ask_discard = lambda reason: (asked.append(reason), False)[1]
    panel.rows["sex"].spin.setValue(1.0)
    wait_for_head(qtbot, panel)
    assert len(asked) == 1 and "differs from the default head's" in asked[0]
    assert document.model is opened and panel.rows["sex"].value() == 0.5 and panel.rows["age"].value() == 40.0


def test_a_head_fitted_to_photographs_is_not_remade_from_its_identity_without_asking(head_window, qtbot):
    """The photo-fit wizard pushes its head as the document's model; a slider would make a new identity from
    the default head and drop the photograph's shape and texture: the panel asks first (issue 19)."""
    from engine.identity import make_identity_head
    from engine.model.texture import TextureImage

    window = head_window
    panel = open_panel(window, qtbot)
    document = window.document
    fitted = make_identity_head(Identity({"age": 40.0}))
    skin = np.flatnonzero(fitted.vertex_part == fitted.parts.index("skin"))
    fitted.vertices = fitted.vertices.copy()
    fitted.vertices[skin, 0] *= 1.02                                  # the photograph's residual warp
    fitted.texture.images = [TextureImage("photo", np.full((8, 8, 3), 200, np.uint8))]
    fitted.changed()
    document.push(ReplaceModelCommand(document, fitted, "New head from photographs"))   # as the wizard does
    asked: list[str] = []
    panel.heads.ask_discard = lambda reason: (asked.append(reason), False)[1]
    panel.rows["sex"].spin.setValue(1.0)
    wait_for_head(qtbot, panel)
    assert len(asked) == 1 and "shape and texture is more than its identity makes" in asked[0]
    assert document.model is fitted and panel.rows["age"].value() == 40.0


def test_a_head_made_here_is_remade_without_asking(head_window, qtbot):
    window = head_window
    panel = open_panel(window, qtbot)
    asked: list[str] = []
    panel.heads.ask_discard = lambda reason: (asked.append(reason), True)[1]
    panel.rows["age"].spin.setValue(40.0)
    wait_for_head(qtbot, panel)
    panel.rows["sex"].spin.setValue(1.0)
    wait_for_head(qtbot, panel)
    assert not asked and window.document.model.identity.values == {"age": 40.0, "sex": 1.0}
