"""Phone label files (Praat TextGrid, label lines, phones CSV): read, or refused with a LabelFileError naming the file.

The fuzz test feeds mutated TextGrids (long and short format), label lines
and phones tables, in UTF-8 and UTF-16, plus arbitrary bytes, through
:func:`engine.speech.labels.read_labels`. The cases after it are the ones
found by fuzzing, each refused with one clear error. Size: ``AP_FUZZ_EXAMPLES``.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from engine.mocap.errors import LabelFileError
from engine.speech.labels import parse_textgrid, read_labels
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated, no_hang

LONG_TEXTGRID = '''File type = "ooTextFile"
Object class = "TextGrid"

xmin = 0
xmax = 0.5
tiers? <exists>
size = 1
item []:
    item [1]:
        class = "IntervalTier"
        name = "phones"
        xmin = 0
        xmax = 0.5
        intervals: size = 3
        intervals [1]:
            xmin = 0
            xmax = 0.1
            text = ""
        intervals [2]:
            xmin = 0.1
            xmax = 0.3
            text = "h"
        intervals [3]:
            xmin = 0.3
            xmax = 0.5
            text = "e ""quoted"""
'''
SHORT_TEXTGRID = '''File type = "ooTextFile"
Object class = "TextGrid"

0
0.5
<exists>
1
"IntervalTier"
"phones"
0
0.5
2
0
0.2
"h"
0.2
0.5
"e"
'''
LABEL_LINES = "# units: ms\n0 120 h\n120 200 e\n\\ 100 200\n"
PHONES_CSV = "start_ms,end_ms,phone,word\n0,120,h,hei\n120,200,e,hei\n"
SEEDS = [LONG_TEXTGRID, SHORT_TEXTGRID, LABEL_LINES, PHONES_CSV]

_text = st.one_of(st.sampled_from(SEEDS).flatmap(mutated),
                  st.lists(st.tuples(NUMBER_TEXT, NUMBER_TEXT, st.text(max_size=3)), max_size=5).map(
                      lambda rows: "\n".join(f"{a} {b} {c}" for a, b, c in rows)),
                  st.sampled_from([SHORT_TEXTGRID]).map(
                      lambda g: g.replace("\n2\n", "\n1e999\n")))
LABEL_BYTES = st.one_of(_text.map(lambda t: t.encode("utf-8")), _text.map(lambda t: t.encode("utf-16")),
                        st.binary(max_size=200), st.binary(max_size=60).map(lambda b: b"\xff\xfe" + b))


@FUZZ
@given(LABEL_BYTES)
def test_label_files_are_read_or_refused_with_the_file_named(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("labels") / "take.TextGrid"
    path.write_bytes(data)
    labels = expect_clean(lambda: read_labels(path), LabelFileError, str(path))
    if isinstance(labels, LabelFileError):
        return
    for start, end, label in labels:
        assert math.isfinite(start) and math.isfinite(end) and start <= end and label


def _grid(**replacements: str) -> str:
    text = SHORT_TEXTGRID
    for old, new in replacements.items():
        text = text.replace(old, new, 1)
    return text


@pytest.mark.parametrize(("text", "words"), [
    (SHORT_TEXTGRID.replace("<exists>\n1\n", "<exists>\n1e999\n"), "number 1e999 is too large"),
    (SHORT_TEXTGRID.replace("\n2\n0\n", "\n1e999\n0\n"), "number 1e999 is too large"),
    (SHORT_TEXTGRID.replace("\n2\n0\n", "\n2.5\n0\n"), "not a whole number"),
    (SHORT_TEXTGRID.replace("\n2\n0\n", "\n1000000000\n0\n"), "not a whole number the file can hold"),
    (SHORT_TEXTGRID.replace("0.2\n0.5\n", "0.2\n1e999\n"), "too large"),
    (SHORT_TEXTGRID.replace("0.2\n0.5\n", "0.2\n1e300\n"), "beyond 86400000 ms"),
    (SHORT_TEXTGRID.replace('"e"', '"e'), "no closing quote"),
], ids=["tiers-1e999", "intervals-1e999", "intervals-2.5", "intervals-1e9", "end-1e999", "end-1e300",
        "open-quote"])
def test_textgrid_counts_and_times_beyond_reason_are_refused(text, words):
    with pytest.raises(LabelFileError, match=words) as caught:
        parse_textgrid(text, "take.TextGrid")
    assert str(caught.value).startswith("take.TextGrid:")


@pytest.mark.parametrize("line", ["0 1e999 a", "0 inf a", "0 1e300 a"])
def test_a_label_line_ending_beyond_a_day_is_refused(tmp_path, line):
    path = tmp_path / "take.lab"
    path.write_text(line + "\n")
    with pytest.raises(LabelFileError, match=r"take.lab:1: .*(beyond 86400000 ms)"):
        read_labels(path)


def test_a_phones_table_ending_at_1e999_is_refused(tmp_path):
    path = tmp_path / "take.csv"
    path.write_text("start_ms,end_ms,phone,word\n0,1e999,h,hei\n")
    with pytest.raises(LabelFileError, match=r"take.csv:2: .*beyond"):
        read_labels(path)


def test_utf16_with_a_lone_surrogate_is_refused(tmp_path):
    path = tmp_path / "take.TextGrid"
    path.write_bytes(b"\xff\xfe" + SHORT_TEXTGRID[:40].encode("utf-16-le") + b"\x00\xd8" + b"a\x00")
    with pytest.raises(LabelFileError, match="not valid UTF-16"):
        read_labels(path)


def test_tokenizing_a_textgrid_takes_linear_time_on_unclosed_brackets_and_quotes():
    """400,000 '[' on one line took about 8 minutes (each rescanned the line); now they are one token."""
    header = 'File type = "ooTextFile"\nObject class = "TextGrid"\n'
    for body in ("[" * 400_000, '"' + "1 " * 200_000):
        with no_hang(), pytest.raises(LabelFileError):
            parse_textgrid(header + body, "take.TextGrid")


def test_devices_are_not_read_as_label_files():
    with pytest.raises(LabelFileError, match="not a regular file"):
        read_labels("/dev/zero")


def test_a_phones_table_row_with_no_phone_is_silence(tmp_path):
    path = tmp_path / "take.csv"
    path.write_text("start_ms,end_ms,phone,word\n0,120,h,hei\n120,200,,hei\n")
    assert read_labels(path) == [(0.0, 120.0, "h")]
