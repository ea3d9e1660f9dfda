"""A click on a captured marker in the 3-D view selects it (for naming it, and for the coordinate plot).

An event filter on the viewport's render widget watches the left button:
a press and release no more than :data:`CLICK_SLOP_PX` apart, without
modifier keys, on a marker drawn by the :class:`~.marker_overlay.MarkerOverlay`
(within its pick radius) emits ``picked(marker)``. The filter takes no
events: the camera still turns on a drag, and a click that does not move
the mouse does not move the camera either. While the brush paints, a click
paints and picks nothing.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QObject, QPointF, Qt, Signal

if TYPE_CHECKING:
    from ..tools import ToolContext

CLICK_SLOP_PX = 4.0


class MarkerPicker(QObject):
    """``picked(str)``: the marker clicked in ``viewport``."""

    picked = Signal(str)

    def __init__(self, context: ToolContext, overlay, parent: QObject | None = None):
        super().__init__(parent)
        self._context = context
        self._overlay = overlay
        self._pressed_at: QPointF | None = None
        context.viewport.plotter.installEventFilter(self)

    def pick_at(self, x: float, y: float) -> str | None:
        """The marker drawn at widget pixel (``x``, ``y``) of the view, emitted as ``picked``; or ``None``."""
        name = self._overlay.marker_at(x, y, self._context.viewport.world_to_widget)
        if name is not None:
            self.picked.emit(name)
        return name

    def eventFilter(self, watched, event) -> bool:
        kind = event.type()
        if kind not in (QEvent.Type.MouseButtonPress, QEvent.Type.MouseButtonRelease) \
                or event.button() != Qt.MouseButton.LeftButton:
            return False
        if kind == QEvent.Type.MouseButtonPress:
            plain = event.modifiers() == Qt.KeyboardModifier.NoModifier
            self._pressed_at = event.position() if plain and not self._painting() else None
            return False
        pressed, self._pressed_at = self._pressed_at, None
        if pressed is not None:
            moved = event.position() - pressed
            if abs(moved.x()) <= CLICK_SLOP_PX and abs(moved.y()) <= CLICK_SLOP_PX:
                self.pick_at(event.position().x(), event.position().y())
        return False

    def _painting(self) -> bool:
        """Whether weight painting has the mouse: its command (``paint.mode``) is on."""
        paint_mode = self._context.actions.get("paint.mode")
        return bool(paint_mode is not None and paint_mode.isChecked())
