"""One Say, done off the GUI thread: text → :class:`engine.speech.say.Speech` + a WAV file.

No Qt here: :class:`SayRequest` holds everything the worker needs (copied
from the panel when Say is pressed, so typing on while Festival runs changes
nothing), :func:`run_say` does the work, :func:`error_location` finds where
in the text an error points.

>>> request = SayRequest("Hyvää <Happy/> huomenta!", model, voice="suo_fi_lj_diphone")   # doctest: +SKIP
>>> result = run_say(request, folder)                                                   # doctest: +SKIP
>>> result.speech.utterance.phones[1].label, result.wav                                 # doctest: +SKIP
('h', PosixPath('…/say-1.wav'))
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass
from pathlib import Path

#: The name the text goes by in error messages: ``text:2: column 7: …``.
TEXT_NAME = "text"
COARTICULATIONS = (("Cohen–Massaro", "cohen-massaro"), ("none (target interpolation)", "none"))
_counter = itertools.count(1)


@dataclass
class SayRequest:
    text: str
    model: object
    voice: str | None = None
    coarticulation: str = "cohen-massaro"
    prosody_seed: int | None = None        # None: no visual prosody; a seed: blinks, brows, nods
    synthesizer: object | None = None      # None: a FestivalSynthesizer


@dataclass
class SayResult:
    request: SayRequest
    speech: object                         # engine.speech.say.Speech
    wav: Path

    @property
    def duration(self) -> float:
        """Seconds of audio."""
        return self.speech.duration_ms / 1000.0


def run_say(request: SayRequest, folder: Path) -> SayResult:
    """Synthesize and articulate ``request``; the audio is written to a new WAV in ``folder``."""
    from engine.speech.say import speak
    from engine.speech.synthesis import write_wav

    speech = speak(request.text, request.model, synthesizer=request.synthesizer, voice=request.voice,
                   coarticulation=request.coarticulation, prosody_seed=request.prosody_seed, name=TEXT_NAME)
    wav = Path(folder) / f"say-{next(_counter)}.wav"
    write_wav(wav, speech.utterance)
    return SayResult(request, speech, wav)


def error_location(error: Exception) -> tuple[int, int] | None:
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


def described_error(error: Exception) -> str:
    """The message for the dialog: the engine's own line, with the column added when it lacks one."""
    message = str(error)
    where = error_location(error)
    if where is not None and not re.search(r"\bcolumn \d+", message):
        message += f" (line {where[0]}, column {where[1]})"
    return message
