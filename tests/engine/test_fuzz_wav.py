"""WAV files fuzzed: each is read, or refused with one SynthesisError naming the file.

Inputs: RIFF files built from chunks whose declared sizes lie (0, 0xfffffff0, past the end, odd) and
``fmt `` chunks with any format tag, channel count, sample rate and bit depth; a valid WAV mutated byte by
byte or cut short; arbitrary bytes. Every one goes through :func:`engine.speech.synthesis.read_wav` (what
``say --audio``, a design's ``audio``/``noise``, ``web-export --audio`` and ``capture --audio`` read with),
and through a stimulus's noise mixing. What is read must be sound: float32 samples in [-1, 1] at a rate
within the documented range. Size: ``AP_FUZZ_EXAMPLES`` (docs/robustness.md).
"""

from __future__ import annotations

import io
import struct
import wave

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from engine.errors import UserError
from engine.speech.synthesis import WAV_RATES, SynthesisError, read_wav, read_wav_layout
from engine.stimuli.audio import add_noise
from tests.engine.fuzz_support import FUZZ, expect_clean

_u32 = st.one_of(st.sampled_from([0, 1, 2, 15, 16, 17, 40, 0xFFFFFFF0, 0xFFFFFFFF, 0x7FFFFFFF]),
                 st.integers(0, 0xFFFFFFFF))
_fmt = st.builds(
    lambda tag, channels, rate, byte_rate, align, bits, extra: struct.pack(
        "<HHIIHH", tag, channels, rate, byte_rate, align, bits) + extra,
    st.one_of(st.sampled_from([1, 1, 3, 0xFFFE, 0]), st.integers(0, 0xFFFF)),
    st.one_of(st.sampled_from([0, 1, 1, 2, 3, 255, 256, 257, 0xFFFF]), st.integers(0, 0xFFFF)),
    st.one_of(st.sampled_from([0, 1, 999, 1000, 8000, 16000, 44100, 768000, 768001, 0xFFFFFFFF]), _u32),
    _u32,
    st.integers(0, 0xFFFF),
    st.one_of(st.sampled_from([0, 1, 8, 12, 16, 24, 32, 33, 64, 0xFFFF]), st.integers(0, 0xFFFF)),
    st.one_of(st.just(b""), st.binary(max_size=30),
              st.just(struct.pack("<HHI", 22, 16, 4) + struct.pack("<H", 1) + bytes(14))),
)
_sane_fmt = st.builds(
    lambda channels, rate, bits: struct.pack("<HHIIHH", 1, channels, rate, rate * channels * bits // 8,
                                             channels * bits // 8, bits),
    st.integers(1, 3), st.sampled_from([1000, 8000, 16000, 768000]), st.sampled_from([8, 16, 24, 32]))
_chunk = st.builds(
    lambda name, body, size: name + struct.pack("<I", len(body) if size is None else size) + body,
    st.one_of(st.sampled_from([b"fmt ", b"data", b"LIST", b"fact", b"junk"]), st.binary(min_size=4, max_size=4)),
    st.one_of(_fmt, st.binary(max_size=400)),
    st.one_of(st.none(), st.none(), _u32),
)
_built = st.builds(
    lambda magic, chunks, size: magic[:4] + struct.pack("<I", size & 0xFFFFFFFF) + magic[4:] + b"".join(chunks),
    st.sampled_from([b"RIFFWAVE"] * 8 + [b"RIFXWAVE", b"RF64WAVE", b"RIFFAVI "]),
    st.one_of(st.tuples(_chunk, _chunk).map(list),
              st.tuples(st.builds(lambda f: b"fmt " + struct.pack("<I", len(f)) + f, _fmt), _chunk).map(list),
              st.tuples(st.builds(lambda f: b"fmt " + struct.pack("<I", len(f)) + f, _sane_fmt), _chunk).map(list),
              st.lists(_chunk, max_size=5)),
    _u32,
)


def _valid(channels: int, width: int, rate: int, frames: bytes) -> bytes:
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:
        out.setnchannels(channels)
        out.setsampwidth(width)
        out.setframerate(rate)
        out.writeframes(frames)
    return buffer.getvalue()


_valid_wavs = st.builds(_valid, st.integers(1, 3), st.integers(1, 4),
                        st.sampled_from([1000, 8000, 16000, 22050, 48000]), st.binary(max_size=600))


def _mutate(data: bytes, edits: list[tuple[int, int, int]]) -> bytes:
    out = bytearray(data)
    for kind, position, value in edits:
        if len(out) <= 12:
            break
        i = 12 + position % (len(out) - 12)              # past the RIFF WAVE magic: into the chunks
        if kind == 0:
            out[i] = value
        elif kind == 1:
            out[i:i + 4] = struct.pack("<I", value * 0x01010101 & 0xFFFFFFFF)
        elif kind == 2:
            del out[i]
        else:
            del out[i:]
    return bytes(out)


_mutated = st.builds(_mutate, _valid_wavs,
                     st.lists(st.tuples(st.integers(0, 3), st.integers(0, 10**6), st.integers(0, 255)),
                              min_size=1, max_size=6))
WAVS = st.one_of(_built, _valid_wavs, _mutated, st.binary(max_size=200),
                 st.binary(max_size=100).map(lambda b: b"RIFF" + b[:4] + b"WAVE" + b[4:]))


def _read(path):
    result = expect_clean(lambda: read_wav(path), SynthesisError, str(path))
    if isinstance(result, SynthesisError):
        return None
    samples, rate = result
    assert samples.dtype == np.float32 and samples.ndim == 1 and WAV_RATES[0] <= rate <= WAV_RATES[1]
    assert np.all(np.isfinite(samples)) and np.all(np.abs(samples) <= 1.0)
    assert read_wav_layout(path).frames == len(samples)
    return samples, rate


@FUZZ
@given(WAVS)
def test_fuzz_wav_files_are_read_or_refused_with_the_file_named(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("wav") / "take.wav"
    path.write_bytes(data)
    _read(path)


@FUZZ
@given(WAVS)
def test_fuzz_a_noise_wav_is_mixed_or_refused_with_the_file_named(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("noise") / "noise.wav"
    path.write_bytes(data)
    if _read(path) is None:
        return
    speech = (0.3 * np.sin(np.arange(1600) / 3)).astype(np.float32)
    result = expect_clean(lambda: add_noise(speech, 16000, 0.0, path, np.ones(1600, bool), seed=1), UserError,
                          str(path))
    if not isinstance(result, UserError):
        mixed, gain = result
        assert len(mixed) == 1600 and np.all(np.isfinite(mixed)) and 0 < gain <= 1
