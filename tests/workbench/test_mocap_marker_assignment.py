"""Naming a real facial take's markers in the workbench: the import's warning, a click on the face, undo, the files.

The take is c3d.org's NaturalPoint Facial-Sing, cut after 200 frames
(tests/engine/data/capture): 38 markers labelled ``root-1`` … ``section14-3``,
``Unlabeled1``, none an MPEG-4 id; ``section14-2`` is the chin's midpoint.
Everything is driven as a user would: the import dialog, a real mouse click
on the marker where the view draws it, the Assign button, Ctrl+Z in the
marker list, the session saved and opened again. On a laptop-sized window
(the size a 1366 × 768 screen opens).
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QRect, Qt
from PySide6.QtGui import QFontMetrics
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QFileDialog, QStyle

import engine
from engine.mocap.importer import import_marker_file
from engine.mocap.marker_assignment import marker_labels
from engine.mocap.naming import read_mapping, write_mapping
from engine.mocap.readers import read_marker_file
from engine.mocap.sample_files import write_sample_recording
from engine.mocap.session import load_session
from tests.workbench.test_mocap_tool import read_into_dialog, wait_jobs
from workbench.mocap.import_dialog import POINT
from workbench.window.layouts import fresh_window_size
from workbench.window.recent_files import add_recent_file

FACIAL_SING = Path(__file__).parents[1] / "engine" / "data" / "capture" / "Facial-Sing-200-frames.c3d"
STEM = FACIAL_SING.stem
HEAD = [f"root-{k}" for k in range(1, 7)]
LAPTOP = fresh_window_size(QRect(0, 0, 1366, 768))
SCREENSHOTS = os.environ.get("AP_SCREENSHOT_DIR")


@pytest.fixture
def lab_take(tmp_path) -> Path:
    """The take in a folder of its own (the lab's share), away from the project."""
    folder = tmp_path / "lab-share"
    folder.mkdir()
    return Path(shutil.copy(FACIAL_SING, folder))


@pytest.fixture
def project(tmp_path) -> Path:
    """A project folder holding the model last opened (the open model is the shipped head, never saved over)."""
    folder = tmp_path / "project"
    folder.mkdir()
    person = folder / "person.xml"
    person.write_text("<model/>\n")            # only its folder matters: File ▸ Open recent remembers it
    add_recent_file(person)
    return folder


@pytest.fixture
def head_window(make_window):
    return make_window(engine.default_model_path(), size=(LAPTOP.width(), LAPTOP.height()))


def import_take(window, qtbot, path):
    """Through the import dialog: the file's up axis +Z, the head markers as reference."""
    dialog = read_into_dialog(window, qtbot, path)
    dialog.up_combo.setCurrentIndex(dialog.up_combo.findData("Z"))
    dialog.set_references(HEAD)
    dialog.start_import()
    wait_jobs(qtbot)
    assert window.mocap.state.session is not None and not dialog.isVisible()
    return window.mocap.state.session


def click_marker(window, qtbot, marker):
    """A real left click on the view where ``marker`` is drawn."""
    overlay = window.mocap.overlay
    window.viewport.render_now()
    point = overlay.shown_points[overlay.shown_names.index(marker)]
    x, y = window.viewport.world_to_widget(point)
    plotter = window.viewport.plotter
    assert 0 <= x < plotter.width() and 0 <= y < plotter.height()
    qtbot.mouseClick(plotter, Qt.MouseButton.LeftButton, pos=QPoint(round(x), round(y)))


def choose_point(panel, point):
    panel.point_combo.setCurrentIndex(panel.point_combo.findData(point))


def test_the_import_warns_of_labels_that_name_no_feature_point(head_window, qtbot, lab_take, project):
    dialog = read_into_dialog(head_window, qtbot, lab_take)
    assert "note: the file is cut short: its data end after 200 of the 3000 frames" in dialog.summary.text()
    warning = dialog.unmapped_warning
    assert warning.isVisible()
    text = warning.text()
    assert "38 of 38 labels map to no MPEG-4 feature point" in text
    assert "root-1, root-2, root-3, root-4, root-5, root-6, section1-1, section1-2 and 30 more" in text
    assert warning.toolTip().splitlines()[1:] == dialog.labels()           # every one of them
    if SCREENSHOTS:                 # docs/images/workbench-mocap-unmapped-labels.png (AP_SCREENSHOT_DIR=docs/images)
        assert dialog.grab().save(str(Path(SCREENSHOTS) / "workbench-mocap-unmapped-labels.png"))
    row = dialog.labels().index("section14-2")
    dialog.table.item(row, POINT).setText("2.1")                          # the user names one ...
    assert "37 of 38 labels" in warning.text() and "section14-2" not in warning.toolTip()
    dialog.table.item(dialog.labels().index("Unlabeled1"), POINT).setText("-")   # ... and drops one
    assert "36 of 37 labels" in warning.text()
    # the session is suggested beside the project, not beside the data
    assert Path(dialog.session_edit.text()) == project / f"{STEM}.h5"
    dialog.reject()


def test_no_warning_when_every_label_names_a_feature_point(head_window, qtbot, tmp_path):
    take = write_sample_recording(tmp_path / "take", "Papu ja kala.", fmt="tsv", seed=1,
                                  labels={"2.1": "FP2_1", "8.1": "fp8.1"})
    dialog = read_into_dialog(head_window, qtbot, take["markers"])
    assert not dialog.unmapped_warning.isVisible() and not dialog.unmapped()
    dialog.start_import()
    wait_jobs(qtbot)
    assert head_window.mocap.state.session is not None
    assert not head_window.mocap.plot_dock.names_button.isChecked()        # nothing to name: the plot stays wide


def test_a_session_is_suggested_beside_the_open_model(make_window, synthetic_model_path, qtbot, lab_take):
    window = make_window(synthetic_model_path)
    dialog = window.mocap.import_dialog_for(lab_take)
    wait_jobs(qtbot)
    assert Path(dialog.session_edit.text()) == synthetic_model_path.parent.resolve() / f"{STEM}.h5"
    dialog.reject()


def test_click_a_marker_assign_the_chin_undo_redo_save_reopen(head_window, qtbot, lab_take, project, tmp_path,
                                                              monkeypatch):
    window = head_window
    mocap, panel = window.mocap, window.mocap.names_panel
    session = import_take(window, qtbot, lab_take)
    assert session.markers == read_marker_file(lab_take).labels
    assert panel.markers() == session.markers and mocap.overlay.visible
    assert mocap.plot_dock.names_button.isChecked() and panel.isVisible()      # markers to name: the list opens

    click_marker(window, qtbot, "section14-2")
    assert mocap.plot_dock.marker == "section14-2" and panel.current_marker() == "section14-2"
    assert "section14-2" in mocap.overlay.labels_visible                   # the selected marker, named
    choose_point(panel, "2.1")
    assert panel.point_combo.currentText().startswith("2.1  bottom of the chin")
    qtbot.mouseClick(panel.assign_button, Qt.MouseButton.LeftButton)

    chin = session.marker_index("2.1")
    assert marker_labels(session)[chin] == "section14-2" and "section14-2" not in session.markers
    assert panel.table.item(chin, 0).text() == "section14-2" and panel.table.item(chin, 1).text() == "2.1"
    assert mocap.plot_dock.marker == "2.1" and panel.current_marker() == "2.1"
    assert "2.1 (section14-2)" in mocap.overlay.labels_visible             # drawn beside the marker
    assert not mocap.state.undo_stack.isClean()

    panel.table.setFocus()
    QTest.keyClick(panel.table, Qt.Key.Key_Z, Qt.KeyboardModifier.ControlModifier)
    assert "section14-2" in session.markers and "2.1" not in session.markers
    assert mocap.state.undo_stack.isClean() and panel.table.item(chin, 1).text() == "—"
    QTest.keyClick(panel.table, Qt.Key.Key_Z,
                   Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier)
    assert session.markers[chin] == "2.1"
    assert panel.redo_action.isEnabled() is False and panel.undo_action.text().startswith("Undo marker name: Assign")

    # Save session as…: suggested beside the project
    asked = {}

    def save_as(parent, caption, directory, *args, **kwargs):
        asked["directory"] = directory
        return str(tmp_path / "sung.h5"), ""

    monkeypatch.setattr(QFileDialog, "getSaveFileName", staticmethod(save_as))
    window.actions_by_id["mocap.save"].trigger()
    assert Path(asked["directory"]) == project / f"{STEM}.h5"
    assert mocap.state.undo_stack.isClean()
    saved = load_session(tmp_path / "sung.h5")
    assert saved.markers[chin] == "2.1" and marker_labels(saved)[chin] == "section14-2"

    mocap.state.set_session(None)
    mocap.open_session(tmp_path / "sung.h5")
    wait_jobs(qtbot)
    again = mocap.state.session
    assert again.markers[chin] == "2.1" and panel.table.item(chin, 1).text() == "2.1"
    assert not mocap.state.undo_stack.canUndo()

    # the names as a marker map, and the map onto the next take
    assert panel.save_map(tmp_path / "sing.map")
    assert read_mapping(tmp_path / "sing.map") == {"section14-2": "2.1"}


def test_a_marker_map_names_the_markers_in_one_step(head_window, qtbot, lab_take, tmp_path):
    window = head_window
    mocap, panel = window.mocap, window.mocap.names_panel
    session = import_take(window, qtbot, lab_take)
    lips = {"section14-2": "2.1", "section10-2": "8.1", "section13-2": "8.2", "section11-1": "8.3",
            "section12-1": "8.4", "Unlabeled1": "-"}
    write_mapping(tmp_path / "lab.map", lips)
    before = mocap.overlay.transform
    assert panel.load_map(tmp_path / "lab.map")
    assert {session.markers[i] for i, label in enumerate(marker_labels(session)) if label in lips} \
        == {"2.1", "8.1", "8.2", "8.3", "8.4", "Unlabeled1"}
    assert mocap.state.undo_stack.count() == 1
    # five markers now pair with the model's landmarks: the markers are fitted onto the face
    assert not np.allclose(mocap.overlay.transform[1], before[1])
    model = window.document.model
    window.playhead.set_frame(0)
    chin = mocap.overlay.to_model(session.positions[mocap.current_frame(), session.marker_index("2.1")])
    assert np.linalg.norm(chin - model.vertices[model.landmarks["2.1"]]) < 15.0
    assert {"2.1", "8.3", "8.4"} <= set(mocap.overlay.labels_visible)
    mocap.plot_dock.show_coordinate("2.1", "y")
    np.testing.assert_array_equal(mocap.plot_dock.plot.values, session.positions[:, session.marker_index("2.1"), 1])
    panel.undo_button.click()
    assert "2.1" not in session.markers and not mocap.state.undo_stack.canUndo()


def test_a_point_given_to_a_second_marker_leaves_the_first(head_window, qtbot, lab_take):
    window = head_window
    panel, session = window.mocap.names_panel, import_take(window, qtbot, lab_take)
    assert panel.assign("section14-2", "2.1")
    click_marker(window, qtbot, "section14-1")
    choose_point(panel, "2.1")
    panel.assign_button.click()
    assert marker_labels(session)[session.marker_index("2.1")] == "section14-1"
    assert "section14-2" in session.markers
    assert window.mocap.state.undo_stack.undoText() == "Assign 2.1 to section14-1"
    panel.unassign_button.click()
    assert "2.1" not in session.markers


def test_a_drag_turns_the_camera_and_picks_nothing(head_window, qtbot, lab_take):
    window = head_window
    mocap = window.mocap
    import_take(window, qtbot, lab_take)
    window.viewport.render_now()
    overlay = mocap.overlay
    x, y = window.viewport.world_to_widget(overlay.shown_points[overlay.shown_names.index("section14-2")])
    plotter = window.viewport.plotter
    camera = window.viewport.plotter.camera.position
    QTest.mousePress(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, QPoint(round(x), round(y)))
    QTest.mouseMove(plotter, QPoint(round(x) + 40, round(y) + 10))
    QTest.mouseRelease(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                       QPoint(round(x) + 40, round(y) + 10))
    assert mocap.plot_dock.marker != "section14-2"
    assert plotter.camera.position != camera


def test_the_error_column_and_the_frame_count_read_whole(head_window, qtbot):
    """Issue 30 §4: "…out error, RMS" (the column was cut at 1366 px) and "1 spans"."""
    window = head_window
    mocap = window.mocap
    window.layouts.reveal(mocap.pca_dock, task="mocap")
    mocap.pca_dock.tabs.setCurrentIndex(2)
    qtbot.wait(50)
    table = mocap.pca_dock.error_table
    header = table.horizontalHeader()
    metrics = QFontMetrics(header.font())
    margins = 2 * header.style().pixelMetric(QStyle.PixelMetric.PM_HeaderMargin)
    for column in range(table.columnCount()):
        text = table.horizontalHeaderItem(column).text()
        assert metrics.horizontalAdvance(text) + margins <= header.sectionSize(column), text
    take_plot = mocap.plot_dock
    mocap.state.set_session(import_marker_file(FACIAL_SING, reference=HEAD, up="Z"))
    mocap.state.add_span(10, 10, "a")
    assert take_plot.count_label.text() == "1 frame selected in 1 span"
    mocap.state.add_span(20, 22, "a")
    assert take_plot.count_label.text() == "4 frames selected in 2 spans"


def test_screenshot_of_named_markers(head_window, qtbot, lab_take, tmp_path):
    """docs/images/workbench-mocap-marker-names.png (AP_SCREENSHOT_DIR=docs/images to refresh it)."""
    folder = Path(SCREENSHOTS or tmp_path)
    window = head_window
    session = import_take(window, qtbot, lab_take)
    panel = window.mocap.names_panel
    for label, point in (("section14-2", "2.1"), ("section11-1", "8.3"), ("section12-1", "8.4"),
                         ("section10-2", "8.1")):
        assert panel.assign(label, point)
    click_marker(window, qtbot, "section13-2")
    window.playhead.set_frame(60)
    window.viewport.render_now()
    qtbot.wait(50)
    assert session.markers.count("2.1") == 1
    assert window.grab().save(str(folder / "workbench-mocap-marker-names.png"))
