"""The library's commands, folder by folder and file by file; double-click opens the file.

A command overridden by a later folder is shown struck out; a file that does
not parse is shown in red with the engine's message as its tooltip.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QBrush, QColor
from PySide6.QtWidgets import QTreeWidget, QTreeWidgetItem, QWidget

from engine.commands.library_format import load_library_file
from engine.errors import UserError

from ..library_sources import LibrarySources, library_files

PATH_ROLE = Qt.ItemDataRole.UserRole
LINE_ROLE = Qt.ItemDataRole.UserRole + 1


class CommandList(QTreeWidget):
    """``file_activated(path, line)`` when a file or one of its commands is double-clicked."""

    file_activated = Signal(str, int)

    def __init__(self, sources: LibrarySources, parent: QWidget | None = None):
        super().__init__(parent)
        self.sources = sources
        self.setHeaderHidden(True)
        self.setMinimumWidth(150)
        self.itemActivated.connect(self._activated)
        self.commands: dict[str, Path] = {}
        """Every command in force → the file defining it (later folders win)."""
        self.reload()

    def reload(self) -> None:
        expanded = {self.topLevelItem(i).text(0) for i in range(self.topLevelItemCount())
                    if self.topLevelItem(i).isExpanded()}
        self.clear()
        items: dict[str, QTreeWidgetItem] = {}
        self.commands = {}
        for label, folder in self.sources.search_path():
            top = QTreeWidgetItem([f"{label} — {folder.name or folder}"])
            top.setToolTip(0, str(folder))
            top.setData(0, PATH_ROLE, "")
            self.addTopLevelItem(top)
            if not folder.is_dir():
                top.setForeground(0, QBrush(QColor("#c0392b")))
                top.setToolTip(0, f"{folder}: the folder does not exist")
            for path in library_files(folder):
                file_item = QTreeWidgetItem([path.name])
                file_item.setData(0, PATH_ROLE, str(path))
                file_item.setData(0, LINE_ROLE, 1)
                file_item.setToolTip(0, str(path))
                top.addChild(file_item)
                try:
                    definitions = load_library_file(path)
                except UserError as exc:
                    file_item.setForeground(0, QBrush(QColor("#c0392b")))
                    file_item.setToolTip(0, str(exc))
                    continue
                for definition in definitions:
                    item = QTreeWidgetItem([definition.name])
                    item.setData(0, PATH_ROLE, str(path))
                    item.setData(0, LINE_ROLE, definition.line)
                    item.setToolTip(0, definition.description or definition.name)
                    file_item.addChild(item)
                    overridden = items.get(definition.name)
                    if overridden is not None:
                        font = overridden.font(0)
                        font.setStrikeOut(True)
                        overridden.setFont(0, font)
                        overridden.setToolTip(0, f"replaced by {path}")
                    items[definition.name] = item
                    self.commands[definition.name] = path
            top.setExpanded(not expanded or top.text(0) in expanded)

    def _activated(self, item: QTreeWidgetItem, _column: int) -> None:
        path = item.data(0, PATH_ROLE)
        if path:
            self.file_activated.emit(path, int(item.data(0, LINE_ROLE) or 1))
