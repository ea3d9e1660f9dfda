"""A TRC file saved comma-separated is read as the tab-separated one, and the import report says so (issue 30).

The layout is the TRC's own line for line (key line, values, names, X1 Y1 Z1,
rows); only the separator differs, and no TRC value holds a comma. Such files
come from spreadsheets, from Python scripts that write TRC with the ``csv``
module's default dialect (as pyomeca-based pipelines do) and from MATLAB
writers. They were refused ("the TRC header is separated by commas").
"""

from __future__ import annotations

import csv

import numpy as np
import pytest

from engine.cli import main
from engine.mocap import MarkerFileError
from engine.mocap.readers import detect_format, read_marker_file
from tests.engine.test_capture_corpus import DATA as CAPTURE_DATA
from tests.engine.test_mocap_import import IDS, RATE, face_motion, with_gaps, write_trc

NOTE = "read as comma-separated TRC"


@pytest.fixture(scope="module")
def gappy():
    return with_gaps(face_motion()[1])


def with_commas(tmp_path, tabbed, name="commas.trc"):
    path = tmp_path / name
    path.write_text(tabbed.read_text().replace("\t", ","))
    return path


def same(a, b) -> bool:
    return bool(np.array_equal(a.positions, b.positions, equal_nan=True)) and a.labels == b.labels


def test_a_comma_separated_trc_reads_as_its_tab_separated_twin(tmp_path, gappy):
    tabbed = tmp_path / "take.trc"
    write_trc(tabbed, IDS, gappy)
    commas = read_marker_file(with_commas(tmp_path, tabbed))
    tabs = read_marker_file(tabbed)
    assert same(commas, tabs) and commas.rate_hz == tabs.rate_hz == RATE and commas.start_ms == tabs.start_ms
    assert any(note.startswith(NOTE) for note in commas.notes) and not tabs.notes


def test_rows_that_leave_out_trailing_gaps_read_too(tmp_path, gappy):
    tabbed = tmp_path / "take.trc"
    write_trc(tabbed, IDS, gappy, trim_trailing_gaps=True)
    assert same(read_marker_file(with_commas(tmp_path, tabbed)), read_marker_file(tabbed))


def test_opensims_example_with_commas_reads(tmp_path):
    example = CAPTURE_DATA / "opensim-exampleFormat.trc"
    assert same(read_marker_file(with_commas(tmp_path, example)), read_marker_file(example))


def test_a_trc_written_by_the_csv_module_reads(tmp_path, gappy):
    """The ``csv`` module's default dialect: CRLF line ends, empty cells for the names' padding and for gaps,
    an empty row before the data, a quoted name holding a comma."""
    names = ["a, b", *IDS[1:]]
    path = tmp_path / "written.trc"
    rows = [["PathFileType", 4, "(X/Y/Z)", str(path)],
            ["DataRate", "CameraRate", "NumFrames", "NumMarkers", "Units", "OrigDataRate", "OrigDataStartFrame",
             "OrigNumFrames"],
            [RATE, RATE, len(gappy), len(names), "mm", RATE, 1, len(gappy)],
            ["Frame#", "Time", *[cell for n in names for cell in (n, None, None)]],
            ["", "", *[f"{a}{k + 1}" for k in range(len(names)) for a in "XYZ"]],
            []]
    rows += [[f + 1, f / RATE, *["" if np.isnan(v) else repr(float(v)) for v in frame.ravel()]]
             for f, frame in enumerate(gappy)]
    with path.open("w", newline="") as stream:
        csv.writer(stream).writerows(rows)
    assert b"\r\n" in path.read_bytes() and b'"a, b"' in path.read_bytes()
    recording = read_marker_file(path)
    assert recording.labels == names and NOTE in recording.notes[0]
    np.testing.assert_array_equal(recording.positions, gappy)


def test_content_tells_a_comma_separated_trc_whatever_its_name(tmp_path, gappy):
    tabbed = tmp_path / "take.trc"
    write_trc(tabbed, IDS, gappy)
    assert detect_format(with_commas(tmp_path, tabbed, "export.txt")) == "trc"


def test_the_import_report_says_how_it_was_read(tmp_path, gappy, capsys):
    tabbed = tmp_path / "take.trc"
    write_trc(tabbed, IDS, gappy)
    assert main(["mocap", "import", str(with_commas(tmp_path, tabbed)), "-o", str(tmp_path / "s.h5")]) == 0
    out = capsys.readouterr().out
    assert f"note: {NOTE}" in out, out


def test_a_bad_cell_in_a_comma_separated_trc_names_its_line_and_column(tmp_path, gappy):
    tabbed = tmp_path / "take.trc"
    write_trc(tabbed, IDS, gappy[:8])
    lines = tabbed.read_text().replace("\t", ",").splitlines()
    cells = lines[8].split(",")
    cells[4] = "x"
    lines[8] = ",".join(cells)
    path = tmp_path / "bad.trc"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(MarkerFileError, match=r"bad\.trc:9: column 5: 'x' is not a number"):
        read_marker_file(path)
