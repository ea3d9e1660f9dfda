"""The expression gallery: every expression command and action unit as a clickable face.

:func:`install` adds the dock ``dock:expression-gallery`` (hidden until
opened) as ``window.expression_gallery``. **Library → Expression gallery**
(Ctrl+G, ``actions_by_id["library.gallery"]``) always shows it in front,
never hides it; **View → Expression gallery** (the dock's own checkable
entry, ``"view.gallery"``, also on the toolbar) opens and closes it.
Clicking a face plays it through the context's ``player`` with its onset, apex and
offset; the intensity slider scales it (``amplitude`` in percent). What is
listed comes from :mod:`engine.timeline.expressions`; the pictures from :mod:`.thumbnails`.

Every face has its name under it (wrapped onto a second line, then elided;
the tooltip has it whole). Each list shows at least one whole row of faces
with their names: where the gallery is too low for a row of expressions and
a row of action units one above the other, the two lists become tabs.
"""

from __future__ import annotations

import re

from PySide6.QtCore import QModelIndex, QSize, Qt
from PySide6.QtGui import QAction, QColor, QIcon, QPainter, QPixmap, QResizeEvent
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QListView,
    QListWidget,
    QListWidgetItem,
    QMenu,
    QPushButton,
    QSlider,
    QStyledItemDelegate,
    QStyleOptionViewItem,
    QTabBar,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError
from engine.timeline.expressions import GalleryEntry, gallery_entries

from ..icons import icon
from ..tools import ToolContext
from .thumbnails import THUMBNAIL_SIZE, ThumbnailCache

DOCK_NAME = "dock:expression-gallery"
MAX_INTENSITY = 150
COLUMNS = 3                 # faces side by side when the gallery is opened
USEFUL_HEIGHT = 500
NAME_ROLE = Qt.ItemDataRole.UserRole
NAME_LINES = 2              # a face's name wraps onto this many lines under it, then is elided
EXPRESSIONS, UNITS = 0, 1   # the tabs, when the lists are tabs
_BREAKS = re.compile(r"(?<=_)|(?<=[a-z])(?=[A-Z])|(?<=[A-Za-z])(?=[0-9])")


def breakable(name: str) -> str:
    """``name`` with a zero-width space where a line may break: after ``_``, inside CamelCase, before digits.

    >>> breakable("eyelid_right_close").split("\u200b"), breakable("HappySurprise").split("\u200b")
    (['eyelid_', 'right_', 'close'], ['Happy', 'Surprise'])
    """
    return _BREAKS.sub("\u200b", name)


class NameUnderFace(QStyledItemDelegate):
    """Draws a face with its name under it, broken between words onto :data:`NAME_LINES` lines, then elided;
    every item the size of the view's grid, so each has room for those lines."""

    def initStyleOption(self, option: QStyleOptionViewItem, index: QModelIndex) -> None:
        super().initStyleOption(option, index)
        option.text = breakable(option.text)

    def sizeHint(self, option: QStyleOptionViewItem, index: QModelIndex) -> QSize:
        view = self.parent()
        return view.gridSize() - QSize(2 * view.spacing(), 2 * view.spacing())


