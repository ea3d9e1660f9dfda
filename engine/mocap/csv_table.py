"""Plain CSV marker tables with a column mapping.

One header row, then one row per frame; comma, semicolon or tab separated
(taken from the header row); lines starting with ``#`` before the header are
skipped. Marker columns are found by a pattern with ``{marker}`` and
``{axis}`` (x, y or z, either case); by default the first of
``{marker}_{axis}``, ``{marker}.{axis}``, ``{marker} {axis}`` and
``{marker}:{axis}`` that matches any column. The project's own landmarks
table (``frame,time_ms,2.1_x,2.1_y,2.1_z,…``) therefore reads as it is.

Time: a column ``time_ms`` (milliseconds) or ``time_s``, ``time``, ``t``
(seconds), or one named by :attr:`CsvLayout.time_column`; its spacing gives
the frame rate (rounded to a whole number when within 0.05 %). Without a
time column, :attr:`CsvLayout.rate_hz` must be given. Missing samples are
empty cells or ``NaN``. Other columns (``frame``, quality, …) are ignored.

>>> bool(_pattern_regex("{marker}_{axis}").fullmatch("8.3_x"))
True
>>> _pattern_regex("{marker}_{axis}").fullmatch("8.3_X").group("marker")
'8.3'
"""

from __future__ import annotations

import re
from dataclasses import dataclass
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
from engine.mocap.text_tables import parse_rows, read_text_lines, row_line

DEFAULT_PATTERNS = ("{marker}_{axis}", "{marker}.{axis}", "{marker} {axis}", "{marker}:{axis}")
TIME_COLUMNS = {"time_ms": "ms", "time_s": "s", "time": "s", "t": "s"}


@dataclass
class CsvLayout:
    """How a CSV table's columns map onto markers and time (all optional)."""

    columns: str | None = None
    """Column-name pattern with ``{marker}`` and ``{axis}``, e.g. ``"{marker}_pos_{axis}"``."""
    time_column: str | None = None
    """Name of the time column (default: time_ms, time_s, time or t)."""
    time_unit: str | None = None
    """``ms`` or ``s`` for :attr:`time_column` (default: ms for names ending in _ms, else s)."""
    rate_hz: float | None = None
    """Frames per second; needed when there is no time column, and wins over it when given."""
    units: str = "mm"
    """Length unit of the coordinates: mm, cm or m."""


def read_csv(path: str | Path, layout: CsvLayout | None = None) -> Recording:
    """Read a CSV marker table; positions in mm, empty or NaN cells as missing."""
    path = Path(path)
    layout = layout or CsvLayout()
    scale = unit_scale(layout.units, path)
    lines = read_text_lines(path)
    first = 0
    while first < len(lines) and (not lines[first].strip() or lines[first].lstrip().startswith("#")):
        first += 1
    if first >= len(lines):
        raise MarkerFileError("the file has no header row", file=path, line=max(len(lines), 1))
    header_line = first + 1
    delimiter = max(",;\t", key=lines[first].count)
    names = [c.strip().strip('"') for c in lines[first].split(delimiter)]
    markers, _ = _marker_columns(names, layout.columns, path, header_line)
    time_index, time_unit = _time_column(names, layout, path, header_line)
    table = parse_rows(lines[first + 1:], header_line + 1, len(names), path, delimiter=delimiter,
                       empty_is_missing=True)
    n_frames = len(table)
    if n_frames == 0:
        raise MarkerFileError("the table has a header but no rows", file=path, line=header_line)
    start_ms = 0.0
    if layout.rate_hz is not None:
        rate = float(layout.rate_hz)
        if time_index is not None and np.isfinite(table[0, time_index]):
            start_ms = table[0, time_index] * (1.0 if time_unit == "ms" else 1000.0)
    elif time_index is None:
        raise MarkerFileError("no time column (time_ms, time_s, time or t) to take the frame rate from: "
                              "give the rate (--rate HZ) or the column (--time-column NAME)", file=path,
                              line=header_line)
    else:
        times = table[:, time_index] * (1.0 if time_unit == "ms" else 1000.0)
        rate, start_ms = _rate_from_times(times, path, header_line + 1)
    labels = list(markers)
    index = np.array([markers[m] for m in labels], dtype=int).reshape(len(labels), 3)
    rate = check_rate(rate, "the frame rate", path)
    positions = check_coordinates(scaled_to_mm(table[:, index], scale), labels, path,
                                  lambda f: row_line(lines[first + 1:], header_line + 1, f),
                                  gap="as an empty cell or NaN")
    nan_partial_samples(positions)
    return Recording(labels=labels, positions=positions, rate_hz=rate, source=path.name, format="csv",
                     units=layout.units, start_ms=start_ms, events=[])


