""""Pick on mesh": the next left click in the viewport gives a surface point instead of turning the camera.

While armed, an event filter on the viewport's render widget takes the left
click, asks :meth:`Viewport.pick` for the surface under it and hands the
point to a callback; Esc or a right click cancels. A click on the
background keeps the picker armed and says so in the status bar.

The point is the surface *as drawn*; when the model is posed, it is carried
back to the rest pose with the offset of the nearest vertex, since pivots
live in the rest frame.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from PySide6.QtCore import QEvent, QObject, Qt, Signal
from PySide6.QtGui import QCursor

MESSAGE_MS = 4000


class PivotPicker(QObject):
    """Arm with :meth:`arm`; ``on_pick(point)`` receives the rest-pose point (mm); ``finished`` after pick or cancel."""

    finished = Signal()

    def __init__(self, viewport, document, on_pick: Callable[[np.ndarray], None], parent: QObject | None = None):
        super().__init__(parent)
        self._viewport = viewport
        self._document = document
        self._on_pick = on_pick
        self._armed = False

    @property
    def armed(self) -> bool:
        return self._armed

    def arm(self, message: str = "Click on the model to place the pivot (Esc: cancel)") -> None:
        if self._armed:
            return
        self._armed = True
        widget = self._viewport.plotter
        widget.installEventFilter(self)
        widget.setCursor(QCursor(Qt.CursorShape.CrossCursor))
        self._status(message, 0)

    def cancel(self) -> None:
        if not self._armed:
            return
        self._armed = False
        widget = self._viewport.plotter
        widget.removeEventFilter(self)
        widget.unsetCursor()
        self._status("", 0)
        self.finished.emit()

    def pick_at(self, x: float, y: float) -> bool:
        """Pick at widget pixel (``x``, ``y``); ``True`` (and disarmed) if it hit the model."""
        hit = self._viewport.pick(x, y)
        if hit is None:
            self._status("Nothing under the cursor: click on the model (Esc: cancel)", MESSAGE_MS)
            return False
        point = np.asarray(hit.point, dtype=float)
        document = self._document
        if not document.is_at_rest():
            point = point - document.vertices()[hit.vertex] + document.model.vertices[hit.vertex]
        self.cancel()
        self._on_pick(point)
        return True

    def eventFilter(self, watched, event) -> bool:
        if not self._armed:
            return False
        kind = event.type()
        if kind == QEvent.Type.MouseButtonPress:
            if event.button() == Qt.MouseButton.LeftButton:
                position = event.position()
                self.pick_at(position.x(), position.y())
            else:
                self.cancel()
            return True
        if kind in (QEvent.Type.MouseButtonRelease, QEvent.Type.MouseButtonDblClick):
            return True          # the camera must not see half a click
        if kind == QEvent.Type.KeyPress and event.key() == Qt.Key.Key_Escape:
            self.cancel()
            return True
        return False

    def _status(self, text: str, ms: int) -> None:
        window = self._viewport.window()
        bar = window.statusBar() if hasattr(window, "statusBar") else None
        if bar is not None:
            if text:
                bar.showMessage(text, ms)
            else:
                bar.clearMessage()
