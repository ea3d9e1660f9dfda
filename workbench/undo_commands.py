"""Undo commands: every model edit, as a small QUndoCommand around one engine operation.

Each command captures in its constructor what the edit will change (a
parameter, a region, the tree's order, the weights of some vertices) and its
``redo``/``undo`` call :class:`~workbench.document.ModelDocument`'s
``apply_*`` methods, which call the engine and announce the change. Undo puts
back the captured state itself, so the model returns bit for bit. Push them
with :meth:`ModelDocument.push`, which applies the edit first and so refuses
an invalid one (an :class:`engine.UserError`) before it reaches the stack.

>>> document.push(RenameParameterCommand(document, "jaw_open", "jaw_drop"))   # doctest: +SKIP
>>> document.undo_stack.undoText()                                          # doctest: +SKIP
'Rename jaw_open to jaw_drop'

Pose changes (moving a slider) are not model edits and never come here.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtGui import QUndoCommand

import engine
from engine.errors import UserError

from .model_edits import TreeSnapshot, moved_parameters, subtree, without_subtree

if TYPE_CHECKING:
    from .document import ModelDocument

WEIGHTS_COMMAND_ID = 1001  # QUndoCommand.id() of weight edits that merge (one brush stroke)


class ModelEditCommand(QUndoCommand):
    """Base class: ``apply`` makes the edit, ``revert`` takes it back.

    The document is held weakly: the stack (owned by the document) owns the
    commands, and a strong reference back would keep the document alive.
    """

    def __init__(self, document: "ModelDocument", text: str):
        super().__init__(text)
        self._document_ref = weakref.ref(document)
        self._skip_next_redo = False

    @property
    def document(self) -> "ModelDocument":
        document = self._document_ref()
        if document is None:
            raise RuntimeError("the document of this undo command is gone")
        return document

    @property
    def model(self) -> engine.Model:
        return self.document.model

    def apply_first(self) -> None:
        """Make the edit now (called by :meth:`ModelDocument.push`); the stack's first redo is skipped."""
        self.apply()
        self._skip_next_redo = True

    def redo(self) -> None:
        if self._skip_next_redo:
            self._skip_next_redo = False
            return
        self.apply()

    def undo(self) -> None:
        self.revert()

    def apply(self) -> None:
        raise NotImplementedError

    def revert(self) -> None:
        raise NotImplementedError


class AddParameterCommand(ModelEditCommand):
    """Add a new parameter (at the end of the order) with its region (empty if none is given)."""

    def __init__(self, document: "ModelDocument", parameter: engine.Parameter,
                 region: engine.InfluenceRegion | None = None):
        super().__init__(document, f"Add parameter {parameter.name}")
        self._parameter = parameter.copy()
        self._region = region.copy() if region is not None else engine.InfluenceRegion()

    def apply(self) -> None:
        self.document.apply_add_parameter(self._parameter.copy(), self._region.copy())

    def revert(self) -> None:
        # A new parameter has no children and sits last, so removing it restores the tree exactly.
        self.document.apply_remove_parameter(self._parameter.name)


class RemoveParameterCommand(ModelEditCommand):
    """Remove a parameter and its region; its children move up to its parent (as the engine does)."""

    def __init__(self, document: "ModelDocument", name: str):
        super().__init__(document, f"Remove parameter {name}")
        self._name = name
        # The engine re-parents the children and drops the parameter from the order;
        # undo needs the whole order and the children's parents back, so keep the tree.
        self._before = TreeSnapshot.of(document.model, [name])

    def apply(self) -> None:
        self.document.apply_remove_parameter(self._name)

    def revert(self) -> None:
        self.document.apply_restore_tree(self._before)


class RemoveSubtreeCommand(ModelEditCommand):
    """Remove a parameter together with everything below it, and their regions.

    Undo puts the whole subtree back in its place in the order, with its
    regions, bit for bit.
    """

    def __init__(self, document: "ModelDocument", name: str):
        names = subtree(document.model.parameters, name)
        below = f" and {len(names) - 1} below it" if len(names) > 1 else ""
        super().__init__(document, f"Remove parameter {name}{below}")
        self._name = name
        self.removed = names
        self._before = TreeSnapshot.of(document.model, names)

    def apply(self) -> None:
        snapshot, removed = without_subtree(self.model, self._name)
        self.document.apply_restore_tree(snapshot, drop_regions=removed)

    def revert(self) -> None:
        self.document.apply_restore_tree(self._before)


class ReplaceParameterCommand(ModelEditCommand):
    """Give a parameter new properties (type, axis, pivot, range, default, parent, …); same name."""

    def __init__(self, document: "ModelDocument", parameter: engine.Parameter, text: str | None = None):
        super().__init__(document, text or f"Edit parameter {parameter.name}")
        self._old = document.model.parameters[parameter.name].copy()
        self._new = parameter.copy()

    def apply(self) -> None:
        self.document.apply_replace_parameter(self._new.copy())

    def revert(self) -> None:
        self.document.apply_replace_parameter(self._old.copy())


