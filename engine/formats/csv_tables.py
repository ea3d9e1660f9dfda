"""A user's CSV table read as header and rows, a malformed one refused with the file and line.

Python's ``csv`` module raises its own ``csv.Error`` on a NUL byte, a bare carriage return in a
field, a field over 128 kB or a quote left open; :func:`read_table` turns that into a
:class:`~engine.errors.UserError` naming the file and the line.

>>> header, rows = table_rows("file,emotion\\na.png,happy\\n", "t.csv")
>>> header, rows
(['file', 'emotion'], [(2, {'file': 'a.png', 'emotion': 'happy'})])
>>> table_rows("file\\n" + "x" * 200_000 + "\\n", "t.csv")
Traceback (most recent call last):
engine.errors.UserError: t.csv:2: malformed CSV: field larger than field limit (131072)
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

from engine.errors import UserError
from engine.formats.text_files import read_bounded_text


def read_table(path: str | Path, what: str = "table") -> tuple[list[str], list[tuple[int, dict[str, str]]]]:
    """The header and the rows (line number, column → cell) of the CSV file ``path``."""
    return table_rows(read_bounded_text(path, what=what), str(path))


def table_rows(text: str, name: str) -> tuple[list[str], list[tuple[int, dict[str, str]]]]:
    """:func:`read_table` of text already read; ``name`` is the file named in errors. Cells missing at
    the end of a short row are empty strings; cells beyond the header are dropped."""
    reader = csv.reader(io.StringIO(text, newline=""))
    try:
        header = [cell.strip() for cell in next(reader, [])]
        rows = []
        for cells in reader:
            if not any(cell.strip() for cell in cells):
                continue
            padded = cells + [""] * (len(header) - len(cells))
            rows.append((reader.line_num, dict(zip(header, padded[:len(header)], strict=True))))
    except csv.Error as exc:
        raise UserError(f"malformed CSV: {exc}", file=name, line=reader.line_num) from None
    return header, rows
