"""The workbench's QSettings keys and defaults, in one place.

Settings live where Qt puts them for the organisation "Artificial Person"
and the application "Artificial Person Workbench" (on Linux
``~/.config/Artificial Person/Artificial Person Workbench.conf``).

==============================  =====================================================
key                             value
==============================  =====================================================
``window/geometry``             the main window's size and place (``saveGeometry``)
``window/layout``               the task layout in use (``model``, ``painting``, ``mocap``, …)
``layouts/<id>``                a task layout's docks and toolbars as the user left them (``saveState``)
``files/last_dir``              folder the last file dialog ended in
``files/recent``                recently opened or saved models, newest first (≤ 8)
``autosave/interval_seconds``   seconds between autosaves of a modified model (60)
``library/folders``             the user's command library folders, in search order
==============================  =====================================================
"""

from __future__ import annotations

from PySide6.QtCore import QSettings

WINDOW_GEOMETRY = "window/geometry"
WINDOW_LAYOUT = "window/layout"
LAST_DIR = "files/last_dir"
RECENT_FILES = "files/recent"
AUTOSAVE_INTERVAL = "autosave/interval_seconds"
LIBRARY_FOLDERS = "library/folders"

DEFAULT_AUTOSAVE_SECONDS = 60.0
MAX_RECENT_FILES = 8


def layout_key(layout_id: str) -> str:
    """Where the task layout ``layout_id`` is remembered once the user has changed it."""
    return f"layouts/{layout_id}"


def string_list(key: str) -> list[str]:
    """A list of strings stored under ``key`` (INI files give back a lone string for one item)."""
    value = QSettings().value(key, [])
    if value is None:
        return []
    if isinstance(value, str):
        return [value] if value else []
    return [str(v) for v in value]


def autosave_interval_seconds() -> float:
    """The autosave interval; the default when unset or not a positive number."""
    try:
        seconds = float(QSettings().value(AUTOSAVE_INTERVAL, DEFAULT_AUTOSAVE_SECONDS))
    except (TypeError, ValueError):
        return DEFAULT_AUTOSAVE_SECONDS
    return seconds if seconds > 0 else DEFAULT_AUTOSAVE_SECONDS


def library_folders() -> list[str]:
    return string_list(LIBRARY_FOLDERS)
