"""Motion-capture import (§3.1.1): readers, naming, gaps, head motion, labels, sessions, CLI.

Marker files are written by the small writers below from known arrays —
markers on a talking face with head motion, dropouts and gaps — and read
back: import must be exact (to the precision of each format), gaps filled or
left as configured, head motion removed to ~1e-9 mm for noise-free data, and
every bad file must end in one error naming file and line. The hand-written
files in ``data/mocap/`` look like real exports (QTM with its column row and
an EVENT line, an OpenSim-style TRC in metres, Praat and Audacity labels).
"""

from __future__ import annotations

import doctest
import importlib
import json
from pathlib import Path

import h5py
import numpy as np
import pytest

from engine.cli import main
from engine.deform.transforms import rotation_about_axis, translation
from engine.mocap import LabelFileError, MarkerFileError, MocapError, Session, SessionFileError
from engine.mocap.csv_table import CsvLayout
from engine.mocap.gaps import fill_gaps, find_gaps, max_gap_frames
from engine.mocap.head_motion import apply_alignment, kabsch, remove_head_motion
from engine.mocap.importer import build_session, format_report, import_marker_file
from engine.mocap.naming import default_reference, marker_names, read_mapping
from engine.mocap.readers import detect_format, read_marker_file
from engine.mocap.recording import Recording
from engine.mocap.session import SESSION_FORMAT, load_session, save_session
from engine.speech.labels import festival_phones, read_labels
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run

DATA = Path(__file__).parent / "data" / "mocap"
pytestmark = pytest.mark.filterwarnings("ignore:No analog data found in file:UserWarning")  # c3d writer, no analog
RATE = 60.0
# the paper's markers (§3.1.1): lip contour 8.x, chin 2.1, and head-fixed reference points
IDS = ["2.1", "8.1", "8.2", "8.3", "8.4", "8.5", "8.6", "8.7", "8.8", "9.3", "11.1", "20.1", "20.2"]
REFERENCE = ["9.3", "11.1", "20.1", "20.2"]
REST = np.array([
    [0, -95, 70], [0, -38, 95], [0, -52, 93], [27, -45, 84], [-27, -45, 84], [14, -39, 91], [-14, -39, 91],
    [14, -50, 89], [-14, -50, 89], [0, 0, 105], [0, 85, 85], [65, 55, 30], [-65, 55, 30]], dtype=float)


# ---------------------------------------------------------------------------
# known motion: speech-like lip and jaw movement, carried by a moving head
# ---------------------------------------------------------------------------

def face_motion(n_frames: int = 90, seed: int = 0):
    """(clean, raw): markers in the head's own frame (mm), and the same moved by head motion.

    Frame 0 carries no head motion, so ``clean`` is what head-motion removal
    against the first frame must give back.
    """
    rng = np.random.default_rng(seed)
    t = np.arange(n_frames) / RATE
    clean = np.repeat(REST[None], n_frames, axis=0)
    jaw = 6 * (1 - np.cos(2 * np.pi * 3.1 * t))            # jaw opening, mm
    widen = 3 * np.sin(2 * np.pi * 1.7 * t + 0.4)         # mouth widening
    protrude = 2 * np.sin(2 * np.pi * 2.3 * t + 1.1)     # lip protrusion
    lower = [0, 2, 7, 8]
    clean[:, lower, 1] -= jaw[:, None] * np.array([1.0, 0.8, 0.7, 0.7])
    clean[:, 3, 0] += widen
    clean[:, 4, 0] -= widen
    clean[:, 1:9, 2] += protrude[:, None]
    raw = np.empty_like(clean)
    axis = rng.normal(size=3)
    for f in range(n_frames):
        angle = 8 * np.sin(2 * np.pi * 0.4 * t[f])
        T = rotation_about_axis(axis, [0, 0, -80], angle) @ translation([4 * t[f], -3 * t[f] ** 2, 2 * t[f]])
        raw[f] = clean[f] @ T[:3, :3] + T[3, :3]
    return clean, raw


def with_gaps(raw: np.ndarray) -> np.ndarray:
    """Dropouts: a 3-frame gap in 8.3, a 40-frame gap in 8.4, a 1-frame dropout of 11.1, 8.8 missing at the end."""
    p = raw.copy()
    p[20:23, 3] = np.nan
    p[30:70, 4] = np.nan
    p[50, 10] = np.nan
    p[-4:, 8] = np.nan
    return p


# ---------------------------------------------------------------------------
# writers: each format as its exporters write it
# ---------------------------------------------------------------------------

def _num(v: float) -> str:
    return repr(float(v))


def write_tsv(path, labels, p, rate=RATE, column_row=True, frame_time=True, events=(), newline="\n"):
    lines = [f"NO_OF_FRAMES\t{len(p)}", "NO_OF_CAMERAS\t8", f"NO_OF_MARKERS\t{len(labels)}", f"FREQUENCY\t{rate:g}",
             "NO_OF_ANALOG\t0", "ANALOG_FREQUENCY\t0", "DESCRIPTION\t--", "TIME_STAMP\t2003-05-14, 10:00:00\t12.5",
             "DATA_INCLUDED\t3D"]
    lines += [f"EVENT\t{name}\t{frame}\t{frame / rate:.5f}" for name, frame in events]
    lines += ["MARKER_NAMES\t" + "\t".join(labels), "TRAJECTORY_TYPES\t" + "\t".join(["Measured"] * len(labels))]
    if column_row:
        lines.append("Frame\tTime\t" + "\t".join(f"{n} {a}" for n in labels for a in "XYZ") + "\t")
    for f, frame in enumerate(np.nan_to_num(p, nan=0.0)):  # QTM writes a gap as 0 0 0
        cells = [_num(v) for v in frame.ravel()]
        lines.append("\t".join(([str(f + 1), f"{f / rate:.5f}"] if frame_time else []) + cells))
    Path(path).write_text(newline.join(lines) + newline)


