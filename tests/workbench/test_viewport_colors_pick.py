"""The viewport's shared services for the tools: heat map of the selected parameter, colours, picking."""

from __future__ import annotations

import numpy as np
import pytest

from engine.painting import heat_colors
from workbench.document.playhead import Playhead


@pytest.fixture
def window(reused_window):
    """One main window for this module's tests, reset before each (``reused_window``, tests/workbench/conftest.py)."""
    return reused_window


def _painted_parameter(window) -> str:
    model = window.document.model
    return next(n for n in model.parameters.names if len(model.regions[n].indices))


def test_selecting_a_parameter_shows_its_weights_as_a_heat_map(window):
    viewport, view_state = window.viewport, window.view_state
    ordinary = viewport.displayed_colors()
    name = _painted_parameter(window)
    view_state.select_parameter(name)
    model = window.document.model
    expected = heat_colors(model.regions[name].dense(model.n_vertices), base=ordinary)
    assert np.array_equal(viewport.displayed_colors(), expected)
    view_state.set_heat_map(False)
    assert np.array_equal(viewport.displayed_colors(), ordinary)
    view_state.set_heat_map(True)
    view_state.select_parameter(None)
    assert np.array_equal(viewport.displayed_colors(), ordinary)


def test_tool_colours_override_and_update_in_part(window):
    viewport = window.viewport
    n = window.document.model.n_vertices
    grey = np.full((n, 3), 90, dtype=np.uint8)
    viewport.show_colors(grey)
    assert np.array_equal(viewport.displayed_colors(), grey)
    viewport.update_colors([0, 5], [[1, 2, 3], [4, 5, 6]])
    shown = viewport.displayed_colors()
    assert shown[0].tolist() == [1, 2, 3] and shown[5].tolist() == [4, 5, 6]
    assert (shown[1:5] == 90).all()
    viewport.show_colors(None)
    assert not (viewport.displayed_colors() == 90).all()


def _fresh_normals(mesh) -> np.ndarray:
    """Vertex normals computed from scratch from what the mesh holds now."""
    from tests.workbench.normals import whole_mesh_normals

    return whole_mesh_normals(mesh.points.copy(), mesh.faces.copy())


def test_shading_follows_the_pose_and_a_colour_change_recomputes_nothing(window):
    """Normals live on the drawn mesh: a pose and a live-preview move recompute them, a brush dab's
    colour change leaves them (and the points) untouched, so drawing it costs no pipeline work."""
    import pyvista as pv

    viewport, document = window.viewport, window.document
    skin = pv.wrap(viewport.part_actor("skin").GetMapper().GetInput())     # what is drawn
    rest_normals = np.array(skin.point_data["Normals"])
    assert np.allclose(rest_normals, _fresh_normals(skin), atol=1e-6)
    rotation = next(n for n in document.model.parameters.names
                    if document.model.parameters[n].kind == "rotation"
                    and np.isin(viewport._parts["skin"].vertex_indices, document.model.regions[n].indices).any())
    document.set_values({rotation: 0.8})
    posed = np.array(skin.point_data["Normals"])
    assert not np.allclose(posed, rest_normals, atol=1e-3)
    assert np.allclose(posed, _fresh_normals(skin), atol=1e-6)

    normals_array = skin.GetPointData().GetNormals()
    points_time = skin.GetPoints().GetMTime()
    viewport.update_colors(np.arange(50), np.full((50, 3), 200, dtype=np.uint8))
    assert skin.GetPointData().GetNormals() is normals_array
    assert skin.GetPoints().GetMTime() == points_time

    moved = document.vertices()[viewport._parts["skin"].vertex_indices[:200]] + [0.0, 0.0, 3.0]
    viewport.update_points(viewport._parts["skin"].vertex_indices[:200], moved)
    assert np.allclose(skin.points[:200], moved)
    assert np.allclose(skin.point_data["Normals"], _fresh_normals(skin), atol=1e-6)


def test_pick_finds_the_surface_under_the_pixel(window):
    viewport = window.viewport
    viewport.render_now()
    cx, cy = viewport.plotter.width() / 2, viewport.plotter.height() / 2
    hit = viewport.pick(cx, cy)
    assert hit is not None and hit.part == "skin"
    x, y = viewport.world_to_widget(hit.point)
    assert abs(x - cx) < 1.5 and abs(y - cy) < 1.5
    vertex = window.document.vertices()[hit.vertex]
    assert np.linalg.norm(vertex - hit.point) < 15.0           # a corner of the hit polygon
    assert viewport.pick(2, 2) is None                         # the background


def test_playhead_clamps_and_counts_frames(qtbot):
    playhead = Playhead()
    playhead.set_range(2.0, fps=30)
    assert playhead.n_frames == 61
    with qtbot.waitSignal(playhead.time_changed):
        playhead.set_frame(15)
    assert playhead.time == 0.5 and playhead.frame == 15
    playhead.set_time(9.0)
    assert playhead.time == 2.0


def _brute_force_pick(viewport, x, y):
    """The same pick by a fresh vtkCellPicker testing every polygon (no cell locator)."""
    from vtkmodules.vtkRenderingCore import vtkCellPicker

    picker = vtkCellPicker()
    picker.SetTolerance(viewport._picker.GetTolerance())
    picker.PickFromListOn()
    for part in viewport.part_names:
        if viewport.part_actor(part).GetVisibility():
            picker.AddPickList(viewport.part_actor(part))
    height = viewport.plotter.render_window.GetSize()[1]
    ratio = viewport.plotter.devicePixelRatioF()
    assert picker.Pick(x * ratio, height - 1 - y * ratio, 0.0, viewport.plotter.renderer)
    return np.array(picker.GetPickPosition())


def test_picking_follows_the_drawn_surface_after_it_moves(window):
    """Picks go through a cell locator per part, rebuilt when the drawn points move (a pose, a
    live-preview dab): each pick agrees with testing every polygon."""
    viewport, document = window.viewport, window.document
    viewport.render_now()
    cx, cy = viewport.plotter.width() / 2, viewport.plotter.height() / 2
    pixels = [(cx, cy), (cx - 20, cy + 15), (cx + 25, cy - 30)]
    for x, y in pixels:
        hit = viewport.pick(x, y)
        assert hit is not None and np.linalg.norm(hit.point - _brute_force_pick(viewport, x, y)) < 0.2
    skin = viewport._parts["skin"].vertex_indices
    viewport.update_points(skin, document.vertices()[skin] + [15.0, 10.0, 12.0])
    viewport.render_now()
    for x, y in pixels:
        hit = viewport.pick(x, y)
        assert hit is not None and np.linalg.norm(hit.point - _brute_force_pick(viewport, x, y)) < 0.2
