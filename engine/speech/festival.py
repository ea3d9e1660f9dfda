"""Festival backend of the synthesizer interface (§2.1): Finnish Suopuhe voices by default.

Festival runs as a subprocess on a generated Scheme script
(:mod:`engine.speech.festival_script`) that selects the voice, cuts the text
into utterances as Festival's tts mode does, and for each saves the wave to a
temporary file and prints the Segment relation (name, end time and phone
features of every phone), the Word relation, and for each phone the word it
belongs to (through the SylStructure relation). Phone boundaries are
Festival's own, seconds → ms, to the microsecond Festival prints; the
utterances follow each other without a gap.

Festival reads ISO-8859-1 (Latin-1). The text is NFC-normalised; typographic
characters outside Latin-1 are transliterated (:data:`TRANSLITERATION`:
curly quotes, dashes, ellipsis, special spaces, š/ž, €); any other character
Latin-1 cannot carry is an error that names it. ``docs/speech-synthesis.md``
documents the choices and the phones the voices emit.

>>> from engine.speech.festival import prepare_text, scheme_string
>>> prepare_text("“Hyvää päivää” – sanoi hän…")
'"Hyvää päivää", sanoi hän...'
>>> print(scheme_string('say "hi" \\\\ bye'))
"say \\"hi\\" \\\\ bye"
>>> prepare_text("Hyvää 🙂")  # doctest: +NORMALIZE_WHITESPACE
Traceback (most recent call last):
...
engine.speech.synthesis.SynthesisError: <text>:1: Festival reads ISO-8859-1 (Latin-1), which has no character '🙂'
(U+1F642 SLIGHTLY SMILING FACE, column 7); leave it out or replace it
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import tempfile
import time
import unicodedata
from collections.abc import Callable
from pathlib import Path

import numpy as np

from engine.processes import with_parent_death_signal
from engine.programs import locate, missing_message, program_name
from engine.speech.festival_script import (
    VOICES_SCRIPT,
    WAVE_FILE_PATTERN,
    FestivalOutput,
    parse_output,
    parse_segments,
    parse_voices,
    scheme_string,
    synthesis_script,
)
from engine.speech.synthesis import SynthesisError, Utterance, decode_wav

__all__ = ["DEFAULT_VOICE", "FestivalSynthesizer", "parse_segments", "parse_voices", "prepare_text",
           "scheme_string", "synthesis_script"]

DEFAULT_VOICE = "suo_fi_lj_diphone"
"""Female Finnish voice (Suopuhe, Debian package ``festvox-suopuhe-lj``)."""

MALE_FINNISH_VOICE = "hy_fi_mv_diphone"
"""Male Finnish voice (Suopuhe, Debian package ``festvox-suopuhe-mv``)."""

VOICE_PACKAGES = {
    "suo_fi_lj_diphone": "festvox-suopuhe-lj",
    "hy_fi_mv_diphone": "festvox-suopuhe-mv",
    "kal_diphone": "festvox-kallpc16k",
    "ked_diphone": "festvox-kdlpc16k",
    "rab_diphone": "festvox-rablpc16k",
    "don_diphone": "festvox-don",
    "el_diphone": "festvox-ellpc11k",
}
"""The Debian package that installs each well-known Festival voice."""

FESTIVAL_PACKAGE = "festival"

TRANSLITERATION = {
    # quotes
    "\u2018": "'", "\u2019": "'", "\u201a": "'", "\u201b": "'", "\u2032": "'", "\u2039": "'", "\u203a": "'",
    "\u201c": '"', "\u201d": '"', "\u201e": '"', "\u201f": '"', "\u2033": '"',
    # dashes and minus
    "\u2010": "-", "\u2011": "-", "\u2012": "-", "\u2013": "-", "\u2014": "-", "\u2015": "-", "\u2212": "-",
    # ellipsis, bullet
    "\u2026": "...", "\u2022": "-",
    # spaces (no-break space is Latin-1 but Festival would not split words at it)
    "\u00a0": " ", "\u2000": " ", "\u2001": " ", "\u2002": " ", "\u2003": " ", "\u2004": " ",
    "\u2005": " ", "\u2006": " ", "\u2007": " ", "\u2008": " ", "\u2009": " ", "\u200a": " ",
    "\u202f": " ", "\u205f": " ", "\u3000": " ", "\u2028": "\n", "\u2029": "\n",
    # invisible: zero-width spaces and joiners, byte-order mark, soft hyphen
    "\u200b": "", "\u200c": "", "\u200d": "", "\u2060": "", "\ufeff": "", "\u00ad": "",
    # letters of Finnish loanwords (šakki, Žukov) that Latin-1 lacks: Suopuhe reads "sh" as its S
    "\u0161": "sh", "\u0160": "Sh", "\u017e": "zh", "\u017d": "Zh",
    # currency
    "\u20ac": " euroa",
}
"""Characters outside Latin-1 that are replaced before the text goes to Festival."""

_DASHES = "\u2013\u2014\u2015"
_STANDALONE_PUNCTUATION = [
    # a dialogue dash opening a line ("– Mitä kuuluu?") is not read at all
    (re.compile(f"(^|\\n)[ \\t]*[{_DASHES}][ \\t]+"), r"\1"),
    # a dash between spaces is a pause: a comma on the word before it
    (re.compile(f"[ \\t]+[{_DASHES}](?=\\s|$)"), ","),
    # an ellipsis after a space goes onto the word before it
    (re.compile("[ \\t]+\u2026"), "\u2026"),
]
"""Dashes and ellipses standing alone, rewritten before :data:`TRANSLITERATION` (see :func:`prepare_text`)."""

_VOICE_NAME = re.compile(r"[A-Za-z0-9_]+\Z")
_SCRIPT_FILE = "synthesize.scm"
_POLL_SECONDS = 0.1


# ---------------------------------------------------------------------------
# Text → Latin-1 Scheme string
# ---------------------------------------------------------------------------

def prepare_text(text: str, source: str = "<text>") -> str:
    """The text as Festival will get it: NFC, transliterated, Latin-1 only, no control characters.

    Raises :class:`SynthesisError` for empty text and for a character Latin-1
    cannot carry, naming the character, its code point and where it stands
    (``source``, line, column). Before the character-by-character
    :data:`TRANSLITERATION`, dashes and ellipses that stand alone become the
    punctuation Festival pauses at instead of words it spells out (a lone
    ``-`` is read "viiva", a lone ``...`` "piste"):

    >>> prepare_text("– Tule tänne – nyt heti … kiitos")
    'Tule tänne, nyt heti... kiitos'
    """
    if not isinstance(text, str):
        raise TypeError(f"text must be a str, not {type(text).__name__}")
    text = unicodedata.normalize("NFC", text).replace("\r\n", "\n").replace("\r", "\n")
    for line, content in enumerate(text.split("\n"), start=1):
        for column, char in enumerate(content, start=1):
            if ord(char) > 0xFF and char not in TRANSLITERATION:
                try:
                    name = unicodedata.name(char)
                except ValueError:
                    name = "unnamed character"
                raise SynthesisError(
                    f"Festival reads ISO-8859-1 (Latin-1), which has no character {char!r} "
                    f"(U+{ord(char):04X} {name}, column {column}); leave it out or replace it",
                    file=source, line=line)
    for pattern, replacement in _STANDALONE_PUNCTUATION:
        text = pattern.sub(replacement, text)
    out = []
    for original in text:
        char = TRANSLITERATION.get(original, original)
        if len(char) == 1 and unicodedata.category(char) == "Cc" and char not in "\n\t":
            char = " "  # other control characters (NUL, bell, C1 controls) become spaces
        out.append(char)
    prepared = "".join(out)
    if not prepared.strip():
        raise SynthesisError("nothing to say: the text is empty", file=source)
    return prepared


# ---------------------------------------------------------------------------
# The synthesizer
# ---------------------------------------------------------------------------

class FestivalSynthesizer:
    """Text → :class:`Utterance` with the Festival speech synthesizer.

    ``festival`` is the program (name on ``PATH`` or a path; default ``$AP_FESTIVAL``, else ``festival``
    on ``PATH``: :mod:`engine.programs`); ``timeout`` (s)
    bounds every Festival run — a run that takes longer is killed and
    reported, never waited for. ``cancelled``, when given, is asked every
    0.1 s while Festival runs; once it answers ``True`` Festival is killed and
    :class:`SynthesisCancelled` raised. Festival never outlives the process
    that started it, whatever ends that process (``kill -9`` included): it
    is started with the parent-death signal set (``setpriv --pdeathsig``).
    """

    default_voice = DEFAULT_VOICE

    def __init__(self, festival: str | None = None, timeout: float = 600,
                 cancelled: Callable[[], bool] | None = None):
        self.festival = str(festival) if festival is not None else program_name("festival")
        self.timeout = float(timeout)
        self.cancelled = cancelled
        self._voices: list[str] | None = None
        self.last_run_seconds: float | None = None
        """Wall-clock time of the last Festival run (for benchmarks)."""

    # -- public --------------------------------------------------------------

    def voices(self) -> list[str]:
        """Names of the installed Festival voices (``voice.list``), e.g. ``['suo_fi_lj_diphone', …]``."""
        if self._voices is None:
            stdout, _, _ = self._run(VOICES_SCRIPT)
            self._voices = parse_voices(stdout)
        return list(self._voices)

    def synthesize(self, text: str, voice: str | None = None) -> Utterance:
        """Speak ``text`` with ``voice`` (default :data:`DEFAULT_VOICE`), utterance by utterance."""
        voice = self.default_voice if voice is None else str(voice)
        if not _VOICE_NAME.match(voice):
            raise SynthesisError(f"{voice!r} is not a Festival voice name (letters, digits and _ only)")
        prepared = prepare_text(text)
        stdout, stderr, waves = self._run(synthesis_script(prepared, voice), want_waves=True)
        if "\nAP-NOVOICE" in stdout:
            self._voices = parse_voices(stdout)
            raise SynthesisError(missing_voice_message(voice, self._voices))
        if "AP-END" not in stdout.splitlines():
            raise SynthesisError(f"Festival failed to synthesize the text with voice {voice}"
                                 + _stderr_summary(stderr))
        parsed = parse_output(stdout)
        if not parsed.words:
            raise SynthesisError(f"nothing to say: Festival found no words in {text.strip()!r}")
        samples, rate = _joined_waves(parsed, waves, stderr)
        return Utterance(text=text, voice=voice, samples=samples, sample_rate=rate, phones=parsed.phones,
                         words=parsed.words, phoneset=parsed.phoneset, phone_features=parsed.features)

    # -- running Festival ------------------------------------------------------

    def executable(self) -> str:
        """The Festival program to run; :class:`SynthesisError` saying how to install it if there is none."""
        found = locate(self.festival)
        if found is None:
            raise SynthesisError(missing_message("festival", self.festival))
        return found

    def _run(self, script: str, want_waves: bool = False) -> tuple[str, str, dict[str, bytes]]:
        """Run Festival on ``script`` in a fresh temporary folder: (stdout, stderr, wave files by name)."""
        program = self.executable()
        with tempfile.TemporaryDirectory(prefix="artificial-person-festival-") as folder:
            Path(folder, _SCRIPT_FILE).write_bytes(script.encode("latin-1"))
            started = time.perf_counter()
            try:
                process = subprocess.Popen(
                    with_parent_death_signal([program, "--batch", _SCRIPT_FILE]), cwd=folder,
                    stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                    start_new_session=True)
            except OSError as exc:
                raise SynthesisError(f"cannot run Festival ({program}): {exc.strerror or exc}; "
                                     f"install the Debian package {FESTIVAL_PACKAGE}") from None
            try:
                out, err = self._wait(process)
            except BaseException:
                _kill_group(process)
                raise
            self.last_run_seconds = time.perf_counter() - started
            waves = ({path.name: path.read_bytes() for path in Path(folder).glob("*.wav")}
                     if want_waves else {})
        stdout, stderr = out.decode("latin-1"), err.decode("latin-1")
        if process.returncode != 0 and "AP-END" not in stdout.splitlines():
            raise SynthesisError(f"Festival ({program}) failed with exit status {process.returncode}"
                                 + _stderr_summary(stderr))
        return stdout, stderr, waves

    def _wait(self, process: subprocess.Popen) -> tuple[bytes, bytes]:
        """Festival's output once it ends; killed on timeout or when :attr:`cancelled`."""
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                return process.communicate(timeout=_POLL_SECONDS if self.cancelled else self.timeout)
            except subprocess.TimeoutExpired:
                if self.cancelled is not None and self.cancelled():
                    _kill_group(process)
                    raise SynthesisCancelled("speech synthesis was cancelled") from None
                if time.monotonic() >= deadline:
                    _kill_group(process)
                    raise SynthesisError(
                        f"Festival did not finish within {self.timeout:g} s and was stopped "
                        f"(a very long text? split it, or allow more time)") from None


