"""A tracks CSV (``Timeline.tracks_csv``, DESIGN.md) read back as something the player can play.

The table has a header ``time_ms,<parameter>,…`` and one row per frame.
:class:`TracksTable` answers like an :class:`engine.timeline.Timeline`:
``values_at(ms)``, ``sample(times)``, ``start``/``end`` (ms) and
``parameters``; between rows values are interpolated linearly, so at the
frame times it gives back exactly the numbers written. The parameters it
drives (:attr:`TracksTable.driven`) are the columns that ever leave the
model's default; the other parameters keep their default, as on the timeline.

>>> table = read_tracks_csv("nod.csv", model)                  # doctest: +SKIP
>>> table.values_at(1166.5)["head_nod"]                         # doctest: +SKIP
0.09
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from engine.errors import UserError

TIME_COLUMN = "time_ms"


class TracksTable:
    """Sampled parameter tracks: ``times`` (ms, rising) × ``parameters`` → ``values``."""

    def __init__(self, times, parameters: list[str], values, model, source: str = "<tracks>"):
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
        return float(self.times[0]) if len(self.times) else 0.0

    @property
    def end(self) -> float:
        return float(self.times[-1]) if len(self.times) else 0.0

    @property
    def fps(self) -> float:
        """Frames per second of the rows (the median spacing; 60 for a single row)."""
        steps = np.diff(self.times)
        steps = steps[steps > 0]
        return 1000.0 / float(np.median(steps)) if len(steps) else 60.0

    def sample(self, times) -> np.ndarray:
        """Values (len(times) × parameters) at ``times`` (ms); held at the first and last row outside."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        out = np.tile(self._default, (times.size, 1))
        for j, name in enumerate(self.parameters):
            column = self._columns.get(name)
            if column is not None and len(self.times):
                out[:, j] = np.interp(times, self.times, self.values[:, column])
        return out

    def values_at(self, time: float) -> dict[str, float]:
        return dict(zip(self.parameters, self.sample([time])[0].tolist()))


def read_tracks_csv(path: str | Path, model) -> TracksTable:
    """Read a tracks CSV for ``model``; bad files raise :class:`UserError` with file and line."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise UserError(f"cannot read the tracks file: {getattr(exc, 'strerror', None) or exc}", file=path) from None
    return parse_tracks_csv(text, model, str(path))


def parse_tracks_csv(text: str, model, name: str = "<tracks>") -> TracksTable:
    rows = list(csv.reader(io.StringIO(text)))
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
    times, values = [], []
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
        for column, value in zip(parameters, numbers[1:]):
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
