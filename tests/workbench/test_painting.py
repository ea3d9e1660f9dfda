"""Weight painting in the real window: strokes, brushes, restrictions, undo, live preview (issue 7).

Strokes are driven through the same methods the viewport's mouse events call
(``press``/``drag``/``release`` with widget pixels from
``viewport.world_to_widget``); one test goes through real Qt mouse events.
Expected weights come from the engine functions themselves
(:func:`engine.painting.compute_dab`, :class:`~engine.painting.Stroke`).
"""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest

from engine.painting import Brush, DenseRegion, Stroke, compute_dab, compute_gradient
from workbench_model_state import model_state


@pytest.fixture(autouse=True)
def _painting_only(monkeypatch):
    """Install only this tool: other tools are tested on their own (and may be mid-edit in a shared tree)."""
    from workbench import features

    monkeypatch.setattr(features, "INSTALLERS", ["painting:install"])


def dense(window, name):
    return DenseRegion.from_model(window.document.model, name).weights


def rest_vertex(window, near):
    """Index of the skin vertex nearest ``near`` (mm) on the front of the synthetic head."""
    model = window.document.model
    skin = np.flatnonzero(model.vertex_part == model.parts.index("skin"))
    return int(skin[np.argmin(np.linalg.norm(model.vertices[skin] - near, axis=1))])


def pixel_of(window, point):
    window.viewport.render_now()
    return window.viewport.world_to_widget(point)


def start_painting(window, name="jaw_open", **brush):
    window.view_state.select_parameter(name)
    window.actions_by_id["paint.mode"].trigger()
    paint = window.paint
    assert paint.active
    paint.set_brush(**brush)
    window.viewport.render_now()
    return paint


def record_dabs(monkeypatch, paint):
    """Wrap ``paint.dab`` so the test knows each dab's rest point."""
    points = []
    original = paint.dab

    def dab(point):
        points.append(np.array(point, dtype=float))
        return original(point)

    monkeypatch.setattr(paint, "dab", dab)
    return points


def test_paint_mode_refuses_without_a_selected_parameter(window):
    action = window.actions_by_id["paint.mode"]
    action.trigger()
    assert not window.paint.active and not action.isChecked()
    assert "Select a parameter" in window.statusBar().currentMessage()
    window.view_state.select_parameter("jaw_open")
    action.trigger()
    assert window.paint.active and action.isChecked()
    assert window.tool_options.current_tool == "paint"
    assert "Alt+left-drag orbits" in window.statusBar().currentMessage()
    window.view_state.select_parameter(None)                     # deselecting stops painting
    assert not window.paint.active and not action.isChecked()
    assert "no parameter selected" in window.statusBar().currentMessage()


def test_one_dab_changes_exactly_what_compute_dab_predicts(window):
    paint = start_painting(window, radius=20.0, strength=0.4, mode="add")
    before = dense(window, "jaw_open")
    target = window.document.model.vertices[rest_vertex(window, (10, -40, 80))]
    x, y = pixel_of(window, target)
    hit = paint._hit(x, y)
    assert hit is not None
    expected = compute_dab(paint.context(), before, paint.brush, hit[1], **paint._view())
    assert len(expected) > 3
    stack = window.document.undo_stack
    count = stack.count()
    paint.press(x, y)
    paint.release(x, y)
    after = dense(window, "jaw_open")
    changed = np.flatnonzero(before.view(np.uint64) != after.view(np.uint64))
    assert np.array_equal(changed, expected.indices)
    assert np.array_equal(after[expected.indices], expected.after)
    assert stack.count() == count + 1


def test_a_stroke_is_the_engine_stroke_and_one_undo_step_restored_bit_for_bit(window, monkeypatch):
    paint = start_painting(window, radius=12.0, strength=0.3, mode="add", falloff="linear")
    model = window.document.model
    before_state = model_state(model)
    before = dense(window, "jaw_open")
    points = record_dabs(monkeypatch, paint)
    a = model.vertices[rest_vertex(window, (-35, -40, 70))]
    b = model.vertices[rest_vertex(window, (35, -40, 70))]
    (xa, ya), (xb, yb) = pixel_of(window, a), pixel_of(window, b)
    stack = window.document.undo_stack
    count = stack.count()
    paint.press(xa, ya)
    for t in np.linspace(0, 1, 8)[1:]:
        paint.drag(xa + t * (xb - xa), ya + t * (yb - ya))
    paint.release(xb, yb)
    assert stack.count() == count + 1, "one stroke must be one undo step"
    # Dabs are spaced a quarter of the radius apart along the stroke.
    gaps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    assert len(points) >= 15 and np.allclose(gaps, 0.25 * 12.0)
    replay = before.copy()
    stroke = Stroke(replay)
    for p in points:
        stroke.dab(paint.context(), paint.brush, p, **paint._view())
    after = dense(window, "jaw_open")
    assert after.tobytes() == replay.tobytes()
    painted_state = model_state(model)
    assert painted_state != before_state
    window.undo()
    assert model_state(model) == before_state
    window.redo()
    assert model_state(model) == painted_state
    # The viewport shows the model's weights again after undo/redo.
    assert np.array_equal(window.viewport.displayed_colors(), window.viewport.heat_map_colors("jaw_open"))


def test_real_mouse_events_paint_and_alt_drag_does_not(window):
    paint = start_painting(window, radius=15.0, strength=0.5)
    plotter = window.viewport.plotter
    model = window.document.model
    x, y = pixel_of(window, model.vertices[rest_vertex(window, (0, -45, 75))])
    before = dense(window, "jaw_open")
    QTest.mouseMove(plotter, QPoint(round(x), round(y)))
    assert paint.cursor.visible
    assert abs(paint.cursor.ring_radius() - 15.0) < 1e-9
    count = window.document.undo_stack.count()
    QTest.mousePress(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.AltModifier, QPoint(round(x), round(y)))
    QTest.mouseRelease(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.AltModifier,
                       QPoint(round(x), round(y)))
    assert window.document.undo_stack.count() == count
    QTest.mousePress(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, QPoint(round(x), round(y)))
    QTest.mouseMove(plotter, QPoint(round(x) + 25, round(y)))
    QTest.mouseRelease(plotter, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                       QPoint(round(x) + 25, round(y)))
    assert window.document.undo_stack.count() == count + 1
    assert not np.array_equal(dense(window, "jaw_open"), before)
