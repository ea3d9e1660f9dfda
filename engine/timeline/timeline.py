"""The timeline: low-level activations → the value of every parameter at any time.

Several activations on one parameter **add**: a nod during a head turn moves
the head by both. The sum is taken on top of the parameter's default value
and then clamped to the parameter's range, so a command can never drive the
face outside what its model allows. An activation contributes nothing
before its first key and after its last (``docs/commands.md``).

Sampling is vectorised: each activation is evaluated only over the frames
inside its own span. The rule itself lives in :mod:`engine.timeline.rule`,
which the live head uses too.

>>> from engine import load_model
>>> from engine.commands import load_library, translate, parse_commands_text
>>> from engine.timeline.timeline import Timeline
>>> head = load_model()
>>> script = parse_commands_text('<commands><HeadNod at="1000" amplitude="60" count="2"/></commands>')
>>> timeline = Timeline(translate(script, load_library(), head), head)
>>> round(timeline.values_at(1166.5)["head_nod"], 6)
0.09
>>> times, values = timeline.sample_frames(fps=60)            # every parameter, 0 … 2000 ms
>>> values.shape == (121, len(head.parameters))
True
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from engine.commands.command_files import Activation
from engine.commands.limits import LimitProblem, frame_count
from engine.commands.translator import check_activation
from engine.errors import UserError
from engine.formats.atomic import atomic_write_text
from engine.model.model import Model
from engine.timeline.rule import AnimationRule
from engine.timeline.tracks import tracks_csv_text


class Timeline:
    """Every parameter of ``model`` over time, from a list of activations."""

    def __init__(self, activations: list[Activation], model: Model):
        for activation in activations:
            check_activation(activation, model)
        self.model = model
        self.activations = list(activations)
        self.parameters: list[str] = model.parameters.names
        self.rule = AnimationRule(model)
        self._column = self.rule.columns(self.activations)

    @property
    def start(self) -> float:
        """Time of the earliest key (0 when there are none)."""
        return min((a.start for a in self.activations), default=0.0)

    @property
    def end(self) -> float:
        """Time of the last key (0 when there are none)."""
        return max((a.end for a in self.activations), default=0.0)

    def sample(self, times: ArrayLike) -> np.ndarray:
        """Values (len(times) × parameters, in ``self.parameters`` order) at the given times (ms)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        return self.rule.values(times, [(self.activations, self._column, 0.0)])

    def values_at(self, time: float) -> dict[str, float]:
        """Every parameter's value at one time, as a dict ready for ``Model.deform``."""
        return dict(zip(self.parameters, self.sample([time])[0].tolist(), strict=True))

    def frame_times(self, fps: float, start: float = 0.0, end: float | None = None) -> np.ndarray:
        """Frame times ``start, start + 1000/fps, …`` up to and including ``end`` (default: the last key).

        At most :data:`engine.commands.limits.MAX_FRAMES` frames, ``fps`` at most
        :data:`~engine.commands.limits.MAX_FPS`, times within ±24 hours; beyond them a :class:`UserError`.
        """
        end = max(self.end, start) if end is None else end     # keys all before start: the start frame alone
        try:
            count = frame_count(start, end, fps)
        except LimitProblem as exc:
            raise UserError(str(exc)) from None
        return start + np.arange(count) * (1000.0 / fps)

    def sample_frames(self, fps: float = 60.0, start: float = 0.0,
                      end: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """``(times, values)`` at every frame from ``start`` to ``end``."""
        times = self.frame_times(fps, start, end)
        return times, self.sample(times)

    def tracks_csv(self, fps: float = 60.0, start: float = 0.0, end: float | None = None) -> str:
        """The tracks table: header ``time_ms,<parameter>,…``, one row per frame."""
        times, values = self.sample_frames(fps, start, end)
        return tracks_csv_text(self.parameters, times, values)

    def write_tracks(self, path: str | Path, fps: float = 60.0, start: float = 0.0,
                     end: float | None = None) -> None:
        """Write the tracks CSV (:meth:`tracks_csv`) to ``path`` atomically."""
        atomic_write_text(path, self.tracks_csv(fps, start, end))