def write_trc(path, labels, p, rate=RATE, units="mm", trim_trailing_gaps=False):
    scale = {"mm": 1.0, "cm": 0.1, "m": 0.001}[units]
    n = len(labels)
    lines = [f"PathFileType\t4\t(X/Y/Z)\t{Path(path).name}",
             "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames",
             f"{rate:.2f}\t{rate:.2f}\t{len(p)}\t{n}\t{units}\t{rate:.2f}\t1\t{len(p)}",
             "Frame#\tTime\t" + "\t\t\t".join(labels) + "\t\t",
             "\t\t" + "\t".join(f"{a}{k + 1}" for k in range(n) for a in "XYZ"), ""]
    for f, frame in enumerate(p):
        cells = ["" if np.isnan(v) else _num(v * scale) for v in frame.ravel()]
        while trim_trailing_gaps and cells and cells[-1] == "":
            cells.pop()
        lines.append("\t".join([str(f + 1), f"{f / rate:.6f}", *cells]))
    Path(path).write_text("\n".join(lines) + "\n")


def write_csv(path, labels, p, rate=RATE, pattern="{marker}_{axis}", time="time_ms", gap="", sep=","):
    head = (["frame", time] if time else ["frame"]) + [pattern.format(marker=n, axis=a) for n in labels for a in "xyz"]
    lines = [sep.join(head)]
    for f, frame in enumerate(p):
        stamp = {"time_ms": _num(f * 1000 / rate), "time_s": _num(f / rate), None: None}[time]
        cells = [gap if np.isnan(v) else _num(v) for v in frame.ravel()]
        lines.append(sep.join([str(f)] + ([stamp] if time else []) + cells))
    Path(path).write_text("\n".join(lines) + "\n")


def write_c3d(path, labels, p, rate=RATE, scale=-1.0, units="mm  "):
    c3d = pytest.importorskip("c3d")
    writer = c3d.Writer(point_rate=rate, point_scale=scale, point_units=units)
    writer.set_point_labels(labels)
    frames = []
    for frame in p:
        points = np.zeros((len(labels), 5), np.float32)
        gap = np.isnan(frame[:, 0])
        points[:, :3] = np.nan_to_num(frame)
        points[gap, 3] = -1  # residual -1: no sample
        frames.append((points, np.zeros((0, 0))))
    writer.add_frames(frames)
    with open(path, "wb") as fh:
        writer.write(fh)


def same_gaps(a, b) -> bool:
    return bool(np.array_equal(np.isnan(a), np.isnan(b)))


# ---------------------------------------------------------------------------
# readers: exact, units to mm, rate kept, gaps found
# ---------------------------------------------------------------------------

@pytest.fixture(scope="module")
def motion():
    clean, raw = face_motion()
    return clean, raw, with_gaps(raw)


@pytest.mark.parametrize("column_row, frame_time", [(True, True), (False, True), (False, False)])
def test_qtm_tsv_exact_with_zero_triplets_as_gaps(tmp_path, motion, column_row, frame_time):
    _, _, p = motion
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, p, column_row=column_row, frame_time=frame_time, events=[("start", 6)])
    rec = read_marker_file(path)
    assert rec.format == "tsv" and rec.labels == IDS and rec.rate_hz == RATE
    assert same_gaps(rec.positions, p)
    assert np.array_equal(np.nan_to_num(rec.positions), np.nan_to_num(p))  # repr floats: bit-exact
    assert rec.events == [("start", pytest.approx(100.0, abs=0.01))]


def test_qtm_sample_file_with_column_row_event_and_trajectory_types():
    rec = read_marker_file(DATA / "qtm_sample.tsv")
    assert rec.labels == ["HEAD_L", "HEAD_R", "FOREHEAD", "JAW"]
    assert rec.positions.shape == (6, 4, 3) and rec.rate_hz == 60
    assert np.isnan(rec.positions[3, 3]).all() and np.isfinite(np.delete(rec.positions, 3, axis=0)).all()
    assert rec.positions[4, 3].tolist() == [0.0, -105.0, 70.0]
    assert rec.events[0][0] == "sentence start"


def test_qtm_windows_line_ends(tmp_path, motion):
    _, _, p = motion
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, p[:10], newline="\r\n")
    assert np.array_equal(np.nan_to_num(read_marker_file(path).positions), np.nan_to_num(p[:10]))


@pytest.mark.parametrize("units", ["mm", "cm", "m"])
def test_trc_exact_in_mm_with_empty_cells_as_gaps(tmp_path, motion, units):
    _, _, p = motion
    path = tmp_path / "take.trc"
    write_trc(path, IDS, p, units=units)
    rec = read_marker_file(path)
    assert rec.format == "trc" and rec.labels == IDS and rec.rate_hz == RATE and rec.units == units
    assert same_gaps(rec.positions, p)
    np.testing.assert_allclose(np.nan_to_num(rec.positions), np.nan_to_num(p), rtol=1e-14, atol=1e-12)


