"""Study designs (TOML) fuzzed: each is read, or refused with one StudyDesignError naming the file.

Inputs: the example study designs and the tests' design mutated (characters replaced, inserted, deleted, cut
short), designs built from every key of the format with hostile values (non-finite and enormous numbers, odd
strings, wrong types, nesting, paths with ``..``, NUL and 5,000 characters), and arbitrary text. A design that
is read holds only what a design can: its numbers within their ranges, its keys and choices well formed.
Size: ``AP_FUZZ_EXAMPLES`` (docs/robustness.md).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from engine.study.design import (
    BLOCKINGS,
    HOSTS,
    MAX_ATTENTION,
    MAX_PRACTICE,
    MAX_SCALE_POINTS,
    StudyDesign,
    StudyDesignError,
    parse_study_design,
)
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated
from tests.engine.test_study_helpers import STUDY_DESIGN

EXAMPLES = Path(__file__).parents[2] / "examples" / "study"
SEEDS = [STUDY_DESIGN] + [p.read_text(encoding="utf-8") for p in sorted(EXAMPLES.glob("*.toml"))
                          if "[stimuli]" in p.read_text(encoding="utf-8")]
KEYS = {
    "": ["name", "title", "seed"],
    "stimuli": ["set", "design", "emotion"],
    "conditions": ["presentation", "dynamic"],
    "human": ["table"],
    "identification": ["choices", "neutral", "other", "labels", "keys", "question", "buttons"],
    "procedure": ["tasks", "repetitions", "blocks", "counterbalance", "practice", "attention_checks", "static_ms",
                  "fixation_ms", "gap_ms"],
    "pages": ["consent", "instructions", "practice_end", "debrief", "agree", "decline", "declined"],
    "output": ["hosts", "width"],
}
_strings = st.one_of(
    st.sampled_from(['"set"', '"faces.toml"', '"actors.csv"', '"consent.md"', '"static"', '"dynamic"', '"live"',
                     '"video"', '"identification"', '"rating"', '"presentation"', '"latin"', '"happy"', '"1"',
                     '"../../etc/passwd"', '"/dev/zero"', '"a\\u0000b"', '"' + "x" * 5000 + '"', '""', '"jatos"',
                     '"consent.html"', '"x.md"']),
    st.text(st.characters(blacklist_categories=("Cs", "Cc")), max_size=12).map(
        lambda t: '"' + t.replace("\\", "\\\\").replace('"', '\\"') + '"'),
)
_scalars = st.one_of(NUMBER_TEXT.filter(lambda t: t.strip() != ""), _strings, st.sampled_from(["true", "false"]))
_values = st.one_of(_scalars, st.lists(_scalars, max_size=5).map(lambda v: "[" + ", ".join(v) + "]"),
                    st.sampled_from(["{}", "{ happy = \"Joy\" }", "[[1]]", "[" * 40 + "]" * 40,
                                     "1979-05-27T07:32:00Z", "[\"1\", \"1\"]", "[\"a\", \"b\", \"c\", \"d\"]"]))
_scale = st.fixed_dictionaries({"name": _strings, "min": NUMBER_TEXT, "max": NUMBER_TEXT, "anchors": _values,
                                "keys": _values, "question": _strings})


@st.composite
def designs(draw) -> str:
    lines = [f"{key} = {draw(_values)}" for key in draw(st.lists(st.sampled_from(KEYS[""]), unique=True))]
    for table, keys in KEYS.items():
        if table and draw(st.booleans()):
            lines.append(f"[{table}]")
            lines += [f"{key} = {draw(_values)}" for key in draw(st.lists(st.sampled_from(keys), unique=True))]
    for scale in draw(st.lists(_scale, max_size=3)):
        lines.append("[[scales]]")
        lines += [f"{k} = {v}" for k, v in scale.items() if draw(st.booleans())]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    """A folder where the names a design may give exist: a set's manifest, a set design, a table, pages."""
    root = tmp_path_factory.mktemp("fuzz-study")
    (root / "set").mkdir()
    (root / "set" / "manifest.csv").write_text("id,expression,file_png,sha256_png\n0001,Happy,0001.png,00\n")
    for name, text in (("faces.toml", "[factors]\ntext = [\"Moi.\"]\n"), ("actors.csv", "file,emotion\n"),
                       ("consent.md", "# Consent\n\nYes?"), ("consent.html", "<p>Yes?</p>"), ("x.md", "**x**")):
        (root / name).write_text(text)
    return root


def _parse(text: str, folder: Path) -> None:
    path = folder / "study.toml"
    result = expect_clean(lambda: parse_study_design(text, path), StudyDesignError, str(path))
    if isinstance(result, StudyDesign):
        _holds_only_what_a_design_can(result)


def _holds_only_what_a_design_can(design: StudyDesign) -> None:
    procedure = design.procedure
    assert 0 <= procedure.practice <= MAX_PRACTICE and 0 <= procedure.attention_checks <= MAX_ATTENTION
    assert procedure.blocks in BLOCKINGS and set(design.hosts) <= set(HOSTS) and design.presentations
    assert 0 <= design.seed < 2**32
    for scale in design.scales:
        assert 2 <= scale.high - scale.low + 1 <= MAX_SCALE_POINTS
        assert not scale.keys or len(scale.keys) == scale.high - scale.low + 1
    assert design.set_folder is not None or design.set_design is not None


@FUZZ
@given(seed=st.sampled_from(SEEDS), data=st.data())
def test_fuzz_study_design_mutated(folder, seed, data):
    _parse(data.draw(mutated(seed)), folder)


@FUZZ
@given(text=designs())
def test_fuzz_study_design_built_from_its_keys(folder, text):
    _parse(text, folder)


@FUZZ
@given(text=st.text(max_size=400))
def test_fuzz_study_design_arbitrary_text(folder, text):
    _parse(text, folder)
