"""The open model and its current pose, announcing every change to the widgets.

:class:`ModelDocument` is the one object the workbench's widgets share. It
holds an :class:`engine.Model` and the value of every parameter, forwards
edits to the engine and emits a signal after each one; widgets listen and
redraw, they never talk to each other. Engine code never sees this class.

Model edits and pose changes are kept apart. Moving a slider is a pose
change (:meth:`ModelDocument.set_values`): it is not saved and not undone.
Changing the model (the tree, a region, some weights) goes through an undo
command from :mod:`workbench.document.undo_commands`, pushed with
:meth:`ModelDocument.push`; the commands call the ``apply_*`` methods here,
each one engine edit (:mod:`engine.model.edits`,
:func:`engine.model.apply_weight_change`) whose returned inverse the command
keeps for undo, and announce the change. "Modified" means the undo stack is
not at its clean index.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path

import numpy as np
from PySide6.QtCore import QObject, Signal
from PySide6.QtGui import QUndoCommand, QUndoStack

import engine
from engine.model import edits
from engine.model.edits import TreeState
from engine.model.weight_changes import WeightChange, apply_weight_change, weights_at


class ModelDocument(QObject):
    """An :class:`engine.Model`, where it came from, and the pose being shown.

    Signals
    -------
    model_replaced(object)
        A different model is now open (after :meth:`open` or
        :meth:`replace_model`); every parameter is back at its default.
        Also after :meth:`apply_replace_model` (an identity change, its undo
        and redo), where each parameter the new model has keeps its value.
    values_changed(list)
        The listed parameters have new values; read them from :attr:`values`.
    path_changed(str)
        The file the model is associated with changed (e.g. after a save as; also a new person's head made
        from photographs, which has none, and its undo).
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
        self._suggested_path: Path | None = None
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
    def suggested_path(self) -> Path | None:
        """Where Save proposes to write a model that has no file (:attr:`path` is ``None``), if anywhere."""
        return self._suggested_path

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

        What a :class:`~engine.model.WeightChange` records as ``before``.
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
    def push(self, command: QUndoCommand) -> None:
        """Apply an edit and put it on the undo stack.

        ``command`` is a :class:`~workbench.document.undo_commands.ModelEditCommand`.
        The edit is applied here first, so an edit the engine refuses raises
        its :class:`engine.UserError` with the model unchanged and nothing on
        the stack; the stack's own first ``redo`` is then skipped.
        """
        apply_first = getattr(command, "apply_first", None)
        if apply_first is None:
            raise TypeError("ModelDocument.push takes a ModelEditCommand (workbench.document.undo_commands)")
        apply_first()
        self.undo_stack.push(command)

    def mark_modified(self) -> None:
        """Call the model modified with no step to undo (e.g. after recovering an autosave)."""
        self.undo_stack.resetClean()

    # The apply_* methods are the undo commands' access to the model: each
    # calls one engine edit, announces the change and returns what undoes it.
    # Call them only from a command, or the edit escapes the undo stack.
    def apply_add_parameter(self, parameter: engine.Parameter,
                            region: engine.InfluenceRegion | None = None) -> TreeState:
        return self._tree_edit_done(edits.add_parameter(self._model, parameter, region))

    def apply_add_parameters(
            self, parameters_and_regions: Iterable[tuple[engine.Parameter, engine.InfluenceRegion | None]]
    ) -> TreeState:
        """Add several parameters with their regions at once (all or none)."""
        return self._tree_edit_done(edits.add_parameters(self._model, parameters_and_regions))

    def apply_remove_parameter(self, name: str) -> TreeState:
        """Remove one parameter; its children move up to its parent."""
        return self._tree_edit_done(edits.remove_parameter(self._model, name))

    def apply_remove_subtree(self, name: str) -> TreeState:
        """Remove a parameter and everything below it."""
        return self._tree_edit_done(edits.remove_subtree(self._model, name))

    def apply_replace_parameter(self, parameter: engine.Parameter) -> TreeState:
        """Replace the parameter of the same name (new properties, or a new parent)."""
        return self._tree_edit_done(edits.replace_parameter(self._model, parameter))

    def apply_rename_parameter(self, old: str, new: str) -> TreeState:
        return self._tree_edit_done(edits.rename_parameter(self._model, old, new))

    def apply_move_parameter(self, name: str, parent: str | None, before: str | None = None) -> TreeState:
        return self._tree_edit_done(edits.move_parameter(self._model, name, parent, before))

    def apply_restore_tree(self, state: TreeState) -> TreeState:
        """Make the tree ``state``'s (an undo or a redo); returns the state that takes it back."""
        return self._tree_edit_done(edits.restore_tree(self._model, state))

    def apply_set_region(self, name: str, region: engine.InfluenceRegion) -> engine.InfluenceRegion:
        """Replace a whole region; returns the one it replaced."""
        old = edits.set_region(self._model, name, region)
        self._regions_edited([name])
        return old

    def apply_weight_change(self, name: str, change: WeightChange) -> WeightChange:
        """Write some weights of ``name``'s region (NaN: out of it); returns the change that undoes it."""
        undo = apply_weight_change(self._model, name, change)
        self._regions_edited([name])
        return undo

    def apply_replace_model(self, model: engine.Model) -> engine.Model:
        """Make ``model`` current as an undoable edit (a new identity's head); returns the model it replaced.

        Unlike :meth:`replace_model` the undo stack and the file stay: the
        command keeps the old model and puts it back on undo. The pose is
        kept for every parameter ``model`` has (clamped to its range).
        """
        old = self._model
        self._model = model
        self._values = {p.name: min(max(self._values.get(p.name, p.default), p.minimum), p.maximum)
                        for p in model.parameters}
        self._edited()
        self.model_replaced.emit(model)
        return old

    def apply_file(self, path: str | Path | None,
                   suggested: str | Path | None = None) -> tuple[Path | None, Path | None]:
        """Give the model another file (``None``: none, Save asks, proposing ``suggested``) as part of an undoable
        edit (a new person's head must not keep the previous person's file); returns the file and suggestion
        it had, which undo gives back."""
        before = self._path, self._suggested_path
        self._suggested_path = Path(suggested) if suggested is not None and path is None else None
        self._set_path(path)
        return before

    def _tree_edit_done(self, undo: TreeState) -> TreeState:
        """Announce a tree edit whose undo state is ``undo`` (its parameters are the tree before)."""
        renamed = {old: new for new, old in undo.renamed.items()}
        before, after = set(undo.names), set(self._model.parameters.names)
        names = sorted((before ^ after) - set(renamed) - set(renamed.values()))      # added or removed
        if not names and renamed:
            names = [name for pair in renamed.items() for name in pair]               # [old, new]: views follow
        if not names:
            names = (edits.changed_parameters(undo.parameters, list(self._model.parameters))
                     or self._model.parameters.names)                                  # only the order changed
        self._tree_edited(names, renamed)
        return undo

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
        self._suggested_path = None
        self._set_path(path)
        self.model_replaced.emit(model)

    def save(self, path: str | Path) -> Path:
        """Write the model with :func:`engine.save_model`, remember the new path, mark it unmodified."""
        written = engine.save_model(self._model, path)
        self._suggested_path = None
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
