"""The expression gallery: every expression command and action unit as a clickable face.

:func:`install` adds the dock ``dock:expression-gallery`` (Library →
Expression gallery, Ctrl+G; hidden until opened) as ``window.expression_gallery``.
Clicking a face plays it through ``window.player`` with its onset, apex and
offset; the intensity slider scales it (``amplitude`` in percent). What is
listed comes from :mod:`engine.timeline.expressions`; the pictures from :mod:`.thumbnails`.
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt
from PySide6.QtGui import QColor, QIcon, QPainter, QPixmap
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QListView,
    QListWidget,
    QListWidgetItem,
    QSlider,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError
from engine.timeline.expressions import GalleryEntry, gallery_entries

from ..icons import icon
from ..library_editor import library_sources
from .thumbnails import THUMBNAIL_SIZE, ThumbnailCache

DOCK_NAME = "dock:expression-gallery"
MAX_INTENSITY = 150
COLUMNS = 3                 # faces side by side when the gallery is opened
USEFUL_HEIGHT = 500
NAME_ROLE = Qt.ItemDataRole.UserRole


class ExpressionGallery(QWidget):
    """Thumbnails of ``gallery_entries(library, model)`` in two lists, an intensity slider, previews."""

    def __init__(self, window, parent: QWidget | None = None):
        super().__init__(parent)
        self.window_ = window
        self.sources = library_sources(window)
        self.entries: dict[str, GalleryEntry] = {}
        self.items: dict[str, QListWidgetItem] = {}
        self.last_preview: str | None = None
        self.problems: list[UserError] = []
        self.thumbnails = ThumbnailCache(lambda: window.document.model, self)
        self.thumbnails.ready.connect(self._thumbnail_ready)

        self.intensity = QSlider(Qt.Orientation.Horizontal)
        self.intensity.setRange(0, MAX_INTENSITY)
        self.intensity.setValue(100)
        self.intensity.setPageStep(10)
        self.intensity.setToolTip("Intensity in percent (the commands' amplitude): 50 is half the expression")
        self.intensity_label = QLabel()
        self.intensity.valueChanged.connect(self._intensity_changed)
        self.intensity.sliderReleased.connect(self._replay)
        header = QHBoxLayout()
        header.addWidget(QLabel("Intensity"))
        header.addWidget(self.intensity, 1)
        header.addWidget(self.intensity_label)
        self.hint = QLabel("Click a face to play it: onset, apex, offset")
        self.hint.setStyleSheet("color: palette(mid)")
        self.expressions_label = QLabel("<b>Expressions</b>")
        self.units_label = QLabel("<b>Action units</b>")
        self.expressions_list = self._make_list()
        self.units_list = self._make_list()
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(header)
        layout.addWidget(self.hint)
        layout.addWidget(self.expressions_label)
        layout.addWidget(self.expressions_list, 1)
        layout.addWidget(self.units_label)
        layout.addWidget(self.units_list, 1)
        self._intensity_changed(self.intensity.value())

        document = window.document
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

    # -- building ---------------------------------------------------------------
    def _make_list(self) -> QListWidget:
        view = QListWidget()
        view.setViewMode(QListView.ViewMode.IconMode)
        view.setMovement(QListView.Movement.Static)
        view.setResizeMode(QListView.ResizeMode.Adjust)
        view.setWrapping(True)
        view.setUniformItemSizes(True)
        view.setIconSize(QSize(*THUMBNAIL_SIZE))
        view.setGridSize(QSize(THUMBNAIL_SIZE[0] + 14, THUMBNAIL_SIZE[1] + 34))
        view.setWordWrap(True)
        view.setSpacing(2)
        view.itemClicked.connect(lambda item: self.preview(item.data(NAME_ROLE)))
        view.itemActivated.connect(lambda item: self.preview(item.data(NAME_ROLE)))
        return view

    def rebuild(self, *_args) -> None:
        """List what the library and the model offer now; pictures come as they are rendered."""
        library, self.problems = self.sources.load()
        model = self.window_.document.model
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
            item.setToolTip(f"{entry.description}\nonset {onset:g} ms, apex {apex:g} ms, offset {offset:g} ms")
            (self.expressions_list if entry.kind == "expression" else self.units_list).addItem(item)
            self.items[entry.name] = item
        expressions = self.expressions_list.count()
        self.expressions_label.setText(f"<b>Expressions</b> ({expressions})" if expressions else
                                       "<b>Expressions</b>: none in the library fits this model")
        units = self.units_list.count()
        any_au = any(name.startswith("AU") for name in model.parameters.names)
        self.units_label.setText(f"<b>{'Action units' if any_au else 'Parameters'}</b> ({units})")
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

    # -- Qt overrides: render pictures only while the gallery is on screen ---------------
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
        intensity = self.intensity.value() if intensity is None else intensity
        try:
            timeline = entry.timeline(self.window_.document.model, intensity)
        except UserError as exc:
            self.window_.statusBar().showMessage(f"Cannot play {name}: {exc}", 6000)
            return None
        self.last_preview = name
        player = getattr(self.window_, "player", None)
        if player is None:
            self.window_.document.set_values(timeline.values_at(entry.apex_time))
            return timeline
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


def install(window) -> None:
    gallery = ExpressionGallery(window)
    dock = QDockWidget("Expression gallery", window)
    dock.setObjectName(DOCK_NAME)
    dock.setWidget(gallery)
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, dock)   # the task layouts give it its place
    dock.hide()
    # three faces or more across, and room for a row of expressions and one of units (LayoutManager.reveal)
    dock.useful_size = lambda: QSize(gallery.width_for_columns(COLUMNS), USEFUL_HEIGHT)
    window.expression_gallery = gallery
    window.expression_gallery_dock = dock
    toggle = dock.toggleViewAction()
    toggle.setIcon(icon("expression-gallery"))
    toggle.setText("Expression &gallery")
    toggle.setShortcut("Ctrl+G")
    toggle.setToolTip("Every expression and action unit as a face: click to play it")
    menu = window.menus.get("&Library")
    if menu is None:
        menu = window.menus["&Library"] = window.menuBar().addMenu("&Library")
    actions = menu.actions()
    menu.insertAction(actions[1] if len(actions) > 1 else None, toggle)     # after "Library editor"
    window.toolbar.addAction(toggle)
    window.actions_by_id["library.gallery"] = toggle
