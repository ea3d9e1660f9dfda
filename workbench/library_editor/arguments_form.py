"""A form generated from a command's ``$optional`` (and ``$mandatory``) arguments: one spin box each.

The spin boxes start at the file's defaults; ``at`` is left out (a preview
starts at 0). Editing the text keeps what the user typed for arguments that
still exist, so tuning a curve while watching the plot does not reset the form.
"""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QDoubleSpinBox, QGridLayout, QLabel, QToolButton, QWidget

from engine.commands.library_format import START, CommandDefinition

LIMIT = 1e7
COLUMNS = 2
"""Arguments per row of the form (name, spin box, reset button each)."""


class NumberBox(QDoubleSpinBox):
    """A spin box that shows ``400`` rather than ``400.000``."""

    def textFromValue(self, value: float) -> str:
        return f"{value:g}"


class ArgumentsForm(QWidget):
    """Spin boxes for a command's arguments; ``changed`` after any edit."""

    changed = Signal()

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.grid = QGridLayout(self)
        self.grid.setContentsMargins(0, 0, 0, 0)
        self.grid.setHorizontalSpacing(4)
        self.spin_boxes: dict[str, QDoubleSpinBox] = {}
        self.defaults: dict[str, float] = {}
        self._command: str | None = None
        self._widgets: list[QWidget] = []

    def set_definition(self, definition: CommandDefinition | None) -> None:
        """Rebuild for ``definition`` (keep edited values when it is the same command)."""
        kept = self.values() if definition is not None and definition.name == self._command else {}
        kept = {k: v for k, v in kept.items() if v != self.defaults.get(k)}
        for widget in self._widgets:
            self.grid.removeWidget(widget)
            widget.deleteLater()
        self._widgets, self.spin_boxes, self.defaults = [], {}, {}
        self._command = definition.name if definition is not None else None
        arguments = {} if definition is None else definition.arguments()
        for name, default in arguments.items():
            if name == START:
                continue
            self.defaults[name] = 0.0 if default is None else float(default)
            box = NumberBox()
            box.setRange(-LIMIT, LIMIT)
            box.setDecimals(4)
            box.setKeyboardTracking(False)
            box.setValue(kept.get(name, self.defaults[name]))
            box.setToolTip(f"{name}: default {self.defaults[name]:g}" if default is not None
                           else f"{name}: mandatory, no default")
            box.valueChanged.connect(self.changed)
            reset = QToolButton()
            reset.setText("↺")
            reset.setAutoRaise(True)
            reset.setToolTip(f"Back to the default, {self.defaults[name]:g}")
            reset.clicked.connect(lambda _=False, b=box, d=self.defaults[name]: b.setValue(d))
            index = len(self.spin_boxes)
            row, column = divmod(index, COLUMNS)
            label = QLabel(name)
            for offset, widget in enumerate((label, box, reset)):
                self.grid.addWidget(widget, row, 3 * column + offset)
                self._widgets.append(widget)
            self.spin_boxes[name] = box
        if definition is not None and not self.spin_boxes:
            label = QLabel("No arguments")
            self.grid.addWidget(label, 0, 0)
            self._widgets.append(label)

    def values(self) -> dict[str, float]:
        return {name: box.value() for name, box in self.spin_boxes.items()}

    def set_value(self, name: str, value: float) -> None:
        self.spin_boxes[name].setValue(value)
