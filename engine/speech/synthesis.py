"""The synthesizer interface: text → waveform, phone segments and word segments (§2.1).

The paper's synthesizer is Festival with the Finnish Suopuhe voices; it turns
text into a waveform *and* the timing of every phone, and those timings drive
the visual articulation. This module holds what every backend shares — the
:class:`Utterance` it returns, the :class:`Synthesizer` protocol, and the WAV
and phones-CSV files (header ``start_ms,end_ms,phone,word``). The Festival backend is
:class:`engine.speech.festival.FestivalSynthesizer`; ``docs/speech-synthesis.md``
lists the phones the Finnish voices emit.

Times are milliseconds. Phones are contiguous and in time order: the first
starts at 0, each starts where the one before ends, and the last ends where
the waveform ends.

>>> import numpy as np
>>> from engine.speech.synthesis import Segment, Utterance, phones_csv
>>> utterance = Utterance(
...     text="moi", voice="test", samples=np.zeros(2205, dtype=np.float32), sample_rate=22050,
...     phones=[Segment("#", 0.0, 30.0), Segment("m", 30.0, 61.25, "moi"),
...             Segment("o", 61.25, 80.0, "moi"), Segment("i", 80.0, 100.0, "moi")],
...     words=[Segment("moi", 30.0, 100.0)])
>>> utterance.duration_ms
100.0
>>> print(phones_csv(utterance), end="")
start_ms,end_ms,phone,word
0,30,#,
30,61.25,m,moi
61.25,80,o,moi
80,100,i,moi
"""

from __future__ import annotations

import csv
import io
import wave
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

from engine.errors import UserError
from engine.formats.atomic import atomic_write_bytes, atomic_write_text
from engine.formats.text_files import read_bounded_bytes, read_bounded_text
from engine.speech.phone_features import PhoneFeatures

PHONES_CSV_HEADER = ("start_ms", "end_ms", "phone", "word")


class SynthesisError(UserError):
    """Speech synthesis failed: no synthesizer, a voice not installed, text it cannot say, a timeout."""


@dataclass(frozen=True)
class Segment:
    """A phone or a word and its time span (ms).

    ``label`` is the phone as the synthesizer names it (Suopuhe: ``a e i o u y
    @ 7``, long forms ``a:`` …, ``N`` for ng, pauses ``#``) or, for a word
    segment, the word. ``word`` is, for a phone, the word it belongs to
    (``""`` for pauses and for word segments).
    """

    label: str
    start_ms: float
    end_ms: float
    word: str = ""

    @property
    def duration_ms(self) -> float:
        return self.end_ms - self.start_ms

    @property
    def mid_ms(self) -> float:
        return 0.5 * (self.start_ms + self.end_ms)


@dataclass
class Utterance:
    """What a synthesizer returns: the spoken waveform and its timing."""

    text: str
    voice: str
    samples: np.ndarray
    """Mono float32 in [-1, 1]."""
    sample_rate: int
    phones: list[Segment]
    """Contiguous, in time order, covering 0 … :attr:`duration_ms`."""
    words: list[Segment]
    """In time order; each spans its phones exactly."""
    phoneset: str = ""
    """The voice's phone set (Festival: ``finnish``, ``radio`` …; "" when the synthesizer does not say)."""
    phone_features: dict[str, PhoneFeatures] = field(default_factory=dict)
    """Each phone's features from the phone set (vowel height, rounding, place …), for articulation."""
    source_wav: Path | None = None
    """The recording the samples were read from (a recorded voice): a WAV output copies it unchanged."""

    @property
    def duration_ms(self) -> float:
        """Length of the waveform in milliseconds."""
        return 1000.0 * len(self.samples) / self.sample_rate


@runtime_checkable
class Synthesizer(Protocol):
    """Anything that turns text into an :class:`Utterance`."""

    def synthesize(self, text: str, voice: str | None = None) -> Utterance:  # pragma: no cover - protocol
        ...


# ---------------------------------------------------------------------------
# WAV files
# ---------------------------------------------------------------------------

def wav_bytes(samples: np.ndarray, sample_rate: int) -> bytes:
    """Mono float samples in [-1, 1] as a 16-bit PCM WAV file (values outside are clipped)."""
    samples = np.asarray(samples, dtype=np.float64).reshape(-1)
    pcm = np.clip(np.round(np.nan_to_num(samples) * 32767.0), -32768, 32767).astype("<i2")
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:
        out.setnchannels(1)
        out.setsampwidth(2)
        out.setframerate(int(sample_rate))
        out.writeframes(pcm.tobytes())
    return buffer.getvalue()


