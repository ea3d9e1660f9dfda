"""ModelDocument and ViewState: the state the widgets share, and the signals they listen to."""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest

import engine
import workbench
from tests.workbench.synthetic_workbench_model import build_synthetic_model
from workbench.document.model_document import ModelDocument
from workbench.document.view_state import ViewState
from workbench.viewport.colors import EYE, EYELASHES, SKIN, TEETH, TONGUE, default_part_color, part_color


@pytest.fixture
def document(qapp):
    return ModelDocument(build_synthetic_model())


def test_values_start_at_defaults_and_vertices_at_rest(document):
    assert document.values == document.model.default_values()
    assert document.is_at_rest()
    np.testing.assert_array_equal(document.vertices(), document.model.vertices)


def test_set_values_emits_once_with_the_changed_names(document, qtbot):
    with qtbot.waitSignal(document.values_changed) as signal:
        document.set_values({"jaw_open": 0.3, "head_turn": 0.0})
    assert signal.args == [["jaw_open"]]
    np.testing.assert_array_equal(document.vertices(), document.model.deform({"jaw_open": 0.3}))
    with qtbot.assertNotEmitted(document.values_changed):
        document.set_value("jaw_open", 0.3)


def test_out_of_range_and_unknown_values_are_refused(document):
    with pytest.raises(engine.ParameterError, match="outside its range"):
        document.set_value("jaw_open", 2.0)
    with pytest.raises(engine.ParameterError, match="did you mean 'jaw_open'"):
        document.set_value("jaw_opne", 0.1)
    assert document.is_at_rest()


def test_failed_open_changes_nothing(document, broken_model_path, qtbot):
    model = document.model
    document.set_value("brow_raise", 0.5)
    with qtbot.assertNotEmitted(document.model_replaced), pytest.raises(engine.ModelFileError):
        document.open(broken_model_path)
    assert document.model is model and document.value("brow_raise") == 0.5


def test_open_replaces_the_model_and_resets_the_pose(document, synthetic_model_path, qtbot):
    document.set_value("brow_raise", 0.5)
    with qtbot.waitSignal(document.model_replaced):
        document.open(synthetic_model_path)
    assert document.path == synthetic_model_path
    assert document.is_at_rest()


def test_view_state_signals_only_real_changes(qapp, qtbot):
    state = ViewState()
    with qtbot.waitSignal(state.part_visibility_changed) as signal:
        state.set_part_visible("eye_left", False)
    assert signal.args == ["eye_left", False]
    with qtbot.assertNotEmitted(state.part_visibility_changed):
        state.set_part_visible("eye_left", False)
    state.show_all_parts()
    assert state.hidden_parts == frozenset()
    with qtbot.assertNotEmitted(state.wireframe_changed):
        state.set_wireframe(False)


def test_default_part_colours_by_name():
    assert default_part_color("skin") == SKIN
    assert default_part_color("eye_left") == default_part_color("eye_right") == EYE
    assert default_part_color("eyelashes_left") == EYELASHES
    assert default_part_color("teeth_upper") == default_part_color("teeth_lower") == TEETH
    assert default_part_color("tongue") == TONGUE


def test_model_colours_win_over_defaults():
    model = build_synthetic_model()
    model.part_colors["eye_left"] = "#336699"
    assert part_color(model, "eye_left") == "#336699"
    assert part_color(model, "eye_right") == EYE


def test_only_the_viewport_imports_pyvista():
    """Among the workbench's modules, only the viewport's (its parts, picking and point overlays), the tools'
    named drawing modules, and the plain window of ``serve --window`` (one VTK view in Qt, no workbench)."""
    package = Path(workbench.__file__).parent
    importers = set()
    for path in package.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            if any(n.split(".")[0] in ("pyvista", "pyvistaqt", "vtk", "vtkmodules") for n in names):
                importers.add(path.relative_to(package).as_posix())
    assert importers == {"viewport/view.py", "viewport/parts.py", "viewport/picking.py", "viewport/points.py",
                         "painting/cursor.py", "tree_editor/gizmo.py", "mocap/marker_overlay.py", "live_window.py"}
