"""Task layouts in the window: building, switching, remembering, revealing one dock, fitting the screen.

:class:`LayoutManager` (``window.layouts``) arranges the docks as a
:class:`~workbench.window.task_layouts.TaskLayout` says, switches between the
layouts (View → Layout, the toolbar's switcher), remembers each one in
QSettings once the user has changed it (``layouts/<id>``), puts a layout back
the way it was built (*Reset layout*), shows one dock in front and usefully
sized (:meth:`~LayoutManager.reveal`), and keeps the window on its screen
(:func:`fit_to_screen`). No dock is left squeezed: revealing one leaves the
others in its column at least :func:`least_height`, and a remembered layout
whose docks were squeezed below that (a layout stored before, or a dock
dragged small) gets that much back when it is restored and before it is stored.

>>> window.layouts.switch("mocap")                    # doctest: +SKIP
>>> window.layouts.reveal(window.expression_gallery_dock)   # doctest: +SKIP
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, QRect, QSettings, QSize, Qt, QTimer
from PySide6.QtGui import QAction, QActionGroup
from PySide6.QtWidgets import QComboBox, QDockWidget, QMainWindow, QMenu, QSizePolicy, QWidget

from .. import settings
from ..icons import icon
from .dock_scroller import FRAME, TITLE_BAR, content_minimum, fitted_lengths, least_height, wanted_size
from .task_layouts import BY_ID, DEFAULT_LAYOUT, LAYOUTS, Stack, TaskLayout

STATE_VERSION = 1             # saveState's version: a layout stored by another dock set is not restored
MIN_VIEWPORT_SHARE = 0.34     # the columns never leave the viewport less than this share of the width
FRESH_MARGIN = QSize(24, 56)  # a fresh window leaves this much of the screen free (for the title bar)
FRESH_MOST = QSize(1760, 1060)
MIN_SIBLING = 90              # what a dock keeps when another in its column is made larger and there is no room

AREAS = {"left": Qt.DockWidgetArea.LeftDockWidgetArea, "right": Qt.DockWidgetArea.RightDockWidgetArea,
         "bottom": Qt.DockWidgetArea.BottomDockWidgetArea}


def fresh_window_size(available: QRect) -> QSize:
    """The size of a window opened with no remembered geometry: nearly the whole screen, up to :data:`FRESH_MOST`."""
    return (available.size() - FRESH_MARGIN).boundedTo(FRESH_MOST)


def fit_to_screen(window: QWidget) -> None:
    """Shrink and move ``window`` (frame included) into its screen's available geometry; floating docks too."""
    screen = window.screen()
    if screen is None:
        return
    available = screen.availableGeometry()
    windows = [window] + [d for d in window.findChildren(QDockWidget) if d.isFloating() and d.isVisible()]
    for widget in windows:
        if widget.isMaximized() or widget.isFullScreen():
            continue
        frame, inner = widget.frameGeometry(), widget.geometry()
        extra = frame.size() - inner.size()
        size = widget.size().boundedTo(available.size() - extra)
        if size != widget.size():
            widget.resize(size)
            frame = widget.frameGeometry()
        x = min(max(frame.x(), available.left()), available.right() + 1 - frame.width())
        y = min(max(frame.y(), available.top()), available.bottom() + 1 - frame.height())
        if (x, y) != (frame.x(), frame.y()):
            widget.move(x, y)


