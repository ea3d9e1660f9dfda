"""The Weights menu: whole-region operations on the selected parameter, each one undo step.

Each operation calls one engine function of :mod:`engine.painting` on the
painted parameter's dense weights and pushes the difference, as the model's
:class:`~engine.model.WeightChange` (:func:`~engine.painting.weight_change_from_dense`),
in a :class:`~workbench.document.undo_commands.WeightsChangedCommand`; normalising group 1
changes several regions and is one macro of
:class:`~workbench.document.undo_commands.SetRegionCommand`. Invert, clear, smooth,
grow and shrink keep to the part chosen in the tool options ("All parts":
everywhere).

>>> run(window.paint, "invert")        # doctest: +SKIP
>>> window.document.undo_stack.undoText()   # doctest: +SKIP
'Invert weights of jaw_open'
"""

from __future__ import annotations

import numpy as np
from PySide6.QtWidgets import QMessageBox

from engine.errors import UserError
from engine.painting import (
    LEFT_TO_RIGHT,
    RIGHT_TO_LEFT,
    Change,
    clear_weights,
    group1_names,
    grow_weights,
    invert_weights,
    mirror_region,
    mirror_weights,
    normalise_group1,
    shrink_weights,
    smooth_weights,
    weight_change_from_dense,
)

from ..document.undo_commands import SetRegionCommand, WeightsChangedCommand
from .controller import NO_PARAMETER

SMOOTH_ITERATIONS = 3
RINGS = 1

# operation id → (menu text, what it does to the weights, undo text)
OPERATIONS = {
    "normalise": ("&Normalise group 1", "Scale the rigid (group-1) weights so they sum to 1 at every vertex"),
    "invert": ("&Invert", "Weight w becomes 1 − w"),
    "clear": ("&Clear", "Every weight becomes 0"),
    "mirror_left_to_right": ("Mirror &left → right", "Copy the subject's left side (+X) onto the right"),
    "mirror_right_to_left": ("Mirror &right → left", "Copy the subject's right side (−X) onto the left"),
    "smooth": ("&Smooth region", f"Blur the weights ({SMOOTH_ITERATIONS} passes)"),
    "grow": ("&Grow region", f"Extend the region by {RINGS} ring of neighbours"),
    "shrink": ("Shri&nk region", f"Pull the region's edge in by {RINGS} ring"),
}


def _new_weights(operation: str, ctx, weights: np.ndarray, part: str | None) -> np.ndarray:
    if operation == "invert":
        return invert_weights(ctx, weights, part=part)
    if operation == "clear":
        return clear_weights(ctx, weights, part=part)
    if operation == "smooth":
        return smooth_weights(ctx, weights, iterations=SMOOTH_ITERATIONS, part=part)
    if operation == "grow":
        return grow_weights(ctx, weights, rings=RINGS, part=part)
    if operation == "shrink":
        return shrink_weights(ctx, weights, rings=RINGS, part=part)
    if operation in ("mirror_left_to_right", "mirror_right_to_left"):
        return mirror_weights(ctx, weights, LEFT_TO_RIGHT if operation.endswith("left_to_right") else RIGHT_TO_LEFT)
    raise ValueError(f"unknown weight operation '{operation}' (known: {', '.join(OPERATIONS)})")


def run(controller, operation: str) -> bool:
    """Do ``operation`` on the selected parameter's weights; ``False`` (and a message) if nothing changed."""
    name = controller.parameter
    window, status = controller.window, controller.tools.status
    label = OPERATIONS[operation][0].replace("&", "")
    if name is None:
        status.showMessage(f"{label}: {NO_PARAMETER}")
        return False
    controller.release()                   # a stroke in progress is finished first
    try:
        if operation == "normalise":
            return _normalise(controller, name)
        document, ctx, dense = controller.document, controller.context(), controller.dense()
        if operation.startswith("mirror") and document.model.parameters[name].field:
            direction = LEFT_TO_RIGHT if operation.endswith("left_to_right") else RIGHT_TO_LEFT
            region = mirror_region(ctx, dense, direction).to_region()
            document.push(SetRegionCommand(document, name, region, text=f"{label} on {name}"))
            return True
        change = Change.between(dense.weights, _new_weights(operation, ctx, dense.weights, controller.brush.part))
        if not change:
            status.showMessage(f"{label}: the weights of {name} are already so; nothing changed", 4000)
            return False
        document.push(WeightsChangedCommand.from_change(document, name,
                                                        weight_change_from_dense(document.model, name, change),
                                                        text=f"{label} weights of {name}"))
    except UserError as error:
        QMessageBox.warning(window, f"Weights: {label}", str(error))
        return False
    status.showMessage(f"{label}: {len(change)} weight{'s' * (len(change) != 1)} of {name} changed",
                                   4000)
    return True


def _normalise(controller, name: str) -> bool:
    document = controller.document
    model = document.model
    keep = name if name in group1_names(model) else None
    regions = normalise_group1(model, keep=keep)
    changed = [n for n, region in regions.items()
               if not (np.array_equal(region.indices, model.regions[n].indices)
                       and region.weights.tobytes() == model.regions[n].weights.tobytes())]
    status = controller.tools.status
    if not changed:
        status.showMessage("Normalise group 1: the group-1 weights already sum to 1", 4000)
        return False
    stack = document.undo_stack
    stack.beginMacro("Normalise group-1 weights" + (f" (keeping {keep})" if keep else ""))
    try:
        for n in changed:
            document.push(SetRegionCommand(document, n, regions[n], text=f"Normalise {n}"))
    finally:
        stack.endMacro()
    status.showMessage(f"Normalise group 1: {len(changed)} region{'s' * (len(changed) != 1)} changed",
                                   4000)
    return True

