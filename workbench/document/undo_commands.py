"""Undo commands: every model edit, as a small QUndoCommand around one engine operation.

Each command's ``apply`` calls one :class:`~workbench.document.model_document.ModelDocument`
``apply_*`` method, which makes one engine edit (:mod:`engine.model.edits`,
:func:`engine.model.apply_weight_change`), announces it, and returns what
undoes it: a :class:`~engine.model.TreeState` for the tree, a
:class:`~engine.model.WeightChange` for weights, the old region for a whole
region. The command keeps that and ``revert`` applies it, so the model
returns bit for bit; undoing returns the redo state in turn. Push commands
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

from PySide6.QtGui import QUndoCommand

import engine
from engine.model.edits import TreeState, subtree
from engine.model.weight_changes import WeightChange, weight_change

if TYPE_CHECKING:
    from .model_document import ModelDocument

WEIGHTS_COMMAND_ID = 1001  # QUndoCommand.id() of weight edits that merge (one brush stroke)


class ModelEditCommand(QUndoCommand):
    """Base class: ``apply`` makes the edit, ``revert`` takes it back.

    The document is held weakly: the stack (owned by the document) owns the
    commands, and a strong reference back would keep the document alive.
    """

    def __init__(self, document: ModelDocument, text: str):
        super().__init__(text)
        self._document_ref = weakref.ref(document)
        self._skip_next_redo = False

    @property
    def document(self) -> ModelDocument:
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


class TreeEditCommand(ModelEditCommand):
    """Base class of the tree edits: :meth:`edit` makes the edit and returns the state that undoes it.

    Undo restores that state and keeps the state it returns, which redo
    restores: both directions are exact whatever the edit was.
    """

    def __init__(self, document: ModelDocument, text: str):
        super().__init__(document, text)
        self._undo_state: TreeState | None = None
        self._redo_state: TreeState | None = None

    def edit(self) -> TreeState:
        raise NotImplementedError

    def apply(self) -> None:
        if self._redo_state is None:
            self._undo_state = self.edit()
        else:
            self._undo_state = self.document.apply_restore_tree(self._redo_state)

    def revert(self) -> None:
        if self._undo_state is None:
            raise RuntimeError("undo before the edit was made")
        self._redo_state = self.document.apply_restore_tree(self._undo_state)


class AddParameterCommand(TreeEditCommand):
    """Add a new parameter (at the end of the order) with its region (empty if none is given)."""

    def __init__(self, document: ModelDocument, parameter: engine.Parameter,
                 region: engine.InfluenceRegion | None = None):
        super().__init__(document, f"Add parameter {parameter.name}")
        self._parameter = parameter.copy()
        self._region = region.copy() if region is not None else engine.InfluenceRegion()

    def edit(self) -> TreeState:
        return self.document.apply_add_parameter(self._parameter, self._region)


class RemoveParameterCommand(TreeEditCommand):
    """Remove a parameter and its region; its children move up to its parent (as the engine does)."""

    def __init__(self, document: ModelDocument, name: str):
        document.model.parameters[name]
        super().__init__(document, f"Remove parameter {name}")
        self._name = name

    def edit(self) -> TreeState:
        return self.document.apply_remove_parameter(self._name)


class RemoveSubtreeCommand(TreeEditCommand):
    """Remove a parameter together with everything below it, and their regions.

    Undo puts the whole subtree back in its place in the order, with its
    regions, bit for bit.
    """

    def __init__(self, document: ModelDocument, name: str):
        names = subtree(document.model.parameters, name)
        below = f" and {len(names) - 1} below it" if len(names) > 1 else ""
        super().__init__(document, f"Remove parameter {name}{below}")
        self._name = name
        self.removed = names

    def edit(self) -> TreeState:
        return self.document.apply_remove_subtree(self._name)


class ReplaceParameterCommand(TreeEditCommand):
    """Give a parameter new properties (type, axis, pivot, range, default, parent, …); same name."""

    def __init__(self, document: ModelDocument, parameter: engine.Parameter, text: str | None = None):
        document.model.parameters[parameter.name]
        super().__init__(document, text or f"Edit parameter {parameter.name}")
        self._new = parameter.copy()

    def edit(self) -> TreeState:
        return self.document.apply_replace_parameter(self._new)


class MoveParameterCommand(TreeEditCommand):
    """Move a parameter under another one (``None``: to the top), before its new sibling ``before``
    (``None``: after the last one). Its subtree moves with it.

    The tree refuses loops and children under a displacement field; the
    groups (rigid / leaf) follow from the new shape. The order of the
    parameters is the order siblings are shown and saved in.
    """

    def __init__(self, document: ModelDocument, name: str, parent: str | None, before: str | None = None):
        where = f"under {parent}" if parent is not None else "to the top"
        if before is not None:
            same_parent = document.model.parameters[name].parent == parent
            where = f"before {before}" if same_parent else f"{where}, before {before}"
        super().__init__(document, f"Move {name} {where}")
        self._move = (name, parent, before)

    def edit(self) -> TreeState:
        return self.document.apply_move_parameter(*self._move)


class RenameParameterCommand(TreeEditCommand):
    """Rename a parameter; its region and its children's ``parent`` follow, the order stays."""

    def __init__(self, document: ModelDocument, old: str, new: str):
        super().__init__(document, f"Rename {old} to {new}")
        document.model.parameters[old]
        self._old, self._new = old, new

    def edit(self) -> TreeState:
        return self.document.apply_rename_parameter(self._old, self._new)


