"""The phone → articulatory-target table (``library/articulation/*.phones``).

One row per phone (or several phones sharing a row), one column per
articulatory parameter::

    $parameters = jaw_open mouth_widen lip_protrude upper_lip_raise lower_lip_raise
    $dominance = 1           # default magnitude α of a phone's dominance (Cohen–Massaro)
    $anticipation = 0.02     # default anticipatory rate θ− (1/ms): how early a phone shows
    $carryover = 0.025       # default carry-over rate θ+ (1/ms): how long it lingers
    $weak = 0.05             # dominance of a '-' cell (the parameter is free for the neighbours)
    # phone     jaw_open  mouth_widen  lip_protrude  upper_lip_raise  lower_lip_raise
    a           0.62      0.15         0             0.1              0
    p,b,m       0!/8      0            0             0                1!/8

A cell is ``target[!][/dominance[/anticipation[/carryover]]]``; ``!`` marks a
target that is *enforced*: at the middle of the phone the parameter reaches
it whatever the neighbours do (bilabial and labiodental closure). ``-`` means
the phone does not care (target 0 with the ``$weak`` dominance), so lip
rounding spreads across a ``k`` or an ``h``. A long phone (``a:``) uses the
row of its short form unless it has a row of its own. ``#`` starts a comment
only at the start of a line or after whitespace (``#`` and ``##`` are also
Festival's pause phones, written as the first cell of their rows).

>>> from engine.speech.articulation import load_articulation
>>> table = load_articulation()
>>> table.target("a:", "jaw_open") == table.target("a", "jaw_open")
True
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import LibraryError
from engine.paths import LIBRARY_DIR

if TYPE_CHECKING:
    from engine.model import Model

DEFAULT_TABLE = LIBRARY_DIR / "articulation" / "finnish.phones"
LONG_MARK = ":"
DEFAULTS = {"dominance": 1.0, "anticipation": 0.02, "carryover": 0.025, "weak": 0.05, "exponent": 1.0}


@dataclass(frozen=True)
class Target:
    """One phone's target for one parameter, with its Cohen–Massaro dominance function."""

    value: float
    dominance: float
    anticipation: float
    carryover: float
    enforced: bool = False


