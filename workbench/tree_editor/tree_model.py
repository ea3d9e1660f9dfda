"""The parameter tree as a Qt item model: name, group and type of every parameter, in tree order.

:class:`ParameterTreeModel` mirrors ``document.model.parameters`` and never
edits the model itself: an in-place rename (``setData`` on a name) and a drop
(``dropMimeData``, what :class:`QTreeView` calls when a drag ends over it)
are handed to callbacks, which push undo commands; the model then follows
the document's ``parameters_changed`` signal like every other widget.

>>> model = ParameterTreeModel(rename=lambda old, new: True,                                 # doctest: +SKIP
...                            move=lambda names, parent, before: None)
>>> model.sync(document.model.parameters)                                                      # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QByteArray, QMimeData, QModelIndex, QPersistentModelIndex, Qt
from PySide6.QtGui import QFont, QStandardItem, QStandardItemModel

import engine

MIME_TYPE = "application/x-artificial-person-parameters"
NAME_ROLE = Qt.ItemDataRole.UserRole + 1
COLUMNS = ("Parameter", "Group", "Type")
GROUP_TEXT = {1: "1 · rigid", 2: "2 · leaf"}
GROUP_TIP = {1: "Group 1: has children, so it moves rigidly and carries them (§2.2); "
                "its weights are normalised per vertex",
             2: "Group 2: a leaf, deforming in the rest frame (§2.2); its weights are not normalised"}


def type_text(parameter: engine.Parameter) -> str:
    """``rotation``, ``translation`` or ``field`` for a translation by a displacement field (a blendshape)."""
    if parameter.field:
        return "field"
    return parameter.kind


class ParameterTreeModel(QStandardItemModel):
    """One row per parameter, children under their parent; column 0 editable (rename), rows draggable.

    ``rename(old, new) -> bool`` is called for an edited name and
    ``move(names, parent_or_None, before_or_None)`` for a drop; both push the edit.
    """

    def __init__(self, rename: Callable[[str, str], bool],
                 move: Callable[[list[str], str | None, str | None], None], parent=None):
        super().__init__(parent)
        self._rename = rename
        self._move = move
        self._shape: tuple = ()
        self._items: dict[str, QStandardItem] = {}
        self.setHorizontalHeaderLabels(list(COLUMNS))

    # -- following the document ---------------------------------------------
    def sync(self, tree: engine.ParameterTree) -> bool:
        """Show ``tree``; returns ``True`` if the rows were rebuilt, ``False`` if only texts changed.

        A rename or a property edit keeps the shape of the tree, so the rows
        (and the view's selection, expansion and any open editor) stay.
        """
        entries = tree.depth_first()
        position = {name: i for i, (name, _depth) in enumerate(entries)}
        shape = tuple(position.get(tree[name].parent, -1) for name, _depth in entries)
        if shape == self._shape and len(self._items) == len(entries):
            rows = list(self._items.values())
            self._items = {}
            for (name, _depth), row in zip(entries, rows, strict=True):
                self._fill(row, tree, name)
            return False
        self.removeRows(0, self.rowCount())
        self._items = {}
        flags = (Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
                 | Qt.ItemFlag.ItemIsDragEnabled | Qt.ItemFlag.ItemIsDropEnabled)
        for name, _depth in entries:
            parent = tree[name].parent
            row = [QStandardItem() for _ in COLUMNS]
            for column, item in enumerate(row):
                item.setFlags(flags | Qt.ItemFlag.ItemIsEditable if column == 0 else flags)
            (self._items[parent] if parent is not None else self.invisibleRootItem()).appendRow(row)
            self._fill(row[0], tree, name)
        self._shape = shape
        return True

    def _fill(self, item: QStandardItem, tree: engine.ParameterTree, name: str) -> None:
        parameter = tree[name]
        group = tree.group(name)
        parent = item.parent() or self.invisibleRootItem()
        row = [parent.child(item.row(), column) or item for column in range(len(COLUMNS))]
        texts = (name, GROUP_TEXT[group], type_text(parameter))
        for cell, text in zip(row, texts, strict=True):
            if cell.text() != text:
                cell.setText(text)
            cell.setData(name, NAME_ROLE)
        font = QFont(row[0].font())
        font.setBold(group == 1)
        row[0].setFont(font)
        row[0].setToolTip(parameter.description or name)
        row[1].setToolTip(GROUP_TIP[group])
        self._items[name] = row[0]

    # -- lookups -------------------------------------------------------------
    def index_of(self, name: str) -> QModelIndex:
        """Index of ``name``'s row (column 0); invalid if it is not shown."""
        item = self._items.get(name)
        return item.index() if item is not None else QModelIndex()

    @staticmethod
    def name_at(index: QModelIndex | QPersistentModelIndex) -> str | None:
        return index.data(NAME_ROLE) if index.isValid() else None

    def names(self) -> list[str]:
        """Parameter names as shown, depth first."""
        return list(self._items)

    # -- rename in place ---------------------------------------------------
    def setData(self, index, value, role=Qt.ItemDataRole.EditRole) -> bool:
        if role != Qt.ItemDataRole.EditRole or index.column() != 0:
            return super().setData(index, value, role)
        old = self.name_at(index)
        new = str(value).strip()
        if old is None or new == old:
            return False
        return bool(self._rename(old, new))

    # -- drag and drop -----------------------------------------------------
    def supportedDropActions(self) -> Qt.DropAction:
        return Qt.DropAction.MoveAction

    def supportedDragActions(self) -> Qt.DropAction:
        return Qt.DropAction.MoveAction

    def mimeTypes(self) -> list[str]:
        return [MIME_TYPE]

    def mimeData(self, indexes) -> QMimeData:
        names = list(dict.fromkeys(n for n in (self.name_at(i) for i in indexes) if n is not None))
        data = QMimeData()
        data.setData(MIME_TYPE, QByteArray("\n".join(names).encode()))
        return data

    @staticmethod
    def dragged_names(data: QMimeData) -> list[str]:
        if not data.hasFormat(MIME_TYPE):
            return []
        return [n for n in bytes(data.data(MIME_TYPE).data()).decode().split("\n") if n]

    def canDropMimeData(self, data, action, row, column, parent) -> bool:
        return bool(self.dragged_names(data))

    def dropMimeData(self, data, action, row, column, parent) -> bool:
        """A drop on a row moves the dragged parameters under it (after its children); a drop between
        rows places them there, among those rows' siblings (``row``: the position between them); a
        drop below every row moves them to the top level, last.

        Always returns ``False``: the rows are not moved here but rebuilt
        from the edited model, so the view must not delete the dragged ones.
        """
        names = self.dragged_names(data)
        if not names:
            return False
        target = self.name_at(parent.siblingAtColumn(0)) if parent.isValid() else None
        before = None
        if row >= 0:
            holder = self.itemFromIndex(parent.siblingAtColumn(0)) if parent.isValid() else self.invisibleRootItem()
            if row < holder.rowCount():
                before = holder.child(row, 0).data(NAME_ROLE)
        self._move(names, target, before)
        return False
