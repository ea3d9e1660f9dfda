"""The files beside a video are written by one dispatch (engine/outputs/data_files.py) for ``say``,
Export speech… and a stimulus of a design (issue 35, item 4: the kind → writer dispatch in one place)."""

from __future__ import annotations

import csv
import io
import shutil

import numpy as np
import pytest

import engine.outputs.data_files as data_files
from engine.outputs.data_files import DATA_FILE_KINDS, FrameData, data_file_bytes, data_file_text
from engine.outputs.speech_files import SPEECH_FILE_KINDS, write_speech_files
from engine.speech.say import speak
from engine.speech.synthesis import Segment, Utterance, decode_wav, wav_bytes
from engine.stimuli import parse_design
from engine.stimuli.make import FILE_NAMES, make_stimulus
from tests.engine.recorded_speech import Recorded

needs_festival = pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")


@pytest.fixture
def calls(monkeypatch):
    """Every call of the shared writers, by kind."""
    seen: list[str] = []
    for kind, writer in list(data_files._WRITERS.items()):
        def spy(data, kind=kind, writer=writer):
            seen.append(kind)
            return writer(data)
        monkeypatch.setitem(data_files._WRITERS, kind, spy)
    return seen


def test_every_file_kind_but_the_videos_and_the_still_is_written_here():
    assert set(SPEECH_FILE_KINDS) - {"mp4"} == DATA_FILE_KINDS
    assert set(FILE_NAMES) - {"mp4", "silent-mp4", "png"} <= DATA_FILE_KINDS


def test_say_writes_its_tables_through_the_shared_writers(head, tmp_path, calls):
    speech = speak("moi", head, synthesizer=Recorded())
    names = {"wav": "s.wav", "xml": "s.xml", "phones": "p.csv", "tracks": "t.csv", "landmarks": "l.csv"}
    write_speech_files(speech, head, {kind: tmp_path / name for kind, name in names.items()}, fps=25)
    assert calls == ["wav", "xml", "phones", "tracks", "landmarks"]


@needs_festival
def test_a_stimulus_writes_its_tables_through_the_same_writers(tmp_path, calls):
    design = parse_design('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["wav", "phones", "tracks"]\n', "d.toml")
    record = make_stimulus(design, design.stimuli[0], tmp_path)
    assert sorted(calls) == ["phones", "tracks", "wav"]
    assert sorted(record["files"]) == ["phones", "tracks", "wav"]
    phones = list(csv.reader(io.StringIO((tmp_path / "0001-phones.csv").read_text())))
    assert phones[0] == ["start_ms", "end_ms", "phone", "word"] and len(phones) > 2


def test_the_wav_is_the_samples_or_the_recording_byte_for_byte(tmp_path):
    samples = (0.25 * np.sin(np.arange(1600) / 7)).astype(np.float32)
    spoken = Utterance("x", "v", samples, 16000, [Segment("#", 0.0, 100.0)], [])
    data = FrameData([], np.zeros(0), np.zeros((0, 0)), spoken)
    decoded, rate = decode_wav(data_file_bytes("wav", data))
    assert rate == 16000
    np.testing.assert_allclose(decoded, samples, atol=1 / 32767)
    recording = tmp_path / "own.wav"
    recording.write_bytes(wav_bytes(samples, 16000) + b"")         # a file of its own, with its own bytes
    own = data_file_bytes("wav", FrameData([], np.zeros(0), np.zeros((0, 0)),
                                           Utterance("x", "v", samples * 0, 16000, [], [], source_wav=recording)))
    assert own == recording.read_bytes()


def test_what_a_kind_needs_is_asked_for():
    spoken = Utterance("x", "v", np.zeros(10, np.float32), 16000, [], [])
    data = FrameData([], np.zeros(0), np.zeros((0, 0)), spoken)
    with pytest.raises(ValueError, match="activations"):
        data_file_text("xml", data)
    with pytest.raises(ValueError, match="model"):
        data_file_text("landmarks", data)
    with pytest.raises(ValueError, match="not text"):
        data_file_text("wav", data)
