"""The files of one utterance (engine.outputs.speech_files): one sampling, every file, all or nothing.

A recorded synthesizer (fixed phones, no Festival) gives the speech; the
video needs ffmpeg and is only written where a test says so.
"""

from __future__ import annotations

import csv
import io
import shutil
from pathlib import Path

import numpy as np
import pytest

import engine.outputs.data_files as data_files
from engine.commands import low_level_xml
from engine.errors import UserError
from engine.outputs.data_files import landmarks_csv
from engine.outputs.speech_files import (
    KINDS,
    SPEECH_FILE_KINDS,
    ExportCancelled,
    ExportPlan,
    export_speech,
    write_speech_files,
)
from engine.speech.say import Speech, speak
from engine.speech.synthesis import Segment, Utterance, decode_wav, phones_csv

needs_ffmpeg = pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")
TABLES = ("wav", "xml", "phones", "tracks", "landmarks")


class Recorded:
    """Festival's interface with fixed timings: "moi" in 400 ms of audio (a quiet tone)."""

    def synthesize(self, text, voice=None):
        phones = [Segment("#", 0.0, 100.0, ""), Segment("m", 100.0, 180.0, "moi"),
                  Segment("o", 180.0, 300.0, "moi"), Segment("i", 300.0, 400.0, "moi")]
        samples = (0.1 * np.sin(np.arange(8820) / 10)).astype(np.float32)
        return Utterance(text, "recorded", samples, 22050, phones, [Segment("moi", 100.0, 400.0, "moi")])


@pytest.fixture(scope="module")
def speech(head) -> Speech:
    return speak("moi <Blink/>", head, synthesizer=Recorded())


def targets_in(folder: Path, kinds=TABLES) -> dict[str, Path]:
    names = {"mp4": "s.mp4", "wav": "s.wav", "xml": "s.xml", "phones": "p.csv", "tracks": "t.csv",
             "landmarks": "l.csv"}
    return {kind: folder / names[kind] for kind in kinds}


def files_in(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_every_table_holds_the_speech(speech, head, tmp_path):
    targets = targets_in(tmp_path)
    written = write_speech_files(speech, head, targets, fps=25)
    assert written == list(targets.values())
    times = speech.frame_times(25)
    assert targets["tracks"].read_text() == speech.timeline.tracks_csv(fps=25, end=float(times[-1]))
    assert targets["xml"].read_text() == low_level_xml(speech.activations)
    assert targets["phones"].read_text() == phones_csv(speech.utterance)
    samples, rate = decode_wav(targets["wav"].read_bytes())
    assert rate == 22050 and len(samples) == 8820
    np.testing.assert_allclose(samples, speech.utterance.samples, atol=1 / 32767)
    rows = list(csv.reader(io.StringIO(targets["landmarks"].read_text())))
    assert rows[0][:5] == ["frame", "time_ms", "2.1_x", "2.1_y", "2.1_z"] and len(rows) - 1 == len(times)
    middle = len(times) // 2
    points = head.landmark_positions(speech.timeline.values_at(times[middle]))
    assert float(rows[1 + middle][2]) == pytest.approx(points["2.1"][0], abs=1e-9)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in targets.values())


@needs_ffmpeg
def test_the_timeline_is_sampled_once_for_the_video_and_the_tables(speech, head, tmp_path, monkeypatch):
    from engine.outputs.video_probe import probe

    calls = []
    real = type(speech.timeline).sample
    monkeypatch.setattr(type(speech.timeline), "sample", lambda self, times: calls.append(len(times)) or
                        real(self, times))
    steps = []
    targets = targets_in(tmp_path, ("mp4", "tracks", "landmarks"))
    write_speech_files(speech, head, targets, fps=20, size=(64, 48), progress=lambda *step: steps.append(step))
    frames = len(speech.frame_times(20))
    assert calls == [frames]
    assert probe(targets["mp4"]).frames == frames
    assert steps[0] == (0, frames + 2) and steps[-1] == (frames + 2, frames + 2)
    assert [done for done, _ in steps] == sorted(done for done, _ in steps)


def test_cancelling_leaves_the_old_files_and_nothing_else(speech, head, tmp_path):
    targets = targets_in(tmp_path)
    targets["wav"].write_bytes(b"an older file of the same name")
    before = files_in(tmp_path)
    asked = []

    def cancelled() -> bool:
        asked.append(1)
        return len(asked) > 3

    with pytest.raises(ExportCancelled):
        write_speech_files(speech, head, targets, fps=25, cancelled=cancelled)
    assert files_in(tmp_path) == before


@pytest.mark.parametrize("failure", [RuntimeError("a bug"), KeyboardInterrupt()])
def test_a_failure_half_way_leaves_the_old_files_and_nothing_else(speech, head, tmp_path, monkeypatch, failure):
    targets = targets_in(tmp_path)
    targets["tracks"].write_text("old tracks\n")
    before = files_in(tmp_path)

    def fail(*_):
        raise failure

    monkeypatch.setattr(data_files, "landmarks_csv", fail)        # the last file
    with pytest.raises(type(failure)):
        write_speech_files(speech, head, targets, fps=25)
    assert files_in(tmp_path) == before


@pytest.mark.parametrize("targets, options, words", [
    ({}, {}, "nothing to write"),
    ({"video": "x.mp4"}, {}, "unknown kind of speech file: video"),
    ({"tracks": "x.txt"}, {}, "unknown extension '.txt' for the tracks (use .csv)"),
    ({"wav": "x.csv"}, {}, "(use .wav)"),
    ({"tracks": "x.csv"}, {"fps": 0}, "positive"),
    ({"mp4": "x.avi"}, {}, "as .mp4"),
    ({"mp4": "x.mp4"}, {"size": (65, 48)}, "even"),
    ({"mp4": "missing/x.mp4"}, {}, "folder does not exist"),
    ({"tracks": "missing/x.csv"}, {}, "folder does not exist"),
])
def test_bad_arguments_are_user_errors_before_anything_is_written(speech, head, tmp_path, monkeypatch,
                                                                   targets, options, words):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(UserError) as caught:
        write_speech_files(speech, head, targets, **options)
    assert words in str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_landmarks_csv_needs_every_parameter_in_tree_order(head):
    with pytest.raises(ValueError, match="parameters of values"):
        landmarks_csv(head, np.zeros(2), np.zeros((2, 3)))


def test_export_plan_names_the_files_and_checks_itself(speech, head, tmp_path):
    assert set(KINDS) <= set(SPEECH_FILE_KINDS) and "xml" not in KINDS
    plan = ExportPlan(tmp_path, "hello", {"wav", "phones", "landmarks"}, fps=10)
    assert [p.name for p in plan.paths().values()] == ["hello.wav", "hello-phones.csv", "hello-landmarks.csv"]
    assert export_speech(plan, speech, head) == list(plan.paths().values())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hello-landmarks.csv", "hello-phones.csv", "hello.wav"]
    with pytest.raises(UserError, match="even"):
        ExportPlan(tmp_path, "x", {"mp4"}, size=(161, 120)).check()
    with pytest.raises(UserError, match="nothing to export"):
        ExportPlan(tmp_path, "x", set()).check()
    with pytest.raises(UserError, match="not a file name"):
        ExportPlan(tmp_path, "a/b", {"wav"}).check()
    with pytest.raises(UserError, match="unknown export kind"):
        ExportPlan(tmp_path, "x", {"xml"}).check()
    with pytest.raises(UserError, match="the folder does not exist"):
        export_speech(ExportPlan(tmp_path / "missing", "x", {"wav"}), speech, head)
