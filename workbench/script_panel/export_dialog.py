"""“Export speech…”: choose the files, folder, base name, frame size and rate; write them off the GUI thread.

:class:`ExportSpeechDialog` only gathers an :class:`engine.outputs.speech_files.ExportPlan`
(remembered in QSettings ``script_panel/export/…``). It proposes the folder of
:func:`default_export_folder` (the document's, or the one last exported to
from it), and it closes only on a plan that can be written: a folder that
does not exist is created once the user agrees, and anything else wrong is
said in the dialog, which stays open with what was typed. :class:`SpeechExporter`
runs :func:`engine.outputs.speech_files.export_speech` on a worker thread with a
QProgressDialog whose Cancel removes everything written so far, then names
what was written in the status bar.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QObject, QSettings, Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDoubleSpinBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QMessageBox,
    QProgressDialog,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError
from engine.outputs.speech_files import KINDS, ExportCancelled, ExportPlan, export_speech

from .. import settings
from ..jobs import Job
from ..tools import ToolContext
from ..window.file_controller import is_shipped

PREFIX = "script_panel/export/"
FOLDER_FOR = PREFIX + "folder_for"      # the model file whose speech was last exported (to PREFIX + "folder")
DEFAULT_KINDS = ("mp4", "wav", "tracks", "landmarks")
VIEWS = (("Front", "front"), ("Three-quarter", "three-quarter"), ("Side", "side"))
MESSAGE_MS = 8000


def default_export_folder(document_path: Path | None) -> Path:
    """Where Export speech… proposes to write, for the model file ``document_path`` (``None``: untitled).

    The folder last exported to from this same model file, if it still exists; else the model file's
    folder (not the shipped ``data/``); else the folder last exported to, the folder the last file
    dialog ended in, the home folder — the first of these that exists.
    """
    store = QSettings()
    last = Path(str(store.value(PREFIX + "folder", "") or ""))
    last_ok = str(last) not in ("", ".") and last.is_dir()
    own = document_path is not None and not is_shipped(document_path)
    if last_ok and own and str(store.value(FOLDER_FOR, "")) == str(document_path):
        return last
    if own and Path(document_path).parent.is_dir():
        return Path(document_path).parent
    dialogs = Path(str(store.value(settings.LAST_DIR, "") or ""))
    for folder in ([last] if last_ok else []) + [dialogs]:
        if str(folder) not in ("", ".") and folder.is_dir():
            return folder
    return Path.home()


class ExportSpeechDialog(QDialog):
    """The choices of one export; :meth:`plan` reads them. ``folder``: the one proposed (see
    :func:`default_export_folder`); ``document_path``: the model file, remembered with the folder."""

    def __init__(self, parent: QWidget | None = None, base: str = "speech", folder: Path | None = None,
                 document_path: Path | None = None):
        super().__init__(parent)
        self.document_path = document_path
        self.setWindowTitle("Export speech")
        self.setObjectName("script_panel.export_dialog")
        store = QSettings()
        chosen = set(str(store.value(PREFIX + "kinds", ",".join(DEFAULT_KINDS))).split(","))
        self.kind_boxes: dict[str, QCheckBox] = {}
        files = QVBoxLayout()
        for kind, (suffix, what) in KINDS.items():
            box = QCheckBox(f"{what}  (…{suffix})")
            box.setChecked(kind in chosen)
            self.kind_boxes[kind] = box
            files.addWidget(box)
        self.folder_edit = QLineEdit(str(folder if folder is not None else default_export_folder(document_path)))
        self.folder_edit.setMinimumWidth(320)
        browse = QPushButton("Browse…")
        browse.clicked.connect(self._browse)
        folder_row = QHBoxLayout()
        folder_row.addWidget(self.folder_edit, 1)
        folder_row.addWidget(browse)
        self.base_edit = QLineEdit(base)
        self.width_box = _spin(16, 3840, int(store.value(PREFIX + "width", 640)))
        self.height_box = _spin(16, 2160, int(store.value(PREFIX + "height", 480)))
        size_row = QHBoxLayout()
        size_row.addWidget(self.width_box)
        size_row.addWidget(self.height_box)
        size_row.addStretch(1)
        self.fps_box = QDoubleSpinBox()
        self.fps_box.setRange(1, 240)
        self.fps_box.setDecimals(2)
        self.fps_box.setValue(float(store.value(PREFIX + "fps", 30.0)))
        self.fps_box.setSuffix(" fps")
        self.view_box = QComboBox()
        for label, value in VIEWS:
            self.view_box.addItem(label, value)
        self.view_box.setCurrentIndex(max(0, self.view_box.findData(str(store.value(PREFIX + "view", "front")))))

        form = QFormLayout()
        form.addRow("Files:", files)
        # Labels made here, each with its buddy: a label QFormLayout makes for a row of several widgets has
        # none, and without a buddy QLabel shows "&Folder:" literally instead of as the mnemonic Alt+F.
        form.addRow(_buddy_label("&Folder:", self.folder_edit), folder_row)
        form.addRow(_buddy_label("&Base name:", self.base_edit), self.base_edit)
        form.addRow(_buddy_label("Frame &size (px):", self.width_box), size_row)
        form.addRow(_buddy_label("Frame &rate:", self.fps_box), self.fps_box)
        form.addRow(_buddy_label("&Camera:", self.view_box), self.view_box)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel)
        self.export_button = buttons.button(QDialogButtonBox.StandardButton.Ok)
        self.export_button.setText("Export")
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        self.message = QLabel()               # why Export did not close the dialog
        self.message.setObjectName("script_panel.export_message")
        self.message.setWordWrap(True)
        self.message.setStyleSheet("color: #a02020")
        self.message.hide()
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.message)
        layout.addWidget(buttons)

    def folder(self) -> Path:
        """The folder typed (``~`` expanded; empty: the current folder)."""
        return Path(self.folder_edit.text().strip() or ".").expanduser()

    def accept(self) -> None:
        """Close only on a plan that can be written: a missing folder is created if the user agrees;
        what is wrong otherwise is said here, and the dialog stays open as it was."""
        folder = self.folder()
        if folder.exists() and not folder.is_dir():
            return self._refuse(f"{folder} is a file, not a folder: choose a folder to write into.")
        if not folder.exists():
            if not self.ask_create(folder):
                return self._refuse(f"The folder {folder} does not exist: choose another one, or press Export "
                                    "again and let it be created.")
            try:
                folder.mkdir(parents=True)
            except OSError as error:
                return self._refuse(f"Cannot create the folder {folder}: {error.strerror or error}.")
        try:
            self.plan().check()
        except UserError as error:
            return self._refuse(f"Cannot export: {error}")
        self.message.hide()
        super().accept()
        return None

    def ask_create(self, folder: Path) -> bool:
        """Whether to create the missing ``folder`` (a question; tests may answer it)."""
        answer = QMessageBox.question(self, "Export speech", f"The folder {folder} does not exist.\n\nCreate it?",
                                      QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
                                      QMessageBox.StandardButton.Yes)
        return answer == QMessageBox.StandardButton.Yes

    def _refuse(self, text: str) -> None:
        self.message.setText(text)
        self.message.show()
        self.folder_edit.setFocus()

    def plan(self) -> ExportPlan:
        return ExportPlan(self.folder(), self.base_edit.text().strip(),
                          {kind for kind, box in self.kind_boxes.items() if box.isChecked()},
                          fps=self.fps_box.value(), size=(self.width_box.value(), self.height_box.value()),
                          view=self.view_box.currentData())

    def remember(self) -> None:
        plan = self.plan()
        store = QSettings()
        store.setValue(PREFIX + "kinds", ",".join(k for k in KINDS if k in plan.kinds))
        store.setValue(PREFIX + "folder", str(plan.folder.resolve()))
        store.setValue(FOLDER_FOR, str(self.document_path) if self.document_path is not None else "")
        store.setValue(PREFIX + "width", plan.size[0])
        store.setValue(PREFIX + "height", plan.size[1])
        store.setValue(PREFIX + "fps", plan.fps)
        store.setValue(PREFIX + "view", plan.view)

    def _browse(self) -> None:
        here = self.folder()
        start = next((p for p in (here, *here.parents) if p.is_dir()), Path.home())
        folder = QFileDialog.getExistingDirectory(self, "Export into folder", str(start))
        if folder:
            self.folder_edit.setText(folder)


def _buddy_label(text: str, buddy: QWidget) -> QLabel:
    """A form label whose ``&`` mnemonic puts the keyboard focus on ``buddy``."""
    label = QLabel(text)
    label.setBuddy(buddy)
    return label


def _spin(low: int, high: int, value: int) -> QSpinBox:
    box = QSpinBox()
    box.setRange(low, high)
    box.setSingleStep(2)                  # H.264 4:2:0 wants even sizes
    box.setValue(value)
    return box


class SpeechExporter(QObject):
    """Runs one export at a time for the context's window; ``exported(list of paths)`` when files were written."""

    exported = Signal(list)
    ended = Signal(str)                    # "written" | "cancelled" | "failed"

    def __init__(self, context: ToolContext):
        super().__init__(context.window)
        self.context = context
        self.window = context.window      # the parent of its dialogs
        self.job: Job | None = None
        self.plan: ExportPlan | None = None
        self.progress_dialog: QProgressDialog | None = None

    @property
    def busy(self) -> bool:
        return self.job is not None

    def export(self, plan: ExportPlan, speech, model) -> bool:
        """Start writing ``plan``; False (with a dialog) when the plan cannot be written."""
        if self.busy:
            return False
        try:
            plan.check()
        except UserError as error:
            QMessageBox.warning(self.window, "Export speech", str(error))
            return False
        existing = [p.name for p in plan.paths().values() if p.exists()]
        if existing:
            answer = QMessageBox.question(self.window, "Export speech",
                                          f"Replace {', '.join(existing)} in {plan.folder}?")
            if answer != QMessageBox.StandardButton.Yes:
                return False
        job = self.job = Job(lambda job: export_speech(plan, speech, model, job.report, lambda: job.cancelled))
        dialog = self.progress_dialog = QProgressDialog("Writing " + ", ".join(p.name for p in plan.paths().values()),
                                                        "Cancel", 0, 0, self.window)
        dialog.setObjectName("script_panel.export_progress")
        dialog.setWindowTitle("Export speech")
        dialog.setWindowModality(Qt.WindowModality.WindowModal)
        dialog.setMinimumDuration(0)
        dialog.setAutoClose(False)
        dialog.setAutoReset(False)
        dialog.canceled.connect(self.cancel)
        job.progress.connect(self._on_progress)
        self.plan = plan
        job.ended.connect(self._on_ended)
        dialog.show()
        job.start()
        return True

    def cancel(self) -> None:
        if self.job is not None:
            self.job.cancel()
            if self.progress_dialog is not None:
                self.progress_dialog.setLabelText("Cancelling…")

    def _on_progress(self, done: int, total: int) -> None:
        if self.progress_dialog is not None and not self.progress_dialog.wasCanceled():
            self.progress_dialog.setMaximum(max(1, total))
            self.progress_dialog.setValue(min(done, total))

    def _on_ended(self) -> None:
        job, plan = self.sender(), self.plan
        if job is not self.job:
            return
        self.job = None
        if self.progress_dialog is not None:
            self.progress_dialog.canceled.disconnect(self.cancel)
            self.progress_dialog.close()
            self.progress_dialog.deleteLater()
            self.progress_dialog = None
        status = self.context.status
        if job.error is None:                      # written, even if Cancel came too late to stop it
            names = ", ".join(Path(p).name for p in job.result)
            status.showMessage(f"Exported {names} to {plan.folder}", MESSAGE_MS)
            self.exported.emit(list(job.result))
            self.ended.emit("written")
        elif isinstance(job.error, ExportCancelled):
            status.showMessage("Export cancelled: nothing was written", MESSAGE_MS)
            self.ended.emit("cancelled")
        else:
            error = job.error
            message = str(error) if isinstance(error, UserError) else f"{type(error).__name__}: {error}"
            self.ended.emit("failed")
            QMessageBox.warning(self.window, "Export speech", f"Nothing was written: {message}")
