"""Tree edits (engine.model.edits): each edit's returned state undoes it bit for bit, and redo likewise."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.errors import UserError
from engine.model import InfluenceRegion, Model, Parameter, ParameterTree, edits
from engine.model.edits import TreeState, restore_tree
from tests.engine.synthetic import random_model


def _bits(array) -> tuple | None:
    if array is None:
        return None
    array = np.ascontiguousarray(array)
    return (array.dtype.str, array.shape, array.tobytes())


def model_bits(model: Model) -> dict:
    """The parameters in order (every attribute, bit for bit), the groups and every region's arrays."""
    parameters = [(p.name, p.kind, p.parent, p.field, p.description,
                   _bits(np.array([p.minimum, p.maximum, p.default, p.degrees_per_unit])),
                   _bits(p.axis), _bits(p.pivot), _bits(p.direction)) for p in model.parameters]
    regions = {name: (_bits(r.indices), _bits(r.weights), _bits(r.displacements)) for name, r in model.regions.items()}
    return {"parameters": parameters, "regions": regions,
            "groups": [model.parameters.group(p.name) for p in model.parameters],
            "mesh": (_bits(model.vertices), _bits(model.faces), _bits(model.vertex_part))}


def small_model() -> Model:
    """head → jaw → lip, head → brow; pucker (a displacement field) under jaw."""
    vertices = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [10, 10, 0], [5, 15, 0]], dtype=float)
    faces = [3, 0, 1, 2, 3, 1, 3, 2, 3, 2, 3, 4]
    tree = ParameterTree([
        Parameter("head", "rotation", axis=(0, 1, 0)),
        Parameter("jaw", "rotation", parent="head", pivot=(0, 5, 0)),
        Parameter("lip", "translation", parent="jaw", direction=(0, 1, 0)),
        Parameter("brow", "translation", parent="head", direction=(0, 0, 1)),
        Parameter("pucker", "translation", parent="jaw", field=True, minimum=0),
    ])
    regions = {"head": InfluenceRegion([0, 1, 2, 3, 4], np.ones(5)),
               "jaw": InfluenceRegion([0, 1], [1.0, 0.5]),
               "lip": InfluenceRegion([1], [0.0]),
               "pucker": InfluenceRegion([3, 4], [0.5, 1.0], [[0, 1, 0], [0, 0, -0.0]])}
    return Model(vertices, faces, parameters=tree, regions=regions)


# -- every edit, undone and redone -------------------------------------------------------
EDITS = {
    "add-leaf": lambda m: edits.add_parameter(m, Parameter("smile", "translation", parent="lip"),
                                              InfluenceRegion([2, 4], [0.25, 1.0])),
    "add-root": lambda m: edits.add_parameter(m, Parameter("neck", "rotation")),
    "add-several": lambda m: edits.add_parameters(m, [(Parameter("a", "rotation"), None),
                                                      (Parameter("b", "translation", parent="a"),
                                                       InfluenceRegion([0], [1.0]))]),
    "remove-parent": lambda m: edits.remove_parameter(m, "jaw"),
    "remove-leaf": lambda m: edits.remove_parameter(m, "brow"),
    "remove-subtree": lambda m: edits.remove_subtree(m, "jaw"),
    "rename-parent": lambda m: edits.rename_parameter(m, "jaw", "jaw_open"),
    "rename-field": lambda m: edits.rename_parameter(m, "pucker", "lips_pucker"),
    "move-under-a-leaf": lambda m: edits.move_parameter(m, "brow", "lip"),
    "move-to-the-top": lambda m: edits.move_parameter(m, "jaw", None),
    "reorder-siblings": lambda m: edits.move_parameter(m, "brow", "head", before="jaw"),
    "replace": lambda m: edits.replace_parameter(m, m.parameters["jaw"].copy(maximum=2.0, pivot=(1, 2, 3))),
    "replace-parent": lambda m: edits.replace_parameter(m, m.parameters["brow"].copy(parent="jaw")),
}


@pytest.mark.parametrize("edit", list(EDITS.values()), ids=list(EDITS))
def test_an_edit_returns_the_state_that_undoes_it_and_undo_returns_redo(edit):
    model = small_model()
    before = model_bits(model)
    revision = model.revision
    undo = edit(model)
    after = model_bits(model)
    assert after != before and model.revision > revision
    redo = restore_tree(model, undo)
    assert model_bits(model) == before
    values = {name: 0.5 for name in ("head", "jaw", "lip", "pucker") if name in model.parameters}
    np.testing.assert_array_equal(model.deform(values), small_model().deform(values))   # deformer rebuilt
    again = restore_tree(model, redo)
    assert model_bits(model) == after
    restore_tree(model, again)
    assert model_bits(model) == before
    restore_tree(model, redo)                  # a state can be restored again
    assert model_bits(model) == after


