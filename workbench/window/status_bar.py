"""The status bar: which model is open, how big it is, what is being changed."""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QStatusBar, QWidget

import engine

from ..document.model_document import ModelDocument

MESSAGE_MS = 4000


class ModelStatusBar(QStatusBar):
    """The model's file, vertex and parameter counts on the right; the parameter just changed on the left.

    The file's name, not the model's: a copy of the default head saved as
    ``painted.xml`` still calls itself ``default-head`` inside, and the user
    knows it by its file. An untitled model (new from a mesh) shows its name.
    """

    def __init__(self, document: ModelDocument, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self.model_label = QLabel()
        self.addPermanentWidget(self.model_label)
        document.model_replaced.connect(self._show_model)
        document.values_changed.connect(self._show_change)
        document.parameters_changed.connect(self._show_tree_change)
        document.path_changed.connect(self._show_path_change)
        self._show_model(document.model)

    def _show_tree_change(self, _names: list) -> None:
        self._show_model(self._document.model, clear=False)

    def _show_path_change(self, _path: str) -> None:
        self._show_model(self._document.model, clear=False)

    def _show_model(self, model: engine.Model, clear: bool = True) -> None:
        path = self._document.path
        name = path.name if path is not None else model.name
        count = len(model.parameters)
        self.model_label.setText(f"{name} · {model.n_vertices:,} vertices · {count} parameter{'s' * (count != 1)}")
        self.model_label.setToolTip(str(path) if path is not None else f"{model.name} (not saved to a file yet)")
        if clear:
            self.clearMessage()

    def _show_change(self, names: list) -> None:
        if len(names) == 1:
            name = names[0]
            self.showMessage(f"{name} = {self._document.value(name):.3f}", MESSAGE_MS)
        else:
            self.showMessage(f"{len(names)} parameters changed", MESSAGE_MS)
