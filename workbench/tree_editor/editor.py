"""The tree editor's edits: add, remove (with the subtree), rename and move parameters.

Each edit is one undo command pushed with :meth:`ModelDocument.push`; an edit
the engine refuses (a duplicate or illegal name, a loop, children under a
displacement field) is reported in a message box with the engine's words and
changes nothing.

>>> editor = window.tree_editor                     # doctest: +SKIP
>>> editor.add_parameter(parent="jaw_open")         # doctest: +SKIP
'parameter'
>>> editor.rename("parameter", "lip_curl")          # doctest: +SKIP
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QObject
from PySide6.QtWidgets import QMessageBox

import engine
from engine.model.edits import subtree, unique_name

from ..document.undo_commands import (
    AddParameterCommand,
    ModelEditCommand,
    MoveParameterCommand,
    RemoveSubtreeCommand,
    RenameParameterCommand,
)

if TYPE_CHECKING:
    from ..tools import ToolContext

TITLE = "Parameter tree"
MESSAGE_MS = 4000


class TreeEditor(QObject):
    """The tree editor of one window: its dock, property sheet, gizmo and pivot picker (set by ``install``)."""

    def __init__(self, context: ToolContext):
        super().__init__(context.window)
        self.context = context
        self.window = context.window        # the parent of its dialogs
        self.dock = None
        self.sheet = None
        self.gizmo = None
        self.actions: dict = {}

    @property
    def document(self):
        return self.context.document

    @property
    def selected(self) -> str | None:
        """The selected parameter (the view state's selection, if it names one of this model's)."""
        name = self.context.view_state.selected_parameter
        return name if name is not None and name in self.document.model.parameters else None

    def update_actions(self, *_args) -> None:
        """Remove and Rename need a selected parameter; Move up / down one with a sibling that way."""
        name = self.selected
        first = last = True
        if name is not None:
            tree = self.document.model.parameters
            parent = tree[name].parent
            siblings = tree.children(parent) if parent is not None else tree.roots()
            first, last = siblings[0] == name, siblings[-1] == name
        enabled = {"parameters.remove": name is not None, "parameters.rename": name is not None,
                   "parameters.move_up": not first, "parameters.move_down": not last}
        for action_id, on in enabled.items():
            if action_id in self.actions:
                self.actions[action_id].setEnabled(on)

    # -- edits -------------------------------------------------------------
    def push(self, command_factory) -> bool:
        """Build and push a command; a refused edit shows its message and returns ``False``."""
        try:
            command: ModelEditCommand = command_factory()
            self.document.push(command)
        except engine.UserError as error:
            self.warn(str(error))
            return False
        self.context.status.showMessage(command.text(), MESSAGE_MS)
        return True

    def add_parameter(self, parent: str | None = "selected", *, edit_name: bool = True) -> str | None:
        """Add a rotation with an empty region under ``parent`` (default: the selected one, else at the top).

        Its name is ``parameter`` (``parameter_2``, … if taken); the new row is
        selected and, with ``edit_name``, opened for renaming. Returns the name.
        """
        if parent == "selected":
            parent = self.selected
        model = self.document.model
        name = unique_name(model.parameters)
        pivot = model.parameters[parent].pivot.copy() if parent is not None else _centre(model)
        parameter = engine.Parameter(name, "rotation", parent=parent, pivot=pivot, degrees_per_unit=10.0,
                                     description="")
        if not self.push(lambda: AddParameterCommand(self.document, parameter)):
            return None
        self.context.view_state.select_parameter(name)
        if edit_name and self.dock is not None:
            self.dock.view.edit(self.dock.model.index_of(name))
        return name

    def remove_parameter(self, name: str | None = None, *, confirm: bool = True) -> bool:
        """Remove ``name`` (default: the selected one) and everything below it, after asking."""
        name = name or self.selected
        if name is None:
            self.context.status.showMessage("Select a parameter to remove first", MESSAGE_MS)
            return False
        names = subtree(self.document.model.parameters, name)
        if confirm:
            below = ""
            if len(names) > 1:
                below = f"\n\nThese {len(names) - 1} below it go too: {', '.join(names[1:])}."
            answer = QMessageBox.question(
                self.window, TITLE,
                f"Remove the parameter {name} and its influence region?{below}\n\nEdit → Undo brings it back.",
                QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.Cancel,
                QMessageBox.StandardButton.Cancel)
            if answer != QMessageBox.StandardButton.Yes:
                return False
        return self.push(lambda: RemoveSubtreeCommand(self.document, name))

    def rename(self, old: str, new: str) -> bool:
        """Rename ``old`` to ``new``; a name that is taken or not allowed shows why and changes nothing."""
        new = new.strip()
        if new == old:
            return False
        if not new:
            self.warn(f"A parameter needs a name: {old} keeps its own.")
            return False
        return self.push(lambda: RenameParameterCommand(self.document, old, new))

    def start_rename(self) -> None:
        """Open the selected parameter's name for editing in the tree (F2)."""
        name = self.selected
        if name is None or self.dock is None:
            self.context.status.showMessage("Select a parameter to rename first", MESSAGE_MS)
            return
        self.dock.show()
        self.dock.view.setFocus()
        self.dock.view.edit(self.dock.model.index_of(name))

    def reparent(self, names: list[str], parent: str | None, before: str | None = None) -> bool:
        """Move each of ``names`` under ``parent`` (``None``: to the top), one undo step each.

        With ``before`` (a child of ``parent``) they are placed just before it,
        in the order given; without, after ``parent``'s last child (a parameter
        already under ``parent`` then stays where it is). A move into its own
        subtree is refused with a message.
        """
        done = True
        tree = self.document.model.parameters
        for name in names:
            if name not in tree or name == before or (before is None and tree[name].parent == parent):
                continue
            done = self.push(lambda name=name: MoveParameterCommand(self.document, name, parent, before)) and done
        return done

    def move_among_siblings(self, step: int, name: str | None = None) -> bool:
        """Move ``name`` (default: the selected parameter) ``step`` places up (−1) or down (+1) among its siblings."""
        name = name if name is not None else self.selected
        if name is None:
            return False
        tree = self.document.model.parameters
        parent = tree[name].parent
        siblings = tree.children(parent) if parent is not None else tree.roots()
        at = siblings.index(name) + step
        if not 0 <= at < len(siblings):
            return False
        rest = [s for s in siblings if s != name]
        before = rest[at] if at < len(rest) else None
        if before is None:
            return self.push(lambda: MoveParameterCommand(self.document, name, parent))
        return self.push(lambda: MoveParameterCommand(self.document, name, parent, before))

    # -- messages ------------------------------------------------------------
    def warn(self, text: str) -> None:
        QMessageBox.warning(self.window, TITLE, text)


def _centre(model: engine.Model) -> np.ndarray:
    """Middle of the model's bounding box (mm): where a new root's pivot starts."""
    if model.n_vertices == 0:
        return np.zeros(3)
    return (model.vertices.min(axis=0) + model.vertices.max(axis=0)) / 2
