"""The status bar: which model is open, how big it is, what is being changed."""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QStatusBar, QWidget

import engine

from .document import ModelDocument

MESSAGE_MS = 4000


class ModelStatusBar(QStatusBar):
    """Model name and vertex count on the right; the parameter just changed on the left."""

    def __init__(self, document: ModelDocument, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self.model_label = QLabel()
        self.addPermanentWidget(self.model_label)
        document.model_replaced.connect(self._show_model)
        document.values_changed.connect(self._show_change)
        document.parameters_changed.connect(self._show_tree_change)
        self._show_model(document.model)

    def _show_tree_change(self, _names: list) -> None:
        self._show_model(self._document.model, clear=False)

    def _show_model(self, model: engine.Model, clear: bool = True) -> None:
        self.model_label.setText(f"{model.name} · {model.n_vertices:,} vertices · "
                                 f"{len(model.parameters)} parameters")
        self.clearMessage()

    def _show_change(self, names: list) -> None:
        if len(names) == 1:
            name = names[0]
            self.showMessage(f"{name} = {self._document.value(name):.3f}", MESSAGE_MS)
        else:
            self.showMessage(f"{len(names)} parameters changed", MESSAGE_MS)
