"""One Say as a job (engine.speech.requests): the speech and its WAV, and where an error in the text points."""

from __future__ import annotations

import numpy as np
import pytest

from engine.errors import CommandError, UserError
from engine.speech.requests import TEXT_NAME, SayRequest, described_error, error_location, run_say
from engine.speech.synthesis import Segment, Utterance, read_wav


class Recorded:
    """Festival's interface with fixed timings: "moi" in 400 ms of audio."""

    def __init__(self):
        self.texts: list[str] = []

    def synthesize(self, text, voice=None):
        self.texts.append(text)
        phones = [Segment("#", 0.0, 100.0, ""), Segment("m", 100.0, 180.0, "moi"),
                  Segment("o", 180.0, 300.0, "moi"), Segment("i", 300.0, 400.0, "moi")]
        samples = (0.1 * np.sin(np.arange(8820) / 10)).astype(np.float32)
        return Utterance(text, voice or "recorded", samples, 22050, phones, [Segment("moi", 100.0, 400.0, "moi")])


def test_run_say_speaks_the_request_and_writes_its_audio(head, tmp_path):
    synthesizer = Recorded()
    request = SayRequest("moi <Blink/>", head, prosody_seed=None, synthesizer=synthesizer)
    first = run_say(request, tmp_path)
    second = run_say(request, tmp_path)
    assert synthesizer.texts == ["moi", "moi"]                     # the text without its commands
    assert first.wav != second.wav and first.wav.parent == tmp_path and first.wav.name.startswith("say-")
    assert first.request is request and first.duration == pytest.approx(0.4)
    samples, rate = read_wav(first.wav)
    assert rate == 22050
    np.testing.assert_allclose(samples, first.speech.utterance.samples, atol=1 / 32767)
    assert any(a.command == "Blink" for a in first.speech.activations)


def test_an_error_in_the_text_names_its_line_and_column(head, tmp_path):
    request = SayRequest("moi\nja <Hapy/> kala", head, synthesizer=Recorded())
    with pytest.raises(UserError) as caught:
        run_say(request, tmp_path)
    assert caught.value.file == TEXT_NAME and error_location(caught.value) == (2, 4)
    assert list(tmp_path.iterdir()) == []


def test_error_location_and_description():
    assert error_location(CommandError("column 5: unknown command <Hapy>", file=TEXT_NAME, line=2)) == (2, 5)
    assert error_location(CommandError("bad", file="other.xml", line=2)) is None
    assert error_location(ValueError("no line")) is None
    assert described_error(CommandError("no text to speak", file=TEXT_NAME, line=3)) == \
        "text:3: no text to speak (line 3, column 1)"
    assert described_error(CommandError("column 5: x", file=TEXT_NAME, line=2)) == "text:2: column 5: x"
