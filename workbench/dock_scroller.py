"""A scroll area for a dock's content, so that no dock can make the main window wider or taller than the screen.

A :class:`QMainWindow` is at least as large as the minimum sizes of its docks
add up to; a dock whose content needs 470 px (a row of buttons, a form with
long labels) pushes the window past the edge of a laptop screen. Inside a
:class:`DockScroller` the content keeps its own minimum size and scrolls when
the dock is smaller, while the dock asks the window for at most
:data:`MOST_MINIMUM` (or less, when the content needs less).

>>> dock.setWidget(DockScroller(content))        # doctest: +SKIP
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QFrame, QScrollArea, QWidget

MOST_MINIMUM = QSize(240, 140)
"""The most room a dock's content may demand; below its own minimum it scrolls."""


class DockScroller(QScrollArea):
    """Holds ``content`` at the scroller's size, or at the content's minimum size (scrolling) when that is larger."""

    def __init__(self, content: QWidget | None = None, parent: QWidget | None = None):
        super().__init__(parent)
        self.setWidgetResizable(True)
        self.setFrameShape(QFrame.Shape.NoFrame)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        if content is not None:
            self.setWidget(content)

    def minimumSizeHint(self) -> QSize:
        content = self.widget()
        if content is None:
            return super().minimumSizeHint()
        wanted = content.minimumSizeHint().expandedTo(content.minimumSize())
        return wanted.boundedTo(MOST_MINIMUM)

    def sizeHint(self) -> QSize:
        content = self.widget()
        return super().sizeHint() if content is None else content.sizeHint()


def scroll_dock_content(dock: QDockWidget) -> None:
    """Put ``dock``'s content into a :class:`DockScroller`, unless it already scrolls by itself."""
    content = dock.widget()
    if content is None or isinstance(content, QScrollArea) or getattr(dock, "fits_by_itself", False):
        return
    dock.setWidget(DockScroller(content))
