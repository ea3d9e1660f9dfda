"""The library editor in a real window on the synthetic head (head_turn → jaw_open, brow_raise)."""

from __future__ import annotations

import os
import weakref

import numpy as np
import pytest
import shiboken6
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox, QWidget

from engine.commands import load_library, parse_commands_text, translate
from engine.timeline.timeline import Timeline

GOOD = """# brow_raise swung up and down, count times
$command = BrowSwing
$description = brows up and down
$mandatory = at
$optional = amplitude=100, count=2, period=400
$interp = cosine
brow_raise = 0,0; 200,0.8; 400,0
$proc = periodic
"""


@pytest.fixture
def window(qtbot, make_window, synthetic_model_path):
    """The main window on the synthetic head; its library edits are forgotten before pytest-qt closes it.

    pytest-qt closes its widgets in the order they were registered, before
    fixtures tear down: a widget registered before the window gets the chance.
    """
    windows = []
    sentinel = QWidget()
    qtbot.addWidget(sentinel, before_close_func=lambda _w: [forget_library_edits(w()) for w in windows])
    window = make_window(synthetic_model_path)
    windows.append(weakref.ref(window))
    window.library_test_sentinel = sentinel          # pytest-qt holds widgets only weakly
    return window


def forget_library_edits(window) -> None:
    if window is not None and shiboken6.isValid(window):
        window.library_editor.text.document().setModified(False)


@pytest.fixture
def editor(window):
    window.library_editor_dock.show()
    return window.library_editor


def type_text(qtbot, widget, text: str) -> None:
    """Type ``text`` key by key, Return for each new line, as a user would."""
    for number, line in enumerate(text.split("\n")):
        if number:
            qtbot.keyClick(widget, Qt.Key.Key_Return)
        if line:
            qtbot.keyClicks(widget, line)


def wait_checked(qtbot, editor) -> None:
    """Until the debounced check after the last keystroke has run."""
    qtbot.waitUntil(lambda: not editor.check_pending)


def replace_line(qtbot, editor, line: int, text: str) -> None:
    editor.text.go_to_line(line)
    qtbot.keyClick(editor.text, Qt.Key.Key_End, Qt.KeyboardModifier.ShiftModifier)
    qtbot.keyClicks(editor.text, text)


def test_typing_an_error_marks_its_line_and_fixing_it_clears_the_mark(window, editor, qtbot):
    editor.set_text("")
    editor.text.setFocus()
    type_text(qtbot, editor.text, GOOD.replace("$interp = cosine", "$interp = wobbly"))
    wait_checked(qtbot, editor)
    assert editor.text.error_lines() == [6]
    assert "unknown interpolation 'wobbly'" in editor.text.problems[6]
    assert "line 6" in editor.status.text()
    assert editor.is_modified and editor.title().endswith("untitled.lib*")

    replace_line(qtbot, editor, 6, "$interp = cosine")
    wait_checked(qtbot, editor)
    assert editor.text.error_lines() == []
    assert editor.text.extraSelections() == []
    assert "fits the model" in editor.status.text()
    assert editor.command_choice.currentText() == "BrowSwing"

    # A parameter the open model does not have: the engine's binding check, at the line that names it.
    replace_line(qtbot, editor, 7, "brow_lift = 0,0; 200,0.8; 400,0")
    wait_checked(qtbot, editor)
    assert editor.text.error_lines() == [7]
    assert "does not have" in editor.text.problems[7]
    replace_line(qtbot, editor, 7, "brow_raise = 0,0; 200,0.8; 400,0")
    wait_checked(qtbot, editor)
    assert editor.text.error_lines() == []


def test_the_plot_shows_the_translated_curves_for_the_chosen_arguments(window, editor, qtbot, tmp_path):
    editor.set_text(GOOD)
    assert set(editor.form.spin_boxes) == {"amplitude", "count", "period"}
    assert editor.form.spin_boxes["period"].value() == 400
    editor.form.set_value("count", 3)
    editor.form.set_value("amplitude", 50)

    (tmp_path / "BrowSwing.lib").write_text(GOOD)
    script = parse_commands_text('<commands><BrowSwing at="0" count="3" amplitude="50"/></commands>')
    model = window.document.model
    timeline = Timeline(translate(script, load_library([tmp_path]), model), model)
    times, values = editor.plot.curves["brow_raise"]
    assert list(editor.plot.curves) == ["brow_raise"]
    assert times[0] == 0 and times[-1] == timeline.end == 1200
    column = timeline.parameters.index("brow_raise")
    np.testing.assert_allclose(values, timeline.sample(times)[:, column], atol=1e-12)
    assert values.max() == pytest.approx(0.4)                    # 0.8 at 50 %

    editor.form.set_value("count", 0)                            # no action: said, not raised
    assert editor.plot.curves == {}
    assert "count must be positive" in editor.plot.message
    assert not editor.preview_button.isEnabled()


