"""The selected parameter's properties, on the tree editor's page of the Tool options dock.

Type (rotation / translation), axis, degrees per unit and pivot for a
rotation (the pivot typed in mm or picked on the mesh), direction (mm per
unit) for a translation, the value range, the default and a description.
Each finished edit of one property is one undo step
(:class:`~workbench.document.undo_commands.ReplaceParameterCommand`); a value the engine
refuses (minimum above maximum, a zero axis, a default outside the range,
text that is not a number) is explained in a message and the field goes back
to what the model holds.

>>> sheet = window.tree_editor.sheet                           # doctest: +SKIP
>>> sheet.pivot.set_texts("0", "-20", "-30"); sheet.commit("pivot")   # doctest: +SKIP
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QComboBox, QFormLayout, QHBoxLayout, QLabel, QLineEdit, QPushButton, QVBoxLayout, QWidget

import engine

from ..document.undo_commands import ReplaceParameterCommand
from ..icons import icon
from .fields import ScalarField, VectorField
from .pivot_picker import PivotPicker
from .tree_model import GROUP_TEXT, type_text

if TYPE_CHECKING:
    from .editor import TreeEditor

TOOL_ID = "tree-editor"
LABELS = {"kind": "type", "axis": "axis", "degrees_per_unit": "degrees per unit", "pivot": "pivot",
          "direction": "direction", "minimum": "minimum", "maximum": "maximum", "default": "default",
          "description": "description"}


class PropertySheet(QWidget):
    """Form over ``editor.selected``; follows selection, tree edits, undo/redo and model changes."""

    def __init__(self, editor: TreeEditor, parent: QWidget | None = None):
        super().__init__(parent)
        self.setObjectName("tree-editor:properties")
        self._editor = editor
        context = editor.context
        self._shown_name: str | None = None

        self.hint = QLabel("Select a parameter in the Parameter tree to edit its properties.")
        self.hint.setWordWrap(True)
        self.hint.setEnabled(False)
        self.title = QLabel()
        self.title.setTextFormat(Qt.TextFormat.PlainText)
        font = self.title.font()
        font.setBold(True)
        self.title.setFont(font)

        self.kind = QComboBox()
        self.kind.addItems(["rotation", "translation"])
        self.kind.setToolTip("Rotation about an axis through the pivot, or translation along a direction")
        self.axis = VectorField("axis")
        self.axis.setToolTip("Rotation axis (any length; stored as a unit vector)")
        self.degrees = ScalarField("degrees per unit")
        self.degrees.setToolTip("Rotation angle in degrees for value 1")
        self.pivot = VectorField("pivot")
        self.pivot.setToolTip("A point on the rotation axis, mm (rest pose)")
        self.pick_button = QPushButton(icon("pick-pivot"), "Pick on mesh")
        self.pick_button.setCheckable(True)
        self.pick_button.setToolTip("Then click on the model: the pivot goes to the surface point under the cursor")
        self.direction = VectorField("direction")
        self.direction.setToolTip("Translation in mm for value 1")
        self.minimum = ScalarField("minimum")
        self.maximum = ScalarField("maximum")
        self.default = ScalarField("default")
        self.description = QLineEdit()
        self.description.setPlaceholderText("what it does, for users")

        pick_row = QWidget()
        pick_layout = QHBoxLayout(pick_row)
        pick_layout.setContentsMargins(0, 0, 0, 0)
        pick_layout.addWidget(self.pick_button)
        pick_layout.addStretch(1)
        range_row = QWidget()
        range_layout = QHBoxLayout(range_row)
        range_layout.setContentsMargins(0, 0, 0, 0)
        for label, field in (("min", self.minimum), ("max", self.maximum), ("default", self.default)):
            caption = QLabel(label)
            caption.setEnabled(False)
            range_layout.addWidget(caption)
            range_layout.addWidget(field, 1)

        self.form = QFormLayout()
        self.form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
        self.form.addRow("Type", self.kind)
        self.form.addRow("Axis", self.axis)
        self.form.addRow("Degrees / unit", self.degrees)
        self.form.addRow("Pivot (mm)", self.pivot)
        self.form.addRow("", pick_row)
        self.form.addRow("Direction (mm)", self.direction)
        self.form.addRow("Range", range_row)
        self.form.addRow("Description", self.description)
        self.form_widget = QWidget()
        self.form_widget.setLayout(self.form)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 6, 6, 6)
        layout.addWidget(self.hint)
        layout.addWidget(self.title)
        layout.addWidget(self.form_widget)
        layout.addStretch(1)

        self.picker = PivotPicker(context.viewport, context.document, self._on_picked, self)
        self.pick_button.toggled.connect(self._on_pick_toggled)
        self.picker.finished.connect(lambda: self.pick_button.setChecked(False))

        self.kind.activated.connect(lambda _i: self.commit("kind"))
        self.axis.committed.connect(lambda: self.commit("axis"))
        self.degrees.committed.connect(lambda: self.commit("degrees_per_unit"))
        self.pivot.committed.connect(lambda: self.commit("pivot"))
        self.direction.committed.connect(lambda: self.commit("direction"))
        self.minimum.committed.connect(lambda: self.commit("minimum"))
        self.maximum.committed.connect(lambda: self.commit("maximum"))
        self.default.committed.connect(lambda: self.commit("default"))
        self.description.editingFinished.connect(lambda: self.commit("description"))

        context.view_state.selected_parameter_changed.connect(self.refresh)
        context.document.parameters_changed.connect(self.refresh)
        context.document.model_replaced.connect(self.refresh)
        self.refresh()

    # -- showing -------------------------------------------------------------
    def refresh(self, *_args) -> None:
        """Show the selected parameter's properties as the model holds them now."""
        name = self._editor.selected
        self._shown_name = name
        self.hint.setVisible(name is None)
        self.title.setVisible(name is not None)
        self.form_widget.setVisible(name is not None)
        if name is None:
            self.picker.cancel()
            return
        tree = self._editor.document.model.parameters
        p = tree[name]
        self.title.setText(f"{name}  —  group {GROUP_TEXT[tree.group(name)]}, {type_text(p)}")
        self.kind.setCurrentText(p.kind)
        self.axis.show_value(p.axis)
        self.degrees.show_value(p.degrees_per_unit)
        self.pivot.show_value(p.pivot)
        self.direction.show_value(p.direction)
        self.direction.setEnabled(not p.field)
        for field, value in ((self.minimum, p.minimum), (self.maximum, p.maximum), (self.default, p.default)):
            field.show_value(value)
        if self.description.text() != p.description:
            self.description.setText(p.description)
            self.description.setCursorPosition(0)      # show how it begins
        rotation = p.kind == "rotation"
        for row in (self.axis, self.degrees, self.pivot, self.pick_button.parentWidget()):
            self.form.setRowVisible(row, rotation)
        self.form.setRowVisible(self.direction, not rotation)
        self.pick_button.setEnabled(rotation)

    # -- editing -------------------------------------------------------------
    def commit(self, prop: str) -> bool:
        """Make the edited ``prop`` (an :class:`engine.Parameter` attribute) one undo step.

        Returns ``True`` if the model changed. Invalid input: a message, the
        field reverts, nothing changes.
        """
        name = self._shown_name
        if name is None or name not in self._editor.document.model.parameters:
            return False
        old = self._editor.document.model.parameters[name]
        try:
            value = self._read(prop, old)
        except ValueError as error:
            self._editor.warn(str(error))
            self.refresh()
            return False
        if _same(getattr(old, prop), value):
            return False
        try:
            new = old.copy(**{prop: value})
        except engine.UserError as error:
            self._editor.warn(str(error))
            self.refresh()
            return False
        text = f"Set {LABELS[prop]} of {name}"
        done = self._editor.push(lambda: ReplaceParameterCommand(self._editor.document, new, text=text))
        if not done:
            self.refresh()
        return done

    def set_pivot(self, point) -> bool:
        """Put the selected rotation's pivot at ``point`` (mm) as one undo step."""
        self.pivot.show_value(self._editor.document.model.parameters[self._shown_name].pivot)
        for edit, v in zip(self.pivot.edits, point, strict=True):
            edit.setText(repr(float(v)))
        return self.commit("pivot")

    def _read(self, prop: str, old: engine.Parameter):
        if prop == "kind":
            return self.kind.currentText()
        if prop == "description":
            return self.description.text().strip()
        field = {"axis": self.axis, "degrees_per_unit": self.degrees, "pivot": self.pivot,
                 "direction": self.direction, "minimum": self.minimum, "maximum": self.maximum,
                 "default": self.default}[prop]
        return field.value(getattr(old, prop))

    # -- picking the pivot ---------------------------------------------------
    def _on_pick_toggled(self, on: bool) -> None:
        if on and self._shown_name is not None:
            self.picker.arm(f"Click on the model to put the pivot of {self._shown_name} there (Esc: cancel)")
        else:
            self.picker.cancel()

    def _on_picked(self, point) -> None:
        if self._shown_name is not None:
            self.set_pivot(point)


def _same(a, b) -> bool:
    """Equal bit for bit (vectors) or by value (numbers, text)."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    return a == b
