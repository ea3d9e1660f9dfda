"""Launch timing for ``benchmarks/bench_launch.py``: note when the head is first drawn.

With ``AP_LAUNCH_MARKER=PATH`` in the environment, the workbench writes the
wall-clock time (``time.time()``) of the viewport's first finished paint to
``PATH``; with ``AP_LAUNCH_QUIT=1`` as well it then closes the window. A normal
start sets neither and this does nothing.
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QWidget

if TYPE_CHECKING:
    from ..tools import ToolContext
    from ..viewport.view import Viewport

MARKER = "AP_LAUNCH_MARKER"
QUIT = "AP_LAUNCH_QUIT"


class _FirstPaint(QObject):
    def __init__(self, window: QWidget, viewport: Viewport, path: Path):
        super().__init__(window)
        self._window, self._path = window, path
        viewport.plotter.installEventFilter(self)

    def eventFilter(self, watched, event) -> bool:
        if event.type() == QEvent.Type.Paint and self._window.isVisible():
            watched.removeEventFilter(self)
            QTimer.singleShot(0, self._mark)     # after this paint has been drawn
        return False

    def _mark(self) -> None:
        self._path.write_text(f"{time.time():.6f}\n")
        if os.environ.get(QUIT):
            QTimer.singleShot(0, self._window.close)


def install(context: ToolContext) -> None:
    path = os.environ.get(MARKER)
    if path:
        window = context.window
        window._launch_probe = _FirstPaint(window, context.viewport, Path(path))
