"""Number fields for the property sheet that keep what the model holds unless the user typed something.

A field shows a value rounded for reading (``%.6g``); reading it back gives
the model's exact value for every part the user did not touch, so looking at
a parameter and pressing Enter changes nothing, bit for bit. Text that is not
a number raises :class:`ValueError` naming the field.

>>> field = ScalarField("Minimum")      # doctest: +SKIP
>>> field.show_value(-1.0); field.setText("-2.5")   # doctest: +SKIP
>>> field.value(-1.0)                   # doctest: +SKIP
-2.5
"""

from __future__ import annotations

import math

import numpy as np
from PySide6.QtCore import Signal
from PySide6.QtWidgets import QApplication, QHBoxLayout, QLabel, QLineEdit, QWidget

FIELD_WIDTH = 70


def format_number(value: float) -> str:
    return f"{value:.6g}"


def parse_number(text: str, what: str) -> float:
    try:
        value = float(text.strip().replace(",", ".").replace("−", "-"))
    except ValueError:
        raise ValueError(f"{what}: '{text.strip()}' is not a number") from None
    if not math.isfinite(value):
        raise ValueError(f"{what}: '{text.strip()}' is not a finite number")
    return value


class ScalarField(QLineEdit):
    """One number; ``committed`` when editing finishes with changed text."""

    committed = Signal()

    def __init__(self, what: str, parent: QWidget | None = None):
        super().__init__(parent)
        self.what = what
        self._shown = ""
        self.setObjectName(f"field:{what}")
        self.editingFinished.connect(self._finished)

    def show_value(self, value: float) -> None:
        self._shown = format_number(value)
        self.setText(self._shown)

    def is_edited(self) -> bool:
        return self.text().strip() != self._shown

    def value(self, original: float) -> float:
        return original if not self.is_edited() else parse_number(self.text(), self.what)

    def revert(self) -> None:
        self.setText(self._shown)

    def _finished(self) -> None:
        if self.is_edited():
            self.committed.emit()


class VectorField(QWidget):
    """Three numbers x, y, z; ``committed`` once the user leaves the three (or presses Enter) with changes.

    Tabbing from x to y to z does not commit half a vector, so an axis can be
    turned from (1, 0, 0) to (0, 1, 0) without passing through the zero vector.
    """

    committed = Signal()

    def __init__(self, what: str, parent: QWidget | None = None):
        super().__init__(parent)
        self.what = what
        self.edits = [ScalarField(f"{what} {axis}") for axis in "xyz"]
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(3)
        for axis, edit in zip("xyz", self.edits, strict=True):
            label = QLabel(axis)
            label.setEnabled(False)
            layout.addWidget(label)
            edit.setMinimumWidth(FIELD_WIDTH // 2)
            layout.addWidget(edit, 1)
            edit.editingFinished.connect(self._finished)
        self.setObjectName(f"field:{what}")

    def show_value(self, vector) -> None:
        for edit, v in zip(self.edits, np.asarray(vector, dtype=float), strict=False):
            edit.show_value(float(v))

    def set_texts(self, x: str, y: str, z: str) -> None:
        for edit, text in zip(self.edits, (x, y, z), strict=True):
            edit.setText(text)

    def is_edited(self) -> bool:
        return any(edit.is_edited() for edit in self.edits)

    def value(self, original) -> np.ndarray:
        original = np.asarray(original, dtype=float)
        return np.array([edit.value(float(o)) for edit, o in zip(self.edits, original, strict=False)])

    def revert(self) -> None:
        for edit in self.edits:
            edit.revert()

    def _finished(self) -> None:
        if QApplication.focusWidget() in self.edits and not any(e.hasFocus() and e is self.sender()
                                                               for e in self.edits):
            return          # moved on to another part of the same vector: wait for the whole of it
        if self.is_edited():
            self.committed.emit()
