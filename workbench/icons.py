"""The workbench's SVG icons (``workbench/icon_files/``, installed with the package), by name.

>>> icon("open")          # doctest: +SKIP
<PySide6.QtGui.QIcon ...>
"""

from __future__ import annotations

from functools import cache
from importlib.resources import files
from pathlib import Path

from PySide6.QtGui import QIcon

ICON_DIR = Path(str(files("workbench") / "icon_files"))
APP_ICON = "artificial-person"


def icon_path(name: str) -> Path:
    return ICON_DIR / f"{name}.svg"


@cache
def icon(name: str) -> QIcon:
    """The icon ``icon_files/<name>.svg``; an empty icon if the file is missing (text still shows)."""
    path = icon_path(name)
    return QIcon(str(path)) if path.exists() else QIcon()