@pytest.mark.parametrize("edit, message", [
    (lambda m: edits.add_parameter(m, Parameter("jaw", "rotation")), "already exists"),
    (lambda m: edits.add_parameters(m, [(Parameter("x", "rotation"), None), (Parameter("x", "rotation"), None)]),
     "already exists"),
    (lambda m: edits.add_parameter(m, Parameter("child", "rotation", parent="pucker")), "cannot have children"),
    (lambda m: edits.add_parameter(m, Parameter("orphan", "rotation", parent="nobody")), "does not exist"),
    (lambda m: edits.add_parameter(m, Parameter("far", "rotation"), InfluenceRegion([99], [1.0])), "outside"),
    (lambda m: edits.remove_parameter(m, "nobody"), "unknown parameter"),
    (lambda m: edits.remove_subtree(m, "nobody"), "unknown parameter"),
    (lambda m: edits.move_parameter(m, "head", "lip"), "loops"),
    (lambda m: edits.move_parameter(m, "jaw", "jaw"), "loops"),
    (lambda m: edits.move_parameter(m, "brow", "pucker"), "cannot have children"),
    (lambda m: edits.move_parameter(m, "jaw", None, before="brow"), "not a child of the top level"),
    (lambda m: edits.rename_parameter(m, "jaw", "brow"), "already exists"),
    (lambda m: edits.rename_parameter(m, "jaw", "2 bad"), "not allowed"),
    (lambda m: edits.rename_parameter(m, "nobody", "x"), "unknown parameter"),
    (lambda m: edits.replace_parameter(m, m.parameters["lip"].copy(field=True)), "has no displacements"),
    (lambda m: edits.replace_parameter(m, m.parameters["pucker"].copy(field=False)), "has displacements"),
    (lambda m: edits.replace_parameter(m, m.parameters["head"].copy(parent="lip")), "loops"),
    (lambda m: edits.replace_parameter(m, Parameter("nobody", "rotation")), "unknown parameter"),
    (lambda m: edits.set_region(m, "jaw", InfluenceRegion([99], [1.0])), "outside"),
    (lambda m: restore_tree(m, TreeState((*m.parameters, Parameter("new", "rotation")))), "no influence region"),
])
def test_a_refused_edit_leaves_the_model_untouched(edit, message):
    model = small_model()
    before, revision = model_bits(model), model.revision
    with pytest.raises(UserError, match=message):
        edit(model)
    assert model_bits(model) == before and model.revision == revision


def test_removing_a_parameter_moves_its_children_up_like_the_model_method():
    by_edit, by_method = small_model(), small_model()
    edits.remove_parameter(by_edit, "jaw")
    by_method.remove_parameter("jaw")
    assert model_bits(by_edit) == model_bits(by_method)
    assert [by_edit.parameters[n].parent for n in ("lip", "pucker")] == ["head", "head"]


def test_adding_a_parameter_matches_the_model_method():
    by_edit, by_method = small_model(), small_model()
    region = InfluenceRegion([0, 4], [0.5, 1.0])
    edits.add_parameter(by_edit, Parameter("smile", "translation", parent="lip"), region)
    by_method.add_parameter(Parameter("smile", "translation", parent="lip"), region)
    assert model_bits(by_edit) == model_bits(by_method)


def test_a_state_is_not_changed_by_later_edits_of_the_model():
    model = small_model()
    before = model_bits(model)
    state = TreeState.of(model, model.regions)
    model.remove_parameter("jaw")              # ParameterTree.remove re-parents the children in place
    model.parameters["brow"].description = "edited in place"
    restore_tree(model, state)
    assert model_bits(model) == before


def test_rename_carries_the_region_and_the_children_and_keeps_the_order():
    model = small_model()
    region = model.regions["jaw"]
    undo = edits.rename_parameter(model, "jaw", "jaw_open")
    assert model.parameters.names == ["head", "jaw_open", "lip", "brow", "pucker"]
    assert model.regions["jaw_open"] is region and "jaw" not in model.regions
    assert [model.parameters[n].parent for n in ("lip", "pucker")] == ["jaw_open", "jaw_open"]
    assert dict(undo.renamed) == {"jaw_open": "jaw"} and dict(undo.regions) == {}


def test_remove_subtree_returns_the_removed_regions_and_subtree_lists_them():
    model = small_model()
    assert edits.subtree(model.parameters, "jaw") == ["jaw", "lip", "pucker"]
    undo = edits.remove_subtree(model, "jaw")
    assert model.parameters.names == ["head", "brow"] and set(model.regions) == {"head", "brow"}
    assert sorted(undo.regions) == ["jaw", "lip", "pucker"]


def test_set_region_returns_the_region_it_replaced():
    model = small_model()
    old = model.regions["jaw"]
    assert edits.set_region(model, "jaw", InfluenceRegion([2], [1.0])) is old
    edits.set_region(model, "jaw", old)
    assert model_bits(model) == model_bits(small_model())


