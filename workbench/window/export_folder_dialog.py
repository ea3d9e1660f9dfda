"""“Export configuration…”: which folder to write, existing or new, and what will be in it.

``QFileDialog.getExistingDirectory`` refuses a folder that does not exist
yet, so a user exporting for a colleague had to make the folder somewhere
else first. Here the folder is a line to type in (a new one is created by the
export) with a Browse… button for an existing one, and the dialog names the
files the export writes, ``model/painted.xml`` for ``painted.xml``, so the
name of the model is no surprise.

>>> dialog = ExportFolderDialog(window, Path("/home/anna"), Path("model/painted.xml"))   # doctest: +SKIP
>>> dialog.exec() and dialog.folder()                                                  # doctest: +SKIP
PosixPath('/home/anna/painted-configuration')
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

Button = QDialogButtonBox.StandardButton


class ExportFolderDialog(QDialog):
    """The folder an export configuration writes; proposes ``<start>/<stem>-configuration``."""

    def __init__(self, parent: QWidget | None, start: Path, model_file: Path):
        super().__init__(parent)
        self.setWindowTitle("Export configuration")
        self.setObjectName("export_folder_dialog")
        self._start = start
        self.folder_edit = QLineEdit(str(start / f"{model_file.stem}-configuration"))
        self.folder_edit.setObjectName("folder")
        self.folder_edit.setMinimumWidth(380)
        browse = QPushButton("&Browse…")
        browse.setObjectName("browse")
        browse.clicked.connect(self._browse)
        row = QHBoxLayout()
        row.addWidget(self.folder_edit, 1)
        row.addWidget(browse)
        label = QLabel("&Folder:")
        label.setBuddy(self.folder_edit)           # without a buddy the label would show "&Folder:" literally
        form = QFormLayout()
        form.addRow(label, row)
        what = QLabel(f"Writes <b>{model_file.as_posix()}</b> (with {model_file.with_suffix('.h5').name}), "
                      "the command library files whose commands fit the model, and README.txt. "
                      "A folder that does not exist yet is created.")
        what.setWordWrap(True)
        what.setObjectName("what_is_written")
        self.buttons = QDialogButtonBox(Button.Ok | Button.Cancel)
        self.buttons.button(Button.Ok).setText("&Export")
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        self.folder_edit.textChanged.connect(self._update_button)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(what)
        layout.addWidget(self.buttons)
        self._update_button()

    def folder(self) -> Path:
        """The folder typed or chosen; a relative one is taken from the proposed folder's parent."""
        folder = Path(self.folder_edit.text().strip()).expanduser()
        return folder if folder.is_absolute() else self._start / folder

    def _update_button(self) -> None:
        self.buttons.button(Button.Ok).setEnabled(bool(self.folder_edit.text().strip()))

    def _browse(self) -> None:
        here = self.folder()
        start = here if here.is_dir() else here.parent
        folder = QFileDialog.getExistingDirectory(self, "Export configuration to folder", str(start))
        if folder:
            self.folder_edit.setText(folder)
