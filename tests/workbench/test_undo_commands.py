"""Undo commands on a ModelDocument: every edit, undone and redone, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

import engine
from engine.model.weight_changes import WeightChange
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from tests.workbench.workbench_model_state import model_state
from workbench.document.model_document import ModelDocument
from workbench.document.undo_commands import (
    AddParameterCommand,
    MoveParameterCommand,
    RemoveParameterCommand,
    RenameParameterCommand,
    ReplaceParameterCommand,
    SetRegionCommand,
    WeightsChangedCommand,
)

POSE = {"head_turn": 0.3, "jaw_open": 0.7, "brow_raise": 0.6}


def model_with_field() -> engine.Model:
    """The synthetic head plus ``pucker``, a displacement-field leaf under ``head_turn``."""
    model = build_synthetic_model()
    skin = model.part_vertices("skin")[::9]
    rng = np.random.default_rng(7)
    model.add_parameter(engine.Parameter("pucker", "translation", parent="head_turn", minimum=0, field=True),
                        engine.InfluenceRegion(skin, rng.uniform(0.1, 1, len(skin)),
                                               rng.normal(0, 2, (len(skin), 3))))
    return model


@pytest.fixture
def document(qapp):
    return ModelDocument(model_with_field())


def _skin(document, every=5):
    return document.model.part_vertices("skin")[::every]


# Each edit: (test id, command factory, the undo text it shows).
EDITS = [
    ("add-leaf", lambda d: AddParameterCommand(
        d, engine.Parameter("smile", "translation", parent="jaw_open", direction=(0, 2, 1)),
        engine.InfluenceRegion(_skin(d, 7), np.linspace(0, 1, len(_skin(d, 7))))), "Add parameter smile"),
    ("add-root", lambda d: AddParameterCommand(d, engine.Parameter("neck", "rotation", axis=(0, 0, 1))),
     "Add parameter neck"),
    ("remove-parent", lambda d: RemoveParameterCommand(d, "head_turn"), "Remove parameter head_turn"),
    ("remove-leaf", lambda d: RemoveParameterCommand(d, "jaw_open"), "Remove parameter jaw_open"),
    ("replace", lambda d: ReplaceParameterCommand(
        d, d.model.parameters["jaw_open"].copy(maximum=2.0, pivot=(1, -12, -25), degrees_per_unit=15.5,
                                                description="Open wide.")), "Edit parameter jaw_open"),
    ("reparent-under-leaf", lambda d: MoveParameterCommand(d, "brow_raise", "jaw_open"),
     "Move brow_raise under jaw_open"),
    ("reparent-to-top", lambda d: MoveParameterCommand(d, "jaw_open", None), "Move jaw_open to the top"),
    ("reorder-siblings", lambda d: MoveParameterCommand(d, "brow_raise", "head_turn", before="jaw_open"),
     "Move brow_raise before jaw_open"),
    ("move-before-a-new-sibling", lambda d: MoveParameterCommand(d, "brow_raise", None, before="head_turn"),
     "Move brow_raise to the top, before head_turn"),
    ("rename-parent", lambda d: RenameParameterCommand(d, "head_turn", "head_yaw"), "Rename head_turn to head_yaw"),
    ("rename-leaf", lambda d: RenameParameterCommand(d, "pucker", "lips_pucker"), "Rename pucker to lips_pucker"),
    ("set-region", lambda d: SetRegionCommand(
        d, "brow_raise", engine.InfluenceRegion(_skin(d, 3), np.full(len(_skin(d, 3)), 0.25))),
     "Set region of brow_raise"),
    ("weights", lambda d: WeightsChangedCommand(
        # Change members, add non-members, take one vertex out (NaN).
        d, "jaw_open", np.r_[d.model.regions["jaw_open"].indices[:6], _skin(d, 11)[:5]],
        np.r_[np.nan, np.linspace(0, 1, 10)]), "Paint weights"),
    ("weights-field", lambda d: WeightsChangedCommand(
        d, "pucker", np.r_[d.model.regions["pucker"].indices[:3], _skin(d, 13)[1:5]], np.full(7, 0.5)),
     "Paint weights"),
]


@pytest.mark.parametrize("make, text", [e[1:] for e in EDITS], ids=[e[0] for e in EDITS])
def test_undo_restores_the_model_bit_for_bit_and_redo_reapplies_it(document, qtbot, make, text):
    model = document.model
    pristine = model_with_field()
    before = model_state(model)
    values = dict(POSE)
    document.set_values(values)
    deformed_before = document.vertices().copy()

    with qtbot.waitSignal(document.modified_changed) as modified:
        document.push(make(document))
    assert modified.args == [True]
    assert document.undo_stack.count() == 1 and document.undo_stack.undoText() == text
    after = model_state(model)
    assert after != before

    document.undo_stack.undo()
    assert model_state(model) == before
    assert not document.is_modified
    # The deformation caches were rebuilt: the pose deforms exactly as the untouched model does.
    np.testing.assert_array_equal(document.vertices(), pristine.deform(document.values))
    if document.values == values:
        np.testing.assert_array_equal(document.vertices(), deformed_before)

    document.undo_stack.redo()
    assert model_state(model) == after
    document.undo_stack.undo()
    assert model_state(model) == before


def test_tree_edits_announce_themselves_and_keep_the_pose_consistent(document, qtbot):
    document.set_values({"jaw_open": 0.4, "head_turn": -0.2})
    with qtbot.waitSignal(document.parameters_changed) as signal:
        document.push(RenameParameterCommand(document, "jaw_open", "jaw_drop"))
    assert signal.args == [["jaw_open", "jaw_drop"]]
    assert document.value("jaw_drop") == 0.4                     # the pose follows the rename
    assert document.model.parameters["jaw_drop"].parent == "head_turn"

    with qtbot.waitSignal(document.parameters_changed) as signal:
        document.push(RemoveParameterCommand(document, "head_turn"))
    assert signal.args == [["head_turn"]]
    assert "head_turn" not in document.values                    # values follow the tree
    assert document.model.parameters["jaw_drop"].parent is None  # children moved up, as the engine does
    np.testing.assert_array_equal(document.vertices(), document.model.deform(document.values))

    with qtbot.waitSignal(document.parameters_changed):
        document.undo_stack.undo()
    assert document.value("head_turn") == 0.0                    # back, at its default
    assert document.model.parameters.group("head_turn") == 1     # a parent again: rigid


def test_weight_edits_announce_the_region(document, qtbot):
    with qtbot.waitSignal(document.regions_changed) as signal:
        document.push(WeightsChangedCommand(document, "brow_raise", [0, 1], [0.5, 0.5]))
    assert signal.args == [["brow_raise"]]
    with qtbot.waitSignal(document.regions_changed):
        document.undo_stack.undo()


def test_one_stroke_is_one_undo_step(document):
    model = document.model
    before = model_state(model)
    skin = model.part_vertices("skin")
    dabs = [skin[0:40], skin[20:60], skin[50:90]]
    for dab in dabs:
        weights = document.region_weights("brow_raise", dab)
        new = np.clip(np.nan_to_num(weights) + 0.3, 0, 1)
        document.push(WeightsChangedCommand(document, "brow_raise", dab, new, stroke_id="stroke-1"))
    assert document.undo_stack.count() == 1
    after = model_state(model)
    final = model.regions["brow_raise"].dense(model.n_vertices)[skin[0:90]]

    document.undo_stack.undo()
    assert model_state(model) == before
    document.undo_stack.redo()
    assert model_state(model) == after
    np.testing.assert_array_equal(model.regions["brow_raise"].dense(model.n_vertices)[skin[0:90]], final)

    # A second stroke is a second step; unnamed strokes never merge.
    document.push(WeightsChangedCommand(document, "brow_raise", skin[:5], np.zeros(5), stroke_id="stroke-2"))
    document.push(WeightsChangedCommand(document, "brow_raise", skin[5:9], np.zeros(4)))
    document.push(WeightsChangedCommand(document, "brow_raise", skin[9:12], np.zeros(3)))
    assert document.undo_stack.count() == 4
    # Same stroke id on another parameter is another step too.
    document.push(WeightsChangedCommand(document, "jaw_open", skin[:3], np.ones(3), stroke_id="stroke-2"))
    assert document.undo_stack.count() == 5
    for _ in range(5):
        document.undo_stack.undo()
    assert model_state(model) == before


def test_a_tool_that_already_wrote_the_weights_pushes_before_and_after(document):
    """Live preview: the brush writes each dab itself, then records the stroke without re-applying it."""
    model = document.model
    before_state = model_state(model)
    dab = model.part_vertices("skin")[100:130]
    before = document.region_weights("jaw_open", dab)
    after = np.full(len(dab), 0.75)
    document.apply_weight_change("jaw_open", WeightChange(dab, before, after))   # what a tool may do while painting
    painted = model_state(model)
    revision = model.revision
    document.push(WeightsChangedCommand(document, "jaw_open", dab, after, before, already_applied=True))
    assert model.revision == revision                        # pushing did not apply it again
    assert model_state(model) == painted
    document.undo_stack.undo()
    assert model_state(model) == before_state
    document.undo_stack.redo()
    assert model_state(model) == painted


@pytest.mark.parametrize("make, error", [
    (lambda d: AddParameterCommand(d, engine.Parameter("jaw_open", "rotation")), "already exists"),
    (lambda d: AddParameterCommand(d, engine.Parameter("child", "rotation", parent="pucker")),
     "cannot have children"),
    (lambda d: MoveParameterCommand(d, "head_turn", "jaw_open"), "loops"),
    (lambda d: MoveParameterCommand(d, "jaw_open", "pucker"), "cannot have children"),
    (lambda d: MoveParameterCommand(d, "jaw_open", None, before="brow_raise"), "not a child of the top level"),
    (lambda d: RenameParameterCommand(d, "jaw_open", "brow_raise"), "already exists"),
    (lambda d: RenameParameterCommand(d, "jaw_open", "2 bad"), "not allowed"),
    (lambda d: ReplaceParameterCommand(d, d.model.parameters["jaw_open"].copy(field=False, kind="translation",
                                                                              direction=(0, 0, 1))), None),
    (lambda d: ReplaceParameterCommand(d, d.model.parameters["brow_raise"].copy(field=True)),
     "has no displacements"),
    (lambda d: SetRegionCommand(d, "jaw_open", engine.InfluenceRegion([10 ** 6], [1.0])), "outside"),
    (lambda d: WeightsChangedCommand(d, "jaw_open", [1, 2], [0.5, 1.5]), r"\[0, 1\]"),
    (lambda d: WeightsChangedCommand(d, "pucker", d.model.regions["pucker"].indices[:1], [np.nan]),
     "displacement"),
    (lambda d: WeightsChangedCommand(d, "jaw_open", [3, 3], [0.5, 0.5]), "twice"),
])
def test_an_edit_the_engine_refuses_changes_nothing(document, make, error):
    before = model_state(document.model)
    if error is None:      # a valid edit, to show the list above is not refusing everything
        document.push(make(document))
        assert document.undo_stack.count() == 1
        return
    with pytest.raises(engine.UserError, match=error):
        document.push(make(document))
    assert document.undo_stack.count() == 0
    assert not document.is_modified
    assert model_state(document.model) == before


def test_pose_changes_are_not_model_edits(document):
    document.set_values({"jaw_open": 0.5, "brow_raise": -0.25})
    document.reset_all()
    assert document.undo_stack.count() == 0
    assert not document.is_modified


def test_modified_follows_the_clean_index(document, tmp_path, qtbot):
    signals = []
    document.modified_changed.connect(signals.append)
    document.push(WeightsChangedCommand(document, "jaw_open", [1], [0.5]))
    document.save(tmp_path / "saved.xml")
    assert not document.is_modified
    document.push(WeightsChangedCommand(document, "jaw_open", [2], [0.5]))
    assert document.is_modified
    document.undo_stack.undo()                     # back at the saved state
    assert not document.is_modified
    document.undo_stack.undo()                     # before the save: differs from the file again
    assert document.is_modified
    assert signals == [True, False, True, False, True]

    document.replace_model(build_synthetic_model())   # another model: no history, nothing modified
    assert document.undo_stack.count() == 0 and not document.is_modified
    document.mark_modified()                       # e.g. a recovered autosave
    assert document.is_modified and not document.undo_stack.canUndo()
