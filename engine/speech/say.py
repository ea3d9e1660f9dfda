"""The whole speech pipeline: text with inline commands → audio, phones, one timeline.

    text ─► user command interpreter (engine.script.inline_commands) ─► synthesizer (Festival, §2.1)
         ─► articulation with coarticulation ─┐
         ─► inline commands, anchored to words ├─► translator (§2.3) ─► timeline ─► video, tables
         ─► visual prosody (optional) ─────────┘

>>> from engine import load_model
>>> from engine.speech.say import speak
>>> speech = speak('Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä kuuluu?', load_model())  # doctest: +SKIP
>>> speech.timeline.values_at(500)["jaw_open"]                                                   # doctest: +SKIP
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np

from engine.commands import Library, load_library, translate
from engine.commands.command_files import Activation
from engine.errors import CommandError
from engine.model.model import Model
from engine.script.inline_commands import Script, anchored_commands, parse_script
from engine.speech.articulation import ArticulationTable, table_for
from engine.speech.coarticulation import articulate
from engine.speech.festival import prepare_text
from engine.speech.prosody import prosody_commands
from engine.speech.reading_checks import ReadingWarning, reading_warnings
from engine.speech.synthesis import Synthesizer, Utterance
from engine.timeline.timeline import Timeline


@dataclass
class Speech:
    """Everything one utterance produced."""

    script: Script
    utterance: Utterance
    activations: list[Activation]
    timeline: Timeline
    reading_warnings: list[ReadingWarning] = field(default_factory=list)
    """Tokens Festival reads oddly: numbers, dates, abbreviations
    (:func:`~engine.speech.reading_checks.reading_warnings`)."""

    @property
    def warnings(self) -> list[str]:
        """The reading warnings as lines ``NAME:LINE: column C: 'token': advice``."""
        return [warning.located(self.script.name) for warning in self.reading_warnings]

    @property
    def duration_ms(self) -> float:
        """Length of the audio, ms."""
        return float(self.utterance.duration_ms)

    @property
    def end_ms(self) -> float:
        """Where the performance ends: the audio's end, or the last key of any command when that is later
        (an expression still fading out after the last word). Keys less than a millisecond past the
        audio (Festival's phone labels end up to a sample after its waveform) do not count."""
        last_key = float(self.timeline.end)
        return last_key if last_key > self.duration_ms + 1.0 else self.duration_ms

    def frame_times(self, fps: float) -> np.ndarray:
        """Frame n at n·1000/fps ms, covering the audio and every command (the last frame starts before
        :attr:`end_ms`). A video pads the audio with silence to its length."""
        count = max(1, math.ceil(self.end_ms * fps / 1000.0 - 1e-9))
        return np.arange(count) * (1000.0 / fps)


def speak(text: str, model: Model, synthesizer: Synthesizer | None = None, voice: str | None = None,
          library: Library | None = None, table: ArticulationTable | None = None,
          coarticulation: str = "cohen-massaro", prosody_seed: int | None = None, name: str = "<text>",
          table_of: Callable[[Utterance], ArticulationTable] | None = None) -> Speech:
    """Synthesize ``text`` (with inline commands) and build the timeline that animates it.

    ``synthesizer`` defaults to Festival (:class:`engine.speech.festival.FestivalSynthesizer`),
    ``library`` to the shipped command library, ``table`` to the shipped
    articulation table of the voice's phone set (Finnish, English), any phone
    without a row getting one derived from its phone features, or ``table_of(utterance)`` when the table
depends on what was synthesized (a viseme continuum's blended row), so the animation is built once;
``name`` is what errors call the text. The files an
    utterance becomes (video, audio, tables) are written by
    :func:`engine.outputs.speech_files.write_speech_files`.
    """
    script = parse_script(text, name)
    if not script.text.strip():
        raise CommandError("there is no text to speak (only commands?)", file=name)
    # A character Festival cannot read, named by file, line and column in the text as written
    # (the synthesizer only sees the text with the commands taken out).
    prepare_text(text, name)
    library = load_library() if library is None else library
    if table is not None:
        table.check(model)
    check_commands(script, library, model)
    if synthesizer is None:
        from engine.speech.festival import FestivalSynthesizer

        synthesizer = FestivalSynthesizer()
    utterance = synthesizer.synthesize(script.text, voice)
    if table_of is not None:
        table = table_of(utterance)
    speech = animate(script, utterance, model, library, table, coarticulation, prosody_seed)
    speech.reading_warnings = reading_warnings(text, voice)
    return speech


def check_commands(script: Script, library: Library, model: Model) -> None:
    """Translate the script's inline commands once, at time 0, so their errors come before synthesis."""
    translate([replace(c.command, arguments={"at": 0.0, **c.command.arguments}) for c in script.commands],
              library, model)


def animate(script: Script, utterance: Utterance, model: Model, library: Library, table: ArticulationTable | None,
            coarticulation: str = "cohen-massaro", prosody_seed: int | None = None) -> Speech:
    """The timeline of an utterance (synthesized or recorded): articulation of its phones, the script's
    inline commands anchored to its words, visual prosody when ``prosody_seed`` is given."""
    table = table_for(utterance, table)      # the voice's phone set; rows it lacks come from phone features
    table.check(model)
    activations = articulate(utterance.phones, table, coarticulation)
    commands = anchored_commands(script, utterance.words)
    if prosody_seed is not None:
        commands += prosody_commands(utterance.words, utterance.phones, utterance.duration_ms, seed=prosody_seed)
    activations += translate(commands, library, model)
    return Speech(script, utterance, activations, Timeline(activations, model))