def test_trc_rows_may_leave_out_trailing_empty_cells(tmp_path, motion):
    _, _, p = motion
    path = tmp_path / "take.trc"
    q = p.copy()
    q[-3:, -2:] = np.nan  # the last two markers missing at the end: their cells are left out
    write_trc(path, IDS, q, trim_trailing_gaps=True)
    assert len(path.read_text().splitlines()[-1].split("\t")) == 2 + 3 * (len(IDS) - 2)
    rec = read_marker_file(path)
    assert same_gaps(rec.positions, q)
    assert np.array_equal(np.nan_to_num(rec.positions), np.nan_to_num(q))


def test_trc_sample_file_in_metres():
    rec = read_marker_file(DATA / "trc_sample.trc")
    assert rec.labels == ["Nose", "Chin", "FP8_3"] and rec.rate_hz == 100
    np.testing.assert_allclose(rec.positions[1, 1], [0, -91, 80])
    assert np.isnan(rec.positions[2, 1]).all() and np.isnan(rec.positions[4, 2]).all()
    assert np.isfinite(rec.positions[4, :2]).all()


@pytest.mark.parametrize("pattern, time, gap, sep", [
    ("{marker}_{axis}", "time_ms", "", ","),
    ("{marker}.{axis}", "time_s", "NaN", ";"),
    ("{marker} {axis}", "time_ms", "nan", "\t"),
])
def test_csv_exact_with_default_column_patterns(tmp_path, motion, pattern, time, gap, sep):
    _, _, p = motion
    path = tmp_path / "take.csv"
    write_csv(path, IDS, p, pattern=pattern.replace("{axis}", "{axis}"), time=time, gap=gap, sep=sep)
    rec = read_marker_file(path)
    assert rec.format == "csv" and rec.labels == IDS and rec.rate_hz == RATE
    assert same_gaps(rec.positions, p)
    assert np.array_equal(np.nan_to_num(rec.positions), np.nan_to_num(p))


def test_csv_column_mapping_rate_and_units(tmp_path, motion):
    _, _, p = motion
    path = tmp_path / "export.csv"
    write_csv(path, IDS, p / 1000.0, pattern="{marker}_pos_{axis}", time=None)
    layout = CsvLayout(columns="{marker}_pos_{axis}", rate_hz=120, units="m")
    rec = read_marker_file(path, csv_layout=layout)
    assert rec.rate_hz == 120 and rec.labels == IDS
    np.testing.assert_allclose(np.nan_to_num(rec.positions), np.nan_to_num(p), rtol=1e-14)
    with pytest.raises(MarkerFileError, match=r"export.csv:1: no time column"):
        read_marker_file(path, csv_layout=CsvLayout(columns="{marker}_pos_{axis}"))
    # the default patterns read '2.1_pos_x' as marker '2.1_pos'
    assert read_marker_file(path, csv_layout=CsvLayout(rate_hz=60)).labels == [f"{n}_pos" for n in IDS]
    path.write_text("time_ms,chin,lip\n0,1,2\n")
    with pytest.raises(MarkerFileError, match=r"export.csv:1: no marker columns"):
        read_marker_file(path)


def test_landmarks_table_of_say_reads_as_csv(tmp_path):
    path = tmp_path / "landmarks.csv"
    path.write_text("frame,time_ms,2.1_x,2.1_y,2.1_z,8.3_x,8.3_y,8.3_z\n0,0.000,0,-95,70,27,-45,84\n"
                    "1,33.333,0,-96,70,27,-45,84\n2,66.667,0,-97,70,27,-45,84\n")
    rec = read_marker_file(path)
    assert rec.labels == ["2.1", "8.3"] and rec.rate_hz == 30.0


@pytest.mark.parametrize("scale", [-1.0, 0.01])
def test_c3d_float_and_integer_points(tmp_path, motion, scale):
    _, _, p = motion
    path = tmp_path / "take.c3d"
    write_c3d(path, IDS, p, scale=scale)
    rec = read_marker_file(path)
    assert rec.format == "c3d" and rec.labels == IDS and rec.rate_hz == RATE
    assert same_gaps(rec.positions, p)
    tolerance = 1e-4 if scale < 0 else abs(scale) + 1e-9  # float32, or the integer step (the writer truncates)
    np.testing.assert_allclose(np.nan_to_num(rec.positions), np.nan_to_num(p), atol=tolerance)


def test_c3d_one_pass_read_agrees_with_the_readers_frame_iterator(tmp_path, motion):
    c3d = pytest.importorskip("c3d")
    _, _, p = motion
    path = tmp_path / "take.c3d"
    write_c3d(path, IDS, p, units="m   ")
    rec = read_marker_file(path)
    with open(path, "rb") as fh:
        frames = [pts.copy() for _, pts, _ in c3d.Reader(fh).read_frames()]
    reference = np.array([f[:, :3] for f in frames], dtype=float) * 1000.0
    reference[np.array([f[:, 3] < 0 for f in frames])] = np.nan
    assert same_gaps(rec.positions, reference)
    assert np.array_equal(np.nan_to_num(rec.positions), np.nan_to_num(reference))


