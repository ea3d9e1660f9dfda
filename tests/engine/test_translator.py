"""The command translator (§2.3): the paper's worked example, procedures, arguments, errors."""

from __future__ import annotations

import numpy as np
import pytest

from engine.commands import Library, load_library, parse_commands_text, parse_library_text, translate
from engine.commands.command_files import low_level_xml
from engine.commands.procedures import ArgumentProblem, Arguments, periodic_timing, register_procedure, stretch
from engine.errors import CommandError, LibraryError
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree


def synthetic_model():
    """Three vertices, one triangle, one translation parameter 'lift'."""
    tree = ParameterTree([Parameter("lift", "translation", direction=(0, 1, 0))])
    return Model([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [3, 0, 1, 2], parameters=tree,
                 regions={"lift": InfluenceRegion(np.arange(3), np.ones(3))}, name="tiny")

PAPER_KEYS = [(1000, 0), (1166.5, 0.09), (1333, 0), (1416.5, -0.015), (1500, 0),
              (1666.5, 0.09), (1833, 0), (1916.5, -0.015), (2000, 0)]



@pytest.fixture(scope="module")
def library():
    return load_library()


def run(xml: str, library, model):
    return translate(parse_commands_text(f"<commands>{xml}</commands>", "script.xml"), library, model)


def keys(activation):
    return list(zip(activation.times.tolist(), activation.values.tolist(), strict=True))


def test_paper_worked_example_to_the_digit(head, library):
    """§2.3: <HeadNod at="1000" amplitude="60" count="2"> → exactly nine keys."""
    [nod] = run('<HeadNod at="1000" amplitude="60" count="2"/>', library, head)
    assert nod.parameter == "head_nod"
    assert nod.interpolation == "linear"
    assert keys(nod) == PAPER_KEYS
    text = low_level_xml([nod])
    printed = [f'<key at="{t:g}" value="{v:g}"/>' for t, v in PAPER_KEYS]
    assert [line.strip() for line in text.splitlines() if line.strip().startswith("<key")] == printed


def _definition(text):
    [d] = parse_library_text(text, "test.lib")
    return Library([d])


NOD_LIKE = "$command = Nod\n$mandatory = at\n$optional = {optional}\n$interp = linear\n" \
           "amplitude = 0,0; 500,1; 1000,0\n$proc = periodic\n$parameter = head_nod\n"


def timing(optional: str, given: str):
    library = _definition(NOD_LIKE.format(optional=optional))
    from engine.commands.command_files import HighLevelCommand
    from engine.commands.translator import command_arguments

    arguments = {k: float(v) for k, v in (p.split("=") for p in given.split())} if given else {}
    args = command_arguments(HighLevelCommand("Nod", {"at": 0, **arguments}), library["Nod"])
    return periodic_timing(args, 1000.0)


@pytest.mark.parametrize("given, expected", [
    ("", (1, 500)),                         # defaults: period first, then count
    ("count=2", (2, 500)),                  # the paper's example
    ("count=3", (3, 500)),
    ("end=2000", (4, 500)),                 # repeat the default period until end
    ("end=1200", (2, 600)),                 # end honoured exactly: whole count, period adjusted
    ("period=250", (1, 250)),
    ("frequency=4", (1, 250)),
    ("count=2 end=3000", (2, 1500)),
    ("period=300 end=900", (3, 300)),
    ("frequency=2 count=3", (3, 500)),
    ("count=2 period=400 end=800", (2, 400)),   # three given, consistent
    ("period=500 frequency=2", (1, 500)),        # consistent
])
def test_periodic_precedence(given, expected):
    count, period = timing("amplitude=100, count=1, period=500, frequency=1, end=1000", given)
    assert (count, period) == pytest.approx(expected)


@pytest.mark.parametrize("given, words", [
    ("period=500 frequency=1", "disagree"),
    ("count=2 period=400 end=1000", "disagree"),
    ("count=1.5", "whole number"),
    ("count=0", "positive"),
    ("period=-3", "positive"),
])
def test_periodic_conflicts_are_errors(given, words):
    with pytest.raises(ArgumentProblem, match=words):
        timing("amplitude=100, count=1, period=500, frequency=1, end=1000", given)


def test_periodic_without_library_defaults_uses_the_template_length():
    assert timing("count=1", "") == (1, 1000)
    assert timing("count=1", "count=3") == (3, 1000)
    assert timing("end=1000", "") == (1, 1000)


def test_periodic_with_only_end_default_and_a_given_count():
    assert timing("end=1000, count=1", "count=4") == (4, 250)


def test_periodic_conflict_becomes_a_command_error_with_the_line(head, library):
    with pytest.raises(CommandError) as caught:
        run('\n<HeadNod at="0" period="500" frequency="1"/>', library, head)
    assert caught.value.line == 2 and "disagree" in caught.value.message


def test_amplitude_scales_every_activation_by_percent(head, library):
    full = run('<Blink at="0"/>', library, head)
    half = run('<Blink at="0" amplitude="50"/>', library, head)
    assert len(full) == 2
    for a, b in zip(full, half, strict=True):
        np.testing.assert_allclose(b.values, a.values * 0.5)
        np.testing.assert_array_equal(a.times, b.times)


def test_once_stretches_the_template_to_duration(head, library):
    [left, right] = run('<Blink at="500" duration="600"/>', library, head)
    assert left.parameter == "eyelid_left_close" and right.parameter == "eyelid_right_close"
    assert keys(left) == [(500, 0), (700, 1), (780, 1), (1100, 0)]
    [left, _] = run('<Blink at="500"/>', library, head)
    assert keys(left) == [(500, 0), (600, 1), (640, 1), (800, 0)]


def test_once_without_duration_keeps_the_template_as_written():
    library = _definition("$command = Sweep\nbrow_raise = 0,0; 40,1; 100,0\n")
    [a] = run('<Sweep at="10"/>', library, synthetic_model_with_brow())
    assert keys(a) == [(10, 0), (50, 1), (110, 0)]


def synthetic_model_with_brow():
    model = synthetic_model()
    model.add_parameter(Parameter("brow_raise", "translation", direction=(0, 1, 0)))
    return model



def test_attack_hold_release_with_a_level(head, library):
    [jaw] = run('<JawOpen at="100" onset="200" apex="300" offset="400"/>', library, head)
    assert keys(jaw) == [(100, 0), (300, 0.8), (600, 0.8), (1000, 0)]
    assert jaw.interpolation == "cosine"


def test_attack_hold_release_cuts_a_curve_at_its_peak():
    library = _definition("$command = Surprise\n$optional = onset=100, apex=200, offset=300\n"
                          "brow_raise = 0,0; 10,0.5; 20,1; 30,1; 35,0.8; 40,1; 60,0.2; 80,0\n"
                          "$proc = attack-hold-release\n")
    [a] = run('<Surprise at="0"/>', library, synthetic_model_with_brow())
    # onset 0..20 → 0..100, apex 20..40 → 100..300, offset 40..80 → 300..600
    assert keys(a) == [(0, 0), (50, 0.5), (100, 1), (200, 1), (250, 0.8), (300, 1), (450, 0.2), (600, 0)]


def test_attack_hold_release_zero_phases_do_not_repeat_keys(head, library):
    [jaw] = run('<JawOpen at="0" onset="0" apex="0" offset="100"/>', library, head)
    assert keys(jaw) == [(0, 0), (0, 0.8), (100, 0)]        # a jump up at 0, then down


def test_negative_durations_are_rejected(head, library):
    with pytest.raises(CommandError, match="onset must not be negative"):
        run('<JawOpen at="0" onset="-1"/>', library, head)


def test_scaled_lines_and_their_arguments(head, library):
    look = run('<EyesLook at="0" x="20" y="-10"/>', library, head)
    levels = {a.parameter: a.values.max() if a.values.max() > 0 else a.values.min() for a in look}
    assert levels["eye_left_turn"] == pytest.approx(20 * 0.0174533)
    assert levels["eye_right_turn"] == pytest.approx(20 * 0.0174533)
    assert levels["eye_left_raise"] == pytest.approx(-10 * 0.0174533)
    wink = run('<Wink at="0" left="0" right="1"/>', library, head)
    peak = {a.parameter: a.values.max() for a in wink}
    assert peak == {"eyelid_left_close": 0, "eyelid_right_close": 1}


@pytest.mark.parametrize("xml, words", [
    ('<HeadNod amplitude="60"/>', "needs the argument 'at'"),
    ('<HeadNod at="0" cuont="2"/>', "has no argument 'cuont' (did you mean 'count'?)"),
    ('<HeadNodd at="0"/>', "unknown command <HeadNodd> (did you mean 'HeadNod'?)"),
    ('<HeadNod at="soon"/>', "is not a number: 'soon'"),
    ('<HeadNod at="0" count="inf"/>', "finite"),
    ('<HeadNod at="0"><x/></HeadNod>', "holds content"),
])
def test_command_errors_name_file_and_line(head, library, xml, words):
    with pytest.raises(CommandError) as caught:
        run("\n\n" + xml, library, head)
    assert caught.value.file == "script.xml"
    assert caught.value.line == 3
    assert words in caught.value.message


def test_a_line_for_a_parameter_the_model_lacks_is_reported_at_the_library_line():
    library = _definition("$command = Smile\n\nlip_corner_pull = 0,0; 100,1\n")
    with pytest.raises(LibraryError) as caught:
        run('<Smile at="0"/>', library, synthetic_model())
    assert (caught.value.file, caught.value.line) == ("test.lib", 3)
    assert "does not have" in caught.value.message
    assert library.check(synthetic_model()) and library.check(synthetic_model())[0].line == 3
    with pytest.raises(LibraryError):
        library.bind(synthetic_model())


def test_amplitude_line_maps_to_parameter_directive_command_name_or_snake_case(head):
    by_name = _definition("$command = head_nod\namplitude = 0,0; 10,1\n")
    by_snake = _definition("$command = HeadNod\namplitude = 0,0; 10,1\n")
    by_directive = _definition("$command = Yes\n$parameter = head_nod\namplitude = 0,0; 10,1\n")
    for library, name in ((by_name, "head_nod"), (by_snake, "HeadNod"), (by_directive, "Yes")):
        assert library.parameters_of(name, head) == ["head_nod"]
    nothing = _definition("$command = Frown\namplitude = 0,0; 10,1\n")
    with pytest.raises(LibraryError, match="neither 'Frown' nor 'frown'"):
        nothing.parameters_of("Frown", head)
    missing = _definition("$command = Yes\n$parameter = nodding\namplitude = 0,0; 10,1\n")
    with pytest.raises(LibraryError) as caught:
        missing.parameters_of("Yes", head)
    assert caught.value.line == 2


def test_low_level_activations_pass_through(head, library):
    out = run('<activate parameter="jaw_open" interp="step"><key at="0" value="0.2"/>'
              '<key at="100" value="0"/></activate><Blink at="0"/>', library, head)
    assert [a.parameter for a in out] == ["jaw_open", "eyelid_left_close", "eyelid_right_close"]
    assert out[0].interpolation == "step" and keys(out[0]) == [(0, 0.2), (100, 0)]


def test_an_activation_of_an_unknown_parameter_is_reported_at_its_element(head, library):
    with pytest.raises(CommandError) as caught:
        run('\n<activate parameter="jaw_opne"><key at="0" value="1"/></activate>', library, head)
    assert caught.value.line == 2 and "did you mean 'jaw_open'" in caught.value.message


def test_registering_a_new_procedure(head):
    @register_procedure("twice-test", arguments=("gap",), required=("gap",))
    def twice(times, values, span, args):
        one = stretch(times, span, 0.0, span[1] - span[0])
        return np.concatenate([one, one + one[-1] + args["gap"]]), np.concatenate([values, values])

    library = _definition("$command = DoubleNod\n$optional = gap=100\n$parameter = head_nod\n"
                          "amplitude = 0,0; 50,0.1; 100,0\n$proc = twice-test\n")
    [a] = run('<DoubleNod at="0" gap="20"/>', library, head)
    assert keys(a) == [(0, 0), (50, 0.1), (100, 0), (120, 0), (170, 0.1), (220, 0)]


def test_every_shipped_command_moves_the_default_head(head, library):
    expected = {"HeadNod": ["head_nod"], "HeadShake": ["head_turn"], "HeadTurn": ["head_turn"],
                "HeadTilt": ["head_tilt"], "Blink": ["eyelid_left_close", "eyelid_right_close"],
                "Wink": ["eyelid_left_close", "eyelid_right_close"],
                "EyesLook": ["eye_left_turn", "eye_right_turn", "eye_left_raise", "eye_right_raise"],
                "BrowRaise": ["brow_raise"], "JawOpen": ["jaw_open"]}
    assert set(expected) <= set(library.names())
    assert library.bind(head) is library
    from engine.timeline.timeline import Timeline

    for name, parameters in expected.items():
        args = ' x="20" y="10"' if name == "EyesLook" else ""
        acts = run(f'<{name} at="0"{args}/>', library, head)
        assert [a.parameter for a in acts] == parameters
        timeline = Timeline(acts, head)
        _times, values = timeline.sample_frames(fps=30)
        busiest = int(np.abs(values).sum(axis=1).argmax())
        moved = head.deform(dict(zip(timeline.parameters, values[busiest], strict=True)))
        rest = head.deform({})
        assert np.abs(moved - rest).max() > 1.0, name      # more than a millimetre somewhere


def test_user_library_overrides_shipped_and_duplicates_in_one_folder_are_errors(tmp_path, head):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "nod.lib").write_text("$command = HeadNod\n$optional = count=1\n$parameter = head_nod\n"
                                  "amplitude = 0,0; 100,0.3; 200,0\n$proc = periodic\n")
    library = load_library([mine])
    assert library["HeadNod"].file.endswith("nod.lib")
    assert library.overridden["HeadNod"][0].file.endswith("HeadNod.lib")
    [a] = run('<HeadNod at="0"/>', library, head)
    assert a.values.max() == pytest.approx(0.3)
    (mine / "again.lib").write_text("$command = HeadNod\namplitude = 0,0; 1,1\n")
    with pytest.raises(LibraryError, match="defined twice in one library folder"):
        load_library([mine])
    with pytest.raises(LibraryError, match="does not exist"):
        load_library([tmp_path / "nowhere"])
    single = load_library([mine / "nod.lib"], shipped=False)
    assert single.names() == ["HeadNod"]


