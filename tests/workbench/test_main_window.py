"""The main window on the synthetic head: what it shows, and what each user action does."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog
from vtkmodules.vtkCommonCore import VTK_COLOR_MODE_DIRECT_SCALARS

import engine
from tests.workbench.synthetic_workbench_model import SYNTHETIC_PARAMETERS, build_synthetic_model


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window


def test_window_opens_on_the_model_and_shows_the_mesh(make_window, synthetic_model_path):
    window = make_window(synthetic_model_path)      # start-up itself: a new window, not the module's
    model = window.document.model
    assert window.windowTitle() == "synthetic-head.xml[*] — Artificial Person"
    assert window.viewport.part_names == ["skin", "eye_left", "eye_right"]
    np.testing.assert_array_equal(window.viewport.displayed_points(), model.vertices)
    for part in model.parts:
        mesh = window.viewport.part_mesh(part)
        assert mesh.n_points == len(model.part_vertices(part))
        assert mesh.n_cells > 0
        actor = window.viewport.part_actor(part)
        assert actor.GetVisibility()
        # The actor draws this very mesh (through the normals filter), so
        # updating its points in place is what moves the picture.
        assert _pipeline_source(actor) is mesh
    assert f"{model.n_vertices:,} vertices" in window.statusBar().model_label.text()
    assert "synthetic-head" in window.statusBar().model_label.text()


def _pipeline_source(actor):
    """The data object at the upstream end of an actor's pipeline."""
    algorithm = actor.GetMapper().GetInputAlgorithm()
    while algorithm.GetNumberOfInputPorts() and algorithm.GetNumberOfInputConnections(0):
        algorithm = algorithm.GetInputAlgorithm()
    return algorithm.GetOutputDataObject(0)


def test_painted_vertex_colours_are_drawn_and_follow_the_pose(make_window, tmp_path):
    model = build_synthetic_model("painted-head", painted=True)
    window = make_window(engine.save_model(model, tmp_path / "painted.xml"))
    model = window.document.model
    assert model.vertex_colors is not None
    for part in model.parts:
        actor = window.viewport.part_actor(part)
        mapper = actor.GetMapper()
        assert mapper.GetScalarVisibility()
        assert mapper.GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS   # sRGB as given, no colour map
        mesh = _pipeline_source(actor)
        assert mesh is window.viewport.part_mesh(part)
        np.testing.assert_array_equal(mesh.point_data["vertex_colors"],
                                      model.vertex_colors[model.part_vertices(part)])
    window.parameter_panel.row("head_turn").slider.setValue(1500)
    np.testing.assert_array_equal(window.viewport.displayed_points(),
                                  model.deform({"head_turn": window.document.value("head_turn")}))


def test_parameter_rows_follow_the_tree(window):
    rows = window.parameter_panel.rows
    assert list(rows) == SYNTHETIC_PARAMETERS
    model = window.document.model
    for name, row in rows.items():
        p = model.parameters[name]
        assert row.toolTip() == p.description
        assert row.slider.toolTip() == p.description
        assert (row.spin.minimum(), row.spin.maximum()) == (p.minimum, p.maximum)
        assert row.value_at(row.slider.minimum()) == p.minimum
        assert row.value_at(row.slider.maximum()) == p.maximum
    assert rows["head_turn"].label.indent() == 0
    assert rows["jaw_open"].label.indent() > 0          # a child, indented under its parent
    assert rows["head_turn"].label.font().bold()          # group 1 (rigid)
    assert not rows["jaw_open"].label.font().bold()       # group 2 (leaf)