def test_format_detection_by_content_then_extension(tmp_path, motion):
    _, _, p = motion
    for writer, fmt in ((write_tsv, "tsv"), (write_trc, "trc")):
        path = tmp_path / f"export_{fmt}.txt"
        writer(path, IDS, p[:5])
        assert detect_format(path) == fmt
    csv = tmp_path / "table.txt"
    write_csv(csv, IDS, p[:5])
    assert detect_format(csv) == "csv"
    odd = tmp_path / "notes.dat"
    odd.write_text("hello\n")
    with pytest.raises(MarkerFileError, match=r"notes.dat:1: unknown marker file format"):
        read_marker_file(odd)
    text = tmp_path / "xp.tsv"  # a text file whose second byte is C3D's key 'P' is still text
    text.write_text("XP" + "a" * 600 + "\n")
    with pytest.raises(MarkerFileError, match=r"xp.tsv:1: 'XPa+…' is neither a QTM header key nor a data row"):
        read_marker_file(text)
    empty = tmp_path / "empty.tsv"
    empty.write_text("NO_OF_FRAMES\t0\nNO_OF_MARKERS\t1\nFREQUENCY\t60\nMARKER_NAMES\ta\n")
    with pytest.raises(MarkerFileError, match=r"empty.tsv:4: the file ends before its data"):
        read_marker_file(empty)


# ---------------------------------------------------------------------------
# bad files: one error, naming file and line
# ---------------------------------------------------------------------------

def _tsv_lines(tmp_path, motion, **kw) -> tuple[Path, list[str]]:
    path = tmp_path / "bad.tsv"
    write_tsv(path, IDS, motion[2][:8], **kw)
    return path, path.read_text().splitlines()


def _rewrite(path: Path, lines: list[str], newline=True):
    path.write_text("\n".join(lines) + ("\n" if newline else ""))


def test_tsv_errors_name_file_and_line(tmp_path, motion):
    path, lines = _tsv_lines(tmp_path, motion)
    first_data = next(i for i, ln in enumerate(lines) if ln.startswith("1\t"))
    cases = []
    # truncated: two frames fewer than NO_OF_FRAMES
    cases.append((lines[:-2], rf"bad.tsv:{len(lines) - 2}: the file ends after 6 frames but NO_OF_FRAMES is 8"))
    # truncated in the middle of the last row
    cases.append(([*lines[:-1], lines[-1][:40]], rf"bad.tsv:{len(lines)}: \d+ columns where 41 were expected "
                                                  r"\(the file looks truncated\)"))
    # a row with a cell too many
    wrong = list(lines)
    wrong[first_data + 2] += "\t1.0"
    cases.append((wrong, rf"bad.tsv:{first_data + 3}: 42 columns where 41 were expected"))
    # a non-numeric cell
    bad = list(lines)
    cells = bad[first_data + 4].split("\t")
    cells[7] = "12,5"
    bad[first_data + 4] = "\t".join(cells)
    cases.append((bad, rf"bad.tsv:{first_data + 5}: column 8: '12,5' is not a number"))
    # a missing header key
    cases.append(([ln for ln in lines if not ln.startswith("FREQUENCY")], r"bad.tsv:\d+: .*lacks FREQUENCY"))
    # marker count that disagrees with the names
    names = [ln.replace("NO_OF_MARKERS\t13", "NO_OF_MARKERS\t12") for ln in lines]
    cases.append((names, r"bad.tsv:\d+: MARKER_NAMES lists 13 names but NO_OF_MARKERS is 12"))
    # a column header that lacks a marker's column
    col = [ln.replace("8.3 Y", "8.3 Q") for ln in lines]
    cases.append((col, r"bad.tsv:\d+: the column-header row has no column '8.3 Y'"))
    two_d = [ln.replace("DATA_INCLUDED\t3D", "DATA_INCLUDED\t2D") for ln in lines]
    cases.append((two_d, r"bad.tsv:9: DATA_INCLUDED is '2D'"))
    for content, pattern in cases:
        _rewrite(path, content)
        with pytest.raises(MarkerFileError, match=pattern):
            read_marker_file(path)


def test_trc_errors_name_file_and_line(tmp_path, motion):
    path = tmp_path / "bad.trc"
    write_trc(path, IDS, motion[2][:8])
    lines = path.read_text().splitlines()
    cases = [
        (lines[:-3], rf"bad.trc:{len(lines) - 3}: the file ends after 5 frames but NumFrames is 8"),
        ([lines[0], lines[1].replace("Units", "Unit"), *lines[2:]], r"bad.trc:2: the TRC header lacks Units"),
        ([*lines[:2], lines[2].replace("\tmm\t", "\tinch\t"), *lines[3:]], r"bad.trc:3: unknown length unit 'inch'"),
        ([*lines[:8], lines[8].replace("\t", "\tx", 3), *lines[9:]], r"bad.trc:9: column 2: 'x.*' is not a number"),
        (lines[:3], r"bad.trc:3: the TRC header ends early"),
        ([*lines[:3], lines[3] + "\textra", *lines[4:]], r"bad.trc:4: the marker-name line lists 14 markers"),
    ]
    for content, pattern in cases:
        _rewrite(path, content)
        with pytest.raises(MarkerFileError, match=pattern):
            read_marker_file(path)
    # cut in the middle of the last row (no line end): truncation, not a row with trailing gaps
    path.write_text("\n".join(lines[:-1]) + "\n" + "\t".join(lines[-1].split("\t")[:8]))
    with pytest.raises(MarkerFileError, match=rf"bad.trc:{len(lines)}: 8 columns where 41 were expected"):
        read_marker_file(path)


