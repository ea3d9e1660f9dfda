"""Command library files: the §2.3 format that turns a high-level command into activations.

A library file defines one high-level command (or several, each starting at
its own ``$command``) in the paper's format::

    $command = HeadNod
    $mandatory = at
    $optional = amplitude=100, count=1,
    period=500,
    frequency=1, end=1000
    $interp = linear
    amplitude = 0,0; 333,0.15; 666,0;
    833,-0.025; 1000,0
    $proc = periodic

Directives start with ``$``; every other statement is a *line*: a name and a
list of ``time,value`` pairs (ms, parameter units). A value continues on the
next line when its line ends with ``,`` or ``;`` or when the next line starts
with a number. ``#`` starts a comment. Besides the paper's directives
(``$command``, ``$mandatory``, ``$optional``, ``$interp``, ``$proc``) there are
``$parameter`` (the model parameter the line called ``amplitude`` drives) and
``$description``. A line may be scaled by one of the command's arguments:
``eye_left_turn * x = 0,0; 200,0.01745; …``. See ``docs/commands.md``.

>>> from engine.commands.library_format import load_library_file
>>> from engine.paths import LIBRARY_DIR
>>> [nod] = load_library_file(LIBRARY_DIR / "HeadNod.lib")
>>> nod.name, nod.procedure, nod.optional["count"]
('HeadNod', 'periodic', 1.0)
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from engine.commands.command_definition import AMPLITUDE, IMPLICIT_ARGUMENTS, START, CommandDefinition, Curve
from engine.commands.interpolation import INTERPOLATIONS
from engine.commands.limits import LimitProblem, check_time
from engine.commands.procedures import check_definition
from engine.errors import LibraryError
from engine.formats.text_files import read_bounded_bytes

# The command types live in engine.commands.command_definition (the procedures need them too);
# what a library file reads is importable from here as well.
__all__ = [
    "AMPLITUDE",
    "DIRECTIVES",
    "IMPLICIT_ARGUMENTS",
    "START",
    "CommandDefinition",
    "Curve",
    "load_library_file",
    "parse_library_text",
]

DIRECTIVES = ("command", "mandatory", "optional", "interp", "proc", "parameter", "description")

_NAME = r"[A-Za-z_][A-Za-z0-9_.\-]*"
_STATEMENT = re.compile(rf"^\s*(\$?)({_NAME})\s*(?:\*\s*({_NAME})\s*)?=(.*)$")
_IDENTIFIER = re.compile(rf"^{_NAME}$")


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

def load_library_file(path: str | Path) -> list[CommandDefinition]:
    """Every command defined in one library file."""
    path = Path(path)
    raw = read_bounded_bytes(path, error=LibraryError, what="library file")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise LibraryError("the library file is not UTF-8 text", file=path, line=line) from None
    return parse_library_text(text, str(path))


def parse_library_text(text: str, file: str = "<library>") -> list[CommandDefinition]:
    """Parse library-file text; ``file`` names it in error messages.

    Raises :class:`~engine.errors.LibraryError` with file and line for anything wrong.
    """
    definitions = []
    for block in _blocks(_statements(text, file), file):
        definition = _definition(block, file)
        check_definition(definition)
        definitions.append(definition)
    if not definitions:
        raise LibraryError("the library file defines no command (it has no $command line)", file=file, line=1)
    return definitions


@dataclass
class _Statement:
    directive: bool
    name: str
    scale: str | None
    value: str
    line: int
    char_lines: list[int]          # line number of every character of value
    continuations: list[str] = field(default_factory=list)
    """Text of the lines that continue the value, joined onto it once the statement is complete
    (joining as each line comes would copy the value again for every line: quadratic time)."""

    def line_of(self, offset: int) -> int:
        if not self.char_lines:
            return self.line
        return self.char_lines[min(max(offset, 0), len(self.char_lines) - 1)]


def _statements(text: str, file: str) -> list[_Statement]:
    statements: list[_Statement] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        content = raw.split("#", 1)[0].rstrip()
        if not content.strip():
            continue
        if "\x00" in content:
            raise LibraryError("the line holds a NUL character", file=file, line=number)
        previous = statements[-1] if statements else None
        match = _STATEMENT.match(content)
        if previous is not None and _continues(previous, content, match):
            addition = " " + content.strip()
            previous.continuations.append(addition)
            previous.char_lines += [number] * len(addition)
            continue
        if match is None:
            raise LibraryError(f"cannot read '{content.strip()[:60]}': expected '$directive = value' "
                               "or 'parameter = time,value; time,value; …'", file=file, line=number)
        dollar, name, scale, value = match.groups()
        if dollar and scale:
            raise LibraryError(f"a directive cannot be scaled: '${name} * {scale}'", file=file, line=number)
        stripped = value.strip()
        statements.append(_Statement(bool(dollar), name, scale, stripped, number, [number] * len(stripped)))
    for statement in statements:
        statement.value += "".join(statement.continuations)
        statement.continuations.clear()
    return statements


def _continues(previous: _Statement, content: str, match: re.Match[str] | None) -> bool:
    """Whether a line continues the previous statement's value (the paper breaks values over lines)."""
    text = content.lstrip()
    if text.startswith("$"):
        return False
    if re.match(r"[-+.\d]", text):
        return True                                  # curve data: '833,-0.025; 1000,0'
    last = previous.continuations[-1] if previous.continuations else previous.value
    open_list = last.rstrip().endswith((",", ";"))
    if previous.directive and previous.name in ("optional", "mandatory") and open_list:
        return True                                  # 'period=500,' after '$optional = …,'
    return open_list and match is None