def test_moving_a_slider_deforms_the_viewport_mesh_exactly(window, qtbot):
    model = window.document.model
    row = window.parameter_panel.row("jaw_open")
    row.slider.setValue(600)
    assert window.document.value("jaw_open") == 0.6
    expected = model.deform({"jaw_open": window.document.value("jaw_open")})
    assert not np.array_equal(expected, model.vertices)
    np.testing.assert_array_equal(window.viewport.displayed_points(), expected)
    assert row.spin.value() == pytest.approx(0.6)
    assert "jaw_open = 0.600" in window.statusBar().currentMessage()

    # A second parameter, moved from the keyboard as a user would.
    turn = window.parameter_panel.row("head_turn")
    turn.slider.setFocus()
    qtbot.keyClick(turn.slider, Qt.Key.Key_PageUp)
    assert window.document.value("head_turn") == turn.value_at(turn.position_of(0.0) + turn.slider.pageStep())
    assert window.document.value("head_turn") == 0.2          # a tenth of [-1, 1], a round value
    expected = model.deform({"jaw_open": window.document.value("jaw_open"),
                             "head_turn": window.document.value("head_turn")})
    np.testing.assert_array_equal(window.viewport.displayed_points(), expected)


def test_spin_box_sets_the_exact_value(window):
    row = window.parameter_panel.row("brow_raise")
    row.spin.setValue(0.25)
    assert window.document.value("brow_raise") == 0.25
    assert row.slider.value() == row.position_of(0.25)
    np.testing.assert_array_equal(window.viewport.displayed_points(),
                                  window.document.model.deform({"brow_raise": 0.25}))


def test_setting_a_value_in_code_updates_the_row_without_echo(window, qtbot):
    emitted = []
    window.document.values_changed.connect(emitted.append)
    window.document.set_value("head_turn", -0.5)
    assert emitted == [["head_turn"]]                       # the row's update did not write back
    row = window.parameter_panel.row("head_turn")
    assert row.slider.value() == row.position_of(-0.5)
    assert row.spin.value() == -0.5


def test_reset_one_and_reset_all_restore_the_rest_mesh(window, qtbot):
    model = window.document.model
    panel = window.parameter_panel
    panel.row("jaw_open").slider.setValue(800)
    panel.row("brow_raise").slider.setValue(900)
    assert panel.reset_all_button.isEnabled()

    qtbot.mouseClick(panel.row("jaw_open").reset_button, Qt.MouseButton.LeftButton)
    assert window.document.value("jaw_open") == 0.0
    assert panel.row("jaw_open").slider.value() == panel.row("jaw_open").position_of(0.0)
    assert not panel.row("jaw_open").reset_button.isEnabled()
    np.testing.assert_array_equal(window.viewport.displayed_points(),
                                  model.deform({"brow_raise": window.document.value("brow_raise")}))

    window.actions_by_id["pose.reset_all"].trigger()
    assert window.document.values == model.default_values()
    np.testing.assert_array_equal(window.viewport.displayed_points(), model.vertices)
    assert not panel.reset_all_button.isEnabled()

    panel.row("head_turn").slider.setValue(100)
    qtbot.mouseClick(panel.reset_all_button, Qt.MouseButton.LeftButton)
    np.testing.assert_array_equal(window.viewport.displayed_points(), model.vertices)


def test_opening_a_malformed_model_shows_an_error_and_keeps_the_current_model(
        window, broken_model_path, captured_errors, monkeypatch):
    model = window.document.model
    window.document.set_value("jaw_open", 0.4)
    before = window.viewport.displayed_points()
    monkeypatch.setattr(QFileDialog, "getOpenFileName",
                        staticmethod(lambda *a, **k: (str(broken_model_path), "")))

    window.actions_by_id["file.open"].trigger()

    assert len(captured_errors) == 1
    title, text = captured_errors[0]
    assert "cannot open model" in title
    assert text.startswith(f"{broken_model_path}:")     # file:line: what is wrong, on one line
    assert "\n" not in text and "Traceback" not in text
    assert window.document.model is model
    assert window.document.value("jaw_open") == 0.4
    assert window.windowTitle() == "synthetic-head.xml[*] — Artificial Person"
    assert list(window.parameter_panel.rows) == SYNTHETIC_PARAMETERS
    np.testing.assert_array_equal(window.viewport.displayed_points(), before)