def test_csv_errors_name_file_and_line(tmp_path, motion):
    path = tmp_path / "bad.csv"
    write_csv(path, IDS, motion[2][:8])
    lines = path.read_text().splitlines()
    bad = list(lines)
    bad[4] = bad[4].replace(",", ",abc,", 1)
    _rewrite(path, bad)
    with pytest.raises(MarkerFileError, match=r"bad.csv:5: 42 columns where 41 were expected"):
        read_marker_file(path)
    bad = list(lines)
    bad[3] = bad[3].rsplit(",", 1)[0] + ",1.2.3"
    _rewrite(path, bad)
    with pytest.raises(MarkerFileError, match=r"bad.csv:4: column 41: '1.2.3' is not a number"):
        read_marker_file(path)
    bad = list(lines)
    bad[6] = "5,999," + bad[6].split(",", 2)[2]
    _rewrite(path, bad)
    with pytest.raises(MarkerFileError, match=r"bad.csv:7: the time column is not evenly spaced"):
        read_marker_file(path)


def test_c3d_errors(tmp_path, motion):
    path = tmp_path / "bad.c3d"
    write_c3d(path, IDS, motion[2])
    data = path.read_bytes()
    path.write_bytes(data[:len(data) - 3000])                          # cut short: what is there is read
    cut = read_marker_file(path)
    assert 0 < cut.n_frames < 90 and any(f"after {cut.n_frames} of the 90 frames" in n for n in cut.notes)
    path.write_bytes(data[:300])
    with pytest.raises(MarkerFileError, match=r"bad.c3d: "):
        read_marker_file(path, format="c3d")
    path.write_bytes(bytes([2, 0x50]) + b"\xff" * 1200)
    with pytest.raises(MarkerFileError, match=r"bad.c3d: not a readable C3D file"):
        read_marker_file(path)


# ---------------------------------------------------------------------------
# gaps
# ---------------------------------------------------------------------------

def test_short_gaps_filled_by_spline_long_and_edge_gaps_left_missing(motion):
    _, raw, p = motion
    filled, was_filled, missing, report = fill_gaps(p, max_gap_frames=max_gap_frames(100, RATE))
    assert was_filled[20:23, 3].all() and was_filled[50, 10] and was_filled.sum() == 4
    np.testing.assert_allclose(filled[20:23, 3], raw[20:23, 3], atol=0.05)  # smooth motion: spline is close
    assert np.isnan(filled[30:70, 4]).all() and missing[30:70, 4].all()
    assert np.isnan(filled[-4:, 8]).all()  # nothing after it to interpolate towards
    assert missing.sum() == 44
    assert report[3] == {"gaps": 1, "filled_gaps": 1, "filled_frames": 3, "missing_gaps": 0, "missing_frames": 0}
    assert report[4] == {"gaps": 1, "filled_gaps": 0, "filled_frames": 0, "missing_gaps": 1, "missing_frames": 40}
    assert report[8]["missing_gaps"] == 1 and report[0]["gaps"] == 0


def test_maximum_gap_length_is_inclusive():
    x = np.tile(np.arange(30.0)[:, None, None], (1, 2, 3))
    x[5:11, 0] = np.nan    # 6 frames
    x[15:22, 1] = np.nan   # 7 frames
    _, was_filled, missing, _ = fill_gaps(x, max_gap_frames=6)
    assert was_filled[5:11, 0].all() and missing[15:22, 1].all()
    assert max_gap_frames(100, 60) == 6 and max_gap_frames(116.7, 60) == 7
    assert find_gaps(np.zeros(4, bool)) == []


# ---------------------------------------------------------------------------
# head motion
# ---------------------------------------------------------------------------

def test_head_motion_removed_exactly_for_noise_free_data(motion):
    clean, raw, _ = motion
    ref = [IDS.index(r) for r in REFERENCE]
    aligned, alignment, info = remove_head_motion(raw, np.zeros(raw.shape[:2], bool), ref)
    assert info["reference_frame"] == 0 and info["unaligned_frames"] == 0
    assert np.abs(aligned - clean).max() < 1e-9
    assert np.nanmax(info["residual_rms_mm"]) < 1e-9
    np.testing.assert_allclose(apply_alignment(raw, alignment), aligned)
    R = alignment[:, :3, :3]
    np.testing.assert_allclose(R @ R.transpose(0, 2, 1), np.tile(np.eye(3), (len(R), 1, 1)), atol=1e-12)
    assert np.allclose(np.linalg.det(R), 1.0) and np.allclose(alignment[:, :3, 3], 0)


def test_head_motion_uses_the_reference_markers_each_frame_has(motion):
    clean, raw, _ = motion
    ref = [IDS.index(r) for r in REFERENCE]
    missing = np.zeros(raw.shape[:2], bool)
    missing[10:20, ref[0]] = True  # one of four reference markers out: three still fix the head
    missing[40, ref[:2]] = True    # two left: cannot be aligned
    p = raw.copy()
    p[missing] = np.nan
    aligned, alignment, info = remove_head_motion(p, missing, ref)
    ok = np.ones(len(p), bool)
    ok[40] = False
    assert np.nanmax(np.abs(aligned[ok] - clean[ok])) < 1e-9
    assert info["unaligned_frames"] == 1 and np.isnan(alignment[40]).all()


