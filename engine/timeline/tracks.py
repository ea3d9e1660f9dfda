"""The tracks table: every parameter at every frame, written and read back.

The table has a header ``time_ms,<parameter>,…`` and one row per frame
(times in ms, values in each parameter's units). :func:`tracks_csv_text`
writes it from sampled values (:meth:`engine.timeline.Timeline.tracks_csv`
samples and writes in one go); :func:`read_tracks_csv` reads it back as a
:class:`TracksTable`, which answers like an :class:`engine.timeline.Timeline`:
``values_at(ms)``, ``sample(times)``, ``start``/``end`` (ms) and
``parameters``. Between rows values are interpolated linearly, so at the
frame times it gives back exactly the numbers written. The parameters it
drives (:attr:`TracksTable.driven`) are the columns that ever leave the
model's default; the other parameters keep their default, as on the timeline.

>>> from engine import load_model
>>> from engine.commands import load_library, parse_commands_text, translate
>>> from engine.timeline import Timeline
>>> head = load_model()
>>> nod = parse_commands_text('<commands><HeadNod at="1000" amplitude="60" count="2"/></commands>')
>>> timeline = Timeline(translate(nod, load_library(), head), head)
>>> table = parse_tracks_csv(timeline.tracks_csv(fps=60), head)
>>> table.driven, round(table.fps, 6)
(['head_nod'], 60.0)
>>> table.values_at(table.times[70])["head_nod"]               # a row gives back the number written
0.0899099099099
>>> timeline.values_at(70 * 1000 / 60)["head_nod"]               # the timeline's, to 12 digits
0.08990990990990987
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from engine.commands.command_files import format_number
from engine.errors import UserError
from engine.formats.text_files import read_bounded_text
from engine.model.model import Model

TIME_COLUMN = "time_ms"
SINGLE_ROW_FPS = 60.0
"""The frame rate a table of a single row is taken to have."""


def tracks_csv_text(parameters: Sequence[str], times: ArrayLike, values: ArrayLike) -> str:
    """The tracks table of ``values`` (frames × parameters) at ``times`` (ms), numbers to 12 digits.

    >>> print(tracks_csv_text(["jaw_open"], [0.0, 40.0], [[0.0], [0.25]]), end="")
    time_ms,jaw_open
    0,0
    40,0.25
    """
    rows = np.asarray(values, dtype=float).reshape(len(np.atleast_1d(times)), len(parameters))
    lines = [",".join([TIME_COLUMN, *parameters])]
    for t, row in zip(np.atleast_1d(np.asarray(times, dtype=float)), rows, strict=True):
        lines.append(",".join([format_number(t)] + [format_number(v) for v in row]))
    return "\n".join(lines) + "\n"


class TracksTable:
    """Sampled parameter tracks: ``times`` (ms, rising) × ``parameters`` → ``values``, for ``model``."""

    def __init__(self, times: ArrayLike, parameters: Sequence[str], values: ArrayLike, model: Model,
                 source: str = "<tracks>"):
        self.times = np.asarray(times, dtype=float)
        self.values = np.asarray(values, dtype=float).reshape(len(self.times), len(parameters))
        self.model = model
        self.source = source
        tree = model.parameters
        self.parameters: list[str] = list(tree.names)
        self._columns = {name: i for i, name in enumerate(parameters)}
        self._default = np.array([tree[n].default for n in self.parameters], dtype=float)
        self.driven: list[str] = [name for name in self.parameters if name in self._columns
                                  and not np.all(self.values[:, self._columns[name]] == tree[name].default)]

    @property
    def start(self) -> float:
        """Time of the first row (ms; 0 for an empty table)."""
        return float(self.times[0]) if len(self.times) else 0.0

    @property
    def end(self) -> float:
        """Time of the last row (ms; 0 for an empty table)."""
        return float(self.times[-1]) if len(self.times) else 0.0

    @property
    def fps(self) -> float:
        """Frames per second of the rows (the median spacing; :data:`SINGLE_ROW_FPS` for a single row)."""
        steps = np.diff(self.times)
        steps = steps[steps > 0]
        return 1000.0 / float(np.median(steps)) if len(steps) else SINGLE_ROW_FPS

    def sample(self, times: ArrayLike) -> np.ndarray:
        """Values (len(times) × parameters) at ``times`` (ms); held at the first and last row outside."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        out = np.tile(self._default, (times.size, 1))
        for j, name in enumerate(self.parameters):
            column = self._columns.get(name)
            if column is not None and len(self.times):
                out[:, j] = np.interp(times, self.times, self.values[:, column])
        return out

    def values_at(self, time: float) -> dict[str, float]:
        """Every parameter's value at ``time`` (ms), as a dict ready for ``Model.deform``."""
        return dict(zip(self.parameters, self.sample([time])[0].tolist(), strict=True))


