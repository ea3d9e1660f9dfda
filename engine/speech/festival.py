"""Festival backend of the synthesizer interface (§2.1): Finnish Suopuhe voices by default.

Festival runs as a subprocess on a generated Scheme script that selects the
voice, synthesizes the text as one utterance, saves the wave to a temporary
file, and prints the Segment relation (name and end time of every phone),
the Word relation, and for each phone the word it belongs to (through the
SylStructure relation). Phone boundaries are Festival's own, seconds → ms,
to the microsecond Festival prints.

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
import shutil
import signal
import subprocess
import tempfile
import time
import unicodedata
from pathlib import Path

import numpy as np

from engine.speech.synthesis import Segment, SynthesisError, Utterance, decode_wav

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
_WAVE_FILE = "utterance.wav"
_SCRIPT_FILE = "synthesize.scm"


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


def scheme_string(text: str) -> str:
    """``text`` as a Scheme string literal (backslashes and double quotes escaped)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def synthesis_script(text: str, voice: str, wave_file: str = _WAVE_FILE) -> str:
    """The Scheme program Festival runs: voice, synthesis, wave file, and the relations on stdout.

    ``text`` must already be prepared (:func:`prepare_text`). Output lines the
    parser reads all start with ``AP-``; anything else Festival or the voice
    prints is ignored. Word names come last on their line, so they may hold
    any character.
    """
    return f"""\
(format t "\\nAP-VOICES")
(mapcar (lambda (v) (format t "\\t%s" v)) (voice.list))
(format t "\\n")
(if (member_string "{voice}" (voice.list))
  (begin
    (voice_{voice})
    (set! ap_utt (utt.synth (Utterance Text {scheme_string(text)})))
    (utt.save.wave ap_utt {scheme_string(wave_file)} 'riff)
    (format t "\\nAP-BEGIN\\n")
    (mapcar
      (lambda (w) (format t "AP-WORD\\t%s\\t%s\\n" (item.feat w "id") (item.name w)))
      (utt.relation.items ap_utt 'Word))
    (mapcar
      (lambda (s)
        (format t "AP-SEG\\t%f\\t%s\\t%s\\n"
                (item.feat s "end") (item.feat s "R:SylStructure.parent.parent.id") (item.name s)))
      (utt.relation.items ap_utt 'Segment))
    (format t "AP-END\\n"))
  (format t "\\nAP-NOVOICE\\n"))
"""


VOICES_SCRIPT = """\
(format t "\\nAP-VOICES")
(mapcar (lambda (v) (format t "\\t%s" v)) (voice.list))
(format t "\\nAP-END\\n")
"""


# ---------------------------------------------------------------------------
# Festival's output → segments
# ---------------------------------------------------------------------------

def parse_voices(stdout: str) -> list[str]:
    """The voice names on the ``AP-VOICES`` line."""
    for line in stdout.splitlines():
        if line.startswith("AP-VOICES"):
            return [name for name in line.split("\t")[1:] if name]
    raise SynthesisError("Festival did not list its voices (is it a working Festival installation?)")


def parse_segments(stdout: str) -> tuple[list[Segment], list[Segment]]:
    """Phones and words from the ``AP-WORD`` / ``AP-SEG`` lines of :func:`synthesis_script`'s output.

    Times: Festival's segment end times (seconds) × 1000, rounded to the
    microsecond; each phone starts where the one before ends, the first at 0.
    A phone's ``word`` is the name of its word in the SylStructure relation
    ("" for pauses Festival inserts outside any word). Each word spans
    exactly its phones; a word without phones is left out.
    """
    lines = stdout.splitlines()
    try:
        begin = lines.index("AP-BEGIN")
        end = lines.index("AP-END", begin)
    except ValueError:
        raise SynthesisError("Festival's output has no segment list") from None
    word_names: dict[str, str] = {}
    word_order: list[str] = []
    raw: list[tuple[str, float, str]] = []
    for number, line in enumerate(lines[begin + 1:end], start=begin + 2):
        kind, _, rest = line.partition("\t")
        if kind == "AP-WORD":
            word_id, _, name = rest.partition("\t")
            word_names[word_id] = name
            word_order.append(word_id)
        elif kind == "AP-SEG":
            fields = rest.split("\t", 2)
            try:
                end_s = float(fields[0])
                word_id, label = fields[1], fields[2]
            except (ValueError, IndexError):
                raise SynthesisError(f"unreadable segment line {number} in Festival's output: {line!r}") from None
            raw.append((label, round(end_s * 1000.0, 3), word_id))
        elif line.strip():
            raise SynthesisError(f"unexpected line {number} in Festival's output: {line!r}")
    if not raw:
        raise SynthesisError("Festival produced no phones")

    phones: list[Segment] = []
    spans: dict[str, list[float]] = {}
    start = 0.0
    for label, end_ms, word_id in raw:
        if end_ms < start:
            raise SynthesisError(
                f"Festival's phone {label!r} ends at {end_ms} ms, before it starts ({start} ms)")
        word = word_names.get(word_id, "")
        phones.append(Segment(label, start, end_ms, word))
        if word_id in word_names:
            span = spans.setdefault(word_id, [start, end_ms])
            span[1] = end_ms
        start = end_ms
    words = [Segment(word_names[w], spans[w][0], spans[w][1]) for w in word_order if w in spans]
    return phones, words


