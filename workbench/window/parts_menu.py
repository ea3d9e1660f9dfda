"""View → Parts: one checkable action per part of the model, shown or hidden."""

from __future__ import annotations

from PySide6.QtCore import QSignalBlocker
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QMenu, QWidget

import engine

from ..document.model_document import ModelDocument
from ..document.view_state import ViewState


class PartsMenu(QMenu):
    """Checkable actions bound to :class:`ViewState`; rebuilt when another model is opened."""

    def __init__(self, document: ModelDocument, view_state: ViewState, parent: QWidget | None = None):
        super().__init__("&Parts", parent)
        self._view_state = view_state
        self.part_actions: dict[str, QAction] = {}
        document.model_replaced.connect(self._build)
        view_state.part_visibility_changed.connect(self._on_visibility_changed)
        self._build(document.model)

    def _build(self, model: engine.Model) -> None:
        self.clear()
        self.part_actions.clear()
        show_all = self.addAction("Show all")
        show_all.triggered.connect(self._view_state.show_all_parts)
        self.addSeparator()
        for part in model.parts:
            action = self.addAction(part)
            action.setCheckable(True)
            action.setChecked(self._view_state.is_part_visible(part))
            action.setObjectName(f"part:{part}")
            action.toggled.connect(lambda on, part=part: self._view_state.set_part_visible(part, on))
            self.part_actions[part] = action

    def _on_visibility_changed(self, part: str, visible: bool) -> None:
        action = self.part_actions.get(part)
        if action is not None and action.isChecked() != visible:
            with QSignalBlocker(action):
                action.setChecked(visible)
