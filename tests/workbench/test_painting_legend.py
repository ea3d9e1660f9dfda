"""Issue 30 §4: while painting, the heat map lies on the face as it is posed and keeps its shape readable,
and the viewport shows a legend: the colour bar of the weights, 0 … 1, with the painted parameter's name.

A laptop-sized window on the default head; paint mode with its key (Ctrl+Shift+P), the live preview with a
mouse click on its check box, the jaw held open at 100 %.
"""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt

import engine
from engine.painting import DenseRegion
from tests.workbench.test_rough_edges_gallery import CTRL, SHIFT, choose_layout, press
from tests.workbench.test_task_layouts import LAPTOP

DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built")


@pytest.fixture
def painting(make_window, qtbot):
    """Painting jaw_open, held fully open (Live preview)."""
    window = make_window(DEFAULT_HEAD, size=(LAPTOP.width(), LAPTOP.height()))
    choose_layout(qtbot, window, "painting")
    window.view_state.select_parameter("jaw_open")              # its row in the parameter tree
    press(qtbot, window, Qt.Key.Key_P, CTRL | SHIFT)            # Weights → Paint weights
    assert window.paint.active
    window.paint.set_hold(fraction=1.0)
    hold = window.paint_options.hold
    if not hold.isChecked():
        qtbot.mouseClick(hold, Qt.MouseButton.LeftButton)
    assert hold.isChecked() and window.document.value("jaw_open") == pytest.approx(1.0)
    window.viewport.render_now()
    return window


def rendered(window) -> np.ndarray:
    window.viewport.render_now()
    image = window.viewport.plotter.grab().toImage()
    image = image.convertToFormat(image.Format.Format_RGB888)
    raw = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    return raw.reshape(image.height(), image.bytesPerLine())[:, :3 * image.width()].reshape(
        image.height(), image.width(), 3).astype(int)


def test_the_heat_map_lies_on_the_posed_face_and_keeps_its_shape_readable(painting):
    window = painting
    viewport, model = window.viewport, window.document.model
    shown = viewport.displayed_points()
    drawn = ~np.isnan(shown[:, 0])
    np.testing.assert_allclose(shown[drawn], window.document.vertices()[drawn], atol=1e-4)   # the jaw held open
    assert not np.allclose(shown[drawn], model.vertices[drawn], atol=0.5)                  # not the rest mesh
    weights = DenseRegion.from_model(model, "jaw_open").weights
    colors = viewport.displayed_colors().astype(float)
    base = viewport.base_colors().astype(float)
    full = weights >= 0.999
    light = base[full] @ [0.299, 0.587, 0.114]
    indices = np.flatnonzero(full)
    assert light.max() - light.min() > 60, "the jaw region holds skin, lips and the mouth's inside"
    bright, dark = indices[light >= np.percentile(light, 90)], indices[light <= np.percentile(light, 10)]
    # One weight, one hue, but the lips and the inside of the open mouth stay darker than the chin's skin:
    # the opening is to be seen (a flat heat map drew them all one red).
    assert colors[dark].sum(axis=1).mean() < 0.8 * colors[bright].sum(axis=1).mean()
    reds = colors[full]
    assert (reds[:, 0] > reds[:, 2]).all(), "weight 1 is still red"
    outside = weights == 0
    assert np.array_equal(colors[outside], base[outside]), "outside the region: the face's own colours"


def test_a_legend_of_the_weights_is_in_the_viewport_while_painting(painting, qtbot):
    window = painting
    picture = rendered(window)
    width = picture.shape[1]
    right = picture[:, int(0.78 * width):]               # the legend's strip at the right edge
    red = (right[..., 0] > 170) & (right[..., 1] < 90) & (right[..., 2] < 70)
    blue = (right[..., 2] > 170) & (right[..., 0] < 110)
    assert red.sum() > 50 and blue.sum() > 50, "no colour bar drawn"
    assert np.nonzero(red)[0].mean() < np.nonzero(blue)[0].mean(), "1 (red) at the top, 0 (blue) at the bottom"
    legend = window.paint.legend
    assert legend.visible and legend.title == "jaw_open"
    table = legend.actor.GetLookupTable()
    assert tuple(table.GetRange()) == (0.0, 1.0) and legend.actor.GetNumberOfLabels() == 3

    window.view_state.select_parameter("lower_lip_raise")          # another parameter: its name
    assert legend.visible and legend.title == "lower_lip_raise"
    press(qtbot, window, Qt.Key.Key_P, CTRL | SHIFT)                # paint mode off: the legend goes
    assert not window.paint.active and not legend.visible
    after = rendered(window)[:, int(0.78 * width):]
    assert ((after[..., 0] > 170) & (after[..., 1] < 90) & (after[..., 2] < 70)).sum() < red.sum() / 10


def test_after_a_stroke_and_its_undo_the_tools_heat_map_is_shown_again(painting, qtbot):
    window = painting
    paint, viewport = window.paint, window.viewport
    plotter = viewport.plotter
    y = int(plotter.height() * 0.62)
    paint.press(int(plotter.width() * 0.45), y)
    paint.drag(int(plotter.width() * 0.55), y)
    paint.release()
    assert window.document.undo_stack.undoText().startswith("Paint")
    assert np.array_equal(viewport.displayed_colors(), paint.heat_map())
    press(qtbot, window, Qt.Key.Key_Z, CTRL)                         # Edit → Undo
    assert np.array_equal(viewport.displayed_colors(), paint.heat_map())
