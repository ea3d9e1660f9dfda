"""Sound for the player: a WAV clip played from any position, or silence where there is no output.

The workbench has no QtMultimedia (PySide6-Essentials), so sound goes out
through PortAudio with the ``sounddevice`` package (Debian: ``libportaudio2``).
Where the machine has no audio output — a server, CI, a container — or the
library is missing, :meth:`AudioOutput.start` returns ``False`` and the
player keeps time with its own clock instead: playback is silent but runs
at the right speed and ends at the right time.

>>> clip = load_clip("hello.wav")                 # doctest: +SKIP
>>> output = AudioOutput()
>>> output.start(clip, 0.5)                       # doctest: +SKIP
True                                              # False: no sound device, play silently
>>> output.position()                             # doctest: +SKIP
0.5213                                            # seconds of the clip heard so far
>>> output.stop()
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from engine.speech.synthesis import read_wav


@dataclass(frozen=True)
class AudioClip:
    """Mono float samples in [-1, 1], their rate (Hz) and where they came from."""

    samples: np.ndarray
    sample_rate: int
    source: str = ""

    @property
    def duration(self) -> float:
        """Length in seconds."""
        return len(self.samples) / float(self.sample_rate) if self.sample_rate else 0.0


def load_clip(audio) -> AudioClip:
    """An :class:`AudioClip` from a WAV path, an :class:`AudioClip`, or anything with
    ``samples`` and ``sample_rate`` (an ``engine.speech.synthesis.Utterance``).

    A file that is not a PCM WAV raises :class:`engine.speech.synthesis.SynthesisError`
    (a :class:`~engine.errors.UserError` naming the file).
    """
    if isinstance(audio, AudioClip):
        return audio
    if isinstance(audio, (str, Path)):
        samples, rate = read_wav(audio)
        return AudioClip(np.asarray(samples, dtype=np.float32), int(rate), str(audio))
    samples = np.asarray(audio.samples, dtype=np.float32).reshape(-1)
    return AudioClip(samples, int(audio.sample_rate), getattr(audio, "source", "") or "<speech>")


def _sounddevice():
    """The ``sounddevice`` module, or ``None`` when it (or PortAudio) is not installed."""
    try:
        import sounddevice
    except (ImportError, OSError):
        return None
    return sounddevice


def output_available() -> bool:
    """Whether there is a default audio output device to play on."""
    sd = _sounddevice()
    if sd is None:
        return False
    try:
        info = sd.query_devices(kind="output")
    except Exception:               # PortAudioError / ValueError: no default output device
        return False
    return bool(info) and int(info.get("max_output_channels", 0)) > 0


class AudioOutput:
    """Plays one clip at a time from a position; tells how far playback has got."""

    def __init__(self):
        self._stream = None
        self._clip: AudioClip | None = None
        self._frame = 0                    # next sample the callback hands to the device
        self._lock = threading.Lock()

    @staticmethod
    def available() -> bool:
        return output_available()

    @property
    def is_playing(self) -> bool:
        stream = self._stream
        return stream is not None and bool(stream.active)

    def start(self, clip: AudioClip, seconds: float = 0.0) -> bool:
        """Play ``clip`` from ``seconds``; ``False`` (and silence) when there is no output to play on."""
        self.stop()
        if not self.available() or clip.sample_rate <= 0:
            return False
        sd = _sounddevice()
        self._clip = clip
        self._frame = int(max(0.0, seconds) * clip.sample_rate)
        if self._frame >= len(clip.samples):
            return False
        try:
            self._stream = sd.OutputStream(samplerate=clip.sample_rate, channels=1, dtype="float32",
                                           callback=self._fill)
            self._stream.start()
        except Exception:             # the device went away or refused the format: stay silent
            self._stream = None
            return False
        return True

    def position(self) -> float | None:
        """Seconds into the clip now being heard, or ``None`` when nothing is playing."""
        stream, clip = self._stream, self._clip
        if stream is None or clip is None or not stream.active:
            return None
        with self._lock:
            frame = self._frame
        try:
            latency = float(stream.latency)
        except Exception:
            latency = 0.0
        return max(0.0, frame / float(clip.sample_rate) - latency)

    def latency(self) -> float | None:
        """Seconds from a sample handed to the device to its output, as PortAudio reports it (``None``: not playing)."""
        stream = self._stream
        try:
            return None if stream is None else float(stream.latency)
        except Exception:
            return None

    def stop(self) -> None:
        stream, self._stream = self._stream, None
        if stream is not None:
            try:
                stream.abort()
                stream.close()
            except Exception:
                pass

    def _fill(self, outdata, frames, _time, _status) -> None:
        # Runs on PortAudio's thread.
        clip = self._clip
        with self._lock:
            start = self._frame
            chunk = clip.samples[start:start + frames]
            self._frame = start + len(chunk)
        outdata[:len(chunk), 0] = chunk
        outdata[len(chunk):, 0] = 0.0
        if len(chunk) < frames:
            sd = _sounddevice()
            raise sd.CallbackStop
