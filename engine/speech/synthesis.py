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
from collections.abc import Callable
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
        atomic_write_bytes(path, read_wav_bytes(utterance.source_wav, "recording"))
        return
    atomic_write_bytes(path, wav_bytes(utterance.samples, utterance.sample_rate))


MAX_WAV_BYTES = 2 * 1024**3
"""A WAV file larger than this (2 GiB: hours of studio audio) is refused before it is read."""
WAV_RATES = (1_000, 768_000)
"""The sample rates a WAV may have, Hz (telephone speech is 8 kHz, studio masters at most 768 kHz)."""
MAX_WAV_CHANNELS = 256
MAX_WAV_CHUNKS = 10_000
"""Chunks before the samples (a WAV has a handful: ``fmt``, ``LIST``, ``fact``, ``bext``)."""
_PCM, _FLOAT, _EXTENSIBLE = 1, 3, 0xFFFE
_BLOCK_FRAMES = 1 << 18


@dataclass(frozen=True)
class WavLayout:
    """How a PCM WAV file's samples lie in its bytes: ``frames`` of ``channels`` samples of ``width`` bytes
    from byte ``start`` on, at ``rate`` frames a second; integers, or IEEE floats where ``floating``."""

    channels: int
    width: int
    rate: int
    start: int
    frames: int
    floating: bool = False

    @property
    def duration_ms(self) -> float:
        return 1000.0 * self.frames / self.rate


def wav_layout(data: bytes, source: str | Path = "<wav>") -> WavLayout:
    """The layout of a PCM WAV file's bytes (RIFF ``WAVE``; integer PCM, format 1 or extensible, of 8, 16,
    24 or 32 bits, or IEEE float, format 3 or extensible, of 32 or 64 bits; :data:`WAV_RATES`; at most
    :data:`MAX_WAV_CHANNELS` channels), or a :class:`SynthesisError` naming ``source``. Every chunk's size is
    checked against the bytes that follow it before anything is read; a data chunk longer than the file (a
    recording cut short) holds the whole frames that are there.
    """
    def refuse(what: str) -> SynthesisError:
        return SynthesisError(f"not a PCM WAV file: {what}", file=source)

    if len(data) < 12 or data[:4] != b"RIFF" or data[8:12] != b"WAVE":
        raise refuse("it does not begin with a RIFF WAVE header")
    position, layout = 12, None
    for _ in range(MAX_WAV_CHUNKS):
        if position + 8 > len(data):
            break
        name, size = data[position:position + 4], int.from_bytes(data[position + 4:position + 8], "little")
        body, left = position + 8, len(data) - position - 8
        shown = name.decode("latin-1").encode("unicode_escape").decode("ascii")
        if name == b"data":
            if layout is None:
                raise refuse("its samples (the data chunk) come before their format (the 'fmt ' chunk)")
            frames = min(size, left) // (layout.channels * layout.width)
            return WavLayout(layout.channels, layout.width, layout.rate, body, frames, layout.floating)
        if size > left:
            raise refuse(f"its '{shown}' chunk claims {size} bytes, but only {left} follow")
        if name == b"fmt ":
            layout = _wav_format(data[body:body + size], refuse)
        position = body + size + (size & 1)                      # chunks are padded to an even length
    else:
        raise refuse(f"more than {MAX_WAV_CHUNKS} chunks before the samples")
    raise refuse("it has no samples (no data chunk)" if layout is not None else "it has no 'fmt ' chunk")


def _wav_format(chunk: bytes, refuse: Callable[[str], SynthesisError]) -> WavLayout:
    if len(chunk) < 16:
        raise refuse(f"its 'fmt ' chunk has {len(chunk)} bytes, a PCM format needs 16")
    tag, channels, rate = int.from_bytes(chunk[0:2], "little"), int.from_bytes(chunk[2:4], "little"), \
        int.from_bytes(chunk[4:8], "little")
    bits = int.from_bytes(chunk[14:16], "little")
    if tag == _EXTENSIBLE and len(chunk) >= 26:
        tag = int.from_bytes(chunk[24:26], "little")             # the sub-format GUID's first two bytes
    if tag not in (_PCM, _FLOAT):
        raise refuse(f"its samples are of format {tag}, not integer PCM (format 1) or IEEE float (format 3)")
    if not 1 <= channels <= MAX_WAV_CHANNELS:
        raise refuse(f"{channels} channels (a WAV has 1 to {MAX_WAV_CHANNELS})")
    if not WAV_RATES[0] <= rate <= WAV_RATES[1]:
        raise refuse(f"a sample rate of {rate} Hz (a WAV's is {WAV_RATES[0]} to {WAV_RATES[1]} Hz)")
    width = (bits + 7) // 8
    if tag == _FLOAT:
        if bits not in (32, 64):
            raise refuse(f"{bits} bits a float sample (IEEE float PCM has 32 or 64)")
        return WavLayout(channels, width, rate, 0, 0, floating=True)
    if not 1 <= width <= 4:
        raise refuse(f"{bits} bits a sample (integer PCM has 8, 16, 24 or 32)")
    return WavLayout(channels, width, rate, 0, 0)


