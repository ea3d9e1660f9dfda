"""One row of the script panel that shows a chosen file: what is chosen, **Choose…** and **×** (clear).

:class:`~workbench.script_panel.recording_chooser.RecordingChooser` (a recorded
voice) and :class:`~workbench.script_panel.table_chooser.PhoneTableChooser` (a
phone table) are such rows; each says what its buttons do.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtWidgets import QHBoxLayout, QLineEdit, QPushButton, QToolButton, QWidget


class FileChoiceRow(QWidget):
    """``summary`` (read-only: long names scroll instead of widening the dock), ``choose_button``, ``clear_button``.

    ``placeholder`` is what the summary says while nothing is chosen: a word or two, which the narrow
    dock of a laptop screen shows whole; ``empty_tip`` (its tooltip then) says it in full.
    """

    def __init__(self, name: str, placeholder: str, choose_tip: str, clear_tip: str,
                 choose: Callable[[], None], clear: Callable[[], None], parent: QWidget | None = None,
                 empty_tip: str = ""):
        super().__init__(parent)
        self.empty_tip = empty_tip or placeholder
        self.summary = QLineEdit()
        self.summary.setReadOnly(True)
        self.summary.setPlaceholderText(placeholder)
        self.summary.setMinimumWidth(60)
        self.summary.setObjectName(f"script_panel.{name}")
        self.choose_button = QPushButton("Choose…")
        self.choose_button.setObjectName(f"script_panel.choose_{name}")
        self.choose_button.setToolTip(choose_tip)
        self.choose_button.clicked.connect(choose)
        self.clear_button = QToolButton()
        self.clear_button.setText("×")
        self.clear_button.setObjectName(f"script_panel.clear_{name}")
        self.clear_button.setToolTip(clear_tip)
        self.clear_button.clicked.connect(clear)
        row = QHBoxLayout(self)
        row.setContentsMargins(0, 0, 0, 0)
        row.addWidget(self.summary, 1)
        row.addWidget(self.choose_button)
        row.addWidget(self.clear_button)

    def show_choice(self, text: str, tip: str, chosen: bool) -> None:
        """Show what is chosen (``text``, its full paths as ``tip``); the clear button only when ``chosen``."""
        self.summary.setText(text)
        self.summary.setCursorPosition(0)
        self.summary.setToolTip(tip if chosen else self.empty_tip)
        self.clear_button.setEnabled(chosen)
