"""The command library as the workbench sees it: the shipped folder plus the user's folders.

The user's folders are the setting ``library/folders`` (``workbench.settings``),
the same list Export configuration copies from, in search order: a command in
a later folder overrides one of the same name in an earlier one, as
``-L DIR`` does on the command line (``engine.commands.load_library``).

One :class:`~workbench.library_sources.LibrarySources` object per window (the tool
context's ``library_sources``) tells the library editor and the expression
gallery when the folders change or a library file was saved, so both reload.

The library editor's own settings:

=================================  ==============================================
key                                value
=================================  ==============================================
``library_editor/last_file``       the library file last opened or saved
``library_editor/last_dir``        the folder the last library file dialog ended in
=================================  ==============================================
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings

from engine.paths import LIBRARY_DIR

LAST_FILE = "library_editor/last_file"
LAST_DIR = "library_editor/last_dir"


def is_shipped(path: str | Path) -> bool:
    """Whether ``path`` is in the shipped library folder (which Save never writes over)."""
    try:
        return Path(path).resolve().parent == LIBRARY_DIR.resolve()
    except OSError:
        return False


def remember(key: str, value: str) -> None:
    QSettings().setValue(key, value)


def recall(key: str, default: str = "") -> str:
    value = QSettings().value(key, default)
    return str(value) if value else default
