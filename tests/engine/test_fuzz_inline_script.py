"""Fuzzing the inline-command script parser (§2): any text is split, or refused naming the text's file.

What parses is anchored to made-up word timings and translated with the
shipped library; that too ends normally or with a UserError naming the file.
Size: ``AP_FUZZ_EXAMPLES`` (``tests/engine/fuzz_support.py``).
"""

from __future__ import annotations

from dataclasses import dataclass

from hypothesis import given
from hypothesis import strategies as st

from engine.commands import load_library, translate
from engine.errors import CommandError, UserError
from engine.script.inline_commands import anchored_commands, parse_script
from engine.timeline.timeline import Timeline
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated, outcome

NAME = "story.txt"
LIBRARY = load_library()
SEED = 'Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä <Blink/> kuuluu?\nToinen rivi <Happy onset="100"/>.'


@dataclass
class Word:
    label: str
    start_ms: float
    end_ms: float


_tag = st.tuples(st.sampled_from([*sorted(LIBRARY.names()), "Nope", "activate", "a b", ""]),
                 st.lists(st.tuples(st.sampled_from(["at", "amplitude", "count", "duration", "x", "at at"]),
                                    NUMBER_TEXT), max_size=3),
                 st.sampled_from(["/>", ">", " />", "/ >", ""])).map(
    lambda t: f"<{t[0]} " + " ".join(f'{k}="{v}"' for k, v in t[1]) + t[2])
_piece = st.one_of(st.text(max_size=12), _tag, st.sampled_from(["<", ">", "<<", "\n", "2", "ääkköset", "&amp;"]))
SCRIPT = st.one_of(st.lists(_piece, max_size=10).map("".join), mutated(SEED), st.text(max_size=200))


@FUZZ
@given(SCRIPT)
def test_scripts_are_split_or_refused_with_the_file_named(head, text):
    script = expect_clean(lambda: parse_script(text, NAME), CommandError, NAME)
    if isinstance(script, CommandError):
        return
    spoken = [Word(w, 300.0 * i, 300.0 * i + 250.0) for i, w in enumerate(script.words)]
    result = outcome(lambda: Timeline(translate(anchored_commands(script, spoken), LIBRARY, head), head)
                     .sample_frames(fps=30))
    if isinstance(result, UserError):
        assert result.file == NAME, str(result)
