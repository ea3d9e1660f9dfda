"""The articulation table parser (``engine/library/articulation/*.phones``) against any input (issue 16 §4).

Only :class:`engine.errors.LibraryError`, naming the file, may come out of it;
no input makes it backtrack for long (a 100,000-digit cell once took minutes).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine.errors import LibraryError
from engine.speech.articulation import load_articulation, parse_articulation

EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "300"))
SHIPPED = [Path(__file__).parents[2] / "engine" / "library" / "articulation" / name for name in ("finnish.phones",
                                                                                        "english.phones")]
ALPHABET = st.sampled_from([*"$=#!/-,.:+eE0123456789 \t\napbx", "jaw_open", "parameters", "weak", "nan", "inf",
                            "1e999", "\u00e4", "\x00"])


def only_library_errors(text: str) -> None:
    try:
        table = parse_articulation(text, "fuzz.phones")
    except LibraryError as error:
        message = str(error)
        assert message.startswith("fuzz.phones"), message
        return
    for phone in table.rows:
        for target in table.row(phone):
            assert target.dominance > 0 and target.anticipation > 0 and target.carryover > 0
            assert abs(target.value) < float("inf")


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(ALPHABET, max_size=80).map("".join))
def test_random_tables_raise_only_library_errors(text):
    only_library_errors(text)


@settings(max_examples=EXAMPLES, deadline=None)
@given(st.sampled_from(SHIPPED), st.data())
def test_mutated_shipped_tables_raise_only_library_errors(path, data):
    text = path.read_text(encoding="utf-8")
    position = data.draw(st.integers(0, len(text)))
    cut = data.draw(st.integers(0, 20))
    insert = data.draw(st.text(alphabet="$=#!/-,.0123456789e \t\nx", max_size=10))
    only_library_errors(text[:position] + insert + text[position + cut:])


def test_a_huge_cell_does_not_make_the_parser_backtrack():
    """In a child process with a generous time limit: the old expression needed minutes for this line."""
    program = ("from engine.speech.articulation import parse_articulation\n"
               "from engine.errors import LibraryError\n"
               "try:\n"
               "    parse_articulation('$parameters = jaw_open\\na ' + '1' * 100000 + 'x\\n', 'big.phones')\n"
               "except LibraryError as error:\n"
               "    print(error)\n")
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=60, check=True)
    assert done.stdout.startswith("big.phones:2: cannot read target")


def test_a_file_that_is_not_a_table_is_refused_without_reading_it_whole(tmp_path):
    big = tmp_path / "huge.phones"
    with big.open("wb") as out:
        out.truncate(64 * 1024 * 1024)                     # sparse: 64 MiB of NUL bytes
    with pytest.raises(LibraryError, match="file too large") as caught:
        load_articulation(big)
    assert str(big) in str(caught.value)
