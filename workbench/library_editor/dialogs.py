"""The library editor's dialogs: the library folders, and a new command from a template."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QListWidget,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from engine.paths import LIBRARY_DIR

from .templates import COMMAND_NAME, TEMPLATES


class LibraryFoldersDialog(QDialog):
    """Edit the user's library folders: add, remove, move up and down (search order).

    >>> dialog = LibraryFoldersDialog(["/home/me/gestures"])     # doctest: +SKIP
    >>> dialog.exec() and dialog.folders()                       # doctest: +SKIP
    """

    def __init__(self, folders: list[str | Path], parent: QWidget | None = None):
        super().__init__(parent)
        self.setWindowTitle("Library folders")
        self.list = QListWidget()
        self.list.addItems([str(f) for f in folders])
        explanation = QLabel(f"Commands are read from the shipped library ({LIBRARY_DIR}) and then from these "
                             "folders, in this order: a command in a later folder replaces one of the same name "
                             "in an earlier one.")
        explanation.setWordWrap(True)
        buttons = QVBoxLayout()
        for text, slot in (("Add…", self._add), ("Remove", self._remove), ("Up", lambda: self._move(-1)),
                           ("Down", lambda: self._move(1))):
            button = QPushButton(text)
            button.clicked.connect(slot)
            buttons.addWidget(button)
        buttons.addStretch(1)
        row = QHBoxLayout()
        row.addWidget(self.list, 1)
        row.addLayout(buttons)
        box = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        box.accepted.connect(self.accept)
        box.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(explanation)
        layout.addLayout(row)
        layout.addWidget(box)
        self.resize(560, 300)

    def folders(self) -> list[str]:
        return [self.list.item(i).text() for i in range(self.list.count())]

    def add_folder(self, folder: str | Path) -> None:
        if str(folder) not in self.folders():
            self.list.addItem(str(folder))

    def _add(self) -> None:
        folder = QFileDialog.getExistingDirectory(self, "Add a library folder")
        if folder:
            self.add_folder(folder)

    def _remove(self) -> None:
        for item in self.list.selectedItems():
            self.list.takeItem(self.list.row(item))

    def _move(self, step: int) -> None:
        row = self.list.currentRow()
        target = row + step
        if row < 0 or not 0 <= target < self.list.count():
            return
        item = self.list.takeItem(row)
        self.list.insertItem(target, item)
        self.list.setCurrentRow(target)


class NewCommandDialog(QDialog):
    """Name, kind (template) and parameter of a new command."""

    def __init__(self, parameters: list[str], selected: str | None = None, parent: QWidget | None = None):
        super().__init__(parent)
        self.setWindowTitle("New command from template")
        self.name = QLineEdit("MyCommand")
        self.kind = QComboBox()
        for kind, (title, _text) in TEMPLATES.items():
            self.kind.addItem(title, kind)
        self.parameter = QComboBox()
        self.parameter.addItems(parameters)
        if selected in parameters:
            self.parameter.setCurrentText(selected)
        self.problem = QLabel()
        self.problem.setStyleSheet("color: #c0392b")
        form = QFormLayout()
        form.addRow("Command name", self.name)
        form.addRow("Kind", self.kind)
        form.addRow("Parameter it drives", self.parameter)
        self.box = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        self.box.accepted.connect(self.accept)
        self.box.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.problem)
        layout.addWidget(self.box)
        self.name.textChanged.connect(self._validate)
        self._validate()

    def choice(self) -> tuple[str, str, str]:
        """``(name, template kind, parameter)``."""
        return self.name.text().strip(), self.kind.currentData(), self.parameter.currentText()

    def _validate(self) -> None:
        ok = bool(COMMAND_NAME.match(self.name.text().strip()))
        self.problem.setText("" if ok else "A command name is letters, digits and _, not starting with a digit")
        self.box.button(QDialogButtonBox.StandardButton.Ok).setEnabled(ok and self.parameter.count() > 0)
