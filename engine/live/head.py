"""The headless animator: the head's parameter values on the frame clock, and the events each frame brings.

Values are the **base** values (the model's defaults, changed by ``set``) plus what every running
performance (an utterance, a command) adds at that moment, clamped to each parameter's range —
the one rule of :mod:`engine.timeline.rule`, which :class:`engine.timeline.timeline.Timeline` samples too,
with ``set`` moving the base.
Everything is placed on the frame clock: :meth:`LiveHead.advance` is called with each frame's
time and returns the events that take effect in that frame, stamped with it.

``owner`` is whatever the caller uses to route events (the server: a connection); the head
only keeps it.

>>> from engine import load_model
>>> head = LiveHead(load_model())
>>> head.add_set(50.0, "s1", None, {"jaw_open": 0.5})
>>> head.advance(33.3)
[]
>>> head.values["jaw_open"]
0.0
>>> [event["event"] for _, event in head.advance(50.0)], head.values["jaw_open"]
(['applied'], 0.5)
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from engine.commands.command_files import Activation
from engine.live.protocol import RequestId
from engine.model.model import Model
from engine.speech.say import Speech
from engine.timeline.rule import AnimationRule, Placed

Event = dict[str, Any]


@dataclass
class Performance:
    """Activations placed at ``start_t`` on the frame clock, and its events (offsets in ms from the start)."""

    request_id: RequestId
    owner: object
    kind: str
    start_t: float
    activations: list[Activation]
    columns: list[int]
    end_offset: float
    events: list[tuple[float, Event]]
    """Offset from the start (ms) and the event's own fields, in time order; ``finished`` is added at the end."""
    next_event: int = 0
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def end_t(self) -> float:
        return self.start_t + self.end_offset


@dataclass
class PendingSet:
    at: float
    request_id: RequestId
    owner: object
    values: dict[str, float]