def write_wav(path: str | Path, utterance: Utterance) -> None:
    """Write the utterance's waveform as a 16-bit PCM mono WAV file, atomically; a recorded utterance's
    own WAV file is copied byte for byte."""
    if utterance.source_wav is not None:
        try:
            data = Path(utterance.source_wav).read_bytes()
        except OSError as exc:
            raise SynthesisError(f"cannot read the recording: {exc.strerror or exc}",
                                 file=utterance.source_wav) from None
        atomic_write_bytes(path, data)
        return
    atomic_write_bytes(path, wav_bytes(utterance.samples, utterance.sample_rate))


def decode_wav(data: bytes, source: str | Path = "<wav>") -> tuple[np.ndarray, int]:
    """Samples (float32 mono in [-1, 1]) and sample rate of an integer-PCM WAV file's bytes.

    Several channels are averaged into one.
    """
    try:
        with wave.open(io.BytesIO(data), "rb") as wav:
            channels, width, rate = wav.getnchannels(), wav.getsampwidth(), wav.getframerate()
            frames = wav.readframes(wav.getnframes())
    except (wave.Error, EOFError) as exc:
        raise SynthesisError(f"not a PCM WAV file: {exc}", file=source) from None
    if width == 1:
        values = (np.frombuffer(frames, dtype=np.uint8).astype(np.float64) - 128.0) / 128.0
    elif width == 2:
        values = np.frombuffer(frames, dtype="<i2").astype(np.float64) / 32768.0
    elif width == 3:
        raw = np.frombuffer(frames, dtype=np.uint8).reshape(-1, 3).astype(np.int32)
        ints = raw[:, 0] | (raw[:, 1] << 8) | (raw[:, 2] << 16)
        ints = np.where(ints >= 1 << 23, ints - (1 << 24), ints)
        values = ints.astype(np.float64) / float(1 << 23)
    elif width == 4:
        values = np.frombuffer(frames, dtype="<i4").astype(np.float64) / float(1 << 31)
    else:  # pragma: no cover - the wave module rejects other widths
        raise SynthesisError(f"unsupported WAV sample width {width} bytes", file=source)
    values = values[: len(values) - len(values) % channels].reshape(-1, channels).mean(axis=1)
    return values.astype(np.float32), rate


MAX_WAV_BYTES = 2 * 1024**3
"""A WAV file larger than this (2 GiB: hours of studio audio) is refused before it is read."""


def read_wav(path: str | Path) -> tuple[np.ndarray, int]:
    """Samples (float32 mono in [-1, 1]) and sample rate of a PCM WAV file (a regular file, at most 2 GiB)."""
    try:
        data = read_bounded_bytes(path, MAX_WAV_BYTES, SynthesisError, "WAV file")
    except OSError as exc:
        raise SynthesisError(f"cannot read: {exc.strerror or exc}", file=path) from None
    return decode_wav(data, path)


# ---------------------------------------------------------------------------
# Phones CSV (header start_ms,end_ms,phone,word)
# ---------------------------------------------------------------------------

def format_ms(value: float) -> str:
    """A time in ms to the microsecond, shortest form: ``88.273``, ``30``, ``0``.

    >>> format_ms(88.27300000000001), format_ms(30.0), format_ms(1117.6299999), format_ms(-0.0)
    ('88.273', '30', '1117.63', '0')
    """
    text = f"{float(value):.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def phones_csv(utterance: Utterance) -> str:
    """The phones CSV: header ``start_ms,end_ms,phone,word``, one row per phone, times to the µs."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(PHONES_CSV_HEADER)
    for phone in utterance.phones:
        writer.writerow([format_ms(phone.start_ms), format_ms(phone.end_ms), phone.label, phone.word])
    return buffer.getvalue()


def write_phones_csv(path: str | Path, utterance: Utterance) -> None:
    """Write :func:`phones_csv` to ``path`` atomically (UTF-8)."""
    atomic_write_text(path, phones_csv(utterance))


def read_phones_csv(path: str | Path) -> list[Segment]:
    """The phones of a phones CSV file, as :class:`Segment` s."""
    try:
        text = read_bounded_text(path, error=SynthesisError, what="phones CSV")
    except OSError as exc:
        raise SynthesisError(f"cannot read: {exc.strerror or exc}", file=path) from None
    rows = list(csv.reader(io.StringIO(text)))
    if not rows or tuple(rows[0]) != PHONES_CSV_HEADER:
        raise SynthesisError(f"not a phones CSV: the header must be {','.join(PHONES_CSV_HEADER)}",
                             file=path, line=1)
    phones = []
    for line, row in enumerate(rows[1:], start=2):
        if not row:
            continue
        try:
            start, end, label, word = row
            phones.append(Segment(label, float(start), float(end), word))
        except ValueError:
            raise SynthesisError("expected start_ms,end_ms,phone,word", file=path, line=line) from None
    return phones
