"""A bar chart of explained variance per PCA component, coloured by stage (QPainter).

>>> chart = VarianceChart(); chart.set_articulation(art)      # doctest: +SKIP
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QPainter
from PySide6.QtWidgets import QWidget

STAGE_COLORS = (QColor(230, 150, 40), QColor(60, 120, 210), QColor(70, 170, 90), QColor(170, 80, 170),
                QColor(200, 70, 70))


class VarianceChart(QWidget):
    """Bars: explained variance of each component (%), one colour per stage; a legend with each stage's total."""

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.setMinimumHeight(150)
        self.ratios = np.zeros(0)
        self.stages = np.zeros(0, dtype=int)
        self.stage_markers: list[list[str]] = []

    def set_articulation(self, art) -> None:
        if art is None:
            self.ratios, self.stages, self.stage_markers = np.zeros(0), np.zeros(0, dtype=int), []
        else:
            self.ratios = np.asarray(art.explained_variance_ratio, dtype=float)
            self.stages = np.asarray(art.stages, dtype=int)
            self.stage_markers = [list(m) for m in art.stage_markers]
        self.update()

    def bar_heights_percent(self) -> np.ndarray:
        return 100.0 * self.ratios

    def paintEvent(self, _event) -> None:
        painter = QPainter(self)
        painter.fillRect(self.rect(), Qt.GlobalColor.white)
        if not len(self.ratios):
            painter.setPen(QColor(120, 120, 120))
            painter.drawText(self.rect(), Qt.AlignmentFlag.AlignCenter, "Run the PCA to see the explained variance")
            return
        left, right, top, bottom = 40, 215, 12, 26
        plot = QRectF(left, top, max(1, self.width() - left - right), max(1, self.height() - top - bottom))
        painter.setPen(QColor(170, 170, 170))
        for pct in (0, 25, 50, 75, 100):
            y = plot.bottom() - plot.height() * pct / 100
            painter.drawLine(int(plot.left()), int(y), int(plot.right()), int(y))
            painter.drawText(QRectF(0, y - 7, left - 4, 14),
                             Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, f"{pct}%")
        n = len(self.ratios)
        slot = plot.width() / n
        for k, (ratio, stage) in enumerate(zip(self.ratios, self.stages, strict=True)):
            h = plot.height() * ratio
            bar = QRectF(plot.left() + k * slot + slot * 0.15, plot.bottom() - h, slot * 0.7, h)
            painter.fillRect(bar, STAGE_COLORS[(stage - 1) % len(STAGE_COLORS)])
            painter.setPen(QColor(40, 40, 40))
            painter.drawText(QRectF(bar.left() - 10, bar.top() - 14, bar.width() + 20, 13),
                             Qt.AlignmentFlag.AlignCenter, f"{100 * ratio:.1f}")
            painter.drawText(QRectF(bar.left(), plot.bottom() + 3, bar.width(), 16), Qt.AlignmentFlag.AlignCenter,
                             f"PC{k + 1}")
        for s, markers in enumerate(self.stage_markers, start=1):
            total = 100 * self.ratios[self.stages == s].sum()
            y = top + 18 * (s - 1)
            painter.fillRect(QRectF(self.width() - right + 10, y + 2, 12, 12),
                             STAGE_COLORS[(s - 1) % len(STAGE_COLORS)])
            names = ", ".join(markers) if len(markers) <= 2 else f"{markers[0]} … {markers[-1]}"
            painter.setPen(QColor(40, 40, 40))
            painter.drawText(QRectF(self.width() - right + 26, y, right - 28, 16), Qt.AlignmentFlag.AlignVCenter,
                             f"stage {s} ({names}): {total:.1f}%")
