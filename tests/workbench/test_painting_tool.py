"""Weight painting in the real window: strokes, brushes, restrictions, undo, live preview (§2.2.2).

Strokes are driven through the same methods the viewport's mouse events call
(``press``/``drag``/``release`` with widget pixels from
``viewport.world_to_widget``); one test goes through real Qt mouse events.
Expected weights come from the engine functions themselves
(:func:`engine.painting.compute_dab`, :class:`~engine.painting.Stroke`), and
a stroke scripted with :class:`~engine.painting.PaintStroke` gives the mouse's
weights bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtTest import QTest

from engine.model import apply_weight_change
from engine.painting import (
    Brush,
    DenseRegion,
    PaintContext,
    PaintStroke,
    Stroke,
    compute_dab,
    compute_gradient,
    rest_point,
)
from tests.workbench.workbench_model_state import model_state


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window


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


def record_dabs(monkeypatch):
    """Wrap the engine's ``PaintStroke.dab`` so the test knows each dab's rest point."""
    points = []
    original = PaintStroke.dab

    def dab(self, point, **view):
        points.append(np.array(point, dtype=float))
        return original(self, point, **view)

    monkeypatch.setattr(PaintStroke, "dab", dab)
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
    expected = compute_dab(paint.context(), before, paint.brush, hit[1], **paint.view())
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
    points = record_dabs(monkeypatch)
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
        stroke.dab(paint.context(), paint.brush, p, **paint.view())
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


@pytest.mark.parametrize("tool, hold", [("add", False), ("add", True), ("gradient", False)],
                         ids=["dabs", "dabs-on-the-posed-mesh", "gradient"])
def test_a_stroke_scripted_from_python_gives_the_mouse_weights_bit_for_bit(window, tool, hold):
    """The mouse stroke and the same stroke through engine.painting.PaintStroke (same rest points, brush, view)."""
    paint = start_painting(window, name="jaw_open", radius=10.0, strength=0.35, falloff="linear", mode="add",
                           value=0.9, front_faces_only=True, mirror=True, connected=True)
    if tool == "gradient":
        paint.set_tool("gradient")
    if hold:
        paint.set_hold(True, 0.8)                  # the mouse picks the posed mesh; painting is on the rest mesh
    window.viewport.render_now()
    document, viewport = window.document, window.viewport
    model = document.model
    scripted = model.copy()                        # the Python prompt's own model, as it was before the stroke
    (xa, ya), (xb, yb) = pixel_of(window, (-30, -35, 75)), pixel_of(window, (30, -45, 75))
    pixels = [(xa + t * (xb - xa), ya + t * (yb - ya)) for t in np.linspace(0, 1, 9)]
    rest_points = []
    for k, (x, y) in enumerate(pixels):
        _, vertices, weights = viewport.pick_cell(x, y)      # what the controller will pick at this pixel
        rest_points.append(rest_point(model, vertices, weights))
        (paint.press if k == 0 else paint.drag)(x, y)
    view, brush = paint.view(), paint.brush
    count = document.undo_stack.count()
    paint.release(*pixels[-1])
    assert document.undo_stack.count() == count + 1
    assert not np.array_equal(model.regions["jaw_open"].dense(model.n_vertices),
                              scripted.regions["jaw_open"].dense(model.n_vertices))

    stroke = PaintStroke(scripted, "jaw_open", brush, PaintContext(scripted), **view)
    for point in rest_points:
        (stroke.gradient_to if tool == "gradient" else stroke.to)(point)
    apply_weight_change(scripted, "jaw_open", stroke.finish())
    assert model_state(scripted) == model_state(model)        # every bit of every region
    region, mouse = scripted.regions["jaw_open"], model.regions["jaw_open"]
    assert region.indices.tobytes() == mouse.indices.tobytes() and region.weights.tobytes() == mouse.weights.tobytes()


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


def test_x_mirror_paints_both_sides_symmetrically(window):
    paint = start_painting(window, name="brow_raise", radius=25.0, strength=0.6, mirror=True, mode="set", value=0.8)
    model = window.document.model
    before = dense(window, "brow_raise")
    x, y = pixel_of(window, model.vertices[rest_vertex(window, (30, -10, 80))])
    paint.press(x, y)
    paint.release(x, y)
    after = dense(window, "brow_raise")
    changed = np.flatnonzero(after != before)
    mirror = paint.context().mirror.map
    assert len(changed) > 2 and (mirror[changed] >= 0).all()
    assert np.any(model.vertices[changed, 0] > 5) and np.any(model.vertices[changed, 0] < -5)
    assert np.array_equal(after[changed], after[mirror[changed]])


def test_restrict_to_part_and_front_faces_only(window):
    model = window.document.model
    eye = model.parts.index("eye_left")
    # A big dab on the left eye, restricted to the skin: no eye vertex changes.
    paint = start_painting(window, name="brow_raise", radius=30.0, strength=1.0, mode="set", value=1.0,
                           part="skin", front_faces_only=False, connected=False)
    before = dense(window, "brow_raise")
    x, y = pixel_of(window, (32, 20, 80))
    paint.press(x, y)
    paint.release(x, y)
    changed = np.flatnonzero(dense(window, "brow_raise") != before)
    assert len(changed) > 5
    assert not np.any(model.vertex_part[changed] == eye)
    assert np.all(model.vertex_part[changed] == model.parts.index("skin"))
    # A dab wider than the head: with front faces only nothing behind (z < 0) changes; without, it does.
    window.undo()
    for front_only, behind in ((True, False), (False, True)):
        paint.set_brush(part="skin", radius=150.0, front_faces_only=front_only, connected=True)
        before = dense(window, "brow_raise")
        x, y = pixel_of(window, model.vertices[rest_vertex(window, (0, 0, 90))])
        paint.press(x, y)
        paint.release(x, y)
        changed = np.flatnonzero(dense(window, "brow_raise") != before)
        assert len(changed) > 50
        assert bool(np.any(model.vertices[changed, 2] < -10)) == behind
        window.undo()


def test_connected_surface_only_does_not_jump_to_the_eye(window):
    model = window.document.model
    paint = start_painting(window, name="brow_raise", radius=14.0, strength=1.0, mode="set", value=1.0,
                           connected=True, front_faces_only=False)
    before = dense(window, "brow_raise")
    x, y = pixel_of(window, (32, 20, 80))                         # on the left eye
    paint.press(x, y)
    paint.release(x, y)
    changed = np.flatnonzero(dense(window, "brow_raise") != before)
    assert len(changed) and np.all(model.vertex_part[changed] == model.parts.index("eye_left"))
    window.undo()
    paint.set_brush(connected=False)                             # now the skin around it is reached too
    paint.press(x, y)
    paint.release(x, y)
    changed = np.flatnonzero(dense(window, "brow_raise") != before)
    assert np.any(model.vertex_part[changed] == model.parts.index("skin"))


def test_gradient_and_sample(window):
    paint = start_painting(window, name="brow_raise", strength=1.0, value=1.0, front_faces_only=True,
                           connected=True, mirror=False)
    paint.set_tool("gradient")
    model = window.document.model
    before = dense(window, "brow_raise")
    (xa, ya) = pixel_of(window, model.vertices[rest_vertex(window, (0, 40, 80))])
    (xb, yb) = pixel_of(window, model.vertices[rest_vertex(window, (0, -40, 80))])
    start, end = paint._hit(xa, ya)[1], paint._hit(xb, yb)[1]
    expected = compute_gradient(paint.context(), before, start, end, start_value=1.0, end_value=0.0, strength=1.0,
                                front_faces_only=True, connected=True, **paint.view())
    count = window.document.undo_stack.count()
    paint.press(xa, ya)
    paint.drag((xa + xb) / 2, (ya + yb) / 2)
    paint.drag(xb, yb)
    paint.release(xb, yb)
    assert window.document.undo_stack.count() == count + 1
    after = dense(window, "brow_raise")
    assert np.array_equal(np.flatnonzero(after != before), expected.indices)
    assert np.array_equal(after[expected.indices], expected.after)
    # Ctrl+click samples the weight under the cursor into the brush's value; the sample tool too.
    x, y = pixel_of(window, model.vertices[rest_vertex(window, (0, 0, 85))])
    paint.set_tool("add")
    paint.press(x, y, sample=True)
    assert window.document.undo_stack.count() == count + 1          # sampling paints nothing
    vertex = paint._hit(x, y)[0].vertex
    assert abs(paint.brush.value - after[vertex]) < 0.2
    assert window.paint_options.value.spin.value() == pytest.approx(paint.brush.value, abs=1e-3)
    paint.set_tool("sample")
    paint.press(x, y)
    assert paint.tool == "set" and "Sampled weight" in window.statusBar().currentMessage()


def test_options_page_is_bound_to_the_brush(window):
    paint = start_painting(window)
    page = window.paint_options
    page.radius.spin.setValue(23.5)
    page.strength.spin.setValue(0.25)
    page.falloff.setCurrentIndex(page.falloff.findData("sharp"))
    page.part.setCurrentIndex(page.part.findData("skin"))
    page.mirror.setChecked(True)
    page.tool.setCurrentIndex(page.tool.findData("smooth"))
    assert paint.brush == Brush("smooth", radius=23.5, strength=0.25, falloff="sharp", value=paint.brush.value,
                                front_faces_only=True, part="skin", mirror=True, connected=True)
    assert "mirrored exactly" in page.mirror_info.text()
    window.actions_by_id["paint.larger"].trigger()
    assert page.radius.spin.value() == pytest.approx(23.5 * 1.25, abs=0.05)


@pytest.mark.parametrize("operation", ["invert", "clear", "smooth", "grow", "shrink"])
def test_weight_operations_do_what_the_engine_does_in_one_undo_step(window, operation):
    from engine.painting import clear_weights, grow_weights, invert_weights, shrink_weights, smooth_weights
    from workbench.painting import operations

    paint = start_painting(window, name="brow_raise", part="skin")
    model = window.document.model
    before_state = model_state(model)
    before = dense(window, "brow_raise")
    ctx = paint.context()
    expected = {"invert": lambda w: invert_weights(ctx, w, part="skin"),
                "clear": lambda w: clear_weights(ctx, w, part="skin"),
                "smooth": lambda w: smooth_weights(ctx, w, iterations=operations.SMOOTH_ITERATIONS, part="skin"),
                "grow": lambda w: grow_weights(ctx, w, rings=1, part="skin"),
                "shrink": lambda w: shrink_weights(ctx, w, rings=1, part="skin")}[operation](before)
    count = window.document.undo_stack.count()
    window.actions_by_id[f"weights.{operation}"].trigger()
    after = dense(window, "brow_raise")
    assert after.tobytes() == expected.tobytes()
    assert window.document.undo_stack.count() == count + 1
    eyes = model.vertex_part != model.parts.index("skin")
    assert np.array_equal(after[eyes], before[eyes])
    inside_before, inside_after = (before > 0).sum(), (after > 0).sum()
    if operation == "grow":
        assert inside_after > inside_before
    elif operation == "shrink":
        assert 0 < inside_after < inside_before
    elif operation == "clear":
        assert inside_after == 0
    elif operation == "invert":
        assert np.allclose(after[~eyes], 1 - before[~eyes])
    window.undo()
    assert model_state(model) == before_state


def test_mirror_left_to_right_and_right_to_left(window):
    paint = start_painting(window, name="brow_raise", radius=10.0, strength=1.0, mode="set", value=1.0,
                           mirror=False)
    model = window.document.model
    x, y = pixel_of(window, model.vertices[rest_vertex(window, (40, -20, 70))])    # the subject's left (+X)
    paint.press(x, y)
    paint.release(x, y)
    painted = dense(window, "brow_raise")
    left = np.flatnonzero((painted > 0) & (model.vertices[:, 0] > 20) & (model.vertices[:, 1] < 0))
    mirror = paint.context().mirror.map
    assert len(left) and np.all(painted[mirror[left]] == 0)
    window.actions_by_id["weights.mirror_left_to_right"].trigger()
    after = dense(window, "brow_raise")
    assert np.array_equal(after[mirror[left]], painted[left])
    window.actions_by_id["weights.mirror_right_to_left"].trigger()     # the right now matches: nothing lost
    assert np.array_equal(dense(window, "brow_raise")[left], painted[left])


def test_operations_refuse_without_a_parameter(window):
    count = window.document.undo_stack.count()
    window.actions_by_id["weights.invert"].trigger()
    assert window.document.undo_stack.count() == count
    assert "Select a parameter" in window.statusBar().currentMessage()


def test_live_preview_follows_every_dab_and_matches_the_engine_after(window):
    paint = start_painting(window, name="brow_raise", radius=15.0, strength=0.8, mode="add", value=1.0)
    paint.set_hold(True, 1.0)
    document, viewport = window.document, window.viewport
    assert document.value("brow_raise") == document.model.parameters["brow_raise"].maximum
    model = document.model
    x, y = pixel_of(window, model.vertices[rest_vertex(window, (20, 10, 80))])
    shown_before = viewport.displayed_points()
    paint.press(x, y)
    paint.drag(x + 30, y)
    during = viewport.displayed_points()                 # the stroke is not yet in the model
    assert paint._live is not None
    moved = np.flatnonzero(np.any(np.abs(during - shown_before) > 1e-9, axis=1))
    assert len(moved) > 3                                # the mesh moves with the dabs
    paint.release(x + 30, y)
    after = viewport.displayed_points()
    engine_pose = model.deform(document.values)
    drawn = ~np.isnan(after[:, 0])
    assert np.allclose(after[drawn], engine_pose[drawn], atol=1e-9)
    assert np.allclose(during[drawn], engine_pose[drawn], atol=1e-9)
    paint.set_active(False)                              # leaving paint mode lets go of the held value
    assert document.value("brow_raise") == model.parameters["brow_raise"].default


def test_normalise_group1_on_the_default_head(make_window):
    import engine
    from engine.painting import group1_names

    window = make_window(engine.default_model_path())
    model = window.document.model
    names = group1_names(model)
    assert len(names) >= 2
    name = names[-1]
    paint = start_painting(window, name=name, radius=25.0, strength=1.0, mode="add", value=1.0,
                           front_faces_only=False)
    x, y = pixel_of(window, model.vertices[model.landmarks["9.3"]])     # paint over the nose tip
    paint.press(x, y)
    paint.release(x, y)
    before_state = model_state(model)
    count = window.document.undo_stack.count()
    window.actions_by_id["weights.normalise"].trigger()
    assert window.document.undo_stack.count() == count + 1
    W = np.array([model.regions[n].dense(model.n_vertices) for n in names])
    total = W.sum(axis=0)
    assert np.allclose(total[total > 0], 1.0)
    window.undo()
    assert model_state(model) == before_state