class SynthesisCancelled(SynthesisError):
    """The synthesis was cancelled by whoever asked for it; Festival was stopped."""


def _joined_waves(parsed: FestivalOutput, waves: dict[str, bytes], stderr: str) -> tuple[np.ndarray, int]:
    """The utterances' waves one after the other, each cut (or padded) to end exactly where its phones end."""
    pieces: list[np.ndarray] = []
    rate = 0
    written = 0
    for number, end_ms in zip(parsed.utterance_numbers, parsed.utterance_ends_ms, strict=True):
        name = WAVE_FILE_PATTERN.format(number)
        if name not in waves:
            raise SynthesisError(f"Festival wrote no wave file for utterance {number}" + _stderr_summary(stderr))
        samples, this_rate = decode_wav(waves[name], f"Festival's wave {name}")
        if rate and this_rate != rate:
            raise SynthesisError(f"Festival's utterances have different sample rates ({rate}, {this_rate} Hz)")
        rate = this_rate
        wanted = round(end_ms * rate / 1000.0) - written     # the piece ends on the sample nearest its end
        pieces.append(fit_to_length(samples, wanted))
        written += wanted
    return np.concatenate(pieces) if pieces else np.zeros(0, np.float32), rate


def missing_voice_message(voice: str, installed: list[str]) -> str:
    """The error for a voice Festival does not have, naming the Debian package that provides it."""
    have = ", ".join(installed) if installed else "none"
    package = VOICE_PACKAGES.get(voice)
    if package:
        how = f"install the Debian package {package}: sudo apt-get install {package}"
    else:
        how = "install the Debian package that provides it (apt-cache search festvox lists them)"
    return f"Festival voice {voice} is not installed (installed voices: {have}); {how}"


