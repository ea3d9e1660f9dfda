"""Tracks tables read back, and animation files opened to play (engine.timeline.tracks, .animation_files).

The engine side of the workbench's Open animation…: a tracks CSV written by
``Timeline.write_tracks`` plays the same values; a bad file is a UserError
naming file and line; a command file becomes a timeline.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.commands import load_library, parse_commands_text, translate, write_low_level
from engine.errors import UserError
from engine.timeline.animation_files import DEFAULT_FPS, load_animation
from engine.timeline.timeline import Timeline
from engine.timeline.tracks import TracksTable, parse_tracks_csv, read_tracks_csv, tracks_csv_text

TWO_TRACKS = """<commands>
  <activate parameter="jaw_open" interp="cosine"><key at="0" value="0"/><key at="200" value="0.9"/>
    <key at="400" value="0"/></activate>
  <activate parameter="brow_raise" interp="linear"><key at="100" value="0"/><key at="300" value="0.8"/>
    <key at="500" value="0"/></activate>
</commands>
"""


@pytest.fixture
def timeline(head) -> Timeline:
    return Timeline(translate(parse_commands_text(TWO_TRACKS), load_library(), head), head)


def test_a_written_table_reads_back_to_the_same_values(timeline, head, tmp_path):
    path = tmp_path / "two.csv"
    timeline.write_tracks(path, fps=50)
    table = read_tracks_csv(path, head)
    assert isinstance(table, TracksTable) and table.source == str(path)
    assert table.fps == pytest.approx(50) and (table.start, table.end) == (0.0, 500.0)
    assert table.driven == ["jaw_open", "brow_raise"]
    assert table.parameters == head.parameters.names
    times = np.arange(0, 501, 20.0)
    np.testing.assert_allclose(table.sample(times), timeline.sample(times), atol=1e-9)
    assert table.values_at(100)["jaw_open"] == pytest.approx(timeline.values_at(100)["jaw_open"], abs=1e-9)
    assert table.values_at(-50) == table.values_at(0) and table.values_at(900) == table.values_at(500)


def test_tracks_csv_text_is_what_the_timeline_writes(timeline):
    times, values = timeline.sample_frames(fps=25)
    assert tracks_csv_text(timeline.parameters, times, values) == timeline.tracks_csv(fps=25)


def test_a_table_of_some_columns_keeps_the_other_parameters_at_their_default(head):
    table = parse_tracks_csv("time_ms,jaw_open\n0,0\n40,0.5\n", head)
    values = table.values_at(20)
    assert values["jaw_open"] == pytest.approx(0.25)
    assert all(values[p.name] == p.default for p in head.parameters if p.name != "jaw_open")
    assert parse_tracks_csv("time_ms,jaw_open\n0,0\n", head).fps == 60.0      # one row: a default rate


@pytest.mark.parametrize("text, where, words", [
    ("", 1, "empty tracks file"),
    ("time,jaw_open\n0,0\n", 1, "first column must be 'time_ms'"),
    ("time_ms,no_such_parameter\n0,0\n", 1, "unknown parameter 'no_such_parameter'"),
    ("time_ms,jaw_open,jaw_open\n0,0,0\n", 1, "appears twice"),
    ("time_ms,jaw_open\n0,0\n16.6,zero\n", 3, "not a number: 'zero'"),
    ("time_ms,jaw_open\n0,0,1\n", 2, "3 columns, the header has 2"),
    ("time_ms,jaw_open\n0,nan\n", 2, "finite"),
    ("time_ms,jaw_open\n10,0\n5,0\n", 3, "goes back"),
    ("time_ms,jaw_open\n0,99\n", 2, "outside its range"),
    ("time_ms,jaw_open\n\n", 1, "no rows"),
])
def test_a_bad_table_names_file_and_line(head, tmp_path, text, where, words):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(UserError) as caught:
        read_tracks_csv(path, head)
    assert caught.value.file == str(path) and caught.value.line == where
    assert words in caught.value.message


def test_an_unreadable_table_is_a_user_error(head, tmp_path):
    path = tmp_path / "latin.csv"
    path.write_bytes("time_ms,jaw_open\n0,0 ä\n".encode("latin-1"))
    with pytest.raises(UserError, match="cannot read the tracks file"):
        read_tracks_csv(path, head)


def test_load_animation_plays_command_files_and_tables(head, timeline, tmp_path):
    high = tmp_path / "two.xml"
    high.write_text(TWO_TRACKS)
    animation = load_animation(high, head)
    assert (animation.kind, animation.title, animation.path, animation.fps) == ("commands", "two", high, DEFAULT_FPS)
    assert isinstance(animation.timeline, Timeline)
    np.testing.assert_allclose(animation.timeline.sample([0, 150, 350]), timeline.sample([0, 150, 350]))
    assert load_animation(high, head, fps=25).fps == 25

    low = tmp_path / "low.xml"
    write_low_level(timeline.activations, low)
    np.testing.assert_allclose(load_animation(low, head).timeline.sample([150, 350]), timeline.sample([150, 350]))

    table = tmp_path / "two.csv"
    timeline.write_tracks(table, fps=40)
    animation = load_animation(table, head)
    assert (animation.kind, animation.fps) == ("tracks", pytest.approx(40))
    assert isinstance(animation.timeline, TracksTable)


def test_load_animation_refuses_what_it_cannot_play(head, tmp_path):
    with pytest.raises(UserError, match="no such file"):
        load_animation(tmp_path / "nothing.xml", head)
    empty = tmp_path / "empty.xml"
    empty.write_text("<commands/>")
    with pytest.raises(UserError, match="no commands to play"):
        load_animation(empty, head)
    unknown = tmp_path / "unknown.xml"
    unknown.write_text('<commands>\n  <HeadNodd at="1000"/>\n</commands>\n')
    with pytest.raises(UserError) as caught:
        load_animation(unknown, head)
    assert str(caught.value).startswith(f"{unknown}:2:")
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "Nod2.lib").write_text("$command = Nod2\n$mandatory = at\nhead_nod = 0, 0; 100, 0.1; 200, 0\n"
                                   "$proc = once\n")
    (tmp_path / "nod2.xml").write_text('<commands><Nod2 at="0"/></commands>')
    assert load_animation(tmp_path / "nod2.xml", head, [mine]).timeline.values_at(100)["head_nod"] > 0
