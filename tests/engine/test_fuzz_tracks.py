"""Fuzzing the tracks CSV reader and animation files: read, or refused with a UserError naming the file.

Size: ``AP_FUZZ_EXAMPLES`` (``tests/engine/fuzz_support.py``).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from engine.errors import UserError
from engine.timeline.animation_files import load_animation
from engine.timeline.tracks import parse_tracks_csv
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated, no_hang

NAME = "fuzzed.csv"
SEED = "time_ms,jaw_open,head_nod\n0,0,0\n16.6667,0.1,0.05\n33.3333,0.2,0.09\n"
_columns = st.lists(st.sampled_from(["time_ms", "jaw_open", "head_nod", "nope", "", " jaw_open", '"a,b"']),
                    min_size=1, max_size=4)
_rows = st.lists(st.lists(NUMBER_TEXT, min_size=1, max_size=4).map(",".join), max_size=8)
TRACKS = st.one_of(st.tuples(_columns, _rows).map(lambda t: "\n".join([",".join(t[0]), *t[1]]) + "\n"),
                   mutated(SEED), st.text(max_size=200))


@FUZZ
@given(TRACKS)
def test_tracks_tables_are_read_or_refused_with_the_file_named(head, text):
    table = expect_clean(lambda: parse_tracks_csv(text, head, NAME), UserError, NAME)
    if isinstance(table, UserError):
        return
    with no_hang():
        table.sample([table.start, table.end, (table.start + table.end) / 2])
        assert table.fps > 0


ANIMATION = st.one_of(
    st.tuples(st.just(".csv"), TRACKS.map(lambda t: t.encode("utf-8"))),
    st.tuples(st.just(".xml"), st.one_of(
        mutated('<commands><HeadNod at="0" amplitude="60" count="2"/><Blink at="100"/></commands>'),
        st.lists(st.tuples(st.sampled_from(["HeadNod", "Blink", "Happy", "X"]), NUMBER_TEXT, NUMBER_TEXT),
                 max_size=3).map(lambda cs: "<commands>" + "".join(
                     f'<{c} at="{a}" amplitude="{b}"/>' for c, a, b in cs) + "</commands>")
    ).map(lambda t: t.encode("utf-8"))),
    st.tuples(st.sampled_from([".xml", ".csv"]), st.binary(max_size=100)),
)


@FUZZ
@given(ANIMATION)
def test_animation_files_open_or_are_refused_with_the_file_named(head, tmp_path_factory, animation):
    suffix, data = animation
    path = tmp_path_factory.mktemp("animation") / f"fuzzed{suffix}"
    path.write_bytes(data)
    opened = expect_clean(lambda: load_animation(path, head), UserError, str(path))
    if isinstance(opened, UserError):
        return
    with no_hang():
        opened.timeline.sample([opened.timeline.start, opened.timeline.end])
