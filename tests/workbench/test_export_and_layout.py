"""Export configuration (model + library files + README) and the remembered window layout."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QSettings, Qt, QTimer
from PySide6.QtWidgets import QApplication, QDialogButtonBox, QLabel, QMessageBox

import engine
from engine.commands import load_library
from engine.outputs.configuration_export import export_configuration
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from tests.workbench.workbench_model_state import model_state
from workbench import settings
from workbench.document.undo_commands import WeightsChangedCommand
from workbench.window.export_folder_dialog import ExportFolderDialog
from workbench.window.tool_options import NO_TOOL

Button = QMessageBox.StandardButton
MY_JAW = """# A user's own JawOpen: wider.
$command = JawOpen
$mandatory = at
$optional = amplitude=100, onset=100, apex=300, offset=100
jaw_open = 1
$proc = attack-hold-release
"""


def test_export_writes_the_model_the_library_files_it_uses_and_a_readme(window, tmp_path, monkeypatch):
    mine = tmp_path / "my-commands"
    mine.mkdir()
    (mine / "WideJaw.lib").write_text(MY_JAW)
    QSettings().setValue(settings.LIBRARY_FOLDERS, [str(mine)])
    document = window.document
    document.push(WeightsChangedCommand(document, "jaw_open", [0, 1], [0.5, 0.5]))
    target = tmp_path / "for-anna"
    monkeypatch.setattr(window.files, "ask_export_folder", lambda: target)
    target.mkdir()                                  # an empty folder: no question

    window.actions_by_id["file.export"].trigger()

    exported = engine.load_model(target / "model" / "synthetic-head.xml")
    assert model_state(exported)["regions"] == model_state(document.model)["regions"]
    # The synthetic head has head_turn, jaw_open and brow_raise: the commands on those fit, the
    # user's JawOpen overrides the shipped one, so the shipped JawOpen.lib is not needed.
    assert sorted(p.name for p in (target / "library").iterdir()) == ["BrowRaise.lib", "HeadShake.lib",
                                                                     "HeadTurn.lib"]
    assert sorted(p.name for p in (target / "library-user-1").iterdir()) == ["WideJaw.lib"]
    readme = (target / "README.txt").read_text()
    assert "model/synthetic-head.xml" in readme and "-L library -L library-user-1" in readme
    assert "Blink" in readme                       # a command left out, with the reason
    # The colleague's view: the exported folders give the same commands, and they fit the model.
    library = load_library([target / "library", target / "library-user-1"], shipped=False)
    assert {"BrowRaise", "HeadTurn", "JawOpen"} <= set(library.names())
    assert library["JawOpen"].curves[0].name == "jaw_open" and "library-user-1" in library["JawOpen"].file
    assert window.isWindowModified()               # exporting is not saving
    assert "Exported" in window.statusBar().currentMessage()


def test_export_into_a_non_empty_folder_asks_first(window, tmp_path, monkeypatch):
    target = tmp_path / "busy"
    target.mkdir()
    (target / "notes.txt").write_text("mine")
    monkeypatch.setattr(window.files, "ask_export_folder", lambda: target)
    asked = []
    monkeypatch.setattr(QMessageBox, "question", staticmethod(lambda *a, **k: asked.append(a) or Button.Cancel))
    assert not window.files.export_dialog()
    assert len(asked) == 1 and sorted(p.name for p in target.iterdir()) == ["notes.txt"]


def _answer_export_folder(qtbot, folder, seen: list) -> None:
    """When the Export configuration dialog is up, type ``folder`` into it and press Export (any other
    dialog is closed, so a test of the old folder chooser fails instead of hanging)."""
    def answer():
        dialog = QApplication.activeModalWidget()
        if dialog is None:
            QTimer.singleShot(20, answer)
            return
        seen.append(dialog)
        if not isinstance(dialog, ExportFolderDialog):
            dialog.reject()
            return
        dialog.folder_edit.setText(str(folder))
        qtbot.mouseClick(dialog.buttons.button(QDialogButtonBox.StandardButton.Ok), Qt.MouseButton.LeftButton)

    QTimer.singleShot(20, answer)


def test_export_into_a_new_folder_names_the_model_after_its_file(make_window, synthetic_model_path, tmp_path,
                                                                 qtbot):
    """A copy of the head saved as painted.xml still calls itself synthetic-head inside: the status bar and
    the exported files use the name the user knows, and a folder that does not exist yet is made."""
    painted = tmp_path / "painted.xml"
    engine.save_model(engine.load_model(synthetic_model_path), painted)
    window = make_window(painted)
    label = window.statusBar().model_label.text()
    assert label.startswith("painted.xml · ") and "synthetic-head" not in label
    target = tmp_path / "new" / "for-anna"
    seen: list = []
    _answer_export_folder(qtbot, target, seen)

    window.actions_by_id["file.export"].trigger()

    assert len(seen) == 1 and "model/painted.xml" in seen[0].findChild(QLabel, "what_is_written").text()
    assert sorted(p.name for p in (target / "model").iterdir()) == ["painted.h5", "painted.xml"]
    assert "model/painted.xml" in (target / "README.txt").read_text()
    message = window.statusBar().currentMessage()
    assert message.startswith("Exported model/painted.xml and ") and message.endswith(f"library files to {target}")


def test_an_untitled_model_exports_under_its_name_and_the_status_bar_follows_the_file(window, tmp_path):
    window.document.replace_model(build_synthetic_model(name="scan"), None)    # as New from mesh makes it
    assert window.statusBar().model_label.text().startswith("scan · ")
    assert window.files.export_configuration(tmp_path / "out")
    assert (tmp_path / "out" / "model" / "scan.xml").is_file()
    assert window.files.save_model(tmp_path / "renamed.xml")
    assert window.statusBar().model_label.text().startswith("renamed.xml · ")


def test_a_broken_user_library_stops_the_export_with_file_and_line(window, tmp_path, monkeypatch):
    mine = tmp_path / "broken-commands"
    mine.mkdir()
    (mine / "Bad.lib").write_text("$command = Bad\njaw_open = 1\n$proc = no-such-procedure\n")
    QSettings().setValue(settings.LIBRARY_FOLDERS, [str(mine)])
    errors = []
    monkeypatch.setattr(QMessageBox, "critical", staticmethod(lambda p, title, text, *a: errors.append(text)))
    assert not window.files.export_configuration(tmp_path / "out")
    assert len(errors) == 1 and errors[0].startswith(f"{mine / 'Bad.lib'}:")


def test_export_configuration_is_plain_python(tmp_path, synthetic_model_path):
    model = engine.load_model(synthetic_model_path)
    summary = export_configuration(model, tmp_path / "plain", source=synthetic_model_path)
    assert summary.library_args() == ["-L", "library"]
    assert str(synthetic_model_path) in (tmp_path / "plain" / "README.txt").read_text()
    assert all((tmp_path / "plain" / f).is_file() for f in summary.library_files)


def test_tool_options_dock_waits_for_a_tool(window):
    dock = window.tool_options
    assert dock.windowTitle() == "Tool options" and dock.isVisible()
    assert window.dockWidgetArea(dock) == Qt.DockWidgetArea.RightDockWidgetArea
    assert dock.current_tool == NO_TOOL
    assert "No tool" in dock.page(NO_TOOL).text() and dock.page(NO_TOOL).isVisible()
    page = QLabel("brush radius …")
    dock.add_page("test-tool", page)
    dock.show_page("test-tool")
    assert dock.current_tool == "test-tool" and dock.page("test-tool") is page and page.isVisible()
    dock.show_page()
    assert dock.current_tool == NO_TOOL
    toggle = dock.toggleViewAction()
    assert toggle in window.menus["&View"].actions()
    toggle.trigger()
    assert not dock.isVisible()


def test_every_tool_page_fits_the_default_column_without_scrolling_sideways(window, qtbot):
    """Tool pages scroll down when tall, never sideways: the right column is at least as wide as the
    widest page needs, and texts that name a parameter wrap instead of widening it."""
    model = window.document.model
    longest = max(model.parameters.names, key=len)
    window.view_state.select_parameter(longest)
    dock = window.tool_options
    for tool in list(dock._holders):
        dock.show_page(tool)
        qtbot.wait(10)
        holder, page = dock._holders[tool], dock.page(tool)
        assert page.width() >= page.minimumSizeHint().width(), f"the {tool!r} page is cut off on the right"
        assert page.width() <= holder.viewport().width(), f"the {tool!r} page is wider than its place"
    dock.show_page()


def test_window_layout_is_remembered(make_window, synthetic_model_path, qtbot):
    first = make_window(synthetic_model_path, size=(1100, 700))
    first.tool_options.hide()
    qtbot.wait(20)
    default = first.parameter_dock.width()
    first.resizeDocks([first.parameter_dock], [default - 50], Qt.Orientation.Horizontal)
    qtbot.waitUntil(lambda: first.parameter_dock.width() != default)
    width = first.parameter_dock.width()
    assert first.close()
    assert QSettings().value(settings.WINDOW_GEOMETRY) is not None

    second = make_window(synthetic_model_path, size=None)
    assert not second.tool_options.isVisible()
    assert (second.width(), second.height()) == (1100, 700)
    qtbot.wait(50)
    assert abs(second.parameter_dock.width() - width) <= 2


@pytest.mark.parametrize("key, value, expected", [(None, None, 60.0), ("0.5", None, 0.5), ("-3", None, 60.0),
                                                  ("soon", None, 60.0)])
def test_autosave_interval_setting_is_read_safely(key, value, expected):
    if key is not None:
        QSettings().setValue(settings.AUTOSAVE_INTERVAL, key)
    assert settings.autosave_interval_seconds() == expected
    assert np.isfinite(settings.autosave_interval_seconds())
