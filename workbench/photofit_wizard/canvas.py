"""A photograph with landmark markers on it: drag them (each drag one undo step), or see a fit laid over it.

Scene coordinates are the photograph's pixels (origin top left, y down), as
POINTS.json has them. A marker keeps its size on screen whatever the zoom.
Required points are red, optional ones cyan; an optional point left out of
the fit (right-click toggles) is drawn hollow and grey. Markers report a
finished drag to :attr:`PhotoCanvas.on_moved` (``id, old, new``), which the
wizard turns into an undo command. :meth:`PhotoCanvas.show_fit` draws a
fitted head over the photograph: its landmarks as green crosses, a line
from each to the user's point, and the head's outline.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping

import numpy as np
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QBrush, QColor, QFont, QImage, QPainter, QPainterPath, QPen, QPixmap, QPolygonF
from PySide6.QtWidgets import (
    QGraphicsEllipseItem,
    QGraphicsItem,
    QGraphicsPixmapItem,
    QGraphicsScene,
    QGraphicsSceneMouseEvent,
    QGraphicsSimpleTextItem,
    QGraphicsView,
    QWidget,
)

MARKER_RADIUS = 5.0                   # screen px
CONTOUR_RADIUS = 3.5                  # screen px: the jaw line's, brows' and nose's iBUG points (ibug.N)
REQUIRED_COLOUR = QColor("#ff3b30")
OPTIONAL_COLOUR = QColor("#19d3f0")
LEFT_OUT_COLOUR = QColor("#9a9a9a")
FIT_COLOUR = QColor("#36e05a")
OUTLINE_COLOUR = QColor("#ffd60a")

#: One landmark's state: pixel position and whether the fit uses it.
PointState = tuple[float, float, bool]


def pixmap_of(photo: np.ndarray) -> QPixmap:
    """A QPixmap of an (H, W, 3) uint8 RGB array."""
    pixels = np.ascontiguousarray(photo[:, :, :3], dtype=np.uint8)
    height, width = pixels.shape[:2]
    image = QImage(pixels.data, width, height, 3 * width, QImage.Format.Format_RGB888)
    return QPixmap.fromImage(image.copy())


class Marker(QGraphicsEllipseItem):
    """One landmark: a dot with its id, dragged by the mouse; right-click leaves an optional one out."""

    def __init__(self, canvas: PhotoCanvas, key: str, required: bool):
        self.radius = CONTOUR_RADIUS if key.startswith("ibug.") else MARKER_RADIUS
        r = self.radius
        super().__init__(-r, -r, 2 * r, 2 * r)
        self.canvas, self.key, self.required = canvas, key, required
        self.used = True
        self._pressed_at: QPointF | None = None
        self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemIgnoresTransformations)
        self.setZValue(10)
        self.setCursor(Qt.CursorShape.OpenHandCursor)
        font = QFont()
        font.setPointSizeF(7.5)
        font.setBold(True)
        text = key.removeprefix("ibug.")                       # a contour point shows its number only
        if text != key:
            font.setPointSizeF(6.0)
            font.setBold(False)
        self.shadow = QGraphicsSimpleTextItem(text, self)       # a dark copy under the label: legible on any photo
        self.shadow.setFont(font)
        self.shadow.setBrush(QBrush(QColor(0, 0, 0, 210)))
        self.shadow.setPos(r + 2, -r - 11)
        self.label = QGraphicsSimpleTextItem(text, self)
        self.label.setFont(font)
        self.label.setPos(r + 1, -r - 12)
        self.set_editable(True)
        self.set_used(True)

    def set_editable(self, editable: bool) -> None:
        """Editable: dragged and toggled, with its id; otherwise a small plain dot (under a fit's crosses)."""
        self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemIsMovable, editable)
        self.setAcceptedMouseButtons(Qt.MouseButton.AllButtons if editable else Qt.MouseButton.NoButton)
        r = self.radius if editable else self.radius * 0.6
        self.setRect(-r, -r, 2 * r, 2 * r)
        self.label.setVisible(editable)
        self.shadow.setVisible(editable)

    def set_used(self, used: bool) -> None:
        self.used = used or self.required
        colour = REQUIRED_COLOUR if self.required else OPTIONAL_COLOUR if self.used else LEFT_OUT_COLOUR
        self.setPen(QPen(QColor("black") if self.used else colour, 1.5))
        self.setBrush(QBrush(colour) if self.used else QBrush(Qt.BrushStyle.NoBrush))
        self.label.setBrush(QBrush(QColor("white") if self.used else LEFT_OUT_COLOUR))
        self.shadow.setVisible(self.used and self.label.isVisible())

    def mousePressEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        if event.button() == Qt.MouseButton.RightButton:
            if not self.required:
                self.canvas.on_toggled(self.key, not self.used)
            event.accept()
            return
        self._pressed_at = QPointF(self.pos())
        super().mousePressEvent(event)

    def mouseReleaseEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        super().mouseReleaseEvent(event)
        start, self._pressed_at = self._pressed_at, None
        if start is not None and start != self.pos():
            self.canvas.on_moved(self.key, (start.x(), start.y()), (self.pos().x(), self.pos().y()))