def _blocks(statements: list[_Statement], file: str) -> list[list[_Statement]]:
    blocks: list[list[_Statement]] = []
    for st in statements:
        if st.directive and st.name == "command":
            blocks.append([st])
        elif not blocks:
            what = f"${st.name}" if st.directive else f"line '{st.name}'"
            raise LibraryError(f"{what} comes before $command: every command starts with "
                               "'$command = Name'", file=file, line=st.line)
        else:
            blocks[-1].append(st)
    return blocks


def _definition(block: list[_Statement], file: str) -> CommandDefinition:
    head = block[0]
    if not _IDENTIFIER.match(head.value):
        raise LibraryError(f"$command needs a name made of letters, digits and _ (got '{head.value}')",
                           file=file, line=head.line)
    directives: dict[str, _Statement] = {}
    curves: list[Curve] = []
    for st in block[1:]:
        if st.directive:
            if st.name not in DIRECTIVES:
                raise LibraryError(f"unknown directive ${st.name} (known: "
                                   + ", ".join("$" + d for d in DIRECTIVES) + ")", file=file, line=st.line)
            if st.name in directives:
                raise LibraryError(f"${st.name} is given twice in command {head.value} "
                                   f"(first on line {directives[st.name].line})", file=file, line=st.line)
            directives[st.name] = st
        else:
            if any(c.name == st.name for c in curves):
                first = next(c for c in curves if c.name == st.name)
                raise LibraryError(f"line '{st.name}' is given twice in command {head.value} "
                                   f"(first on line {first.line})", file=file, line=st.line)
            curves.append(_curve(st, file))
    lines = {name: st.line for name, st in directives.items()}
    lines["command"] = head.line

    mandatory = _names(directives.get("mandatory"), file)
    optional = _defaults(directives.get("optional"), file)
    for name in mandatory:
        if name in optional:
            raise LibraryError(f"argument '{name}' is both mandatory and optional", file=file,
                               line=lines["optional"])
    interpolation = directives["interp"].value if "interp" in directives else "linear"
    if interpolation not in INTERPOLATIONS:
        raise LibraryError(f"unknown interpolation '{interpolation}' (known: {', '.join(INTERPOLATIONS)})",
                           file=file, line=lines["interp"])
    procedure = directives["proc"].value if "proc" in directives else "once"
    parameter = directives["parameter"].value if "parameter" in directives else None
    if parameter is not None and not _IDENTIFIER.match(parameter):
        raise LibraryError(f"$parameter needs one parameter name (got '{parameter}')", file=file,
                           line=lines["parameter"])
    if not curves:
        raise LibraryError(f"command {head.value} activates no parameter: add a line "
                           "'parameter = time,value; time,value; …'", file=file, line=head.line)
    return CommandDefinition(
        name=head.value, mandatory=tuple(mandatory), optional=optional, interpolation=interpolation,
        procedure=procedure, curves=tuple(curves), file=file, line=head.line, parameter=parameter,
        description=directives["description"].value if "description" in directives else "", lines=lines)


