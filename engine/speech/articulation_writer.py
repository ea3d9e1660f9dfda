"""An articulation table back to the phone-table text (``*.phones``) that :func:`parse_articulation` reads.

The text parses back to the same table exactly: the same parameters, phone
set, settings and, for every phone, the same targets to the last bit (floats
are written in their shortest exact form, ``repr``). Phones with identical
rows share one row (``p,b,m``); a cell leaves out the dominance, anticipation
and carry-over it shares with the table's ``$`` settings, and a cell that is
exactly what ``-`` reads as is written ``-``. Before it returns, the writer
parses its own text and compares, so it never hands back a table that would
read differently (phone names the format cannot hold are refused).

>>> from engine.speech.articulation import load_articulation, parse_articulation
>>> table = load_articulation()
>>> text = articulation_text(table, comment="a copy of the shipped table")
>>> again = parse_articulation(text)
>>> again.rows == table.rows and again.settings == table.settings
True
>>> [line for line in text.splitlines() if line.startswith("p,b,m")]
['p,b,m  0!/2  -  -  0/2  1!/2  -']
"""

from __future__ import annotations

import re
from pathlib import Path

from engine.errors import LibraryError
from engine.speech.articulation import DEFAULTS, ArticulationTable, Target, parse_articulation

_PHONE = re.compile(r"[^\s,#$][^\s,]*|#{1,2}")


def articulation_text(table: ArticulationTable, comment: str = "") -> str:
    """The phone-table text of ``table``, with ``comment`` (any lines) as ``#`` comments at the top."""
    lines = [_comment_line(c) for c in comment.splitlines()] if comment else []
    if table.phoneset:
        lines.append(f"$phoneset = {table.phoneset}")
    lines.append(f"$parameters = {' '.join(table.parameters)}")
    settings = {**DEFAULTS, **table.settings, "exponent": table.exponent}
    lines += [f"${name} = {_number(settings[name])}" for name in DEFAULTS]
    lines.append("")
    lines.append("# phone  " + "  ".join(table.parameters))
    for phones, targets in _grouped_rows(table):
        bad = [p for p in phones if not _PHONE.fullmatch(p)]
        if bad:
            raise LibraryError(f"phone name {bad[0]!r} cannot be written in a phone table "
                               "(no spaces or commas, and only # or ## may start with #)", file=table.file)
        lines.append(",".join(phones) + "  " + "  ".join(_cell(t, settings) for t in targets))
    text = "\n".join(lines) + "\n"
    _check_round_trip(table, text)
    return text


def write_articulation(table: ArticulationTable, path: str | Path, comment: str = "") -> Path:
    """Write ``table`` to ``path`` atomically (see :func:`articulation_text`); returns the path."""
    from engine.formats.atomic import atomic_write_text

    out = Path(path)
    atomic_write_text(out, articulation_text(table, comment))
    return out


def _grouped_rows(table: ArticulationTable) -> list[tuple[list[str], list[Target]]]:
    groups: list[tuple[list[str], list[Target]]] = []
    for phone, targets in table.rows.items():
        for phones, shared in groups:
            if shared == targets:
                phones.append(phone)
                break
        else:
            groups.append(([phone], list(targets)))
    return groups


def _cell(target: Target, settings: dict[str, float]) -> str:
    if not target.enforced and target == Target(0.0, settings["weak"], settings["anticipation"],
                                                settings["carryover"]):
        return "-"
    parts = [target.dominance, target.anticipation, target.carryover]
    defaults = [settings["dominance"], settings["anticipation"], settings["carryover"]]
    while parts and parts[-1] == defaults[len(parts) - 1]:
        parts.pop()
    head = _number(target.value) + ("!" if target.enforced else "")
    return "/".join([head, *map(_number, parts)])


def _number(value: float) -> str:
    text = repr(float(value))
    return "0" if text == "0.0" else text.removesuffix(".0") if text.endswith(".0") else text


def _comment_line(text: str) -> str:
    # '# 0.5 …' would read as a row of the pause phone '#': comments start with a word, not a cell
    return "# " + (text if text.strip() and text.strip()[0] not in "-+.0123456789" else "· " + text)


def _check_round_trip(table: ArticulationTable, text: str) -> None:
    again = parse_articulation(text, table.file)
    same = (again.parameters == table.parameters and again.rows == table.rows and again.phoneset == table.phoneset
            and again.exponent == table.exponent
            and all(again.settings[k] == v for k, v in table.settings.items()))
    if not same:
        raise LibraryError("the table's text would not read back the same (a phone name or value the "
                           "format cannot hold)", file=table.file)