def test_mean_reference_shape_keeps_the_reference_markers_still(motion):
    _, raw, _ = motion
    ref = [IDS.index(r) for r in REFERENCE]
    aligned, _, info = remove_head_motion(raw, np.zeros(raw.shape[:2], bool), ref, reference_frame="mean")
    assert info["reference_frame"] == "mean"
    assert np.abs(aligned[:, ref] - aligned[0, ref]).max() < 1e-9
    d = np.linalg.norm(aligned[:, 0] - aligned[:, 1], axis=1)  # a rigid move keeps distances
    np.testing.assert_allclose(d, np.linalg.norm(raw[:, 0] - raw[:, 1], axis=1))


def test_kabsch_refuses_collinear_points():
    line = np.array([[[0.0, 0, 0], [1, 0, 0], [2, 0, 0]]])
    assert np.isnan(kabsch(line, line[0], np.ones((1, 3), bool))).all()


def test_too_few_reference_markers(motion):
    rec = Recording(labels=["2.1", "8.3", "9.3"], positions=motion[1][:, [0, 3, 9]], rate_hz=60, source="x.tsv",
                    format="tsv")
    with pytest.raises(MocapError, match=r"x.tsv: cannot remove head motion: it needs at least 3"):
        build_session(rec)
    session = build_session(rec, reference=[])
    assert session.report["head_motion"] is None and np.array_equal(session.alignment[5], np.eye(4))
    with pytest.raises(MocapError, match=r"reference marker.* 20\.1 are not in the file"):
        build_session(rec, reference=["9.3", "2.1", "20.1"])


# ---------------------------------------------------------------------------
# naming
# ---------------------------------------------------------------------------

def test_mapping_file_and_automatic_ids(tmp_path):
    mapping = read_mapping(DATA / "face.map")
    assert mapping == {"HEAD_L": "20.1", "HEAD_R": "20.2", "FOREHEAD": "11.1", "JAW": "2.1"}
    names, info = marker_names(["HEAD_L", "FP8_3", "mpeg4_9.3", "Cheek L", "junk"], {"HEAD_L": "20.1", "junk": "-"})
    assert names == ["20.1", "8.3", "9.3", "Cheek L", None]
    assert info["dropped"] == ["junk"] and info["renamed"]["FP8_3"] == "8.3"
    with pytest.raises(MocapError, match=r"'8\.3' and 'LM' would both be named '8\.3'"):
        marker_names(["8.3", "LM"], {"LM": "8.3"})
    assert default_reference(IDS) == REFERENCE


@pytest.mark.parametrize("text, pattern", [
    ("a = 8.3\nb 8.4\n", r"bad.map:2: expected 'label = id'"),
    ("a = 8.3\na = 8.4\n", r"bad.map:2: label 'a' is mapped twice"),
    ("a = 8.3\n# comment\nb = 8.3\n", r"bad.map:3: id '8.3' is already given to another label on line 1"),
])
def test_mapping_file_errors(tmp_path, text, pattern):
    path = tmp_path / "bad.map"
    path.write_text(text)
    with pytest.raises(LabelFileError, match=pattern):
        read_mapping(path)


# ---------------------------------------------------------------------------
# phone labels
# ---------------------------------------------------------------------------

EXPECTED_PHONES = [(20.0, 50.0, "m"), (50.0, 100.0, "a:")]


@pytest.mark.parametrize("name", ["phones_long.TextGrid", "phones_short.TextGrid", "phones.txt"])
def test_phone_label_files(name):
    phones = read_labels(DATA / name)
    assert [(pytest.approx(a), pytest.approx(b), c) for a, b, c in phones] == EXPECTED_PHONES


def test_textgrid_tier_choice_and_utf16(tmp_path):
    words = read_labels(DATA / "phones_long.TextGrid", tier="words")
    assert words == [(0.0, 100.0, "maa")]
    path = tmp_path / "utf16.TextGrid"
    path.write_bytes((DATA / "phones_long.TextGrid").read_text().replace('"a:"', '"ä"').encode("utf-16"))
    assert read_labels(path)[-1][2] == "ä"
    with pytest.raises(LabelFileError, match=r"no interval tier named 'syllables' \(there are 'words', 'phones'\)"):
        read_labels(DATA / "phones_long.TextGrid", tier="syllables")


def test_label_file_in_ms_and_phones_csv(tmp_path):
    ms = tmp_path / "ms.lab"
    ms.write_text("# units: ms\n20 50 m\n50 100 a:\n")
    assert read_labels(ms) == EXPECTED_PHONES
    csv = tmp_path / "phones.csv"
    csv.write_text("start_ms,end_ms,phone,word\n20.0,50.0,m,maa\n50.0,100.0,a:,maa\n")
    assert read_labels(csv) == EXPECTED_PHONES


@pytest.mark.parametrize("text, pattern", [
    ("0.1 0.2 a\n0.2 b\n", r"bad.lab:2: expected 'start end label'"),
    ("0.1 x a\n", r"bad.lab:1: '0.1 x' are not two times"),
    ("0.3 0.2 a\n", r"bad.lab:1: segment ends"),
    ('File type = "ooTextFile"\nObject class = "TextGrid"\n0\n1\n<exists>\n1\n"IntervalTier"\n"p"\n0\n1\n2\n0\n0.5\n',
     r"bad.lab:\d+: the TextGrid ends early"),
])
def test_label_file_errors(tmp_path, text, pattern):
    path = tmp_path / "bad.lab"
    path.write_text(text)
    with pytest.raises(LabelFileError, match=pattern):
        read_labels(path)