def test_arguments_mapping_reports_what_was_given():
    args = Arguments({"count": 2.0, "period": 500.0}, {"count"})
    assert args.is_given("count") and not args.is_given("period") and dict(args) == {"count": 2, "period": 500}


# -- bounds: a command can ask for anything a float holds; it gets one error, fast ------------------------

@pytest.mark.parametrize(("xml", "words"), [
    ('<HeadNod at="0" count="1e9"/>', "more than 1000000"),
    ('<HeadNod at="0" count="1e300"/>', "more than 1000000"),
    ('<HeadNod at="0" period="1e-300" end="1000"/>', "more than 1000000"),
    ('<HeadNod at="0" frequency="1e300" end="1000"/>', "more than 1000000"),
    ('<HeadNod at="1e308"/>', "beyond the longest timeline"),
    ('<HeadNod at="-1e308"/>', "beyond the longest timeline"),
    ('<HeadNod at="0" period="1e300"/>', "beyond the longest timeline"),
    ('<Blink at="0" duration="1e308"/>', "beyond the longest timeline"),
    ('<Happy at="0" onset="1e308"/>', "beyond the longest timeline"),
    ('<HeadNod at="0" amplitude="1e308"/>', "beyond ±1e[+]06 parameter units"),
], ids=["count-1e9", "count-1e300", "tiny-period", "huge-frequency", "at-1e308", "at-minus-1e308",
        "period-1e300", "duration-1e308", "onset-1e308", "amplitude-1e308"])
