"""Fuzzing the §2.3 library format: any text is read, or refused with a LibraryError naming the file.

Inputs are the shipped library files mutated, library text built from the
format's own pieces with hostile numbers, and arbitrary text. What parses is
then used: a command with fuzzed arguments is translated and sampled on the
timeline, which must end normally or with a UserError naming a file.
Size: ``AP_FUZZ_EXAMPLES`` (see ``tests/engine/fuzz_support.py``).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from engine.commands import Library, parse_library_text, translate
from engine.commands.command_files import HighLevelCommand
from engine.errors import LibraryError, UserError
from engine.paths import LIBRARY_DIR
from engine.timeline.timeline import Timeline
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated, outcome

NAME = "fuzzed.lib"
SHIPPED = {path.name: path.read_text(encoding="utf-8") for path in sorted(LIBRARY_DIR.glob("*.lib"))}
ARGUMENTS = ("at", "amplitude", "count", "period", "frequency", "end", "duration", "onset", "apex", "offset",
             "left", "right", "x")

_pair = st.tuples(NUMBER_TEXT, NUMBER_TEXT).map(lambda p: f"{p[0]},{p[1]}")
_curve = st.tuples(st.sampled_from(["amplitude", "jaw_open", "eyelid_left_close", "AU12_left", "bad name", ""]),
                   st.sampled_from(["", " * left", " * x", " * "]),
                   st.lists(_pair, max_size=6).map("; ".join),
                   st.sampled_from(["", ";", ",", "\n", "\n1,1"])).map(lambda c: f"{c[0]}{c[1]} = {c[2]}{c[3]}")
_optional = st.lists(st.tuples(st.sampled_from(ARGUMENTS), NUMBER_TEXT).map(lambda a: f"{a[0]}={a[1]}"),
                     max_size=5).map(", ".join)
_directive = st.one_of(
    st.sampled_from(["$interp = linear", "$interp = cosine", "$interp = step", "$interp = cubic", "$interp = wave",
                     "$proc = periodic", "$proc = once", "$proc = attack-hold-release", "$proc = nope",
                     "$mandatory = at", "$mandatory = at, count", "$mandatory = ,", "$parameter = jaw_open",
                     "$description = a fuzzed command", "$unknown = 1", "$command = Second", "# comment"]),
    _optional.map(lambda o: f"$optional = {o}"),
)
_built = st.tuples(st.sampled_from(["Fuzz", "HeadNod", "9bad", ""]),
                   st.lists(st.one_of(_directive, _curve), max_size=8)).map(
    lambda b: "\n".join([f"$command = {b[0]}", *b[1]]) + "\n")
LIBRARY_TEXT = st.one_of(
    st.sampled_from(sorted(SHIPPED)).flatmap(lambda name: mutated(SHIPPED[name])),
    _built,
    st.text(max_size=300),
)
COMMAND_ARGUMENTS = st.dictionaries(st.sampled_from(ARGUMENTS), NUMBER_TEXT, max_size=5)


def _number_or_none(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


@FUZZ
@given(LIBRARY_TEXT, COMMAND_ARGUMENTS)
def test_library_text_is_read_or_refused_with_the_file_named(head, text, arguments):
    definitions = expect_clean(lambda: parse_library_text(text, NAME), LibraryError, NAME)
    if isinstance(definitions, LibraryError):
        return
    numbers = {k: v for k, v in ((k, _number_or_none(t)) for k, t in arguments.items()) if v is not None}
    numbers.setdefault("at", 0.0)
    library = Library(definitions)
    for definition in definitions:
        command = HighLevelCommand(definition.name, numbers, "script.xml", 1)

        def use(command=command):
            timeline = Timeline(translate([command], library, head), head)
            return timeline.sample_frames(fps=25)

        result = outcome(use)
        if isinstance(result, UserError):
            assert result.file in (NAME, "script.xml"), str(result)