def test_preview_plays_the_translated_tracks_through_the_player(window, editor, qtbot, tmp_path):
    editor.set_text(GOOD)
    editor.form.set_value("count", 1)
    qtbot.mouseClick(editor.preview_button, Qt.MouseButton.LeftButton)
    player = window.player
    assert player.timeline is not None and player.is_playing
    player.pause()

    (tmp_path / "BrowSwing.lib").write_text(GOOD)
    script = parse_commands_text('<commands><BrowSwing at="0" count="1"/></commands>')
    model = window.document.model
    expected = Timeline(translate(script, load_library([tmp_path]), model), model)
    assert window.playhead.duration == pytest.approx(expected.end / 1000)
    for seconds in (0.05, 0.2, 0.33):
        window.playhead.set_time(seconds)
        assert window.document.value("brow_raise") == pytest.approx(expected.values_at(seconds * 1000)["brow_raise"])
    assert window.document.value("brow_raise") != 0


def test_save_writes_atomically_and_the_library_reloads(window, editor, qtbot, tmp_path, monkeypatch,
                                                       unexpected_dialogs):
    window.library_sources.set_folders([tmp_path])
    assert editor.new_from_template("Twitch", "once", "jaw_open")
    assert editor.result.ok and editor.is_modified
    target = tmp_path / "Twitch.lib"
    assert editor.save_as(target)
    assert target.read_text() == editor.text.toPlainText()
    assert not editor.is_modified and editor.path == target
    assert editor.command_list.commands["Twitch"] == target
    assert "Twitch" in load_library([tmp_path])

    # A failing rename leaves the old file whole and the edits in the editor.
    editor.text.appendPlainText("# one more comment")
    before = target.read_bytes()

    def failing_replace(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", failing_replace)
    warnings = []
    monkeypatch.setattr(QMessageBox, "warning", lambda parent, title, text, *a: warnings.append(text))
    assert not editor.save()
    assert target.read_bytes() == before
    assert editor.is_modified
    assert warnings and "Twitch.lib" in warnings[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["Twitch.lib"]       # no temporary file left


def test_closing_the_window_asks_about_unsaved_library_edits(window, editor, qtbot, monkeypatch):
    editor.set_text(GOOD)
    editor.text.appendPlainText("# an edit")
    asked = []

    def answer(button):
        def question(parent, title, text, *args):
            asked.append(text)
            return button
        return question

    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.Cancel))
    assert not window.close()
    assert window.isVisible() and editor.is_modified and "untitled.lib" in asked[0]

    monkeypatch.setattr(QMessageBox, "question", answer(QMessageBox.StandardButton.Discard))
    assert window.close()
    assert len(asked) == 2


def test_library_folders_list_user_commands_after_the_shipped_ones(window, editor, tmp_path):
    (tmp_path / "BrowSwing.lib").write_text(GOOD)
    window.library_sources.set_folders([tmp_path])
    assert editor.command_list.commands["BrowSwing"] == tmp_path / "BrowSwing.lib"
    assert "HeadNod" in editor.command_list.commands
    top = editor.command_list.topLevelItem(1)
    assert top.text(0).startswith("User folder 1") and top.child(0).child(0).text(0) == "BrowSwing"
    assert editor.open_file(tmp_path / "BrowSwing.lib")
    assert editor.text.toPlainText() == GOOD and not editor.is_modified


def test_an_empty_editor_shows_what_to_type_and_no_error(window, editor, qtbot, monkeypatch):
    # Never touched: a neutral hint and an example, no red mark anywhere.
    assert editor.is_blank and not editor.is_modified
    assert editor.result.problems == [] and editor.text.problems == {} and editor.text.error_lines() == []
    assert editor.text.extraSelections() == []
    assert "New command" in editor.status.text() and "#c0392b" not in editor.status.styleSheet()
    assert "$command = MyGesture" in editor.text.placeholderText()
    assert "head_turn = 0,0" in editor.text.placeholderText()      # the open model's first parameter
    assert editor.plot.message.startswith("Nothing to plot yet")
    opened = []
    monkeypatch.setattr(editor, "new_dialog", lambda: opened.append("new"))
    editor.status.linkActivated.emit("new")                        # the hint's link starts a template
    assert opened == ["new"]

    editor.text.setFocus()
    type_text(qtbot, editor.text, "\n   \n")                        # blank lines are still nothing to check
    wait_checked(qtbot, editor)
    assert editor.result.problems == [] and editor.text.error_lines() == []

    type_text(qtbot, editor.text, "# a comment and no command")     # text that is wrong: now it is said
    wait_checked(qtbot, editor)
    assert list(editor.text.problems) == [1] and "no command" in editor.status.text()
    assert "#c0392b" in editor.status.styleSheet()

    editor.text.selectAll()
    qtbot.keyClick(editor.text, Qt.Key.Key_Delete)                   # empty again: the hint comes back
    wait_checked(qtbot, editor)
    assert editor.text.problems == {} and "New command" in editor.status.text()

    editor.set_text("")                                              # a new, empty file: the same
    assert editor.result.problems == [] and editor.text.error_lines() == []
