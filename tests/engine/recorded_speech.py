"""A stand-in for Festival with fixed timings, for tests that need an utterance but not a voice."""

from __future__ import annotations

import numpy as np

from engine.speech.synthesis import Segment, Utterance


class Recorded:
    """Festival's interface with fixed timings: "moi" in 400 ms of audio."""

    def synthesize(self, text, voice=None):
        phones = [Segment("#", 0.0, 100.0, ""), Segment("m", 100.0, 250.0, "moi"), Segment("o", 250.0, 400.0, "moi")]
        samples = (0.1 * np.sin(np.arange(8820) / 10)).astype(np.float32)
        return Utterance(text, "recorded", samples, 22050, phones, [Segment("moi", 100.0, 400.0, "moi")])
