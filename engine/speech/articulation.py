"""The phone → articulatory-target table (``engine/library/articulation/*.phones``).

One row per phone (or several phones sharing a row), one column per
articulatory parameter::

    $phoneset = finnish      # the Festival phone set whose phones the rows name (optional)
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

A voice's phone that no row names gets a row derived from its Festival phone
features (:mod:`engine.speech.phone_features`); :func:`table_for` picks the
shipped table of the voice's phone set (``finnish.phones``, ``english.phones``)
and fills in what it lacks, so every Festival voice speaks.

>>> from engine.speech.articulation import load_articulation
>>> table = load_articulation()
>>> table.target("a:", "jaw_open") == table.target("a", "jaw_open")
True
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import LibraryError
from engine.formats.text_files import read_bounded_text
from engine.paths import LIBRARY_DIR
from engine.speech.phone_features import DERIVED_PARAMETERS, PhoneFeatures, derived_cells

if TYPE_CHECKING:
    from engine.model import Model
    from engine.speech.synthesis import Utterance

TABLE_DIR = LIBRARY_DIR / "articulation"
DEFAULT_TABLE = TABLE_DIR / "finnish.phones"
MAX_TABLE_BYTES = 4 * 1024 * 1024
LONG_MARK = ":"
DEFAULTS = {"dominance": 1.0, "anticipation": 0.02, "carryover": 0.025, "weak": 0.05, "exponent": 1.0}
DERIVED_SETTINGS = {**DEFAULTS, "anticipation": 0.03, "carryover": 0.035, "weak": 0.04}
"""Settings of a table made only of derived rows: the shipped Finnish table's."""


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
    phoneset: str = ""
    """The Festival phone set the rows are written for (``$phoneset``; "" if the table does not say)."""
    settings: dict[str, float] = field(default_factory=lambda: dict(DEFAULTS))
    """The table's ``$dominance``, ``$anticipation``, ``$carryover``, ``$weak`` and ``$exponent``."""
    derived: frozenset[str] = frozenset()
    """Phones whose rows were derived from their features, not written in the file."""

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

    def with_derived_rows(self, features: Mapping[str, PhoneFeatures]) -> ArticulationTable:
        """A copy with a row derived from its features (:func:`~engine.speech.phone_features.derived_cells`)
        for every phone in ``features`` the table has no row for (a long phone keeps its short form's row).

        >>> from engine.speech.phone_features import PhoneFeatures
        >>> table = load_articulation().with_derived_rows({"ae": PhoneFeatures.parse("+ s 3 1 - 0 0 0")})
        >>> round(table.target("ae", "jaw_open"), 2), sorted(table.derived)
        (0.4, ['ae'])
        """
        rows, lines, derived = dict(self.rows), dict(self.lines), set(self.derived)
        for phone, phone_features in features.items():
            if phone in rows or (phone.endswith(LONG_MARK) and phone[:-1] in rows):
                continue
            cells = derived_cells(phone_features, self.parameters)
            rows[phone] = [_target(cell, self.settings, self.file, 0) for cell in cells]
            derived.add(phone)
        return ArticulationTable(self.parameters, rows, self.exponent, self.file, lines, self.phoneset,
                                 dict(self.settings), frozenset(derived))

    def with_blended_row(self, phone: str, toward: str, share: float) -> ArticulationTable:
        """A copy where ``phone`` (and its long form) articulates ``share`` of the way to ``toward``:
        every target's value and dominance blended linearly (a viseme continuum, e.g. p → t).

        >>> finnish = load_articulation()
        >>> p, t = finnish.target("p", "lower_lip_raise"), finnish.target("t", "lower_lip_raise")
        >>> finnish.with_blended_row("p", "t", 0.5).target("p", "lower_lip_raise") == (p + t) / 2
        True
        """
        if not 0.0 <= share <= 1.0:
            raise LibraryError(f"a viseme blend share must be in [0, 1], not {share:g}", file=self.file)
        start, end = self.row(phone), self.row(toward)

        def blend(a: Target, b: Target) -> Target:
            return Target((1 - share) * a.value + share * b.value, (1 - share) * a.dominance + share * b.dominance,
                          (1 - share) * a.anticipation + share * b.anticipation,
                          (1 - share) * a.carryover + share * b.carryover, a.enforced or b.enforced)

        rows = dict(self.rows)
        for name in (phone, phone + LONG_MARK):
            if name in rows or name == phone:
                rows[name] = [blend(a, b) for a, b in zip(start, end, strict=True)]
        return ArticulationTable(self.parameters, rows, self.exponent, self.file, dict(self.lines), self.phoneset,
                                 dict(self.settings), self.derived)

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
        text = read_bounded_text(path, MAX_TABLE_BYTES, LibraryError, "articulation table")
    except OSError as exc:
        raise LibraryError(f"cannot read the articulation table: {exc.strerror or exc}", file=path) from None
    return parse_articulation(text, str(path))


def shipped_tables() -> dict[str, Path]:
    """The shipped tables (``engine/library/articulation/*.phones``) by the phone set they declare."""
    tables: dict[str, Path] = {}
    for path in sorted(TABLE_DIR.glob("*.phones")):
        for line in path.read_text(encoding="utf-8").splitlines():
            match = _DIRECTIVE.match(line.strip())
            if match and match.group(1) == "phoneset":
                tables.setdefault(match.group(2).split("#")[0].strip(), path)
                break
    return tables


def table_for(utterance: Utterance, table: ArticulationTable | None = None) -> ArticulationTable:
    """The articulation table for ``utterance``'s phones: ``table`` if given, else the shipped table of the
    voice's phone set (the Finnish one when the synthesizer does not say which), with rows derived from
    the phones' features for every phone it lacks.

    A phone neither the table nor its features describe is an error naming the phone.
    """
    if table is None:
        path = shipped_tables().get(utterance.phoneset) if utterance.phoneset else DEFAULT_TABLE
        if path is None:  # a phone set no hand-made table covers: every row comes from the features
            table = ArticulationTable(list(DERIVED_PARAMETERS), {}, DEFAULTS["exponent"],
                                      f"<rows derived from the {utterance.phoneset} phone set>", {},
                                      utterance.phoneset, dict(DERIVED_SETTINGS))
        else:
            table = load_articulation(path)
    return table.with_derived_rows(utterance.phone_features)


_DIRECTIVE = re.compile(r"^\$([a-z]+)\s*=\s*(.*)$")
_CELL = re.compile(r"^(-|[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)(!?)"
                   r"(?:/([^/!]+))?(?:/([^/!]+))?(?:/([^/!]+))?(!?)$")


def parse_articulation(text: str, file: str = "<articulation>") -> ArticulationTable:
    """Parse a table; errors name file and line."""
    settings = dict(DEFAULTS)
    parameters: list[str] | None = None
    phoneset = ""
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
            elif name == "phoneset":
                if not re.fullmatch(r"[A-Za-z0-9_]+", value.strip()):
                    raise LibraryError(f"$phoneset must be one Festival phone set name, not {value.strip()!r}",
                                       file=file, line=number)
                phoneset = value.strip()
            elif name in DEFAULTS:
                settings[name] = _positive(value, f"${name}", file, number)
            else:
                raise LibraryError(f"unknown directive ${name} (known: $phoneset, $parameters, "
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
    return ArticulationTable(parameters, rows, settings["exponent"], file, lines, phoneset, settings)


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
