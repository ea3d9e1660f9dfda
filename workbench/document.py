"""The open model and its current pose, announcing every change to the widgets.

:class:`ModelDocument` is the one object the workbench's widgets share. It
holds an :class:`engine.Model` and the value of every parameter, forwards
edits to the engine and emits a signal after each one; widgets listen and
redraw, they never talk to each other. Engine code never sees this class.

Model edits and pose changes are kept apart. Moving a slider is a pose
change (:meth:`ModelDocument.set_values`): it is not saved and not undone.
Changing the model (the tree, a region, some weights) goes through an undo
command from :mod:`workbench.undo_commands`, pushed with
:meth:`ModelDocument.push`; the commands call the ``apply_*`` methods here,
which call the engine and announce the change. "Modified" means the undo
stack is not at its clean index.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Mapping

import numpy as np
from PySide6.QtCore import QObject, Signal
from PySide6.QtGui import QUndoStack

import engine

from .model_edits import TreeSnapshot, renamed_parameters, restore_tree, weights_at, with_weights

if TYPE_CHECKING:
    from .undo_commands import ModelEditCommand


class ModelDocument(QObject):
    """An :class:`engine.Model`, where it came from, and the pose being shown.

    Signals
    -------
    model_replaced(object)
        A different model is now open (after :meth:`open` or
        :meth:`replace_model`); every parameter is back at its default.
    values_changed(list)
        The listed parameters have new values; read them from :attr:`values`.
    path_changed(str)
        The file the model is associated with changed (e.g. after a save as).
    parameters_changed(list)
        The parameter tree was edited (a parameter added, removed, renamed,
        moved or its properties changed; also by undo and redo). The list
        names the parameters touched (both names for a rename). Values of
        parameters that are gone were dropped, new ones start at their default.
    regions_changed(list)
        The influence regions (weights) of the listed parameters changed.
    modified_changed(bool)
        The model now differs (``True``) or no longer differs from the file.
    """

    model_replaced = Signal(object)
    values_changed = Signal(list)
    path_changed = Signal(str)
    parameters_changed = Signal(list)
    regions_changed = Signal(list)
    modified_changed = Signal(bool)

    def __init__(self, model: engine.Model, path: str | Path | None = None, parent: QObject | None = None):
        super().__init__(parent)
        self._model = model
        self._path = Path(path) if path is not None else None
        self._values = model.default_values()
        self._vertices: np.ndarray | None = None
        self._generation = 0
        self.undo_stack = QUndoStack(self)
        self.undo_stack.cleanChanged.connect(self._on_clean_changed)

    # -- state -----------------------------------------------------------
    @property
    def model(self) -> engine.Model:
        return self._model

    @property
    def path(self) -> Path | None:
        """The model's XML description on disk, or ``None`` for a model built in memory."""
        return self._path

    @property
    def values(self) -> dict[str, float]:
        """Current value of every parameter, by name (a copy)."""
        return dict(self._values)

    def value(self, name: str) -> float:
        self._model.parameters[name]  # unknown names raise ParameterError with a suggestion
        return self._values[name]

    def vertices(self) -> np.ndarray:
        """The deformed mesh for the current values, (N, 3) mm, computed once per change."""
        if self._vertices is None:
            self._vertices = self._model.deform(self._values)
        return self._vertices

    def is_at_rest(self) -> bool:
        return self._values == self._model.default_values()

    @property
    def is_modified(self) -> bool:
        """Whether the model differs from its file (the undo stack is not clean)."""
        return not self.undo_stack.isClean()

    @property
    def generation(self) -> int:
        """A counter bumped by every model edit, undo and redo (autosave compares it)."""
        return self._generation

    def region_weights(self, name: str, indices) -> np.ndarray:
        """Weights of ``name``'s region at ``indices``; NaN where a vertex is not in the region.

        What a painting tool records as ``before`` for a
        :class:`~workbench.undo_commands.WeightsChangedCommand`.
        """
        self._model.parameters[name]
        return weights_at(self._model.regions[name], indices)

    # -- pose edits --------------------------------------------------------
    def set_value(self, name: str, value: float) -> None:
        """Set one parameter; values outside its range raise :class:`engine.ParameterError`."""
        self.set_values({name: value})

    def set_values(self, values: Mapping[str, float]) -> None:
        """Set several parameters at once (one redraw); unchanged values are ignored."""
        values = {name: float(v) for name, v in values.items()}
        self._model.check_values(values)
        changed = [name for name, v in values.items() if self._values[name] != v]
        if not changed:
            return
        for name in changed:
            self._values[name] = values[name]
        self._vertices = None
        self.values_changed.emit(changed)

    def reset_value(self, name: str) -> None:
        """Put one parameter back to its default."""
        self.set_value(name, self._model.parameters[name].default)

    def reset_all(self) -> None:
        """Put every parameter back to its default: the rest pose."""
        self.set_values(self._model.default_values())

    # -- model edits (undoable) ----------------------------------------------
    def push(self, command: "ModelEditCommand") -> None:
        """Apply an edit and put it on the undo stack.

        The edit is applied here first, so an edit the engine refuses raises
        its :class:`engine.UserError` with the model unchanged and nothing on
        the stack; the stack's own first ``redo`` is then skipped.
        """
        command.apply_first()
        self.undo_stack.push(command)

    def mark_modified(self) -> None:
        """Call the model modified with no step to undo (e.g. after recovering an autosave)."""
        self.undo_stack.resetClean()

    # The apply_* methods are the undo commands' access to the model: each
    # calls one engine operation and announces the change. Call them only
    # from a command, or the edit escapes the undo stack.
    def apply_add_parameter(self, parameter: engine.Parameter, region: engine.InfluenceRegion) -> None:
        self._model.add_parameter(parameter, region)
        self._tree_edited([parameter.name])

    def apply_remove_parameter(self, name: str) -> None:
        self._model.remove_parameter(name)
        self._tree_edited([name])

    def apply_replace_parameter(self, parameter: engine.Parameter) -> None:
        """Replace the parameter of the same name (new properties, or a new parent)."""
        tree = self._model.parameters
        old = tree[parameter.name]
        tree.replace(parameter)
        try:
            self._model.validate()          # e.g. a field translation needs displacements
        except engine.UserError:
            tree.replace(old)
            raise
        self._model.changed()
        self._tree_edited([parameter.name])

    def apply_rename_parameter(self, old: str, new: str) -> None:
        parameters = renamed_parameters(self._model.parameters, old, new)
        restore_tree(self._model, TreeSnapshot(tuple(parameters), {new: self._model.regions[old]}),
                     drop_regions=[old])
        self._tree_edited([old, new], renamed={old: new})

    def apply_restore_tree(self, snapshot: TreeSnapshot, drop_regions=()) -> None:
        """Make the tree the snapshot's, its regions put back (undoing a removal)."""
        before = set(self._model.parameters.names)
        restore_tree(self._model, snapshot, drop_regions)
        after = set(self._model.parameters.names)
        self._tree_edited(sorted(before ^ after) or [p.name for p in snapshot.parameters])

    def apply_set_region(self, name: str, region: engine.InfluenceRegion) -> None:
        self._model.set_region(name, region)
        self._regions_edited([name])

    def apply_weights(self, name: str, indices, weights) -> None:
        """Give the vertices ``indices`` of ``name``'s region these weights (NaN: take them out)."""
        self._model.parameters[name]
        self._model.set_region(name, with_weights(self._model.regions[name], indices, weights))
        self._regions_edited([name])

    def _tree_edited(self, names: list[str], renamed: Mapping[str, str] | None = None) -> None:
        values = dict(self._values)
        for old, new in (renamed or {}).items():
            if old in values:
                values[new] = values.pop(old)
        self._values = {p.name: min(max(values.get(p.name, p.default), p.minimum), p.maximum)
                        for p in self._model.parameters}
        self._edited()
        self.parameters_changed.emit(list(names))

    def _regions_edited(self, names: list[str]) -> None:
        self._edited()
        self.regions_changed.emit(list(names))

    def _edited(self) -> None:
        self._vertices = None
        self._generation += 1

    def _on_clean_changed(self, clean: bool) -> None:
        self.modified_changed.emit(not clean)

    # -- whole-model changes -------------------------------------------------
    def open(self, path: str | Path) -> None:
        """Load the model at ``path`` and make it current.

        Raises :class:`engine.UserError` (nothing changes) if it cannot be read.
        """
        model = engine.load_model(path)
        self.replace_model(model, path)

    def replace_model(self, model: engine.Model, path: str | Path | None = None) -> None:
        """Make ``model`` current, every parameter at its default, with an empty (clean) undo stack."""
        self._model = model
        self._values = model.default_values()
        self._vertices = None
        self._generation += 1
        self.undo_stack.clear()          # the commands edit the old model; clear() also marks it clean
        self._set_path(path)
        self.model_replaced.emit(model)

    def save(self, path: str | Path) -> Path:
        """Write the model with :func:`engine.save_model`, remember the new path, mark it unmodified."""
        written = engine.save_model(self._model, path)
        self._set_path(written)
        self.undo_stack.setClean()
        return written

    def save_copy(self, path: str | Path) -> Path:
        """Write the model to ``path`` without making it the document's file (autosave, export)."""
        return engine.save_model(self._model, path)

    def _set_path(self, path: str | Path | None) -> None:
        new = Path(path) if path is not None else None
        if new != self._path:
            self._path = new
            self.path_changed.emit(str(new) if new is not None else "")
