"""Fuzzing command files (XML, high and low level) through translation and the timeline.

Any bytes are read, or refused with a CommandError naming the file; what is
read is translated with the shipped library and sampled on the timeline,
which ends normally or with a UserError naming the file. Inputs: command
files built from the shipped commands with hostile numbers, hostile XML
(DTDs, entities, deep nesting, wrong encodings), those mutated, and
arbitrary bytes. Size: ``AP_FUZZ_EXAMPLES`` (``tests/engine/fuzz_support.py``).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from engine.commands import load_library, parse_commands_text, translate
from engine.errors import CommandError, UserError
from engine.timeline.timeline import Timeline
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated, outcome

NAME = "fuzzed.xml"
LIBRARY = load_library()
COMMANDS = [*sorted(LIBRARY.names()), "Unknown", "activate"]
ARGUMENTS = ("at", "amplitude", "count", "period", "frequency", "end", "duration", "onset", "apex", "offset",
             "left", "right", "x", "y", "bogus")
HOSTILE = [
    '<?xml version="1.0"?>\n<!DOCTYPE commands SYSTEM "http://example.com/c.dtd">\n<commands>&nod;</commands>',
    '<!DOCTYPE commands [<!ENTITY nod SYSTEM "file:///etc/passwd">]><commands>&nod;</commands>',
    '<!DOCTYPE commands [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]><commands><X at="&b;"/></commands>',
    '<!DOCTYPE low-level-commands SYSTEM "c.dtd"><low-level-commands format="artificial-person-low-level-commands"'
    ' version="1"><activate parameter="jaw_open" source="&s;"><key at="0" value="0"/></activate></low-level-commands>',
    '<commands>' + '<a>' * 300 + '</a>' * 300 + '</commands>',
    '<?xml version="1.0" encoding="UTF-16"?><commands/>',
    '<?xml version="1.0" encoding="nonsense"?><commands/>',
    '<low-level-commands format="artificial-person-low-level-commands" version="99"/>',
    '<commands xmlns="urn:x"><HeadNod at="0"/></commands>',
    '<commands><HeadNod at="0" xmlns:q="urn:q" q:count="2"/></commands>',
    '<commands><?pi x?><!-- c --><Blink at="0"/>text</commands>',
]



def _accepted(command: str) -> list[str]:
    """The arguments a command accepts (mostly what the fuzzer gives it, so that it gets past the checks)."""
    return sorted(LIBRARY[command].arguments()) if command in LIBRARY else ["at"]


def _high_command(command: str) -> st.SearchStrategy[str]:
    names = st.one_of(st.sampled_from(_accepted(command)), st.sampled_from(ARGUMENTS))
    attribute = st.tuples(names, NUMBER_TEXT).map(lambda a: f'{a[0]}="{a[1]}"')
    return st.lists(attribute, max_size=5, unique_by=lambda a: a.split("=")[0]).map(
        lambda attributes: f"<{command} {' '.join(attributes)}/>")


_high = st.sampled_from(COMMANDS).flatmap(_high_command)
_key = st.tuples(NUMBER_TEXT, NUMBER_TEXT).map(lambda k: f'<key at="{k[0]}" value="{k[1]}"/>')
_activate = st.tuples(st.sampled_from(["jaw_open", "head_nod", "nope", ""]),
                      st.sampled_from(["linear", "step", "cubic", "cosine", "wavy"]),
                      st.sampled_from(["", ' source="in.xml:3"', ' source="in.xml:\u00b2"', ' command="X" line="y"']),
                      st.lists(_key, max_size=6)).map(
    lambda a: f'<activate parameter="{a[0]}" interp="{a[1]}"{a[2]}>{"".join(a[3])}</activate>')
_high_file = st.lists(_high, max_size=5).map(lambda cs: "<commands>" + "".join(cs) + "</commands>")
_version = st.one_of(st.just("1"), st.text(max_size=3), st.sampled_from(["2", "01", "\u00b2", "\u0663", "9" * 5000]))
_low_file = st.tuples(_version, st.lists(_activate, max_size=4)).map(
    lambda v: f'<low-level-commands format="artificial-person-low-level-commands" version="{v[0]}">'
              + "".join(v[1]) + "</low-level-commands>")
_mixed_file = st.lists(st.one_of(_high, _activate), max_size=5).map(
    lambda cs: "<commands>" + "".join(cs) + "</commands>")
COMMAND_TEXT = st.one_of(_high_file, _low_file, _mixed_file, st.sampled_from(HOSTILE),
                         st.one_of(_high_file, st.sampled_from(HOSTILE)).flatmap(mutated))
COMMAND_BYTES = st.one_of(COMMAND_TEXT.map(lambda t: t.encode("utf-8")),
                          COMMAND_TEXT.map(lambda t: t.encode("utf-16")),
                          st.binary(max_size=200))


@FUZZ
@given(COMMAND_BYTES, st.sampled_from([1.0, 25.0, 60.0, 1000.0]))
def test_command_files_are_read_or_refused_with_the_file_named(head, data, fps):
    commands = expect_clean(lambda: parse_commands_text(data, NAME), CommandError, NAME)
    if isinstance(commands, CommandError):
        return
    result = outcome(lambda: Timeline(translate(commands, LIBRARY, head), head).sample_frames(fps=fps))
    if isinstance(result, UserError):
        assert result.file is not None and NAME in result.file, str(result)
