"""The File menu's flows: new from mesh, open, save, save as, export (configuration, glTF), recover.

Every flow that would replace or drop the open model first asks about
unsaved changes (Save / Discard / Cancel). Errors a user can cause (an
unreadable file, a folder that cannot be written) are shown in a dialog with
the engine's one-line ``file:line: what`` message; the current model stays.
The questions are separate methods (:meth:`FileController.ask_unsaved`,
:meth:`FileController.ask_recover`, :meth:`FileController.ask_export_folder`)
so tests and test hooks can answer them. Exports carry the name the user
knows the model by, its file's (``painted.xml`` exports ``painted.*``), not
the name stored inside it.
"""

from __future__ import annotations

import threading
import time
import weakref
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QEventLoop, QSettings, Qt
from PySide6.QtWidgets import QApplication, QFileDialog, QMessageBox, QProgressDialog

import engine
from engine.formats.mesh_io import import_mesh
from engine.outputs.configuration_export import export_configuration, exported_model_path
from engine.paths import DATA_DIR

from .. import settings
from .export_folder_dialog import ExportFolderDialog
from .recent_files import add_recent_file
from .recovery import RecoveryEntry, orphaned_entries

if TYPE_CHECKING:
    from ..gltf_export.dialog import GltfExportDialog
    from ..gltf_export.exporter import GltfExporter
    from .main_window import MainWindow

TITLE = "Artificial Person"
MODEL_FILTER = "Model descriptions (*.xml);;All files (*)"
MESH_FILTER = ("Meshes (*.obj *.ply *.stl *.vtk *.vtp *.vtu *.off *.gltf *.glb);;"
               "All files (*)")
METRE_FORMATS = (".gltf", ".glb")  # glTF is in metres by that format's convention; everything else mm
MESH_BUSY_AFTER_S = 0.3
"""A mesh read that takes longer than this (s) shows a busy dialog while the window keeps drawing."""
MESSAGE_MS = 5000
Button = QMessageBox.StandardButton


