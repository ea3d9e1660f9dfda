"""What can be known about a library file's text while it is written (§2.3).

:func:`check_library_text` answers, with the same parser the command line
uses (so the workbench's library editor and the command line never
disagree): is the text a valid §2.3 library file, and does every command fit
the open model? It returns the problems with their line numbers (the
engine's :class:`~engine.errors.LibraryError` carries the line).
:func:`command_arguments` gives the arguments a preview of a command passes.
What a command then does over time, curve by curve, is
:func:`engine.timeline.command_curves.command_curves`.

>>> from engine.paths import LIBRARY_DIR
>>> text = (LIBRARY_DIR / "HeadNod.lib").read_text()
>>> check_library_text(text, "HeadNod.lib").problems
[]
>>> check_library_text("$command = X\\n$interp = wobbly\\nx = 0,0; 1,1\\n", "x.lib").problems[0].line
2
"""

from __future__ import annotations

from dataclasses import dataclass, field

from engine.commands.library import Library
from engine.commands.library_format import START, CommandDefinition, parse_library_text
from engine.errors import UserError
from engine.model.model import Model


@dataclass(frozen=True)
class Problem:
    """One thing wrong with the text: 1-based ``line`` (``None`` when the engine gave none) and ``message``."""

    line: int | None
    message: str
    text: str = ""
    """The engine's full one-line message (``file:line: what``)."""


@dataclass
class CheckResult:
    """The definitions the text holds (empty when it does not parse) and every problem found."""

    definitions: list[CommandDefinition] = field(default_factory=list)
    problems: list[Problem] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """True when the text parsed and every command fits."""
        return not self.problems


def check_library_text(text: str, file: str = "<library>", model: Model | None = None) -> CheckResult:
    """Parse ``text`` as a library file; with ``model``, also bind each command to it.

    A syntax error stops the parse (the engine reports the first one); binding
    problems are collected for every command.
    """
    try:
        definitions = parse_library_text(text, file)
    except UserError as exc:
        return CheckResult([], [_problem(exc)])
    result = CheckResult(definitions)
    if model is not None:
        result.problems = [_problem(exc) for exc in Library(definitions).check(model)]
    return result


def _problem(exc: UserError) -> Problem:
    return Problem(getattr(exc, "line", None), getattr(exc, "message", str(exc)), str(exc))


def command_arguments(definition: CommandDefinition, values: dict[str, float] | None = None) -> dict[str, float]:
    """The arguments a preview passes, as a script would write them: ``at=0`` and what differs.

    Values equal to the file's default are left out, as if the script did not
    give them: procedures treat given arguments as overriding the defaults
    (``periodic`` would otherwise see HeadNod's ``period=500`` and
    ``frequency=1`` as a contradiction). Mandatory arguments other than ``at``
    start at 0.

    >>> from engine.commands import load_library
    >>> command_arguments(load_library()["HeadNod"], {"count": 2, "period": 500})
    {'count': 2.0, 'at': 0.0}
    """
    args: dict[str, float] = {}
    defaults = definition.arguments()
    for name, value in (values or {}).items():
        if name in defaults and value != defaults[name]:
            args[name] = float(value)
    for name in definition.mandatory:
        args.setdefault(name, 0.0)
    args[START] = 0.0
    return args
