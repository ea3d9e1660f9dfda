"""The main window: viewport in the middle, parameter and tool-options docks, menus, toolbar, status bar.

The window only assembles the pieces, keeps the title and the layout, and
guards against losing work on close. File flows live in
:class:`~workbench.window.file_controller.FileController`, autosave in
:mod:`workbench.window.recovery`; the pieces talk through the shared
:class:`ModelDocument` and :class:`ViewState`, never directly to each other.
"""

from __future__ import annotations

from PySide6.QtCore import QSettings, QSize, Qt
from PySide6.QtGui import QAction, QCloseEvent, QShowEvent
from PySide6.QtWidgets import QDockWidget, QMainWindow, QStyle, QToolBar, QWidget

import engine

from .. import features, garbage_collection, settings
from ..document.model_document import ModelDocument
from ..document.playhead import Playhead
from ..document.view_state import ViewState
from ..icons import APP_ICON, icon
from ..identity_panel import panel as identity_panel
from ..library_sources import LibrarySources
from ..parameter_panel.panel import ParameterPanel
from ..playback.player import Player
from ..tools import ToolContext
from ..viewport.landmark_overlay import LandmarkOverlay
from ..viewport.view import Viewport
from . import actions as workbench_actions
from .dock_scroller import scroll_dock_content
from .file_controller import TITLE, FileController
from .layouts import LayoutManager, fit_to_screen, fresh_window_size
from .parts_menu import PartsMenu
from .recent_files import RecentFilesMenu
from .recovery import Autosaver, RecoverySession
from .status_bar import ModelStatusBar
from .tool_options import ToolOptionsDock

MESSAGE_MS = 4000
DOCK_ORDER = ("dock:parameters", "dock:parameter-tree", "dock:tool-options", "dock:timeline", "dock:script",
              "dock:expression-gallery", "dock:library-editor", "dock:mocap-plot", "dock:mocap-pca", "dock:identity")
"""The docks' order in the View menu (any other dock follows, by title)."""