class FileController:
    """File flows on one main window (held weakly: the window owns this object)."""

    def __init__(self, window: MainWindow):
        self._window_ref = weakref.ref(window)
        self._gltf_exporter: GltfExporter | None = None
        self.gltf_dialog: GltfExportDialog | None = None

    @property
    def window(self) -> MainWindow:
        return self._window_ref()

    @property
    def document(self):
        return self.window.document

    # -- questions (replaced by tests and test hooks) ---------------------------
    def ask_unsaved(self, doing: str) -> QMessageBox.StandardButton:
        """Save, Discard or Cancel, before ``doing`` (e.g. "closing") would drop unsaved changes."""
        return QMessageBox.warning(
            self.window, f"{TITLE}: unsaved changes",
            f"The model “{self.display_name()}” has changes that are not saved.\n"
            f"Save them before {doing}?",
            Button.Save | Button.Discard | Button.Cancel, Button.Save)

    def ask_recover(self, entry: RecoveryEntry) -> QMessageBox.StandardButton:
        """Yes (recover), Discard (delete the copy) or Ignore (ask again next time)."""
        belongs = str(entry.original) if entry.original else "a model that was never saved"
        box = QMessageBox(QMessageBox.Icon.Question, f"{TITLE}: recover unsaved changes?",
                          f"The workbench did not shut down cleanly. It kept a copy of "
                          f"“{entry.model_name}” ({belongs}) with the changes made up to "
                          f"{time.strftime('%Y-%m-%d %H:%M:%S', time.localtime(entry.saved_at))}.\n\n"
                          "Recover those changes?",
                          Button.Yes | Button.Discard | Button.Ignore, self.window)
        box.button(Button.Yes).setText("&Recover")
        box.button(Button.Ignore).setText("Ask &later")
        box.setDefaultButton(Button.Yes)
        return Button(box.exec())

    def ask_export_folder(self) -> Path | None:
        """The folder to export the configuration to, existing or new; ``None`` if cancelled."""
        dialog = ExportFolderDialog(self.window, Path(self.start_dir()), exported_model_path(
            self.document.model, self.export_stem()))
        try:
            return dialog.folder() if dialog.exec() == ExportFolderDialog.DialogCode.Accepted else None
        finally:
            dialog.deleteLater()

    # -- the unsaved-changes guard ------------------------------------------------
    def maybe_save(self, doing: str = "closing") -> bool:
        """True when it is fine to drop the current model (nothing unsaved, saved now, or discarded)."""
        if not self.document.is_modified:
            return True
        answer = self.ask_unsaved(doing)
        if answer == Button.Save:
            return self.save()
        return answer == Button.Discard

    # -- new / open -------------------------------------------------------------------
    def new_from_mesh_dialog(self) -> bool:
        """Ask for a mesh file and make it a new model with no parameters."""
        if not self.maybe_save("starting a new model"):
            return False
        path, _ = QFileDialog.getOpenFileName(self.window, "New model from mesh", self.start_dir(), MESH_FILTER)
        return bool(path) and self.new_from_mesh(path)

    def new_from_mesh(self, path: str | Path) -> bool:
        """Import ``path`` (any mesh pyvista reads; glTF in metres, others in mm) as a new, unsaved model.

        The engine reads OBJ, PLY and glTF itself and every other format in a child process, so a
        damaged file ends in a message here, never in a crash or a hang that would lose unsaved work."""
        path = Path(path)
        scale = 1000.0 if path.suffix.lower() in METRE_FORMATS else None
        try:
            model = self._read_mesh_responsively(path)
        except engine.UserError as exc:
            QMessageBox.critical(self.window, f"{TITLE}: cannot import mesh", str(exc))
            return False
        self.document.replace_model(model, None)
        self.remember_dir(path)
        units = "metres, scaled to mm" if scale else "mm"
        self.show_message(f"New model from {path.name}: {model.n_vertices:,} vertices, "
                          f"{len(model.parts)} parts (units: {units})")
        return True

    def _read_mesh_responsively(self, path: Path) -> engine.Model:
        """``import_mesh(path)`` on a thread of its own: the window keeps drawing and shows a busy dialog
        while a slow file (a VTK format read in a child process, stopped after its time limit) is read."""
        outcome: dict[str, object] = {}

        def read() -> None:
            try:
                outcome["model"] = import_mesh(path)
            except BaseException as error:          # handed back to the GUI thread below
                outcome["error"] = error

        reader = threading.Thread(target=read, name=f"read {path.name}", daemon=True)
        reader.start()
        reader.join(MESH_BUSY_AFTER_S)
        if reader.is_alive():
            busy = QProgressDialog(f"Reading {path.name}…", "", 0, 0, self.window)
            busy.setCancelButton(None)               # the child process stops itself at its time limit
            busy.setWindowModality(Qt.WindowModality.WindowModal)
            busy.setMinimumDuration(0)
            busy.setWindowTitle(TITLE)
            busy.show()
            while reader.is_alive():
                QApplication.processEvents(QEventLoop.ProcessEventsFlag.AllEvents, 50)
                reader.join(0.02)
            busy.close()
            busy.deleteLater()
        if "error" in outcome:
            raise outcome["error"]              # type: ignore[misc]
        return outcome["model"]                 # type: ignore[return-value]

    def open_dialog(self) -> bool:
        """Ask for a model description and open it; ``False`` if cancelled or unreadable."""
        if not self.maybe_save("opening another model"):
            return False
        path, _ = QFileDialog.getOpenFileName(self.window, "Open model", self.start_dir(), MODEL_FILTER)
        return bool(path) and self.open_model(path)

    def open_recent(self, path: str | Path) -> bool:
        return self.maybe_save("opening another model") and self.open_model(path)

    def open_model(self, path: str | Path) -> bool:
        """Open the model at ``path`` (no question asked); on failure show why and keep the current model."""
        try:
            self.document.open(path)
        except engine.UserError as exc:
            QMessageBox.critical(self.window, f"{TITLE}: cannot open model", str(exc))
            return False
        add_recent_file(path)
        self.remember_dir(path)
        self.window.recent_menu.rebuild()
        self.show_message(f"Opened {path}")
        return True

    # -- save ------------------------------------------------------------------------------
    def save(self) -> bool:
        """Save to the model's file; asks for one if it has none or it is the shipped default head."""
        path = self.document.path
        if path is None or is_shipped(path):
            return self.save_as_dialog()
        return self.save_model(path)

    def save_as_dialog(self) -> bool:
        """Ask where to save the model (.xml + .h5) and write it; ``False`` if cancelled or failed."""
        path, suggested = self.document.path, self.document.suggested_path
        if path is not None and not is_shipped(path):
            start = str(path)
        elif path is None and suggested is not None:
            start = str(suggested)                  # a head from photographs: named after the photograph
        else:
            start = self.start_dir()
        path, _ = QFileDialog.getSaveFileName(self.window, "Save model as", start, MODEL_FILTER)
        return bool(path) and self.save_model(path)

    def save_identity_as_dialog(self) -> bool:
        """Ask where to save the head with its identity (the Identity panel's button), proposing the
        identity's name (``person-sex1-age60.xml``); ``False`` if cancelled or failed."""
        model = self.document.model
        name = model.name if getattr(model, "identity", None) is not None else "person"
        start = str(Path(self.start_dir()) / f"{name}.xml")
        path, _ = QFileDialog.getSaveFileName(self.window, "Save identity as", start, MODEL_FILTER)
        return bool(path) and self.save_model(path)

    def save_model(self, path: str | Path) -> bool:
        try:
            written = self.document.save(path)
        except (engine.UserError, OSError) as exc:
            QMessageBox.critical(self.window, f"{TITLE}: cannot save model", str(exc))
            return False
        add_recent_file(written)
        self.remember_dir(written)
        self.window.recent_menu.rebuild()
        self.show_message(f"Saved {written}")
        return True

    # -- export ----------------------------------------------------------------------------
    def export_dialog(self) -> bool:
        """Ask for a folder (a new one is created) and export the model and its library files there."""
        folder = self.ask_export_folder()
        if folder is None:
            return False
        if folder.is_dir() and any(folder.iterdir()):
            answer = QMessageBox.question(
                self.window, f"{TITLE}: export configuration",
                f"The folder {folder} is not empty. Files of the same name will be replaced. Export anyway?",
                Button.Yes | Button.Cancel, Button.Cancel)
            if answer != Button.Yes:
                return False
        return self.export_configuration(folder)

    def export_configuration(self, folder: str | Path) -> bool:
        """Write the configuration into ``folder`` (created if needed), the model named as its file."""
        try:
            summary = export_configuration(self.document.model, folder, settings.library_folders(),
                                           source=self.document.path, stem=self.export_stem())
        except (engine.UserError, OSError) as exc:
            QMessageBox.critical(self.window, f"{TITLE}: cannot export configuration", str(exc))
            return False
        self.remember_dir(folder)           # its parent: the next export proposes a folder beside this one
        self.show_message(f"Exported {summary.model.as_posix()} and {len(summary.library_files)} "
                          f"library files to {folder}")
        return True

    def export_stem(self) -> str | None:
        """The name exports give the model: its file's stem; ``None`` (the model's name) when untitled."""
        path = self.document.path
        return path.stem if path is not None else None

    @property
    def gltf_exporter(self) -> GltfExporter:
        if self._gltf_exporter is None:
            from ..gltf_export.exporter import GltfExporter  # on first use: not needed to start the window

            self._gltf_exporter = GltfExporter(self.window)
        return self._gltf_exporter

    def export_gltf_dialog(self) -> GltfExportDialog | None:
        """Open File → Export → glTF… (window-modal, not blocking); its Export button starts the export.

        ``None`` while an export is still running.
        """
        from ..gltf_export.dialog import GltfExportDialog

        if self.gltf_exporter.busy:
            self.show_message("A glTF export is still running")
            return None
        if self.gltf_dialog is not None:
            self.gltf_dialog.deleteLater()
        stem = self.export_stem() or self.document.model.name or "model"
        dialog = self.gltf_dialog = GltfExportDialog(self.document.model, self.document.path,
                                                     Path(self.start_dir()) / f"{stem}.glb", self.window)
        dialog.accepted.connect(self._export_gltf_chosen)
        dialog.open()
        return dialog

    def _export_gltf_chosen(self) -> None:
        if self.gltf_dialog is None:
            return
        choices = self.gltf_dialog.choices()
        if self.gltf_exporter.export(choices, self.document.model, self.document.path):
            self.remember_dir(choices.path)

    # -- crash recovery -------------------------------------------------------------------
    def offer_recovery(self) -> bool:
        """Offer the newest copy a crashed workbench left behind; True if it was recovered.

        Copies older than their saved file are stale and removed unasked.
        """
        fresh = []
        for entry in orphaned_entries(self.window.autosaver.session.folder):
            if entry.is_newer_than_original():
                fresh.append(entry)
            else:
                entry.remove()
        if not fresh:
            return False
        entry = fresh[0]
        answer = self.ask_recover(entry)
        if answer == Button.Discard:
            entry.remove()
            return False
        if answer != Button.Yes:
            return False
        try:
            model = entry.load()
        except engine.UserError as exc:
            QMessageBox.critical(self.window, f"{TITLE}: cannot recover",
                                 f"{exc}\n\nThe copy stays in {entry.folder}.")
            return False
        self.document.replace_model(model, entry.original)
        self.document.mark_modified()
        self.window.autosaver.autosave_now()     # our own copy first, then drop the orphan
        entry.remove()
        self.show_message(f"Recovered unsaved changes to {entry.model_name}; save them to keep them")
        return True

    # -- helpers ----------------------------------------------------------------------------
    def display_name(self) -> str:
        path = self.document.path
        return path.name if path is not None else "untitled"

    def show_message(self, text: str) -> None:
        self.window.statusBar().showMessage(text, MESSAGE_MS)

    def start_dir(self) -> str:
        remembered = QSettings().value(settings.LAST_DIR, "", type=str)
        if remembered and Path(remembered).is_dir():
            return remembered
        path = self.document.path
        if path is not None and not is_shipped(path):
            return str(path.parent)
        return str(Path.cwd())

    @staticmethod
    def remember_dir(path: str | Path) -> None:
        QSettings().setValue(settings.LAST_DIR, str(Path(path).resolve().parent))


def is_shipped(path: str | Path) -> bool:
    """Whether ``path`` is inside the project's shipped ``data/`` folder (never saved over)."""
    try:
        Path(path).resolve().relative_to(DATA_DIR.resolve())
    except ValueError:
        return False
    return True
