"""Reading the text of marker files: lines, numbers and numeric tables, with errors naming file and line.

The QTM TSV, TRC and CSV readers share these. :func:`parse_rows` reads a
well-formed table in one pass (the compiled ``engine.mocap._text_table`` when
it is built, else numpy's ``loadtxt``) and falls back to a line-by-line
parser that reports exactly where and what is wrong.

>>> from pathlib import Path
>>> parse_rows(["1,2", "3,4"], 1, 2, Path("x.csv"), delimiter=",").tolist()
[[1.0, 2.0], [3.0, 4.0]]
"""

from __future__ import annotations

import io
import warnings
from pathlib import Path
from types import ModuleType

import numpy as np

from engine.formats.text_files import read_bounded_bytes
from engine.mocap.errors import MarkerFileError

_text_table: ModuleType | None
try:  # the compiled table reader (engine/mocap/_text_table.c); numpy's loadtxt otherwise
    from engine.mocap import _text_table
except ImportError:  # pragma: no cover - exercised where the extension is not built
    _text_table = None


MAX_TEXT_TABLE_BYTES = 4 << 30
"""A text marker file larger than this (4 GiB: hours of capture at hundreds of markers) is refused unread."""


def read_text_lines(path: Path) -> list[str]:
    """The file's lines without line ends (UTF-8, else Latin-1); a trailing empty line is dropped."""
    try:
        data = read_bounded_bytes(path, MAX_TEXT_TABLE_BYTES, MarkerFileError, "marker file")
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


def parse_number(text: str, what: str, path: Path, line: int) -> float:
    """``text`` as a number, or :class:`MarkerFileError` naming ``what``, the file and the line."""
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


def _parse_fast(lines: list[str], n_columns: int, delimiter: str | None,
                empty_is_missing: bool) -> np.ndarray | None:
    """A C parser for the common case of a well-formed table; None when anything is unusual.

    The compiled ``engine.mocap._text_table`` when it is built (one pass, the same
    doubles as ``float``), else numpy's ``loadtxt``.
    """
    if _text_table is not None and len(delimiter or " ") == 1:
        encoded = "\n".join(lines).encode("utf-8")
        out = np.empty((len(lines), n_columns))
        rows = _text_table.parse_table(encoded, out, n_columns, ord(delimiter) if delimiter is not None else -1,
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


def _parse_slow(lines: list[str], first_line: int, n_columns: int, path: Path, delimiter: str | None,
                empty_is_missing: bool, short_rows_at: int | None, last_line_complete: bool) -> np.ndarray:
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


def row_line(lines: list[str], first_line: int, row: int) -> int:
    """The 1-based line number of table row ``row`` (0-based) of :func:`parse_rows` ``lines`` (blank lines skip).

    >>> row_line(["1", "", "2"], 10, 1)
    12
    """
    seen = -1
    for i, line in enumerate(lines):
        if line.strip():
            seen += 1
            if seen == row:
                return first_line + i
    return first_line + len(lines) - 1


def _shorten(text: str, n: int = 40) -> str:
    return text if len(text) <= n else text[:n] + "…"
