"""Comma-separated tables as the capture producers write them: cells stripped, every line numbered.

Live Link Face writes ``a,b,c``; OpenFace writes ``a, b, c`` (a space after
each comma); a MediaPipe CSV is whatever a script wrote. None quotes cells, so
a line is split at its commas. Numbers are checked one by one, so an error
names the file, the line and the column.

>>> rows = split_rows("t, x\\n0, 1.5\\n\\n40, 2\\n")
>>> rows
[(1, ['t', 'x']), (2, ['0', '1.5']), (4, ['40', '2'])]
>>> number("1.5", "take.csv", 2, "x")
1.5
>>> number("nan", "take.csv", 2, "x")
Traceback (most recent call last):
engine.capture.stream.CaptureFileError: take.csv:2: column 'x': 'nan' is not a finite number
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import overload

from engine.capture.stream import CaptureFileError
from engine.formats.text_files import read_bounded_text

MAX_CAPTURE_BYTES = 500_000_000
"""The largest capture table read (500 MB: an OpenFace table with landmarks of an hour of video)."""


def read_rows(path: str | Path) -> Rows:
    """The non-blank lines of ``path`` as (line number, stripped cells)."""
    text = read_bounded_text(path, limit=MAX_CAPTURE_BYTES, error=CaptureFileError, what="capture file")
    return split_rows(text)


def split_rows(text: str) -> Rows:
    """The non-blank lines of ``text`` as (line number, stripped cells), split when a row is looked at."""
    return Rows([(n, line) for n, line in enumerate(text.splitlines(), start=1) if line.strip()])


class Rows(Sequence[tuple[int, list[str]]]):
    """Numbered lines whose cells are split on access: an hour of OpenFace output with landmarks
    (100,000 rows of 700 cells) is never held as 70 million strings at once."""

    def __init__(self, lines: list[tuple[int, str]]):
        self._lines = lines

    def __len__(self) -> int:
        return len(self._lines)

    @overload
    def __getitem__(self, index: int) -> tuple[int, list[str]]: ...
    @overload
    def __getitem__(self, index: slice) -> Rows: ...

    def __getitem__(self, index: int | slice) -> tuple[int, list[str]] | Rows:
        if isinstance(index, slice):
            return Rows(self._lines[index])
        number_, line = self._lines[index]
        return number_, [cell.strip() for cell in line.split(",")]

    def __eq__(self, other: object) -> bool:
        return list(self) == other if isinstance(other, list) else NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return repr(list(self))


def number(cell: str, source: str, line: int, column: str) -> float:
    """``cell`` as a finite float, or a :class:`CaptureFileError` naming file, line and column."""
    try:
        value = float(cell)
    except ValueError:
        raise CaptureFileError(f"column '{column}': {_shown(cell)} is not a number", file=source, line=line) from None
    if not math.isfinite(value):
        raise CaptureFileError(f"column '{column}': {_shown(cell)} is not a finite number", file=source, line=line)
    return value


def whole_number(cell: str, source: str, line: int, column: str) -> int:
    """``cell`` as a non-negative integer (digits only), or a :class:`CaptureFileError`."""
    if not cell.isdigit() or not cell.isascii() or len(cell) > 12:
        raise CaptureFileError(f"column '{column}': {_shown(cell)} is not a whole number", file=source, line=line)
    return int(cell)


def check_width(cells: list[str], width: int, source: str, line: int) -> None:
    """Refuse a row whose cell count is not the header's."""
    if len(cells) != width:
        raise CaptureFileError(f"{len(cells)} cells where the header has {width}", file=source, line=line)


def check_unique(header: list[str], source: str, line: int) -> None:
    """Refuse a header naming a column twice (or an empty column name)."""
    seen: set[str] = set()
    for name in header:
        if not name:
            raise CaptureFileError("an empty column name in the header", file=source, line=line)
        if name in seen:
            raise CaptureFileError(f"column '{_shown(name, quote=False)}' appears twice in the header",
                                   file=source, line=line)
        seen.add(name)


def _shown(cell: str, quote: bool = True) -> str:
    text = cell if len(cell) <= 40 else cell[:37] + "..."
    text = text.encode("unicode_escape").decode("ascii")
    return repr(text) if quote else text
