"""The viewport's shared services for the tools: heat map of the selected parameter, colours, picking."""

from __future__ import annotations

import numpy as np

from engine.painting import heat_colors
from workbench.playhead import Playhead


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