class ExpressionGallery(QWidget):
    """Thumbnails of ``gallery_entries(library, model)`` in two lists, an intensity slider, previews."""

    def __init__(self, context: ToolContext, parent: QWidget | None = None):
        super().__init__(parent)
        self.context = context
        self.sources = context.library_sources
        self.entries: dict[str, GalleryEntry] = {}
        self.items: dict[str, QListWidgetItem] = {}
        self.last_preview: str | None = None
        self.problems: list[UserError] = []
        self.thumbnails = ThumbnailCache(lambda: context.document.model, self)
        self.thumbnails.ready.connect(self._thumbnail_ready)

        self.intensity = QSlider(Qt.Orientation.Horizontal)
        self.intensity.setRange(0, MAX_INTENSITY)
        self.intensity.setValue(100)
        self.intensity.setPageStep(10)
        self.intensity.setToolTip("Intensity in percent (the commands' amplitude): 50 is half the expression")
        self.intensity_label = QLabel()
        self.intensity.valueChanged.connect(self._intensity_changed)
        self.intensity.sliderReleased.connect(self._replay)
        self.validate_button = QPushButton("Validate")
        self.validate_button.setObjectName("expression-gallery.validate")
        self.validate_button.setToolTip("Judge the face last played, at this intensity, with observers trained on "
                                        "photographs of people: face found, emotion (docs/validation.md)")
        self.validate_button.clicked.connect(lambda _checked=False: self.validate())
        self.validation_job = None
        header = QHBoxLayout()
        header.addWidget(QLabel("Intensity"))
        header.addWidget(self.intensity, 1)
        header.addWidget(self.intensity_label)
        header.addWidget(self.validate_button)
        self.hint = QLabel("Click a face to play it: onset, apex, offset")
        self.hint.setStyleSheet("color: palette(mid)")
        self.expressions_label = QLabel("<b>Expressions</b>")
        self.units_label = QLabel("<b>Action units</b>")
        self.expressions_list = self._make_list()
        self.units_list = self._make_list()
        self.tabs = QTabBar()                 # the lists as tabs, on a gallery too low for both
        self.tabs.setObjectName("expression-gallery-tabs")
        self.tabs.setDrawBase(False)
        self.tabs.setExpanding(False)
        self.tabs.addTab("Expressions")
        self.tabs.addTab("Action units")
        self.tabs.currentChanged.connect(self._show_tab)
        self.tabs.hide()
        self.tabbed = False
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(header)
        layout.addWidget(self.hint)
        layout.addWidget(self.tabs)
        layout.addWidget(self.expressions_label)
        layout.addWidget(self.expressions_list, 1)
        layout.addWidget(self.units_label)
        layout.addWidget(self.units_list, 1)
        self.header_layout = header
        self._intensity_changed(self.intensity.value())

        document = context.document
        document.model_replaced.connect(self.rebuild)
        document.parameters_changed.connect(self.rebuild)
        document.regions_changed.connect(self._regions_changed)
        self.sources.changed.connect(self.rebuild)
        self.rebuild()

    def width_for_columns(self, columns: int) -> int:
        """The gallery's width at which its lists show ``columns`` faces side by side."""
        view = self.expressions_list
        grid = view.gridSize().width() + 2 * view.spacing()
        scroll_bar = view.style().pixelMetric(view.style().PixelMetric.PM_ScrollBarExtent)
        margins = self.layout().contentsMargins()
        return columns * grid + scroll_bar + 2 * view.frameWidth() + margins.left() + margins.right() + 8

    def row_height(self) -> int:
        """The height a list needs to show one whole row of faces with their names."""
        view = self.expressions_list
        return view.gridSize().height() + 2 * view.spacing() + 2 * view.frameWidth()

    def height_for(self, tabbed: bool) -> int:
        """The least height at which each list shown has a whole row on show (``tabbed``: one list, else two)."""
        layout = self.layout()
        margins = layout.contentsMargins()
        parts = [self.header_layout.sizeHint().height(), self.hint.sizeHint().height()]
        if tabbed:
            parts += [self.tabs.sizeHint().height(), self.row_height()]
        else:
            parts += [self.expressions_label.sizeHint().height(), self.row_height(),
                      self.units_label.sizeHint().height(), self.row_height()]
        return sum(parts) + layout.spacing() * (len(parts) - 1) + margins.top() + margins.bottom()

    def set_tabbed(self, tabbed: bool) -> None:
        """Show the two lists one above the other, or as tabs (one at a time, with all the height)."""
        self.tabbed = bool(tabbed)
        self.tabs.setVisible(self.tabbed)
        self.expressions_label.setVisible(not self.tabbed)
        self.units_label.setVisible(not self.tabbed)
        self._show_tab(self.tabs.currentIndex())

    def show_list_of(self, name: str) -> None:
        """Bring the list holding entry ``name`` on show (its tab, when the lists are tabs)."""
        item = self.items.get(name)
        if item is not None and self.tabbed:
            self.tabs.setCurrentIndex(UNITS if item.listWidget() is self.units_list else EXPRESSIONS)

    def _show_tab(self, index: int) -> None:
        self.expressions_list.setVisible(not self.tabbed or index == EXPRESSIONS)
        self.units_list.setVisible(not self.tabbed or index == UNITS)

    # -- building ---------------------------------------------------------------
    def _make_list(self) -> QListWidget:
        view = QListWidget()
        view.setViewMode(QListView.ViewMode.IconMode)
        view.setMovement(QListView.Movement.Static)
        view.setResizeMode(QListView.ResizeMode.Adjust)
        view.setWrapping(True)
        view.setUniformItemSizes(True)
        view.setIconSize(QSize(*THUMBNAIL_SIZE))
        view.setWordWrap(True)                          # long names wrap, anywhere if need be, then elide
        view.setTextElideMode(Qt.TextElideMode.ElideRight)
        view.setSpacing(2)
        text_height = NAME_LINES * view.fontMetrics().lineSpacing() + 12   # and the text margins
        view.setGridSize(QSize(THUMBNAIL_SIZE[0] + 14, THUMBNAIL_SIZE[1] + text_height))
        view.setItemDelegate(NameUnderFace(view))
        view.itemClicked.connect(lambda item: self.preview(item.data(NAME_ROLE)))
        view.itemActivated.connect(lambda item: self.preview(item.data(NAME_ROLE)))
        view.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        view.customContextMenuRequested.connect(lambda point, v=view: self._context_menu(v, point))
        return view

    def _context_menu(self, view: QListWidget, point) -> None:
        item = view.itemAt(point)
        if item is None:
            return
        name = item.data(NAME_ROLE)
        menu = QMenu(self)
        menu.addAction(f"Play {name}", lambda: self.preview(name))
        menu.addAction(f"Validate {name}", lambda: self.validate(name))
        menu.exec(view.viewport().mapToGlobal(point))

    def validate(self, name: str | None = None):
        """Judge entry ``name`` (the one last played by default) at the slider's intensity, front view: the
        verdict opens in a dialog (:mod:`workbench.validation_view`). Returns the job judging it."""
        from engine.validation import Intended, intended_emotion

        from ..validation_view import STILL_SIZE, judge_in_background, render_frames

        name = name or self.last_preview
        if name not in self.entries:
            self.context.status.showMessage("Click a face first: Validate judges the face last played", 6000)
            return None
        entry, intensity = self.entries[name], float(self.intensity.value())
        model = self.context.document.model
        try:
            values = entry.timeline(model, intensity).values_at(entry.apex_time)
        except UserError as exc:
            self.context.status.showMessage(f"Cannot validate {name}: {exc}", 6000)
            return None
        frames = render_frames(model, [model.deform(values)], STILL_SIZE, self)
        meant = intended_emotion(name, intensity) if entry.kind == "expression" else None
        intended = Intended(emotion=meant, expression=f"{name} {intensity:g} %")
        self.context.status.showMessage(f"Judging {name}… (the observers take a few seconds to load)", 6000)
        self.validation_job = judge_in_background(frames, intended, None, f"{name} at {intensity:g} %", self)
        return self.validation_job

    def rebuild(self, *_args) -> None:
        """List what the library and the model offer now; pictures come as they are rendered."""
        library, self.problems = self.sources.load()
        model = self.context.document.model
        entries = gallery_entries(library, model)
        self.entries = {e.name: e for e in entries}
        self.items = {}
        self.thumbnails.clear()
        placeholder = _placeholder()
        for view in (self.expressions_list, self.units_list):
            view.clear()
        for entry in entries:
            item = QListWidgetItem(placeholder, entry.name)
            item.setData(NAME_ROLE, entry.name)
            onset, apex, offset = entry.timing
            item.setToolTip(f"{entry.name}: {entry.description}\n"
                            f"onset {onset:g} ms, apex {apex:g} ms, offset {offset:g} ms")
            (self.expressions_list if entry.kind == "expression" else self.units_list).addItem(item)
            self.items[entry.name] = item
        expressions = self.expressions_list.count()
        self.expressions_label.setText(f"<b>Expressions</b> ({expressions})" if expressions else
                                       "<b>Expressions</b>: none in the library fits this model")
        units = self.units_list.count()
        any_au = any(name.startswith("AU") for name in model.parameters.names)
        units_title = "Action units" if any_au else "Parameters"
        self.units_label.setText(f"<b>{units_title}</b> ({units})")
        self.tabs.setTabText(EXPRESSIONS, f"Expressions ({expressions})")
        self.tabs.setTabText(UNITS, f"{units_title} ({units})")
        self.thumbnails.request(entries)

    def _regions_changed(self, *_args) -> None:
        self.thumbnails.clear()
        placeholder = _placeholder()
        for item in self.items.values():
            item.setIcon(placeholder)
        self.thumbnails.request(list(self.entries.values()))

    def _thumbnail_ready(self, name: str) -> None:
        item = self.items.get(name)
        if item is not None:
            picture = QIcon()
            for mode in (QIcon.Mode.Normal, QIcon.Mode.Selected, QIcon.Mode.Active):
                picture.addPixmap(self.thumbnails.pixmaps[name], mode)   # no blue tint on the one playing
            item.setIcon(picture)

    # -- Qt overrides: render pictures only while the gallery is on screen; tabs when too low ----
    def minimumSizeHint(self) -> QSize:
        # the tabbed gallery's: a dock lower than that scrolls the gallery (workbench.window.dock_scroller)
        return QSize(super().minimumSizeHint().width(), self.height_for(tabbed=True))

    def resizeEvent(self, event: QResizeEvent) -> None:
        super().resizeEvent(event)
        tabbed = event.size().height() < self.height_for(tabbed=False)
        if tabbed != self.tabbed:
            self.set_tabbed(tabbed)

    def showEvent(self, event) -> None:
        super().showEvent(event)
        self.thumbnails.set_active(True)

    def hideEvent(self, event) -> None:
        super().hideEvent(event)
        self.thumbnails.set_active(False)

    # -- playing --------------------------------------------------------------------
    def preview(self, name: str, intensity: float | None = None):
        """Play entry ``name`` at ``intensity`` percent (the slider's by default); returns its timeline."""
        entry = self.entries[name]
        self.show_list_of(name)
        intensity = self.intensity.value() if intensity is None else intensity
        try:
            timeline = entry.timeline(self.context.document.model, intensity)
        except UserError as exc:
            self.context.status.showMessage(f"Cannot play {name}: {exc}", 6000)
            return None
        self.last_preview = name
        player = self.context.player
        player.load(timeline, title=f"{name} at {intensity:g} %")
        player.play()
        return timeline

    def _intensity_changed(self, value: int) -> None:
        self.intensity_label.setText(f"{value} %")
        if not self.intensity.isSliderDown():
            self._replay()

    def _replay(self) -> None:
        if self.last_preview in self.entries:
            self.preview(self.last_preview)


