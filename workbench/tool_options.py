"""The "Tool options" dock: one page per editing tool, the active tool's page shown.

Tools (weight painting, the tree editor's property sheet, …) add their page
with :meth:`ToolOptionsDock.add_page` and show it with :meth:`show_page`.
With no tool active the dock says so.
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QFrame, QLabel, QScrollArea, QStackedWidget, QWidget

NO_TOOL = "none"


class _PageScroller(QScrollArea):
    """Holds one page: scrolls it down when it is tall, never sideways (it is at least as wide as the page)."""

    def __init__(self):
        super().__init__()
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)

    def minimumSizeHint(self) -> QSize:
        hint = super().minimumSizeHint()
        page = self.widget()
        if page is None:
            return hint
        width = page.minimumSizeHint().width() + self.verticalScrollBar().sizeHint().width() + 2 * self.frameWidth()
        return QSize(max(hint.width(), width), hint.height())


class ToolOptionsDock(QDockWidget):
    """A dock holding a :class:`QStackedWidget` of tool pages, keyed by tool id."""

    def __init__(self, parent: QWidget | None = None):
        super().__init__("Tool options", parent)
        self.setObjectName("dock:tool-options")
        self.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                         | QDockWidget.DockWidgetFeature.DockWidgetFloatable
                         | QDockWidget.DockWidgetFeature.DockWidgetClosable)
        self.stack = QStackedWidget()
        self._pages: dict[str, QWidget] = {}
        # each page scrolls down, so a tall page never sets the window's height
        self._holders: dict[str, QScrollArea] = {}
        placeholder = QLabel("No tool is active.\nTools for painting weights and editing the\n"
                             "parameter tree show their options here.")
        placeholder.setAlignment(Qt.AlignmentFlag.AlignCenter)
        placeholder.setWordWrap(True)
        placeholder.setEnabled(False)        # drawn greyed out: it is a hint, not content
        self.add_page(NO_TOOL, placeholder)
        self.setWidget(self.stack)

    @property
    def current_tool(self) -> str:
        widget = self.stack.currentWidget()
        return next(tool for tool, holder in self._holders.items() if holder is widget)

    def add_page(self, tool: str, page: QWidget) -> None:
        """Register ``page`` as the options of ``tool`` (replacing an earlier page of that tool)."""
        old = self._holders.pop(tool, None)
        if old is not None:
            self.stack.removeWidget(old)
            old.deleteLater()
        holder = _PageScroller()
        holder.setWidgetResizable(True)
        holder.setFrameShape(QFrame.Shape.NoFrame)
        holder.setWidget(page)
        self._pages[tool] = page
        self._holders[tool] = holder
        self.stack.addWidget(holder)

    def page(self, tool: str) -> QWidget:
        return self._pages[tool]


    def show_page(self, tool: str = NO_TOOL) -> None:
        """Show ``tool``'s options (its page must have been added); the placeholder by default."""
        self.stack.setCurrentWidget(self._holders[tool])