def test_opening_another_model_replaces_everything(window, tmp_path, captured_errors):
    other = build_synthetic_model("second-head")
    other.parameters.remove("brow_raise")
    del other.regions["brow_raise"]
    path = engine.save_model(other, tmp_path / "second.xml")
    window.view_state.set_part_visible("eye_left", False)
    window.document.set_value("jaw_open", 0.5)

    assert window.files.open_model(path)

    assert not captured_errors
    assert window.windowTitle() == "second.xml[*] — Artificial Person"
    assert list(window.parameter_panel.rows) == ["head_turn", "jaw_open"]
    assert window.document.value("jaw_open") == 0.0
    assert window.view_state.is_part_visible("eye_left")           # a new model starts with all parts shown
    assert window.parts_menu.part_actions["eye_left"].isChecked()
    np.testing.assert_array_equal(window.viewport.displayed_points(), window.document.model.vertices)
    window.parameter_panel.row("jaw_open").slider.setValue(1000)
    np.testing.assert_array_equal(window.viewport.displayed_points(),
                                  window.document.model.deform({"jaw_open": 1.0}))


def test_parts_menu_hides_and_shows_parts(window):
    actions = window.parts_menu.part_actions
    assert list(actions) == ["skin", "eye_left", "eye_right"]
    assert all(a.isCheckable() and a.isChecked() for a in actions.values())
    actions["eye_right"].trigger()
    assert not window.view_state.is_part_visible("eye_right")
    assert not window.viewport.part_actor("eye_right").GetVisibility()
    assert window.viewport.part_actor("skin").GetVisibility()
    actions["eye_right"].trigger()
    assert window.viewport.part_actor("eye_right").GetVisibility()


def test_wireframe_toggle(window):
    action = window.actions_by_id["view.wireframe"]
    assert action.isCheckable() and not action.isChecked()
    action.trigger()
    assert window.view_state.wireframe
    assert all(window.viewport.part_actor(p).prop.style == "Wireframe" for p in window.viewport.part_names)
    action.trigger()
    assert all(window.viewport.part_actor(p).prop.style == "Surface" for p in window.viewport.part_names)


@pytest.mark.parametrize("view, axis", [("view.front", (0, 0, 1)), ("view.side", (1, 0, 0))])
def test_view_presets_look_from_the_right_side(window, view, axis):
    window.actions_by_id[view].trigger()
    camera = window.viewport.plotter.camera
    direction = np.subtract(camera.position, camera.focal_point)
    direction /= np.linalg.norm(direction)
    np.testing.assert_allclose(direction, axis, atol=1e-9)
    np.testing.assert_allclose(camera.up, (0, 1, 0), atol=1e-9)


def test_three_quarter_view_is_between_front_and_side(window):
    window.actions_by_id["view.three_quarter"].trigger()
    camera = window.viewport.plotter.camera
    d = np.subtract(camera.position, camera.focal_point)
    assert d[0] > 0 and d[2] > 0 and abs(d[0] / d[2] - 1) < 0.2


def test_standard_shortcuts(window):
    from PySide6.QtGui import QKeySequence

    assert window.actions_by_id["file.open"].shortcut() == QKeySequence(QKeySequence.StandardKey.Open)
    assert window.actions_by_id["file.quit"].shortcut() == QKeySequence(QKeySequence.StandardKey.Quit)
    assert all(not a.icon().isNull() for k, a in window.actions_by_id.items() if k != "file.quit")


def test_save_as_writes_a_loadable_model(window, tmp_path, monkeypatch, captured_errors):
    target = tmp_path / "saved" / "copy.xml"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(lambda *a, **k: (str(target), "")))
    assert window.files.save_as_dialog()
    assert not captured_errors
    assert window.document.path == target
    again = engine.load_model(target)
    np.testing.assert_array_equal(again.vertices, window.document.model.vertices)
    assert again.parameters.names == SYNTHETIC_PARAMETERS


def test_cancelled_dialogs_change_nothing(window, monkeypatch, captured_errors):
    model = window.document.model
    monkeypatch.setattr(QFileDialog, "getOpenFileName", staticmethod(lambda *a, **k: ("", "")))
    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(lambda *a, **k: ("", "")))
    assert not window.files.open_dialog()
    assert not window.files.save_as_dialog()
    assert window.document.model is model and not captured_errors
