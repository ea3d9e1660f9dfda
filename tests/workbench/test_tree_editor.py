"""The parameter tree editor in the real window: add, remove, rename, drag and drop, undo, save → open."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QPointF, Qt
from PySide6.QtGui import QDropEvent
from PySide6.QtWidgets import QLineEdit, QMessageBox

import engine
from tests.workbench.workbench_model_state import model_state
from workbench.tree_editor import TOOL_ID
from workbench.tree_editor.tree_model import GROUP_TEXT


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window


def _select(window, name):
    """Select ``name`` as a user does: through the tree view's selection."""
    dock = window.tree_editor.dock
    index = dock.model.index_of(name)
    assert index.isValid(), name
    dock.view.setCurrentIndex(index)
    assert window.view_state.selected_parameter == name


def _row(window, name):
    """(name, group text, type text) as the tree shows them."""
    model = window.tree_editor.dock.model
    index = model.index_of(name)
    return tuple(index.siblingAtColumn(c).data() for c in range(3))


def _shown_tree(window):
    """{name: parent} as the tree view's rows say."""
    model = window.tree_editor.dock.model
    out = {}
    for name in model.names():
        parent = model.index_of(name).parent()
        out[name] = model.name_at(parent) if parent.isValid() else None
    return out


def _tree(document):
    return {p.name: p.parent for p in document.model.parameters}


def _answer(monkeypatch, kind, button=None):
    """Record ``QMessageBox.<kind>`` calls (answering ``button``) instead of blocking."""
    calls = []

    def fake(parent, title, text, *args, **kwargs):
        calls.append(text)
        return button if button is not None else QMessageBox.StandardButton.Ok

    monkeypatch.setattr(QMessageBox, kind, staticmethod(fake))
    return calls


def _check_undo_redo(document, before):
    """One undo step back to ``before`` bit for bit, redo to the edited state."""
    stack = document.undo_stack
    after = model_state(document.model)
    assert after != before
    assert stack.count() == 1
    stack.undo()
    assert model_state(document.model) == before
    stack.redo()
    assert model_state(document.model) == after
    return after


def test_the_dock_shows_the_tree_with_groups_and_types(window):
    dock = window.tree_editor.dock
    assert dock.objectName() == "dock:parameter-tree"
    assert window.findChild(type(dock), "dock:parameter-tree") is dock
    assert _shown_tree(window) == _tree(window.document)
    assert _row(window, "head_turn") == ("head_turn", GROUP_TEXT[1], "rotation")
    assert _row(window, "jaw_open") == ("jaw_open", GROUP_TEXT[2], "rotation")
    assert _row(window, "brow_raise") == ("brow_raise", GROUP_TEXT[2], "translation")
    menu = window.menus["&Parameters"]
    ids = [a.objectName() for a in menu.actions() if a.objectName()]
    assert ids == ["parameters.add", "parameters.remove", "parameters.rename",
                   "parameters.move_up", "parameters.move_down"]
    assert window.actions_by_id["parameters.rename"].shortcut().toString() == "F2"
    assert window.actions_by_id["parameters.add"] in window.toolbar.actions()
    assert not window.actions_by_id["parameters.add"].icon().isNull()


def test_selection_is_shared_with_the_view_state_and_opens_the_property_page(window):
    _select(window, "jaw_open")
    assert window.tool_options.current_tool == TOOL_ID
    assert window.tree_editor.sheet.title.text().startswith("jaw_open")
    window.view_state.select_parameter("brow_raise")           # e.g. chosen by another tool
    assert window.tree_editor.dock.selected_name() == "brow_raise"
    window.view_state.select_parameter(None)
    assert window.tree_editor.dock.selected_name() is None
    assert window.tree_editor.sheet.hint.isVisibleTo(window.tree_editor.sheet)
    assert not window.actions_by_id["parameters.remove"].isEnabled()


def test_add_a_child_of_the_selected_parameter_is_one_undo_step(window):
    document = window.document
    before = model_state(document.model)
    _select(window, "jaw_open")
    window.actions_by_id["parameters.add"].trigger()
    p = document.model.parameters["parameter"]
    assert p.parent == "jaw_open" and p.kind == "rotation"
    np.testing.assert_array_equal(p.pivot, document.model.parameters["jaw_open"].pivot)
    assert window.view_state.selected_parameter == "parameter"
    # jaw_open has a child now: rigid, group 1, and the tree says so.
    assert _row(window, "jaw_open")[1] == GROUP_TEXT[1]
    assert _shown_tree(window) == _tree(document)
    assert document.undo_stack.undoText() == "Add parameter parameter"
    _check_undo_redo(document, before)
    document.undo_stack.undo()
    assert _row(window, "jaw_open")[1] == GROUP_TEXT[2]
    assert "parameter" not in _shown_tree(window)


def test_add_with_nothing_selected_adds_a_root(window):
    window.view_state.select_parameter(None)
    name = window.tree_editor.add_parameter(edit_name=False)
    assert window.document.model.parameters[name].parent is None
    assert _shown_tree(window)[name] is None


