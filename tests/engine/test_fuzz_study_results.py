"""Results files fuzzed: each is read and analysed, or refused with one ResultsError naming the file.

Inputs: a real results table (two participants, static and dynamic, ratings, a practice trial and an attention
check) mutated (characters replaced, inserted, deleted, cut short); tables whose cells are hostile (huge,
non-finite and malformed numbers, empty and 5,000-character names, NUL, quotes left open, another study's id,
phases and presentations that are no such thing, a header given again half-way); and arbitrary text. A file
that is read is analysed and its tables written as text: no other exception, no hang. Size:
``AP_FUZZ_EXAMPLES`` (docs/robustness.md).
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from engine.study.analysis import analyse
from engine.study.report import tables
from engine.study.results import Results, ResultsError, read_results_text
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated
from tests.engine.test_study_analyse import COLUMNS, EXAMPLE, judge, results_text

NAME = "results.csv"
SEED = results_text(
    judge([("happy", "happy")], "1", phase="practice", rating_intensity=3, rating_naturalness=4)
    + judge(EXAMPLE, "1", rating_intensity=5, rating_naturalness=2)
    + judge(EXAMPLE[:6], "2", presentation="dynamic", rating_intensity=7, rating_naturalness=1)
    + judge([("sad", "neutral")], "2", phase="attention", expected="neutral"))
_cells = st.one_of(
    NUMBER_TEXT, st.text(max_size=6),
    st.sampled_from(["", " ", "test", "practice", "attention", "static", "dynamic", "synthetic", "human", "happy",
                     "other", "x" * 5000, "a\x00b", '"open', "study_id", "0123456789abcdef", "fedcba9876543210",
                     "-1", "0", "1e400", "nan", "inf", "99999999999", "1.5", "\r", "\n"]))


@st.composite
def hostile_tables(draw) -> str:
    lines = [",".join(COLUMNS)]
    for _ in range(draw(st.integers(1, 8))):
        row = SEED.splitlines()[draw(st.integers(1, len(SEED.splitlines()) - 1))].split(",")
        for _ in range(draw(st.integers(0, 4))):
            row[draw(st.integers(0, len(row) - 1))] = draw(_cells).replace(",", ";")
        if draw(st.booleans()) and len(row) > 3:
            row = row[:draw(st.integers(1, len(row)))] if draw(st.booleans()) else [*row, draw(_cells)]
        lines.append(",".join(row))
        if draw(st.integers(0, 9)) == 0:
            lines.append(",".join(COLUMNS))
    return "\n".join(lines) + "\n"


def _read_and_analyse(text: str) -> None:
    result = expect_clean(lambda: read_results_text(text, NAME), ResultsError, NAME)
    if isinstance(result, Results):
        for trial in result.trials:
            assert trial.rt is None or math.isfinite(trial.rt)
            assert all(math.isfinite(v) for v in trial.ratings.values())
        analysis = analyse(result)
        assert all(isinstance(t, str) for t in tables(analysis).values())


@FUZZ
@given(text=mutated(SEED))
def test_fuzz_study_results_mutated(text):
    _read_and_analyse(text)


@FUZZ
@given(text=hostile_tables())
def test_fuzz_study_results_hostile_cells(text):
    _read_and_analyse(text)


@FUZZ
@given(text=st.text(max_size=600))
def test_fuzz_study_results_arbitrary_text(text):
    _read_and_analyse(text)
