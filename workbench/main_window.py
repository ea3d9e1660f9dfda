"""The main window: viewport in the middle, parameter dock, menus, toolbar, status bar.

The window only assembles the pieces and handles the dialogs (open, save,
errors). The pieces talk through the shared :class:`ModelDocument` and
:class:`ViewState`, never directly to each other.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings, Qt
from PySide6.QtGui import QAction, QCloseEvent
from PySide6.QtWidgets import QDockWidget, QFileDialog, QMainWindow, QMessageBox, QToolBar, QWidget

import engine

from . import actions as workbench_actions
from .document import ModelDocument
from .icons import APP_ICON, icon
from .parameter_panel import ParameterPanel
from .parts_menu import PartsMenu
from .status_bar import ModelStatusBar
from .view_state import ViewState
from .viewport import Viewport

TITLE = "Artificial Person"
MODEL_FILTER = "Model descriptions (*.xml);;All files (*)"


class MainWindow(QMainWindow):
    """The workbench window over one :class:`ModelDocument`."""

    def __init__(self, document: ModelDocument, parent: QWidget | None = None):
        super().__init__(parent)
        self.document = document
        self.view_state = ViewState(self)
        # Connected first, so every part is visible again before the widgets rebuild.
        # Bound methods, not lambdas: a lambda would hold the window alive from
        # the document's connection list, a reference cycle Python cannot see.
        document.model_replaced.connect(self._on_model_replaced)
        document.path_changed.connect(self._update_title)

        self.setWindowIcon(icon(APP_ICON))
        self.viewport = Viewport(document, self.view_state, self)
        self.setCentralWidget(self.viewport)

        self.parameter_panel = ParameterPanel(document)
        self.parameter_dock = QDockWidget("Parameters", self)
        self.parameter_dock.setObjectName("dock:parameters")
        self.parameter_dock.setWidget(self.parameter_panel)
        self.parameter_dock.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                                        | QDockWidget.DockWidgetFeature.DockWidgetFloatable)
        self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.parameter_dock)

        self.toolbar = QToolBar("Main", self)
        self.toolbar.setObjectName("toolbar:main")
        self.toolbar.setMovable(False)
        self.addToolBar(self.toolbar)
        self.actions_by_id: dict[str, QAction] = workbench_actions.create_actions(self)
        self.menus = workbench_actions.populate(self.menuBar(), self.toolbar, self.actions_by_id)
        self.parts_menu = PartsMenu(document, self.view_state, self)
        view_menu = self.menus["&View"]
        view_menu.addSeparator()
        view_menu.addMenu(self.parts_menu)
        self.view_state.wireframe_changed.connect(self.actions_by_id["view.wireframe"].setChecked)

        self.setStatusBar(ModelStatusBar(document, self))
        self._update_title()
        self.resize(1280, 800)
        self.resizeDocks([self.parameter_dock], [430], Qt.Orientation.Horizontal)

    # -- dialogs -----------------------------------------------------------
    def open_model_dialog(self) -> bool:
        """Ask for a model description and open it; ``False`` if cancelled or unreadable."""
        path, _ = QFileDialog.getOpenFileName(self, "Open model", self._start_dir(), MODEL_FILTER)
        return bool(path) and self.open_model(path)

    def open_model(self, path: str | Path) -> bool:
        """Open the model at ``path``; on failure show why and keep the current model."""
        try:
            self.document.open(path)
        except engine.UserError as exc:
            QMessageBox.critical(self, f"{TITLE}: cannot open model", str(exc))
            return False
        self._remember_dir(path)
        return True

    def save_model_dialog(self) -> bool:
        """Ask where to save the model (.xml + .h5) and write it; ``False`` if cancelled or failed."""
        start = str(self.document.path) if self.document.path else self._start_dir()
        path, _ = QFileDialog.getSaveFileName(self, "Save model as", start, MODEL_FILTER)
        return bool(path) and self.save_model(path)

    def save_model(self, path: str | Path) -> bool:
        try:
            written = self.document.save(path)
        except (engine.UserError, OSError) as exc:
            QMessageBox.critical(self, f"{TITLE}: cannot save model", str(exc))
            return False
        self._remember_dir(written)
        self.statusBar().showMessage(f"Saved {written}", 4000)
        return True

    # -- Qt overrides --------------------------------------------------------
    def closeEvent(self, event: QCloseEvent) -> None:  # noqa: N802 (Qt's name)
        self.viewport.close_plotter()
        super().closeEvent(event)

    # -- helpers -----------------------------------------------------------
    def _on_model_replaced(self, _model: engine.Model) -> None:
        self.view_state.show_all_parts()
        self._update_title()

    def _update_title(self, *_args) -> None:
        self.setWindowTitle(f"{TITLE} — {self.document.model.name}")
        path = self.document.path
        self.setWindowFilePath(str(path) if path else "")

    def _start_dir(self) -> str:
        remembered = QSettings().value("workbench/last_dir", "", type=str)
        if remembered and Path(remembered).is_dir():
            return remembered
        if self.document.path is not None:
            return str(self.document.path.parent)
        return str(Path.cwd())

    @staticmethod
    def _remember_dir(path: str | Path) -> None:
        QSettings().setValue("workbench/last_dir", str(Path(path).resolve().parent))
