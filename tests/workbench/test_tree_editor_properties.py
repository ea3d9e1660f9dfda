"""The tree editor's property sheet, pick-on-mesh pivot and gizmo, in the real window."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QMessageBox

import engine
from tests.workbench.workbench_model_state import model_state
from workbench.tree_editor import TOOL_ID


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window

SCREENSHOT_NAME = "workbench-tree-editor.png"


def _select(window, name):
    dock = window.tree_editor.dock
    dock.view.setCurrentIndex(dock.model.index_of(name))
    assert window.view_state.selected_parameter == name


def _warnings(monkeypatch):
    calls = []
    monkeypatch.setattr(QMessageBox, "warning",
                        staticmethod(lambda parent, title, text, *a, **k: calls.append(text)))
    return calls


def _rotation(axis, degrees):
    """Right-hand rotation matrix (column vectors), written out independently of the engine."""
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    t = np.deg2rad(degrees)
    return np.eye(3) + np.sin(t) * k + (1 - np.cos(t)) * (k @ k)


def test_typing_a_new_pivot_moves_the_rotated_vertices_as_the_rotation_formula_says(window, qtbot):
    document = window.document
    _select(window, "jaw_open")
    sheet = window.tree_editor.sheet
    assert window.tool_options.current_tool == TOOL_ID and sheet.isVisible()
    jaw = document.model.parameters["jaw_open"]
    old_pivot = jaw.pivot.copy()
    document.set_values({"jaw_open": 0.5})
    old = document.vertices().copy()
    before = model_state(document.model)

    # Type x, y and z, then Enter: one commit for the whole vector.
    for edit, text in zip(sheet.pivot.edits, ("5", "-25", "-40"), strict=True):
        edit.selectAll()
        qtbot.keyClicks(edit, text)
    qtbot.keyClick(sheet.pivot.edits[-1], Qt.Key.Key_Return)
    new_pivot = np.array([5.0, -25.0, -40.0])
    np.testing.assert_array_equal(document.model.parameters["jaw_open"].pivot, new_pivot)
    assert document.undo_stack.count() == 1 and document.undo_stack.undoText() == "Set pivot of jaw_open"

    # Only jaw_open moves at this pose, in the rest frame: P' = P + w (R (P - c) + c - P), so a new
    # pivot shifts every jaw vertex by w (I - R)(c_new - c_old).
    new = document.vertices()
    region = document.model.regions["jaw_open"]
    R = _rotation(jaw.axis, 0.5 * jaw.degrees_per_unit)
    expected = old.copy()
    expected[region.indices] += region.weights[:, None] * ((np.eye(3) - R) @ (new_pivot - old_pivot))
    np.testing.assert_allclose(new, expected, atol=1e-9)
    assert np.abs(new - old).max() > 0.5
    np.testing.assert_allclose(window.viewport.displayed_points(), new, atol=1e-4)

    document.undo_stack.undo()
    assert model_state(document.model) == before
    np.testing.assert_array_equal(document.vertices(), old)
    assert sheet.pivot.edits[1].text() == "-10"                     # the sheet follows undo


def test_direction_range_default_and_type_are_each_one_undo_step(window):
    document = window.document
    sheet = window.tree_editor.sheet
    _select(window, "brow_raise")
    assert not sheet.form.isRowVisible(sheet.axis) and sheet.form.isRowVisible(sheet.direction)
    sheet.direction.set_texts("0", "4", "2")
    assert sheet.commit("direction")
    document.set_values({"brow_raise": 1.0})
    region = document.model.regions["brow_raise"]
    moved = document.vertices()[region.indices] - document.model.vertices[region.indices]
    np.testing.assert_allclose(moved, region.weights[:, None] * np.array([0.0, 4.0, 2.0]), atol=1e-9)

    sheet.maximum.setText("2")
    assert sheet.commit("maximum")
    sheet.default.setText("0.25")
    assert sheet.commit("default")
    sheet.description.setText("Raise the brows higher.")
    assert sheet.commit("description")
    sheet.kind.setCurrentText("rotation")
    assert sheet.commit("kind")
    assert sheet.form.isRowVisible(sheet.axis) and not sheet.form.isRowVisible(sheet.direction)
    p = document.model.parameters["brow_raise"]
    assert (p.kind, p.maximum, p.default, p.description) == ("rotation", 2.0, 0.25, "Raise the brows higher.")
    assert [document.undo_stack.text(i) for i in range(document.undo_stack.count())] == [
        "Set direction of brow_raise", "Set maximum of brow_raise", "Set default of brow_raise",
        "Set description of brow_raise", "Set type of brow_raise"]
    assert window.tree_editor.dock.model.index_of("brow_raise").siblingAtColumn(2).data() == "rotation"


def test_pressing_enter_on_an_unchanged_field_changes_nothing(window):
    _select(window, "jaw_open")
    sheet = window.tree_editor.sheet
    for field in (sheet.pivot, sheet.axis):
        assert not field.is_edited()
    assert not sheet.commit("pivot") and not sheet.commit("axis") and not sheet.commit("minimum")
    assert window.document.undo_stack.count() == 0


@pytest.mark.parametrize("prop, texts, why", [
    ("minimum", ["5"], "above maximum"),
    ("maximum", ["-1"], "above maximum"),
    ("default", ["3"], "outside its range"),
    ("axis", ["0", "0", "0"], "zero vector"),
    ("degrees_per_unit", ["lots"], "not a number"),
    ("pivot", ["1", "two", "3"], "not a number"),
    ("pivot", ["1", "inf", "3"], "not a finite number"),
])
def test_invalid_values_are_explained_and_change_nothing(window, monkeypatch, prop, texts, why):
    warnings = _warnings(monkeypatch)
    document = window.document
    _select(window, "jaw_open")
    sheet = window.tree_editor.sheet
    before = model_state(document.model)
    field = {"minimum": sheet.minimum, "maximum": sheet.maximum, "default": sheet.default, "axis": sheet.axis,
             "degrees_per_unit": sheet.degrees, "pivot": sheet.pivot}[prop]
    shown = [e.text() for e in getattr(field, "edits", [field])]
    if len(texts) == 3:
        field.set_texts(*texts)
    else:
        field.setText(texts[0])
    assert not sheet.commit(prop)
    assert len(warnings) == 1 and why in warnings[0], warnings
    assert model_state(document.model) == before and document.undo_stack.count() == 0
    assert [e.text() for e in getattr(field, "edits", [field])] == shown      # back to the model's value


def test_a_field_translation_cannot_become_a_rotation(make_window, tmp_path, monkeypatch):
    from tests.workbench.synthetic_workbench_model import build_synthetic_model

    model = build_synthetic_model()
    skin = model.part_vertices("skin")[::9]
    model.add_parameter(engine.Parameter("pucker", "translation", minimum=0, field=True),
                        engine.InfluenceRegion(skin, np.full(len(skin), 0.5), np.ones((len(skin), 3))))
    window = make_window(engine.save_model(model, tmp_path / "field.xml"))
    warnings = _warnings(monkeypatch)
    _select(window, "pucker")
    sheet = window.tree_editor.sheet
    assert not sheet.direction.isEnabled()
    sheet.kind.setCurrentText("rotation")
    assert not sheet.commit("kind")
    assert len(warnings) == 1 and "displacement field" in warnings[0]
    assert sheet.kind.currentText() == "translation"


def _front_skin_pixel(window):
    """Widget pixel of the skin vertex nearest the viewer (front view): surely on the model."""
    model = window.document.model
    skin = model.part_vertices("skin")
    chin = skin[np.argmax(model.vertices[skin, 2] - 0.3 * np.abs(model.vertices[skin, 1] + 30))]
    return window.viewport.world_to_widget(model.vertices[chin])


def test_pick_on_mesh_puts_the_pivot_on_the_clicked_surface_point(window, qtbot):
    document = window.document
    _select(window, "jaw_open")
    sheet = window.tree_editor.sheet
    window.viewport.render_now()
    x, y = _front_skin_pixel(window)
    expected = window.viewport.pick(x, y)
    assert expected is not None

    sheet.pick_button.click()
    assert sheet.picker.armed and sheet.pick_button.isChecked()
    camera = window.viewport.plotter.camera.position
    # A click on the background keeps the picker waiting.
    qtbot.mouseClick(window.viewport.plotter, Qt.MouseButton.LeftButton, pos=QPoint(3, 3))
    assert sheet.picker.armed and document.undo_stack.count() == 0
    qtbot.mouseClick(window.viewport.plotter, Qt.MouseButton.LeftButton, pos=QPoint(round(x), round(y)))
    assert not sheet.picker.armed and not sheet.pick_button.isChecked()
    assert window.viewport.plotter.camera.position == camera          # the click did not turn the view
    pivot = document.model.parameters["jaw_open"].pivot
    np.testing.assert_allclose(pivot, window.viewport.pick(round(x), round(y)).point, atol=1e-9)
    assert np.linalg.norm(pivot - expected.point) < 5.0
    assert document.undo_stack.count() == 1 and document.undo_stack.undoText() == "Set pivot of jaw_open"
    np.testing.assert_allclose(window.tree_editor.gizmo.pivot_position(), pivot, atol=1e-6)


def test_escape_cancels_picking(window, qtbot):
    _select(window, "jaw_open")
    sheet = window.tree_editor.sheet
    sheet.pick_button.click()
    qtbot.keyClick(window.viewport.plotter, Qt.Key.Key_Escape)
    assert not sheet.picker.armed and not sheet.pick_button.isChecked()
    assert window.document.undo_stack.count() == 0


def test_the_gizmo_follows_the_selection_edits_undo_and_the_pose(window):
    document = window.document
    gizmo = window.tree_editor.gizmo
    renderer_actors = window.viewport.plotter.renderer.actors
    assert "tree-editor:gizmo-pivot" in renderer_actors and "tree-editor:gizmo-axis" in renderer_actors
    window.view_state.select_parameter(None)
    assert not gizmo.visible and not gizmo.arrow_visible

    _select(window, "jaw_open")
    jaw = document.model.parameters["jaw_open"]
    assert gizmo.visible and gizmo.arrow_visible
    np.testing.assert_allclose(gizmo.pivot_position(), jaw.pivot, atol=1e-6)
    np.testing.assert_allclose(gizmo.arrow_direction(), jaw.axis, atol=1e-5)

    sheet = window.tree_editor.sheet
    sheet.pivot.set_texts("0", "-30", "-50")
    assert sheet.commit("pivot")
    sheet.axis.set_texts("0", "1", "1")
    assert sheet.commit("axis")
    np.testing.assert_allclose(gizmo.pivot_position(), [0, -30, -50], atol=1e-6)
    np.testing.assert_allclose(gizmo.arrow_direction(), np.array([0, 1, 1]) / np.sqrt(2), atol=1e-5)
    document.undo_stack.undo()
    document.undo_stack.undo()
    np.testing.assert_allclose(gizmo.pivot_position(), jaw.pivot, atol=1e-6)
    np.testing.assert_allclose(gizmo.arrow_direction(), jaw.axis, atol=1e-5)

    # The jaw's axis turns with its parent, the head.
    document.set_values({"head_turn": 1.0})                       # 30° about +y through (0, -100, 0)
    R = np.array([[np.cos(np.pi / 6), 0, np.sin(np.pi / 6)], [0, 1, 0], [-np.sin(np.pi / 6), 0, np.cos(np.pi / 6)]])
    head_pivot = np.array([0, -100, 0])
    np.testing.assert_allclose(gizmo.pivot_position(), R @ (jaw.pivot - head_pivot) + head_pivot, atol=1e-6)
    np.testing.assert_allclose(gizmo.arrow_direction(), R @ jaw.axis, atol=1e-5)
    document.reset_all()

    _select(window, "brow_raise")                                 # a translation: arrow along its direction
    direction = document.model.parameters["brow_raise"].direction
    np.testing.assert_allclose(gizmo.arrow_direction(), direction / np.linalg.norm(direction), atol=1e-5)
    window.view_state.select_parameter(None)
    assert not gizmo.visible


def test_screenshot_of_the_tree_editor(make_window, synthetic_model_path, qtbot, tmp_path):
    """docs/images/workbench-tree-editor.png (set AP_SCREENSHOT_DIR=docs/images to refresh it)."""
    screenshot = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / SCREENSHOT_NAME
    head = engine.default_model_path()
    window = make_window(head if head.exists() else synthetic_model_path, size=(1400, 860))
    name = "jaw_open"
    _select(window, name)
    dock = window.tree_editor.dock
    window.resizeDocks([dock], [380], Qt.Orientation.Horizontal)
    window.resizeDocks([dock], [430], Qt.Orientation.Vertical)
    qtbot.wait(20)
    window.viewport.set_view("three-quarter")
    window.document.set_values({name: 0.6 * window.document.model.parameters[name].maximum})
    window.viewport.render_now()
    qtbot.wait(50)
    screenshot.parent.mkdir(parents=True, exist_ok=True)
    assert window.grab().toImage().save(str(screenshot))

    # The gizmo's white pivot must be on screen where it is projected (seen through the face).
    view = window.viewport.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(view.constBits(), np.uint8).reshape(view.height(), view.bytesPerLine())
    pixels = pixels[:, :view.width() * 3].reshape(view.height(), view.width(), 3).astype(int)
    x, y = window.viewport.world_to_widget(window.tree_editor.gizmo.pivot_position())
    ratio = view.width() / window.viewport.width()
    patch = pixels[int(y * ratio) - 6:int(y * ratio) + 7, int(x * ratio) - 6:int(x * ratio) + 7]
    whitest = patch.reshape(-1, 3).min(axis=1).max()       # the arrow crosses the sphere's middle
    assert whitest > 170, patch.reshape(-1, 3)
