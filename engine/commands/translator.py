"""The command translator (§2.3): high-level commands → low-level activations.

For each high-level command the translator looks the command up in the
library, checks its arguments (mandatory ones present, optional ones
defaulted, unknown ones rejected, all numbers), lets the command's procedure
lay each line out in time, shifts it to ``at`` and scales every value by
``amplitude`` percent (and by the argument a line names with ``* arg``).
Low-level ``<activate>`` commands pass through unchanged.

The paper's worked example, to the digit:

>>> from engine import load_model
>>> from engine.commands import load_library, translate, parse_commands_text
>>> script = parse_commands_text('<commands><HeadNod at="1000" amplitude="60" count="2"/></commands>')
>>> [nod] = translate(script, load_library(), load_model())
>>> nod.parameter, list(zip(nod.times.tolist(), nod.values.tolist()))[:3]
('head_nod', [(1000.0, 0.0), (1166.5, 0.09), (1333.0, 0.0)])
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from engine.commands.command_files import Activation, HighLevelCommand
from engine.commands.library import Library, parameter_of_line
from engine.commands.library_format import AMPLITUDE, START, CommandDefinition
from engine.commands.limits import MAX_VALUE, LimitProblem, check_time
from engine.commands.procedures import ArgumentProblem, Arguments, expand
from engine.errors import CommandError

if TYPE_CHECKING:
    from engine.model.model import Model

SIGNIFICANT_DIGITS = 12
"""Translated times and values are rounded to this many significant digits, so that
``1000 + 333·0.5`` is exactly ``1166.5`` and ``0.15·60 %`` exactly ``0.09``."""


def translate(commands: Iterable[HighLevelCommand | Activation], library: Library, model: Model) -> list[Activation]:
    """Low-level activations for a list of high-level commands (and pass-through activations).

    ``model`` decides which parameter a library line drives and must have every
    parameter an activation names. Errors carry the file and line of the
    command (or of the library line) at fault.
    """
    out: list[Activation] = []
    for command in commands:
        if isinstance(command, Activation):
            check_activation(command, model)
            out.append(command)
        else:
            out.extend(translate_command(command, library, model))
    return out


def translate_command(command: HighLevelCommand, library: Library, model: Model) -> list[Activation]:
    """The activations one high-level command expands to."""
    if command.name not in library:
        raise command.error(f"unknown command <{command.name}>{_closest(command.name, library.names())}")
    definition = library[command.name]
    args = command_arguments(command, definition)
    parameters = [parameter_of_line(definition, curve, model) for curve in definition.curves]
    try:
        check_time(args[START], START)
        laid_out = expand(definition, args)
    except (ArgumentProblem, LimitProblem) as exc:
        raise command.error(f"<{command.name}>: {exc}") from None
    scale = args[AMPLITUDE] / 100.0
    source = f"{command.file}:{command.line}" if command.line is not None else command.file
    activations: list[Activation] = []
    for curve, parameter, (times, values) in zip(definition.curves, parameters, laid_out, strict=True):
        factor = scale * (args[curve.scale] if curve.scale else 1.0)
        with np.errstate(over="ignore", invalid="ignore"):
            shifted, scaled = times + args[START], values * factor
        _check_laid_out(command, curve.name, shifted, scaled)
        activations.append(Activation(parameter, _tidy(shifted), _tidy(scaled),
                                      definition.interpolation, command.name, curve.name, source))
    return activations


def _check_laid_out(command: HighLevelCommand, line: str, times: np.ndarray, values: np.ndarray) -> None:
    """Every key of one translated line lies on the timeline and has a finite value."""
    for t in (times.min(initial=0.0), times.max(initial=0.0)):
        try:
            check_time(float(t), f"line '{line}' reaches a key time; it")
        except LimitProblem as exc:
            raise command.error(f"<{command.name}>: {exc} (check at, count, period, duration)") from None
    if not np.all(np.abs(values) <= MAX_VALUE):          # NaN fails too
        raise command.error(f"<{command.name}>: line '{line}' reaches values beyond ±{MAX_VALUE:g} parameter "
                            "units (check amplitude and the arguments that scale it)")


def command_arguments(command: HighLevelCommand, definition: CommandDefinition) -> Arguments:
    """The command's arguments with defaults filled in; mandatory and unknown ones checked."""
    accepted = definition.arguments()
    for name in command.arguments:
        if name not in accepted:
            known = ", ".join(sorted(accepted))
            raise command.error(f"<{command.name}> has no argument '{name}'{_closest(name, accepted)} "
                                f"(it accepts: {known}; see {definition.file}:{definition.line})")
    values: dict[str, float] = {}
    for name, default in accepted.items():
        if name in command.arguments:
            values[name] = command.arguments[name]
        elif default is None:
            raise command.error(f"<{command.name}> needs the argument '{name}'")
        else:
            values[name] = default
    return Arguments(values, set(command.arguments), tuple(definition.optional))


def check_activation(activation: Activation, model: Model) -> None:
    """A low-level activation names a parameter of the model."""
    if activation.parameter not in model.parameters:
        raise CommandError(f"<activate> names parameter '{activation.parameter}', which the model "
                           f"'{model.name}' does not have{_closest(activation.parameter, model.parameters.names)}",
                           **activation.where())


def _tidy(x: np.ndarray) -> np.ndarray:
    return np.array([float(f"{v:.{SIGNIFICANT_DIGITS}g}") for v in np.asarray(x, dtype=float)]) + 0.0


def _closest(name: str, known: Iterable[str]) -> str:
    close = difflib.get_close_matches(name, list(known), n=1)
    return f" (did you mean '{close[0]}'?)" if close else ""

