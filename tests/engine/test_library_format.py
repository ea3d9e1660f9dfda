"""Library files in the §2.3 format: parsing, and every error naming file and line."""

from __future__ import annotations

import contextlib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.commands.library_format import load_library_file, parse_library_text
from engine.errors import LibraryError, UserError
from engine.paths import LIBRARY_DIR

PAPER_HEADNOD = """\
$command = HeadNod
$mandatory = at
$optional = amplitude=100, count=1,
period=500,
frequency=1, end=1000
$interp = linear
amplitude = 0,0; 333,0.15; 666,0;
833,-0.025; 1000,0
$proc = periodic
"""


def test_shipped_headnod_is_the_paper_file_verbatim():
    assert (LIBRARY_DIR / "HeadNod.lib").read_text() == PAPER_HEADNOD


def test_paper_file_parses_with_values_continued_over_lines():
    [nod] = parse_library_text(PAPER_HEADNOD, "HeadNod.lib")
    assert nod.name == "HeadNod"
    assert nod.mandatory == ("at",)
    assert nod.optional == {"amplitude": 100, "count": 1, "period": 500, "frequency": 1, "end": 1000}
    assert list(nod.optional) == ["amplitude", "count", "period", "frequency", "end"]
    assert nod.interpolation == "linear"
    assert nod.procedure == "periodic"
    [curve] = nod.curves
    assert curve.name == "amplitude" and curve.line == 7
    assert curve.times == (0, 333, 666, 833, 1000)
    assert curve.values == (0, 0.15, 0, -0.025, 0)
    assert nod.span() == (0, 1000)


def test_comments_blank_lines_several_lines_scales_and_levels():
    text = """
    # a comment line
    $command = Look   # trailing comment
    $description = look somewhere
    $optional = x=0, onset=50, apex=100, offset=50

    eye_left_turn * x = 0.0174533
    brow_raise = 0,0; 10,1;
       20,0
    $proc = attack-hold-release
    """
    [look] = parse_library_text(text, "look.lib")
    assert look.description == "look somewhere"
    assert [c.name for c in look.curves] == ["eye_left_turn", "brow_raise"]
    assert look.curves[0].scale == "x" and look.curves[0].is_level and look.curves[0].values == (0.0174533,)
    assert look.curves[1].times == (0, 10, 20)
    assert look.interpolation == "linear" and look.procedure == "attack-hold-release"


def test_several_commands_in_one_file():
    text = "$command = A\nx = 0,0; 1,1\n$command = B\n$proc = periodic\ny = 0,0; 2,1\n"
    a, b = parse_library_text(text, "two.lib")
    assert (a.name, a.procedure, a.line) == ("A", "once", 1)
    assert (b.name, b.procedure, b.line) == ("B", "periodic", 3)


def test_a_statement_after_a_trailing_semicolon_is_not_swallowed():
    text = "$command = A\njaw_open = 0,0; 100,1;\ntongue_raise = 0,0; 100,1;\n$proc = once\n"
    [a] = parse_library_text(text, "a.lib")
    assert [c.name for c in a.curves] == ["jaw_open", "tongue_raise"]


@pytest.mark.parametrize("text, line, words", [
    ("$command = A\n$colour = red\nx = 0,0; 1,1\n", 2, "unknown directive $colour"),
    ("x = 0,0; 1,1\n$command = A\n", 1, "comes before $command"),
    ("# nothing\n\n", 1, "defines no command"),
    ("$command = A\n$proc = once\n", 1, "activates no parameter"),
    ("$command = A\nx = 0,0; 100,1; 50,0\n", 2, "must increase"),
    ("$command = A\nx = 0,0;\n100,1; 100,0\n", 3, "must increase"),
    ("$command = A\nx = 0,0; 100,high\n", 2, "is not a number: 'high'"),
    ("$command = A\nx = 0,0; 100,nan\n", 2, "finite"),
    ("$command = A\n$optional = count=one\nx = 0,0; 1,1\n$proc = periodic\n", 2, "not a number: 'one'"),
    ("$command = A\n$optional = amplitude=100,\ncount\nx = 0,0; 1,1\n", 3, "not 'name=default'"),
    ("$command = A\n$interp = spline\nx = 0,0; 1,1\n", 2, "unknown interpolation 'spline'"),
    ("$command = A\n$proc = bounce\nx = 0,0; 1,1\n", 2, "unknown procedure 'bounce'"),
    ("$command = A\n$proc = once\n$proc = once\nx = 0,0; 1,1\n", 3, "$proc is given twice"),
    ("$command = A\nx = 0,0; 1,1\nx = 0,0; 2,1\n", 3, "line 'x' is given twice"),
    ("$command = A\nx = 0,0 1,1\n", 2, "not one 'time,value' pair"),
    ("$command = A\nx = 0,0\n", 2, "at least two"),
    ("$command = A\nx = 1\n$proc = once\n", 2, "single level"),
    ("$command = A\nx * gain = 0,0; 1,1\n", 2, "scaled by 'gain'"),
    ("$command = A\n$mandatory = at, at\nx = 0,0; 1,1\n", 2, "listed twice"),
    ("$command = A\n$mandatory = count\n$optional = count=1\nx = 0,0; 1,1\n$proc = periodic\n", 3,
     "both mandatory and optional"),
    ("$command = A\n$optional = speed=2\nx = 0,0; 1,1\n", 2, "'speed' is used neither"),
    ("$command = A\n$optional = onset=1\nx = 1\n$proc = attack-hold-release\n", 4, "needs the argument 'apex'"),
    ("$command = A B\nx = 0,0; 1,1\n", 1, "needs a name"),
    ("$command = A\nthis is not a statement\n", 2, "cannot read"),
    ("$command = A\n$proc * x = once\n", 2, "cannot be scaled"),
])
def test_errors_name_file_and_line(text, line, words):
    with pytest.raises(LibraryError) as caught:
        parse_library_text(text, "bad.lib")
    assert caught.value.file == "bad.lib"
    assert caught.value.line == line, str(caught.value)
    assert words in caught.value.message
    assert str(caught.value).startswith(f"bad.lib:{line}: ")


def test_a_file_that_is_not_utf8_is_reported_with_its_line(tmp_path):
    path = tmp_path / "latin.lib"
    path.write_bytes(b"$command = A\n# p\xe4\xe4\nx = 0,0; 1,1\n")
    with pytest.raises(LibraryError) as caught:
        load_library_file(path)
    assert caught.value.line == 2 and "UTF-8" in caught.value.message


def test_a_missing_file_is_a_user_error(tmp_path):
    with pytest.raises(LibraryError, match="no such file"):
        load_library_file(tmp_path / "nope.lib")


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("$=,;#*.-+ \n\tabcxyz_019AHNe")), max_size=200))
def test_the_parser_never_crashes_on_library_like_text(text):
    try:
        parse_library_text(text, "fuzz.lib")
    except UserError as exc:
        error: UserError | None = exc
    else:
        error = None
    assert error is None or error.file == "fuzz.lib"


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=300))
def test_the_parser_never_crashes_on_arbitrary_text(text):
    with contextlib.suppress(UserError):
        parse_library_text(text, "fuzz.lib")
