"""Reading marker files: format detection, the common :class:`Recording`, and the numeric table parser.

Every reader returns a :class:`Recording`: the file's own marker labels,
positions in millimetres with NaN wherever the file has no sample (QTM's
``0 0 0`` triplets, C3D's negative residuals, empty or NaN cells in TRC and
CSV), and the frame rate as the file states it. Naming, gap filling and head
alignment come later (``engine.mocap.importer``).

>>> from engine.mocap.readers import read_marker_file
>>> rec = read_marker_file("take1.tsv")                 # doctest: +SKIP
>>> rec.positions.shape, rec.rate_hz                    # doctest: +SKIP
((600, 32, 3), 60.0)
"""

from __future__ import annotations

import io
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.mocap.errors import MarkerFileError

try:  # the compiled table reader (engine/mocap/_text_table.c); numpy's loadtxt otherwise
    from engine.mocap import _text_table
except ImportError:  # pragma: no cover - exercised where the extension is not built
    _text_table = None

FORMATS = ("tsv", "c3d", "trc", "csv")
FORMAT_NAMES = {"tsv": "Qualisys QTM TSV", "c3d": "C3D", "trc": "TRC", "csv": "CSV"}
UNIT_SCALE = {"mm": 1.0, "cm": 10.0, "m": 1000.0}
"""Factor from a file's length unit to millimetres."""


@dataclass
class Recording:
    """Marker trajectories as a file holds them, converted to mm.

    ``positions`` is (F, M, 3) in mm with NaN where the file has no sample;
    ``labels`` are the file's own marker names; ``start_ms`` is the time the
    file gives its first frame (0 when it gives none); ``events`` are named
    instants (QTM ``EVENT`` lines) as ``(name, time_ms)`` on the recording's
    clock, whose 0 is the first frame.
    """

    labels: list[str]
    positions: np.ndarray
    rate_hz: float
    source: str
    format: str
    units: str = "mm"
    start_ms: float = 0.0
    events: list[tuple[str, float]] = field(default_factory=list)

    @property
    def n_frames(self) -> int:
        return int(self.positions.shape[0])


def detect_format(path: str | Path) -> str:
    """The format of a marker file from its content, else its extension: ``tsv``, ``c3d``, ``trc`` or ``csv``."""
    path = Path(path)
    head = _head_bytes(path)
    if len(head) >= 512 and head[1] == 0x50 and not 32 <= head[0] < 127:  # C3D: block pointer, then key 80
        return "c3d"
    text = head.decode("latin-1").lstrip("\ufeff\xef\xbb\xbf")
    first = text.split("\n", 1)[0].strip()
    key = first.split("\t", 1)[0].split(" ", 1)[0].upper()
    if key == "PATHFILETYPE":
        return "trc"
    if key in ("NO_OF_FRAMES", "FILE_VERSION", "NO_OF_CAMERAS", "NO_OF_MARKERS"):
        return "tsv"
    suffix = path.suffix.lower().lstrip(".")
    if suffix in FORMATS:
        return suffix
    if suffix == "txt" and "," in first:
        return "csv"
    raise MarkerFileError("unknown marker file format: not QTM TSV, C3D, TRC or CSV "
                          "(give --format tsv|c3d|trc|csv if it is one of them)", file=path, line=1)


def read_marker_file(path: str | Path, format: str = "auto", csv_layout=None) -> Recording:
    """Read a marker file of any supported format (``format="auto"`` detects it).

    ``csv_layout`` (a :class:`engine.mocap.csv_table.CsvLayout`) says how a
    CSV file's columns map onto markers and time; other formats ignore it.
    """
    path = Path(path)
    if not path.exists():
        raise MarkerFileError("no such file", file=path)
    if path.is_dir():
        raise MarkerFileError("is a folder, not a marker file", file=path)
    fmt = detect_format(path) if format == "auto" else format
    if fmt == "tsv":
        from engine.mocap.qtm_tsv import read_qtm_tsv
        return read_qtm_tsv(path)
    if fmt == "trc":
        from engine.mocap.trc import read_trc
        return read_trc(path)
    if fmt == "c3d":
        from engine.mocap.c3d_file import read_c3d
        return read_c3d(path)
    if fmt == "csv":
        from engine.mocap.csv_table import read_csv
        return read_csv(path, csv_layout)
    raise MarkerFileError(f"unknown format '{fmt}' (use auto, {', '.join(FORMATS)})", file=path)


def _head_bytes(path: Path, n: int = 4096) -> bytes:
    try:
        with open(path, "rb") as fh:
            return fh.read(n)
    except OSError as exc:
        raise MarkerFileError(f"cannot read: {exc.strerror or exc}", file=path) from None


def read_text_lines(path: Path) -> list[str]:
    """The file's lines without line ends (UTF-8, else Latin-1); a trailing empty line is dropped."""
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise MarkerFileError(f"cannot read: {exc.strerror or exc}", file=path) from None
    if b"\0" in data[:4096]:
        raise MarkerFileError("binary data where text was expected (wrong --format?)", file=path, line=1)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def unit_scale(unit: str, path: Path, line: int | None = None) -> float:
    """Millimetres per file unit for ``mm``, ``cm`` or ``m`` (any case)."""
    scale = UNIT_SCALE.get(unit.strip().lower())
    if scale is None:
        raise MarkerFileError(f"unknown length unit '{unit.strip()}' (use mm, cm or m)", file=path, line=line)
    return scale