def decode_wav(data: bytes, source: str | Path = "<wav>") -> tuple[np.ndarray, int]:
    """Samples (float32 mono in [-1, 1]) and sample rate of a PCM WAV file's bytes (:func:`wav_layout`).

    Several channels are averaged into one. The samples are converted a block at a time into the one array
    returned, so the memory used beyond ``data`` is 4 bytes a frame. Float samples beyond ±1 (a mix with
    headroom) are clipped there, as a player does; a NaN or an infinity is an error naming its time.
    """
    layout = wav_layout(data, source)
    out = np.empty(layout.frames, dtype=np.float32)
    frame = layout.channels * layout.width
    scale = 2.0 ** -(8 * layout.width - 1)
    view = memoryview(data)
    for first in range(0, layout.frames, _BLOCK_FRAMES):
        count = min(_BLOCK_FRAMES, layout.frames - first)
        begin = layout.start + first * frame
        if layout.floating:
            block = np.frombuffer(view[begin:begin + count * frame], dtype=f"<f{layout.width}")
            _check_finite(block, first, layout, source)
            floats = block.reshape(count, layout.channels)
            values = floats[:, 0] if layout.channels == 1 else floats.mean(axis=1)
            out[first:first + count] = np.clip(values, -1.0, 1.0)
            continue
        ints = _pcm_integers(view[begin:begin + count * frame], layout.width).reshape(count, layout.channels)
        values = ints[:, 0] if layout.channels == 1 else ints.mean(axis=1)
        out[first:first + count] = values * scale
    return out, layout.rate


def _check_finite(block: np.ndarray, first_frame: int, layout: WavLayout, source: str | Path) -> None:
    bad = np.flatnonzero(~np.isfinite(block))
    if len(bad):
        frame = first_frame + int(bad[0]) // layout.channels
        raise SynthesisError(f"not a PCM WAV file: the sample at {1000.0 * frame / layout.rate:.3f} ms is "
                             f"{block[bad[0]]}, not a number a sound can have", file=source)


def _pcm_integers(raw: memoryview, width: int) -> np.ndarray:
    """The signed sample values of little-endian PCM bytes (8-bit samples are unsigned, centred on 128)."""
    if width == 1:
        return np.frombuffer(raw, dtype=np.uint8).astype(np.int16) - 128
    if width == 2:
        return np.frombuffer(raw, dtype="<i2")
    if width == 4:
        return np.frombuffer(raw, dtype="<i4")
    bytes3 = np.frombuffer(raw, dtype=np.uint8).reshape(-1, 3).astype(np.int32)
    ints = bytes3[:, 0] | (bytes3[:, 1] << 8) | (bytes3[:, 2] << 16)
    return np.where(ints >= 1 << 23, ints - (1 << 24), ints)


def read_wav_bytes(path: str | Path, what: str = "WAV file") -> bytes:
    """The bytes of a WAV file, read as every WAV is: a regular file of at most :data:`MAX_WAV_BYTES`."""
    try:
        return read_bounded_bytes(path, MAX_WAV_BYTES, SynthesisError, what)
    except OSError as exc:
        raise SynthesisError(f"cannot read: {exc.strerror or exc}", file=path) from None


def read_wav(path: str | Path) -> tuple[np.ndarray, int]:
    """Samples (float32 mono in [-1, 1]) and sample rate of a PCM WAV file (a regular file, at most 2 GiB):
    the one reader of WAV files (``say --audio``, a design's ``audio``/``noise``, ``web-export --audio``,
    ``capture --audio``)."""
    return decode_wav(read_wav_bytes(path), path)


def read_wav_layout(path: str | Path) -> WavLayout:
    """The :class:`WavLayout` of a WAV file (its rate, channels, frames), checked as :func:`read_wav` checks it."""
    return wav_layout(read_wav_bytes(path), path)


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
