"""What a tool may use of the main window: one typed :class:`ToolContext`, handed to each tool's ``install``.

A tool (the parameter-tree editor, weight painting, the timeline, the library
editor, the expression gallery, the script panel, motion capture, …) is
installed by ``install(context: ToolContext) -> None`` (:mod:`workbench.features`).
Everything it shares with the window and the other tools is a member here,
made by the window before any tool: the document, the view state, the
playhead and the player, the viewport, the Tool options dock, the actions,
the status line. A tool keeps its own pieces to itself (it may hang them on
``context.window`` for its own actions' callbacks and for the tests), and
never reads what another tool made; the packages of the tools import none of
each other (an import-linter independence contract in ``pyproject.toml``).

>>> def install(context: ToolContext) -> None:                          # doctest: +SKIP
...     dock = MyDock(context.document, context.window)
...     context.window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, dock)
...     context.add_actions(MY_ACTIONS)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from PySide6.QtGui import QAction
from PySide6.QtWidgets import QDockWidget, QMainWindow, QMenu, QStatusBar, QToolBar

if TYPE_CHECKING:
    from .document.model_document import ModelDocument
    from .document.playhead import Playhead
    from .document.view_state import ViewState
    from .library_sources import LibrarySources
    from .playback.player import Player
    from .viewport.view import Viewport
    from .window.actions import ActionSpec
    from .window.recovery import Autosaver
    from .window.tool_options import ToolOptionsDock


@dataclass(frozen=True, eq=False)
class ToolContext:
    """The window's shared pieces, as a tool may use them.

    ``window`` is the main window as a plain :class:`QMainWindow`: the parent
    of a tool's docks and dialogs, where docks are added and events filtered,
    not a bag of other tools' attributes.
    """

    window: QMainWindow
    document: ModelDocument
    view_state: ViewState
    playhead: Playhead
    player: Player
    """Plays an animation with its sound; every tool that plays (timeline, script, library, gallery) shares it."""
    viewport: Viewport
    tool_options: ToolOptionsDock
    actions: dict[str, QAction]
    """Every command by id (``"file.save"``, ``"paint.mode"``, …), the window's and the tools'."""
    menus: dict[str, QMenu]
    """The menu bar's menus by title (``"&File"``, ``"&View"``, ``"&File/&Export"``, …)."""
    toolbar: QToolBar
    status: QStatusBar
    """The status line: ``context.status.showMessage(text, ms)``."""
    library_sources: LibrarySources
    """The library folders and the "library changed" signal, shared by the library editor and the gallery."""
    _add_actions: Callable[[tuple[ActionSpec, ...]], dict[str, QAction]]
    _reveal: Callable[[QDockWidget, int, int, str | None], None]
    _autosaver: Callable[[], Autosaver | None]

    def add_actions(self, specs: tuple[ActionSpec, ...]) -> dict[str, QAction]:
        """A tool's commands into the menus (a new menu is appended), the toolbar and :attr:`actions`."""
        return self._add_actions(specs)

    def reveal(self, dock: QDockWidget, width: int = 0, height: int = 0, task: str | None = None) -> None:
        """Show ``dock`` in front of its tab group, at least ``width`` × ``height`` (its own wish by default);
        ``task``: turn to that task layout first (:meth:`workbench.window.layouts.LayoutManager.reveal`)."""
        self._reveal(dock, width, height, task)

    def show_dock(self, object_name: str) -> None:
        """Show the dock named ``object_name`` (``"dock:timeline"``) as it is, if the window has it."""
        dock = self.window.findChild(QDockWidget, object_name)
        if dock is not None:
            dock.show()

    def autosaver(self) -> Autosaver | None:
        """The window's autosaver (its interval, its recovery session), once the window is up; ``None`` before."""
        return self._autosaver()