def read_tracks_csv(path: str | Path, model: Model) -> TracksTable:
    """Read a tracks CSV for ``model``; bad files raise :class:`UserError` with file and line."""
    text = read_bounded_text(path, what="tracks file")
    return parse_tracks_csv(text, model, str(path))


def parse_tracks_csv(text: str, model: Model, name: str = "<tracks>") -> TracksTable:
    """The tracks table in ``text`` for ``model``; ``name`` is the file named in errors.

    Every column must be a parameter of the model, every value inside its
    range, times must not go back.

    >>> from engine import load_model
    >>> parse_tracks_csv("time_ms,jaw_open\\n0,zero\\n", load_model(), "t.csv")
    Traceback (most recent call last):
    engine.errors.UserError: t.csv:2: not a number: 'zero'
    """
    reader = csv.reader(io.StringIO(text, newline=""))
    try:
        rows = list(reader)
    except csv.Error as exc:                   # e.g. a NUL byte, a quote left open
        raise UserError(f"malformed CSV: {exc}", file=name, line=reader.line_num) from None
    if not rows or not rows[0]:
        raise UserError("empty tracks file: expected a header 'time_ms,<parameter>,…'", file=name, line=1)
    header = [cell.strip() for cell in rows[0]]
    if header[0] != TIME_COLUMN:
        raise UserError(f"the first column must be '{TIME_COLUMN}', not '{header[0]}'", file=name, line=1)
    parameters = header[1:]
    tree = model.parameters
    for column in parameters:
        if column not in tree.names:
            raise UserError(f"unknown parameter '{column}' (not in the model)", file=name, line=1)
    if len(set(parameters)) != len(parameters):
        raise UserError("a parameter appears twice in the header", file=name, line=1)
    times: list[float] = []
    values: list[list[float]] = []
    for line_number, row in enumerate(rows[1:], start=2):
        if not row or all(not cell.strip() for cell in row):
            continue
        if len(row) != len(header):
            raise UserError(f"{len(row)} columns, the header has {len(header)}", file=name, line=line_number)
        try:
            numbers = [float(cell) for cell in row]
        except ValueError:
            bad = next(cell for cell in row if not _is_number(cell))
            raise UserError(f"not a number: '{bad.strip()}'", file=name, line=line_number) from None
        if not all(math.isfinite(x) for x in numbers):
            raise UserError("numbers must be finite", file=name, line=line_number)
        if times and numbers[0] < times[-1]:
            raise UserError(f"time {numbers[0]:g} ms goes back (previous row {times[-1]:g} ms)",
                            file=name, line=line_number)
        for column, value in zip(parameters, numbers[1:], strict=True):
            parameter = tree[column]
            if not parameter.minimum <= value <= parameter.maximum:
                raise UserError(f"{column} = {value:g} is outside its range "
                                f"[{parameter.minimum:g}, {parameter.maximum:g}]", file=name, line=line_number)
        times.append(numbers[0])
        values.append(numbers[1:])
    if not times:
        raise UserError("no rows after the header", file=name, line=1)
    return TracksTable(times, parameters, values, model, name)


def _is_number(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True