class MoveParameterCommand(ModelEditCommand):
    """Move a parameter under another one (``None``: to the top), before its new sibling ``before``
    (``None``: after the last one). Its subtree moves with it.

    The tree refuses loops and children under a displacement field; the
    groups (rigid / leaf) follow from the new shape. The order of the
    parameters is the order siblings are shown and saved in.
    """

    def __init__(self, document: "ModelDocument", name: str, parent: str | None, before: str | None = None):
        self._after = TreeSnapshot(tuple(moved_parameters(document.model.parameters, name, parent, before)), {})
        self._before = TreeSnapshot.of(document.model)
        where = f"under {parent}" if parent is not None else "to the top"
        if before is not None:
            where = f"before {before}" if document.model.parameters[name].parent == parent else f"{where}, before {before}"
        super().__init__(document, f"Move {name} {where}")

    def apply(self) -> None:
        self.document.apply_restore_tree(self._after)

    def revert(self) -> None:
        self.document.apply_restore_tree(self._before)


class RenameParameterCommand(ModelEditCommand):
    """Rename a parameter; its region and its children's ``parent`` follow, the order stays."""

    def __init__(self, document: "ModelDocument", old: str, new: str):
        super().__init__(document, f"Rename {old} to {new}")
        document.model.parameters[old]
        self._old, self._new = old, new

    def apply(self) -> None:
        self.document.apply_rename_parameter(self._old, self._new)

    def revert(self) -> None:
        self.document.apply_rename_parameter(self._new, self._old)


class SetRegionCommand(ModelEditCommand):
    """Replace a parameter's whole influence region (indices, weights, displacements)."""

    def __init__(self, document: "ModelDocument", name: str, region: engine.InfluenceRegion,
                 text: str | None = None):
        super().__init__(document, text or f"Set region of {name}")
        document.model.parameters[name]
        self._name = name
        self._old = document.model.regions[name].copy()
        self._new = region.copy()

    def apply(self) -> None:
        self.document.apply_set_region(self._name, self._new.copy())

    def revert(self) -> None:
        self.document.apply_set_region(self._name, self._old.copy())


class WeightsChangedCommand(ModelEditCommand):
    """The weights of some vertices of one region changed: a dab, a stroke, a smoothing.

    ``indices`` are model vertex indices, ``before`` and ``after`` their
    weights, NaN meaning "not in the region" (see
    :meth:`ModelDocument.region_weights`). Leave ``before`` out to read it
    from the model now. A tool that already wrote ``after`` into the model
    (live preview while painting) passes ``before`` and
    ``already_applied=True``.

    Commands with the same ``stroke_id`` (not ``None``) on the same
    parameter merge into one undo step: every dab of a brush stroke. The
    merged step keeps the first ``before`` and the last ``after`` of each vertex.
    """

    def __init__(self, document: "ModelDocument", name: str, indices, after, before=None, *,
                 stroke_id: object = None, text: str = "Paint weights", already_applied: bool = False):
        super().__init__(document, text)
        document.model.parameters[name]
        indices = np.asarray(indices, dtype=np.int64).reshape(-1)
        after = np.asarray(after, dtype=float).reshape(-1)
        if before is None:
            if already_applied:
                raise ValueError("already_applied=True needs the weights from before")
            before = document.region_weights(name, indices)
        before = np.asarray(before, dtype=float).reshape(-1)
        if not (indices.shape == after.shape == before.shape):
            raise UserError(f"weights: {len(indices)} vertex indices, {len(before)} weights before "
                            f"and {len(after)} after")
        order = np.argsort(indices, kind="stable")
        self._name = name
        self.indices, self.before, self.after = indices[order], before[order], after[order]
        if len(self.indices) > 1 and np.any(self.indices[1:] == self.indices[:-1]):
            raise UserError("weights: a vertex index is listed twice")
        self._stroke_id = stroke_id
        self._already_applied = already_applied

    @property
    def parameter(self) -> str:
        return self._name

    def apply_first(self) -> None:
        if self._already_applied:
            self._skip_next_redo = True
        else:
            super().apply_first()

    def apply(self) -> None:
        self.document.apply_weights(self._name, self.indices, self.after)

    def revert(self) -> None:
        self.document.apply_weights(self._name, self.indices, self.before)

    def id(self) -> int:  # noqa: A003 (Qt's name)
        return WEIGHTS_COMMAND_ID if self._stroke_id is not None else -1

    def mergeWith(self, other: QUndoCommand) -> bool:  # noqa: N802 (Qt's name)
        if (not isinstance(other, WeightsChangedCommand) or other._stroke_id != self._stroke_id
                or other._name != self._name):
            return False
        indices = np.union1d(self.indices, other.indices)
        mine = np.isin(indices, self.indices, assume_unique=True)
        theirs = np.isin(indices, other.indices, assume_unique=True)
        before = np.empty(len(indices))
        before[mine] = self.before
        before[~mine] = other.before[np.searchsorted(other.indices, indices[~mine])]
        after = np.empty(len(indices))
        after[theirs] = other.after
        after[~theirs] = self.after[np.searchsorted(self.indices, indices[~theirs])]
        self.indices, self.before, self.after = indices, before, after
        return True
