"""The "Parameter tree" dock: a tree view of the model's parameters, kept in step with the document.

The view shows :class:`~workbench.tree_editor.tree_model.ParameterTreeModel`;
names are renamed in place (double-click or F2), rows are dragged onto
another row to move them under it, or onto the empty space below the rows to
make them roots. Selecting a row selects the parameter in the shared
:class:`~workbench.document.view_state.ViewState` (the viewport then shows its
influence region as a heat map), and a selection made elsewhere is shown here.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QItemSelectionModel, QSize, Qt, Signal
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QAbstractItemView, QDockWidget, QHeaderView, QTreeView, QVBoxLayout, QWidget

import engine

from ..document.model_document import ModelDocument
from ..document.view_state import ViewState
from .tree_model import ParameterTreeModel


class ParameterTreeView(QTreeView):
    """A tree view whose Delete key asks to remove the selected parameter."""

    delete_requested = Signal()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        if event.key() in (Qt.Key.Key_Delete, Qt.Key.Key_Backspace) and self.state() != self.State.EditingState:
            self.delete_requested.emit()
            return
        super().keyPressEvent(event)


class ParameterTreeDock(QDockWidget):
    """Dock ``dock:parameter-tree`` with :attr:`view` over :attr:`model`.

    ``rename(old, new) -> bool`` and ``move(names, parent, before)`` push the
    edits (see :class:`~workbench.tree_editor.editor.TreeEditor`).
    ``picked_by_user`` is emitted when the user (not a sync) selects a row.
    """

    picked_by_user = Signal(object)

    def __init__(self, document: ModelDocument, view_state: ViewState,
                 rename: Callable[[str, str], bool],
                 move: Callable[[list[str], str | None, str | None], None],
                 parent: QWidget | None = None):
        super().__init__("Parameter tree", parent)
        self.setObjectName("dock:parameter-tree")
        self.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                         | QDockWidget.DockWidgetFeature.DockWidgetFloatable
                         | QDockWidget.DockWidgetFeature.DockWidgetClosable)
        self._document = document
        self._view_state = view_state
        self._syncing = False
        self._collapsed: set[str] = set()

        self.model = ParameterTreeModel(rename, move, self)
        self.view = ParameterTreeView()
        self.view.setModel(self.model)
        self.view.setObjectName("tree-editor:view")
        self.view.setUniformRowHeights(True)
        self.view.setAlternatingRowColors(True)
        self.view.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.view.setEditTriggers(QAbstractItemView.EditTrigger.DoubleClicked
                                  | QAbstractItemView.EditTrigger.EditKeyPressed)
        # DragDrop, not InternalMove: the model accepts only its own rows' MIME type anyway, and
        # InternalMove would ignore every drop whose source is not a drag this view started.
        self.view.setDragDropMode(QAbstractItemView.DragDropMode.DragDrop)
        self.view.setDefaultDropAction(Qt.DropAction.MoveAction)
        self.view.setDropIndicatorShown(True)
        header = self.view.header()
        header.setStretchLastSection(True)          # names are never cut short: the view scrolls instead
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.ResizeToContents)
        self.view.setIndentation(14)
        self.view.collapsed.connect(lambda index: self._collapsed.add(self.model.name_at(index)))
        self.view.expanded.connect(lambda index: self._collapsed.discard(self.model.name_at(index)))

        body = QWidget()
        layout = QVBoxLayout(body)
        layout.setContentsMargins(2, 2, 2, 2)
        layout.addWidget(self.view)
        self.setWidget(body)

        self.view.selectionModel().selectionChanged.connect(self._on_view_selection)
        view_state.selected_parameter_changed.connect(self.show_selected)
        document.parameters_changed.connect(self._on_tree_edited)
        document.model_replaced.connect(self._on_model_replaced)
        self._sync(document.model)

    def sizeHint(self) -> QSize:
        return QSize(340, 420)

    # -- queries -------------------------------------------------------------
    def selected_name(self) -> str | None:
        rows = self.view.selectionModel().selectedRows(0)
        return self.model.name_at(rows[0]) if rows else None

    # -- following the document and the view state ----------------------------
    def show_selected(self, name: str | None = None) -> None:
        """Select ``name``'s row (none for ``None``) without echoing it back to the view state."""
        self._syncing = True
        try:
            selection = self.view.selectionModel()
            index = self.model.index_of(name) if name is not None else None
            if index is not None and index.isValid():
                selection.setCurrentIndex(index, QItemSelectionModel.SelectionFlag.ClearAndSelect
                                          | QItemSelectionModel.SelectionFlag.Rows)
                self.view.scrollTo(index)
            else:
                selection.clearSelection()
        finally:
            self._syncing = False

    def _sync(self, model: engine.Model) -> None:
        self._syncing = True
        try:
            rebuilt = self.model.sync(model.parameters)
            if rebuilt:
                self.view.expandAll()
                for name in self._collapsed & set(self.model.names()):
                    self.view.collapse(self.model.index_of(name))
                self._collapsed &= set(self.model.names())
        finally:
            self._syncing = False
        if rebuilt:
            self.show_selected(self._view_state.selected_parameter)

    def _on_tree_edited(self, names: list) -> None:
        tree = self._document.model.parameters
        selected = self._view_state.selected_parameter
        self._sync(self._document.model)
        if selected is not None and selected not in tree:
            # A rename (or its undo) announces [old, new]: follow the parameter to its new name.
            renamed = [n for n in names if n != selected and n in tree]
            follow = renamed[0] if len(names) == 2 and selected in names and len(renamed) == 1 else None
            self._view_state.select_parameter(follow)

    def _on_model_replaced(self, model: engine.Model) -> None:
        self._collapsed.clear()
        self._sync(model)

    def _on_view_selection(self, *_args) -> None:
        if self._syncing:
            return
        name = self.selected_name()
        self._view_state.select_parameter(name)
        self.picked_by_user.emit(name)