def parse_number(text: str, what: str, path: Path, line: int) -> float:
    try:
        value = float(text)
    except ValueError:
        raise MarkerFileError(f"{what} '{_shorten(text.strip())}' is not a number", file=path, line=line) from None
    return value


def parse_rows(lines: list[str], first_line: int, n_columns: int, path: Path, delimiter: str | None = "\t",
               empty_is_missing: bool = False, short_rows_at: int | None = None,
               last_line_complete: bool = True) -> np.ndarray:
    """Parse data rows into an (n, n_columns) float array; errors name the file and line.

    ``lines`` are the data lines (``first_line`` is the 1-based line number of
    the first); blank lines are skipped. ``delimiter=None`` splits on runs of
    whitespace. ``empty_is_missing`` turns empty cells into NaN (TRC, CSV);
    otherwise an empty cell is an error. ``short_rows_at`` allows a row that
    stops early at a multiple of that many cells after the first
    ``n_columns % short_rows_at`` (TRC writers leave out the empty cells of
    trailing missing markers); the left-out cells are NaN. A short row on the
    file's last line when the file does not end with a line break is a
    truncation and an error (``last_line_complete=False``).
    """
    fast = _parse_fast(lines, n_columns, delimiter, empty_is_missing)
    if fast is not None:
        return fast
    return _parse_slow(lines, first_line, n_columns, path, delimiter, empty_is_missing, short_rows_at,
                       last_line_complete)


def _parse_fast(lines, n_columns, delimiter, empty_is_missing):
    """A C parser for the common case of a well-formed table; None when anything is unusual.

    The compiled ``engine.mocap._text_table`` when it is built (one pass, the same
    doubles as ``float``), else numpy's ``loadtxt``.
    """
    if _text_table is not None and len(delimiter or " ") == 1:
        text = "\n".join(lines).encode("utf-8")
        out = np.empty((len(lines), n_columns))
        rows = _text_table.parse_table(text, out, n_columns, ord(delimiter) if delimiter is not None else -1,
                                       empty_is_missing)
        return out[:rows] if rows >= 0 else None
    kept = [ln for ln in lines if ln.strip()]
    if not kept:
        return np.zeros((0, n_columns))
    text = "\n".join(kept) + "\n"
    if delimiter is not None and empty_is_missing:
        d = delimiter
        # "a\t\tb" → "a\tnan\tb": two passes catch runs of empty cells; then empty cells at either end
        text = text.replace(d + d, d + "nan" + d).replace(d + d, d + "nan" + d)
        text = text.replace(d + "\n", d + "nan\n").replace("\n" + d, "\nnan" + d)
        if text.startswith(d):
            text = "nan" + text
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            data = np.loadtxt(io.StringIO(text), delimiter=delimiter, dtype=float, ndmin=2, comments=None)
    except (ValueError, Warning):
        return None
    if data.shape != (len(kept), n_columns):
        return None
    return data


def _parse_slow(lines, first_line, n_columns, path, delimiter, empty_is_missing, short_rows_at,
                last_line_complete):
    """Line by line, to report exactly where and what is wrong (and to accept short TRC rows)."""
    rows = []
    lead = n_columns % short_rows_at if short_rows_at else 0
    for i, line in enumerate(lines):
        number = first_line + i
        if not line.strip():
            continue
        cells = line.split(delimiter) if delimiter is not None else line.split()
        if len(cells) != n_columns:
            short_ok = (short_rows_at and len(cells) < n_columns and len(cells) >= lead
                        and (len(cells) - lead) % short_rows_at == 0
                        and (last_line_complete or i < len(lines) - 1))
            if not short_ok:
                raise MarkerFileError(f"{len(cells)} columns where {n_columns} were expected"
                                      + (" (the file looks truncated)" if i == len(lines) - 1
                                         and len(cells) < n_columns else ""), file=path, line=number)
            cells = cells + [""] * (n_columns - len(cells))
        row = []
        for j, cell in enumerate(cells):
            if empty_is_missing and not cell.strip():
                row.append(np.nan)
                continue
            try:
                if "_" in cell:          # float() reads "1_0" as 10; in a marker file it is a mistake
                    raise ValueError(cell)
                row.append(float(cell))
            except ValueError:
                shown = _shorten(cell.strip()) or "an empty cell"
                raise MarkerFileError(f"column {j + 1}: '{shown}' is not a number" if cell.strip()
                                      else f"column {j + 1}: {shown} where a number was expected",
                                      file=path, line=number) from None
        rows.append(row)
    return np.array(rows, dtype=float).reshape(len(rows), n_columns)


def zero_triplets_to_nan(positions: np.ndarray) -> np.ndarray:
    """QTM and some C3D writers store a missing sample as exactly (0, 0, 0): make those NaN (in place)."""
    gap = np.all(positions == 0.0, axis=-1)
    positions[gap] = np.nan
    return positions


def nan_partial_samples(positions: np.ndarray) -> np.ndarray:
    """A sample with any coordinate missing is missing altogether (in place)."""
    bad = np.any(~np.isfinite(positions), axis=-1)
    positions[bad] = np.nan
    return positions


def _shorten(text: str, n: int = 40) -> str:
    return text if len(text) <= n else text[:n] + "…"