def test_rename_in_place_by_typing_in_the_tree(window, qtbot):
    document = window.document
    before = model_state(document.model)
    _select(window, "jaw_open")
    window.actions_by_id["parameters.rename"].trigger()           # F2
    editor = window.tree_editor.dock.view.findChild(QLineEdit)
    assert editor is not None and editor.text() == "jaw_open"
    editor.selectAll()
    qtbot.keyClicks(editor, "jaw_drop")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    # The delegate commits the editor's text through a queued call.
    qtbot.waitUntil(lambda: "jaw_drop" in document.model.parameters)
    assert "jaw_open" not in document.model.parameters
    assert window.view_state.selected_parameter == "jaw_drop"       # the selection follows the name
    assert _shown_tree(window) == _tree(document)
    _check_undo_redo(document, before)
    document.undo_stack.undo()
    assert window.view_state.selected_parameter == "jaw_open"
    assert window.tree_editor.dock.selected_name() == "jaw_open"


@pytest.mark.parametrize("bad, why", [("brow_raise", "already exists"), ("9lives", "not allowed"),
                                      ("jaw open", "not allowed"), ("", "needs a name")])
def test_a_bad_name_is_explained_and_changes_nothing(window, monkeypatch, bad, why):
    warnings = _answer(monkeypatch, "warning")
    document = window.document
    before = model_state(document.model)
    model = window.tree_editor.dock.model
    assert not model.setData(model.index_of("jaw_open"), bad)
    assert len(warnings) == 1 and why in warnings[0]
    assert model_state(document.model) == before and document.undo_stack.count() == 0
    assert _row(window, "jaw_open")[0] == "jaw_open"


def test_remove_takes_the_subtree_after_asking(window, monkeypatch):
    document = window.document
    before = model_state(document.model)
    asked = _answer(monkeypatch, "question", QMessageBox.StandardButton.Cancel)
    _select(window, "head_turn")
    window.actions_by_id["parameters.remove"].trigger()
    assert len(asked) == 1 and "jaw_open" in asked[0] and "brow_raise" in asked[0]
    assert model_state(document.model) == before                  # cancelled

    _answer(monkeypatch, "question", QMessageBox.StandardButton.Yes)
    window.actions_by_id["parameters.remove"].trigger()
    assert len(document.model.parameters) == 0 and document.model.regions == {}
    assert _shown_tree(window) == {}
    assert window.view_state.selected_parameter is None
    assert document.undo_stack.undoText() == "Remove parameter head_turn and 2 below it"
    _check_undo_redo(document, before)
    document.undo_stack.undo()
    assert _shown_tree(window) == _tree(document)


def _drop(window, names, target):
    """Drop the rows ``names`` on ``target``'s row (``None``: below the rows) through the view's dropEvent."""
    view, model = window.tree_editor.dock.view, window.tree_editor.dock.model
    data = model.mimeData([model.index_of(n) for n in names])
    if target is not None:
        position = QPointF(view.visualRect(model.index_of(target)).center())
    else:
        position = QPointF(view.viewport().rect().center().x(), view.viewport().height() - 3)
    event = QDropEvent(position, Qt.DropAction.MoveAction, data, Qt.MouseButton.LeftButton,
                       Qt.KeyboardModifier.NoModifier)
    view.dropEvent(event)


def _drop_above(window, names, target):
    """Drop the rows ``names`` on the upper edge of ``target``'s row: between it and the row above."""
    view, model = window.tree_editor.dock.view, window.tree_editor.dock.model
    rect = view.visualRect(model.index_of(target))
    data = model.mimeData([model.index_of(n) for n in names])      # kept: the event does not own it
    event = QDropEvent(QPointF(rect.center().x(), rect.top() + 1), Qt.DropAction.MoveAction, data,
                       Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier)
    view.dropEvent(event)


def _children_shown(window, name):
    model = window.tree_editor.dock.model
    index = model.index_of(name)
    return [model.name_at(model.index(row, 0, index)) for row in range(model.rowCount(index))]


def test_a_drop_between_rows_places_the_parameter_there_among_its_siblings(window):
    document = window.document
    assert document.model.parameters.children("head_turn") == ["jaw_open", "brow_raise"]
    before = model_state(document.model)
    _drop_above(window, ["brow_raise"], "jaw_open")
    assert document.model.parameters.children("head_turn") == ["brow_raise", "jaw_open"]
    assert _children_shown(window, "head_turn") == ["brow_raise", "jaw_open"]
    assert document.undo_stack.undoText() == "Move brow_raise before jaw_open"
    _check_undo_redo(document, before)


