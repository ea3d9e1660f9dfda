"""Open an animation file to play it: a command file (high or low level) or a tracks CSV.

* ``*.xml`` — a ``<commands>`` file is translated with the command library
  (the shipped one, then the user's library folders, as in the CLI's
  ``-L``); a ``<low-level-commands>`` file is read as it is. Either becomes
  an :class:`engine.timeline.Timeline` on the model.
* ``*.csv`` — a tracks table (:mod:`engine.timeline.tracks`), which plays at
  its own frame rate (the spacing of its rows).

Every problem is a :class:`engine.errors.UserError` naming the file and line.
The workbench's player plays what :func:`load_animation` returns.

>>> from engine import load_model
>>> load_animation("no-such-file.xml", load_model())
Traceback (most recent call last):
engine.errors.UserError: no-such-file.xml: no such file
>>> animation = load_animation("nod.xml", load_model())            # doctest: +SKIP
>>> animation.kind, animation.timeline.end                          # doctest: +SKIP
('commands', 2000.0)
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from engine.commands import load_library, read_commands, translate
from engine.errors import UserError
from engine.model.model import Model
from engine.timeline.timeline import Timeline
from engine.timeline.tracks import TracksTable, read_tracks_csv

DEFAULT_FPS = 60.0
"""Frames per second a command file is played at unless the caller says otherwise."""


@dataclass
class Animation:
    """What a file gave: something to play (``values_at(ms)``, ``sample``, ``start``/``end``), a title, its kind."""

    timeline: Timeline | TracksTable
    title: str
    kind: str                   # "commands" | "tracks"
    path: Path
    fps: float = DEFAULT_FPS    # a tracks table's own frame rate (its row spacing); the caller's for commands


def load_animation(path: str | Path, model: Model, library_folders: Iterable[str | Path] = (),
                   fps: float = DEFAULT_FPS) -> Animation:
    """Read ``path`` for ``model`` (see the module docstring); a command file plays at ``fps`` frames a second."""
    path = Path(path)
    if not path.is_file():
        raise UserError("no such file", file=path)
    if path.suffix.lower() == ".csv":
        table = read_tracks_csv(path, model)
        return Animation(table, path.stem, "tracks", path, table.fps)
    commands = read_commands(path)
    library = load_library(list(library_folders))
    activations = translate(commands, library, model)
    if not activations:
        raise UserError("the file has no commands to play", file=path)
    return Animation(Timeline(activations, model), path.stem, "commands", path, fps)