def test_queries_unique_name_renamed_and_moved_parameters():
    tree = small_model().parameters
    assert edits.unique_name(tree, "jaw") == "jaw_2" and edits.unique_name(tree, "neck") == "neck"
    assert [(p.name, p.parent) for p in edits.renamed_parameters(tree, "head", "skull")][:3] == [
        ("skull", None), ("jaw", "skull"), ("lip", "jaw")]
    assert [p.name for p in edits.moved_parameters(tree, "brow", "head", before="jaw")] == [
        "head", "brow", "jaw", "lip", "pucker"]
    assert [p.name for p in edits.moved_parameters(tree, "jaw", "head", before="jaw")] == tree.names
    assert tree.names == ["head", "jaw", "lip", "brow", "pucker"]          # queries change nothing


def test_changed_parameters_and_same_parameter():
    old = list(small_model().parameters)
    new = [p.copy() for p in old]
    assert edits.changed_parameters(old, new) == []
    new[1] = new[1].copy(degrees_per_unit=np.nextafter(1.0, 2.0))          # one bit
    assert edits.changed_parameters(old, new[::-1]) == ["jaw"]
    assert edits.changed_parameters(old, new[:-1]) == ["jaw", "pucker"]
    assert not edits.same_parameter(old[1], new[1]) and edits.same_parameter(old[0], new[0])


def test_edits_on_the_default_head_deform_as_before_after_undo(head_copy):
    model = head_copy
    values = {"jaw_open": 0.6, "head_turn": 0.3}
    expected = model.deform(values)
    before = model_bits(model)
    group1 = [n for n in model.parameters.names if model.parameters.group(n) == 1]
    undo = edits.remove_subtree(model, group1[-1])
    assert len(model.parameters) < len(before["parameters"])
    restore_tree(model, undo)
    assert model_bits(model) == before
    np.testing.assert_array_equal(model.deform(values), expected)
    undo = edits.rename_parameter(model, "jaw_open", "jaw_drop")
    np.testing.assert_array_equal(model.deform({"jaw_drop": 0.6, "head_turn": 0.3}), expected)
    restore_tree(model, undo)
    assert model_bits(model) == before


# -- random trees ------------------------------------------------------------------------
def _random_edit(data: st.DataObject, model: Model):
    """One edit drawn at random, possibly one the model refuses."""
    names = model.parameters.names
    if not names:
        return lambda m: edits.add_parameter(m, Parameter("added", "translation"))
    name = data.draw(st.sampled_from(names), label="name")
    other = data.draw(st.one_of(st.none(), st.sampled_from(names)), label="other")
    kind = data.draw(st.sampled_from(["add", "remove", "subtree", "rename", "move", "replace"]), label="kind")
    if kind == "add":
        n = model.n_vertices
        idx = data.draw(st.lists(st.integers(0, n - 1), max_size=6, unique=True), label="indices")
        weights = data.draw(st.lists(st.floats(0, 1), min_size=len(idx), max_size=len(idx)), label="weights")
        return lambda m: edits.add_parameter(m, Parameter("added", "rotation", parent=other),
                                             InfluenceRegion(idx, weights))
    if kind == "remove":
        return lambda m: edits.remove_parameter(m, name)
    if kind == "subtree":
        return lambda m: edits.remove_subtree(m, name)
    if kind == "rename":
        new = data.draw(st.sampled_from(["renamed", other or "p0"]), label="new name")
        return lambda m: edits.rename_parameter(m, name, new)
    if kind == "move":
        siblings = [p.name for p in model.parameters if p.parent == other]
        before = data.draw(st.one_of(st.none(), st.sampled_from(siblings or [name])), label="before")
        return lambda m: edits.move_parameter(m, name, other, before)
    p = model.parameters[name]
    changes = data.draw(st.sampled_from([{"parent": other}, {"maximum": p.maximum + 1.0},
                                         {"field": not p.field, "kind": "translation"}]), label="changes")
    return lambda m: edits.replace_parameter(m, p.copy(**changes))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2 ** 32 - 1), n_parameters=st.integers(1, 8), data=st.data())
def test_random_edits_on_random_trees_undo_and_redo_bit_for_bit(seed, n_parameters, data):
    model = random_model(seed, n_vertices=12, n_parameters=n_parameters, depth=3)
    states = [model_bits(model)]
    undos = []
    for _ in range(data.draw(st.integers(1, 4), label="edits")):
        edit = _random_edit(data, model)
        revision = model.revision
        try:
            undos.append(edit(model))
        except UserError:
            assert model_bits(model) == states[-1] and model.revision == revision
            continue
        model.validate()
        states.append(model_bits(model))
    redos = []
    for undo, state in zip(reversed(undos), reversed(states[:-1]), strict=True):
        redos.append(restore_tree(model, undo))
        assert model_bits(model) == state
    for redo, state in zip(reversed(redos), states[1:], strict=True):
        restore_tree(model, redo)
        assert model_bits(model) == state
