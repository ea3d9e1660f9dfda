"""The workbench's motion-capture tool (§3.1): import, marker view, frame selection, multistage PCA wizard.

``install(window)`` adds the **Motion capture** menu, the *Marker
coordinates* dock (:mod:`.plot_dock`), the *Multistage PCA* dock
(:mod:`.pca_dock`) and the markers drawn over the face
(:mod:`.marker_overlay`), animated by the window's shared playhead. Everything
the tool computes is an engine call (:mod:`engine.mocap`); the tool keeps
its state in one :class:`~.state.MocapState` (``window.mocap.state``).
Markers are named by clicking them on the face (:mod:`.marker_picking`) or
in the list beside the plot, and giving each its feature point
(:mod:`.assignment_panel`, on the session's own undo stack). Sessions and
marker maps are suggested beside the project (:mod:`.session_files`).
``docs/workbench-mocap.md`` is the user's guide.

>>> window.mocap.open_session("take1.h5")            # doctest: +SKIP
>>> window.mocap.plot_dock.select_by_phones(["V", "C"])  # doctest: +SKIP
>>> window.mocap.pca_dock.run_pca()                  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PySide6.QtCore import QObject, Qt
from PySide6.QtWidgets import QFileDialog

from engine.mocap.marker_assignment import is_feature_point, marker_labels, session_mapping
from engine.mocap.session import load_session, save_session

from ..background import run_in_background, show_error
from ..tools import ToolContext
from ..window.actions import ActionSpec
from .assignment_panel import AssignmentPanel
from .import_dialog import ImportDialog
from .marker_overlay import HIGHLIGHT_COLOR, MarkerOverlay, default_colors, error_colors, marker_to_model_transform
from .marker_picking import MarkerPicker
from .pca_dock import PcaDock
from .plot_dock import MarkerPlotDock
from .recording_playback import RecordingPlayback
from .session_files import default_session_path, project_folder
from .state import MocapState

MENU = "&Motion capture"
SESSION_FILES = "Capture sessions (*.h5);;All files (*)"


class MocapTool(QObject):
    """Connects the mocap state to the window: menu actions, docks, the markers in the viewport."""

    def __init__(self, context: ToolContext):
        window = context.window
        super().__init__(window)
        self.context = context
        self.window = window              # the parent of its docks and dialogs
        self.state = MocapState(self)
        self.overlay = MarkerOverlay(context.viewport)
        self.import_dialog: ImportDialog | None = None
        self.preview = None                 # (markers, points) of a PCA component being shown, or None
        self.errors: dict[str, float] | None = None
        self.job = None
        self.plot_dock = MarkerPlotDock(self.state, context.playhead, window)
        self.pca_dock = PcaDock(self.state, context.document, window)
        window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, self.plot_dock)   # the task layouts
        window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.pca_dock)     # give them their places
        self.plot_dock.hide()
        self.pca_dock.hide()
        self.names_panel = AssignmentPanel(self.state, context.document, self.project_folder, self.plot_dock)
        self.plot_dock.add_side_panel(self.names_panel)
        self.picker = MarkerPicker(context, self.overlay, self)
        self._texts: dict[str, str] = {}      # marker → the text drawn beside it

        self.state.session_changed.connect(self._on_session)
        self.state.markers_renamed.connect(self._on_renamed)
        context.playhead.time_changed.connect(self._redraw)
        self.plot_dock.marker_combo.currentTextChanged.connect(self._on_marker_shown)
        self.picker.picked.connect(self._on_picked)
        self.names_panel.marker_selected.connect(self.select_marker)
        self.names_panel.names_shown_changed.connect(self._refresh_labels)
        self.pca_dock.preview_changed.connect(self._on_preview)
        self.pca_dock.errors_changed.connect(self._on_errors)
        # a bound method, not a lambda: a lambda in the document's connection list would keep the window alive
        context.document.model_replaced.connect(self._on_model_replaced)
        self.playback = RecordingPlayback(self)     # the session on the player; markers only while it plays

    # -- sessions --------------------------------------------------------------------
    def import_dialog_for(self, path: str | Path | None = None) -> ImportDialog:
        """Open the import dialog (non-modal), on ``path`` if given."""
        if self.import_dialog is None:
            self.import_dialog = ImportDialog(self.window, self.project_folder)
            self.import_dialog.session_imported.connect(self.state.set_session)
        self.import_dialog.show()
        self.import_dialog.raise_()
        if path is not None:
            self.import_dialog.set_path(path)
        return self.import_dialog

    def open_session(self, path: str | Path) -> None:
        """Load a session file (HDF5) in the background; a bad file → dialog, nothing changes."""
        path = Path(path)
        self.job = run_in_background(self.window, f"Opening {path.name}…", lambda: load_session(path),
                                     lambda session: self.state.set_session(session, path))

    def save_session(self, path: str | Path) -> bool:
        if self.state.session is None:
            return False
        try:
            save_session(self.state.session, path)
        except Exception as exc:
            show_error(self.window, "Save session", exc)
            return False
        self.state.session_path = Path(path)
        self.state.undo_stack.setClean()
        return True

    def project_folder(self) -> Path:
        """Where sessions and marker maps are suggested: beside the open model (:mod:`.session_files`)."""
        return project_folder(self.context.document)

    def _open_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self.window, "Open capture session", "", SESSION_FILES)
        if path:
            self.open_session(path)

    def _save_dialog(self) -> None:
        if self.state.session is None:
            return
        default = str(self.state.session_path or default_session_path(self.context.document,
                                                                      self.state.session.source))
        path, _ = QFileDialog.getSaveFileName(self.window, "Save capture session", default, SESSION_FILES)
        if path:
            self.save_session(path)

    def _on_session(self, session) -> None:
        self.preview = None
        self.errors = None
        if session is None:
            self.overlay.hide()
            return
        self._refresh_labels()
        if any(not is_feature_point(m) for m in session.markers):
            self.plot_dock.names_button.setChecked(True)      # markers to name: the list opens beside the plot
        self.playback.show_session()
        self.context.reveal(self.plot_dock, task="mocap")    # a recording to analyse: the window turns
        self.context.reveal(self.pca_dock)                   # to that task
        self._place_markers()
        self.context.status.showMessage(f"Capture session: {session.source}, {session.n_frames} frames, "
                                            f"{session.n_markers} markers", 4000)

    # -- naming markers ---------------------------------------------------------------------------
    def select_marker(self, marker: str) -> None:
        """Make ``marker`` the one selected: plotted, highlighted and labelled on the face, chosen in the list."""
        if self.state.session is not None and marker in self.state.session.markers:
            self.plot_dock.marker_combo.setCurrentText(marker)

    def _on_picked(self, marker: str) -> None:
        self.select_marker(marker)
        if self.names_panel.isVisible():
            self.names_panel.point_combo.setFocus()    # the point is chosen next; Ctrl+Z undoes in the panel

    def _on_marker_shown(self, marker: str) -> None:
        self.names_panel.select(marker)
        self._refresh_labels()

    def _on_renamed(self, _renames) -> None:
        self._refresh_labels()
        self._place_markers()              # markers named after the model's points pair them with the face

    def _refresh_labels(self, *_args) -> None:
        """The text beside each marker: the points given here, the selected marker's names, or every name."""
        session = self.state.session
        self._texts = {}
        if session is not None:
            every = self.names_panel.all_names.isChecked()
            assigned = set(session_mapping(session).values())
            selected = self.plot_dock.marker
            for name, label in zip(session.markers, marker_labels(session), strict=True):
                if name == selected:
                    self._texts[name] = name if name == label else f"{name} ({label})"
                elif every or name in assigned:
                    self._texts[name] = name
        self._redraw()

    # -- the markers in the viewport -----------------------------------------------------------
    def _on_model_replaced(self, _model) -> None:
        self._place_markers()

    def _place_markers(self) -> None:
        session = self.state.session
        if session is None:
            return
        scale, rotation, translation, _pairs = marker_to_model_transform(self.context.document.model,
                                                                         session.markers, session.positions)
        self.overlay.set_transform(scale, rotation, translation)
        self._redraw()

    def current_frame(self) -> int:
        session = self.state.session
        return int(np.clip(round(self.context.playhead.time * session.rate_hz), 0, session.n_frames - 1))

    def _redraw(self, *_args) -> None:
        session = self.state.session
        if session is None:
            return
        if self.preview is not None:
            markers, points = self.preview
        else:
            markers, points = session.markers, session.positions[self.current_frame()]
        if self.errors is not None:
            colors = error_colors([self.errors.get(m, np.nan) for m in markers])
        else:
            colors = default_colors(markers, session.reference)
        shown = self.plot_dock.marker
        if shown in markers and self.errors is None:
            colors[markers.index(shown)] = HIGHLIGHT_COLOR
        self.overlay.show(points, colors, names=markers, labels=[self._texts.get(m, "") for m in markers])

    def _on_preview(self, preview) -> None:
        self.preview = preview
        self._redraw()

    def _on_errors(self, errors) -> None:
        self.errors = errors
        self._redraw()


