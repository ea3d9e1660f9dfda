"""The dock listing every parameter of the model as a slider, in tree order.

Children are indented under their parent, so the parameter tree of §2.2
reads at a glance (rigid group-1 parameters in bold). The panel rebuilds its
rows when another model is opened or the tree is edited (and undone); pose
changes are each row's own business.
"""

from __future__ import annotations

from PySide6.QtWidgets import QPushButton, QScrollArea, QVBoxLayout, QWidget

import engine

from ..document.model_document import ModelDocument
from ..icons import icon
from .slider import INDENT_PX, ParameterSlider


class ParameterPanel(QWidget):
    """A scrollable column of :class:`ParameterSlider` rows and a "Reset all" button."""

    def __init__(self, document: ModelDocument, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self.rows: dict[str, ParameterSlider] = {}

        self.reset_all_button = QPushButton(icon("reset"), "Reset all")
        self.reset_all_button.setToolTip("Put every parameter back to its default (the rest pose)")
        self.reset_all_button.clicked.connect(document.reset_all)

        self._scroll = QScrollArea()
        self._scroll.setWidgetResizable(True)
        self._scroll.setFrameShape(QScrollArea.Shape.NoFrame)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addWidget(self._scroll, stretch=1)
        layout.addWidget(self.reset_all_button)

        document.model_replaced.connect(self._build)
        document.parameters_changed.connect(self._rebuild)
        document.values_changed.connect(self._update_reset_all)
        self._build(document.model)

    def row(self, name: str) -> ParameterSlider:
        return self.rows[name]

    def _rebuild(self, _names: list) -> None:
        self._build(self._document.model)

    def _build(self, model: engine.Model) -> None:
        for row in self.rows.values():
            row.retire()
        self.rows.clear()
        content = QWidget()
        column = QVBoxLayout(content)
        column.setContentsMargins(0, 0, 0, 0)
        column.setSpacing(2)
        tree = model.parameters
        for name, depth in tree.depth_first():
            row = ParameterSlider(self._document, tree[name], depth)
            self.rows[name] = row
            column.addWidget(row)
        column.addStretch(1)
        if self.rows:
            label = max(r.label.sizeHint().width() for r in self.rows.values())  # includes the indent
            spin = max(r.spin.sizeHint().width() for r in self.rows.values())
            for r in self.rows.values():
                r.set_column_widths(label + INDENT_PX // 2, spin)
        old = self._scroll.takeWidget()
        self._scroll.setWidget(content)
        if old is not None:
            old.deleteLater()
        self._update_reset_all()

    def _update_reset_all(self, _names: list | None = None) -> None:
        self.reset_all_button.setEnabled(not self._document.is_at_rest())


