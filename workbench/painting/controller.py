"""The weight-paint tool: mouse strokes on the viewport drive the engine's stroke, one undo step per stroke.

:class:`PaintController` is the tool's state (the engine :class:`~engine.painting.Brush`,
the tool — a brush mode, ``"gradient"`` or ``"sample"`` —, the held value)
and its mouse handling. While paint mode is on it filters the viewport's
mouse events: the left button paints, Ctrl+left-click samples the weight
under the cursor, Alt+left-drag orbits (VTK's own camera interaction, as do
the middle button and the wheel). Tests drive it with :meth:`press`,
:meth:`drag` and :meth:`release` in widget coordinates — exactly what the
event filter calls.

The stroke itself is the engine's :class:`~engine.painting.PaintStroke`: a
pick on the drawn mesh is mapped to the rest mesh
(:func:`~engine.painting.rest_point`), and :meth:`PaintStroke.to
<engine.painting.PaintStroke.to>` (dabs along the drag) or
:meth:`~engine.painting.PaintStroke.gradient_to` paints the dense weights.
This module only recolours the changed vertices (and moves them, with the
live preview), draws the cursor, and on release pushes the stroke's
:class:`~engine.model.WeightChange` as one
:class:`~workbench.document.undo_commands.WeightsChangedCommand`.

While paint mode is on the viewport shows the tool's own heat map
(:func:`~workbench.painting.shading.shaded_heat_colors`, through
:meth:`Viewport.show_colors <workbench.viewport.view.Viewport.show_colors>`) on
the mesh as it is posed — the held parameter's deformation stays readable
— and a legend of it (:class:`~workbench.painting.cursor.WeightLegend`).

>>> paint = window.paint                               # doctest: +SKIP
>>> window.view_state.select_parameter("jaw_open")     # doctest: +SKIP
>>> paint.set_active(True)                             # doctest: +SKIP
>>> paint.press(400, 300); paint.drag(440, 300); paint.release(440, 300)   # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QEvent, QObject, Qt, Signal
from PySide6.QtWidgets import QApplication, QMessageBox

from engine.errors import UserError
from engine.painting import (
    MODES,
    Brush,
    Change,
    DenseRegion,
    LivePreview,
    PaintContext,
    PaintStroke,
    mirrored_points,
    mirrored_vectors,
    rest_point,
    sample_weight,
)

from ..document.undo_commands import WeightsChangedCommand
from .cursor import BrushCursor, WeightLegend
from .shading import shaded_heat_colors

if TYPE_CHECKING:
    from ..tools import ToolContext

TOOLS = (*MODES, "gradient", "sample")
NO_PARAMETER = "Select a parameter in the Parameters dock to paint its weights"
HELP = ("left-drag paints · Ctrl+click samples · Alt+left-drag orbits · middle-drag pans · wheel zooms · "
        "[ and ] change the radius")


class PaintController(QObject):
    """Paint mode of one main window (``window.paint``).

    Signals: ``active_changed(bool)``, ``brush_changed(object)`` (the new
    :class:`Brush`), ``tool_changed(str)``, ``hold_changed()``.
    """

    active_changed = Signal(bool)
    brush_changed = Signal(object)
    tool_changed = Signal(str)
    hold_changed = Signal()

    def __init__(self, context: ToolContext):
        super().__init__(context.window)
        self.tools = context                  # the window's ToolContext (self.context() is the stroke's)
        self.window = context.window          # the parent of its dialogs
        self.document, self.view_state, self.viewport = context.document, context.view_state, context.viewport
        self.brush = Brush("add", radius=10.0, strength=0.5, falloff="smooth", front_faces_only=True)
        self.tool = "add"
        self.hold_enabled, self.hold_fraction = False, 1.0
        self._active = False
        self._ctx: PaintContext | None = None
        self._dense: DenseRegion | None = None
        self._dense_name: str | None = None
        self._held: tuple[object, str, float] | None = None   # (model, parameter, value before it was held)
        self._pressed = False
        self._stroke: PaintStroke | None = None
        self._live: LivePreview | None = None
        self._gradient_start: np.ndarray | None = None      # where the gradient began on the drawn mesh
        self.cursor = BrushCursor(self.viewport.plotter)
        self.legend = WeightLegend(self.viewport.plotter)
        self.viewport.plotter.installEventFilter(self)
        self.document.model_replaced.connect(self._on_model_replaced)
        self.document.regions_changed.connect(self._on_weights_edited)
        self.document.parameters_changed.connect(self._on_weights_edited)
        self.document.values_changed.connect(self._forget_preview)
        self.view_state.selected_parameter_changed.connect(self._on_selection_changed)

    # -- state ---------------------------------------------------------------
    @property
    def active(self) -> bool:
        return self._active

    @property
    def parameter(self) -> str | None:
        """The parameter being painted: the selected one, if it exists."""
        name = self.view_state.selected_parameter
        return name if name is not None and name in self.document.model.parameters else None

    def context(self) -> PaintContext:
        """The engine's topology of the current mesh, built on first use (once per model)."""
        if self._ctx is None:
            QApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
            try:
                self._ctx = PaintContext(self.document.model)
            finally:
                QApplication.restoreOverrideCursor()
        return self._ctx

    def dense(self) -> DenseRegion:
        """The painted parameter's weights, dense (one per vertex); what strokes paint into."""
        name = self.parameter
        if name is None:
            raise UserError(NO_PARAMETER)
        if self._dense is None or self._dense_name != name:
            self._dense, self._dense_name = DenseRegion.from_model(self.document.model, name), name
        return self._dense

    def set_brush(self, **changes) -> None:
        """Change brush settings (``radius=``, ``strength=``, ``falloff=``, ``value=``, ``part=``, …)."""
        brush = dataclasses.replace(self.brush, **changes)
        if brush != self.brush:
            self.brush = brush
            if self._stroke is not None:
                self._stroke.brush = brush
            self.brush_changed.emit(brush)

    def set_tool(self, tool: str) -> None:
        """``add``, ``subtract``, ``set``, ``smooth`` (brush modes), ``gradient`` or ``sample``."""
        if tool not in TOOLS:
            raise ValueError(f"unknown paint tool '{tool}' (tools: {', '.join(TOOLS)})")
        if tool in MODES:
            self.set_brush(mode=tool)
        if tool != self.tool:
            self.tool = tool
            self.tool_changed.emit(tool)

    def set_hold(self, enabled: bool | None = None, fraction: float | None = None) -> None:
        """Live preview: hold the painted parameter at ``fraction`` of its range (0 = minimum, 1 = maximum)."""
        if enabled is not None:
            self.hold_enabled = bool(enabled)
        if fraction is not None:
            self.hold_fraction = min(max(float(fraction), 0.0), 1.0)
        if self._active:
            self._apply_hold()
        self.hold_changed.emit()

    def hold_value(self, name: str | None = None) -> float | None:
        name = name or self.parameter
        if name is None:
            return None
        p = self.document.model.parameters[name]
        return p.minimum + self.hold_fraction * (p.maximum - p.minimum)

    # -- paint mode ----------------------------------------------------------
    def set_active(self, on: bool) -> bool:
        """Enter or leave paint mode; refuses (returns ``False``, says why) with no parameter selected."""
        on = bool(on)
        if on and not self._active:
            if self.parameter is None:
                self._say(NO_PARAMETER)
                self._sync_action(False)
                return False
            self.context()
            self._active = True
            self.view_state.set_heat_map(True)
            self._show_heat_map()
            self.tools.tool_options.show_page("paint")
            self.tools.tool_options.show()
            self._apply_hold()
            self._say_painting()
        elif not on and self._active:
            self.release()
            self._active = False
            self._restore_hold()
            self.cursor.hide()
            self.legend.hide()
            self.viewport.show_colors(None)          # the viewport's own colours again
            self.viewport.plotter.update()
            self.tools.tool_options.show_page()
            self._say("Weight painting off")
        self._sync_action(self._active)
        self.active_changed.emit(self._active)
        return self._active == on

    def _sync_action(self, on: bool) -> None:
        action = self.tools.actions.get("paint.mode")
        if action is not None and action.isChecked() != on:
            action.blockSignals(True)
            action.setChecked(on)
            action.blockSignals(False)

    # -- mouse ---------------------------------------------------------------
    def eventFilter(self, watched, event) -> bool:
        if not self._active:
            return False
        kind = event.type()
        if kind == QEvent.Type.MouseButtonPress and event.button() == Qt.MouseButton.LeftButton:
            if event.modifiers() & Qt.KeyboardModifier.AltModifier:
                return False                                  # Alt+left: the camera's
            pos = event.position()
            self.press(pos.x(), pos.y(), sample=bool(event.modifiers() & Qt.KeyboardModifier.ControlModifier))
            return True
        if kind == QEvent.Type.MouseMove:
            pos = event.position()
            if self._pressed:
                self.drag(pos.x(), pos.y())
                return True
            self.hover(pos.x(), pos.y())
            return False
        if kind == QEvent.Type.MouseButtonRelease and event.button() == Qt.MouseButton.LeftButton and self._pressed:
            self.release()
            return True
        if kind == QEvent.Type.Leave:
            self.cursor.hide()
            self.viewport.plotter.update()
        return False

    def hover(self, x: float, y: float) -> None:
        """Mouse moved with no button: the brush cursor follows."""
        self._place_cursor(self._hit(x, y))

    def press(self, x: float, y: float, sample: bool = False) -> None:
        """Left button down at widget pixel (x, y): a stroke (or gradient) starts; ``sample``: eyedropper."""
        if not self._active:
            return
        self._pressed = True
        self.viewport.set_fast_rendering(True)
        hit = self._hit(x, y)
        self._place_cursor(hit)
        if hit is None:
            return
        if sample or self.tool == "sample":
            self._pressed = False
            self.viewport.set_fast_rendering(False)
            self.sample_at(hit[1])
        elif self.tool == "gradient":
            self._begin_stroke().gradient_to(hit[1], **self.view())
            self._gradient_start = hit[0].point
        else:
            self._show_weights(self._begin_stroke().to(hit[1], **self.view()).indices)

    def drag(self, x: float, y: float) -> None:
        """Mouse moved with the button down: dabs along the way (or the gradient follows)."""
        if not self._pressed:
            return self.hover(x, y)
        hit = self._hit(x, y)
        self._place_cursor(hit)
        if hit is None:
            return
        if self.tool == "gradient":
            if self._gradient_start is not None and self._stroke is not None:
                self._show_weights(self._stroke.gradient_to(hit[1], **self.view()).indices)
                self.cursor.show_line(self._gradient_start, hit[0].point)
        elif self.tool in MODES:
            self._show_weights(self._begin_stroke().to(hit[1], **self.view()).indices)

    def release(self, *_pos) -> None:
        """Button up: the stroke becomes one undo step."""
        self._pressed = False
        self.viewport.set_fast_rendering(False)
        stroke, self._stroke = self._stroke, None
        self._live, self._gradient_start = None, None
        self.cursor.hide_line()
        if stroke is None:
            return
        change = stroke.finish()
        if not change:
            return
        name = stroke.name
        verb = "Gradient on" if self.tool == "gradient" else "Paint"
        try:
            self.document.push(WeightsChangedCommand.from_change(self.document, name, change, text=f"{verb} {name}"))
        except UserError as error:
            self._show_weights(stroke.cancel().indices)
            QMessageBox.warning(self.window, "Weight painting", str(error))

    def sample_at(self, rest_point) -> float:
        """Eyedropper: the weight at ``rest_point`` becomes the brush's value (the Set brush paints it)."""
        value = sample_weight(self.context(), self.dense().weights, rest_point, part=self.brush.part)
        self.set_brush(value=float(np.clip(value, 0.0, 1.0)))
        if self.tool == "sample":
            self.set_tool("set")
        self._say(f"Sampled weight {value:.3f}: the Set brush now paints it")
        return value

    # -- painting ------------------------------------------------------------
    def _hit(self, x: float, y: float):
        """(pick on the drawn mesh, the same point on the rest mesh) under the pixel, or ``None``."""
        found = self.viewport.pick_cell(x, y)
        if found is None:
            return None
        hit, vertices, weights = found
        return hit, rest_point(self.document.model, vertices, weights)

    def view(self) -> dict:
        """The camera as the engine's brushes take it: ``{"view_direction": …}`` for a parallel
        projection, else ``{"camera_position": …}`` (rest-mesh mm)."""
        camera = self.viewport.plotter.camera
        if camera.parallel_projection:
            direction = np.subtract(camera.focal_point, camera.position)
            return {"view_direction": direction / np.linalg.norm(direction)}
        return {"camera_position": np.asarray(camera.position, dtype=float)}

    def _begin_stroke(self) -> PaintStroke:
        if self._stroke is None:
            dense = self.dense()
            self._stroke = PaintStroke(self.document.model, self._dense_name, self.brush, self.context(),
                                       dense=dense)
            if not self.document.is_at_rest():
                self._live = LivePreview(self.document.model, self._dense_name, dense, self.document.values)
        return self._stroke

    def dab(self, point) -> Change:
        """One dab of the brush at rest-mesh ``point`` (mm) into the current stroke; shows it."""
        change = self._begin_stroke().dab(point, **self.view())
        self._show_weights(change.indices)
        return change

    def heat_map(self) -> np.ndarray:
        """(N, 3) uint8: the painted parameter's weights as paint mode shows them (see :mod:`.shading`)."""
        return shaded_heat_colors(self.dense().weights, self.viewport.base_colors())

    def _show_heat_map(self) -> None:
        """Every vertex in the tool's heat map, and the legend, for the parameter painted."""
        self.viewport.show_colors(self.heat_map())
        self.legend.show(self.parameter)

    def _show_weights(self, indices) -> None:
        """Recolour (and with the live preview, move) only these vertices."""
        indices = np.asarray(indices, dtype=np.int64)
        if len(indices) == 0:
            return
        weights = self._dense.weights[indices]
        self.viewport.update_colors(indices, shaded_heat_colors(weights, self.viewport.base_colors()[indices]))
        if self._live is not None:
            self.viewport.update_points(indices, self._live.update(indices))

    def _place_cursor(self, hit) -> None:
        if hit is None:
            self.cursor.hide()
        else:
            pick = hit[0]
            mirror = normal = None
            if self.brush.mirror:
                center = self.context().mirror.center
                mirror, normal = mirrored_points(pick.point, center), mirrored_vectors(pick.normal)
            self.cursor.place(pick.point, pick.normal, self.brush.radius, mirror, normal)
        self.viewport.plotter.update()

    # -- held value (live preview) -----------------------------------------------
    def _apply_hold(self) -> None:
        name = self.parameter
        if self._held is not None and (not self.hold_enabled or self._held[1] != name):
            self._restore_hold()
        if self.hold_enabled and name is not None:
            if self._held is None:
                self._held = (self.document.model, name, self.document.value(name))
            self.document.set_value(name, self.hold_value(name))

    def _restore_hold(self) -> None:
        held, self._held = self._held, None
        if held is not None and held[0] is self.document.model and held[1] in self.document.model.parameters:
            self.document.set_value(held[1], held[2])

    # -- listeners -----------------------------------------------------------
    def _on_weights_edited(self, _names=None) -> None:
        """A stroke pushed, an undo, a redo, an operation, a renamed parameter: show the model's weights."""
        self._forget_weights()
        if self._active and self._stroke is None and self.parameter is not None:
            self._show_heat_map()

    def _forget_weights(self, _names=None) -> None:
        if self._stroke is None:
            self._dense = None
        self._live = None

    def _forget_preview(self, _names=None) -> None:
        if self._stroke is None:
            self._live = None

    def _on_model_replaced(self, _model) -> None:
        self._stroke, self._pressed, self._gradient_start, self._held = None, False, None, None
        self._ctx, self._dense, self._live = None, None, None

    def _on_selection_changed(self, _name) -> None:
        if not self._active:
            return
        self.release()
        if self.parameter is None:
            self.set_active(False)
            self._say(f"Weight painting stopped: no parameter selected. {NO_PARAMETER}")
            return
        self._apply_hold()
        self._show_heat_map()
        self._say_painting()

    def _say_painting(self) -> None:
        self._say(f"Painting the weights of {self.parameter}: {HELP}")

    def _say(self, message: str) -> None:
        self.tools.status.showMessage(message)
