"""Runs File → Export → glTF… off the GUI thread: the engine's export, a progress dialog, the outcome.

The work is the command line's (``artificial-person export-gltf``):
:func:`engine.outputs.gltf_export.export_targets` chooses and checks the
targets, :func:`~engine.outputs.gltf_export.export_gltf` writes the file,
:func:`~engine.outputs.gltf_export.export_summary` says what was written. It
runs on a copy of the model, so edits made meanwhile neither race with it
nor end up in the file, through the workbench's background runner
(:func:`workbench.background.run_in_background`: a busy progress dialog
with Cancel, the window responsive). A :class:`engine.errors.UserError` is
shown in a dialog as the engine words it; nothing is written then. Cancel
before the file is written leaves no file; afterwards the file stands and is
reported.
"""

from __future__ import annotations

import threading
import weakref
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QMessageBox

import engine
from engine.outputs.gltf_export import export_gltf, export_summary, export_targets

from ..background import BackgroundJob, run_in_background, show_error
from .dialog import GltfExportChoices

if TYPE_CHECKING:
    from ..window.main_window import MainWindow

TITLE = "Export glTF"
MESSAGE_MS = 10000


class GltfExporter(QObject):
    """One glTF export at a time for a window. ``ended(outcome)``: ``"written"``, ``"failed"`` or ``"cancelled"``."""

    ended = Signal(str)

    def __init__(self, window: MainWindow):
        super().__init__(window)
        self._window_ref = weakref.ref(window)
        self.job: BackgroundJob | None = None
        self._path: Path | None = None
        self._summary: str | None = None
        self._stop = threading.Event()

    @property
    def window(self) -> MainWindow:
        return self._window_ref()

    @property
    def busy(self) -> bool:
        """An export is running (its outcome not reported yet)."""
        return self.job is not None

    def export(self, choices: GltfExportChoices, model: engine.Model, model_file: Path | None) -> bool:
        """Start writing ``choices.path``; ``False`` if one is running or the user keeps an existing file."""
        if self.busy:
            return False
        path = choices.path
        existing = [p.name for p in (path, path.with_suffix(".bin")) if p.exists()
                    and (p == path or path.suffix.lower() == ".gltf")]
        if existing:
            answer = QMessageBox.question(self.window, TITLE, f"Replace {' and '.join(existing)} in {path.parent}?")
            if answer != QMessageBox.StandardButton.Yes:
                return False
        snapshot = model.copy()
        # The worker sees only this plain Event. Nothing of Qt's may refer to it (not even a connection
        # to its bound ``set``): the worker drops the last reference to what ``work`` holds when it
        # ends, and a Qt connection torn down from there deadlocks with the GUI thread.
        stop = self._stop = threading.Event()

        def work() -> str | None:     # the worker thread: plain Python only, no Qt object
            targets = export_targets(snapshot, choices.names, choices.values, arkit=choices.arkit,
                                     poses=choices.poses, pose_groups=choices.pose_groups,
                                     skeleton=choices.skeleton, model_file=model_file)
            if stop.is_set():
                return None           # cancelled before anything was written
            mesh = export_gltf(snapshot, path, targets, target_normals=choices.target_normals,
                               skeleton=choices.skeleton)
            return export_summary(path, mesh)

        self._path, self._summary = path, None
        self.window.statusBar().showMessage(f"Exporting {path.name}…")
        self.job = run_in_background(self.window, f"Exporting {path.name}…", work, on_done=self._on_done,
                                     on_error=self._on_error, title=TITLE, on_finished=self._on_finished)
        progress = self.job.progress_dialog
        progress.canceled.connect(self._cancel)
        # A busy dialog is never given a value, so its minimum duration would not start (Qt shows it
        # after its 4 s default instead): a value at the minimum starts that clock.
        progress.setValue(0)
        return True

    def _cancel(self) -> None:
        """Cancel in the progress dialog: the work stops before it writes, if it has not begun to."""
        self._stop.set()

    def _on_done(self, summary: str | None) -> None:
        self._summary = summary

    def _on_error(self, error: Exception) -> None:
        self.window.statusBar().showMessage(f"glTF export failed: nothing was written to {self._path}", MESSAGE_MS)
        show_error(self.window, TITLE, error)
        self.ended.emit("failed")

    def _on_finished(self) -> None:
        job, self.job = self.job, None
        if job is None:
            return
        if job.cancelled:             # its result was not handed over: was the file written all the same?
            self._summary = None if job.future.exception() is not None else job.future.result()
        if self._summary is not None:
            self.window.statusBar().showMessage(f"Exported {self._path}: {self._summary}", MESSAGE_MS)
            self.ended.emit("written")
        elif job.cancelled:
            self.window.statusBar().showMessage("glTF export cancelled: nothing was written", MESSAGE_MS)
            self.ended.emit("cancelled")
