""""Apply to model" as one undo step: the PCA's translation parameters and their regions added together.

:func:`engine.mocap.apply.apply_articulation` runs on a copy of the model in
the background; the parameters and influence regions it made are then added
to the open model by :class:`AddArticulationCommand`, in one engine edit
(:func:`engine.model.edits.add_parameters`, all or none, through
:meth:`~workbench.document.model_document.ModelDocument.apply_add_parameters`). Undo
restores the tree the edit returned, exactly.

>>> document.push(AddArticulationCommand(document, [(parameter, region), ...]))   # doctest: +SKIP
>>> document.undo_stack.undoText()                                                # doctest: +SKIP
'Add 5 PCA parameters (pca1 … pca5)'
"""

from __future__ import annotations

from engine.model.edits import TreeState

from ..document.undo_commands import TreeEditCommand


class AddArticulationCommand(TreeEditCommand):
    """Add several parameters with their regions as one undoable edit (all or none)."""

    def __init__(self, document, parameters_and_regions, text: str | None = None):
        items = [(p.copy(), r.copy()) for p, r in parameters_and_regions]
        names = [p.name for p, _ in items]
        label = f"{names[0]} … {names[-1]}" if len(names) > 2 else ", ".join(names)
        super().__init__(document, text or f"Add {len(items)} PCA parameters ({label})")
        self._items = items

    @property
    def names(self) -> list[str]:
        return [p.name for p, _ in self._items]

    def edit(self) -> TreeState:
        return self.document.apply_add_parameters(self._items)
