"""A label with its time span: a word or a phone as the synthesizer or a label file timed it.

:class:`engine.speech.synthesis.Segment` is one; so is anything else with
``label``, ``start_ms`` and ``end_ms`` (ms). Inline commands are anchored to
timed words (:mod:`engine.script.inline_commands`), motion-capture frames are
selected by timed phones (:mod:`engine.mocap.frame_selection`).

>>> from collections import namedtuple
>>> Word = namedtuple("Word", "label start_ms end_ms")
>>> isinstance(Word("hyvää", 30.0, 410.0), TimedLabel)
True
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable


@runtime_checkable
class TimedLabel(Protocol):
    """A ``label`` from ``start_ms`` to ``end_ms`` (ms)."""

    @property
    def label(self) -> str: ...
    @property
    def start_ms(self) -> float: ...
    @property
    def end_ms(self) -> float: ...