class SetRegionCommand(ModelEditCommand):
    """Replace a parameter's whole influence region (indices, weights, displacements)."""

    def __init__(self, document: ModelDocument, name: str, region: engine.InfluenceRegion,
                 text: str | None = None):
        super().__init__(document, text or f"Set region of {name}")
        document.model.parameters[name]
        self._name = name
        self._new = region.copy()
        self._old: engine.InfluenceRegion | None = None

    def apply(self) -> None:
        self._old = self.document.apply_set_region(self._name, self._new)

    def revert(self) -> None:
        if self._old is None:
            raise RuntimeError("undo before the edit was made")
        self.document.apply_set_region(self._name, self._old)


class WeightsChangedCommand(ModelEditCommand):
    """The weights of some vertices of one region changed: a dab, a stroke, a smoothing.

    Holds one :class:`~engine.model.WeightChange`: ``indices`` are model
    vertex indices, ``before`` and ``after`` their weights, NaN meaning "not
    in the region" (see :meth:`ModelDocument.region_weights`). Leave
    ``before`` out to read it from the model now; a tool with a
    :class:`~engine.model.WeightChange` in hand uses :meth:`from_change`. A
    tool that already wrote ``after`` into the model passes ``before`` and
    ``already_applied=True``.

    Commands with the same ``stroke_id`` (not ``None``) on the same
    parameter merge into one undo step: every dab of a brush stroke. The
    merged step keeps the first ``before`` and the last ``after`` of each
    vertex (:meth:`WeightChange.followed_by <engine.model.WeightChange.followed_by>`).
    """

    def __init__(self, document: ModelDocument, name: str, indices, after, before=None, *,
                 stroke_id: object = None, text: str = "Paint weights", already_applied: bool = False):
        super().__init__(document, text)
        if before is None:
            if already_applied:
                raise ValueError("already_applied=True needs the weights from before")
            change = weight_change(document.model, name, indices, after)
        else:
            document.model.parameters[name]
            change = WeightChange(indices, before, after)
        self._name = name
        self.change = change
        self._undo = change.inverse()     # replaced by the inverse the engine returns when it applies it
        self._stroke_id = stroke_id
        self._already_applied = already_applied

    @classmethod
    def from_change(cls, document: ModelDocument, name: str, change: WeightChange, *, stroke_id: object = None,
                    text: str = "Paint weights", already_applied: bool = False) -> WeightsChangedCommand:
        """The command for a :class:`~engine.model.WeightChange` (e.g. :meth:`engine.painting.PaintStroke.finish`)."""
        return cls(document, name, change.indices, change.after, change.before, stroke_id=stroke_id, text=text,
                   already_applied=already_applied)

    @property
    def parameter(self) -> str:
        return self._name

    def apply_first(self) -> None:
        if self._already_applied:
            self._skip_next_redo = True
        else:
            super().apply_first()

    def apply(self) -> None:
        self._undo = self.document.apply_weight_change(self._name, self.change)

    def revert(self) -> None:
        self.document.apply_weight_change(self._name, self._undo)

    def id(self) -> int:
        return WEIGHTS_COMMAND_ID if self._stroke_id is not None else -1

    def mergeWith(self, other: QUndoCommand) -> bool:
        if (not isinstance(other, WeightsChangedCommand) or other._stroke_id != self._stroke_id
                or other._name != self._name):
            return False
        self.change = self.change.followed_by(other.change)
        self._undo = other._undo.followed_by(self._undo)
        return True


class ReplaceModelCommand(ModelEditCommand):
    """The whole model replaced by another (a head made for a new identity), the old one kept for undo.

    ``base`` is what the new model was made from (the model identities of
    this line are made from), kept with the command so the next identity
    change can be made from it too (:mod:`workbench.identity_panel.heads`).
    """

    def __init__(self, document: ModelDocument, model: engine.Model, text: str, base: engine.Model | None = None):
        super().__init__(document, text)
        self.made = model
        self.base = base
        self.replaced: engine.Model | None = None

    def apply(self) -> None:
        self.replaced = self.document.apply_replace_model(self.made)

    def revert(self) -> None:
        if self.replaced is None:
            raise RuntimeError("undo before the edit was made")
        self.document.apply_replace_model(self.replaced)