class LayoutManager(QObject):
    """The task layouts of one main window: ``View → Layout``, the toolbar switcher, remembering, revealing."""

    def __init__(self, window: QMainWindow):
        super().__init__(window)
        self.window = window
        self.current = DEFAULT_LAYOUT
        self._pristine: bytes | None = None     # the state just after a layout was applied
        self._sizes_pending = False
        self._unsqueeze_pending = False         # a layout was restored: give squeezed docks room once laid out
        self.actions: dict[str, QAction] = {}
        # A timer of our own, not QTimer.singleShot: a pending single shot would keep the window alive.
        self._pristine_timer = QTimer(self)
        self._pristine_timer.setSingleShot(True)
        self._pristine_timer.setInterval(0)
        self._pristine_timer.timeout.connect(self._take_pristine)
        self._build_menu()
        self._build_switcher()
        for dock in self.docks().values():
            dock.toggleViewAction().triggered.connect(lambda on, dock=dock: on and self.reveal(dock))
            dock.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """A dock's command (Ctrl+G, its View-menu entry) while it is open but behind another tab:
        bring it to the front instead of closing what the user cannot see."""
        if (event.type() == QEvent.Type.Close and isinstance(watched, QDockWidget) and watched.isVisible()
                and not watched.isFloating() and watched.visibleRegion().isEmpty()
                and self.window.tabifiedDockWidgets(watched)):
            event.ignore()
            self.reveal(watched)
            watched.toggleViewAction().setChecked(True)
            return True
        return False

    # -- what there is -----------------------------------------------------------------
    def docks(self) -> dict[str, QDockWidget]:
        return {d.objectName(): d for d in self.window.findChildren(QDockWidget) if d.objectName()}

    @property
    def layout(self) -> TaskLayout:
        return BY_ID[self.current]

    # -- switching ------------------------------------------------------------------------
    def switch(self, layout_id: str) -> None:
        """Remember the layout in use (if the user changed it), then show ``layout_id`` as remembered or built."""
        if layout_id not in BY_ID:
            raise ValueError(f"unknown layout '{layout_id}' (layouts: {', '.join(BY_ID)})")
        if layout_id == self.current:
            return
        self.remember()
        self.current = layout_id
        QSettings().setValue(settings.WINDOW_LAYOUT, layout_id)
        if not self._restore_remembered():
            self.build()
        self._show_current()

    def restore(self) -> None:
        """At start: the layout last used, as remembered or built."""
        layout_id = str(QSettings().value(settings.WINDOW_LAYOUT, DEFAULT_LAYOUT))
        self.current = layout_id if layout_id in BY_ID else DEFAULT_LAYOUT
        if not self._restore_remembered():
            self.build()
        self._show_current()

    def reset(self) -> None:
        """Forget the user's changes to the current layout and build it again."""
        QSettings().remove(settings.layout_key(self.current))
        self.build()

    def remember(self) -> None:
        """Store the current layout (QSettings ``layouts/<id>``) if it differs from how it was applied,
        with no dock squeezed (:meth:`unsqueeze`)."""
        if self._pristine is None:
            return
        state = bytes(self.window.saveState(STATE_VERSION))
        if state != self._pristine:
            if self.unsqueeze():
                state = bytes(self.window.saveState(STATE_VERSION))
            QSettings().setValue(settings.layout_key(self.current), state)
            self._pristine = state

    def unsqueeze(self) -> bool:
        """Give every dock on show in a side column at least :func:`least_height`, taken from the docks
        above and below it that have more (all share alike when the column is too short); whether
        anything changed."""
        window = self.window
        if not window.isVisible():
            return False
        window.layout().activate()
        changed = False
        for column in self._columns():
            heights = [dock.height() for dock in column]
            wanted = fitted_lengths(heights, [least_height(dock) for dock in column])
            if any(abs(w - h) > 1 for w, h in zip(wanted, heights, strict=True)):
                window.resizeDocks(column, [round(w) for w in wanted], Qt.Orientation.Vertical)
                changed = True
        if changed:
            window.layout().activate()
        return changed

    def _columns(self) -> list[list[QDockWidget]]:
        """The docks on show in the side areas, one list (top to bottom) per column; one dock per tab group."""
        window = self.window
        shown: dict[tuple[int, int, int, int], QDockWidget] = {}
        for dock in self.docks().values():
            area = window.dockWidgetArea(dock)
            if (dock.isVisible() and not dock.isFloating() and not dock.visibleRegion().isEmpty()
                    and area in (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea)):
                g = dock.geometry()
                shown.setdefault((g.x(), g.y(), g.width(), g.height()), dock)
        columns: list[list[QDockWidget]] = []
        for dock in sorted(shown.values(), key=lambda d: (d.x(), d.y())):
            column = next((c for c in columns if dock.x() < c[0].x() + c[0].width()
                           and c[0].x() < dock.x() + dock.width()
                           and window.dockWidgetArea(c[0]) == window.dockWidgetArea(dock)), None)
            if column is None:
                columns.append([dock])
            else:
                column.append(dock)
        return [sorted(c, key=lambda d: d.y()) for c in columns if len(c) > 1]

    def is_remembered(self, layout_id: str) -> bool:
        return QSettings().value(settings.layout_key(layout_id)) is not None

    def _restore_remembered(self) -> bool:
        state = QSettings().value(settings.layout_key(self.current))
        if state is None:
            return False
        self._set_corners(self.layout)
        if not self.window.restoreState(state, STATE_VERSION):
            return False
        self._sizes_pending = False
        self._unsqueeze_pending = True
        self._settled()
        return True

    # -- building ----------------------------------------------------------------------------
    def build(self) -> None:
        """Arrange every dock as the current layout says; the sizes follow once the window has its size."""
        layout, window, docks = self.layout, self.window, self.docks()
        self._pristine = None
        window.setUpdatesEnabled(False)
        try:
            for dock in docks.values():
                dock.setFloating(False)
                window.removeDockWidget(dock)
            self._set_corners(layout)
            for area_name, stacks in self._arrangement().items():
                area = AREAS[area_name]
                along = Qt.Orientation.Horizontal if area_name == "bottom" else Qt.Orientation.Vertical
                for stack in stacks:
                    members = [docks[name] for name in stack.docks if name in docks]
                    if not members:
                        continue
                    window.addDockWidget(area, members[0], along)
                    for other in members[1:]:
                        window.tabifyDockWidget(members[0], other)
            for name, dock in docks.items():
                dock.setVisible(name in layout.shown or (name not in layout.docks and not dock.isHidden()))
            for stack in (stack for stacks in self._arrangement().values() for stack in stacks):
                front = self._front(stack)
                if front is not None:
                    front.raise_()
        finally:
            window.setUpdatesEnabled(True)
        if window.isVisible():
            self._size_docks()
        else:
            self._sizes_pending = True

    def window_shown(self) -> None:
        """The window is on screen with its real size: size a freshly built layout, fit the screen."""
        fit_to_screen(self.window)
        if self._sizes_pending:
            self.build()            # again, for the size the window has now
        elif self._unsqueeze_pending:
            self._pristine_timer.start()

    def _set_corners(self, layout: TaskLayout) -> None:
        bottom = Qt.DockWidgetArea.BottomDockWidgetArea
        left = bottom if layout.bottom_spans_window else Qt.DockWidgetArea.LeftDockWidgetArea
        right = bottom if layout.bottom_spans_window else Qt.DockWidgetArea.RightDockWidgetArea
        self.window.setCorner(Qt.Corner.BottomLeftCorner, left)
        self.window.setCorner(Qt.Corner.BottomRightCorner, right)

    def _arrangement(self) -> dict[str, list[Stack]]:
        """The current layout's stacks per area, for this window's height (see :attr:`Stack.tabbed_below`)."""
        height = self._dock_region().height()
        arranged: dict[str, list[Stack]] = {}
        for area, stacks in (("left", self.layout.left), ("right", self.layout.right),
                             ("bottom", self.layout.bottom)):
            column: list[Stack] = []
            for stack in stacks:
                if column and height < stack.tabbed_below:
                    before = column.pop()
                    column.append(Stack(before.docks + stack.docks, before.share + stack.share))
                else:
                    column.append(stack)
            arranged[area] = column
        return arranged

    def _front(self, stack: Stack) -> QDockWidget | None:
        docks = self.docks()
        return next((docks[n] for n in stack.docks if n in docks and not docks[n].isHidden()), None)

    def _dock_region(self) -> QSize:
        """Width and height the docks and the viewport share (the window less menus, toolbars, status bar)."""
        window = self.window
        height = window.height() - window.menuBar().sizeHint().height() - window.statusBar().sizeHint().height()
        for toolbar in window.findChildren(QWidget, options=Qt.FindChildOption.FindDirectChildrenOnly):
            if toolbar.inherits("QToolBar") and toolbar.isVisible():
                height -= toolbar.sizeHint().height()
        return QSize(window.width(), max(height, 1))

    def _size_docks(self) -> None:
        self._sizes_pending = False
        layout, window = self.layout, self.window
        region = self._dock_region()
        width, height = region.width(), region.height()
        fronts = {area: [(s, f) for s in stacks if (f := self._front(s)) is not None]
                  for area, stacks in self._arrangement().items()}
        left = max([layout.left_width * width] + [wanted_size(d).width() for _s, d in fronts["left"]])
        right = max([layout.right_width * width] + [wanted_size(d).width() for _s, d in fronts["right"]])
        left, right = (left if fronts["left"] else 0.0), (right if fronts["right"] else 0.0)
        room = (1.0 - MIN_VIEWPORT_SHARE) * width
        if left + right > room:
            left, right = left * room / (left + right), right * room / (left + right)
        bottom = layout.bottom_height * height if fronts["bottom"] else 0.0
        horizontal, vertical = Qt.Orientation.Horizontal, Qt.Orientation.Vertical
        for area, across in (("left", left), ("right", right)):
            if fronts[area]:
                window.resizeDocks([fronts[area][0][1]], [round(across)], horizontal)
                column = height - bottom if layout.bottom_spans_window else height
                self._share(fronts[area], column, vertical)
        if fronts["bottom"]:
            window.resizeDocks([fronts["bottom"][0][1]], [round(bottom)], vertical)
            row = width if layout.bottom_spans_window else width - left - right
            self._share(fronts["bottom"], row, horizontal)
        self._settled()

    def _share(self, stacks: list[tuple[Stack, QDockWidget]], length: float, orientation) -> None:
        """Give each stack its share of ``length``, but no dock less than its content needs when there is room."""
        if len(stacks) < 2:
            return
        total = sum(stack.share for stack, _dock in stacks)
        lengths = [length * stack.share / total for stack, _dock in stacks]
        vertical = orientation == Qt.Orientation.Vertical
        needs = [(content_minimum(dock).height() + TITLE_BAR) if vertical else (content_minimum(dock).width() + FRAME)
                 for _stack, dock in stacks]
        if sum(needs) <= length:
            lengths = fitted_lengths(lengths, needs)
        self.window.resizeDocks([dock for _stack, dock in stacks], [round(x) for x in lengths], orientation)

    def _settled(self) -> None:
        """Take the state to compare with (what "changed by the user" means) once Qt has laid the docks out."""
        self._pristine = None
        self._pristine_timer.start()

    def _take_pristine(self) -> None:
        if self._sizes_pending:
            return
        self._pristine = bytes(self.window.saveState(STATE_VERSION))
        if self._unsqueeze_pending and self.window.isVisible():
            self._unsqueeze_pending = False
            self.unsqueeze()        # after the pristine state: a layout put right is stored again when left

    # -- showing one dock ------------------------------------------------------------------------
    def reveal(self, dock: QDockWidget, width: int = 0, height: int = 0, task: str | None = None) -> None:
        """Show ``dock`` in front of its tab group, at least ``width`` × ``height`` (its own wish by default).

        ``task``: switch to that task layout first (the Motion capture menu's docks belong to theirs).
        """
        if task is not None:
            self.switch(task)
        dock.show()
        dock.raise_()
        if dock.isFloating():
            dock.activateWindow()
            return
        self.window.layout().activate()         # the dock's place laid out, so that its size is its own
        wanted = QSize(width, height).expandedTo(wanted_size(dock))
        region = self._dock_region()
        area = self.window.dockWidgetArea(dock)
        if area in (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea):
            most_wide = round((1.0 - MIN_VIEWPORT_SHARE) * region.width()) - self._other_column(area)
            most_high = region.height() - 60
        else:
            most_wide = region.width()
            most_high = round(0.6 * region.height())
            if dock.width() < min(wanted.width(), most_wide):      # the bottom row runs under the columns too
                self.window.setCorner(Qt.Corner.BottomLeftCorner, Qt.DockWidgetArea.BottomDockWidgetArea)
                self.window.setCorner(Qt.Corner.BottomRightCorner, Qt.DockWidgetArea.BottomDockWidgetArea)
        if dock.width() < min(wanted.width(), most_wide):
            self._resize(dock, min(wanted.width(), most_wide), Qt.Orientation.Horizontal)
        if dock.height() < min(wanted.height(), most_high):
            self._resize(dock, min(wanted.height(), most_high), Qt.Orientation.Vertical)

    def _resize(self, dock: QDockWidget, length: int, orientation: Qt.Orientation) -> None:
        """Make ``dock`` ``length`` long; docks beside it along ``orientation`` share what is left.

        (``resizeDocks`` alone scales every dock of a column to fit, the one asked for too.)
        """
        window, area = self.window, self.window.dockWidgetArea(dock)
        vertical = orientation == Qt.Orientation.Vertical

        def along(other: QDockWidget) -> bool:     # in the same column (vertical) or row (horizontal)
            a, b = (dock.x(), other.x()) if vertical else (dock.y(), other.y())
            size_a, size_b = (dock.width(), other.width()) if vertical else (dock.height(), other.height())
            return a < b + size_b and b < a + size_a

        siblings = [d for d in self.docks().values() if d is not dock and d.isVisible() and not d.isFloating()
                    and window.dockWidgetArea(d) == area and not d.visibleRegion().isEmpty() and along(d)]
        extent = (lambda d: d.height()) if vertical else (lambda d: d.width())
        rest = sum(extent(d) for d in siblings)
        if not siblings or rest <= 0:
            window.resizeDocks([dock], [length], orientation)
            return
        total = rest + extent(dock)
        # the others keep what they need to be of use (vertically; or a strip each where there is no room)
        keep = [min(least_height(d), extent(d)) if vertical else MIN_SIBLING for d in siblings]
        if total - sum(keep) < min(length, least_height(dock) if vertical else MIN_SIBLING):
            keep = [MIN_SIBLING] * len(siblings)
        left = max(total - length, sum(keep))
        shares = fitted_lengths([left * extent(d) / rest for d in siblings], keep)
        window.resizeDocks([dock, *siblings], [total - left] + [max(round(x), 1) for x in shares], orientation)

    def _other_column(self, area) -> int:
        other = (Qt.DockWidgetArea.RightDockWidgetArea if area == Qt.DockWidgetArea.LeftDockWidgetArea
                 else Qt.DockWidgetArea.LeftDockWidgetArea)
        widths = [d.width() for d in self.docks().values()
                  if d.isVisible() and not d.isFloating() and self.window.dockWidgetArea(d) == other]
        return max(widths, default=0)

    # -- menu and switcher --------------------------------------------------------------------------
    def _build_menu(self) -> None:
        window = self.window
        menu = self.menu = QMenu("&Layout", window)
        group = QActionGroup(self)
        for number, layout in enumerate(LAYOUTS, start=1):
            action = QAction(layout.title, window)
            action.setObjectName(f"layout.{layout.id}")
            action.setCheckable(True)
            action.setIcon(icon(f"layout-{layout.id}"))
            action.setShortcut(f"Ctrl+Alt+{number}")
            action.setToolTip(layout.tip)
            action.setStatusTip(layout.tip)
            action.triggered.connect(lambda _checked=False, layout_id=layout.id: self.switch(layout_id))
            group.addAction(action)
            menu.addAction(action)
            self.actions[action.objectName()] = action
        menu.addSeparator()
        reset = QAction("&Reset layout", window)
        reset.setObjectName("layout.reset")
        reset.setIcon(icon("layout-reset"))
        reset.setToolTip("Put the docks of this layout back where the workbench puts them")
        reset.setStatusTip(reset.toolTip())
        reset.triggered.connect(self.reset)
        menu.addAction(reset)
        self.actions["layout.reset"] = reset
        view = window.menus["&View"]
        view.addSeparator()
        view.addMenu(menu)
        window.actions_by_id.update(self.actions)

    def _build_switcher(self) -> None:
        toolbar = self.window.toolbar
        spacer = QWidget()
        spacer.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Preferred)
        toolbar.addWidget(spacer)
        self.switcher = QComboBox()
        self.switcher.setObjectName("layout-switcher")
        self.switcher.setToolTip("Task layout: the docks arranged for one task (View → Layout)")
        for layout in LAYOUTS:
            self.switcher.addItem(icon(f"layout-{layout.id}"), layout.title, layout.id)
            self.switcher.setItemData(self.switcher.count() - 1, layout.tip, Qt.ItemDataRole.ToolTipRole)
        self.switcher.activated.connect(lambda index: self.switch(self.switcher.itemData(index)))
        toolbar.addWidget(self.switcher)

    def _show_current(self) -> None:
        self.actions[f"layout.{self.current}"].setChecked(True)
        self.switcher.setCurrentIndex(self.switcher.findData(self.current))
