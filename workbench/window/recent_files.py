"""File → Open recent: the last models opened or saved, newest first, kept in QSettings.

Files that no longer exist are dropped whenever the list is read.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings, Signal
from PySide6.QtWidgets import QMenu, QWidget

from ..settings import MAX_RECENT_FILES, RECENT_FILES, string_list


def recent_files() -> list[Path]:
    """The remembered files that still exist, newest first (missing ones are forgotten)."""
    stored = string_list(RECENT_FILES)
    existing = [p for p in stored if Path(p).is_file()]
    if existing != stored:
        QSettings().setValue(RECENT_FILES, existing)
    return [Path(p) for p in existing]


def add_recent_file(path: str | Path) -> None:
    """Put ``path`` at the top of the list (once), keeping at most :data:`MAX_RECENT_FILES`."""
    path = str(Path(path).resolve())
    files = [path] + [p for p in string_list(RECENT_FILES) if p != path]
    QSettings().setValue(RECENT_FILES, files[:MAX_RECENT_FILES])


def clear_recent_files() -> None:
    QSettings().setValue(RECENT_FILES, [])


class RecentFilesMenu(QMenu):
    """One action per recent file ("&1 head.xml", full path as tip), then "Clear list".

    Rebuilt each time it is about to show, so it is never out of date.
    """

    file_chosen = Signal(str)

    def __init__(self, parent: QWidget | None = None):
        super().__init__("Open &recent", parent)
        self.setObjectName("menu:recent")
        self.setToolTipsVisible(True)
        self.aboutToShow.connect(self.rebuild)
        self.rebuild()

    def file_actions(self):
        return [a for a in self.actions() if a.data()]

    def rebuild(self) -> None:
        self.clear()
        files = recent_files()
        for i, path in enumerate(files, start=1):
            action = self.addAction(f"&{i} {path.name}")
            action.setData(str(path))
            action.setToolTip(str(path))
            action.setStatusTip(str(path))
            action.triggered.connect(lambda _checked=False, path=str(path): self.file_chosen.emit(path))
        if not files:
            self.addAction("No recent files").setEnabled(False)
        self.addSeparator()
        clear = self.addAction("&Clear list")
        clear.setEnabled(bool(files))
        clear.triggered.connect(self._clear)

    def _clear(self) -> None:
        clear_recent_files()
        self.rebuild()
