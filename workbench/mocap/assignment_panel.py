"""Naming the session's markers by hand: pick a marker (on the face or in the list), give it its feature point.

The panel sits beside the coordinate plot. Its list holds every marker of
the session: the label the file gave it and the MPEG-4 feature point it has
now. A click on a marker in the 3-D view (:mod:`.marker_picking`) or on its
row selects it (and plots it); the point list offers the points the model
names, with the engine's descriptions, then the head-fixed reference points
(:func:`engine.mocap.marker_assignment.feature_point_choices`). **Assign**
gives the selected marker that point, **Unassign** its file label back
(:func:`~engine.mocap.marker_assignment.assignment_renames`: a marker that
had the point goes back to its label). Each is one step on the session's
undo stack (the panel's Undo / Redo, Ctrl+Z / Ctrl+Shift+Z while the panel
has the focus, and the Motion capture menu). The names are saved with the
session; *Save map…* writes them as a marker map (``label = id``, what
``mocap import --map`` and the import dialog read) and *Load map…* names the
markers by one, in one step.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QEvent, QSize, Qt, Signal
from PySide6.QtGui import QAction, QKeySequence, QUndoCommand
from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QComboBox,
    QFileDialog,
    QGridLayout,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from engine.mocap.marker_assignment import (
    assignment_renames,
    feature_point_choices,
    is_feature_point,
    marker_labels,
    marker_map_renames,
    session_mapping,
)
from engine.mocap.naming import read_mapping, write_mapping

from ..background import show_error
from .state import MocapState

TITLE = "Marker names"
MAP_FILES = "Marker maps (*.map *.txt);;All files (*)"
NO_POINT = "(none: the file's label)"
HINT = "Click a marker on the face or in the list, choose its point, Assign."


class RenameMarkersCommand(QUndoCommand):
    """Markers of the session renamed (a point assigned, taken back, a map loaded): one undo step.

    Made after the renames were applied (:meth:`MocapState.rename_markers`
    returned ``undo``), so the stack's first redo is skipped.
    """

    def __init__(self, state: MocapState, renames: dict[str, str], undo: dict[str, str], text: str):
        super().__init__(text)
        self._state, self._renames, self._undo = state, dict(renames), dict(undo)
        self._skip_next_redo = True

    def redo(self) -> None:
        if self._skip_next_redo:
            self._skip_next_redo = False
            return
        self._state.rename_markers(self._renames)

    def undo(self) -> None:
        self._state.rename_markers(self._undo)


class _MarkerTable(QTableWidget):
    """The marker list; it asks for little height, so the short dock of a laptop screen needs no scrolling."""

    def sizeHint(self) -> QSize:
        return QSize(220, 90)


class AssignmentPanel(QWidget):
    """The marker list, the point list and the buttons, over a :class:`MocapState` and the open model.

    ``marker_selected(str)``: the user chose a marker in the list.
    ``names_shown_changed(bool)``: *Every name* was switched.
    """

    marker_selected = Signal(str)
    names_shown_changed = Signal(bool)

    def __init__(self, state: MocapState, document, folder=None, parent: QWidget | None = None):
        super().__init__(parent)
        self.setObjectName("mocap-marker-names")
        self.state, self.document = state, document
        self._folder = folder or Path.cwd
        self._descriptions: dict[str, str] = {}
        hint = QLabel(HINT)
        hint.setWordWrap(True)
        self.table = _MarkerTable(0, 2)
        self.table.setHorizontalHeaderLabels(["Label in file", "Point"])
        self.table.verticalHeader().setVisible(False)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setMinimumWidth(170)
        self.table.verticalHeader().setDefaultSectionSize(self.table.fontMetrics().height() + 6)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.ResizeToContents)
        self.table.itemSelectionChanged.connect(self._on_row_selected)
        self.point_combo = QComboBox()
        self.point_combo.setMinimumContentsLength(12)
        self.point_combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        self.point_combo.setToolTip("The MPEG-4 feature point of the selected marker: the model's points first "
                                    "(with what each is), then the head-fixed reference points")
        self.assign_button = QPushButton("Assign")
        self.assign_button.setToolTip("Give the selected marker the chosen point (one undo step)")
        self.assign_button.clicked.connect(self.assign_chosen)
        self.unassign_button = QPushButton("Unassign")
        self.unassign_button.setToolTip("Give the selected marker its label from the file back")
        self.unassign_button.clicked.connect(lambda: self.assign(self.current_marker(), None))
        stack = state.undo_stack
        self.undo_button = QPushButton("Undo")
        self.undo_button.clicked.connect(stack.undo)
        self.redo_button = QPushButton("Redo")
        self.redo_button.clicked.connect(stack.redo)
        self.undo_action = QAction("Undo marker name", self)    # for the Motion capture menu
        self.undo_action.triggered.connect(stack.undo)
        self.redo_action = QAction("Redo marker name", self)
        self.redo_action.triggered.connect(stack.redo)
        for signal in (stack.canUndoChanged, stack.canRedoChanged, stack.indexChanged):
            signal.connect(self._update_buttons)
        load = QPushButton("Load map…")
        load.setToolTip("Name the markers by a marker map (label = id, one a line)")
        load.clicked.connect(self._load_map_dialog)
        self.save_map_button = QPushButton("Save map…")
        self.save_map_button.setToolTip("Write the markers' names as a marker map for the next import (--map)")
        self.save_map_button.clicked.connect(self._save_map_dialog)
        self.all_names = QCheckBox("Every name")
        self.all_names.setToolTip("Draw every marker's name beside it on the face (else: the points given here "
                                  "and the selected marker)")
        self.all_names.toggled.connect(self.names_shown_changed)

        controls = QGridLayout()          # beside the list, not under it: the dock is short on a laptop
        controls.setContentsMargins(0, 0, 0, 0)
        controls.setVerticalSpacing(2)
        controls.addWidget(self.point_combo, 0, 0, 1, 2)
        for row, pair in enumerate(((self.assign_button, self.unassign_button), (self.undo_button, self.redo_button),
                                    (load, self.save_map_button)), start=1):
            controls.addWidget(pair[0], row, 0)
            controls.addWidget(pair[1], row, 1)
        controls.addWidget(self.all_names, 4, 0, 1, 2)
        controls.setRowStretch(5, 1)
        body = QHBoxLayout()
        body.setContentsMargins(0, 0, 0, 0)
        body.addWidget(self.table, 1)
        body.addLayout(controls)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        layout.addWidget(hint)
        layout.addLayout(body, 1)

        state.session_changed.connect(self._on_session)
        state.markers_renamed.connect(self._on_renamed)
        document.model_replaced.connect(self._fill_points)
        self._fill_points()
        self._on_session(state.session)

    # -- what is shown -------------------------------------------------------------------
    def _fill_points(self, *_args) -> None:
        current = self.point_combo.currentData()
        self.point_combo.clear()
        self.point_combo.addItem(NO_POINT, "")
        self._descriptions = {}
        for choice in feature_point_choices(self.document.model):
            where = "" if choice.on_model else " (not on this model)"
            self.point_combo.addItem(f"{choice.id}  {choice.description}{where}", choice.id)
            self._descriptions[choice.id] = choice.description
        self.point_combo.setCurrentIndex(max(self.point_combo.findData(current), 0))

    def _on_session(self, _session) -> None:
        self._fill_table()
        self._update_buttons()

    def _on_renamed(self, renames: dict) -> None:
        selected = self.current_marker()
        self._fill_table(renames.get(selected, selected))

    def _fill_table(self, select: str | None = None) -> None:
        session = self.state.session
        self.table.blockSignals(True)
        self.table.setRowCount(0 if session is None else session.n_markers)
        if session is not None:
            for row, (name, label) in enumerate(zip(session.markers, marker_labels(session), strict=True)):
                point = name if is_feature_point(name) else ""
                items = (QTableWidgetItem(label), QTableWidgetItem(point or "—"))
                items[0].setData(Qt.ItemDataRole.UserRole, name)
                items[1].setToolTip(self._descriptions.get(point, ""))
                for column, item in enumerate(items):
                    self.table.setItem(row, column, item)
        self.table.blockSignals(False)
        if select is not None:
            self.select(select)
        self._update_buttons()

    def _update_buttons(self, *_args) -> None:
        stack, has = self.state.undo_stack, self.current_marker() is not None
        self.assign_button.setEnabled(has)
        self.unassign_button.setEnabled(has)
        self.save_map_button.setEnabled(self.state.session is not None)
        for verb, can, text, keys, button, action in (
                ("Undo", stack.canUndo(), stack.undoText(), "Ctrl+Z", self.undo_button, self.undo_action),
                ("Redo", stack.canRedo(), stack.redoText(), "Ctrl+Shift+Z", self.redo_button, self.redo_action)):
            button.setEnabled(can)
            action.setEnabled(can)
            button.setToolTip(f"{verb} “{text}” ({keys} in the marker list)" if can else f"Nothing to {verb.lower()}")
            action.setText(f"{verb} marker name: {text}" if can else f"{verb} marker name")

    def markers(self) -> list[str]:
        """The marker of every row (its name in the session)."""
        return [self.table.item(r, 0).data(Qt.ItemDataRole.UserRole) for r in range(self.table.rowCount())]

    def current_marker(self) -> str | None:
        rows = self.table.selectionModel().selectedRows()
        return self.table.item(rows[0].row(), 0).data(Qt.ItemDataRole.UserRole) if rows else None

    def select(self, marker: str) -> None:
        """Select ``marker``'s row (no ``marker_selected``) and show its point in the point list."""
        markers = self.markers()
        if marker not in markers:
            return
        row = markers.index(marker)
        self.table.blockSignals(True)
        self.table.selectRow(row)
        self.table.blockSignals(False)
        self.table.scrollToItem(self.table.item(row, 0))
        self._show_point_of(marker)
        self._update_buttons()

    def _show_point_of(self, marker: str) -> None:
        index = self.point_combo.findData(marker if is_feature_point(marker) else "")
        self.point_combo.setCurrentIndex(max(index, 0))

    def _on_row_selected(self) -> None:
        marker = self.current_marker()
        if marker is not None:
            self._show_point_of(marker)
            self.marker_selected.emit(marker)
        self._update_buttons()

    # -- naming --------------------------------------------------------------------
    def assign_chosen(self) -> bool:
        return self.assign(self.current_marker(), self.point_combo.currentData() or None)

    def assign(self, marker: str | None, point: str | None) -> bool:
        """Give ``marker`` the feature point ``point`` (``None``: its label back) as one undo step."""
        session = self.state.session
        if session is None or marker is None:
            return False
        try:
            renames = assignment_renames(session, marker, point)
        except Exception as exc:
            show_error(self, TITLE, exc)
            return False
        if not renames:
            return False
        label = marker_labels(session)[session.markers.index(marker)]
        text = f"Assign {point} to {label}" if point else f"Give {label} its file label back"
        return self._rename(renames, text)

    def load_map(self, path: str | Path) -> bool:
        """Name the markers by the marker map at ``path`` (one undo step); labels it lacks keep their names."""
        if self.state.session is None:
            return False
        try:
            renames = marker_map_renames(self.state.session, read_mapping(path))
        except Exception as exc:
            show_error(self, TITLE, exc)
            return False
        return bool(renames) and self._rename(renames, f"Load marker map {Path(path).name}")

    def save_map(self, path: str | Path) -> bool:
        """Write the session's naming as a marker map (:func:`~engine.mocap.marker_assignment.session_mapping`)."""
        if self.state.session is None:
            return False
        try:
            write_mapping(path, session_mapping(self.state.session))
        except Exception as exc:
            show_error(self, TITLE, exc)
            return False
        return True

    def _rename(self, renames: dict[str, str], text: str) -> bool:
        try:
            undo = self.state.rename_markers(renames)
        except Exception as exc:
            show_error(self, TITLE, exc)
            return False
        self.state.undo_stack.push(RenameMarkersCommand(self.state, renames, undo, text))
        return True

    def _load_map_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, "Load marker map", str(self._folder()), MAP_FILES)
        if path:
            self.load_map(path)

    def _save_map_dialog(self) -> None:
        session = self.state.session
        if session is None:
            return
        default = self._folder() / (Path(session.source).stem + ".map")
        path, _ = QFileDialog.getSaveFileName(self, "Save marker map", str(default), MAP_FILES)
        if path:
            self.save_map(path)

    # -- keys: the session's undo while the panel has the focus ----------------------------
    def event(self, event) -> bool:
        if event.type() == QEvent.Type.ShortcutOverride and self._undo_key(event) is not None:
            event.accept()          # ours, not the window's Edit ▸ Undo (the model's)
            return True
        return super().event(event)

    def keyPressEvent(self, event) -> None:
        key = self._undo_key(event)
        if key == "undo":
            self.state.undo_stack.undo()
        elif key == "redo":
            self.state.undo_stack.redo()
        else:
            super().keyPressEvent(event)

    @staticmethod
    def _undo_key(event) -> str | None:
        if event.matches(QKeySequence.StandardKey.Undo):
            return "undo"
        if event.matches(QKeySequence.StandardKey.Redo):
            return "redo"
        return None
