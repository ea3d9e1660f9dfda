"""Open an animation file for the player: a command file (high or low level) or a tracks CSV.

* ``*.xml`` — a ``<commands>`` file is translated with the command library
  (the shipped one, then the user's library folders, as in the CLI's
  ``-L``); a ``<low-level-commands>`` file is read as it is. Either becomes
  an :class:`engine.timeline.Timeline` on the open model.
* ``*.csv`` — a tracks table (:mod:`.tracks_table`).

Every problem is a :class:`engine.errors.UserError` naming the file and line.

>>> animation = load_animation("nod.xml", window.document.model)    # doctest: +SKIP
>>> window.player.load(animation.timeline, title=animation.title)    # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from engine.commands import load_library, read_commands, translate
from engine.errors import UserError
from engine.timeline.timeline import Timeline

from ..playhead import DEFAULT_FPS
from .tracks_table import read_tracks_csv

FILE_FILTER = "Animations (*.xml *.csv);;Command files (*.xml);;Tracks tables (*.csv);;All files (*)"


@dataclass
class Animation:
    """What a file gave: something the player plays, a title, and what kind of file it was."""

    timeline: object
    title: str
    kind: str                   # "commands" | "tracks"
    path: Path
    fps: float = DEFAULT_FPS    # a tracks table's own frame rate (its row spacing)


def load_animation(path: str | Path, model, library_folders=()) -> Animation:
    """Read ``path`` for ``model`` (see the module docstring)."""
    path = Path(path)
    if not path.is_file():
        raise UserError("no such file", file=path)
    if path.suffix.lower() == ".csv":
        table = read_tracks_csv(path, model)
        return Animation(table, path.stem, "tracks", path, table.fps)
    commands = read_commands(path)
    library = load_library(library_folders)
    activations = translate(commands, library, model)
    if not activations:
        raise UserError("the file has no commands to play", file=path)
    return Animation(Timeline(activations, model), path.stem, "commands", path)
