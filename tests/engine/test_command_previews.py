"""Previews of commands without a GUI: the expressions a model can show (engine.timeline.expressions) and
what a library file's text says (engine.commands.analysis). The workbench's expression gallery and library
editor show exactly these.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.commands import load_library, parse_commands_text, translate
from engine.commands.analysis import check_library_text, command_arguments
from engine.errors import UserError
from engine.paths import LIBRARY_DIR
from engine.timeline.command_curves import command_curves
from engine.timeline.expressions import AU_TIMING, ORDER, GalleryEntry, full_value, gallery_entries
from engine.timeline.timeline import Timeline

SWING = """# brow_raise swung up and down, count times
$command = BrowSwing
$description = brows up and down
$mandatory = at
$optional = amplitude=100, count=2, period=400
$interp = cosine
brow_raise = 0,0; 200,0.8; 400,0
$proc = periodic
"""


@pytest.fixture(scope="module")
def entries(head) -> list[GalleryEntry]:
    return gallery_entries(load_library(), head)


# -- expressions -----------------------------------------------------------------------------------

def test_the_default_head_shows_the_paper_emotions_first_and_its_35_action_units(entries):
    expressions = [e.name for e in entries if e.kind == "expression"]
    units = [e.name for e in entries if e.kind == "action-unit"]
    assert expressions[:len(ORDER)] == list(ORDER)
    assert expressions[len(ORDER):] == sorted(expressions[len(ORDER):])
    assert len(units) == 35 and all(u.startswith("AU") for u in units)
    numbers = [int(u[2:].split("_")[0]) for u in units]
    assert numbers == sorted(numbers)
    assert all(e.timing == (AU_TIMING["onset"], AU_TIMING["apex"], AU_TIMING["offset"])
               for e in entries if e.kind == "action-unit")


def test_an_expression_plays_as_the_command_a_script_would_write(entries, head):
    happy = next(e for e in entries if e.name == "Happy")
    script = parse_commands_text('<commands><Happy at="0" amplitude="40"/></commands>')
    expected = Timeline(translate(script, load_library(), head), head)
    preview = happy.timeline(head, 40)
    times = np.linspace(0, expected.end, 23)
    np.testing.assert_allclose(preview.sample(times), expected.sample(times))
    assert happy.pose(head)["AU12_left"] == pytest.approx(1.0)          # the middle of the apex
    onset, apex, _ = happy.timing
    assert happy.apex_time == onset + apex / 2


def test_an_action_unit_rises_to_its_full_value_and_back(entries, head):
    unit = next(e for e in entries if e.kind == "action-unit")
    parameter = head.parameters[unit.name]
    timeline = unit.timeline(head, 50)
    onset, apex, offset = unit.timing
    assert timeline.values_at(onset + apex / 2)[unit.name] == pytest.approx(
        parameter.default + 0.5 * (full_value(parameter) - parameter.default))
    assert timeline.values_at(0)[unit.name] == timeline.values_at(onset + apex + offset)[unit.name] == \
        pytest.approx(parameter.default)


def test_a_model_without_action_units_shows_every_parameter_and_only_commands_that_fit(head):
    from tests.engine.synthetic import random_model

    model = random_model(np.random.default_rng(4), n_vertices=20, n_parameters=4, depth=2)
    entries = gallery_entries(load_library(), model)
    assert [e.name for e in entries if e.kind == "action-unit"] == model.parameters.names
    assert [e for e in entries if e.kind == "expression"] == []      # the shipped commands drive other names


def test_full_value_is_the_far_end_of_the_range(head):
    from dataclasses import replace

    parameter = head.parameters["jaw_open"]
    assert full_value(parameter) == parameter.maximum
    assert full_value(replace(parameter, minimum=-5.0, maximum=1.0, default=0.0)) == -5.0


def test_an_expression_entry_without_a_library_says_so(head):
    with pytest.raises(UserError, match="no library"):
        GalleryEntry("expression", "Happy", "", (1.0, 1.0, 1.0)).timeline(head)


# -- library analysis ------------------------------------------------------------------------------

def test_every_shipped_library_file_checks_clean_on_the_default_head(head):
    for path in sorted(LIBRARY_DIR.glob("*.lib")):
        result = check_library_text(path.read_text(encoding="utf-8"), path.name, head)
        assert result.ok, (path.name, result.problems)
        assert result.definitions


def test_a_syntax_error_stops_the_parse_and_binding_problems_are_all_listed(head):
    broken = check_library_text("$command = X\n$interp = wobbly\nx = 0,0; 1,1\n", "x.lib")
    assert broken.definitions == [] and [p.line for p in broken.problems] == [2]
    assert broken.problems[0].text.startswith("x.lib:2:")
    two_unfit = SWING + SWING.replace("BrowSwing", "Other").replace("brow_raise", "no_such_parameter") + \
        SWING.replace("BrowSwing", "Third").replace("brow_raise", "nor_this")
    result = check_library_text(two_unfit, "mine.lib", head)
    assert [d.name for d in result.definitions] == ["BrowSwing", "Other", "Third"]
    assert len(result.problems) == 2 and all("does not have" in p.message for p in result.problems)
    assert [p.line for p in result.problems] == [15, 23]             # the curve line of each copy
    assert check_library_text(two_unfit, "mine.lib").ok                  # without a model: syntax only


def test_command_curves_are_what_the_timeline_of_the_same_command_does(head, tmp_path):
    definition = check_library_text(SWING, "BrowSwing.lib").definitions[0]
    curves = command_curves(definition, head, {"count": 3, "amplitude": 50})
    (tmp_path / "BrowSwing.lib").write_text(SWING)
    script = parse_commands_text('<commands><BrowSwing at="0" count="3" amplitude="50"/></commands>')
    timeline = Timeline(translate(script, load_library([tmp_path]), head), head)
    times, values = curves.curves["brow_raise"]
    assert list(curves.curves) == ["brow_raise"] and curves.end == timeline.end == 1200
    assert times[0] == 0 and times[-1] == 1200
    np.testing.assert_allclose(values, timeline.sample(times)[:, timeline.parameters.index("brow_raise")],
                               atol=1e-12)
    assert values.max() == pytest.approx(0.4)
    with pytest.raises(UserError, match="count must be positive"):
        command_curves(definition, head, {"count": 0})


def test_command_arguments_leave_out_the_defaults(head):
    definition = check_library_text(SWING, "BrowSwing.lib").definitions[0]
    assert command_arguments(definition, {"count": 2, "period": 300, "amplitude": 100}) == {"period": 300.0,
                                                                                            "at": 0.0}
