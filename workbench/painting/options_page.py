"""The weight-paint tool's page in the Tool options dock, bound to the controller's engine Brush.

Every control writes one field of the :class:`~engine.painting.Brush` (via
:meth:`PaintController.set_brush`) or the tool / held value, and follows the
controller's signals back, so the eyedropper or the ``[`` / ``]`` keys show
up here at once.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDoubleSpinBox,
    QFormLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QSlider,
    QVBoxLayout,
    QWidget,
)

from engine.painting import FALLOFFS

from .controller import TOOLS, PaintController

TOOL_LABELS = {"add": "Add", "subtract": "Subtract", "set": "Set (replace)", "smooth": "Smooth (blur)",
               "gradient": "Gradient (drag start → end)", "sample": "Sample weight (eyedropper)"}
ALL_PARTS = "All parts"
SLIDER_STEPS = 1000


class SpinSlider(QWidget):
    """A slider and a spin box showing one number; ``spin.valueChanged`` is the one signal to use."""

    def __init__(self, low: float, high: float, decimals: int, suffix: str = "", parent=None):
        super().__init__(parent)
        self._low, self._high = low, high
        self.slider = QSlider(Qt.Orientation.Horizontal)
        self.slider.setRange(0, SLIDER_STEPS)
        self.spin = QDoubleSpinBox()
        self.spin.setRange(low, high)
        self.spin.setDecimals(decimals)
        self.spin.setSingleStep(10 ** -decimals * (10 if decimals else 1))
        self.spin.setSuffix(suffix)
        self.spin.setKeyboardTracking(False)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.slider, 1)
        layout.addWidget(self.spin)
        self.slider.valueChanged.connect(self._from_slider)
        self.spin.valueChanged.connect(self._to_slider)

    def set_value(self, value: float) -> None:
        self.spin.blockSignals(True)
        self.spin.setValue(value)
        self.spin.blockSignals(False)
        self._to_slider(self.spin.value())

    def _from_slider(self, position: int) -> None:
        self.spin.setValue(self._low + (self._high - self._low) * position / SLIDER_STEPS)

    def _to_slider(self, value: float) -> None:
        self.slider.blockSignals(True)
        self.slider.setValue(round((value - self._low) / (self._high - self._low) * SLIDER_STEPS))
        self.slider.blockSignals(False)


class PaintOptionsPage(QWidget):
    """Brush, restrictions and live preview for :class:`PaintController` ``controller``."""

    def __init__(self, controller: PaintController, parent=None):
        super().__init__(parent)
        self.controller = controller
        self.title = QLabel()
        self.title.setWordWrap(True)
        self.tool = QComboBox()
        for tool in TOOLS:
            self.tool.addItem(TOOL_LABELS[tool], tool)
        self.value = SpinSlider(0.0, 1.0, 3)
        self.radius = SpinSlider(0.5, 100.0, 1, " mm")
        self.strength = SpinSlider(0.0, 1.0, 2)
        self.falloff = QComboBox()
        for name in FALLOFFS:
            self.falloff.addItem(name.capitalize(), name)
        self.mirror = QCheckBox("X-mirror (paint both sides)")
        self.mirror_info = QLabel()
        self.mirror_info.setWordWrap(True)
        self.mirror_info.setEnabled(False)
        self.mirror_info.hide()             # shown with the mirror map's statistics, while X-mirror is on
        self.front_only = QCheckBox("Front faces only")
        self.connected = QCheckBox("Connected surface only")
        self.connected.setToolTip("Reach only surface joined to the point under the mouse: no jumping gaps "
                                  "such as the lips")
        self.part = QComboBox()
        self.hold = QCheckBox("Hold the parameter at")
        self.hold_value = SpinSlider(0.0, 100.0, 0, " %")
        self.hold_label = QLabel()
        self.hold_label.setWordWrap(True)     # its text names the parameter: it must not widen the dock
        self.hold_label.setEnabled(False)

        brush = QFormLayout()
        brush.addRow("Tool", self.tool)
        brush.addRow("Weight", self.value)
        brush.addRow("Radius", self.radius)
        brush.addRow("Strength", self.strength)
        brush.addRow("Falloff", self.falloff)
        where = QGroupBox("Where it paints")
        where_layout = QFormLayout(where)
        where_layout.addRow("Part", self.part)
        where_layout.addRow(self.front_only)
        where_layout.addRow(self.connected)
        where_layout.addRow(self.mirror)
        where_layout.addRow(self.mirror_info)
        live = self.live_preview = QGroupBox("Live preview")
        live_layout = QFormLayout(live)
        live_layout.addRow(self.hold, self.hold_value)
        live_layout.addRow(self.hold_label)
        # Live preview before "Where it paints": on a laptop's screen it is on show without scrolling.
        layout = QVBoxLayout(self)
        layout.setSpacing(4)
        layout.addWidget(self.title)
        layout.addLayout(brush)
        layout.addWidget(live)
        layout.addWidget(where)
        layout.addStretch(1)

        self.tool.currentIndexChanged.connect(lambda _i: controller.set_tool(self.tool.currentData()))
        self.value.spin.valueChanged.connect(lambda v: controller.set_brush(value=v))
        self.radius.spin.valueChanged.connect(lambda v: controller.set_brush(radius=v))
        self.strength.spin.valueChanged.connect(lambda v: controller.set_brush(strength=v))
        self.falloff.currentIndexChanged.connect(lambda _i: controller.set_brush(falloff=self.falloff.currentData()))
        self.mirror.toggled.connect(self._on_mirror)
        self.front_only.toggled.connect(lambda on: controller.set_brush(front_faces_only=on))
        self.connected.toggled.connect(lambda on: controller.set_brush(connected=on))
        self.part.currentIndexChanged.connect(lambda _i: controller.set_brush(part=self.part.currentData()))
        self.hold.toggled.connect(lambda on: controller.set_hold(enabled=on))
        self.hold_value.spin.valueChanged.connect(lambda v: controller.set_hold(fraction=v / 100.0))

        controller.brush_changed.connect(self._show_brush)
        controller.tool_changed.connect(self._show_tool)
        controller.hold_changed.connect(self._show_hold)
        controller.active_changed.connect(self._show_title)
        document, view_state = controller.document, controller.view_state
        document.model_replaced.connect(self._fill_parts)
        document.values_changed.connect(self._show_hold)
        view_state.selected_parameter_changed.connect(self._show_title)
        self._fill_parts()
        self._show_brush(controller.brush)
        self._show_tool(controller.tool)
        self._show_hold()
        self._show_title()

    # -- controller → widgets ----------------------------------------------------
    def _show_brush(self, brush) -> None:
        for widget in (self.falloff, self.mirror, self.front_only, self.connected, self.part):
            widget.blockSignals(True)
        self.value.set_value(brush.value)
        self.radius.set_value(brush.radius)
        self.strength.set_value(brush.strength)
        if isinstance(brush.falloff, str):
            self.falloff.setCurrentIndex(self.falloff.findData(brush.falloff))
        self.mirror.setChecked(brush.mirror)
        self.front_only.setChecked(brush.front_faces_only)
        self.connected.setChecked(brush.connected)
        index = self.part.findData(brush.part)
        self.part.setCurrentIndex(max(index, 0))
        for widget in (self.falloff, self.mirror, self.front_only, self.connected, self.part):
            widget.blockSignals(False)

    def _show_tool(self, tool: str) -> None:
        self.tool.blockSignals(True)
        self.tool.setCurrentIndex(self.tool.findData(tool))
        self.tool.blockSignals(False)
        self.value.setEnabled(tool in ("add", "subtract", "set", "gradient"))
        self.strength.setEnabled(tool != "sample")

    def _show_hold(self, *_args) -> None:
        c = self.controller
        self.hold.blockSignals(True)
        self.hold.setChecked(c.hold_enabled)
        self.hold.blockSignals(False)
        self.hold_value.set_value(c.hold_fraction * 100.0)
        name, value = c.parameter, c.hold_value()
        if name is None:
            self.hold_label.setText("No parameter selected")
        else:
            self.hold_label.setText(f"{name} = {value:.3f} (of its range {c.document.model.parameters[name].minimum:g}"
                                    f" … {c.document.model.parameters[name].maximum:g}); "
                                    "the mesh moves with every dab")

    def _show_title(self, *_args) -> None:
        name = self.controller.parameter
        self.title.setText(f"<b>Painting the weights of {name}</b>" if name else
                           "<b>No parameter selected</b> — select one in the Parameters dock")
        self._show_hold()

    def _fill_parts(self, *_args) -> None:
        self.part.blockSignals(True)
        self.part.clear()
        self.part.addItem(ALL_PARTS, None)
        for part in self.controller.document.model.parts:
            self.part.addItem(part, part)
        self.part.blockSignals(False)
        if self.controller.brush.part not in self.controller.document.model.parts:
            self.controller.set_brush(part=None)
        self._show_brush(self.controller.brush)

    def _on_mirror(self, on: bool) -> None:
        self.controller.set_brush(mirror=on)
        if on:
            ctx = self.controller.context()
            self.mirror_info.setText("Mirror map: " + ctx.mirror.summary(ctx.parts, ctx.vertex_part))
        else:
            self.mirror_info.clear()
        self.mirror_info.setVisible(on)
