"""A layout that puts its widgets in a row and wraps them onto the next line when the row is too narrow.

Qt's "Flow Layout" example, for rows of controls in docks: one line when
the dock is wide, two or three when it is narrow, and never a minimum width
larger than its widest widget. Items added with a stretch of 1
(:meth:`FlowLayout.addWidget` ``stretch=1``) take what is left of their line.
"""

from __future__ import annotations

from PySide6.QtCore import QMargins, QPoint, QRect, QSize, Qt
from PySide6.QtWidgets import QLayout, QLayoutItem, QWidget, QWidgetItem


class FlowLayout(QLayout):
    """Widgets left to right, wrapped at the layout's width."""

    def __init__(self, parent: QWidget | None = None, spacing: int = 6):
        super().__init__(parent)
        self._items: list[QLayoutItem] = []
        self._stretch: list[int] = []
        self._widgets: list[QWidget] = []
        self.setSpacing(spacing)
        self.setContentsMargins(QMargins(0, 0, 0, 0))

    def addWidget(self, widget: QWidget, stretch: int = 0) -> None:
        self.addChildWidget(widget)
        self._widgets.append(widget)        # a Python reference until a parent widget owns it
        self._items.append(QWidgetItem(widget))
        self._stretch.append(stretch)
        self.invalidate()

    def addItem(self, item: QLayoutItem) -> None:
        self._items.append(item)
        self._stretch.append(0)

    def count(self) -> int:
        return len(self._items)

    def itemAt(self, index: int) -> QLayoutItem | None:
        return self._items[index] if 0 <= index < len(self._items) else None

    def takeAt(self, index: int) -> QLayoutItem | None:
        if 0 <= index < len(self._items):
            self._stretch.pop(index)
            return self._items.pop(index)
        return None

    def expandingDirections(self) -> Qt.Orientation:
        return Qt.Orientation(0)

    def hasHeightForWidth(self) -> bool:
        return True

    def heightForWidth(self, width: int) -> int:
        return self._arrange(QRect(0, 0, width, 0), move=False)

    def setGeometry(self, rect: QRect) -> None:
        super().setGeometry(rect)
        self._arrange(rect, move=True)

    def sizeHint(self) -> QSize:
        width = sum(item.sizeHint().width() for item in self._items) + self.spacing() * max(len(self._items) - 1, 0)
        height = max((item.sizeHint().height() for item in self._items), default=0)
        margins = self.contentsMargins()
        return QSize(width + margins.left() + margins.right(), height + margins.top() + margins.bottom())

    def minimumSize(self) -> QSize:
        size = QSize()
        for item in self._items:
            size = size.expandedTo(item.minimumSize())
        margins = self.contentsMargins()
        return size + QSize(margins.left() + margins.right(), margins.top() + margins.bottom())

    def _lines(self, width: int) -> list[list[int]]:
        """Indices of the visible items on each line at ``width``."""
        lines: list[list[int]] = [[]]
        used = 0
        for index, item in enumerate(self._items):
            if item.isEmpty():
                continue
            wanted = item.sizeHint().width()
            if lines[-1] and used + self.spacing() + wanted > width:
                lines.append([])
                used = 0
            used += (self.spacing() if lines[-1] else 0) + wanted
            lines[-1].append(index)
        return [line for line in lines if line]

    def _arrange(self, rect: QRect, move: bool) -> int:
        """Place the items in ``rect`` (if ``move``); the height they take."""
        margins = self.contentsMargins()
        area = rect.adjusted(margins.left(), margins.top(), -margins.right(), -margins.bottom())
        y = area.y()
        for line in self._lines(area.width()):
            sizes = [self._items[i].sizeHint() for i in line]
            height = max(size.height() for size in sizes)
            spare = area.width() - sum(s.width() for s in sizes) - self.spacing() * (len(line) - 1)
            stretch = sum(self._stretch[i] for i in line)
            x = area.x()
            for index, size in zip(line, sizes, strict=True):
                width = size.width()
                if stretch and spare > 0:
                    width += spare * self._stretch[index] // stretch
                width = max(min(width, area.width()), self._items[index].minimumSize().width())
                if move:        # each at its own height, centred on the line
                    self._items[index].setGeometry(QRect(QPoint(x, y + (height - size.height()) // 2),
                                                         QSize(width, size.height())))
                x += width + self.spacing()
            y += height + self.spacing()
        return max(y - self.spacing() - area.y(), 0) + margins.top() + margins.bottom()
