"""The workbench's tools, each installed into the main window by one function.

A tool (the parameter-tree editor, weight painting, the library editor, the
timeline, the script panel, the motion-capture wizard, …) lives in its own
module and exposes ``install(context) -> None``, taking the window's
:class:`~workbench.tools.ToolContext`: it adds its docks, its tool-options page
(:meth:`~workbench.window.tool_options.ToolOptionsDock.add_page`) and its actions
(:meth:`~workbench.tools.ToolContext.add_actions`). The main window makes the
context (the player among it) and calls every installer listed here, in order,
once its own pieces are up; no tool needs another installed first.

Adding a tool is adding one line to :data:`INSTALLERS`.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .tools import ToolContext

INSTALLERS: list[str] = [
    # "module:function", relative to the workbench package
    "timeline_dock:install",
    "tree_editor:install",
    "painting:install",
    "library_editor:install",
    "expression_gallery:install",
    "script_panel:install",
    "mocap:install",
    "capture_import:install",       # File → Import capture stream… (docs/capture-streams.md)
    "look_menu:install",            # View → Look (docs/looks.md)
]


def install_all(context: ToolContext) -> None:
    """Run every installer in :data:`INSTALLERS` with the window's ``context``."""
    for entry in INSTALLERS:
        module_name, _, function = entry.partition(":")
        module = import_module(f".{module_name}", __package__)
        getattr(module, function or "install")(context)
