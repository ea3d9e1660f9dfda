"""The sound of a stimulus: audio–visual offsets, noise at a signal-to-noise ratio, and measuring both back.

**Offsets** (``av_offset_ms``; positive: the audio later than the video): the
audio is shifted to the sample, the video to the frame, and the clip is padded
so nothing is cut — a positive offset puts silence before the audio and holds
the face's last pose after the speech; a negative one starts the face late,
holding its first (rest) pose. :func:`clip_layout` says where each starts.

**Noise** at ``snr_db``, measured over the speech (the samples inside
non-pause phones): white (seeded Gaussian), speech-shaped (white noise given
the long-term spectrum of this very utterance), or a WAV file (looped,
resampled by nearest sample when its rate differs). The mixture is scaled
down only if it would clip, which leaves the SNR as it is.

>>> layout = clip_layout(speech_ms=1000.0, video_ms=1100.0, offset_ms=200.0)
>>> layout.audio_start_ms, layout.video_start_ms, layout.length_ms
(200.0, 0.0, 1200.0)
>>> rng = np.random.default_rng(0)
>>> speech = np.sin(np.linspace(0, 2000, 16000)).astype(np.float32) * 0.3
>>> mixed, gain = add_noise(speech, 16000, 6.0, "white", np.ones(16000, bool), seed=1)
>>> round(measured_snr_db(speech, mixed, np.ones(16000, bool), gain), 6)
6.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from engine.errors import UserError


@dataclass(frozen=True)
class ClipLayout:
    """Where the audio and the video start in the clip, and how long the clip is (ms)."""

    audio_start_ms: float
    video_start_ms: float
    length_ms: float


def clip_layout(speech_ms: float, video_ms: float, offset_ms: float) -> ClipLayout:
    """The clip for an utterance of ``speech_ms`` of audio and ``video_ms`` of movement, offset by ``offset_ms``."""
    audio_start = max(0.0, float(offset_ms))
    video_start = max(0.0, -float(offset_ms))
    return ClipLayout(audio_start, video_start, max(audio_start + speech_ms, video_start + video_ms))


def placed_audio(samples: np.ndarray, rate: int, start_ms: float, length_ms: float) -> np.ndarray:
    """``samples`` starting ``start_ms`` into a clip of ``length_ms`` (silence around them), to the sample."""
    total = round(length_ms * rate / 1000.0)
    start = round(start_ms * rate / 1000.0)
    out = np.zeros(max(total, start + len(samples)), dtype=np.float32)
    out[start:start + len(samples)] = samples
    return out[:total] if total >= start + len(samples) else out


def speech_mask(phones: list, rate: int, count: int, pauses: frozenset[str]) -> np.ndarray:
    """True at the samples inside non-pause phones (where the SNR is measured)."""
    mask = np.zeros(count, dtype=bool)
    for phone in phones:
        if phone.label in pauses:
            continue
        mask[round(phone.start_ms * rate / 1000.0):round(phone.end_ms * rate / 1000.0)] = True
    return mask


def add_noise(speech: np.ndarray, rate: int, snr_db: float, noise: str | Path, mask: np.ndarray,
              seed: int = 0) -> tuple[np.ndarray, float]:
    """``speech`` plus noise whose power over the masked samples is the speech's divided by 10^(snr/10),
    and the gain the mixture was scaled by so as not to clip (1 when it did not need to be)."""
    speech = np.asarray(speech, dtype=np.float64)
    if not mask.any():
        raise UserError("cannot set a signal-to-noise ratio: the utterance has no speech sounds")
    rng = np.random.default_rng(seed)
    if noise == "white":
        raw = rng.standard_normal(len(speech))
    elif noise == "speech-shaped":
        raw = _shaped_like(speech[mask], len(speech), rng)
    else:
        raw = _noise_file(Path(noise), rate, len(speech))
    speech_power = float(np.mean(speech[mask] ** 2))
    noise_power = float(np.mean(raw[mask] ** 2))
    if noise_power == 0:
        raise UserError("the noise is silent where the speech is", file=str(noise))
    scaled = raw * math.sqrt(speech_power / noise_power / 10 ** (snr_db / 10))
    mixed = speech + scaled
    peak = float(np.max(np.abs(mixed)))
    gain = 0.99 / peak if peak > 0.99 else 1.0           # scale both together: the ratio stays
    return (mixed * gain).astype(np.float32), gain


def measured_snr_db(clean: np.ndarray, mixed: np.ndarray, mask: np.ndarray, gain: float = 1.0) -> float:
    """The SNR of ``mixed`` over the masked samples: the clean speech (times the mixture's ``gain``) against
    what else the samples hold."""
    clean = np.asarray(clean, dtype=np.float64)[mask] * gain
    mixed = np.asarray(mixed, dtype=np.float64)[mask]
    noise = mixed - clean
    return 10 * math.log10(float(np.mean(clean ** 2)) / float(np.mean(noise ** 2)))


def measured_offset_ms(reference: np.ndarray, recorded: np.ndarray, rate: int, search_ms: float) -> float:
    """Where ``reference`` starts in ``recorded`` (ms), by cross-correlation over ±``search_ms``."""
    reference = np.asarray(reference, dtype=np.float64)
    recorded = np.asarray(recorded, dtype=np.float64)
    reach = round(search_ms * rate / 1000.0)
    size = 1 << math.ceil(math.log2(len(reference) + len(recorded) + 1))
    spectrum = np.fft.rfft(recorded, size) * np.conj(np.fft.rfft(reference, size))
    correlation = np.fft.irfft(spectrum, size)
    lags = np.concatenate([np.arange(0, reach + 1), np.arange(-reach, 0)])
    values = correlation[lags % size]
    return float(lags[int(np.argmax(values))]) * 1000.0 / rate


def _shaped_like(speech: np.ndarray, count: int, rng: np.random.Generator) -> np.ndarray:
    """White noise filtered to the long-term magnitude spectrum of ``speech`` (1024-point frames)."""
    frame = 1024
    padded = np.pad(speech, (0, (-len(speech)) % frame))
    spectrum = np.sqrt(np.mean(np.abs(np.fft.rfft(padded.reshape(-1, frame) * np.hanning(frame), axis=1)) ** 2,
                               axis=0))
    white = rng.standard_normal(count + frame)
    shaped = np.fft.irfft(np.fft.rfft(white, len(white)) * np.interp(
        np.linspace(0, 1, len(white) // 2 + 1), np.linspace(0, 1, len(spectrum)), spectrum), len(white))
    return shaped[:count]


def _noise_file(path: Path, rate: int, count: int) -> np.ndarray:
    from engine.speech.synthesis import read_wav

    samples, noise_rate = read_wav(path)
    if len(samples) == 0:
        raise UserError("the noise file has no samples", file=path)
    if noise_rate == rate:
        repeats = -(-count // len(samples))
        return np.tile(samples.astype(np.float64), repeats)[:count]
    # the noise resampled by nearest sample to `length` samples at `rate`, looped: only the `count` needed are
    # made (a noise file at a low rate would otherwise be resampled whole, many times its length)
    length = int(len(samples) * rate / noise_rate)
    if length == 0:
        raise UserError("the noise file is shorter than one sample at the speech's rate", file=path)
    index = np.minimum((np.arange(count) % length * noise_rate / rate).astype(int), len(samples) - 1)
    return samples[index].astype(np.float64)
