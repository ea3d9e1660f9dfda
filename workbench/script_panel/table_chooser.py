"""The phone table Say articulates with: the shipped one for the voice, or a file (issue 22 §2).

One row of the script panel: what is chosen (``learned.phones``, or nothing:
the shipped table of the voice's phone set), **Choose…** and **×** (back to
the shipped table). A table learned from capture by ``artificial-person mocap
learn`` is used here as ``say --articulation LEARNED.phones`` uses it. The
file is read when chosen, so a bad one is refused at once in a dialog naming
its line, and the choice is kept across sessions (QSettings
``script_panel/phone_table``) while the file still reads.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings, Signal
from PySide6.QtWidgets import QFileDialog, QMessageBox, QWidget

from engine.errors import UserError

from .file_choice_row import FileChoiceRow

KEY_TABLE = "script_panel/phone_table"
TABLE_FILTER = "Phone tables (*.phones);;All files (*)"
TITLE = "Phone table"


class PhoneTableChooser(FileChoiceRow):
    """``path`` is the chosen table file or ``None`` (the shipped table); ``changed`` fires when it changes."""

    changed = Signal()

    def __init__(self, parent: QWidget | None = None):
        super().__init__(
            "phone_table", "shipped",
            "Articulate with another phone → target table (a .phones file, e.g. one learned from motion capture "
            "by 'mocap learn')", "Back to the shipped table", self.choose, lambda: self.set_path(None), parent,
            empty_tip="The shipped phone table of the voice's phone set")
        self.path: Path | None = None
        self._restore()

    def choose(self) -> None:
        """Ask for a ``.phones`` file; nothing changes if the dialog is cancelled or the file is refused."""
        start = str(self.path.parent) if self.path else ""
        chosen, _ = QFileDialog.getOpenFileName(self, "Phone table", start, TABLE_FILTER)
        if chosen:
            self.set_path(Path(chosen), ask=True)

    def set_path(self, path: str | Path | None, ask: bool = False) -> bool:
        """Use the table at ``path`` (``None``: the shipped one); a file that does not read is refused
        (a dialog when ``ask``) and the choice stays as it was. Returns whether it was taken."""
        if path is not None:
            try:
                read_table(path)
            except UserError as exc:
                if ask:
                    QMessageBox.warning(self, TITLE, f"This phone table cannot be used:\n{exc}")
                return False
        self.path = Path(path) if path is not None else None
        self.show_choice(self.path.name if self.path else "", str(self.path) if self.path else "",
                         self.path is not None)
        QSettings().setValue(KEY_TABLE, str(self.path) if self.path else "")
        self.changed.emit()
        return True

    def _restore(self) -> None:
        stored = str(QSettings().value(KEY_TABLE, "") or "")
        if not (stored and Path(stored).is_file() and self.set_path(stored)):
            self.set_path(None)


def read_table(path: str | Path):
    """The :class:`~engine.speech.articulation.ArticulationTable` in ``path``, or a :class:`UserError`."""
    from engine.speech.articulation import load_articulation

    return load_articulation(path)