def _names(st: _Statement | None, file: str) -> list[str]:
    if st is None:
        return []
    names = []
    for offset, item in _items(st.value, ","):
        if not item:
            continue
        if not _IDENTIFIER.match(item):
            raise LibraryError(f"'{item}' is not an argument name", file=file, line=st.line_of(offset))
        if item in names:
            raise LibraryError(f"argument '{item}' is listed twice", file=file, line=st.line_of(offset))
        names.append(item)
    return names


def _defaults(st: _Statement | None, file: str) -> dict[str, float]:
    if st is None:
        return {}
    defaults: dict[str, float] = {}
    for offset, item in _items(st.value, ","):
        if not item:
            continue
        name, eq, value = item.partition("=")
        name, value = name.strip(), value.strip()
        line = st.line_of(offset)
        if not eq or not _IDENTIFIER.match(name):
            raise LibraryError(f"'{item}' is not 'name=default' (optional arguments need a default)",
                               file=file, line=line)
        if name in defaults:
            raise LibraryError(f"argument '{name}' is listed twice", file=file, line=line)
        defaults[name] = _number(value, f"the default of '{name}'", file, line)
    return defaults


def _curve(st: _Statement, file: str) -> Curve:
    items = [(offset, item) for offset, item in _items(st.value, ";") if item]
    if not items:
        raise LibraryError(f"line '{st.name}' has no time,value pairs", file=file, line=st.line)
    if len(items) == 1 and "," not in items[0][1]:
        offset, item = items[0]
        level = _number(item, f"the level of '{st.name}'", file, st.line_of(offset))
        return Curve(st.name, (), (level,), st.line, st.scale)
    times: list[float] = []
    values: list[float] = []
    for offset, item in items:
        line = st.line_of(offset)
        parts = [p.strip() for p in item.split(",")]
        if len(parts) != 2:
            raise LibraryError(f"'{item}' in line '{st.name}' is not one 'time,value' pair", file=file, line=line)
        t = _number(parts[0], f"a time in line '{st.name}'", file, line)
        try:
            check_time(t, f"a time in line '{st.name}'")
        except LimitProblem as exc:
            raise LibraryError(str(exc), file=file, line=line) from None
        v = _number(parts[1], f"a value in line '{st.name}'", file, line)
        if times and t <= times[-1]:
            raise LibraryError(f"times in line '{st.name}' must increase: {_fmt(t)} comes after "
                               f"{_fmt(times[-1])}", file=file, line=line)
        times.append(t)
        values.append(v)
    if len(times) < 2:
        raise LibraryError(f"line '{st.name}' needs at least two time,value pairs", file=file, line=st.line)
    return Curve(st.name, tuple(times), tuple(values), st.line, st.scale)


def _items(text: str, separator: str) -> Iterator[tuple[int, str]]:
    """(offset, stripped item) for each ``separator``-separated item of ``text``."""
    offset = 0
    for piece in text.split(separator):
        lead = len(piece) - len(piece.lstrip())
        yield offset + lead, piece.strip()
        offset += len(piece) + 1


def _number(text: str, what: str, file: str, line: int) -> float:
    try:
        value = float(text)
    except ValueError:
        raise LibraryError(f"{what} is not a number: '{text}'", file=file, line=line) from None
    if not math.isfinite(value):
        raise LibraryError(f"{what} must be a finite number, not '{text}'", file=file, line=line)
    return value


def _fmt(x: float) -> str:
    return f"{x:g}"
