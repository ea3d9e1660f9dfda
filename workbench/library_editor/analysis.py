"""What the library editor knows about the text being edited, with no Qt.

Two questions, both answered by the engine (``engine.commands``) so the
editor and the command line never disagree:

* :func:`check_library_text` — is the text a valid §2.3 library file, and
  does every command fit the open model? Returns the problems with their
  line numbers (the engine's :class:`~engine.errors.LibraryError` carries the
  line).
* :func:`command_curves` — the time-value curve of every parameter a command
  activates, for given arguments: the command is translated exactly as a
  script would translate it (``at=0``) and sampled on an
  :class:`engine.timeline.Timeline`, so the curves are what the head does
  (default value added, range clamped).

>>> from engine.paths import LIBRARY_DIR
>>> text = (LIBRARY_DIR / "HeadNod.lib").read_text()
>>> check_library_text(text, "HeadNod.lib").problems
[]
>>> check_library_text("$command = X\\n$interp = wobbly\\nx = 0,0; 1,1\\n", "x.lib").problems[0].line
2
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from engine.commands import Library, parse_library_text
from engine.commands.command_files import HighLevelCommand
from engine.commands.library_format import START, CommandDefinition
from engine.commands.translator import translate_command
from engine.errors import UserError
from engine.timeline.timeline import Timeline

PLOT_SAMPLES = 400
"""Samples per curve between the first and the last key (the keys themselves are added)."""


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
        return not self.problems


def check_library_text(text: str, file: str = "<library>", model=None) -> CheckResult:
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


@dataclass(frozen=True)
class CommandCurves:
    """The translated command: its activations, its timeline and each activated parameter's curve.

    ``curves`` maps parameter → ``(times_ms, values)``; values are the
    timeline's (parameter units, default added, clamped to the range).
    """

    activations: list
    timeline: Timeline
    curves: dict[str, tuple[np.ndarray, np.ndarray]]

    @property
    def end(self) -> float:
        return self.timeline.end


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


def command_curves(definition: CommandDefinition, model, values: dict[str, float] | None = None,
                   samples: int = PLOT_SAMPLES) -> CommandCurves:
    """Translate ``definition`` at ``at=0`` with ``values`` on ``model`` and sample its curves.

    Raises :class:`~engine.errors.UserError` (a ``CommandError`` or
    ``LibraryError`` naming file and line) when the arguments do not define an
    action or the model lacks a parameter.

    >>> import engine
    >>> from engine.commands import load_library
    >>> nod = command_curves(load_library()["HeadNod"], engine.load_model(), {"count": 2})
    >>> nod.end, round(float(nod.curves["head_nod"][1].max()), 3)
    (1000.0, 0.15)
    """
    command = HighLevelCommand(definition.name, command_arguments(definition, values), file="<preview>")
    activations = translate_command(command, Library([definition]), model)
    timeline = Timeline(activations, model)
    start, end = timeline.start, timeline.end
    keys = np.concatenate([a.times for a in activations]) if activations else np.zeros(0)
    times = np.unique(np.concatenate([np.linspace(start, end, max(2, samples)), keys]))
    sampled = timeline.sample(times)
    column = {name: i for i, name in enumerate(timeline.parameters)}
    curves = {}
    for activation in activations:
        if activation.parameter not in curves:
            curves[activation.parameter] = (times, sampled[:, column[activation.parameter]])
    return CommandCurves(activations, timeline, curves)
