"""Weight changes (engine.model.weight_changes): one representation, applied with an exact inverse."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.errors import UserError
from engine.model import InfluenceRegion, Model, Parameter, WeightChange, apply_weight_change
from engine.model.weight_changes import weight_change, weights_at, with_weights
from engine.painting import Change, DenseRegion, weight_change_from_dense
from tests.engine.synthetic import random_model

NAN = np.nan


def region_bits(region: InfluenceRegion) -> tuple:
    d = region.displacements
    return (region.indices.dtype.str, region.indices.tobytes(), region.weights.dtype.str, region.weights.tobytes(),
            None if d is None else (d.shape, d.tobytes()))


def regions_bits(model: Model) -> dict:
    return {name: region_bits(r) for name, r in model.regions.items()}


def small_model() -> Model:
    """``jaw`` (a rotation) and ``pucker`` (a displacement field, one vertex with an all-zero displacement)."""
    vertices = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [10, 10, 0], [5, 15, 0], [0, 20, 0]], dtype=float)
    model = Model(vertices, [3, 0, 1, 2, 3, 1, 3, 2, 3, 2, 3, 4, 3, 2, 4, 5])
    model.add_parameter(Parameter("jaw", "rotation"), InfluenceRegion([0, 1, 2], [1.0, 0.0, 0.5]))
    model.add_parameter(Parameter("pucker", "translation", field=True),
                        InfluenceRegion([2, 3, 4], [0.5, 1.0, 0.25], [[0, 1, 0], [0, 0, 0], [0, -0.0, 0]]))
    return model


# -- the moved workbench test, assertions kept --------------------------------------------
def test_with_weights_and_weights_at_mark_absent_vertices_with_nan():
    region = InfluenceRegion([2, 5, 9], [0.5, 0.0, 1.0])
    np.testing.assert_array_equal(weights_at(region, [9, 4, 5]), [1.0, np.nan, 0.0])
    new = with_weights(region, [5, 4, 9], [np.nan, 0.0, 0.25])
    assert new.indices.tolist() == [2, 4, 9]            # 5 taken out, 4 added with weight 0
    assert new.weights.tolist() == [0.5, 0.0, 0.25]
    again = with_weights(new, [5, 4, 9], weights_at(region, [5, 4, 9]))
    assert again.indices.tolist() == region.indices.tolist()
    assert again.weights.tobytes() == region.weights.tobytes()


# -- WeightChange ------------------------------------------------------------------------
def test_a_weight_change_is_sorted_checked_and_read_only():
    change = WeightChange([7, 2, 5], [NAN, 0.5, 0.0], [0.25, NAN, 1.0])
    assert change.indices.tolist() == [2, 5, 7]
    np.testing.assert_array_equal(change.before, [0.5, 0.0, NAN])
    np.testing.assert_array_equal(change.after, [NAN, 1.0, 0.25])
    with pytest.raises(ValueError, match="read-only"):
        change.after[0] = 0.5
    assert len(change) == 3 and change and not WeightChange.empty()
    assert change.inverse().inverse() == change and change.inverse() != change
    assert change == WeightChange([2, 5, 7], [0.5, 0.0, NAN], [NAN, 1.0, 0.25])     # NaN equals NaN here
    assert change != WeightChange([2, 5, 7], [0.5, -0.0, NAN], [NAN, 1.0, 0.25])    # but −0 is not 0


@pytest.mark.parametrize("indices, before, after, message", [
    ([1, 2], [0.5], [0.5, 0.5], "2 vertex indices, 1 weights before"),
    ([1, 1], [0.5, 0.5], [0.5, 0.5], "twice"),
    ([1], [0.5], [1.5], r"\[0, 1\]"),
    ([1], [-0.25], [0.5], r"\[0, 1\]"),
    ([1], [0.5], [np.inf], r"\[0, 1\]"),
])
def test_a_weight_change_refuses_what_no_region_can_hold(indices, before, after, message):
    with pytest.raises(UserError, match=message):
        WeightChange(indices, before, after)


def test_weight_change_reads_before_from_the_model():
    model = small_model()
    change = weight_change(model, "jaw", [5, 1, 2], [0.5, 0.75, NAN])
    assert change == WeightChange([1, 2, 5], [0.0, 0.5, NAN], [0.75, NAN, 0.5])
    with pytest.raises(UserError, match="unknown parameter"):
        weight_change(model, "nobody", [1], [0.5])


def test_apply_returns_the_inverse_read_from_the_model_not_from_the_change():
    model = small_model()
    before = regions_bits(model)
    wrong = WeightChange([0, 5], [0.25, 0.25], [NAN, 0.5])         # its "before" is not what the model has
    undo = apply_weight_change(model, "jaw", wrong)
    assert undo == WeightChange([0, 5], [NAN, 0.5], [1.0, NAN])
    redo = apply_weight_change(model, "jaw", undo)
    assert regions_bits(model) == before
    assert redo == WeightChange([0, 5], [1.0, NAN], [NAN, 0.5])


def test_listed_zeros_and_field_displacements_come_back_exactly():
    model = small_model()
    before = regions_bits(model)
    # jaw: vertex 1 is listed at 0; take it out, then put it back.
    undo = apply_weight_change(model, "jaw", WeightChange([1, 3], [0.0, NAN], [NAN, 0.5]))
    assert model.regions["jaw"].indices.tolist() == [0, 2, 3]
    apply_weight_change(model, "jaw", undo)
    # pucker: vertex 3's displacement is all-zero bits, so it may leave and come back; 5 joins with (0, 0, 0).
    undo = apply_weight_change(model, "pucker", WeightChange([3, 5], [1.0, NAN], [NAN, 0.75]))
    assert model.regions["pucker"].indices.tolist() == [2, 4, 5]
    assert model.regions["pucker"].displacements[-1].tolist() == [0.0, 0.0, 0.0]
    apply_weight_change(model, "pucker", undo)
    assert regions_bits(model) == before


@pytest.mark.parametrize("vertex", [2, 4], ids=["displacement", "minus-zero-displacement"])
def test_taking_out_a_vertex_whose_displacement_would_be_lost_is_refused(vertex):
    model = small_model()
    before, revision = regions_bits(model), model.revision
    with pytest.raises(UserError, match="displacement would be lost"):
        apply_weight_change(model, "pucker", WeightChange([vertex], [0.5], [NAN]))
    assert regions_bits(model) == before and model.revision == revision


def test_an_empty_change_changes_nothing():
    model = small_model()
    revision = model.revision
    assert not apply_weight_change(model, "jaw", WeightChange.empty())
    assert model.revision == revision


def test_followed_by_is_one_step_for_a_stroke():
    model, merged_model = small_model(), small_model()
    original = regions_bits(model)
    steps = [WeightChange([0, 1], [1.0, 0.0], [0.5, 0.25]), WeightChange([1, 5], [0.25, NAN], [NAN, 0.5]),
             WeightChange([0, 3, 5], [0.5, NAN, 0.5], [0.75, 0.125, NAN])]
    undos = [apply_weight_change(model, "jaw", step) for step in steps]
    merged = steps[0].followed_by(steps[1]).followed_by(steps[2])
    assert merged == WeightChange([0, 1, 3, 5], [1.0, 0.0, NAN, NAN], [0.75, NAN, 0.125, NAN])
    apply_weight_change(merged_model, "jaw", merged)
    assert regions_bits(merged_model) == regions_bits(model)
    undo = undos[2].followed_by(undos[1]).followed_by(undos[0])       # the commands' merge of their inverses
    apply_weight_change(model, "jaw", undo)
    assert regions_bits(model) == original


# -- from dense painting -----------------------------------------------------------------
def test_dense_zero_leaves_the_region_unless_a_displacement_would_be_lost():
    model = small_model()
    # jaw: 0 → out; a painted-up vertex joins.
    change = weight_change_from_dense(model, "jaw", Change(np.array([0, 3]), np.array([1.0, 0.0]),
                                                           np.array([0.0, 0.5])))
    assert change == WeightChange([0, 3], [1.0, NAN], [NAN, 0.5])
    # pucker: vertex 2 moves (stays listed at 0), 3 has zero bits (leaves), 4 has −0.0 (stays).
    dense = Change(np.array([2, 3, 4]), np.array([0.5, 1.0, 0.25]), np.zeros(3))
    change = weight_change_from_dense(model, "pucker", dense)
    assert change == WeightChange([2, 3, 4], [0.5, 1.0, 0.25], [0.0, NAN, 0.0])
    apply_weight_change(model, "pucker", change)
    assert model.regions["pucker"].indices.tolist() == [2, 4]


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2 ** 32 - 1), data=st.data())
def test_random_weight_changes_on_random_models_undo_and_redo_bit_for_bit(seed, data):
    model = random_model(seed, n_vertices=15, n_parameters=5, depth=3)
    name = data.draw(st.sampled_from(model.parameters.names), label="parameter")
    indices = data.draw(st.lists(st.integers(0, model.n_vertices - 1), min_size=1, max_size=8, unique=True),
                        label="indices")
    after = data.draw(st.lists(st.one_of(st.just(NAN), st.just(0.0), st.just(1.0), st.floats(0, 1)),
                               min_size=len(indices), max_size=len(indices)), label="after")
    before_bits, revision = regions_bits(model), model.revision
    change = weight_change(model, name, indices, after)
    try:
        undo = apply_weight_change(model, name, change)
    except UserError:
        assert regions_bits(model) == before_bits and model.revision == revision
        return
    np.testing.assert_array_equal(weights_at(model.regions[name], indices), after)
    model.validate()
    after_bits = regions_bits(model)
    redo = apply_weight_change(model, name, undo)
    assert regions_bits(model) == before_bits
    assert redo == change
    apply_weight_change(model, name, redo)
    assert regions_bits(model) == after_bits


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2 ** 32 - 1), data=st.data())
def test_a_dense_edit_written_into_the_model_reads_back_as_painted(seed, data):
    model = random_model(seed, n_vertices=15, n_parameters=5, depth=3)
    name = data.draw(st.sampled_from(model.parameters.names), label="parameter")
    dense = DenseRegion.from_model(model, name)
    painted = dense.weights.copy()
    indices = data.draw(st.lists(st.integers(0, model.n_vertices - 1), max_size=8, unique=True), label="indices")
    painted[indices] = data.draw(st.lists(st.sampled_from([0.0, 0.5, 1.0]), min_size=len(indices),
                                          max_size=len(indices)), label="values")
    before_bits = regions_bits(model)
    change = weight_change_from_dense(model, name, Change.between(dense.weights, painted))
    undo = apply_weight_change(model, name, change)          # never refused: displacements are kept
    assert model.regions[name].dense(model.n_vertices).tobytes() == painted.tobytes()
    apply_weight_change(model, name, undo)
    assert regions_bits(model) == before_bits
