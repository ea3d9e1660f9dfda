"""Frames shown on a display (``serve --window``): what the server hands a presenter, and the stamps it gets back.

Headless, an event is delivered in the frame it takes effect in and stamped
``presented_t = t``. With a :class:`Presenter` (a window), the server hands
each frame's pose to it and keeps the frame's events back until the
presenter says the frame — or a later one, when it skipped frames to keep
up — is on the screen: then they leave stamped with ``presented_t``, the
moment the swap of the frame showing them finished, in ms on the frame
clock. A ``speech_start`` whose audio the presenter started also gets
``audio_t``: when its first sample reaches the sound device's output (the
stream's start plus the latency PortAudio reports), or ``None`` when the
computer has no sound output and the utterance is shown silent.

>>> stamps = PresentationStamps()
>>> stamps.hold(3, [("a", {"event": "applied", "id": 1, "t": 50.0})])
>>> stamps.hold(4, [("a", {"event": "word", "id": 2, "t": 66.7})])
>>> stamps.presented(4, 70.2, {})        # frame 3 was skipped: its event shows first in frame 4
[('a', {'event': 'applied', 'id': 1, 't': 50.0, 'presented_t': 70.2}), ('a', {'event': 'word', 'id': 2, 't': 66.7, \
'presented_t': 70.2})]
"""

from __future__ import annotations

from collections import deque
from collections.abc import Hashable, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from engine.model.model import Model

Event = dict[str, Any]
SoundKey = tuple[int, Hashable]
"""Which utterance a sound is: the owner's ``id()`` and the request's id (ids are the clients' own)."""


@dataclass(frozen=True)
class Sound:
    """An utterance's waveform, its first sample due at ``start_t`` (ms on the frame clock)."""

    key: SoundKey
    samples: np.ndarray
    sample_rate: int
    start_t: float


class Presenter(Protocol):
    """A display the server's frames go to. Its methods are called on the server's thread and must not block;
    the presenter answers by calling ``presented(frame, presented_t, audio)`` of the server from any thread."""

    fps: float
    """The display's refresh rate: the frame clock runs at it."""

    def show(self, frame: int, t: float, model: Model, values: np.ndarray) -> None:
        """Show frame ``frame`` (time ``t``): ``model`` posed by ``values`` (its parameters in tree order)."""

    def play(self, sound: Sound) -> None:
        """Play ``sound`` from its ``start_t`` (from the right sample if the frame showing it is later)."""

    def silence(self, key: SoundKey) -> None:
        """Stop the sound ``key`` now, if it is playing or waiting."""

    def close(self) -> None:
        """The server is ending."""


class PresentationStamps:
    """Events held back per frame until a presenter says which frame is on the screen."""

    def __init__(self) -> None:
        self._held: deque[tuple[int, list[tuple[object, Event]]]] = deque()

    def hold(self, frame: int, events: list[tuple[object, Event]]) -> None:
        if events:
            self._held.append((frame, events))

    def presented(self, frame: int, presented_t: float,
                  audio: Mapping[SoundKey, float | None]) -> list[tuple[object, Event]]:
        """The events of every held frame up to ``frame``, stamped ``presented_t`` (and ``audio_t`` on the
        ``speech_start`` of each sound in ``audio``, started in this frame)."""
        out: list[tuple[object, Event]] = []
        while self._held and self._held[0][0] <= frame:
            for owner, event in self._held.popleft()[1]:
                stamped = {**event, "presented_t": presented_t}
                key = (id(owner), event.get("id"))
                if event.get("event") == "speech_start" and key in audio:
                    stamped["audio_t"] = audio[key]
                out.append((owner, stamped))
        return out

    def __len__(self) -> int:
        return sum(len(events) for _, events in self._held)


def stopped_sounds(events: list[tuple[object, Event]]) -> list[SoundKey]:
    """The utterances among ``events`` that a ``stop`` (or a client leaving, or a ``load``) ended."""
    return [(id(owner), event.get("id")) for owner, event in events
            if event.get("event") == "finished" and event.get("stopped") and "sample_rate" in event]