def _placeholder() -> QIcon:
    pixmap = QPixmap(*THUMBNAIL_SIZE)
    pixmap.fill(QColor("#e4e4e4"))
    painter = QPainter(pixmap)
    painter.setPen(QColor("#9a9a9a"))
    painter.drawText(pixmap.rect(), Qt.AlignmentFlag.AlignCenter, "…")
    painter.end()
    return QIcon(pixmap)


def show_gallery(context: ToolContext, dock: QDockWidget, gallery: ExpressionGallery) -> None:
    """Library → Expression gallery (Ctrl+G): the gallery in front, at a useful size, its faces focused.

    Never hides it (View → Expression gallery does that): a user pressing Ctrl+G wants to see it.
    """
    context.reveal(dock)
    (gallery.units_list if gallery.tabbed and gallery.tabs.currentIndex() == UNITS
     else gallery.expressions_list).setFocus(Qt.FocusReason.ShortcutFocusReason)


def install(context: ToolContext) -> None:
    """Add the gallery's dock (hidden), Library → Expression gallery and its toolbar toggle."""
    window = context.window
    gallery = ExpressionGallery(context)
    dock = QDockWidget("Expression gallery", window)
    dock.setObjectName(DOCK_NAME)
    dock.setWidget(gallery)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, dock)   # the task layouts give it its place
    dock.hide()
    # three faces or more across, and room for a row of expressions and one of units (LayoutManager.reveal)
    dock.useful_size = lambda: QSize(gallery.width_for_columns(COLUMNS), USEFUL_HEIGHT)
    window.expression_gallery = gallery
    window.expression_gallery_dock = dock
    tip = "Every expression and action unit as a face: click to play it"
    toggle = dock.toggleViewAction()               # View → Expression gallery: open / close (the main window lists it)
    toggle.setIcon(icon("expression-gallery"))
    toggle.setText("Expression &gallery")
    toggle.setToolTip(f"{tip} (Ctrl+G shows it)")
    show = QAction(icon("expression-gallery"), "Expression &gallery", window)
    show.setObjectName("library.gallery")
    show.setShortcut("Ctrl+G")
    show.setToolTip(f"{tip}; shows it in front, whether it was open or not")
    show.setStatusTip(show.toolTip())
    show.triggered.connect(lambda _checked=False: show_gallery(context, dock, gallery))
    menu = context.menus.get("&Library")
    if menu is None:
        menu = context.menus["&Library"] = window.menuBar().addMenu("&Library")
    actions = menu.actions()
    menu.insertAction(actions[1] if len(actions) > 1 else None, show)     # after "Library editor"
    context.toolbar.addAction(toggle)
    context.actions["library.gallery"] = show
    context.actions["view.gallery"] = toggle
