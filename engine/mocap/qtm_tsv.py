"""Qualisys QTM TSV export of 3D marker data (the MacReflex-era and current exports).

The file is a header of ``KEY<TAB>value`` lines, then the data::

    NO_OF_FRAMES    600                 required
    NO_OF_CAMERAS   4                   optional
    NO_OF_MARKERS   32                  required
    FREQUENCY       60                  required (frames per second; "EXT" is refused)
    NO_OF_ANALOG, ANALOG_FREQUENCY, DESCRIPTION, TIME_STAMP, FILE_VERSION   optional, ignored
    DATA_INCLUDED   3D                  optional; anything but 3D is refused
    EVENT           name  frame  time   optional, any number (time in seconds)
    MARKER_NAMES    name1  name2 ...    required, NO_OF_MARKERS names
    TRAJECTORY_TYPES  Measured ...      optional, ignored
    Frame  Time  name1 X  name1 Y  name1 Z ...     optional column-header row
    1  0.000  x  y  z ...                          one row per frame, mm

Without the column-header row a data row holds either the 3·M coordinates
or the frame number and time followed by them. A missing sample is written
as ``0 0 0``; those become NaN, as does a sample with a NaN coordinate (QTM
writes none, but a converted file may). An infinite coordinate, or one beyond
±1 km, is no measurement: refused with its line.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.mocap.errors import MarkerFileError
from engine.mocap.recording import (
    Recording,
    check_coordinates,
    check_rate,
    nan_partial_samples,
    zero_triplets_to_nan,
)
from engine.mocap.text_tables import parse_number, parse_rows, read_text_lines, row_line

REQUIRED_KEYS = ("NO_OF_FRAMES", "NO_OF_MARKERS", "FREQUENCY", "MARKER_NAMES")


def read_qtm_tsv(path: str | Path) -> Recording:
    """Read a QTM TSV 3D export; positions in mm, ``0 0 0`` samples as NaN."""
    path = Path(path)
    lines = read_text_lines(path)
    header: dict[str, tuple[list[str], int]] = {}
    events: list[tuple[str, float]] = []
    i = 0
    while i < len(lines):
        cells = lines[i].rstrip("\t").split("\t")
        key = cells[0].strip()
        if not key and len(cells) == 1:
            i += 1
            continue
        if not key[:1].isalpha() or key.lower() == "frame":
            break
        if key.upper() != key or " " in key:
            shown = key if len(key) <= 40 else key[:40] + "…"
            raise MarkerFileError(f"'{shown}' is neither a QTM header key nor a data row", file=path, line=i + 1)
        if key == "EVENT":
            if len(cells) < 4:
                raise MarkerFileError("an EVENT line needs a name, a frame number and a time", file=path,
                                      line=i + 1)
            events.append((cells[1], 1000.0 * parse_number(cells[3], "event time", path, i + 1)))
        else:
            header[key] = ([c.strip() for c in cells[1:]], i + 1)
        i += 1
    missing = [k for k in REQUIRED_KEYS if k not in header]
    if missing:
        raise MarkerFileError(f"not a QTM TSV 3D export: the header lacks {', '.join(missing)}", file=path,
                              line=min(i + 1, len(lines)) or 1)
    n_frames = _count(header, "NO_OF_FRAMES", path)
    n_markers = _count(header, "NO_OF_MARKERS", path)
    rate = _rate(header, path)
    if "DATA_INCLUDED" in header:
        values, line = header["DATA_INCLUDED"]
        if not values or values[0].upper() != "3D":
            raise MarkerFileError(f"DATA_INCLUDED is '{' '.join(values)}': only 3D marker data can be imported "
                                  "(export 3D data from QTM)", file=path, line=line)
    names, names_line = header["MARKER_NAMES"]
    while names and names[-1] == "":
        names.pop()
    if len(names) != n_markers:
        raise MarkerFileError(f"MARKER_NAMES lists {len(names)} names but NO_OF_MARKERS is {n_markers}",
                              file=path, line=names_line)
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise MarkerFileError(f"marker name(s) {', '.join(duplicates)} appear more than once", file=path,
                              line=names_line)

    columns, n_columns, first_data, time_column = _columns(lines, i, names, path)
    data_lines = [ln.rstrip("\t") for ln in lines[first_data:]]
    while data_lines and not data_lines[-1].strip():
        data_lines.pop()
    if not data_lines:
        raise MarkerFileError(f"the file ends before its data (NO_OF_FRAMES is {n_frames})", file=path,
                              line=max(len(lines), 1))
    if columns is None or n_columns is None:  # no column-header row: 3·M values, or frame and time first
        first = data_lines[0].split("\t")
        if len(first) == 3 * n_markers + 2:
            n_columns = 3 * n_markers + 2
        elif len(first) == 3 * n_markers:
            n_columns = 3 * n_markers
        else:
            raise MarkerFileError(f"{len(first)} columns where {3 * n_markers} coordinates (or frame, time and "
                                  "the coordinates) were expected", file=path, line=first_data + 1)
        offset = n_columns - 3 * n_markers
        columns = np.arange(offset, n_columns)
        time_column = 1 if offset == 2 else None
    table = parse_rows(data_lines, first_data + 1, n_columns, path, delimiter="\t",
                       last_line_complete=True)
    if len(table) != n_frames:
        last = first_data + len(data_lines)
        if len(table) < n_frames:
            raise MarkerFileError(f"the file ends after {len(table)} frames but NO_OF_FRAMES is {n_frames} "
                                  "(truncated?)", file=path, line=last)
        raise MarkerFileError(f"{len(table)} frames of data but NO_OF_FRAMES is {n_frames}", file=path, line=last)
    positions = zero_triplets_to_nan(table[:, columns].reshape(n_frames, n_markers, 3))  # indexing copied
    check_coordinates(positions, names, path, lambda f: row_line(data_lines, first_data + 1, f),
                      gap="as 0 0 0 (or NaN)")
    nan_partial_samples(positions)
    start_ms = 0.0
    if n_frames and time_column is not None and np.isfinite(table[0, time_column]):
        start_ms = 1000.0 * float(table[0, time_column])
    events = [(name, t - start_ms) for name, t in events]
    return Recording(labels=names, positions=positions, rate_hz=rate, source=path.name, format="tsv",
                     units="mm", start_ms=start_ms, events=events)


def _count(header: dict[str, tuple[list[str], int]], key: str, path: Path) -> int:
    values, line = header[key]
    text = values[0] if values else ""
    try:
        n = int(text)
    except ValueError:
        raise MarkerFileError(f"{key} '{text}' is not a whole number", file=path, line=line) from None
    if n < 0:
        raise MarkerFileError(f"{key} must not be negative", file=path, line=line)
    return n


def _rate(header: dict[str, tuple[list[str], int]], path: Path) -> float:
    values, line = header["FREQUENCY"]
    text = values[0] if values else ""
    if text.upper() == "EXT":
        raise MarkerFileError("FREQUENCY is EXT (external timebase): export with a known frame rate", file=path,
                              line=line)
    return check_rate(parse_number(text, "FREQUENCY", path, line), "FREQUENCY", path, line)


def _columns(lines: list[str], i: int, names: list[str], path: Path,
             ) -> tuple[np.ndarray | None, int | None, int, int | None]:
    """Column indices (x, y, z of each marker, flattened) from the column-header row, if there is one."""
    if i >= len(lines) or lines[i].split("\t", 1)[0].strip().lower() != "frame":
        return None, None, i, None
    cells = [c.strip() for c in lines[i].rstrip("\t").split("\t")]
    where = {c: k for k, c in enumerate(cells)}
    columns = []
    for name in names:
        for axis in "XYZ":
            k = where.get(f"{name} {axis}")
            if k is None:
                raise MarkerFileError(f"the column-header row has no column '{name} {axis}'", file=path, line=i + 1)
            columns.append(k)
    lowered = [c.lower() for c in cells]
    time_column = lowered.index("time") if "time" in lowered else None
    return np.array(columns), len(cells), i + 1, time_column