class FakeSynthesizer:
    """Festival's interface (synthesize(text, voice).phones) with fixed timings."""

    def synthesize(self, text, voice=None):
        from engine.speech.synthesis import Segment

        class Utterance:
            def __init__(self) -> None:
                self.phones = [Segment("#", 0.0, 100.0, ""), Segment("m", 100.0, 180.0, "maa"),
                               Segment("a:", 180.0, 400.0, "maa")]
        return Utterance()


def test_phones_from_festival_timing_as_is_or_stretched():
    assert festival_phones("maa", synthesizer=FakeSynthesizer())[1] == (100.0, 180.0, "m")
    stretched = festival_phones("maa", duration_ms=800, synthesizer=FakeSynthesizer())
    assert stretched[-1] == (360.0, 800.0, "a:")


@pytest.mark.skipif(__import__("shutil").which("festival") is None, reason="Festival is not installed")
def test_cli_phones_from_real_festival(tmp_path, motion, capsys):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2])
    out = tmp_path / "s.h5"
    assert main(["mocap", "import", str(path), "--text", "Papu", "--stretch-text", "-o", str(out)]) == 0
    phones = load_session(out).phones
    assert [p[2] for p in phones if p[2] != "#"] == ["p", "a", "p", "u"]
    assert phones[-1][1] == pytest.approx(len(motion[2]) * 1000 / RATE)
    assert "phones: " in capsys.readouterr().out


# ---------------------------------------------------------------------------
# the whole import and the session file
# ---------------------------------------------------------------------------

def test_import_names_fills_aligns_and_reports(tmp_path, motion):
    clean, _raw, p = motion
    labels = [f"M{k}" for k in range(len(IDS))]
    mapping = tmp_path / "lab.map"
    mapping.write_text("".join(f"{a} = {b}\n" for a, b in zip(labels, IDS, strict=True)))
    path = tmp_path / "take.tsv"
    write_tsv(path, labels, p)
    session = import_marker_file(path, mapping=mapping, max_gap_ms=100, labels=DATA / "phones_long.TextGrid")
    assert session.markers == IDS and session.reference == REFERENCE and session.rate_hz == RATE
    assert np.array_equal(np.nan_to_num(session.raw), np.nan_to_num(p)) and same_gaps(session.raw, p)
    ok = ~session.missing
    assert np.abs(session.positions[ok] - clean[ok]).max() < 0.05  # filled samples: spline-close; others exact
    exact = ok & ~session.filled
    assert np.abs(session.positions[exact] - clean[exact]).max() < 1e-9
    assert session.missing.sum() == 44 and session.filled.sum() == 4
    np.testing.assert_allclose(apply_alignment(np.where(np.isnan(p), 0, p), session.alignment)[exact],
                               session.positions[exact])
    gaps = session.report["gaps"]
    assert gaps["8.4"]["missing_frames"] == 40 and gaps["8.3"]["filled_frames"] == 3
    assert session.phones == [(pytest.approx(20.0), pytest.approx(50.0), "m"),
                              (pytest.approx(50.0), pytest.approx(100.0), "a:")]
    text = format_report(session)
    assert "8.4" in text and "head motion removed: reference 9.3, 11.1, 20.1, 20.2" in text
    assert "phones: 2 from phones_long.TextGrid" in text


def test_the_same_motion_imports_alike_from_every_format(tmp_path, motion):
    pytest.importorskip("c3d")
    clean, _, p = motion
    sessions = {}
    for fmt, writer in (("tsv", write_tsv), ("trc", write_trc), ("csv", write_csv), ("c3d", write_c3d)):
        path = tmp_path / f"take.{fmt}"
        writer(path, IDS, p)
        sessions[fmt] = import_marker_file(path)
    for fmt, s in sessions.items():
        assert np.array_equal(s.missing, sessions["tsv"].missing), fmt
        tolerance = 1e-3 if fmt == "c3d" else 1e-9  # C3D keeps float32
        ok = ~s.missing & ~s.filled
        assert np.abs(s.positions[ok] - clean[ok]).max() < tolerance, fmt


def test_session_round_trip(tmp_path, motion):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2])
    session = import_marker_file(path, labels=DATA / "phones.txt")
    out = tmp_path / "take.h5"
    save_session(session, out)
    back = load_session(out)
    for name in ("markers", "rate_hz", "phones", "source", "report", "reference"):
        assert getattr(back, name) == getattr(session, name), name
    for name in ("positions", "raw", "missing", "filled", "alignment"):
        assert np.array_equal(getattr(back, name), getattr(session, name), equal_nan=name != "missing"), name
    assert np.allclose(back.times_ms[:3], [0, 1000 / 60, 2000 / 60])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["take.h5", "take.tsv"]  # no temporary left


def test_failed_save_leaves_the_old_file(tmp_path, motion):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2][:10])
    session = import_marker_file(path)
    out = tmp_path / "take.h5"
    save_session(session, out)
    before = out.read_bytes()
    session.report["bad"] = object()  # not JSON: the write fails half-way
    with pytest.raises(TypeError):
        save_session(session, out)
    assert out.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["take.h5", "take.tsv"]


def _small_session() -> Session:
    f, m = 4, 2
    return Session(markers=["2.1", "8.3"], positions=np.zeros((f, m, 3)), raw=np.zeros((f, m, 3)), rate_hz=60,
                   missing=np.zeros((f, m), bool), alignment=np.tile(np.eye(4), (f, 1, 1)))