def _pattern_regex(pattern: str) -> re.Pattern[str]:
    if pattern.count("{marker}") != 1 or pattern.count("{axis}") != 1:
        raise ValueError("a column pattern needs exactly one {marker} and one {axis}")
    parts = re.split(r"(\{marker\}|\{axis\})", pattern)
    regex = "".join("(?P<marker>.+?)" if p == "{marker}" else "(?P<axis>[xyzXYZ])" if p == "{axis}"
                    else re.escape(p) for p in parts)
    return re.compile(regex)


def _marker_columns(names: list[str], pattern: str | None, path: Path,
                    line: int) -> tuple[dict[str, list[int]], list[str]]:
    """{marker: [x, y, z column]} for markers with all three axes, and the columns left over."""
    patterns = [pattern] if pattern else list(DEFAULT_PATTERNS)
    for p in patterns:
        try:
            regex = _pattern_regex(p)
        except ValueError as exc:
            raise MarkerFileError(f"column pattern '{p}': {exc}", file=path) from None
        found: dict[str, dict[str, int]] = {}
        for k, name in enumerate(names):
            m = regex.fullmatch(name)
            if m:
                axes = found.setdefault(m.group("marker"), {})
                axis = m.group("axis").lower()
                if axis in axes:
                    raise MarkerFileError(f"two columns for marker '{m.group('marker')}' axis {axis}", file=path,
                                          line=line)
                axes[axis] = k
        markers = {m: [a["x"], a["y"], a["z"]] for m, a in found.items() if len(a) == 3}
        if markers:
            used = {k for cols in markers.values() for k in cols}
            return markers, [n for k, n in enumerate(names) if k not in used]
    tried = ", ".join(patterns)
    raise MarkerFileError(f"no marker columns: no name matches {tried} for all of x, y and z "
                          "(give the pattern with --columns, e.g. '{marker}_pos_{axis}')", file=path, line=line)


def _time_column(names: list[str], layout: CsvLayout, path: Path, line: int) -> tuple[int | None, str | None]:
    lowered = [n.lower() for n in names]
    if layout.time_column is not None:
        if layout.time_column not in names:
            raise MarkerFileError(f"no column named '{layout.time_column}'", file=path, line=line)
        k = names.index(layout.time_column)
        unit = layout.time_unit or ("ms" if lowered[k].endswith("ms") else "s")
        return k, unit
    for name, unit in TIME_COLUMNS.items():
        if name in lowered:
            return lowered.index(name), layout.time_unit or unit
    return None, None


def _rate_from_times(times: np.ndarray, path: Path, first_line: int) -> tuple[float, float]:
    if not np.all(np.isfinite(times)):
        k = int(np.flatnonzero(~np.isfinite(times))[0])
        raise MarkerFileError("the time column has an empty or non-finite cell", file=path, line=first_line + k)
    if len(times) < 2:
        raise MarkerFileError("one frame: the frame rate cannot be taken from the time column (give --rate)",
                              file=path, line=first_line)
    steps = np.diff(times)
    step = (times[-1] - times[0]) / (len(times) - 1)
    bad = np.flatnonzero((steps <= 0) | (np.abs(steps - step) > 0.02 * step))
    if len(bad):
        raise MarkerFileError("the time column is not evenly spaced and increasing: resample the data "
                              "or give the frame rate with --rate", file=path, line=first_line + int(bad[0]) + 1)
    rate = 1000.0 / step
    if abs(rate - round(rate)) <= 5e-4 * rate:
        rate = float(round(rate))
    return rate, float(times[0])
