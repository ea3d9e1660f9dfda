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
#: The name Festival's text check gives it (``engine.speech.festival.prepare_text``'s default).
SYNTHESIS_NAME = "<text>"
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


def error_location(error: Exception, text: str) -> tuple[int, int] | None:
    """(line, column), both from 1, of what ``error`` complains about in ``text``; ``None`` if unknown.

    The column comes from the message (``column 7``) or, for a command the
    library does not know, from where ``<Name`` stands on the error's line.

    >>> from engine.errors import CommandError
    >>> error_location(CommandError("unknown command <Hapy>", file="text", line=2), "Hei\\nmoi <Hapy/>")
    (2, 5)
    """
    line = getattr(error, "line", None)
    if not isinstance(line, int) or getattr(error, "file", None) not in (TEXT_NAME, SYNTHESIS_NAME):
        return None
    message = getattr(error, "message", str(error))
    character = re.search(r"has no character '(.)'", message)
    if character and character.group(1) in text:
        # Festival's check counts in the text with the commands taken out; find it in what was typed.
        before = text[:text.index(character.group(1))]
        return before.count("\n") + 1, len(before) - (before.rfind("\n") + 1) + 1
    column = re.search(r"\bcolumn (\d+)", message)
    if column:
        return line, int(column.group(1))
    lines = text.split("\n")
    tag = re.search(r"<([A-Za-z_][\w.\-]*)", message)
    if tag and 0 < line <= len(lines):
        found = re.search(r"<\s*" + re.escape(tag.group(1)) + r"\b", lines[line - 1])
        if found:
            return line, found.start() + 1
    return line, 1


def described_error(error: Exception, text: str) -> str:
    """The message for the dialog: the engine's own line, with the column added when it lacks one."""
    message = str(error)
    if message.startswith(SYNTHESIS_NAME + ":"):
        message = TEXT_NAME + message[len(SYNTHESIS_NAME):]
    where = error_location(error, text)
    if where is not None and not re.search(r"\bcolumn \d+", message):
        message += f" (line {where[0]}, column {where[1]})"
    return message