class MainWindow(QMainWindow):
    """The workbench window over one :class:`ModelDocument`.

    ``autosave_seconds`` overrides the ``autosave/interval_seconds`` setting.
    """

    def __init__(self, document: ModelDocument, parent: QWidget | None = None, *,
                 autosave_seconds: float | None = None):
        super().__init__(parent)
        garbage_collection.collect_on_gui_thread()   # worker threads must never finalise Qt objects
        self.document = document
        self.view_state = ViewState(self)
        self.playhead = Playhead(self)
        self.files = FileController(self)
        self._closed = False
        # Connected first, so every part is visible again before the widgets rebuild.
        # Bound methods, not lambdas: a lambda would hold the window alive from
        # the document's connection list, a reference cycle Python cannot see.
        document.model_replaced.connect(self._on_model_replaced)
        document.path_changed.connect(self._update_title)
        document.modified_changed.connect(self.setWindowModified)

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
        self.parameter_dock.useful_size = self._parameter_dock_width   # the sliders' rows whole, not scrolled
        self.tool_options = ToolOptionsDock(self)
        self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.tool_options)

        self.toolbar = QToolBar("Main", self)
        self.toolbar.setObjectName("toolbar:main")
        self.toolbar.setMovable(False)
        self.addToolBar(self.toolbar)
        self.actions_by_id: dict[str, QAction] = workbench_actions.create_actions(self)
        self.menus = workbench_actions.populate(self.menuBar(), self.toolbar, self.actions_by_id)
        self.recent_menu = RecentFilesMenu(self)
        self.recent_menu.file_chosen.connect(self.files.open_recent)
        self.menus["&File"].insertMenu(self.actions_by_id["file.save"], self.recent_menu)
        self.parts_menu = PartsMenu(document, self.view_state, self)
        view_menu = self.menus["&View"]
        view_menu.addSeparator()
        view_menu.addMenu(self.parts_menu)
        self.tool_options.toggleViewAction().setIcon(icon("tool-options"))
        self.view_state.wireframe_changed.connect(self.actions_by_id["view.wireframe"].setChecked)
        self.landmarks = LandmarkOverlay(self.viewport, document, self.view_state, self)
        self.view_state.landmarks_changed.connect(self.actions_by_id["view.landmarks"].setChecked)
        self._bind_undo_actions()

        self.setStatusBar(ModelStatusBar(document, self))
        self.player = Player(document, self.playhead, self)     # before the tools: all that play share it
        self.library_sources = LibrarySources(self)
        self.tools = self._tool_context()
        features.install_all(self.tools)      # the tools: their docks exist before the layout is restored
        identity_panel.install(self)           # a part of the window (its File → Save identity), not a tool
        for dock in self.findChildren(QDockWidget):
            scroll_dock_content(dock)   # no dock's content may push the window off the screen
        self._list_docks_in_view_menu()
        self.layouts = LayoutManager(self)
        self._update_title()
        self.setWindowModified(document.is_modified)
        available = self.screen().availableGeometry()
        self.resize(fresh_window_size(available))
        self.move(available.center() - self.rect().center())
        self.restore_layout()

        seconds = autosave_seconds if autosave_seconds is not None else settings.autosave_interval_seconds()
        self.autosaver = Autosaver(document, RecoverySession(), seconds, self)
        self.autosaver.autosaved.connect(self._on_autosaved)
        self.autosaver.failed.connect(self._on_autosave_failed)

    # -- edit ----------------------------------------------------------------
    def undo(self) -> None:
        stack = self.document.undo_stack
        if stack.canUndo():
            text = stack.undoText()
            stack.undo()
            self.statusBar().showMessage(f"Undone: {text}", MESSAGE_MS)

    def redo(self) -> None:
        stack = self.document.undo_stack
        if stack.canRedo():
            text = stack.redoText()
            stack.redo()
            self.statusBar().showMessage(f"Redone: {text}", MESSAGE_MS)

    # -- layout --------------------------------------------------------------
    def save_layout(self) -> None:
        """Remember the window's size and place, and the task layout as the user left it (QSettings)."""
        QSettings().setValue(settings.WINDOW_GEOMETRY, self.saveGeometry())
        self.layouts.remember()

    def restore_layout(self) -> bool:
        """The remembered size and place (fitted to this screen) and task layout; ``False`` if none was."""
        geometry = QSettings().value(settings.WINDOW_GEOMETRY)
        restored = geometry is not None and self.restoreGeometry(geometry)
        if restored:
            fit_to_screen(self)
        self.layouts.restore()
        return restored

    # -- Qt overrides --------------------------------------------------------
    def showEvent(self, event: QShowEvent) -> None:
        super().showEvent(event)
        self.layouts.window_shown()

    def closeEvent(self, event: QCloseEvent) -> None:
        if self._closed:
            event.accept()
            return
        if not self.files.maybe_save("closing"):
            event.ignore()
            return
        self._closed = True
        self.save_layout()
        self.autosaver.stop()
        self.identity_panel.heads.stop()         # a head still being made must not reach a closed viewport
        self.autosaver.session.close()           # a clean shutdown leaves no recovery copy
        self.document.undo_stack.clear()         # the commands go with the window
        self.viewport.close_plotter()
        super().closeEvent(event)

    # -- helpers -----------------------------------------------------------
    def _tool_context(self) -> ToolContext:
        """What the tools may use of this window (:mod:`workbench.tools`)."""
        return ToolContext(window=self, document=self.document, view_state=self.view_state,
                           playhead=self.playhead, player=self.player, viewport=self.viewport,
                           tool_options=self.tool_options, actions=self.actions_by_id, menus=self.menus,
                           toolbar=self.toolbar, status=self.statusBar(), library_sources=self.library_sources,
                           _add_actions=self._add_actions, _reveal=self._reveal,
                           _autosaver=self._autosaver)

    def _add_actions(self, specs: tuple[workbench_actions.ActionSpec, ...]) -> dict[str, QAction]:
        return workbench_actions.add_actions(self, specs)

    def _reveal(self, dock: QDockWidget, width: int = 0, height: int = 0, task: str | None = None) -> None:
        self.layouts.reveal(dock, width, height, task=task)

    def _autosaver(self) -> Autosaver | None:
        return getattr(self, "autosaver", None)       # made once the window is up

    def _list_docks_in_view_menu(self) -> None:
        """Every dock in the View menu, checkable and ticked while it is open, in :data:`DOCK_ORDER`.

        The dock's own toggle action, so the tick follows the dock however it is opened or closed (its
        tool's command, its close button, a layout). Tools may add theirs elsewhere too (Library →
        Library editor is the same action). The Parameters dock cannot be closed: its entry shows it
        in front of its tab group.
        """
        view = self.menus["&View"]
        docks = [d for d in self.findChildren(QDockWidget) if d.objectName()]
        rank = {name: k for k, name in enumerate(DOCK_ORDER)}
        docks.sort(key=lambda d: (rank.get(d.objectName(), len(rank)), d.windowTitle()))
        view.addSeparator()
        for dock in docks:
            view.removeAction(dock.toggleViewAction())
            view.addAction(self._parameters_entry() if dock is self.parameter_dock else dock.toggleViewAction())

    def _parameters_entry(self) -> QAction:
        entry = QAction("Parameters", self)
        entry.setObjectName("view.parameters")
        entry.setCheckable(True)
        entry.setChecked(True)
        entry.setToolTip("The sliders of every parameter (always open: this brings them to the front)")
        entry.setStatusTip(entry.toolTip())
        entry.triggered.connect(self._show_parameters)
        self.parameters_entry = entry
        return entry

    def _show_parameters(self, _checked: bool = False) -> None:
        self.parameters_entry.setChecked(True)
        self.layouts.reveal(self.parameter_dock)

    def _parameter_dock_width(self) -> QSize:
        scroll_bar = self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent)
        return QSize(self.parameter_panel.sizeHint().width() + scroll_bar + 4, 0)

    def _bind_undo_actions(self) -> None:
        stack = self.document.undo_stack
        stack.canUndoChanged.connect(self.actions_by_id["edit.undo"].setEnabled)
        stack.canRedoChanged.connect(self.actions_by_id["edit.redo"].setEnabled)
        stack.undoTextChanged.connect(self._update_undo_texts)
        stack.redoTextChanged.connect(self._update_undo_texts)
        stack.indexChanged.connect(self._update_undo_texts)
        self._update_undo_texts()

    def _update_undo_texts(self, *_args) -> None:
        stack = self.document.undo_stack
        for action_id, verb, can, text in (("edit.undo", "Undo", stack.canUndo(), stack.undoText()),
                                           ("edit.redo", "Redo", stack.canRedo(), stack.redoText())):
            action = self.actions_by_id[action_id]
            action.setEnabled(can)
            action.setText(f"&{verb} {text}" if can and text else f"&{verb}")
            tip = f"{verb} “{text}”" if can and text else f"Nothing to {verb.lower()}"
            action.setToolTip(tip)
            action.setStatusTip(tip)

    def _on_model_replaced(self, _model: engine.Model) -> None:
        self.view_state.show_all_parts()
        self.view_state.select_parameter(None)
        self._update_title()

    def _update_title(self, *_args) -> None:
        # "[*]" is where Qt puts the modified marker ("*") while isWindowModified().
        self.setWindowTitle(f"{self.files.display_name()}[*] — {TITLE}")
        path = self.document.path
        self.setWindowFilePath(str(path) if path else "")

    def _on_autosaved(self, _path: str) -> None:
        self.statusBar().showMessage("Autosaved: a crash would not lose the unsaved changes", MESSAGE_MS)

    def _on_autosave_failed(self, message: str) -> None:
        self.statusBar().showMessage(f"Autosave failed: {message}", MESSAGE_MS)