@pytest.mark.parametrize("damage, pattern", [
    (lambda f: f.attrs.__setitem__("format", "something-else"), r"not a motion-capture session"),
    (lambda f: f.attrs.__setitem__("version", 2), r"session format version 2 is not one this program reads"),
    (lambda f: f.__delitem__("positions"), r"missing HDF5 dataset '/positions'"),
    (lambda f: (f.__delitem__("missing"), f.create_dataset("missing", data=np.zeros((3, 2), bool))),
     r"dataset '/missing' has shape \(3, 2\), expected \(4, 2\)"),
    (lambda f: f.attrs.__delitem__("rate_hz"), r"no valid 'rate_hz'"),
    (lambda f: (f.__delitem__("report"), f.create_dataset("report", data="{oops")), r"not valid JSON"),
])
def test_session_file_validation(tmp_path, damage, pattern):
    path = tmp_path / "s.h5"
    save_session(_small_session(), path)
    with h5py.File(path, "r+") as f:
        assert f.attrs["format"] == SESSION_FORMAT and f.attrs["version"] == 1
        damage(f)
    with pytest.raises(SessionFileError, match=rf"s.h5: .*{pattern}"):
        load_session(path)


def test_session_file_not_hdf5(tmp_path):
    path = tmp_path / "s.h5"
    path.write_text("hello")
    with pytest.raises(SessionFileError, match=r"s.h5: not a readable HDF5 file"):
        load_session(path)


def test_session_checks_its_arrays():
    with pytest.raises(MocapError, match=r"positions have shape"):
        Session(markers=["a"], positions=np.zeros((3, 2, 3)), raw=np.zeros((3, 2, 3)), rate_hz=60,
                missing=np.zeros((3, 1), bool), alignment=np.zeros((3, 4, 4)))
    s = _small_session()
    assert s.marker_index("8.3") == 1
    with pytest.raises(MocapError, match=r"no marker '8\.1'"):
        s.marker_index("8.1")


# ---------------------------------------------------------------------------
# command line
# ---------------------------------------------------------------------------

def test_cli_import_prints_the_gap_report(tmp_path, motion, capsys):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2])
    out = tmp_path / "take.h5"
    assert main(["mocap", "import", str(path), "--max-gap", "100", "--labels", str(DATA / "phones.txt"),
                 "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "8.4" in text and "40" in text and f"wrote {out}" in text
    assert load_session(out).report["max_gap_frames"] == 6


def test_cli_sample_files_with_mapping(tmp_path, capsys):
    out = tmp_path / "s.h5"
    assert main(["mocap", "import", str(DATA / "qtm_sample.tsv"), "--map", str(DATA / "face.map"),
                 "--reference-frame", "mean", "-o", str(out)]) == 0
    session = load_session(out)
    assert session.markers == ["20.1", "20.2", "11.1", "2.1"] and session.reference == ["11.1", "20.1", "20.2"]
    assert session.filled[3, 3] and session.report["events"][0][0] == "sentence start"
    assert main(["mocap", "import", str(DATA / "trc_sample.trc"), "--reference", "none", "-o", str(out)]) == 0
    assert load_session(out).markers == ["Nose", "Chin", "8.3"]


@pytest.mark.parametrize("args, pattern", [
    (["--format", "trc"], r"take.tsv:1: not a TRC file"),
    (["--reference", "9.3,8.1"], r"removing head motion needs at least 3"),
    (["--max-gap", "-5"], r"argument --max-gap: '-5' must be 0 or more"),
    (["--rate", "60"], r"--columns, --time-column, --rate and --units apply to CSV tables only"),
    (["--labels", "missing.TextGrid"], r"missing.TextGrid: no such file"),
    (["--map", "missing.map"], r"missing.map: no such file"),
    (["--tier", "phones"], r"--tier needs --labels"),
    (["-o", "s.txt"], r"unknown output extension '.txt' for a session"),
])
def test_cli_user_errors(tmp_path, motion, capsys, args, pattern):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2][:10])
    code = main(["mocap", "import", str(path), "-o", str(tmp_path / "s.h5"), *args])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and err[0].startswith("error: ")
    assert __import__("re").search(pattern, err[0]), err[0]
    assert not (tmp_path / "s.h5").exists()


def test_cli_subprocess_exit_codes(tmp_path, motion):
    path = tmp_path / "take.tsv"
    write_tsv(path, IDS, motion[2][:10])
    good = run("mocap", "import", path, "-o", tmp_path / "s.h5")
    assert good.returncode == 0, good.stderr
    assert "gaps (filled up to 100 ms = 6 frames)" in good.stdout
    lines = path.read_text().splitlines()
    path.write_text("\n".join([*lines[:-1], lines[-1][:30]]) + "\n")
    line = assert_user_error(run_in_process("mocap", "import", path, "-o", tmp_path / "s.h5"))
    assert line.startswith(f"error: {path}:{len(lines)}: ")


# ---------------------------------------------------------------------------
# docstring examples
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["engine.mocap.session", "engine.mocap.naming", "engine.mocap.gaps",
                                  "engine.mocap.head_motion", "engine.speech.labels", "engine.mocap.csv_table"])
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0 and result.attempted > 0


def test_report_is_json(tmp_path, motion):
    path = tmp_path / "take.csv"
    write_csv(path, IDS, motion[2])
    json.dumps(import_marker_file(path).report)
