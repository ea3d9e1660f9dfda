"""The "Tool options" dock: one page per editing tool, the active tool's page shown.

Tools (weight painting, the tree editor's property sheet, …) add their page
with :meth:`ToolOptionsDock.add_page` and show it with :meth:`show_page`.
With no tool active the dock shows the *idle page*: a tool may offer one
(:meth:`ToolOptionsDock.set_idle_page`: the tree editor's properties of the
selected parameter), and otherwise the dock says that no tool is active.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QFrame, QLabel, QScrollArea, QStackedWidget, QWidget

from .dock_scroller import MOST_MINIMUM

NO_TOOL = "none"


class _PageScroller(QScrollArea):
    """Holds one page: scrolls it down when it is tall; sideways only when the column is narrower than the page.

    Its minimum width is the page's, up to :data:`~workbench.window.dock_scroller.MOST_MINIMUM`: a wide page
    never makes the window wider than the screen.
    """

    def __init__(self):
        super().__init__()
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)

    def minimumSizeHint(self) -> QSize:
        hint = super().minimumSizeHint()
        page = self.widget()
        if page is None:
            return hint
        return QSize(min(max(hint.width(), self.page_width_wanted()), MOST_MINIMUM.width()), hint.height())

    def page_width_wanted(self) -> int:
        """The width at which the page shows whole, beside the vertical scroll bar."""
        page = self.widget()
        return page.minimumSizeHint().width() + self.verticalScrollBar().sizeHint().width() + 2 * self.frameWidth()


class ToolOptionsDock(QDockWidget):
    """A dock holding a :class:`QStackedWidget` of tool pages, keyed by tool id."""

    fits_by_itself = True       # every page scrolls in its own scroller (see workbench.window.dock_scroller)

    def __init__(self, parent: QWidget | None = None):
        super().__init__("Tool options", parent)
        self.setObjectName("dock:tool-options")
        self.setFeatures(QDockWidget.DockWidgetFeature.DockWidgetMovable
                         | QDockWidget.DockWidgetFeature.DockWidgetFloatable
                         | QDockWidget.DockWidgetFeature.DockWidgetClosable)
        self.stack = QStackedWidget()
        self._pages: dict[str, QWidget] = {}
        # each page scrolls down, so a tall page never sets the window's height
        self._holders: dict[str, _PageScroller] = {}
        self._idle: tuple[str, Callable[[], bool]] | None = None
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

    def show_page(self, tool: str | None = None) -> None:
        """Show ``tool``'s options (its page must have been added); the idle page by default."""
        if tool is None:
            tool = self.idle_tool()
        self.stack.setCurrentWidget(self._holders[tool])

    def set_idle_page(self, tool: str, wanted: Callable[[], bool]) -> None:
        """Show ``tool``'s page instead of the placeholder while no tool is active and ``wanted()`` is true."""
        self._idle = (tool, wanted)

    def idle_tool(self) -> str:
        """The page shown while no tool is active: the idle page if it is wanted now, else the placeholder."""
        if self._idle is not None and self._idle[1]():
            return self._idle[0]
        return NO_TOOL

    def refresh_idle(self, *_args) -> None:
        """Switch between the placeholder and the idle page if one of them is showing (the selection changed)."""
        idle = self._idle[0] if self._idle is not None else NO_TOOL
        if self.current_tool in (NO_TOOL, idle):
            self.show_page()

    def useful_size(self) -> QSize:
        """Wide enough for the page shown not to scroll sideways (:meth:`LayoutManager.reveal`)."""
        holder = self.stack.currentWidget()
        return QSize(holder.page_width_wanted(), 0)
