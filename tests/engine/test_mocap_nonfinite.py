"""Marker coordinates no capture gives: infinite, or beyond ±1 km (issue 30).

A QTM TSV with ``1e308`` beside a gap the spline fills ended in scipy's
``ValueError: `dydx` must contain only finite values`` traceback, and ``inf``
was silently taken for a gap. The rule now (``docs/mocap.md``, "Gaps"): a
missing sample is what the format writes for one — ``0 0 0`` in QTM TSV, empty
cells in TRC and CSV, and ``NaN`` in any of them —; an infinite coordinate or
one beyond ±10⁶ mm is a damaged export, refused with its file and line.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.cli import main
from engine.mocap import MarkerFileError
from engine.mocap.importer import import_marker_file
from tests.engine.test_mocap_import import IDS, face_motion, with_gaps, write_csv, write_trc, write_tsv

MARKER = IDS.index("8.3")          # with_gaps() leaves 8.3 a 3-frame gap at frames 20–22, which is filled
BESIDE = 19                        # the frame before that gap (0-based): its samples carry the spline


@pytest.fixture(scope="module")
def gappy():
    return with_gaps(face_motion()[1])


def tsv_with(tmp_path, positions, cells: dict[tuple[int, int], str]):
    """A QTM TSV of ``positions`` with some cells (frame, coordinate column) written as given; its data's first line."""
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, positions)
    lines = path.read_text().splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("1\t"))
    for (frame, column), text in cells.items():
        row = lines[first + frame].split("\t")
        row[2 + column] = text                       # after the frame number and the time
        lines[first + frame] = "\t".join(row)
    path.write_text("\n".join(lines) + "\n")
    return path, first + 1


@pytest.mark.parametrize("cells", [
    {(BESIDE, 3 * MARKER): "1e308"},
    {(BESIDE, 3 * MARKER): "1.7e308", (23, 3 * MARKER): "-1.7e308"},
    {(BESIDE, 3 * MARKER + 1): "inf"},
    {(BESIDE, 3 * MARKER + 2): "-Infinity"},
    {(BESIDE, 3 * MARKER): "2e6"},
])
def test_a_qtm_coordinate_no_capture_gives_is_refused_with_its_line(tmp_path, gappy, cells):
    path, first_line = tsv_with(tmp_path, gappy, cells)
    with pytest.raises(MarkerFileError) as caught:
        import_marker_file(path)
    message = str(caught.value)
    assert message.startswith(f"{path}:{first_line + BESIDE}: marker '8.3' ") and "not a position" in message
    assert "finite and within ±1e+06 mm" in message


def test_the_command_line_gives_one_error_line_not_scipys_traceback(tmp_path, gappy, capsys):
    path, first_line = tsv_with(tmp_path, gappy, {(BESIDE, 3 * MARKER): "1e308"})
    assert main(["mocap", "import", str(path), "-o", str(tmp_path / "s.h5")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {path}:{first_line + BESIDE}: marker '8.3' X in frame 20")
    assert not (tmp_path / "s.h5").exists()


def test_nan_in_a_qtm_file_is_a_gap_as_0_0_0_is(tmp_path, gappy):
    zeros = import_marker_file(tsv_with(tmp_path, gappy, {(BESIDE, c): "0" for c in range(3 * MARKER,
                                                                                         3 * MARKER + 3)})[0])
    nans = import_marker_file(tsv_with(tmp_path, gappy, {(BESIDE, 3 * MARKER + 1): "nan"})[0])
    assert np.isnan(nans.raw[BESIDE, MARKER]).all()                       # the whole sample is missing
    np.testing.assert_array_equal(nans.positions, zeros.positions)         # and gap-filled as the zeros are
    assert nans.report["gaps"]["8.3"] == zeros.report["gaps"]["8.3"]


@pytest.mark.parametrize("fmt", ["trc", "csv"])
def test_trc_and_csv_refuse_an_infinite_coordinate_with_its_line(tmp_path, gappy, fmt):
    p = gappy.copy()
    p[BESIDE, MARKER, 0] = np.inf
    path = tmp_path / f"take.{fmt}"
    (write_trc if fmt == "trc" else write_csv)(path, IDS, p)
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1) if "inf" in text)
    with pytest.raises(MarkerFileError, match=rf"take\.{fmt}:{line}: marker '8\.3' X in frame 20 is inf mm"):
        import_marker_file(path)


def test_a_trc_in_metres_whose_coordinate_becomes_too_large_in_mm_is_refused(tmp_path, gappy):
    p = gappy.copy()
    p[BESIDE, MARKER, 1] = 5e9                        # 5e6 m after write_trc's scaling: 5e9 mm
    path = tmp_path / "take.trc"
    write_trc(path, IDS, p, units="m")
    with pytest.raises(MarkerFileError, match=r"take\.trc:\d+: marker '8\.3' Y in frame 20 is 5e\+09 mm"):
        import_marker_file(path)