@dataclass
class ArticulationTable:
    parameters: list[str]
    rows: dict[str, list[Target]]
    exponent: float
    file: str
    lines: dict[str, int]
    """Line of each phone's row, and of ``$parameters``."""

    def row(self, phone: str) -> list[Target]:
        """The targets of ``phone`` (a long phone falls back to its short form)."""
        if phone in self.rows:
            return self.rows[phone]
        if phone.endswith(LONG_MARK) and phone[:-1] in self.rows:
            return self.rows[phone[:-1]]
        raise LibraryError(f"the articulation table has no row for phone '{phone}' "
                           f"(phones: {' '.join(sorted(self.rows))})", file=self.file)

    def target(self, phone: str, parameter: str) -> float:
        return self.row(phone)[self.parameters.index(parameter)].value

    def arrays(self, phones: list[str]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(value, dominance, anticipation, carryover, enforced)``, each phones × parameters."""
        rows = [self.row(p) for p in phones]

        def attribute(name: str, dtype: type) -> np.ndarray:
            return np.array([[getattr(t, name) for t in row] for row in rows],
                            dtype=dtype).reshape(len(phones), len(self.parameters))

        return (attribute("value", float), attribute("dominance", float), attribute("anticipation", float),
                attribute("carryover", float), attribute("enforced", bool))

    def check(self, model: Model) -> None:
        """Every parameter of the table exists on ``model`` (else a LibraryError at ``$parameters``)."""
        for name in self.parameters:
            if name not in model.parameters:
                raise LibraryError(f"articulation parameter '{name}' does not exist on the model '{model.name}'",
                                   file=self.file, line=self.lines.get("$parameters"))


def load_articulation(path: str | Path | None = None) -> ArticulationTable:
    """Read an articulation table (default: the shipped Finnish one)."""
    path = Path(path) if path is not None else DEFAULT_TABLE
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise LibraryError(f"cannot read the articulation table: {exc.strerror or exc}", file=path) from None
    except UnicodeDecodeError:
        raise LibraryError("the articulation table is not UTF-8 text", file=path) from None
    return parse_articulation(text, str(path))


_DIRECTIVE = re.compile(r"^\$([a-z]+)\s*=\s*(.*)$")
_CELL = re.compile(r"^(-|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(!?)"
                   r"(?:/([^/!]+))?(?:/([^/!]+))?(?:/([^/!]+))?(!?)$")


def parse_articulation(text: str, file: str = "<articulation>") -> ArticulationTable:
    """Parse a table; errors name file and line."""
    settings = dict(DEFAULTS)
    parameters: list[str] | None = None
    rows: dict[str, list[Target]] = {}
    lines: dict[str, int] = {}
    for number, raw in enumerate(text.splitlines(), start=1):
        content = _strip_comment(raw).strip()
        if not content:
            continue
        directive = _DIRECTIVE.match(content)
        if directive:
            name, value = directive.groups()
            if name == "parameters":
                parameters = value.split()
                lines["$parameters"] = number
                if not parameters:
                    raise LibraryError("$parameters lists no parameter", file=file, line=number)
            elif name in DEFAULTS:
                settings[name] = _positive(value, f"${name}", file, number)
            else:
                raise LibraryError(f"unknown directive ${name} (known: $parameters, "
                                   + ", ".join("$" + d for d in DEFAULTS) + ")", file=file, line=number)
            continue
        if parameters is None:
            raise LibraryError("a phone row comes before $parameters", file=file, line=number)
        cells = content.split()
        phones, cells = cells[0].split(","), cells[1:]
        if len(cells) != len(parameters):
            raise LibraryError(f"row '{' '.join([','.join(phones), *cells])}' has {len(cells)} targets for "
                               f"{len(parameters)} parameters", file=file, line=number)
        targets = [_target(cell, settings, file, number) for cell in cells]
        for phone in phones:
            if not phone:
                raise LibraryError("an empty phone name (two commas?)", file=file, line=number)
            if phone in rows:
                raise LibraryError(f"phone '{phone}' has two rows (first on line {lines[phone]})",
                                   file=file, line=number)
            rows[phone] = targets
            lines[phone] = number
    if parameters is None:
        raise LibraryError("the articulation table has no $parameters line", file=file, line=1)
    if not rows:
        raise LibraryError("the articulation table has no phone rows", file=file, line=1)
    return ArticulationTable(parameters, rows, settings["exponent"], file, lines)


def _strip_comment(line: str) -> str:
    """The line without its comment. ``#`` and ``##`` are also pause phones: a line whose
    first token is made of them and whose second token is a target is a row, not a comment."""
    tokens = line.split()
    if not tokens:
        return ""
    if re.fullmatch(r"#{1,2}(,#{1,2})*", tokens[0]) and len(tokens) > 1 and _CELL.match(tokens[1]):
        head, rest = tokens[0], line.split(tokens[0], 1)[1]
        return head + re.split(r"\s#", rest, maxsplit=1)[0]
    if tokens[0].startswith("#"):
        return ""
    return re.split(r"\s#", line, maxsplit=1)[0]


def _target(cell: str, settings: dict[str, float], file: str, line: int) -> Target:
    match = _CELL.match(cell)
    if match is None:
        raise LibraryError(f"cannot read target '{cell}': expected value[!][/dominance[/anticipation[/carryover]]] "
                           "or -", file=file, line=line)
    value, mark, dominance, anticipation, carryover, end_mark = match.groups()
    enforced = "!" if (mark or end_mark) else ""
    if value == "-":
        if dominance or enforced:
            raise LibraryError(f"'{cell}': a '-' (don't care) cell takes no dominance and cannot be enforced",
                               file=file, line=line)
        return Target(0.0, settings["weak"], settings["anticipation"], settings["carryover"])
    return Target(
        _finite(value, cell, file, line),
        _positive(dominance, f"dominance in '{cell}'", file, line) if dominance else settings["dominance"],
        _positive(anticipation, f"anticipation in '{cell}'", file, line) if anticipation else settings["anticipation"],
        _positive(carryover, f"carry-over in '{cell}'", file, line) if carryover else settings["carryover"],
        enforced == "!")


def _finite(text: str, what: str, file: str, line: int) -> float:
    try:
        value = float(text)
    except ValueError:
        raise LibraryError(f"'{what}' is not a number", file=file, line=line) from None
    if not math.isfinite(value):
        raise LibraryError(f"'{what}' must be finite", file=file, line=line)
    return value


def _positive(text: str, what: str, file: str, line: int) -> float:
    value = _finite(text, what, file, line)
    if value <= 0:
        raise LibraryError(f"{what} must be positive (got {text})", file=file, line=line)
    return value
