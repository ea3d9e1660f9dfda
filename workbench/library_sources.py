"""The command library as the workbench sees it: the shipped folder plus the user's folders (§2.3).

The user's folders are the setting ``library/folders`` (``workbench.settings``),
the same list Export configuration copies from, in search order: a command in
a later folder overrides one of the same name in an earlier one, as
``-L DIR`` does on the command line (``engine.commands.load_library``).
The window makes one :class:`LibrarySources` (``context.library_sources``,
:mod:`workbench.tools`), shared by the library editor and the expression gallery.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QObject, QSettings, Signal

from engine.commands import Library, load_library
from engine.commands.library import LIBRARY_SUFFIX
from engine.commands.library_format import load_library_file
from engine.errors import UserError
from engine.paths import LIBRARY_DIR

from . import settings


class LibrarySources(QObject):
    """The library folders setting, and a signal whenever the library on disk may have changed.

    ``changed`` is emitted after :meth:`set_folders` and :meth:`notify_saved`.
    """

    changed = Signal()

    def folders(self) -> list[Path]:
        """The user's folders, in search order (those that do not exist are kept: they may come back)."""
        return [Path(f) for f in settings.library_folders()]

    def set_folders(self, folders: list[str | Path]) -> None:
        QSettings().setValue(settings.LIBRARY_FOLDERS, [str(f) for f in folders])
        self.changed.emit()

    def notify_saved(self, path: str | Path) -> None:
        """A library file was written: whoever lists commands reloads."""
        self.changed.emit()

    def search_path(self) -> list[tuple[str, Path]]:
        """``(label, folder)`` for the shipped folder and every user folder, in search order."""
        out = [("Shipped library", LIBRARY_DIR)]
        out += [(f"User folder {i}", folder) for i, folder in enumerate(self.folders(), start=1)]
        return out

    def load(self) -> tuple[Library, list[UserError]]:
        """The whole library; files that do not parse are left out and reported, not raised.

        Tries :func:`engine.commands.load_library` first (exactly the command
        line's library); when that fails, reads file by file so one bad file
        does not hide the others.
        """
        try:
            return load_library(self.existing_folders()), []
        except UserError:
            pass
        library, problems = Library(), []
        for _label, folder in self.search_path():
            for path in library_files(folder):
                try:
                    for definition in load_library_file(path):
                        library.add(definition)
                except UserError as exc:
                    problems.append(exc)
        return library, problems

    def existing_folders(self) -> list[Path]:
        return [f for f in self.folders() if f.is_dir()]


def library_files(folder: Path) -> list[Path]:
    """The ``*.lib`` files of one folder, sorted; none when it does not exist."""
    return sorted(folder.glob("*" + LIBRARY_SUFFIX)) if folder.is_dir() else []
