"""The File menu on the real window: new from mesh, open, save, save as, recent files, unsaved changes."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QSettings, QTimer
from PySide6.QtWidgets import QApplication, QFileDialog, QMessageBox

import engine
from engine.formats.mesh_io import write_mesh
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from tests.workbench.workbench_model_state import model_state
from workbench import settings
from workbench.document.undo_commands import AddParameterCommand, RenameParameterCommand, WeightsChangedCommand
from workbench.window.file_controller import is_shipped
from workbench.window.recent_files import add_recent_file, recent_files

Button = QMessageBox.StandardButton


@pytest.fixture
def captured_errors(monkeypatch):
    """QMessageBox.critical records its message instead of blocking the test."""
    errors: list[tuple[str, str]] = []

    def critical(parent, title, text, *args, **kwargs):
        errors.append((title, text))
        return Button.Ok

    monkeypatch.setattr(QMessageBox, "critical", staticmethod(critical))
    return errors


@pytest.fixture
def answer_unsaved(window, monkeypatch):
    """Answer the unsaved-changes question with the button set in ``asked.answer``; record the questions."""
    class Asked(list):
        answer = Button.Cancel

    asked = Asked()

    def ask(doing):
        asked.append(doing)
        return asked.answer

    monkeypatch.setattr(window.files, "ask_unsaved", ask)
    return asked


def _edit(window):
    """A few model edits of different kinds."""
    document = window.document
    skin = document.model.part_vertices("skin")[::4]
    document.push(WeightsChangedCommand(document, "jaw_open", skin, np.linspace(0, 1, len(skin))))
    document.push(RenameParameterCommand(document, "brow_raise", "brows_up"))
    document.push(AddParameterCommand(document, engine.Parameter("cheek_puff", "translation", parent="head_turn",
                                                                  direction=(0, 0, 3), minimum=0),
                                      engine.InfluenceRegion(skin[:20], np.full(20, 0.5))))


def _by_name(state: dict) -> dict:
    """A model state with the parameters keyed by name (a saved file lists the tree depth-first)."""
    state = dict(state)
    state["parameters"] = {p[0]: p for p in state["parameters"]}
    return state


def _set_dialog(monkeypatch, name, result):
    monkeypatch.setattr(QFileDialog, name, staticmethod(lambda *a, **k: result))


# ---------------------------------------------------------------------------
# save / open
# ---------------------------------------------------------------------------

def test_save_as_then_open_round_trips_every_edit(window, tmp_path, monkeypatch, captured_errors):
    _edit(window)
    edited = model_state(window.document.model)
    target = tmp_path / "edited" / "head.xml"
    _set_dialog(monkeypatch, "getSaveFileName", (str(target), ""))
    window.actions_by_id["file.save_as"].trigger()

    assert not captured_errors
    assert window.document.path == target and not window.isWindowModified()
    assert window.windowTitle() == "head.xml[*] — Artificial Person"
    assert target.exists() and target.with_suffix(".h5").exists()
    assert _by_name(model_state(engine.load_model(target))) == _by_name(edited)

    window.document.replace_model(build_synthetic_model())        # something else in between
    assert window.files.open_model(target)
    assert _by_name(model_state(window.document.model)) == _by_name(edited)
    assert list(window.parameter_panel.rows) == ["head_turn", "jaw_open", "brows_up", "cheek_puff"]
    assert window.document.undo_stack.count() == 0 and not window.isWindowModified()


def test_save_writes_to_the_models_file_without_asking(window, tmp_path, monkeypatch, captured_errors):
    path = engine.save_model(build_synthetic_model(), tmp_path / "mine.xml")
    assert window.files.open_model(path)
    _edit(window)
    _set_dialog(monkeypatch, "getSaveFileName", AssertionError("no dialog expected"))
    window.actions_by_id["file.save"].trigger()
    assert not window.isWindowModified() and not captured_errors
    assert _by_name(model_state(engine.load_model(path))) == _by_name(model_state(window.document.model))
    assert "Saved" in window.statusBar().currentMessage()


def test_save_never_overwrites_the_shipped_head(window, monkeypatch):
    shipped = engine.default_model_path()
    assert is_shipped(shipped) and not is_shipped(window.document.path)
    window.document._set_path(shipped)          # as if the workbench had been started on the default head
    _edit(window)
    asked = []
    monkeypatch.setattr(QFileDialog, "getSaveFileName",
                        staticmethod(lambda *a, **k: asked.append(a) or ("", "")))
    assert not window.files.save()               # Save became Save as…, and the user cancelled
    assert len(asked) == 1 and window.isWindowModified()


def test_a_failed_save_says_why_and_keeps_the_changes(window, tmp_path, captured_errors):
    _edit(window)
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    assert not window.files.save_model(blocker / "head.xml")
    assert len(captured_errors) == 1 and "cannot save model" in captured_errors[0][0]
    assert "Traceback" not in captured_errors[0][1]
    assert window.isWindowModified() and window.document.path.name == "synthetic-head.xml"


def test_opening_a_bad_file_shows_file_and_line_and_changes_nothing(window, broken_model_path, monkeypatch,
                                                                     captured_errors):
    _edit(window)
    before = model_state(window.document.model)
    monkeypatch.setattr(window.files, "ask_unsaved", lambda doing: Button.Discard)
    _set_dialog(monkeypatch, "getOpenFileName", (str(broken_model_path), ""))
    assert not window.files.open_dialog()
    [(title, text)] = captured_errors
    assert "cannot open model" in title
    assert re.match(rf"{re.escape(str(broken_model_path))}:\d+: ", text)      # file:line: what is wrong
    assert model_state(window.document.model) == before
    assert window.document.undo_stack.count() == 3


# ---------------------------------------------------------------------------
# new from mesh
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", [".obj", ".ply", ".stl"])
def test_new_from_mesh_starts_an_untitled_model(window, tmp_path, monkeypatch, suffix, captured_errors):
    source = build_synthetic_model()
    mesh = tmp_path / f"scan{suffix}"
    if suffix == ".stl":
        import pyvista as pv

        pv.PolyData(source.vertices, source.faces).triangulate().save(mesh)
    else:
        write_mesh(mesh, source.vertices, source.faces)
    _set_dialog(monkeypatch, "getOpenFileName", (str(mesh), ""))
    window.actions_by_id["file.new_from_mesh"].trigger()

    assert not captured_errors
    model = window.document.model
    assert model.name == "scan" and len(model.parameters) == 0
    assert window.document.path is None
    assert window.windowTitle() == "untitled[*] — Artificial Person"
    assert window.parameter_panel.rows == {}
    shown = window.viewport.displayed_points()
    if suffix != ".stl":      # STL stores every triangle's corners anew; the others keep the vertex order
        # (PLY holds single-precision floats)
        np.testing.assert_allclose(model.vertices, source.vertices, rtol=1e-7, atol=1e-5)
        np.testing.assert_array_equal(shown, model.vertices)
    assert "New model from" in window.statusBar().currentMessage()

    # An untitled model has no file yet: Save asks for one.
    target = tmp_path / "from-scan.xml"
    _set_dialog(monkeypatch, "getSaveFileName", (str(target), ""))
    assert window.files.save()
    assert window.document.path == target and engine.load_model(target).n_vertices == model.n_vertices


def test_a_file_that_is_not_a_mesh_gives_a_dialog(window, tmp_path, captured_errors):
    bad = tmp_path / "notes.ply"
    bad.write_text("this is not a mesh\n")
    model = window.document.model
    assert not window.files.new_from_mesh(bad)
    [(title, text)] = captured_errors
    assert "cannot import mesh" in title and str(bad) in text and "Traceback" not in text
    assert window.document.model is model


# ---------------------------------------------------------------------------
# unsaved changes
# ---------------------------------------------------------------------------

def test_closing_with_unsaved_changes_asks_and_cancel_keeps_the_window(window, answer_unsaved):
    _edit(window)
    answer_unsaved.answer = Button.Cancel
    assert not window.close()
    assert window.isVisible() and answer_unsaved == ["closing"]
    assert not window.viewport.plotter._closed


def test_discard_closes_without_saving(window, answer_unsaved, synthetic_model_path):
    stamp = synthetic_model_path.stat().st_mtime_ns
    _edit(window)
    answer_unsaved.answer = Button.Discard
    assert window.close()
    assert not window.isVisible()
    assert synthetic_model_path.stat().st_mtime_ns == stamp


def test_save_on_close_writes_the_file_then_closes(make_window, tmp_path, monkeypatch):
    path = engine.save_model(build_synthetic_model(), tmp_path / "to-close.xml")
    window = make_window(path)
    _edit(window)
    edited = model_state(window.document.model)
    monkeypatch.setattr(window.files, "ask_unsaved", lambda doing: Button.Save)
    assert window.close()
    assert _by_name(model_state(engine.load_model(path))) == _by_name(edited)


def test_no_question_when_nothing_changed(window, answer_unsaved):
    window.document.set_value("jaw_open", 0.5)            # a pose is not a change to the model
    assert window.close()
    assert answer_unsaved == []


def test_open_and_new_ask_first_and_cancel_stops_them(window, answer_unsaved, monkeypatch):
    _edit(window)
    model = window.document.model
    _set_dialog(monkeypatch, "getOpenFileName", AssertionError("no file dialog after Cancel"))
    answer_unsaved.answer = Button.Cancel
    assert not window.files.open_dialog()
    assert not window.files.new_from_mesh_dialog()
    assert not window.files.open_recent(window.document.path)
    assert answer_unsaved == ["opening another model", "starting a new model", "opening another model"]
    assert window.document.model is model and window.isWindowModified()


def test_the_real_question_offers_save_discard_and_cancel(window, qtbot, monkeypatch, unexpected_dialogs):
    """The dialog itself, not a stand-in: found on screen and answered with a click."""
    monkeypatch.undo()                               # the real QMessageBox.warning
    _edit(window)
    seen = {}

    def answer():
        box = next(w for w in QApplication.topLevelWidgets() if isinstance(w, QMessageBox) and w.isVisible())
        seen["buttons"] = {box.standardButton(b) for b in box.buttons()}
        seen["text"] = box.text()
        box.button(Button.Cancel).click()

    QTimer.singleShot(100, answer)
    assert not window.close()
    assert seen["buttons"] == {Button.Save, Button.Discard, Button.Cancel}
    assert "synthetic-head.xml" in seen["text"] and "closing" in seen["text"]
    assert window.isVisible()


# ---------------------------------------------------------------------------
# recent files
# ---------------------------------------------------------------------------

def test_recent_files_newest_first_at_most_eight_missing_ones_pruned(window, tmp_path, qtbot):
    paths = [engine.save_model(build_synthetic_model(f"head-{i}"), tmp_path / f"head-{i}.xml") for i in range(10)]
    for path in paths:
        assert window.files.open_model(path)
    expected = [p.resolve() for p in reversed(paths)][:8]
    assert recent_files() == expected
    menu = window.recent_menu
    menu.rebuild()
    actions = menu.file_actions()
    assert [a.text() for a in actions] == [f"&{i} head-{9 - i + 1}.xml" for i in range(1, 9)]
    assert [a.data() for a in actions] == [str(p) for p in expected]

    paths[8].unlink()                               # a file that went away is dropped from the list
    menu.rebuild()
    assert [Path(a.data()).name for a in menu.file_actions()][:2] == ["head-9.xml", "head-7.xml"]
    assert str(paths[8].resolve()) not in settings.string_list(settings.RECENT_FILES)

    # Choosing one opens it (nothing unsaved, so no question).
    target = next(a for a in menu.file_actions() if a.data().endswith("head-5.xml"))
    target.trigger()
    assert window.document.model.name == "head-5"
    assert recent_files()[0].name == "head-5.xml"

    clear = next(a for a in menu.actions() if a.text() == "&Clear list")
    clear.trigger()
    assert recent_files() == [] and menu.file_actions() == []


def test_saving_adds_to_recent_files_and_the_list_survives_a_restart(window, tmp_path):
    target = tmp_path / "saved.xml"
    assert window.files.save_model(target)
    assert recent_files()[0] == target.resolve()
    QSettings().sync()
    add_recent_file(target)                          # adding again does not duplicate it
    assert settings.string_list(settings.RECENT_FILES).count(str(target.resolve())) == 1


def test_file_menu_lists_the_commands_in_order(window):
    texts = [a.text() for a in window.menus["&File"].actions() if not a.isSeparator()]
    assert texts == ["&New from mesh…", "New head from &photographs…", "&Open model…", "Open &recent", "&Save",
                     "Save model &as…", "&Export", "Import &capture stream…", "&Quit"]
    assert [a.text() for a in window.menus["&File/&Export"].actions()] == ["&Configuration…", "&glTF…"]
    assert [m.title() for m in window.menuBar().findChildren(type(window.menus["&File"]))
            if m.parent() is window.menuBar()][:4] == ["&File", "&Edit", "&Pose", "&View"]