def install(context: ToolContext) -> MocapTool:
    """Add the Motion capture menu and docks to the context's window (``window.mocap`` is the tool)."""
    tool = context.window.mocap = MocapTool(context)
    context.add_actions((
        ActionSpec("mocap.import", "&Import marker file…", MENU, triggered=lambda w: w.mocap.import_dialog_for(),
                   icon="mocap-import", shortcut="Ctrl+Shift+M",
                   tip="Read a QTM TSV, C3D, TRC or CSV marker file into a capture session"),
        ActionSpec("mocap.open", "&Open session…", MENU, triggered=lambda w: w.mocap._open_dialog(),
                   icon="session-open", tip="Open a capture session file (.h5) made by an import"),
        ActionSpec("mocap.save", "&Save session as…", MENU, triggered=lambda w: w.mocap._save_dialog(),
                   icon="session-save", tip="Write the capture session, with its phone labels, to an HDF5 file"),
        ActionSpec("mocap.show", "Show the &recording", MENU, triggered=lambda w: w.mocap.playback.show_session(),
                   icon="mocap-show",
                   tip="Put the capture session back on the player: its markers show and Space plays them"),
        ActionSpec("mocap.plot", "Marker &coordinates", MENU, separator_before=True,
                   triggered=lambda _w: context.reveal(tool.plot_dock, task="mocap"), icon="marker-plot",
                   tip="Plot a marker coordinate over time and select frames"),
        ActionSpec("mocap.pca", "Multistage &PCA…", MENU,
                   triggered=lambda _w: context.reveal(tool.pca_dock, task="mocap"), icon="mocap-pca",
                   tip="Derive articulatory parameters from the selected frames (§3.1.2)"),
    ))
    menu = context.menus[MENU]
    menu.addSeparator()
    menu.addActions([tool.names_panel.undo_action, tool.names_panel.redo_action])
    return tool
