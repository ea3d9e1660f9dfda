"""The paint tool's stroke as an engine object (engine.painting.strokes): spacing, gradient, picks, result."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.errors import UserError
from engine.model import InfluenceRegion, Model, Parameter, WeightChange, apply_weight_change
from engine.painting import (
    SPACING,
    Brush,
    Change,
    DenseRegion,
    PaintContext,
    PaintStroke,
    Stroke,
    compute_gradient,
    rest_point,
    weight_change_from_dense,
)

FRONT = (0.0, 0.0, -1.0)       # the default head faces +Z: a camera in front looks down −Z


@pytest.fixture(scope="module")
def ctx(head):
    return PaintContext(head)


def across_the_brow(head, n=5):
    """``n`` rest points on the skin across the forehead, left to right (mm)."""
    skin = head.part_vertices("skin")
    points = []
    for x in np.linspace(-35, 35, n):
        near = skin[np.argmin(np.linalg.norm(head.vertices[skin] - (x, 160.0, 125.0), axis=1))]
        points.append(head.vertices[near].copy())
    return points


def test_dabs_are_spaced_a_quarter_of_the_radius_apart_from_the_first_point(head, ctx):
    brush = Brush("add", radius=8.0, strength=0.3)
    stroke = PaintStroke(head, "brow_raise", brush, ctx, view_direction=FRONT)
    a, b = np.array([-20.0, 160.0, 125.0]), np.array([20.0, 160.0, 125.0])
    stroke.to(a)
    assert len(stroke.points) == 1 and np.array_equal(stroke.points[0], a)
    stroke.to(a)                                            # no movement: no dab
    assert len(stroke.points) == 1
    stroke.to(b)
    gaps = np.linalg.norm(np.diff(stroke.points, axis=0), axis=1)
    assert SPACING == 0.25 and len(stroke.points) == 1 + int(40 // 2.0)
    np.testing.assert_allclose(gaps, SPACING * 8.0)
    assert np.linalg.norm(stroke.points[-1] - b) < SPACING * 8.0   # the rest of the way waits for the next move


def test_a_stroke_paints_what_its_dabs_paint_one_by_one(head, ctx):
    brush = Brush("add", radius=12.0, strength=0.4, falloff="linear", front_faces_only=True, mirror=True)
    stroke = PaintStroke(head, "brow_raise", brush, ctx, camera_position=(0.0, 150.0, 600.0))
    shown = np.zeros(head.n_vertices, dtype=bool)
    for point in across_the_brow(head):
        change = stroke.to(point)
        shown[change.indices] = True
    replay = DenseRegion.from_model(head, "brow_raise").weights
    by_hand = Stroke(replay)
    for point in stroke.points:
        by_hand.dab(ctx, brush, point, camera_position=(0.0, 150.0, 600.0))
    assert replay.tobytes() == stroke.weights.tobytes()
    original = DenseRegion.from_model(head, "brow_raise").weights
    assert np.array_equal(np.flatnonzero(shown), np.flatnonzero(original != stroke.weights))   # recolour these


def test_finish_gives_the_model_change_and_applying_it_writes_the_painted_weights(head, head_copy, ctx):
    stroke = PaintStroke(head, "brow_raise", Brush("set", radius=15.0, strength=0.8, value=0.6), ctx,
                         view_direction=FRONT)
    for point in across_the_brow(head):
        stroke.to(point)
    change = stroke.finish()                               # the shared head is not written (the fixture checks)
    assert isinstance(change, WeightChange) and len(change) > 10
    dense = Change.between(DenseRegion.from_model(head, "brow_raise").weights, stroke.weights)
    assert change == weight_change_from_dense(head, "brow_raise", dense)
    before = head_copy.regions["brow_raise"]
    undo = apply_weight_change(head_copy, "brow_raise", change)
    assert head_copy.regions["brow_raise"].dense(head.n_vertices).tobytes() == stroke.weights.tobytes()
    assert DenseRegion(stroke.weights.copy()).to_region().indices.tolist() == \
        head_copy.regions["brow_raise"].indices.tolist()
    apply_weight_change(head_copy, "brow_raise", undo)
    after = head_copy.regions["brow_raise"]
    assert after.indices.tobytes() == before.indices.tobytes() and after.weights.tobytes() == before.weights.tobytes()


def test_the_brush_may_change_during_a_stroke(head, ctx):
    stroke = PaintStroke(head, "brow_raise", Brush("add", radius=4.0), ctx, view_direction=FRONT)
    stroke.to((-20.0, 160.0, 125.0))
    stroke.to((-10.0, 160.0, 125.0))                       # 1 mm apart
    stroke.brush = Brush("add", radius=20.0)
    stroke.to((10.0, 160.0, 125.0))                        # 5 mm apart
    gaps = np.linalg.norm(np.diff(stroke.points, axis=0), axis=1)
    np.testing.assert_allclose(gaps, [1.0] * 10 + [5.0] * 4)


def test_the_gradient_follows_the_mouse_and_ends_as_one_ramp(head, ctx):
    brush = Brush("add", strength=0.9, value=0.8, part="skin", front_faces_only=True, connected=True)
    stroke = PaintStroke(head, "jaw_open", brush, ctx, view_direction=FRONT)
    original = stroke.weights.copy()
    start = np.array([0.0, 40.0, 120.0])
    assert not stroke.gradient_to(start)                  # the first point is the start: nothing yet
    assert not stroke.gradient_to(start)                  # no length, no ramp
    shown = np.zeros(head.n_vertices, dtype=bool)
    for end in ([0.0, 20.0, 120.0], [10.0, -10.0, 120.0], [0.0, -30.0, 110.0]):
        shown[stroke.gradient_to(end).indices] = True
    expected = compute_gradient(ctx, original, start, (0.0, -30.0, 110.0), start_value=0.8, end_value=0.0,
                                strength=0.9, part="skin", front_faces_only=True, connected=True,
                                view_direction=FRONT)
    ramp = original.copy()
    expected.redo(ramp)
    assert stroke.weights.tobytes() == ramp.tobytes()     # each preview undone before the next
    assert np.all(shown[np.flatnonzero(ramp != original)])
    assert stroke.finish() == weight_change_from_dense(head, "jaw_open", expected)


def test_dabs_and_a_gradient_do_not_mix_in_one_stroke(head, ctx):
    dabs = PaintStroke(head, "brow_raise", Brush(), ctx)
    dabs.to((0.0, 160.0, 125.0))
    with pytest.raises(UserError, match="gradient is a stroke of its own"):
        dabs.gradient_to((0.0, 150.0, 125.0))
    ramp = PaintStroke(head, "brow_raise", Brush(), ctx)
    ramp.gradient_to((0.0, 160.0, 125.0))
    with pytest.raises(UserError, match="dabs need a stroke of their own"):
        ramp.to((0.0, 150.0, 125.0))


def test_cancel_puts_the_dense_weights_back(head, ctx):
    dense = DenseRegion.from_model(head, "brow_raise")
    original = dense.weights.copy()
    stroke = PaintStroke(head, "brow_raise", Brush("add", radius=20.0), ctx, dense=dense, view_direction=FRONT)
    assert stroke.weights is dense.weights                 # painted in place, for the tool's colours
    for point in across_the_brow(head):
        stroke.to(point)
    back = stroke.cancel()
    assert dense.weights.tobytes() == original.tobytes() and len(back) > 0
    assert not stroke.finish() and stroke.points == []


def test_refused_settings(head, ctx):
    with pytest.raises(UserError, match="unknown parameter"):
        PaintStroke(head, "nobody", Brush(), ctx)
    with pytest.raises(UserError, match="spacing"):
        PaintStroke(head, "brow_raise", Brush(), ctx, spacing=0.0)
    with pytest.raises(UserError, match="build one for this model"):
        PaintStroke(head, "brow_raise", Brush(), PaintContext(Model([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [3, 0, 1, 2])))
    with pytest.raises(UserError, match="shape"):
        PaintStroke(head, "brow_raise", Brush(), ctx, dense=DenseRegion(np.zeros(3)))
    with pytest.raises(UserError, match="front-faces-only painting needs the view"):
        PaintStroke(head, "brow_raise", Brush(front_faces_only=True), ctx).to((0.0, 160.0, 125.0))


# -- picks on a posed mesh ---------------------------------------------------------------
def test_rest_point_of_a_pick_on_the_rest_mesh():
    model = Model([[0, 0, 0], [10, 0, 0], [0, 10, 0]], [3, 0, 1, 2])
    np.testing.assert_array_equal(rest_point(model, [2, 0, 1], [0.2, 0.3, 0.5]), [5.0, 2.0, 0.0])
    with pytest.raises(UserError, match="one interpolation weight per polygon vertex"):
        rest_point(model, [0, 1], [1.0])
    with pytest.raises(UserError, match="outside"):
        rest_point(model, [0, 3], [0.5, 0.5])


@settings(max_examples=50, deadline=None)
@given(offset=st.tuples(*[st.floats(-50, 50)] * 3), value=st.floats(-1, 1),
       barycentric=st.lists(st.floats(0.01, 1), min_size=3, max_size=3))
def test_a_pick_on_the_posed_mesh_maps_to_the_same_surface_point_at_rest(offset, value, barycentric):
    """A rigid shift of the whole mesh: the pick at rest is the posed pick shifted back."""
    model = Model([[0, 0, 0], [10, 0, 0], [0, 10, 0], [10, 10, 5]], [3, 0, 1, 2, 3, 1, 3, 2])
    model.add_parameter(Parameter("shift", "translation", direction=offset),
                        InfluenceRegion([0, 1, 2, 3], np.ones(4)))
    posed = model.deform({"shift": value})
    w = np.asarray(barycentric) / np.sum(barycentric)
    picked = w @ posed[[1, 3, 2]]
    np.testing.assert_allclose(rest_point(model, [1, 3, 2], w), picked - value * np.asarray(offset), atol=1e-9)
