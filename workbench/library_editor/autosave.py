"""Autosave and crash recovery for the library editor's unsaved text, alongside the model's.

The text goes into the window's recovery session
(``context.autosaver().session``, :class:`workbench.window.recovery.RecoverySession`)
as ``<id>.library.json``, with the library file it belongs to (or none, for a
new file). It is written every autosave interval (the model's:
``autosave/interval_seconds``) while the text has unsaved edits and differs
from the last copy, and removed when the file is saved, its edits are
discarded or the window closes cleanly.

A workbench that crashed leaves the copy behind; at the next start
:meth:`LibraryAutosaver.offer_recovery` offers it. Recovering puts the text
back in the editor, belonging to its file and marked unsaved: nothing is
written to the library file until the user saves.
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, QTimer, Signal
from PySide6.QtWidgets import QMessageBox

from engine.errors import UserError

from .. import settings
from ..window.recovery import LibraryCopy, RecoverySession, orphaned_library_copies

if TYPE_CHECKING:
    from .editor import LibraryEditor

MESSAGE_MS = 4000
Button = QMessageBox.StandardButton


class LibraryAutosaver(QObject):
    """Keeps a recovery copy of one library editor's unsaved text.

    The timer runs only while the text is modified. The recovery session is
    the main window's, looked up when needed (the editor is built before the
    window's autosaver); without one nothing is written.

    Signals
    -------
    autosaved(str)
        The copy was written to this path.
    failed(str)
        Writing it failed; the message says why.
    """

    autosaved = Signal(str)
    failed = Signal(str)

    def __init__(self, editor: LibraryEditor):
        super().__init__(editor)
        self._editor = editor
        self._written: tuple[str, str] | None = None     # (text, file) of the last copy
        self.timer = QTimer(self)
        self.timer.timeout.connect(self.autosave_now)
        editor.text.modificationChanged.connect(self._on_modification_changed)

    @property
    def session(self) -> RecoverySession | None:
        autosaver = self._editor.context.autosaver()
        return autosaver.session if autosaver is not None else None

    def autosave_now(self) -> bool:
        """Write the copy now if the text has unsaved edits and changed since the last copy."""
        editor, session = self._editor, self.session
        if session is None or not editor.is_modified or editor.edits_discarded:
            return False
        text = editor.text.toPlainText()
        written = (text, str(editor.path))
        if written == self._written and session.has_library_copy():
            return False
        try:
            session.write_library_text(text, editor.path)
        except (UserError, OSError) as exc:
            self.failed.emit(str(exc))
            return False
        self._written = written
        self.autosaved.emit(str(session.library_path))
        return True

    def clear(self) -> None:
        """Remove the copy (the file was saved, or its edits discarded)."""
        self._written = None
        session = self.session
        if session is not None:
            session.clear_library()

    # -- crash recovery ----------------------------------------------------------
    def offer_recovery(self) -> bool:
        """Offer the newest library text a crashed workbench left behind; True if it was recovered.

        Copies older than their library file are stale and removed unasked.
        The question is :meth:`LibraryEditor.ask_recover` (Recover, Discard,
        Ask later).
        """
        session = self.session
        if session is None:
            return False
        fresh = []
        for copy in orphaned_library_copies(session.folder):
            if copy.is_newer_than_original():
                fresh.append(copy)
            else:
                copy.remove()
        if not fresh:
            return False
        copy, editor = fresh[0], self._editor
        answer = editor.ask_recover(copy)
        if answer == Button.Discard:
            copy.remove()
            return False
        if answer != Button.Yes or not editor.maybe_save("recovering another library text"):
            return False
        editor.set_text(copy.text, copy.original, modified=True)
        self.autosave_now()               # our own copy first, then drop the orphan
        copy.remove()
        dock = getattr(editor.window_, "library_editor_dock", None)     # this tool's own dock
        if dock is not None:
            toggle = dock.toggleViewAction()
            if not toggle.isChecked():
                toggle.trigger()          # as Library → Library editor does: the window's layout makes room
            dock.raise_()
        editor.context.status.showMessage(
            f"Recovered unsaved edits to {copy.display_name()}; save them to keep them", MESSAGE_MS)
        return True

    # -- helpers -------------------------------------------------------------------
    def _on_modification_changed(self, modified: bool) -> None:
        if modified:
            self.timer.setInterval(self._interval_ms())
            self.timer.start()
        else:
            self.timer.stop()
            self.clear()

    def _interval_ms(self) -> int:
        """The model autosaver's interval (the window may override the setting), else the setting's."""
        autosaver = self._editor.context.autosaver()
        if autosaver is not None:
            return autosaver.timer.interval()
        return max(1, round(settings.autosave_interval_seconds() * 1000))


def recovery_question(parent, copy: LibraryCopy) -> Button:
    """Recover, Discard or Ask later, about ``copy``."""
    belongs = str(copy.original) if copy.original is not None else "a new file that was never saved"
    when = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(copy.saved_at))
    box = QMessageBox(QMessageBox.Icon.Question, "Artificial Person: recover unsaved library edits?",
                      f"The workbench did not shut down cleanly. It kept the library editor's unsaved text of "
                      f"{copy.display_name()} ({belongs}) as it was at {when}.\n\n"
                      "Recover it into the library editor? The file itself is not changed until you save.",
                      Button.Yes | Button.Discard | Button.Ignore, parent)
    box.button(Button.Yes).setText("&Recover")
    box.button(Button.Ignore).setText("Ask &later")
    box.setDefaultButton(Button.Yes)
    return Button(box.exec())