class PhotoCanvas(QGraphicsView):
    """One photograph and its markers, zoomed to fit (the wheel zooms in and out)."""

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.setScene(QGraphicsScene(self))
        self.setRenderHint(QPainter.RenderHint.Antialiasing)
        self.setTransformationAnchor(QGraphicsView.ViewportAnchor.AnchorUnderMouse)
        self.setBackgroundBrush(QBrush(QColor("#30343a")))
        self.setMinimumSize(240, 240)
        self.markers: dict[str, Marker] = {}
        self.on_moved: Callable[[str, tuple[float, float], tuple[float, float]], object] = lambda *_: None
        self.on_toggled: Callable[[str, bool], object] = lambda *_: None
        self._photo_item: QGraphicsPixmapItem | None = None
        self._fit_items: list[QGraphicsItem] = []
        self._zoomed = False

    # -- content -----------------------------------------------------------------
    def set_photo(self, photo: np.ndarray) -> None:
        scene = self.scene()
        scene.clear()
        self.markers.clear()
        self._fit_items.clear()
        self._photo_item = scene.addPixmap(pixmap_of(photo))
        self._photo_item.setTransformationMode(Qt.TransformationMode.SmoothTransformation)
        height, width = photo.shape[:2]
        scene.setSceneRect(QRectF(0, 0, width, height))
        self._zoomed = False
        self.fit_photo()

    def set_markers(self, state: Mapping[str, PointState], required: Iterable[str], editable: bool = True) -> None:
        """Markers for ``state`` (id → x, y, used), replacing any there were."""
        for marker in self.markers.values():
            self.scene().removeItem(marker)
        self.markers.clear()
        needed = set(required)
        for key, (x, y, used) in state.items():
            marker = Marker(self, key, key in needed)
            marker.setPos(x, y)
            marker.set_used(used)
            marker.set_editable(editable)
            self.scene().addItem(marker)
            self.markers[key] = marker

    def state(self) -> dict[str, PointState]:
        return {k: (m.pos().x(), m.pos().y(), m.used) for k, m in self.markers.items()}

    def apply_state(self, state: Mapping[str, PointState]) -> None:
        """Move and switch the markers there are to ``state`` (ids it lacks stay as they are)."""
        for key, (x, y, used) in state.items():
            marker = self.markers.get(key)
            if marker is not None:
                marker.setPos(x, y)
                marker.set_used(used)

    def used_points(self) -> dict[str, tuple[float, float]]:
        return {k: (x, y) for k, (x, y, used) in self.state().items() if used}

    # -- the fit over the photograph ------------------------------------------------
    def show_fit(self, fitted: Mapping[str, tuple[float, float]], outline: np.ndarray | None) -> None:
        """Green crosses at ``fitted`` landmark pixels joined to the user's points, and the ``outline`` polygon."""
        self.clear_fit()
        scene = self.scene()
        cross = QPainterPath()
        joins = QPainterPath()
        size = max(3.0, 0.006 * max(scene.sceneRect().width(), scene.sceneRect().height()))
        for key, (x, y) in fitted.items():
            cross.moveTo(x - size, y - size)
            cross.lineTo(x + size, y + size)
            cross.moveTo(x - size, y + size)
            cross.lineTo(x + size, y - size)
            marker = self.markers.get(key)
            if marker is not None and marker.used:
                joins.moveTo(marker.pos())
                joins.lineTo(x, y)
        for path, colour, width in ((joins, QColor("white"), 1.0), (cross, FIT_COLOUR, 2.0)):
            pen = QPen(colour, width)
            pen.setCosmetic(True)
            self._fit_items.append(scene.addPath(path, pen))
        if outline is not None and len(outline) > 2:
            pen = QPen(OUTLINE_COLOUR, 1.5, Qt.PenStyle.DashLine)
            pen.setCosmetic(True)
            polygon = QPolygonF([QPointF(float(x), float(y)) for x, y in outline])
            self._fit_items.append(scene.addPolygon(polygon, pen))
        for item in self._fit_items:
            item.setZValue(15)            # over the user's points: where the fit put them is what is looked at

    def clear_fit(self) -> None:
        for item in self._fit_items:
            self.scene().removeItem(item)
        self._fit_items.clear()

    def fit_items(self) -> list[QGraphicsItem]:
        return list(self._fit_items)

    # -- view --------------------------------------------------------------------
    def fit_photo(self) -> None:
        if self._photo_item is not None:
            self.fitInView(self.scene().sceneRect(), Qt.AspectRatioMode.KeepAspectRatio)

    def zoom_to(self, region: QRectF) -> None:
        """Show ``region`` of the photograph (pixels) as large as fits, as the wheel would."""
        self.fitInView(region, Qt.AspectRatioMode.KeepAspectRatio)
        self._zoomed = True

    def resizeEvent(self, event) -> None:
        super().resizeEvent(event)
        if not self._zoomed:
            self.fit_photo()

    def showEvent(self, event) -> None:
        super().showEvent(event)
        if not self._zoomed:
            self.fit_photo()

    def wheelEvent(self, event) -> None:
        factor = 1.2 if event.angleDelta().y() > 0 else 1 / 1.2
        self.scale(factor, factor)
        self._zoomed = True

    def mouseDoubleClickEvent(self, event) -> None:
        if self.itemAt(event.position().toPoint()) in (None, self._photo_item):
            self._zoomed = False
            self.fit_photo()            # double-click the photograph: the whole of it again
            return
        super().mouseDoubleClickEvent(event)

