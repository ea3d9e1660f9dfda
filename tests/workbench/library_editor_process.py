"""A real workbench process for the library editor's crash-recovery tests (not a test module itself).

Runs :func:`workbench.app.main` — the start-up, recovery offers and event loop
of ``python -m workbench`` — with the library editor driven as a user would:

``python -m tests.workbench.library_editor_process edit MODEL LIBRARY_FILE TEXT``
    Open the library editor (its Ctrl+L action), open LIBRARY_FILE in it, put
    the cursor at the end and type TEXT key by key (Return for each newline),
    then run until killed.
``python -m tests.workbench.library_editor_process recover|discard MODEL REPORT.json``
    Answer the library editor's recovery question with Recover or Discard,
    write the editor's state to REPORT.json once the window is up, then close
    the window (discarding unsaved library edits, as a user answering Discard).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QTextCursor
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QMessageBox

from workbench import app
from workbench.library_editor import LibraryEditor
from workbench.window.main_window import MainWindow

Button = QMessageBox.StandardButton
ANSWERS = {"recover": Button.Yes, "discard": Button.Discard}


def _when_window_is_up(action) -> None:
    """Call ``action(window)`` once :func:`workbench.app.main` has shown the window and made its offers."""
    windows = [w for w in QApplication.topLevelWidgets() if isinstance(w, MainWindow) and w.isVisible()]
    if windows:
        action(windows[0])
    else:
        QTimer.singleShot(50, lambda: _when_window_is_up(action))


def _type(library_file: str, text: str):
    def edit(window: MainWindow) -> None:
        window.actions_by_id["library.editor"].trigger()          # Library → Library editor (Ctrl+L)
        editor = window.library_editor
        assert editor.open_file(library_file)
        editor.text.moveCursor(QTextCursor.MoveOperation.End)
        for number, line in enumerate(text.split("\n")):
            if number:
                QTest.keyClick(editor.text, Qt.Key.Key_Return)
            if line:
                QTest.keyClicks(editor.text, line)
        print("typed", flush=True)
    return edit


def _report(path: str, asked: list[dict]):
    def report(window: MainWindow) -> None:
        editor = window.library_editor
        state = {"asked": asked, "text": editor.text.toPlainText(), "modified": editor.is_modified,
                 "path": str(editor.path) if editor.path is not None else None, "title": editor.title(),
                 "dock_visible": window.library_editor_dock.isVisible(),
                 "own_copy": window.autosaver.session.has_library_copy()}
        Path(path).write_text(json.dumps(state, indent=2), encoding="utf-8")
        QTimer.singleShot(0, window.close)
    return report


def run(argv: list[str]) -> int:
    verb, model, *rest = argv
    app.application()
    if verb == "edit":
        library_file, text = rest
        QTimer.singleShot(0, lambda: _when_window_is_up(_type(library_file, text)))
    else:
        (report_path,) = rest
        asked: list[dict] = []

        def ask_recover(_editor, copy):
            asked.append({"original": str(copy.original) if copy.original else None, "text": copy.text})
            return ANSWERS[verb]

        LibraryEditor.ask_recover = ask_recover
        LibraryEditor.ask_unsaved = lambda _editor, _reason: Button.Discard
        QTimer.singleShot(0, lambda: _when_window_is_up(_report(report_path, asked)))
    return app.main(model)


if __name__ == "__main__":
    sys.exit(run(sys.argv[1:]))
