"""Interpolation, the timeline (additive overlap, clamping, sampling) and command files (§2.3)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.commands import Activation, load_library, parse_commands_text, translate
from engine.commands.command_files import low_level_xml, read_commands, write_low_level
from engine.commands.interpolation import INTERPOLATIONS, interpolate
from engine.errors import CommandError, UserError
from engine.timeline.timeline import Timeline

# -- interpolation ---------------------------------------------------------------

TIMES = [0, 100, 200, 400]
VALUES = [0, 1, 0.5, 0]


@pytest.mark.parametrize("kind", INTERPOLATIONS)
def test_every_interpolation_passes_through_its_keys_and_is_zero_outside(kind):
    at = np.array(TIMES, dtype=float)
    np.testing.assert_allclose(interpolate(kind, TIMES, VALUES, at), VALUES, atol=1e-15)
    np.testing.assert_array_equal(interpolate(kind, TIMES, VALUES, np.array([-1.0, 400.001, 1e9])), 0)


def test_linear_step_and_cosine_between_keys():
    at = np.array([50.0, 150.0, 300.0])
    np.testing.assert_allclose(interpolate("linear", TIMES, VALUES, at), [0.5, 0.75, 0.25])
    np.testing.assert_allclose(interpolate("step", TIMES, VALUES, at), [0, 1, 0.5])
    np.testing.assert_allclose(interpolate("cosine", TIMES, VALUES, at), [0.5, 0.75, 0.25])   # midpoints
    quarter = interpolate("cosine", [0, 100], [0, 1], np.array([25.0]))[0]
    assert quarter == pytest.approx((1 - np.cos(np.pi / 4)) / 2)


def test_cosine_and_cubic_are_flat_at_an_extremum():
    h = 1e-4
    for kind in ("cosine", "cubic"):
        left, mid, right = interpolate(kind, TIMES, VALUES, np.array([100 - h, 100.0, 100 + h]))
        assert (mid - left) / h == pytest.approx(0, abs=1e-3) and (right - mid) / h == pytest.approx(0, abs=1e-3)


def test_a_jump_is_right_continuous():
    times, values = [0, 100, 100, 200], [0, 1, 3, 0]
    for kind in INTERPOLATIONS:
        before, at, after = interpolate(kind, times, values, np.array([99.999, 100.0, 100.001]))
        assert at == 3, kind
        assert after == pytest.approx(3, abs=0.01)
        assert before == pytest.approx(1 if kind != "step" else 0, abs=0.01)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.floats(1, 500), st.floats(-5, 5)), min_size=2, max_size=12))
def test_cubic_never_overshoots_its_neighbouring_keys(steps):
    times = np.cumsum([s[0] for s in steps])
    values = np.array([s[1] for s in steps])
    at = np.linspace(times[0], times[-1], 2001)
    curve = interpolate("cubic", times, values, at)
    segment = np.clip(np.searchsorted(times, at, side="right") - 1, 0, len(times) - 2)
    low = np.minimum(values[segment], values[segment + 1])
    high = np.maximum(values[segment], values[segment + 1])
    assert np.all(curve >= low - 1e-9) and np.all(curve <= high + 1e-9)


def test_unknown_interpolation_is_refused():
    with pytest.raises(ValueError, match="unknown interpolation"):
        interpolate("spline", [0, 1], [0, 1], np.array([0.5]))


# -- the timeline ------------------------------------------------------------------

def act(parameter, keys, interp="linear"):
    t, v = zip(*keys, strict=True)
    return Activation(parameter, t, v, interp)


def test_overlapping_activations_add(head):
    a = act("head_turn", [(0, 0), (100, 0.2), (200, 0)])
    b = act("head_turn", [(100, 0), (200, 0.1), (300, 0)])
    timeline = Timeline([a, b], head)
    column = timeline.parameters.index("head_turn")
    values = timeline.sample([50, 100, 150, 200, 250, 300])[:, column]
    np.testing.assert_allclose(values, [0.1, 0.2, 0.15, 0.1, 0.05, 0])


def test_the_sum_is_clamped_to_the_parameter_range(head):
    big = [act("jaw_open", [(0, 0), (100, 0.8), (200, 0)]), act("jaw_open", [(0, 0), (100, 0.7), (200, 0)])]
    timeline = Timeline(big, head)
    assert timeline.values_at(100)["jaw_open"] == head.parameters["jaw_open"].maximum == 1
    down = Timeline([act("jaw_open", [(0, 0), (100, -5), (200, 0)])], head)
    assert down.values_at(100)["jaw_open"] == head.parameters["jaw_open"].minimum


def test_untouched_parameters_stay_at_their_default_and_every_parameter_is_sampled(head):
    timeline = Timeline([act("brow_raise", [(0, 0), (100, 1)])], head)
    values = timeline.values_at(100)
    assert list(values) == head.parameters.names
    assert values["brow_raise"] == 1
    assert all(values[n] == head.parameters[n].default for n in values if n != "brow_raise")


def test_frame_times_cover_start_to_end_inclusive(head):
    timeline = Timeline([act("brow_raise", [(0, 0), (1000, 0)])], head)
    times = timeline.frame_times(60)
    assert len(times) == 61 and times[0] == 0 and times[-1] == pytest.approx(1000)
    assert len(timeline.frame_times(25, end=100)) == 3
    with pytest.raises(UserError, match="positive"):
        timeline.frame_times(0)
    with pytest.raises(UserError, match="comes before"):
        timeline.frame_times(60, start=10, end=5)


def test_sampling_matches_pointwise_evaluation_and_any_time_order(head):
    acts = translate(parse_commands_text('<commands><HeadNod at="100" count="3"/><Blink at="300"/>'
                                         '<EyesLook at="0" x="15"/></commands>'), load_library(), head)
    timeline = Timeline(acts, head)
    times = np.array([1300.0, 0.0, 412.5, 17.0, 999.0, 412.5])
    block = timeline.sample(times)
    for t, row in zip(times, block, strict=True):
        np.testing.assert_array_equal(row, timeline.sample([t])[0])


def test_tracks_csv_layout(head):
    acts = translate(parse_commands_text('<commands><HeadNod at="1000" amplitude="60" count="2"/></commands>'),
                     load_library(), head)
    lines = Timeline(acts, head).tracks_csv(fps=4).splitlines()
    assert lines[0] == "time_ms," + ",".join(head.parameters.names)
    assert len(lines) == 1 + 9                      # 0, 250, …, 2000 ms
    nod = lines[0].split(",").index("head_nod")
    rows = [line.split(",") for line in lines[1:]]
    assert [r[0] for r in rows] == ["0", "250", "500", "750", "1000", "1250", "1500", "1750", "2000"]
    assert float(rows[5][nod]) == pytest.approx(0.09 * (250 - 166.5) / 166.5 * -1 + 0.09, abs=1e-12)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["HeadNod", "Blink", "BrowRaise", "HeadShake", "JawOpen"]),
                          st.integers(0, 3000), st.integers(10, 200)), max_size=6))
def test_translate_then_tracks_is_deterministic(head, script):
    xml = "<commands>" + "".join(f'<{n} at="{t}" amplitude="{a}"/>' for n, t, a in script) + "</commands>"
    first = Timeline(translate(parse_commands_text(xml), load_library(), head), head).tracks_csv(fps=60)
    again = Timeline(translate(parse_commands_text(xml), load_library(), head), head).tracks_csv(fps=60)
    assert first == again


# -- command files -------------------------------------------------------------------

def test_low_level_file_round_trips(tmp_path, head):
    acts = translate(parse_commands_text('<commands><HeadNod at="1000" amplitude="60" count="2"/>'
                                         '<EyesLook at="0" x="-12.5"/></commands>', "in.xml"),
                     load_library(), head)
    path = tmp_path / "low.xml"
    write_low_level(acts, path)
    back = read_commands(path)
    assert len(back) == len(acts)
    for a, b in zip(acts, back, strict=True):
        assert (a.parameter, a.interpolation, a.command, a.line, a.source) == \
               (b.parameter, b.interpolation, b.command, b.line, b.source)
        np.testing.assert_array_equal(a.times, b.times)
        np.testing.assert_array_equal(a.values, b.values)
    assert low_level_xml(back) == path.read_text()
    assert acts[0].source == "in.xml:1"


@pytest.mark.parametrize("text, line, words", [
    ("<commands>\n<HeadNod at='1'>\n</commands>", 3, "malformed XML"),
    ("<script>\n</script>", 1, "not a command file"),
    ("<commands>\n  hello <HeadNod/>\n</commands>", 1, "Character content"),
    ("<low-level-commands version='1'>\n<HeadNod/>\n</low-level-commands>", 2, "not expected"),
    ("<low-level-commands>\n</low-level-commands>", 1, "version"),
    ("<low-level-commands version='9'>\n</low-level-commands>", 1, "newer"),
    ("<commands>\n<activate parameter='x' interp='spline'><key at='0' value='1'/></activate></commands>", 2,
     "spline"),
    ("<commands>\n<activate parameter='x'>\n<key at='0' value='1'/>\n<key at='-5' value='1'/>\n"
     "</activate></commands>", 4, "must not decrease"),
    ("<commands>\n<activate parameter='x'>\n<key at='0' value='INF'/></activate></commands>", 3, "finite"),
    ("<commands>\n<activate parameter='x'>\n<key at='0'/></activate></commands>", 3, "value"),
])
def test_command_file_errors_name_file_and_line(text, line, words):
    with pytest.raises(CommandError) as caught:
        parse_commands_text(text, "in.xml")
    assert caught.value.file == "in.xml" and caught.value.line == line, str(caught.value)
    assert words in caught.value.message


def test_hostile_xml_is_neither_expanded_nor_fetched(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP SECRET")
    xxe = (f'<?xml version="1.0"?><!DOCTYPE c [<!ENTITY x SYSTEM "file://{secret}">]>'
           '<commands><HeadNod at="&x;"/></commands>')
    with pytest.raises(CommandError) as caught:
        parse_commands_text(xxe, "xxe.xml")
    assert "TOP SECRET" not in str(caught.value)
    bomb = ('<?xml version="1.0"?><!DOCTYPE c [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">'
            '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;">]><commands><HeadNod at="&c;"/></commands>')
    with pytest.raises(CommandError):
        parse_commands_text(bomb, "bomb.xml")


def test_comments_are_ignored_and_commands_keep_document_order():
    commands = parse_commands_text("<commands><!-- hi --><Blink at='5'/><?pi x?><HeadNod at='1'/></commands>")
    assert [c.name for c in commands] == ["Blink", "HeadNod"]


# -- bounds on sampling: one UserError, no overflow, no array of petabytes ---------------------------

@pytest.mark.parametrize(("fps", "end", "words"), [
    (1e308, None, "at most 1000"),
    (float("nan"), None, "positive"),
    (60.0, float("nan"), "beyond the longest timeline"),
    (60.0, 1e308, "beyond the longest timeline"),
    (1000.0, 86_400_000.0, "more than 5000000"),
], ids=["fps-1e308", "fps-nan", "end-nan", "end-1e308", "too-many-frames"])
def test_sampling_beyond_the_bounds_is_one_user_error(head, fps, end, words):
    timeline = Timeline([act("brow_raise", [(0, 0), (1000, 0.5)])], head)
    with pytest.raises(UserError, match=words):
        timeline.frame_times(fps, end=end)


def test_a_timeline_whose_keys_are_all_before_the_start_samples_the_start_frame(head):
    timeline = Timeline([act("brow_raise", [(-500, 0), (-100, 0.5)])], head)
    assert timeline.frame_times(60).tolist() == [0.0]


@pytest.mark.parametrize("name", ["AU" + "1" * 5000, "AU\u0663"])
def test_action_units_with_numbers_int_cannot_read_still_sort(name):
    from engine.timeline.expressions import _unit_order

    assert _unit_order(name)[1] == name


def test_the_timeline_and_the_live_head_both_call_the_one_rule(monkeypatch):
    """Issue 35 item 3: ``AnimationRule.values`` (base + sum of activations + clamp) is the only place both
    the offline timeline and the live head turn activations into values."""
    from engine import load_model
    from engine.live.head import LiveHead
    from engine.timeline.rule import AnimationRule

    head = load_model()
    calls = []
    real = AnimationRule.values

    def counted(self, times, placed, base=None):
        calls.append(len(times))
        return real(self, times, placed, base)

    monkeypatch.setattr(AnimationRule, "values", counted)
    nod = [Activation("head_nod", np.array([0.0, 100.0, 200.0]), np.array([0.0, 0.2, 0.0]))]
    offline = Timeline(nod, head).sample([0.0, 100.0, 150.0])
    assert calls == [3]
    live = LiveHead(head)
    live.add_commands(0.0, "c", None, nod)
    for k, t in enumerate([0.0, 100.0, 150.0]):
        live.advance(t)
        np.testing.assert_array_equal(live.current, offline[k])
    assert calls == [3, 1, 1, 1]