def test_move_up_and_down_reorder_siblings_one_undo_step_each(window, tmp_path):
    document, actions = window.document, window.actions_by_id
    _select(window, "jaw_open")
    assert not actions["parameters.move_up"].isEnabled() and actions["parameters.move_down"].isEnabled()
    assert actions["parameters.move_down"].shortcut().toString() == "Ctrl+Shift+Down"
    before = model_state(document.model)
    actions["parameters.move_down"].trigger()
    assert _children_shown(window, "head_turn") == ["brow_raise", "jaw_open"]
    assert actions["parameters.move_up"].isEnabled() and not actions["parameters.move_down"].isEnabled()
    assert window.view_state.selected_parameter == "jaw_open"
    moved = _check_undo_redo(document, before)
    path = document.save(tmp_path / "reordered.xml")            # the order is what the file keeps
    document.open(path)
    assert document.model.parameters.children("head_turn") == ["brow_raise", "jaw_open"]
    assert model_state(document.model) == moved
    _select(window, "jaw_open")
    actions["parameters.move_up"].trigger()
    assert document.model.parameters.children("head_turn") == ["jaw_open", "brow_raise"]
    _select(window, "head_turn")                                 # a lone root has nowhere to go
    assert not actions["parameters.move_up"].isEnabled() and not actions["parameters.move_down"].isEnabled()


def test_drag_and_drop_moves_a_parameter_under_another(window):
    document = window.document
    before = model_state(document.model)
    _drop(window, ["brow_raise"], "jaw_open")
    assert document.model.parameters["brow_raise"].parent == "jaw_open"
    assert _shown_tree(window) == _tree(document)
    assert _row(window, "jaw_open")[1] == GROUP_TEXT[1]
    assert document.undo_stack.undoText() == "Move brow_raise under jaw_open"
    _check_undo_redo(document, before)


def test_drop_below_the_rows_makes_a_root(window):
    document = window.document
    before = model_state(document.model)
    _drop(window, ["jaw_open"], None)
    assert document.model.parameters["jaw_open"].parent is None
    assert _shown_tree(window) == _tree(document)
    _check_undo_redo(document, before)


def test_a_drop_that_would_loop_is_refused_with_a_message(window, monkeypatch):
    warnings = _answer(monkeypatch, "warning")
    document = window.document
    before = model_state(document.model)
    model = window.tree_editor.dock.model
    model.dropMimeData(model.mimeData([model.index_of("head_turn")]), Qt.DropAction.MoveAction, -1, -1,
                       model.index_of("jaw_open"))
    assert len(warnings) == 1 and "loop" in warnings[0]
    assert model_state(document.model) == before and document.undo_stack.count() == 0
    assert _shown_tree(window) == _tree(document)


def test_a_displacement_field_cannot_get_children(make_window, tmp_path, monkeypatch):
    from tests.workbench.synthetic_workbench_model import build_synthetic_model

    model = build_synthetic_model()
    skin = model.part_vertices("skin")[::9]
    model.add_parameter(engine.Parameter("pucker", "translation", parent="head_turn", minimum=0, field=True),
                        engine.InfluenceRegion(skin, np.full(len(skin), 0.5), np.ones((len(skin), 3))))
    path = engine.save_model(model, tmp_path / "field.xml")
    window = make_window(path)
    assert _row(window, "pucker")[2] == "field"
    warnings = _answer(monkeypatch, "warning")
    before = model_state(window.document.model)
    _select(window, "pucker")
    assert window.tree_editor.add_parameter(edit_name=False) is None
    assert len(warnings) == 1 and "displacement field" in warnings[0]
    assert model_state(window.document.model) == before


def test_another_model_replaces_the_tree(window, make_window, tmp_path):
    from tests.workbench.synthetic_workbench_model import build_synthetic_model

    other = build_synthetic_model()
    other.add_parameter(engine.Parameter("blink", "translation", direction=(0, -3, 0)))
    path = engine.save_model(other, tmp_path / "other.xml")
    _select(window, "jaw_open")
    window.document.open(path)
    assert _shown_tree(window) == _tree(window.document)
    assert "blink" in _shown_tree(window)
    assert window.tree_editor.dock.selected_name() is None


def test_an_edited_tree_survives_save_and_open(window, tmp_path, monkeypatch):
    document = window.document
    _select(window, "jaw_open")
    window.tree_editor.add_parameter(edit_name=False)
    assert window.tree_editor.rename("parameter", "lip_curl")
    _drop(window, ["brow_raise"], "jaw_open")
    window.view_state.select_parameter("lip_curl")
    sheet = window.tree_editor.sheet
    sheet.pivot.set_texts("1.5", "-30", "40.25")
    assert sheet.commit("pivot")
    sheet.axis.set_texts("0", "1", "1")
    assert sheet.commit("axis")
    sheet.minimum.setText("-0.5")
    assert sheet.commit("minimum")
    window.view_state.select_parameter("brow_raise")
    sheet.direction.set_texts("0", "2", "0.5")
    assert sheet.commit("direction")
    edited = model_state(document.model)
    path = tmp_path / "edited.xml"
    document.save(path)
    window.document.open(path)
    # The file nests children in their parents, so the order read back is depth first.
    reread = model_state(document.model)
    assert sorted(reread.pop("parameters")) == sorted(edited.pop("parameters"))
    assert reread == edited
    assert _shown_tree(window) == _tree(document)
    assert _row(window, "lip_curl") == ("lip_curl", GROUP_TEXT[2], "rotation")
    assert _row(window, "jaw_open") == ("jaw_open", GROUP_TEXT[1], "rotation")
