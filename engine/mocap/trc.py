"""TRC marker files (Motion Analysis; the format OpenSim reads), tab-separated::

    PathFileType  4  (X/Y/Z)  take1.trc
    DataRate  CameraRate  NumFrames  NumMarkers  Units  OrigDataRate  OrigDataStartFrame  OrigNumFrames
    60        60          600        32          mm     60            1                   600
    Frame#  Time  name1        name2 ...
                  X1  Y1  Z1   X2  Y2  Z2 ...
    (an optional blank line)
    1  0.000  x  y  z  x  y  z ...

DataRate, NumFrames, NumMarkers and Units (mm, cm or m) are required. A
missing sample is empty cells (or NaN); a row may leave out the empty cells
of missing markers at its end, and may end in a tab (OpenSim's own example
files do: the empty cells after the last column are ignored). An infinite
coordinate, or one beyond ±1 km, is refused with its line. Columns are
separated by tabs. A comma-separated TRC (what a spreadsheet, pyomeca-based
scripts and some MATLAB writers save) has the same lines with commas, which
no TRC value holds, so its layout is as unambiguous: it is read, and the
recording's notes (the import report) say "read as comma-separated TRC".
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from engine.mocap.errors import MarkerFileError
from engine.mocap.recording import (
    Recording,
    check_coordinates,
    check_rate,
    nan_partial_samples,
    scaled_to_mm,
    unit_scale,
)
from engine.mocap.text_tables import parse_number, parse_rows, read_text_lines, row_line

REQUIRED_KEYS = ("DataRate", "NumFrames", "NumMarkers", "Units")


def read_trc(path: str | Path) -> Recording:
    """Read a TRC file; positions in mm, empty cells as NaN."""
    path = Path(path)
    lines = read_text_lines(path)
    if not lines or not lines[0].strip().lower().startswith("pathfiletype"):
        raise MarkerFileError("not a TRC file: the first line must start with PathFileType", file=path, line=1)
    if len(lines) < 5:
        raise MarkerFileError("the TRC header ends early: it needs the key line, the value line, the marker "
                              "names and the X1 Y1 Z1 line (truncated?)", file=path, line=len(lines))
    comma = "\t" not in lines[1] and lines[1].count(",") >= 3   # the key line: eight names, no tab
    separator = "," if comma else "\t"
    keys = _split(lines[1], comma)
    values = _split(lines[2], comma)
    if len(values) < len(keys):
        raise MarkerFileError(f"{len(values)} header values for {len(keys)} header keys on line 2", file=path,
                              line=3)
    header = dict(zip(keys, values, strict=False))
    missing = [k for k in REQUIRED_KEYS if k not in header]
    if missing:
        raise MarkerFileError(f"the TRC header lacks {', '.join(missing)}", file=path, line=2)
    rate = check_rate(parse_number(header["DataRate"], "DataRate", path, 3), "DataRate", path, 3)
    n_frames = _whole(header["NumFrames"], "NumFrames", path)
    n_markers = _whole(header["NumMarkers"], "NumMarkers", path)
    scale = unit_scale(header["Units"], path, line=3)

    names = [c.strip() for c in _cells(lines[3], separator)[2:] if c.strip()]
    if len(names) != n_markers:
        raise MarkerFileError(f"the marker-name line lists {len(names)} markers but NumMarkers is {n_markers}",
                              file=path, line=4)
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise MarkerFileError(f"marker name(s) {', '.join(duplicates)} appear more than once", file=path, line=4)
    axes = [c.strip() for c in _cells(lines[4], separator) if c.strip()]
    if len(axes) != 3 * n_markers:
        raise MarkerFileError(f"the X1 Y1 Z1 line has {len(axes)} coordinate names for {n_markers} markers",
                              file=path, line=5)

    n_columns = 2 + 3 * n_markers
    data = _without_trailing_empty_cells(lines[5:], n_columns, separator)
    tab = any("\t" in ln for ln in data[:5])
    ends_with_newline = _last_byte(path) in (b"\n", b"\r")
    table = parse_rows(data, 6, n_columns, path, delimiter="," if comma else "\t" if tab else None,
                       empty_is_missing=True, short_rows_at=3, last_line_complete=ends_with_newline)
    notes = ["read as comma-separated TRC (TRC columns are tab-separated; the layout is the same)"] if comma else []
    if len(table) == n_frames - 1 and n_frames > 1:
        notes.append(f"the data end one frame early ({len(table)} of NumFrames {n_frames}); {len(table)} read")
        n_frames = len(table)
    if len(table) != n_frames:
        last = len(lines)
        if len(table) < n_frames:
            raise MarkerFileError(f"the file ends after {len(table)} frames but NumFrames is {n_frames} "
                                  "(truncated?)", file=path, line=last)
        raise MarkerFileError(f"{len(table)} frames of data but NumFrames is {n_frames}", file=path, line=last)
    positions = check_coordinates(scaled_to_mm(table[:, 2:].reshape(n_frames, n_markers, 3), scale), names, path,
                                  lambda f: row_line(data, 6, f), gap="as empty cells or NaN")
    nan_partial_samples(positions)
    start_ms = 1000.0 * float(table[0, 1]) if n_frames and np.isfinite(table[0, 1]) else 0.0
    return Recording(labels=names, positions=positions, rate_hz=rate, source=path.name, format="trc",
                     units=header["Units"].strip(), start_ms=start_ms, notes=notes)


def _without_trailing_empty_cells(lines: list[str], n_columns: int, separator: str = "\t") -> list[str]:
    """Rows with empty cells after the last column, as OpenSim writes them (a tab at the end), cut to the columns."""
    out = []
    for line in lines:
        cells = line.split(separator) if line.count(separator) >= n_columns else []
        if cells and not any(c.strip() for c in cells[n_columns:]):
            out.append(separator.join(cells[:n_columns]))
        else:
            out.append(line)
    return out


def _split(line: str, comma: bool = False) -> list[str]:
    cells = _cells(line, ",") if comma else line.split("\t") if "\t" in line else line.split()
    return [c.strip() for c in cells if c.strip()]


def _cells(line: str, separator: str) -> list[str]:
    """The cells of a header line; a comma-separated one may quote a cell ("a, b"), as spreadsheets do."""
    if separator == "," and '"' in line:
        return next(csv.reader([line]))
    return line.split(separator)


def _whole(text: str, key: str, path: Path) -> int:
    try:
        n = int(float(text))
    except (ValueError, OverflowError):
        raise MarkerFileError(f"{key} '{text}' is not a whole number", file=path, line=3) from None
    if n < 0 or n != float(text):
        raise MarkerFileError(f"{key} '{text}' is not a whole number", file=path, line=3)
    return n


def _last_byte(path: Path) -> bytes:
    """The file's last byte (without reading the rest again)."""
    try:
        with path.open("rb") as stream:
            stream.seek(0, 2)
            if stream.tell() == 0:
                return b""
            stream.seek(-1, 2)
            return stream.read(1)
    except OSError as exc:
        raise MarkerFileError(f"cannot read: {exc.strerror or exc}", file=path) from None