def fit_to_duration(samples: np.ndarray, rate: int, duration_ms: float) -> np.ndarray:
    """Trim or zero-pad ``samples`` to ``duration_ms`` (rounded to the sample).

    Festival's diphone wave runs a few tens of ms past the end of its last
    segment (a silent pause); cutting it there makes the phones cover the
    waveform exactly, so audio, phones and video all end together.
    """
    return fit_to_length(samples, round(float(duration_ms) * rate / 1000.0))


def fit_to_length(samples: np.ndarray, n: int) -> np.ndarray:
    """``samples`` cut or zero-padded to ``n`` samples."""
    n = max(0, int(n))
    if len(samples) >= n:
        return np.ascontiguousarray(samples[:n])
    return np.concatenate([samples, np.zeros(n - len(samples), dtype=samples.dtype)])


def _kill_group(process: subprocess.Popen) -> None:
    """Stop the Festival process we started, and anything it started (its own process group)."""
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(process.pid, signal.SIGKILL)
    with contextlib.suppress(subprocess.TimeoutExpired):  # SIGKILL cannot be ignored: communicate returns
        process.communicate(timeout=5)


def _stderr_summary(stderr: str) -> str:
    """The last meaningful lines of Festival's stderr (ALSA noise left out), for an error message."""
    lines = [line.strip() for line in stderr.splitlines()
             if line.strip() and not line.startswith(("ALSA lib", "aplay:"))]
    return (": " + " / ".join(lines[-3:])) if lines else ""
