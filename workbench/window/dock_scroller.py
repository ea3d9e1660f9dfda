"""A scroll area for a dock's content, so that no dock can make the main window wider or taller than the screen.

A :class:`QMainWindow` is at least as large as the minimum sizes of its docks
add up to; a dock whose content needs 470 px (a row of buttons, a form with
long labels) pushes the window past the edge of a laptop screen. Inside a
:class:`DockScroller` the content keeps its own minimum size and scrolls when
the dock is smaller, while the dock asks the window for at most
:data:`MOST_MINIMUM` (or less, when the content needs less).

>>> dock.setWidget(DockScroller(content))        # doctest: +SKIP

It also says what size a dock is of use at, for the task layouts
(:mod:`workbench.window.layouts`): its content's minimum (:func:`content_minimum`),
its own wish (:func:`wanted_size`), and the height below which it counts as
squeezed (:func:`least_height`).
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtWidgets import QDockWidget, QFrame, QScrollArea, QWidget

MOST_MINIMUM = QSize(240, 140)
"""The most room a dock's content may demand; below its own minimum it scrolls."""
USEFUL_LEAST = 160            # the content height below which a dock is squeezed (when its content would use it), px
TITLE_BAR = 26                # a docked dock's title bar and frame, px
FRAME = 8                     # a docked dock's frame and the separator beside it, px


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


def content_minimum(dock: QDockWidget) -> QSize:
    """The minimum size of what ``dock`` shows (a dock asks the window for less and scrolls, see
    :mod:`workbench.window.dock_scroller`; a layout gives it this much when there is room)."""
    content = dock.widget()
    if isinstance(content, QScrollArea) and content.widget() is not None:
        content = content.widget()
    return content.minimumSizeHint() if content is not None else QSize()


def wanted_size(dock: QDockWidget) -> QSize:
    """The size at which ``dock`` is of use: its own ``useful_size()`` if it has one, else its content's minimum."""
    useful = getattr(dock, "useful_size", None)
    return useful() if callable(useful) else content_minimum(dock)


def least_height(dock: QDockWidget) -> int:
    """The height below which ``dock`` counts as squeezed: its title bar and its content's size hint, or
    :data:`USEFUL_LEAST` px of content when the hint is larger (its content's minimum if that is larger still)."""
    content = dock.widget()
    if content is None:
        return TITLE_BAR
    hint = content.sizeHint().height()
    return TITLE_BAR + min(hint, max(content_minimum(dock).height(), USEFUL_LEAST))


def fitted_lengths(lengths: list[float], needs: list[float]) -> list[float]:
    """``lengths`` changed so that each is at least its ``need``, the room taken from those with more
    than they need (in proportion to what they have over); the total stays. When the total is less
    than the needs, each gets the same share of its need.

    >>> fitted_lengths([500, 100], [186, 186])
    [414.0, 186]
    >>> fitted_lengths([200, 100], [186, 186])
    [150.0, 150.0]
    """
    short = sum(max(need - got, 0.0) for need, got in zip(needs, lengths, strict=True))
    if short <= 0:
        return list(lengths)
    spare = sum(max(got - need, 0.0) for need, got in zip(needs, lengths, strict=True))
    if short <= spare:
        return [need if got < need else got - (got - need) * short / spare
                for need, got in zip(needs, lengths, strict=True)]
    total, wanted = sum(lengths), sum(needs)
    return [total * need / wanted for need in needs]
