"""A small plot of time-value curves: one colour per parameter, time in ms, values in parameter units.

>>> plot = CurvePlot()                                                        # doctest: +SKIP
>>> plot.set_curves({"head_nod": (np.array([0, 500, 1000]), np.array([0, .15, 0]))})  # doctest: +SKIP
"""

from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import QPointF, QRectF, QSize, Qt
from PySide6.QtGui import QColor, QPainter, QPainterPath, QPalette, QPen
from PySide6.QtWidgets import QSizePolicy, QWidget

PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
           "#bcbd22", "#7f7f7f")
MARGIN_LEFT, MARGIN_RIGHT, MARGIN_TOP, MARGIN_BOTTOM = 52, 12, 10, 34
LEGEND_ROW = 15


def nice_ticks(low: float, high: float, count: int = 5) -> list[float]:
    """Round tick values covering ``[low, high]`` (1, 2, 5 × a power of ten apart).

    >>> nice_ticks(0, 1000)
    [0.0, 200.0, 400.0, 600.0, 800.0, 1000.0]
    """
    if not (math.isfinite(low) and math.isfinite(high)) or high <= low:
        return [low]
    raw = (high - low) / max(1, count)
    power = 10 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    first = math.ceil(low / step - 1e-9) * step
    ticks = []
    value = first
    while value <= high + step * 1e-9:
        ticks.append(round(value, 12) + 0.0)
        value += step
    return ticks


class CurvePlot(QWidget):
    """Draws ``{name: (times_ms, values)}``; a message replaces the plot when there is nothing to draw."""

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        self.message = "No command to plot"
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.setMinimumHeight(150)
        self.setAutoFillBackground(True)
        self.setBackgroundRole(QPalette.ColorRole.Base)

    def sizeHint(self) -> QSize:
        return QSize(420, 220)

    def set_curves(self, curves: dict[str, tuple[np.ndarray, np.ndarray]]) -> None:
        self.curves = {name: (np.asarray(t, float), np.asarray(v, float)) for name, (t, v) in curves.items()}
        self.message = "" if self.curves else "The command activates nothing"
        self.update()

    def set_message(self, message: str) -> None:
        """Clear the curves and say why (e.g. the arguments do not define an action)."""
        self.curves = {}
        self.message = message
        self.update()

    def colour_of(self, name: str) -> QColor:
        names = list(self.curves)
        return QColor(PALETTE[names.index(name) % len(PALETTE)]) if name in names else QColor("black")

    # -- drawing --------------------------------------------------------------
    def paintEvent(self, _event) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        text_colour = self.palette().color(QPalette.ColorRole.Text)
        if not self.curves:
            painter.setPen(text_colour)
            painter.drawText(self.rect().adjusted(8, 8, -8, -8), Qt.AlignmentFlag.AlignCenter
                             | Qt.TextFlag.TextWordWrap, self.message)
            return
        legend = self._legend_layout(painter.fontMetrics())
        top = MARGIN_TOP + (1 + max(row for _, _, row in legend)) * LEGEND_ROW
        area = QRectF(MARGIN_LEFT, top, max(10, self.width() - MARGIN_LEFT - MARGIN_RIGHT),
                      max(10, self.height() - top - MARGIN_BOTTOM))
        t_low = min(float(t[0]) for t, _ in self.curves.values())
        t_high = max(float(t[-1]) for t, _ in self.curves.values())
        v_low = min(0.0, *(float(v.min()) for _, v in self.curves.values()))
        v_high = max(0.0, *(float(v.max()) for _, v in self.curves.values()))
        if t_high <= t_low:
            t_high = t_low + 1.0
        if v_high <= v_low:
            v_high = v_low + 1.0
        pad = 0.06 * (v_high - v_low)
        v_low, v_high = v_low - pad, v_high + pad

        def to_point(t: float, v: float) -> QPointF:
            return QPointF(area.left() + (t - t_low) / (t_high - t_low) * area.width(),
                           area.bottom() - (v - v_low) / (v_high - v_low) * area.height())

        self._axes(painter, area, to_point, (t_low, t_high), (v_low, v_high), text_colour)
        for name, (times, values) in self.curves.items():
            path = QPainterPath(to_point(float(times[0]), float(values[0])))
            for t, v in zip(times[1:].tolist(), values[1:].tolist(), strict=False):
                path.lineTo(to_point(t, v))
            painter.setPen(QPen(self.colour_of(name), 2.0))
            painter.drawPath(path)
        self._legend(painter, legend, text_colour)

    def _axes(self, painter, area, to_point, t_range, v_range, text_colour) -> None:
        grid = QPen(QColor(0, 0, 0, 30), 1.0)
        painter.setPen(QPen(text_colour, 1.0))
        painter.drawRect(area)
        metrics = painter.fontMetrics()
        for t in nice_ticks(*t_range, count=max(2, int(area.width() // 70))):
            x = to_point(t, v_range[0]).x()
            painter.setPen(grid)
            painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()))
            painter.setPen(text_colour)
            label = f"{t:g}"
            painter.drawText(QPointF(x - metrics.horizontalAdvance(label) / 2, area.bottom() + metrics.ascent() + 2),
                             label)
        for v in nice_ticks(*v_range, count=max(2, int(area.height() // 35))):
            y = to_point(t_range[0], v).y()
            painter.setPen(QPen(QColor(0, 0, 0, 90 if abs(v) < 1e-12 else 30), 1.0))
            painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y))
            painter.setPen(text_colour)
            label = f"{v:g}"
            painter.drawText(QPointF(area.left() - metrics.horizontalAdvance(label) - 4, y + metrics.ascent() / 2 - 1),
                             label)
        caption = "time (ms)"
        painter.drawText(QPointF(area.right() - metrics.horizontalAdvance(caption),
                                 self.height() - 4), caption)
        painter.save()
        painter.translate(12, area.center().y() + metrics.horizontalAdvance("value") / 2)
        painter.rotate(-90)
        painter.drawText(QPointF(0, 0), "value")
        painter.restore()

    def _legend_layout(self, metrics) -> list[tuple[str, float, int]]:
        """``(name, x, row)`` of each legend entry, wrapped to the widget's width."""
        out, x, row = [], float(MARGIN_LEFT), 0
        for name in self.curves:
            width = 22 + metrics.horizontalAdvance(name) + 14
            if x + width > self.width() - MARGIN_RIGHT and x > MARGIN_LEFT:
                x, row = float(MARGIN_LEFT), row + 1
            out.append((name, x, row))
            x += width
        return out

    def _legend(self, painter, layout, text_colour) -> None:
        metrics = painter.fontMetrics()
        for name, x, row in layout:
            y = float(MARGIN_TOP + row * LEGEND_ROW)
            painter.setPen(QPen(self.colour_of(name), 3.0))
            painter.drawLine(QPointF(x, y + 6), QPointF(x + 16, y + 6))
            painter.setPen(text_colour)
            painter.drawText(QPointF(x + 20, y + metrics.ascent() - 1), name)
