"""The Identity panel's rows and groups: one identity parameter as a slider row, a group of them that folds.

An :class:`IdentitySlider` shows one :class:`engine.identity.IdentityParameter`
(name, slider, value box, reset) and only reports what the user does:
``moved`` while the value changes (a drag: preview it), ``committed`` when a
value is meant (the drag's release, a click on the groove, a key, a typed
value, reset: make the head). It redraws only through :meth:`IdentitySlider.show_value`,
with its own widgets' signals blocked, so nothing echoes. An
:class:`IdentityGroup` holds the rows of one group (macro, nose, mouth …)
under a header that folds it, counts its changed values and resets them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QSignalBlocker, Qt, Signal
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import (
    QDoubleSpinBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QSlider,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from ..icons import icon
from ..parameter_panel.slider import SliderScale

if TYPE_CHECKING:
    from engine.identity import IdentityParameter

GROUP_TITLES = {"macro": "Sex, age, ancestry, build"}
DIRECTION_WORDS = {"decr", "incr", "in", "out", "down", "up", "backward", "forward", "less", "more"}


class WheelSafeSlider(QSlider):
    """A slider the mouse wheel moves only once it has focus: wheeling down the panel scrolls it instead
    of reshaping the face at every row the pointer passes."""

    def wheelEvent(self, event: QWheelEvent) -> None:
        if self.hasFocus():
            super().wheelEvent(event)
        else:
            event.ignore()


class WheelSafeSpinBox(QDoubleSpinBox):
    """A value box the mouse wheel changes only once it has focus (as :class:`WheelSafeSlider`)."""

    def wheelEvent(self, event: QWheelEvent) -> None:
        if self.hasFocus():
            super().wheelEvent(event)
        else:
            event.ignore()


def short_label(parameter: IdentityParameter) -> str:
    """The row's label: a face modifier without the word its group already says (``nose-`` in Nose).

    >>> from engine.identity import identity_parameter
    >>> short_label(identity_parameter("nose-flaring-decr-incr")), short_label(identity_parameter("age"))
    ('flaring-decr-incr', 'age (years)')
    """
    if parameter.group == "macro":
        return "age (years)" if parameter.name == "age" else parameter.name
    _head, _, rest = parameter.name.partition("-")
    if not rest or set(rest.split(".")[0].split("-")) <= DIRECTION_WORDS:
        return parameter.name      # "head-fat" would say nothing without its first word
    return rest


class IdentitySlider:
    """Label, slider, value box and reset button of one identity parameter (placed in a group's grid)."""

    def __init__(self, parameter: IdentityParameter, group: IdentityGroup):
        self.parameter = parameter
        self.group = group
        tip = f"{parameter.name}: {parameter.description}" if parameter.description else parameter.name
        self.label = QLabel(short_label(parameter))
        self.label.setToolTip(tip)
        self.scale = SliderScale(parameter.minimum, parameter.maximum)
        self.step, self.decimals, self.steps = self.scale.step, self.scale.decimals, self.scale.steps
        self.slider = WheelSafeSlider(Qt.Orientation.Horizontal)
        self.slider.setFocusPolicy(Qt.FocusPolicy.StrongFocus)      # a click or Tab gives it the wheel
        self.slider.setObjectName(f"identity:{parameter.name}")
        self.slider.setRange(0, self.steps)
        self.slider.setSingleStep(max(1, self.steps // 100))
        self.slider.setPageStep(max(1, self.steps // 10))
        self.slider.setMinimumWidth(90)
        self.slider.setToolTip(tip)
        self.spin = WheelSafeSpinBox()
        self.spin.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.spin.setDecimals(self.decimals)
        self.spin.setRange(parameter.minimum, parameter.maximum)
        self.spin.setSingleStep(self.step * 10)
        self.spin.setKeyboardTracking(False)      # commit on Enter / focus-out, not on every keystroke
        self.spin.setToolTip(tip)
        self.reset_button = QToolButton()
        self.reset_button.setIcon(icon("reset"))
        self.reset_button.setAutoRaise(True)
        self.reset_button.setToolTip(f"Reset {parameter.name} to {parameter.default:g}")
        self._value = parameter.default
        self.show_value(parameter.default)
        self.slider.valueChanged.connect(self._on_slider_changed)
        self.slider.sliderReleased.connect(self._on_slider_released)
        self.spin.valueChanged.connect(self._on_spin_changed)
        self.reset_button.clicked.connect(self._on_reset)

    @property
    def name(self) -> str:
        return self.parameter.name

    def widgets(self) -> tuple[QWidget, ...]:
        return self.label, self.slider, self.spin, self.reset_button

    def set_visible(self, visible: bool) -> None:
        for widget in self.widgets():
            widget.setVisible(visible)

    # -- value <-> slider position -----------------------------------------------------------
    def value_at(self, position: int) -> float:
        """The value at slider ``position``; the ends are exact."""
        return self.scale.value_at(position)

    def position_of(self, value: float) -> int:
        return self.scale.position_of(value)

    def value(self) -> float:
        """The value the row shows (exact: a default of 1/3 reads 1/3, not the slider's 0.333)."""
        return self._value

    def show_value(self, value: float) -> None:
        """Show ``value`` (no signal goes out); a changed value reads bold."""
        self._value = value
        with QSignalBlocker(self.slider), QSignalBlocker(self.spin):
            self.slider.setValue(self.position_of(value))
            self.spin.setValue(value)
        changed = abs(value - self.parameter.default) > 1e-12
        font = self.label.font()
        if font.bold() != changed:
            font.setBold(changed)
            self.label.setFont(font)
        self.reset_button.setEnabled(changed)

    # -- what the user does -------------------------------------------------------------------
    def _on_slider_changed(self, position: int) -> None:
        value = self._value = self.value_at(position)
        with QSignalBlocker(self.spin):
            self.spin.setValue(value)
        self.group.moved.emit(self.name, value)
        if not self.slider.isSliderDown():      # a click on the groove, a key: meant at once
            self.group.committed.emit(self.name, value)

    def _on_slider_released(self) -> None:
        self.group.committed.emit(self.name, self.value_at(self.slider.value()))

    def _on_spin_changed(self, value: float) -> None:
        self._value = value
        with QSignalBlocker(self.slider):
            self.slider.setValue(self.position_of(value))
        self.group.moved.emit(self.name, value)
        self.group.committed.emit(self.name, value)

    def _on_reset(self) -> None:
        self.group.moved.emit(self.name, self.parameter.default)
        self.group.committed.emit(self.name, self.parameter.default)


class IdentityGroup(QWidget):
    """The rows of one group under a header that folds them away, with the count of changed values and a reset.

    Signals: ``moved(name, value)`` and ``committed(name, value)`` from its
    rows, ``reset_requested(group)`` from its reset button.
    """

    moved = Signal(str, float)
    committed = Signal(str, float)
    reset_requested = Signal(str)

    def __init__(self, group: str, parameters: list[IdentityParameter], parent: QWidget | None = None):
        super().__init__(parent)
        self.group = group
        self.setObjectName(f"identity-group:{group}")
        self.title = GROUP_TITLES.get(group, group.capitalize())
        self.header = QToolButton()
        self.header.setCheckable(True)
        self.header.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextBesideIcon)
        self.header.setAutoRaise(True)
        font = self.header.font()
        font.setBold(True)
        self.header.setFont(font)
        self.header.toggled.connect(self.set_expanded)
        self.reset_button = QToolButton()
        self.reset_button.setIcon(icon("reset"))
        self.reset_button.setAutoRaise(True)
        self.reset_button.setToolTip(f"Reset every value of {self.title} to its default")
        self.reset_button.clicked.connect(lambda: self.reset_requested.emit(self.group))
        top = QHBoxLayout()
        top.setContentsMargins(0, 0, 0, 0)
        top.addWidget(self.header)
        top.addStretch(1)
        top.addWidget(self.reset_button)

        self.body = QWidget()
        grid = QGridLayout(self.body)
        grid.setContentsMargins(14, 0, 0, 4)
        grid.setHorizontalSpacing(6)
        grid.setVerticalSpacing(1)
        grid.setColumnStretch(1, 1)
        self.grid = grid
        self.rows: dict[str, IdentitySlider] = {}
        for row_index, parameter in enumerate(parameters):
            row = IdentitySlider(parameter, self)
            for column, widget in enumerate(row.widgets()):
                grid.addWidget(widget, row_index, column)
            self.rows[parameter.name] = row
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(top)
        layout.addWidget(self.body)
        self._expanded = True
        self.set_expanded(False)
        self.update_header()

    @property
    def expanded(self) -> bool:
        return self._expanded

    def set_expanded(self, expanded: bool) -> None:
        self._expanded = expanded
        with QSignalBlocker(self.header):
            self.header.setChecked(expanded)
        self.header.setArrowType(Qt.ArrowType.DownArrow if expanded else Qt.ArrowType.RightArrow)
        self.body.setVisible(expanded)

    def show_values(self, values: dict[str, float]) -> None:
        """Show every row's value from ``values`` (name → value; defaults where missing)."""
        for name, row in self.rows.items():
            row.show_value(values.get(name, row.parameter.default))
        self.update_header()

    def changed_names(self) -> list[str]:
        return [name for name, row in self.rows.items() if abs(row.value() - row.parameter.default) > 1e-12]

    def update_header(self) -> None:
        changed = len(self.changed_names())
        self.header.setText(f"{self.title}  ({changed} changed)" if changed else self.title)
        self.reset_button.setEnabled(changed > 0)

    def filter(self, text: str) -> int:
        """Show only the rows whose name holds ``text`` (all when empty); returns how many are shown."""
        text = text.strip().lower()
        shown = 0
        for row in self.rows.values():
            visible = not text or text in row.name.lower() or text in row.label.text().lower()
            row.set_visible(visible)
            shown += visible
        self.setVisible(shown > 0)
        return shown

    def set_label_width(self, width: int) -> None:
        """Align this group's columns with the other groups' (the panel passes the widest label)."""
        self.grid.setColumnMinimumWidth(0, width)
