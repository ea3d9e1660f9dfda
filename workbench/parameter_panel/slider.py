"""One parameter as a row: name, slider, value box, reset button.

The slider's integer positions map linearly onto the parameter's
[minimum, maximum] in round steps (1000 to 10000 of them: 0.001 for a range
of 1 or 2, 0.01 for a range of 30), so dragging lands on values that read
well; the spin box shows (and accepts) the exact value. The
row writes user edits to the document and redraws itself only from the
document's ``values_changed`` signal, blocking its own widgets' signals while
it does so, so an edit never echoes back.
"""

from __future__ import annotations

import math

from PySide6.QtCore import QSignalBlocker, Qt
from PySide6.QtWidgets import QDoubleSpinBox, QHBoxLayout, QLabel, QSlider, QToolButton, QWidget

import engine

from ..document.model_document import ModelDocument
from ..icons import icon

INDENT_PX = 14


class ParameterSlider(QWidget):
    """Slider + spin box + reset for one :class:`engine.Parameter`."""

    def __init__(self, document: ModelDocument, parameter: engine.Parameter, depth: int = 0,
                 parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self._model = document.model
        self.parameter = parameter
        group = document.model.parameters.group(parameter.name)
        tip = parameter.description or f"{parameter.name} ({parameter.kind})"
        self.setToolTip(tip)
        self.setObjectName(f"parameter:{parameter.name}")

        self.label = QLabel(parameter.name)
        self.label.setIndent(depth * INDENT_PX)
        self.label.setToolTip(tip)
        if group == 1:  # rigid, non-leaf parameters read as headings of their subtree
            font = self.label.font()
            font.setBold(True)
            self.label.setFont(font)

        self.scale = SliderScale(parameter.minimum, parameter.maximum)
        self.step, self.decimals, self.steps = self.scale.step, self.scale.decimals, self.scale.steps
        self.slider = QSlider(Qt.Orientation.Horizontal)
        self.slider.setRange(0, self.steps)
        self.slider.setSingleStep(max(1, self.steps // 100))
        self.slider.setPageStep(max(1, self.steps // 10))
        self.slider.setToolTip(tip)
        self.slider.setMinimumWidth(120)

        self.spin = QDoubleSpinBox()
        self.spin.setDecimals(self.decimals)
        self.spin.setRange(parameter.minimum, parameter.maximum)
        self.spin.setSingleStep(self.step * 10)
        self.spin.setKeyboardTracking(False)  # commit on Enter / focus-out, not every keystroke
        self.spin.setToolTip(tip)

        self.reset_button = QToolButton()
        self.reset_button.setIcon(icon("reset"))
        self.reset_button.setAutoRaise(True)
        self.reset_button.setToolTip(f"Reset {parameter.name} to {parameter.default:g}")

        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.label)
        layout.addWidget(self.slider, stretch=1)
        layout.addWidget(self.spin)
        layout.addWidget(self.reset_button)

        self._show_value(document.value(parameter.name))
        self.slider.valueChanged.connect(self._on_slider_moved)
        self.spin.valueChanged.connect(self._on_spin_changed)
        self.reset_button.clicked.connect(self._on_reset_clicked)
        document.values_changed.connect(self._on_values_changed)

    # -- value <-> slider position -----------------------------------------
    def value_at(self, position: int) -> float:
        """The parameter value at slider ``position`` (0 … :attr:`steps`); the ends are exact."""
        return self.scale.value_at(position)

    def position_of(self, value: float) -> int:
        """The slider position nearest to ``value``."""
        return self.scale.position_of(value)

    def set_column_widths(self, label: int, spin: int) -> None:
        """Align this row with its siblings (the panel passes the widest label and spin box)."""
        self.label.setFixedWidth(label)
        self.spin.setFixedWidth(spin)

    def retire(self) -> None:
        """Stop following the document (the panel is replacing this row; its parameter may be gone)."""
        self._document.values_changed.disconnect(self._on_values_changed)

    # -- listeners -------------------------------------------------------
    def _on_slider_moved(self, position: int) -> None:
        self._document.set_value(self.parameter.name, self.value_at(position))

    def _on_reset_clicked(self) -> None:
        self._document.reset_value(self.parameter.name)

    def _on_spin_changed(self, value: float) -> None:
        self._document.set_value(self.parameter.name, value)

    def _on_values_changed(self, names: list) -> None:
        # A row of a model just replaced may still get a signal before Qt deletes it.
        if self._document.model is self._model and self.parameter.name in names:
            self._show_value(self._document.value(self.parameter.name))

    def _show_value(self, value: float) -> None:
        with QSignalBlocker(self.slider), QSignalBlocker(self.spin):
            self.slider.setValue(self.position_of(value))
            self.spin.setValue(value)
        self.reset_button.setEnabled(value != self.parameter.default)


class SliderScale:
    """Integer slider positions 0 … ``steps`` for values ``minimum`` … ``maximum`` in round steps.

    >>> scale = SliderScale(-0.5, 1.0)
    >>> scale.steps, scale.value_at(0), scale.value_at(scale.steps), scale.position_of(0.25)
    (1500, -0.5, 1.0, 750)
    """

    def __init__(self, minimum: float, maximum: float) -> None:
        self.minimum, self.maximum = minimum, maximum
        self.step, self.decimals = slider_step(maximum - minimum)
        self.steps = max(1, round((maximum - minimum) / self.step))

    def value_at(self, position: int) -> float:
        """The value at ``position``; the ends are exact."""
        if position <= 0:
            return self.minimum
        if position >= self.steps:
            return self.maximum
        return min(max(round(self.minimum + position * self.step, self.decimals), self.minimum), self.maximum)

    def position_of(self, value: float) -> int:
        """The position nearest to ``value``."""
        return min(max(round((value - self.minimum) / self.step), 0), self.steps)


def slider_step(span: float) -> tuple[float, int]:
    """A round slider step for a value range of width ``span``, and the decimals it needs.

    >>> slider_step(1.5)
    (0.001, 3)
    >>> slider_step(60.0)
    (0.01, 2)
    """
    if not span > 0:
        return 1.0, 3
    exponent = math.floor(math.log10(span)) - 3
    return 10.0 ** exponent, max(0, -exponent)