# ---------------------------------------------------------------------------
# The synthesizer
# ---------------------------------------------------------------------------

class FestivalSynthesizer:
    """Text → :class:`Utterance` with the Festival speech synthesizer.

    ``festival`` is the program (name on ``PATH`` or a path); ``timeout`` (s)
    bounds every Festival run — a run that takes longer is killed and
    reported, never waited for.
    """

    default_voice = DEFAULT_VOICE

    def __init__(self, festival: str = "festival", timeout: float = 120):
        self.festival = str(festival)
        self.timeout = float(timeout)
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
        """Speak ``text`` with ``voice`` (default :data:`DEFAULT_VOICE`)."""
        voice = self.default_voice if voice is None else str(voice)
        if not _VOICE_NAME.match(voice):
            raise SynthesisError(f"{voice!r} is not a Festival voice name (letters, digits and _ only)")
        prepared = prepare_text(text)
        stdout, stderr, wave_data = self._run(synthesis_script(prepared, voice), want_wave=True)
        if "\nAP-NOVOICE" in stdout:
            self._voices = parse_voices(stdout)
            raise SynthesisError(missing_voice_message(voice, self._voices))
        if "AP-END" not in stdout.splitlines():
            raise SynthesisError(f"Festival failed to synthesize the text with voice {voice}"
                                 + _stderr_summary(stderr))
        phones, words = parse_segments(stdout)
        if not words:
            raise SynthesisError(f"nothing to say: Festival found no words in {text.strip()!r}")
        if wave_data is None:
            raise SynthesisError("Festival wrote no wave file" + _stderr_summary(stderr))
        samples, rate = decode_wav(wave_data, "Festival's wave")
        samples = fit_to_duration(samples, rate, phones[-1].end_ms)
        return Utterance(text=text, voice=voice, samples=samples, sample_rate=rate, phones=phones, words=words)

    # -- running Festival ------------------------------------------------------

    def executable(self) -> str:
        """The Festival program to run; :class:`SynthesisError` naming the package if there is none."""
        if os.sep in self.festival or (os.altsep and os.altsep in self.festival):
            if os.path.isfile(self.festival) and os.access(self.festival, os.X_OK):
                return self.festival
            raise SynthesisError(
                f"Festival is not installed at {self.festival} (no such program); "
                f"install the Debian package {FESTIVAL_PACKAGE}: "
                f"sudo apt-get install {FESTIVAL_PACKAGE} {VOICE_PACKAGES[DEFAULT_VOICE]}")
        found = shutil.which(self.festival)
        if found is None:
            raise SynthesisError(
                f"Festival is not installed (no program {self.festival!r} on PATH); "
                f"install the Debian package {FESTIVAL_PACKAGE}: "
                f"sudo apt-get install {FESTIVAL_PACKAGE} {VOICE_PACKAGES[DEFAULT_VOICE]}")
        return found

    def _run(self, script: str, want_wave: bool = False) -> tuple[str, str, bytes | None]:
        """Run Festival on ``script`` in a fresh temporary folder: (stdout, stderr, wave bytes or None)."""
        program = self.executable()
        with tempfile.TemporaryDirectory(prefix="artificial-person-festival-") as folder:
            Path(folder, _SCRIPT_FILE).write_bytes(script.encode("latin-1"))
            started = time.perf_counter()
            try:
                process = subprocess.Popen(
                    [program, "--batch", _SCRIPT_FILE], cwd=folder, stdin=subprocess.DEVNULL,
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
            except OSError as exc:
                raise SynthesisError(f"cannot run Festival ({program}): {exc.strerror or exc}; "
                                     f"install the Debian package {FESTIVAL_PACKAGE}") from None
            try:
                out, err = process.communicate(timeout=self.timeout)
            except subprocess.TimeoutExpired:
                _kill_group(process)
                raise SynthesisError(
                    f"Festival did not finish within {self.timeout:g} s and was stopped "
                    f"(a very long text? split it, or allow more time)") from None
            except BaseException:
                _kill_group(process)
                raise
            self.last_run_seconds = time.perf_counter() - started
            wave_path = Path(folder, _WAVE_FILE)
            wave_data = wave_path.read_bytes() if want_wave and wave_path.is_file() else None
        stdout, stderr = out.decode("latin-1"), err.decode("latin-1")
        if process.returncode != 0 and "AP-END" not in stdout.splitlines():
            raise SynthesisError(f"Festival ({program}) failed with exit status {process.returncode}"
                                 + _stderr_summary(stderr))
        return stdout, stderr, wave_data


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
    n = round(float(duration_ms) * rate / 1000.0)
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
