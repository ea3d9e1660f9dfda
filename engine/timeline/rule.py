"""The animation rule (§2.3), in one place: a parameter's value at a time is its **base** (the model's
default, or what the live service's ``set`` made it) plus what every activation covering that time adds,
clamped to the parameter's range. An activation adds nothing before its first key and after its last,
and adds its value at both.

:class:`~engine.timeline.timeline.Timeline` samples it over many frames; the live head
(:class:`~engine.live.head.LiveHead`) over one frame at a time, for performances started at different
moments. Both call :meth:`AnimationRule.values`, the rule whole (base, sum, clamp), so a sentence plays the
same offline and live; :meth:`~AnimationRule.add` and :meth:`~AnimationRule.clamp` are its two steps.

>>> import numpy as np
>>> from engine import load_model
>>> from engine.commands.command_files import Activation
>>> rule = AnimationRule(load_model())
>>> nod = [Activation("head_nod", np.array([0.0, 100.0, 200.0]), np.array([0.0, 0.2, 0.0]))]
>>> total = rule.base_rows(3)
>>> rule.add(total, nod, rule.columns(nod), np.array([50.0, 100.0, 300.0]))
>>> rule.clamp(total)[:, rule.column["head_nod"]].round(6).tolist()
[0.1, 0.2, 0.0]
>>> rule.values(np.array([50.0]), [(nod, rule.columns(nod), 0.0)])[:, rule.column["head_nod"]].round(6).tolist()
[0.1]
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from engine.commands.command_files import Activation
from engine.commands.interpolation import interpolate
from engine.model.model import Model

Placed = tuple[list[Activation], list[int], float]
"""Activations, their columns (:meth:`AnimationRule.columns`) and where their time 0 is (ms): a timeline's
activations at 0, a live performance's at its start on the frame clock."""


class AnimationRule:
    """The defaults and ranges of ``model``'s parameters (in tree order), and the rule that combines
    activations into values."""

    def __init__(self, model: Model):
        tree = model.parameters
        self.names: list[str] = tree.names
        self.column: dict[str, int] = {name: i for i, name in enumerate(self.names)}
        self.default = np.array([float(tree[n].default) for n in self.names])
        self.minimum = np.array([float(tree[n].minimum) for n in self.names])
        self.maximum = np.array([float(tree[n].maximum) for n in self.names])

    def columns(self, activations: list[Activation]) -> list[int]:
        """The column of each activation's parameter."""
        return [self.column[a.parameter] for a in activations]

    def base_rows(self, count: int, base: np.ndarray | None = None) -> np.ndarray:
        """``count`` rows of the base values (the defaults unless ``base`` is given), to add activations to."""
        return np.tile(self.default if base is None else base, (count, 1))

    @staticmethod
    def add(total: np.ndarray, activations: list[Activation], columns: list[int], times: np.ndarray) -> None:
        """Add into ``total`` (one row per time) what each activation contributes at ``times`` (ms, any order):
        each is evaluated only at the times inside its own span, first and last key included."""
        if not activations:
            return
        order = np.argsort(times, kind="stable")
        ordered = times[order]
        for activation, column in zip(activations, columns, strict=True):
            lo = np.searchsorted(ordered, activation.start, side="left")
            hi = np.searchsorted(ordered, activation.end, side="right")
            if hi > lo:
                rows = order[lo:hi]
                total[rows, column] += interpolate(activation.interpolation, activation.times, activation.values,
                                                   times[rows])

    def clamp(self, total: np.ndarray) -> np.ndarray:
        """``total`` clamped to every parameter's range (a new array)."""
        return np.clip(total, self.minimum, self.maximum)

    def values(self, times: np.ndarray, placed: Iterable[Placed], base: np.ndarray | None = None) -> np.ndarray:
        """The rule: every parameter's value (one row per time in ``times``, ms) — the base (the defaults
        unless ``base`` is given) plus what each of the ``placed`` activations adds at that time measured
        from its own start, clamped to the parameter's range."""
        total = self.base_rows(times.size, base)
        for activations, columns, start in placed:
            self.add(total, activations, columns, times - start if start else times)
        return self.clamp(total)
