"""A marker coordinate over time, drawn with QPainter: the curve, phone labels, selected spans, the playhead.

*"Frames … were selected manually with a help of time course of relevant
coordinates"* (§3.1.2): the vertical coordinate of the chin marker 2.1
shows every jaw opening. A click on the plot picks one frame and a drag a
range (:attr:`CoordinatePlot.frame_clicked`, :attr:`CoordinatePlot.range_dragged`);
the selection is drawn as shaded spans with their phone label, the phone
labels of the session as boxes along the time axis, the shared playhead as a
red line. Frame ``i`` is at ``i / rate`` s.
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QColor, QFont, QPainter, QPainterPath, QPen
from PySide6.QtWidgets import QSizePolicy, QWidget

LEFT, RIGHT, TOP, BOTTOM = 56, 12, 10, 46
PHONE_BAND = 18
DRAG_PIXELS = 4
SPAN_COLOR = QColor(70, 130, 230, 70)
SPAN_EDGE = QColor(40, 90, 200, 160)
CURVE_COLOR = QColor(30, 30, 30)
PLAYHEAD_COLOR = QColor(220, 30, 30)


class CoordinatePlot(QWidget):
    """One coordinate (mm) of one marker against time (s).

    Signals
    -------
    frame_clicked(int)
        A click (no drag) at this frame.
    range_dragged(int, int)
        A drag from the first to the second frame (in the order dragged).
    """

    frame_clicked = Signal(int)
    range_dragged = Signal(int, int)

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.setMinimumSize(240, 160)     # never a sliver: the dock scrolls below this
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.setMouseTracking(False)
        self.values = np.zeros(0)
        self.rate_hz = 60.0
        self.title = ""
        self.spans: list = []           # Span(start, end, label)
        self.phones: list = []          # (start_ms, end_ms, label)
        self.playhead_s: float | None = 0.0   # None: the player plays something else, no line
        self._press_x: float | None = None
        self._drag_x: float | None = None

    # -- data ------------------------------------------------------------------------
    def set_curve(self, values, rate_hz: float, title: str = "") -> None:
        """The coordinate in every frame (mm; NaN where missing) and the frame rate."""
        self.values = np.asarray(values, dtype=float)
        self.rate_hz = float(rate_hz)
        self.title = title
        self.update()

    def set_spans(self, spans) -> None:
        self.spans = list(spans)
        self.update()

    def set_phones(self, phones) -> None:
        self.phones = list(phones)
        self.update()

    def set_playhead(self, seconds: float | None) -> None:
        """The red line at ``seconds``; ``None`` takes it away (the player plays another animation)."""
        self.playhead_s = None if seconds is None else float(seconds)
        self.update()

    # -- coordinates -------------------------------------------------------------------
    @property
    def n_frames(self) -> int:
        return len(self.values)

    def _plot_rect(self) -> QRectF:
        return QRectF(LEFT, TOP, max(1, self.width() - LEFT - RIGHT), max(1, self.height() - TOP - BOTTOM))

    def x_of_frame(self, frame: float) -> float:
        rect = self._plot_rect()
        last = max(self.n_frames - 1, 1)
        return rect.left() + rect.width() * float(frame) / last

    def frame_at(self, x: float) -> int:
        rect = self._plot_rect()
        last = max(self.n_frames - 1, 1)
        return int(np.clip(round((x - rect.left()) / rect.width() * last), 0, max(self.n_frames - 1, 0)))

    def _value_range(self) -> tuple[float, float]:
        finite = self.values[np.isfinite(self.values)]
        if not len(finite):
            return 0.0, 1.0
        lo, hi = float(finite.min()), float(finite.max())
        pad = max((hi - lo) * 0.08, 0.5)
        return lo - pad, hi + pad

    def _y_of(self, value: np.ndarray, lo: float, hi: float) -> np.ndarray:
        rect = self._plot_rect()
        return rect.bottom() - (value - lo) / (hi - lo) * rect.height()

    # -- mouse -----------------------------------------------------------------------------
    def mousePressEvent(self, event) -> None:
        if event.button() == Qt.MouseButton.LeftButton and self.n_frames:
            self._press_x = self._drag_x = event.position().x()
            self.update()

    def mouseMoveEvent(self, event) -> None:
        if self._press_x is not None:
            self._drag_x = event.position().x()
            self.update()

    def mouseReleaseEvent(self, event) -> None:
        if self._press_x is None or event.button() != Qt.MouseButton.LeftButton:
            return
        start, end = self._press_x, event.position().x()
        self._press_x = self._drag_x = None
        self.update()
        if abs(end - start) < DRAG_PIXELS:
            self.frame_clicked.emit(self.frame_at(start))
        else:
            self.range_dragged.emit(self.frame_at(start), self.frame_at(end))

    # -- drawing --------------------------------------------------------------------------
    def paintEvent(self, _event) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), QColor(250, 250, 250))
        rect = self._plot_rect()
        painter.fillRect(rect, Qt.GlobalColor.white)
        painter.setPen(QColor(180, 180, 180))
        painter.drawRect(rect)
        small = QFont(painter.font())
        small.setPointSizeF(max(7.0, small.pointSizeF() * 0.85))
        painter.setFont(small)
        if not self.n_frames:
            painter.drawText(rect, Qt.AlignmentFlag.AlignCenter, "No session: import or open one (Motion capture menu)")
            return
        half = 0.5 * rect.width() / max(self.n_frames - 1, 1)
        for span in self.spans:
            x0, x1 = self.x_of_frame(span.start) - half, self.x_of_frame(span.end) + half
            painter.fillRect(QRectF(x0, rect.top(), max(x1 - x0, 2.0), rect.height()), SPAN_COLOR)
            if span.label:
                painter.setPen(SPAN_EDGE)
                painter.drawText(QPointF(x0 + 1, rect.top() + 11), span.label)
        if self._press_x is not None and self._drag_x is not None:
            a, b = sorted((self._press_x, self._drag_x))
            painter.fillRect(QRectF(a, rect.top(), max(b - a, 1.0), rect.height()), QColor(240, 160, 40, 90))

        lo, hi = self._value_range()
        ys = self._y_of(self.values, lo, hi)
        xs = np.array([self.x_of_frame(i) for i in range(self.n_frames)])
        path = QPainterPath()
        pen_down = False
        for x, y in zip(xs, ys, strict=True):
            if not np.isfinite(y):
                pen_down = False
            elif pen_down:
                path.lineTo(x, y)
            else:
                path.moveTo(x, y)
                pen_down = True
        painter.setPen(QPen(CURVE_COLOR, 1.4))
        painter.drawPath(path)

        painter.setPen(QColor(90, 90, 90))
        for value in (lo, (lo + hi) / 2, hi):
            y = float(self._y_of(np.array(value), lo, hi))
            painter.drawText(QRectF(0, y - 8, LEFT - 4, 16),
                             Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, f"{value:.1f}")
        duration = (self.n_frames - 1) / self.rate_hz
        step = _nice_step(duration / 8)
        t = 0.0
        while t <= duration + 1e-9:
            x = self.x_of_frame(t * self.rate_hz)
            painter.drawLine(QPointF(x, rect.bottom()), QPointF(x, rect.bottom() + 3))
            painter.drawText(QRectF(x - 30, rect.bottom() + PHONE_BAND + 4, 60, 14), Qt.AlignmentFlag.AlignCenter,
                             f"{t:g} s")
            t += step
        if self.title:
            painter.drawText(QRectF(rect.left() + 4, rect.bottom() - 16, rect.width() - 8, 14),
                             Qt.AlignmentFlag.AlignRight, self.title)

        band = QRectF(rect.left(), rect.bottom() + 2, rect.width(), PHONE_BAND)
        for k, (start, end, label) in enumerate(self.phones):
            x0 = self.x_of_frame(start * self.rate_hz / 1000.0)
            x1 = self.x_of_frame(end * self.rate_hz / 1000.0)
            if x1 < band.left() or x0 > band.right():
                continue
            x0, x1 = max(x0, band.left()), min(x1, band.right())
            box = QRectF(x0, band.top(), max(x1 - x0, 1.0), band.height())
            painter.fillRect(box, QColor(235, 235, 220) if k % 2 else QColor(220, 228, 236))
            painter.setPen(QColor(60, 60, 60))
            painter.drawText(box, Qt.AlignmentFlag.AlignCenter, label)

        if self.playhead_s is not None:
            x = self.x_of_frame(self.playhead_s * self.rate_hz)
            painter.setPen(QPen(PLAYHEAD_COLOR, 1.5))
            painter.drawLine(QPointF(x, rect.top()), QPointF(x, rect.bottom() + PHONE_BAND))


def _nice_step(raw: float) -> float:
    """1, 2 or 5 times a power of ten, at least ``raw``."""
    if raw <= 0:
        return 1.0
    power = 10 ** np.floor(np.log10(raw))
    for m in (1, 2, 5, 10):
        if m * power >= raw:
            return float(m * power)
    return float(10 * power)
