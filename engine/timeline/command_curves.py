"""The curves a command draws: every parameter it activates, over time, as the head does it (§2.3).

:func:`command_curves` translates a library command exactly as a script
would (``at=0``, with the given arguments) and samples it on an
:class:`engine.timeline.Timeline`, so the curves are what the head does
(default value added, range clamped). The workbench's library editor plots
them as you type.

>>> import engine
>>> from engine.commands import load_library
>>> nod = command_curves(load_library()["HeadNod"], engine.load_model(), {"count": 2})
>>> nod.end, round(float(nod.curves["head_nod"][1].max()), 3)
(1000.0, 0.15)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from engine.commands.analysis import command_arguments
from engine.commands.command_files import Activation, HighLevelCommand
from engine.commands.library import Library
from engine.commands.library_format import CommandDefinition
from engine.commands.translator import translate_command
from engine.model.model import Model
from engine.timeline.timeline import Timeline

PLOT_SAMPLES = 400
"""Samples per curve between the first and the last key (the keys themselves are added)."""


@dataclass(frozen=True)
class CommandCurves:
    """The translated command: its activations, its timeline and each activated parameter's curve.

    ``curves`` maps parameter → ``(times_ms, values)``; values are the
    timeline's (parameter units, default added, clamped to the range).
    """

    activations: list[Activation]
    timeline: Timeline
    curves: dict[str, tuple[np.ndarray, np.ndarray]]

    @property
    def end(self) -> float:
        """Time of the command's last key (ms)."""
        return self.timeline.end


def command_curves(definition: CommandDefinition, model: Model, values: dict[str, float] | None = None,
                   samples: int = PLOT_SAMPLES) -> CommandCurves:
    """Translate ``definition`` at ``at=0`` with ``values`` on ``model`` and sample its curves.

    Raises :class:`~engine.errors.UserError` (a ``CommandError`` or
    ``LibraryError`` naming file and line) when the arguments do not define an
    action or the model lacks a parameter.
    """
    command = HighLevelCommand(definition.name, command_arguments(definition, values), file="<preview>")
    activations = translate_command(command, Library([definition]), model)
    timeline = Timeline(activations, model)
    start, end = timeline.start, timeline.end
    keys = np.concatenate([a.times for a in activations]) if activations else np.zeros(0)
    times = np.unique(np.concatenate([np.linspace(start, end, max(2, samples)), keys]))
    sampled = timeline.sample(times)
    column = {name: i for i, name in enumerate(timeline.parameters)}
    curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for activation in activations:
        if activation.parameter not in curves:
            curves[activation.parameter] = (times, sampled[:, column[activation.parameter]])
    return CommandCurves(activations, timeline, curves)
