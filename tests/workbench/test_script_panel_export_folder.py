"""Issue 30 §4: Say's Export… proposes the document's folder (then the one last exported to from it), and a
folder that does not exist keeps the dialog open (it is created only once the user agrees).

The dialog is opened with a mouse click on the script panel's Export… button and filled in with keys
and clicks, as a user does. One Festival run for the module (``spoken``, the export tests' fixture);
the WAV alone is written, so no video is encoded.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QApplication, QCheckBox, QDialogButtonBox, QLabel, QMessageBox

import engine
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from tests.workbench.test_script_panel_export import spoken as spoken  # the module's Festival run (a fixture)

DEFAULT_HEAD = engine.default_model_path()
pytestmark = [
    pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built"),
    pytest.mark.skipif(shutil.which("festival") is None or shutil.which("ffmpeg") is None,
                       reason="Festival or ffmpeg is not installed"),
]


def model_in(folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "head.xml"
    engine.save_model(build_synthetic_model(), path)
    return path


@pytest.fixture
def project_window(make_window, spoken, tmp_path):
    window = make_window(model_in(tmp_path / "project"))
    window.script_panel.adopt(spoken)
    return window


def in_dialog(qtbot, window, steps) -> list[str]:
    """Click Export… in the script panel and run ``steps(dialog)`` in the dialog (modal: from a timer).

    Returns what went wrong inside (an exception there must not leave the dialog open for ever).
    """
    failures: list[str] = []

    def run() -> None:
        dialog = QApplication.activeModalWidget()
        try:
            assert dialog is not None and dialog.objectName() == "script_panel.export_dialog"
            steps(dialog)
        except Exception as error:          # reported by the test, once the dialog is gone
            failures.append(f"{type(error).__name__}: {error}")
        if dialog is not None and dialog.isVisible():
            dialog.reject()

    QTimer.singleShot(0, run)
    qtbot.mouseClick(window.script_panel.export_button, Qt.MouseButton.LeftButton)
    return failures


def type_folder(qtbot, dialog, folder: Path) -> None:
    edit = dialog.folder_edit
    edit.setFocus()
    qtbot.keyClick(edit, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(edit, str(folder))


def only_wav(qtbot, dialog) -> None:
    """Tick the WAV file alone (each box says its file's ending: "…(….wav)")."""
    for box in dialog.findChildren(QCheckBox):
        if box.isChecked() != box.text().endswith(".wav)"):
            qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    assert [b.text()[-5:] for b in dialog.findChildren(QCheckBox) if b.isChecked()] == [".wav)"]


def press_export(qtbot, dialog) -> None:
    box = dialog.findChild(QDialogButtonBox)
    button = next(b for b in box.buttons() if b.text().replace("&", "") == "Export")
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def wait_for_export(qtbot, window) -> None:
    qtbot.waitUntil(lambda: not window.speech_exporter.busy, timeout=120000)


def test_export_proposes_the_documents_folder_then_the_one_last_exported_to(project_window, qtbot, tmp_path):
    window = project_window
    seen: dict[str, str] = {}
    exports = tmp_path / "exports"
    exports.mkdir()

    def first(dialog) -> None:
        seen["first"] = dialog.folder_edit.text()
        type_folder(qtbot, dialog, exports)
        only_wav(qtbot, dialog)
        press_export(qtbot, dialog)

    assert not in_dialog(qtbot, window, first)
    wait_for_export(qtbot, window)
    assert seen["first"] == str(tmp_path / "project"), "not the document's folder"
    assert [p.name for p in exports.iterdir()] and all(p.suffix == ".wav" for p in exports.iterdir())

    def second(dialog) -> None:
        seen["second"] = dialog.folder_edit.text()

    assert not in_dialog(qtbot, window, second)
    assert seen["second"] == str(exports), "the folder last exported to from this document"

    other = model_in(tmp_path / "other-project")                      # File → Open another model
    assert window.files.open_model(other)
    window.script_panel.adopt(window.script_panel.result)
    assert not in_dialog(qtbot, window, second)
    assert seen["second"] == str(tmp_path / "other-project")


def test_a_missing_folder_keeps_the_dialog_open_until_it_may_be_created(project_window, qtbot, tmp_path,
                                                                       monkeypatch):
    window = project_window
    missing = tmp_path / "new" / "takes"
    answers, asked = [QMessageBox.StandardButton.No, QMessageBox.StandardButton.Yes], []

    def question(parent, title, text, *args, **kwargs):
        asked.append(text)
        return answers.pop(0)

    monkeypatch.setattr(QMessageBox, "question", staticmethod(question))
    state: dict[str, object] = {}

    def steps(dialog) -> None:
        type_folder(qtbot, dialog, missing)
        only_wav(qtbot, dialog)
        press_export(qtbot, dialog)                                        # "Create it?" — No
        state["open after no"] = dialog.isVisible()
        state["message"] = " ".join(label.text() for label in dialog.findChildren(QLabel) if label.isVisible())
        state["typed"] = dialog.folder_edit.text()
        state["created after no"] = missing.exists()
        press_export(qtbot, dialog)                                        # again — Yes
        state["open after yes"] = dialog.isVisible()

    assert not in_dialog(qtbot, window, steps)
    wait_for_export(qtbot, window)
    assert state["open after no"] and not state["created after no"]
    assert "does not exist" in state["message"] and state["typed"] == str(missing)
    assert len(asked) == 2 and str(missing) in asked[0]
    assert not state["open after yes"]
    assert missing.is_dir() and [p.suffix for p in missing.iterdir()] == [".wav"]
    assert "Exported" in window.statusBar().currentMessage()


def test_an_impossible_export_is_said_in_the_dialog_which_stays_open(project_window, qtbot, tmp_path):
    window = project_window
    state: dict[str, object] = {}

    def steps(dialog) -> None:
        type_folder(qtbot, dialog, tmp_path)
        edit = dialog.base_edit
        edit.setFocus()
        qtbot.keyClick(edit, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
        qtbot.keyClicks(edit, "a/b")
        press_export(qtbot, dialog)
        state["open"] = dialog.isVisible()
        state["message"] = " ".join(label.text() for label in dialog.findChildren(QLabel) if label.isVisible())

    assert not in_dialog(qtbot, window, steps)
    assert state["open"] and "not a file name" in state["message"]
    assert not window.speech_exporter.busy
    assert sorted(p.name for p in tmp_path.iterdir()) == ["project"]        # nothing written
