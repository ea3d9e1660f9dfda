"""The track view: a time ruler, one curve per driven parameter, the phones, the current time.

A custom QPainter widget over the :class:`~workbench.playback.player.Player`:

* the ruler at the top, seconds with ticks at a step that keeps labels apart;
* one row per parameter the loaded animation drives, its curve sampled at
  every frame time and drawn across the parameter's range (the dashed line
  is its default); clicking a row's name selects that parameter;
* a row of phones under the tracks when phones are loaded, each label
  between its boundaries;
* the current time as a red line.

Clicking or dragging anywhere right of the names scrubs the playhead (to
the nearest frame). Time runs across the whole width (no zoom).
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QPointF, QRectF, QSize, Qt
from PySide6.QtGui import QColor, QFontMetrics, QMouseEvent, QPainter, QPaintEvent, QPen, QPolygonF
from PySide6.QtWidgets import QSizePolicy, QWidget

LABEL_WIDTH = 170
RULER_HEIGHT = 24
TRACK_HEIGHT = 34
PHONE_HEIGHT = 24
RIGHT_MARGIN = 12
NICE_STEPS = (0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5, 10, 15, 30, 60, 120, 300)
MIN_LABEL_SPACING = 70

TRACK_COLORS = ("#3b82f6", "#ef4444", "#10b981", "#f59e0b", "#8b5cf6", "#ec4899", "#14b8a6", "#84cc16")


def track_span(values: np.ndarray, parameter) -> tuple[float, float]:
    """The value range a track is drawn over: what it covers and its default, a little wider.

    Small motions fill their row (a nod of 0.09 on a ±1 parameter is still a visible curve);
    a flat track gets the parameter's range.
    """
    low = min(float(np.min(values)), parameter.default)
    high = max(float(np.max(values)), parameter.default)
    if high - low < 1e-12:
        low, high = parameter.minimum, parameter.maximum
        if high - low < 1e-12:
            low, high = low - 1.0, high + 1.0
        return low, high
    pad = 0.08 * (high - low)
    return low - pad, high + pad


def ruler_step(duration: float, pixels: float) -> float:
    """The smallest nice step (s) whose ticks are at least :data:`MIN_LABEL_SPACING` px apart."""
    if duration <= 0 or pixels <= 0:
        return 1.0
    for step in NICE_STEPS:
        if step / duration * pixels >= MIN_LABEL_SPACING:
            return step
    return NICE_STEPS[-1]


class TrackView(QWidget):
    """Draws the loaded animation; scrubs the playhead on click and drag."""

    def __init__(self, player, view_state=None, parent: QWidget | None = None):
        super().__init__(parent)
        self.player = player
        self.playhead = player.playhead
        self.view_state = view_state
        self.times = np.zeros(0)                       # frame times (s)
        self.tracks: dict[str, np.ndarray] = {}        # parameter → value at each frame
        self._scrubbing = False
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Preferred)
        self.setMouseTracking(False)
        player.loaded.connect(self.refresh)
        player.document.parameters_changed.connect(self.refresh)
        player.document.model_replaced.connect(self.refresh)
        self.playhead.time_changed.connect(self._on_time_changed)
        self.playhead.range_changed.connect(self.refresh)
        if view_state is not None:
            view_state.selected_parameter_changed.connect(lambda _name: self.update())
        self.refresh()

    # -- data --------------------------------------------------------------
    @property
    def track_names(self) -> list[str]:
        """The parameters drawn, top to bottom."""
        return list(self.tracks)

    def refresh(self, *_args) -> None:
        """Sample the loaded timeline at every frame again (after a load or a model change)."""
        timeline = self.player.timeline
        names = [n for n in self.player.driven if n in self.player.document.model.parameters.names]
        self.tracks = {}
        self.times = np.zeros(0)
        if timeline is not None and names:
            fps, duration = self.playhead.fps, self.playhead.duration
            self.times = np.arange(round(duration * fps) + 1) / fps
            values = timeline.sample(self.times * 1000.0)
            column = {name: i for i, name in enumerate(timeline.parameters)}
            self.tracks = {name: values[:, column[name]] for name in names}
        self.setMinimumHeight(self.sizeHint().height())
        self.updateGeometry()
        self.update()

    def sizeHint(self) -> QSize:
        rows = max(1, len(self.tracks))
        phones = PHONE_HEIGHT if self.player.phones else 0
        return QSize(600, RULER_HEIGHT + rows * TRACK_HEIGHT + phones + 2)

    # -- geometry ----------------------------------------------------------
    def _span(self) -> tuple[float, float]:
        left = float(LABEL_WIDTH)
        return left, max(1.0, self.width() - RIGHT_MARGIN - left)

    def x_of(self, seconds: float) -> float:
        left, width = self._span()
        duration = self.playhead.duration
        return left + (seconds / duration * width if duration > 0 else 0.0)

    def time_at(self, x: float) -> float:
        left, width = self._span()
        duration = self.playhead.duration
        return min(max(0.0, (x - left) / width * duration), duration)

    def track_rect(self, index: int) -> QRectF:
        return QRectF(0, RULER_HEIGHT + index * TRACK_HEIGHT, self.width(), TRACK_HEIGHT)

    def phone_rect(self) -> QRectF:
        return QRectF(0, RULER_HEIGHT + len(self.tracks) * TRACK_HEIGHT, self.width(), PHONE_HEIGHT)

    # -- mouse -------------------------------------------------------------
    def mousePressEvent(self, event: QMouseEvent) -> None:
        if event.button() != Qt.MouseButton.LeftButton:
            return super().mousePressEvent(event)
        x, y = event.position().x(), event.position().y()
        if x < LABEL_WIDTH:
            index = int((y - RULER_HEIGHT) // TRACK_HEIGHT)
            if y >= RULER_HEIGHT and 0 <= index < len(self.tracks) and self.view_state is not None:
                self.view_state.select_parameter(self.track_names[index])
            return
        self._scrubbing = True
        self._scrub_to(x)

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        if self._scrubbing:
            self._scrub_to(event.position().x())

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        self._scrubbing = False

    def _scrub_to(self, x: float) -> None:
        self.playhead.set_frame(round(self.time_at(x) * self.playhead.fps))

    def _on_time_changed(self, _seconds: float) -> None:
        self.update()

    # -- painting ----------------------------------------------------------
    def paintEvent(self, _event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        palette = self.palette()
        painter.fillRect(self.rect(), palette.base())
        self._paint_tracks(painter)
        if self.player.phones:
            self._paint_phones(painter)
        self._paint_ruler(painter)
        if self.playhead.duration > 0:
            x = self.x_of(self.playhead.time)
            painter.setPen(QPen(QColor("#dc2626"), 2))
            painter.drawLine(QPointF(x, 0), QPointF(x, self.height()))
        else:
            painter.setPen(palette.placeholderText().color())
            painter.drawText(self.rect().adjusted(8, RULER_HEIGHT, -8, 0),
                             Qt.AlignmentFlag.AlignCenter | Qt.TextFlag.TextWordWrap,
                             "Nothing loaded — Animation ▸ Open animation… (Ctrl+Shift+O)")
        painter.end()

    def _paint_ruler(self, painter: QPainter) -> None:
        palette = self.palette()
        painter.fillRect(QRectF(0, 0, self.width(), RULER_HEIGHT), palette.window())
        painter.setPen(palette.mid().color())
        painter.drawLine(QPointF(0, RULER_HEIGHT - 0.5), QPointF(self.width(), RULER_HEIGHT - 0.5))
        duration = self.playhead.duration
        title = self.player.title or "Timeline"
        painter.setPen(palette.text().color())
        painter.drawText(QRectF(6, 0, LABEL_WIDTH - 10, RULER_HEIGHT), Qt.AlignmentFlag.AlignVCenter,
                         QFontMetrics(self.font()).elidedText(title, Qt.TextElideMode.ElideRight, LABEL_WIDTH - 12))
        if duration <= 0:
            return
        _left, width = self._span()
        step = ruler_step(duration, width)
        minor = step / 5
        metrics = QFontMetrics(self.font())
        count = int(duration / minor + 1e-9)
        for k in range(count + 1):
            t = k * minor
            x = self.x_of(t)
            major = k % 5 == 0
            painter.setPen(palette.text().color() if major else palette.mid().color())
            painter.drawLine(QPointF(x, RULER_HEIGHT - (10 if major else 5)), QPointF(x, RULER_HEIGHT - 1))
            if major:
                label = f"{t:.2f}".rstrip("0").rstrip(".") + (" s" if k == 0 else "")
                if x + 3 + metrics.horizontalAdvance(label) <= self.width():
                    painter.drawText(QPointF(x + 3, RULER_HEIGHT - 11), label)

    def _paint_tracks(self, painter: QPainter) -> None:
        palette = self.palette()
        tree = self.player.document.model.parameters
        selected = self.view_state.selected_parameter if self.view_state is not None else None
        small = self.font()
        small.setPointSizeF(max(6.0, small.pointSizeF() * 0.75))
        for index, name in enumerate(self.tracks):
            rect = self.track_rect(index)
            if name == selected:
                painter.fillRect(rect, palette.highlight().color().lighter(185))
            elif index % 2:
                painter.fillRect(rect, palette.alternateBase())
            painter.setPen(palette.mid().color())
            painter.drawLine(rect.bottomLeft(), rect.bottomRight())
            painter.setPen(palette.text().color())
            painter.drawText(rect.adjusted(6, 0, LABEL_WIDTH - rect.width() - 4, 0), Qt.AlignmentFlag.AlignVCenter,
                             QFontMetrics(self.font()).elidedText(name, Qt.TextElideMode.ElideRight, LABEL_WIDTH - 52))
            if name not in tree.names or not len(self.times):
                continue
            parameter = tree[name]
            values = self.tracks[name]
            low, high = track_span(values, parameter)
            span = high - low
            top, bottom = rect.top() + 4, rect.bottom() - 4

            def y_of(value, top=top, bottom=bottom, low=low, span=span):
                return bottom - (value - low) / span * (bottom - top)

            painter.setFont(small)
            painter.setPen(palette.placeholderText().color())
            painter.drawText(QRectF(LABEL_WIDTH - 44, rect.top() + 1, 40, 12), Qt.AlignmentFlag.AlignRight,
                             f"{max(float(values.max()), parameter.default):.3g}")
            painter.drawText(QRectF(LABEL_WIDTH - 44, rect.bottom() - 13, 40, 12), Qt.AlignmentFlag.AlignRight,
                             f"{min(float(values.min()), parameter.default):.3g}")
            painter.setFont(self.font())
            pen = QPen(palette.mid().color(), 1, Qt.PenStyle.DashLine)
            painter.setPen(pen)
            y_default = y_of(parameter.default)
            painter.drawLine(QPointF(LABEL_WIDTH, y_default), QPointF(self.x_of(self.playhead.duration), y_default))
            points = QPolygonF([QPointF(self.x_of(t), y_of(v))
                                for t, v in zip(self.times, self.tracks[name], strict=True)])
            painter.setPen(QPen(QColor(TRACK_COLORS[index % len(TRACK_COLORS)]), 1.6))
            painter.drawPolyline(points)

    def _paint_phones(self, painter: QPainter) -> None:
        palette = self.palette()
        rect = self.phone_rect()
        painter.fillRect(rect, palette.window())
        painter.setPen(palette.text().color())
        painter.drawText(rect.adjusted(6, 0, LABEL_WIDTH - rect.width() - 4, 0), Qt.AlignmentFlag.AlignVCenter,
                         "phones")
        metrics = QFontMetrics(self.font())
        for segment in self.player.phones:
            x0 = self.x_of(segment.start_ms / 1000.0)
            x1 = self.x_of(segment.end_ms / 1000.0)
            painter.setPen(palette.mid().color())
            painter.drawLine(QPointF(x0, rect.top()), QPointF(x0, rect.bottom()))
            label = segment.label
            if metrics.horizontalAdvance(label) < x1 - x0 - 2:
                painter.setPen(palette.text().color())
                painter.drawText(QRectF(x0, rect.top(), x1 - x0, rect.height()), Qt.AlignmentFlag.AlignCenter, label)
