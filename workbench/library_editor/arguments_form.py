"""A form generated from a command's ``$optional`` (and ``$mandatory``) arguments: one spin box each.

The spin boxes start at the file's defaults; ``at`` is left out (a preview
starts at 0). Editing the text keeps what the user typed for arguments that
still exist, so tuning a curve while watching the plot does not reset the form.
"""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QDoubleSpinBox, QFormLayout, QHBoxLayout, QLabel, QToolButton, QWidget

from engine.commands.library_format import START, CommandDefinition

LIMIT = 1e7


class ArgumentsForm(QWidget):
    """Spin boxes for a command's arguments; ``changed`` after any edit."""

    changed = Signal()

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        self.layout_ = QFormLayout(self)
        self.layout_.setContentsMargins(0, 0, 0, 0)
        self.spin_boxes: dict[str, QDoubleSpinBox] = {}
        self.defaults: dict[str, float] = {}
        self._command: str | None = None
        self._empty = QLabel("No arguments")
        self.layout_.addRow(self._empty)

    def set_definition(self, definition: CommandDefinition | None) -> None:
        """Rebuild for ``definition`` (keep edited values when it is the same command)."""
        kept = self.values() if definition is not None and definition.name == self._command else {}
        kept = {k: v for k, v in kept.items() if v != self.defaults.get(k)}
        while self.layout_.rowCount():
            self.layout_.removeRow(0)
        self.spin_boxes, self.defaults = {}, {}
        self._command = definition.name if definition is not None else None
        arguments = {} if definition is None else definition.arguments()
        for name, default in arguments.items():
            if name == START:
                continue
            self.defaults[name] = 0.0 if default is None else float(default)
            box = QDoubleSpinBox()
            box.setRange(-LIMIT, LIMIT)
            box.setDecimals(3)
            box.setKeyboardTracking(False)
            box.setValue(kept.get(name, self.defaults[name]))
            box.setToolTip(f"{name}: default {self.defaults[name]:g}" if default is not None
                           else f"{name}: mandatory, no default")
            box.valueChanged.connect(self.changed)
            reset = QToolButton()
            reset.setText("↺")
            reset.setToolTip(f"Back to the default, {self.defaults[name]:g}")
            reset.clicked.connect(lambda _=False, b=box, d=self.defaults[name]: b.setValue(d))
            row = QWidget()
            line = QHBoxLayout(row)
            line.setContentsMargins(0, 0, 0, 0)
            line.addWidget(box, 1)
            line.addWidget(reset)
            self.layout_.addRow(name, row)
            self.spin_boxes[name] = box
        if not self.spin_boxes:
            self._empty = QLabel("No arguments" if definition is not None else "")
            self.layout_.addRow(self._empty)

    def values(self) -> dict[str, float]:
        return {name: box.value() for name, box in self.spin_boxes.items()}

    def set_value(self, name: str, value: float) -> None:
        self.spin_boxes[name].setValue(value)
