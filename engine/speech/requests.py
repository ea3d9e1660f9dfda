"""One Say as a self-contained job: text → :class:`engine.speech.say.Speech` + a WAV file, and where errors point.

A front end that speaks off its main thread (the workbench's script panel)
copies everything the job needs into a :class:`SayRequest` when Say is
pressed, so typing on while Festival runs changes nothing; :func:`run_say`
does the work anywhere; :func:`error_location` finds where in the typed text
an error points, :func:`described_error` words it for a dialog.

>>> request = SayRequest("Hyvää <Happy/> huomenta!", model, voice="suo_fi_lj_diphone")   # doctest: +SKIP
>>> result = run_say(request, folder)                                                   # doctest: +SKIP
>>> result.speech.utterance.phones[1].label, result.wav                                 # doctest: +SKIP
('h', PosixPath('…/say-1.wav'))
"""

from __future__ import annotations

import copy
import itertools
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from engine.errors import UserError
from engine.model.model import Model

if TYPE_CHECKING:
    from engine.speech.say import Speech
    from engine.speech.synthesis import Synthesizer

#: The name the text goes by in error messages: ``text:2: column 7: …``.
TEXT_NAME = "text"
_counter = itertools.count(1)


@dataclass
class SayRequest:
    """Everything one Say needs: the text (with inline commands), the model and the speech settings."""

    text: str
    model: Model
    voice: str | None = None
    coarticulation: str = "cohen-massaro"
    prosody_seed: int | None = None        # None: no visual prosody; a seed: blinks, brows, nods
    synthesizer: Synthesizer | None = None  # None: a FestivalSynthesizer
    audio: Path | None = None               # a recorded voice (WAV) instead of synthesis …
    labels: Path | None = None              # … with its phone labels; the text then holds inline commands
    table: Path | None = None               # a phone table file (.phones) instead of the shipped one


@dataclass
class SayResult:
    """What :func:`run_say` made: the speech and the WAV file holding its audio."""

    request: SayRequest
    speech: Speech
    wav: Path

    @property
    def duration(self) -> float:
        """Seconds of audio."""
        return self.speech.duration_ms / 1000.0


def run_say(request: SayRequest, folder: str | Path, cancelled: Callable[[], bool] | None = None) -> SayResult:
    """Synthesize and articulate ``request``; the audio is written to a new WAV (``say-N.wav``) in ``folder``.

    Errors in the text are :class:`~engine.errors.UserError` s naming
    :data:`TEXT_NAME`, its line and (in the message) the column. ``cancelled``
    is polled while Festival runs (when the request brings no synthesizer of
    its own): once it is true, Festival is stopped and
    :class:`~engine.speech.festival.SynthesisCancelled` raised.
    """
    # Imported here: the speech pipeline loads Festival's helpers and the command library's
    # parser, which a front end should not pay for before the first Say.
    from engine.speech.festival import FestivalSynthesizer
    from engine.speech.say import speak
    from engine.speech.synthesis import write_wav

    synthesizer = request.synthesizer
    if synthesizer is None:
        synthesizer = FestivalSynthesizer(cancelled=cancelled)
    elif cancelled is not None and isinstance(synthesizer, FestivalSynthesizer):
        synthesizer = copy.copy(synthesizer)
        synthesizer.cancelled = cancelled
    table = None
    if request.table is not None:
        from engine.speech.articulation import load_articulation

        table = load_articulation(request.table)
    if request.audio is not None:
        from engine.speech.recorded import speak_recording

        if request.labels is None:
            raise UserError("a recorded voice needs its phone labels", file=request.audio)
        speech = speak_recording(request.audio, request.labels, request.model, text=request.text.strip() or None,
                                 table=table, coarticulation=request.coarticulation, prosody_seed=request.prosody_seed,
                                 name=TEXT_NAME)
    else:
        speech = speak(request.text, request.model, synthesizer=synthesizer, voice=request.voice, table=table,
                       coarticulation=request.coarticulation, prosody_seed=request.prosody_seed, name=TEXT_NAME)
    wav = Path(folder) / f"say-{next(_counter)}.wav"           # a copy: the front end may delete it later
    write_wav(wav, speech.utterance)
    return SayResult(request, speech, wav)


def error_location(error: BaseException) -> tuple[int, int] | None:
    """(line, column), both from 1, of what ``error`` complains about in the typed text; ``None`` if unknown.

    The engine names the text's line and, in the message, the column
    (``column 7``) in the text as typed, commands included.

    >>> from engine.errors import CommandError
    >>> error_location(CommandError("column 5: unknown command <Hapy>", file="text", line=2))
    (2, 5)
    """
    line = getattr(error, "line", None)
    if not isinstance(line, int) or getattr(error, "file", None) != TEXT_NAME:
        return None
    column = re.search(r"\bcolumn (\d+)", getattr(error, "message", str(error)))
    return line, int(column.group(1)) if column else 1


def described_error(error: BaseException) -> str:
    """The message for a dialog: the engine's own line, with line and column added when it lacks the column.

    >>> from engine.errors import CommandError
    >>> described_error(CommandError("there is no text to speak", file="text", line=3))
    'text:3: there is no text to speak (line 3, column 1)'
    """
    message = str(error)
    where = error_location(error)
    if where is not None and not re.search(r"\bcolumn \d+", message):
        message += f" (line {where[0]}, column {where[1]})"
    return message