class LiveHead:
    """Parameter values and performances of one head, advanced frame by frame."""

    def __init__(self, model: Model):
        self.model = model
        self.rule = AnimationRule(model)
        self.names: list[str] = self.rule.names
        self._column = self.rule.column
        self.ranges = {name: (float(lo), float(hi))
                       for name, lo, hi in zip(self.names, self.rule.minimum, self.rule.maximum, strict=True)}
        self._base = self.rule.default.copy()
        self._current = self._base.copy()
        self.performances: list[Performance] = []
        self.pending_sets: list[PendingSet] = []
        self.t = 0.0
        """The time of the last frame advanced to (ms on the frame clock)."""

    @property
    def values(self) -> dict[str, float]:
        """Every parameter's value in the last frame."""
        return dict(zip(self.names, self._current.tolist(), strict=True))

    @property
    def current(self) -> np.ndarray:
        """Every parameter's value in the last frame, in the model's tree order (a copy)."""
        return self._current.copy()

    def playing(self) -> list[dict[str, Any]]:
        """What is running or waiting to start: id, kind, start and end on the frame clock."""
        return [{"id": p.request_id, "kind": p.kind, "start_t": p.start_t, "end_t": p.end_t}
                for p in self.performances]

    # -- scheduling ----------------------------------------------------------------------

    def add_set(self, at: float, request_id: RequestId, owner: object, values: dict[str, float]) -> None:
        """New base values from the first frame at or after ``at`` (names and ranges checked by the caller)."""
        bisect.insort_right(self.pending_sets, PendingSet(at, request_id, owner, dict(values)), key=lambda s: s.at)

    def add_speech(self, start_t: float, request_id: RequestId, owner: object, speech: Speech) -> Performance:
        """An utterance whose audio sample 0 is at ``start_t``: its timeline plus speech_start, word, phone events."""
        utterance = speech.utterance
        rate = utterance.sample_rate

        def sample(ms: float) -> int:
            return round(ms * rate / 1000.0)

        events: list[tuple[float, Event]] = [(0.0, {"event": "speech_start", "sample": 0, "sample_rate": rate,
                                                    "duration_ms": speech.duration_ms, "voice": utterance.voice})]
        timed: list[tuple[float, int, Event]] = []
        for index, word in enumerate(utterance.words):
            timed.append((word.start_ms, 0, {"event": "word", "word": word.label, "index": index,
                                             "onset_ms": word.start_ms, "sample": sample(word.start_ms)}))
        timed.extend((phone.start_ms, 1, {"event": "phone", "phone": phone.label, "word": phone.word,
                                          "onset_ms": phone.start_ms, "sample": sample(phone.start_ms)})
                     for phone in utterance.phones)
        timed.extend((offset, 2, event) for offset, event in command_events(speech.timeline.activations))
        timed.sort(key=lambda item: (item[0], item[1]))
        events += [(offset, event) for offset, _, event in timed]
        end = speech.end_ms
        finished = {"event": "finished", "sample": sample(speech.duration_ms), "sample_rate": rate}
        return self._add(Performance(request_id, owner, "say", start_t, speech.timeline.activations,
                                     self._columns(speech.timeline.activations), end, events,
                                     extra={"finished": finished}))

    def add_commands(self, start_t: float, request_id: RequestId, owner: object,
                     activations: list[Activation]) -> Performance:
        """Translated commands placed at ``start_t``: command_start/apex/end for each command, then finished."""
        end = max((a.end for a in activations), default=0.0)
        return self._add(Performance(request_id, owner, "command", start_t, list(activations),
                                     self._columns(activations), max(end, 0.0), command_events(activations),
                                     extra={"finished": {"event": "finished"}}))

    def stop(self, target: RequestId = None, owner: object = None,
             every_owner: bool = True) -> list[tuple[object, Event]]:
        """End performances and pending sets now: those of request ``target`` (all when ``None``), of ``owner``
        only unless ``every_owner``. Each ended performance gets ``finished`` with ``"stopped": true``."""
        def chosen(item_id: RequestId, item_owner: object) -> bool:
            return ((target is None or item_id == target)
                    and (every_owner or item_owner is owner))

        out: list[tuple[object, Event]] = []
        kept: list[Performance] = []
        for performance in self.performances:
            if chosen(performance.request_id, performance.owner):
                event = {**performance.extra["finished"], "id": performance.request_id, "t": self.t, "stopped": True}
                out.append((performance.owner, event))
            else:
                kept.append(performance)
        self.performances = kept
        self.pending_sets = [s for s in self.pending_sets if not chosen(s.request_id, s.owner)]
        return out

    def forget(self, owner: object) -> list[tuple[object, Event]]:
        """Drop everything ``owner`` started (a client gone): its performances end (their ``finished`` events
        are returned), its sets do not happen."""
        return self.stop(owner=owner, every_owner=False)

    # -- frames --------------------------------------------------------------------------

    def advance(self, t: float) -> list[tuple[object, Event]]:
        """Move to the frame at ``t`` (ms): apply due sets, compute the values, return the frame's events."""
        self.t = float(t)
        out: list[tuple[object, Event]] = []
        while self.pending_sets and self.pending_sets[0].at <= t:
            pending = self.pending_sets.pop(0)
            for name, value in pending.values.items():
                self._base[self._column[name]] = value
            out.append((pending.owner, {"event": "applied", "id": pending.request_id, "t": self.t}))
        placed: list[Placed] = []
        running: list[Performance] = []
        for performance in self.performances:
            local = t - performance.start_t
            if local < 0:
                running.append(performance)
                continue
            placed.append((performance.activations, performance.columns, performance.start_t))
            while (performance.next_event < len(performance.events)
                   and performance.events[performance.next_event][0] <= local):
                offset, fields = performance.events[performance.next_event]
                performance.next_event += 1
                out.append((performance.owner, {**fields, "id": performance.request_id, "t": self.t,
                                                # t − start_t ≥ offset does not make start_t + offset ≤ t in floats
                                                "onset_t": min(performance.start_t + offset, self.t)}))
            if local >= performance.end_offset:
                out.append((performance.owner, {**performance.extra["finished"], "id": performance.request_id,
                                                "t": self.t, "onset_t": min(performance.end_t, self.t)}))
            else:
                running.append(performance)
        self.performances = running
        self._current = self.rule.values(np.array([float(t)]), placed, self._base)[0]
        return out

    def _add(self, performance: Performance) -> Performance:
        self.performances.append(performance)
        return performance

    def _columns(self, activations: list[Activation]) -> list[int]:
        return self.rule.columns(activations)


def command_events(activations: list[Activation]) -> list[tuple[float, Event]]:
    """command_start, command_apex and command_end of every high-level command among ``activations``
    (offsets in ms), in time order. A command is a run of consecutive activations with the same command
    name and source (the translator emits each command's together); the articulation of speech is not
    a command. The apex is the first key where one of its activations is farthest from zero.

    >>> import numpy as np
    >>> nod = [Activation("head_nod", np.array([0, 100, 300]), np.array([0, 0.2, 0]), command="HeadNod",
    ...                   source="<command>:1")]
    >>> [(t, e["event"]) for t, e in command_events(nod)]
    [(0.0, 'command_start'), (100.0, 'command_apex'), (300.0, 'command_end')]
    """
    runs: list[list[Activation]] = []
    for activation in activations:
        if activation.command in (None, "speech"):
            continue
        if runs and (runs[-1][0].command, runs[-1][0].source) == (activation.command, activation.source):
            runs[-1].append(activation)
        else:
            runs.append([activation])
    events: list[tuple[float, Event]] = []
    for index, run in enumerate(runs):
        fields = {"command": run[0].command, "source": run[0].source or "", "index": index}
        peak, apex = -1.0, run[0].start
        for activation in run:
            k = int(np.argmax(np.abs(activation.values)))
            size = float(abs(activation.values[k]))
            if size > peak or (size == peak and activation.times[k] < apex):
                peak, apex = size, float(activation.times[k])
        events += [(min(a.start for a in run), {"event": "command_start", **fields}),
                   (apex, {"event": "command_apex", **fields}),
                   (max(a.end for a in run), {"event": "command_end", **fields})]
    order = {"command_start": 0, "command_apex": 1, "command_end": 2}
    events.sort(key=lambda item: (item[0], order[item[1]["event"]]))
    return events