def test_commands_beyond_the_documented_bounds_are_one_error_naming_the_command(head, library, xml, words):
    with pytest.raises(CommandError, match=words) as caught:
        run(xml, library, head)
    assert str(caught.value).startswith("script.xml:1:")


def test_a_command_at_the_bounds_still_translates(head, library):
    [nod] = run('<HeadNod at="86398000" count="2"/>', library, head)
    assert nod.end == 86_399_000
    [many] = run('<HeadNod at="0" count="100000"/>', library, head)
    assert len(many.times) < 1_000_000


def test_library_times_beyond_a_day_are_refused():
    with pytest.raises(LibraryError, match=r"x.lib:3: .*beyond the longest timeline"):
        parse_library_text("$command = Far\n$proc = once\njaw_open = 0,0; 1e300,1\n", "x.lib")


def test_low_level_key_times_beyond_a_day_are_refused():
    xml = ('<low-level-commands format="artificial-person-low-level-commands" version="1">\n'
           '<activate parameter="jaw_open"><key at="0" value="0"/>\n<key at="1e308" value="0.2"/></activate>'
           '</low-level-commands>')
    with pytest.raises(CommandError, match=r"low.xml:3: .*beyond the longest timeline"):
        parse_commands_text(xml, "low.xml")


@pytest.mark.parametrize(("version", "words"), [("9" * 5000, "newer than this program reads"),
                                                ("\u00b2", "not a valid value")])
def test_a_format_version_int_cannot_read_is_one_error(version, words):
    xml = f'<low-level-commands format="artificial-person-low-level-commands" version="{version}"/>'
    with pytest.raises(CommandError, match=words):
        parse_commands_text(xml, "low.xml")


def test_an_activation_whose_source_line_is_not_ascii_digits_names_the_source_alone():
    from engine.commands import Activation

    where = Activation("jaw_open", [0.0], [0.0], source="in.xml:\u00b2").where()
    assert where == {"file": "in.xml:\u00b2", "line": None}
