"""View → Look: the viewport lit and shaded as ``render`` draws (portrait, flat, legacy) or in the workbench's
own shading, one choice, remembered between sessions (docs/looks.md)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QSettings
from PySide6.QtGui import QAction, QActionGroup
from PySide6.QtWidgets import QMenu

from engine.outputs.looks import DEFAULT_LOOK, LOOKS

if TYPE_CHECKING:
    from .tools import ToolContext

SETTING = "view/look"
WORKBENCH = "workbench"          # the viewport's own shading (pyvista's light kit), not a look of the renderer
TITLES = {"portrait": "&Portrait (three-point light)", "flat": "&Flat (even light)",
          "legacy": "&Legacy (before looks)", WORKBENCH: "&Workbench shading (for editing)"}


class LookMenu(QMenu):
    """One checkable action per look; choosing one redraws the viewport in it and stores the choice."""

    def __init__(self, context: ToolContext) -> None:
        super().__init__("&Look", context.window)
        self.setObjectName("menu:look")
        self._viewport = context.viewport
        self.look_actions: dict[str, QAction] = {}
        group = QActionGroup(self)
        group.setExclusive(True)
        for name in [*LOOKS, WORKBENCH]:
            action = self.addAction(TITLES.get(name, name))
            action.setCheckable(True)
            action.setObjectName(f"look:{name}")
            group.addAction(action)
            action.triggered.connect(lambda _checked=False, name=name: self.choose(name))
            self.look_actions[name] = action
            if name == "legacy":
                self.addSeparator()
        stored = str(QSettings().value(SETTING, DEFAULT_LOOK))
        self.choose(stored if stored in self.look_actions else DEFAULT_LOOK, remember=False)

    def choose(self, name: str, remember: bool = True) -> None:
        """Draw the viewport in the look ``name`` (or the workbench's own shading)."""
        self.look_actions[name].setChecked(True)
        current = self._viewport.look
        if (current.name if current is not None else WORKBENCH) != name:
            self._viewport.set_look(None if name == WORKBENCH else name)
        if remember:
            QSettings().setValue(SETTING, name)


def install(context: ToolContext) -> None:
    """Add View → Look to the context's window (``window.look_menu``)."""
    menu = LookMenu(context)
    context.window.look_menu = menu
    context.menus["&View"].addMenu(menu)
