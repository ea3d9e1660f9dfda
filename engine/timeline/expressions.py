"""The expressions a model can show: one entry per expression command and per action unit (§3.2).

The workbench's expression gallery lists these entries as thumbnails; a
script can preview any of them the same way.

* **Expressions** are the library's commands laid out by ``attack-hold-release``
  (onset, apex, offset: Happy, Sad, Surprise, …, and gestures such as
  HeadTurn) whose every line drives a parameter of the model.
* **Action units** are the model's parameters named ``AU…`` (35 on the default
  head, ``docs/default-head.md``); a model with none (a new or synthetic one)
  shows every parameter instead.

Each entry gives the pose of its thumbnail (the middle of the apex) and the
timeline a preview plays, scaled by an intensity in percent: an expression is
translated like ``<Happy at="0" amplitude="intensity"/>``; an action unit
rises to its full value (its maximum) and back with the same
onset/apex/offset shape.

>>> import engine
>>> from engine.commands import load_library
>>> head = engine.load_model()
>>> entries = gallery_entries(load_library(), head)
>>> [e.name for e in entries if e.kind == "expression"][:3]
['Neutral', 'Happy', 'Sad']
>>> happy = next(e for e in entries if e.name == "Happy")
>>> round(happy.timeline(head, 50).values_at(1000)["AU12_left"], 3)
0.5
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from engine.commands.command_files import Activation, HighLevelCommand
from engine.commands.library import Library
from engine.commands.library_format import AMPLITUDE, START
from engine.commands.translator import translate_command
from engine.errors import UserError
from engine.model.model import Model
from engine.model.parameters import Parameter
from engine.timeline.timeline import Timeline

EXPRESSION_PROCEDURE = "attack-hold-release"
AU_NAME = re.compile(r"^AU[0-9]+")
_AU_NUMBER = re.compile(r"^AU([0-9]{1,9})")      # ASCII, and few enough digits for int() to take
ORDER = ("Neutral", "Happy", "Sad", "Surprise", "Fear", "Anger", "Disgust", "Contempt", "HappySurprise")
"""The paper's six emotions (§4) and their kin first; other expression commands follow by name."""
AU_TIMING = {"onset": 300.0, "apex": 1000.0, "offset": 400.0}
"""ms: how an action unit's preview rises, holds and falls."""


@dataclass(frozen=True)
class GalleryEntry:
    """One thumbnail: ``kind`` is ``"expression"`` (a library command) or ``"action-unit"`` (a parameter)."""

    kind: str
    name: str
    description: str
    timing: tuple[float, float, float]
    """onset, apex, offset (ms)."""
    library: Library | None = None

    @property
    def apex_time(self) -> float:
        """The middle of the apex (ms): the pose of the thumbnail."""
        onset, apex, _ = self.timing
        return onset + apex / 2

    def timeline(self, model: Model, intensity: float = 100.0) -> Timeline:
        """The preview at ``intensity`` percent, starting at 0 ms."""
        if self.kind == "expression":
            if self.library is None:
                raise UserError(f"the expression '{self.name}' has no library to translate it with")
            command = HighLevelCommand(self.name, {START: 0.0, AMPLITUDE: float(intensity)}, file="<gallery>")
            return Timeline(translate_command(command, self.library, model), model)
        parameter = model.parameters[self.name]
        level = (full_value(parameter) - parameter.default) * intensity / 100.0
        onset, apex, offset = self.timing
        activation = Activation(self.name, np.array([0.0, onset, onset + apex, onset + apex + offset]),
                                np.array([0.0, level, level, 0.0]), "cosine", None, None, "<gallery>")
        return Timeline([activation], model)

    def pose(self, model: Model) -> dict[str, float]:
        """Every parameter's value in the middle of the apex, at full intensity."""
        return self.timeline(model).values_at(self.apex_time)


def full_value(parameter: Parameter) -> float:
    """An action unit's full activation: its maximum, or its minimum when that is further from the default."""
    up, down = parameter.maximum - parameter.default, parameter.default - parameter.minimum
    if not np.isfinite(up) and not np.isfinite(down):
        return parameter.default + 1.0
    return parameter.maximum if not np.isfinite(down) or (np.isfinite(up) and up >= down) else parameter.minimum


def gallery_entries(library: Library, model: Model) -> list[GalleryEntry]:
    """The expressions that fit ``model`` (:data:`ORDER`, then by name), then its action units (by number)."""
    entries: list[GalleryEntry] = []
    for name in sorted(library.names(), key=lambda n: (ORDER.index(n) if n in ORDER else len(ORDER), n)):
        definition = library[name]
        if definition.procedure != EXPRESSION_PROCEDURE:
            continue
        try:
            library.parameters_of(name, model)
        except UserError:
            continue                     # drives a parameter this model lacks
        args = definition.arguments()
        onset, apex, offset = (float(args.get(k) or 0.0) for k in ("onset", "apex", "offset"))
        entries.append(GalleryEntry("expression", name, definition.description or name, (onset, apex, offset),
                                    library))
    names = model.parameters.names
    units = sorted((n for n in names if AU_NAME.match(n)), key=_unit_order) or names
    timing = (AU_TIMING["onset"], AU_TIMING["apex"], AU_TIMING["offset"])
    for name in units:
        description = model.parameters[name].description or name
        entries.append(GalleryEntry("action-unit", name, description, timing))
    return entries


def _unit_order(name: str) -> tuple[int, str]:
    """``AU12_left`` → (12, name): action units by number, then by name."""
    match = _AU_NUMBER.match(name)
    return (int(match[1]) if match else 0), name
