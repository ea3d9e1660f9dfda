"""Weight painting in the workbench (§2.2.2): the GUI over :mod:`engine.painting`.

``install(context)`` adds

* ``window.paint`` — the :class:`~workbench.painting.controller.PaintController`
  (paint mode, mouse strokes, brush cursor, live preview);
* the "paint" page of the Tool options dock
  (:class:`~workbench.painting.options_page.PaintOptionsPage`);
* the **Weights** menu: *Paint weights* (checkable, Ctrl+Shift+P, also on the
  toolbar), smaller / larger brush (``[`` / ``]``), and the whole-region
  operations of :mod:`workbench.painting.operations`.

User documentation: ``docs/workbench-painting.md``.
"""

from __future__ import annotations

from ..tools import ToolContext
from ..window.actions import ActionSpec
from . import launch_probe, operations
from .controller import PaintController
from .options_page import PaintOptionsPage

PAINT_SHORTCUT = "Ctrl+Shift+P"
RADIUS_STEP = 1.25          # [ and ] scale the radius by this factor
MENU = "&Weights"


def _scale_radius(window, factor: float) -> None:
    paint = window.paint
    paint.set_brush(radius=min(max(paint.brush.radius * factor, 0.5), 100.0))
    paint.tools.status.showMessage(f"Brush radius {paint.brush.radius:.1f} mm", 2000)


def _specs() -> tuple[ActionSpec, ...]:
    specs = [
        ActionSpec("paint.mode", "&Paint weights", MENU, toggled=lambda w, on: w.paint.set_active(on),
                   shortcut=PAINT_SHORTCUT, icon="paint-weights", toolbar=True, separator_before=True,
                   tip="Paint the selected parameter's weights with the mouse (Alt+drag orbits)"),
        ActionSpec("paint.smaller", "S&maller brush", MENU, triggered=lambda w: _scale_radius(w, 1 / RADIUS_STEP),
                   shortcut="[", icon="brush-smaller", tip="Make the brush radius smaller"),
        ActionSpec("paint.larger", "L&arger brush", MENU, triggered=lambda w: _scale_radius(w, RADIUS_STEP),
                   shortcut="]", icon="brush-larger", tip="Make the brush radius larger"),
    ]
    for k, (operation, (text, tip)) in enumerate(operations.OPERATIONS.items()):
        specs.append(ActionSpec(f"weights.{operation}", text, MENU,
                                triggered=lambda w, op=operation: operations.run(w.paint, op),
                                separator_before=k in (0, 1, 3, 5), tip=tip,
                                icon="weights-" + operation.replace("_", "-")))
    return tuple(specs)


def install(context: ToolContext) -> None:
    """Add weight painting to the context's window (see the module docstring)."""
    window = context.window
    window.paint = paint = PaintController(context)
    window.paint_options = options = PaintOptionsPage(paint)
    context.tool_options.add_page("paint", options)
    context.add_actions(_specs())
    launch_probe.install(context)
