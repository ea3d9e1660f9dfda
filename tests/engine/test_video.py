"""Video output : real rendering, real ffmpeg, decoded back and checked.

One short video of the default head does most of the work: the head is at
rest for the first half (jaw closed, facing the camera) and turned with the
jaw open for the second half, and the audio is silent for the first half and a
1 kHz tone for the second. Frame n must show the face at time n/fps, so the
decoded frames must switch exactly at the half, and the tone must start there
too. Small pictures and few frames keep it quick on two cores.
"""

from __future__ import annotations

import contextlib
import io
import os
import shutil
from pathlib import Path

import numpy as np
import pytest

from engine.errors import ParameterError, UserError

video_writer = pytest.importorskip("engine.outputs.video_writer")
video_probe = pytest.importorskip("engine.outputs.video_probe")

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(shutil.which("ffmpeg") is None or shutil.which("ffprobe") is None,
                       reason="ffmpeg is not installed (Debian package ffmpeg)"),
]

FPS = 30.0
FRAMES = 20
SWITCH = 10                    # first frame of the second pose
SIZE = (240, 180)
RATE = 16000                   # Festival's sample rate
TONE_HZ = 1000.0
NAMES = ["jaw_open", "head_turn"]
POSE_A = [0.0, 0.0]
POSE_B = [1.0, 0.4]



def two_state_values() -> tuple[np.ndarray, np.ndarray]:
    times = np.arange(FRAMES) * (1000.0 / FPS)
    values = np.array([POSE_A] * SWITCH + [POSE_B] * (FRAMES - SWITCH), dtype=float)
    return times, values


def silence_then_tone(seconds: float) -> np.ndarray:
    """Silent until the switch, then a 1 kHz tone (float32, mono)."""
    t = np.arange(round(seconds * RATE)) / RATE
    samples = 0.5 * np.sin(2 * np.pi * TONE_HZ * t)
    samples[t < SWITCH / FPS] = 0.0
    return samples.astype(np.float32)


@pytest.fixture(scope="module")
def two_state(head, tmp_path_factory):
    """The video (audio a little shorter than the video: it must be padded), its stats and
    the two poses rendered directly."""
    out = tmp_path_factory.mktemp("video") / "two-state.mp4"
    times, values = two_state_values()
    calls = []
    stats = video_writer.write_video(out, head, times, values, NAMES, FPS, audio=silence_then_tone(0.6),
                              sample_rate=RATE, size=SIZE, progress=lambda done, total: calls.append((done, total)))
    from engine.outputs.render import FrameRenderer

    with FrameRenderer(head, size=SIZE, antialias=False) as renderer:
        pictures = [renderer.render(head.deform(dict(zip(NAMES, pose, strict=True)))) for pose in (POSE_A, POSE_B)]
    return out, stats, pictures, calls


def leftovers(folder: Path) -> list[str]:
    """Hidden temporary files write_video may have left in ``folder``."""
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


# ---------------------------------------------------------------------------
# Frames and timing


def test_one_frame_per_time_and_the_stream_facts(two_state):
    out, stats, _, _ = two_state
    info = video_probe.probe(out)
    assert info.frames == FRAMES == stats.frames
    assert (info.width, info.height) == SIZE
    assert info.fps == pytest.approx(FPS)
    assert info.video_codec == "h264" and info.audio_codec == "aac"
    assert info.video_duration == pytest.approx(FRAMES / FPS, abs=1e-3)


def test_audio_and_video_start_together_and_end_within_one_frame(two_state):
    info = video_probe.probe(two_state[0])
    assert info.video_start == pytest.approx(0.0, abs=1e-3)
    assert info.audio_start == pytest.approx(0.0, abs=1e-3)
    assert abs(info.audio_duration - info.video_duration) <= 1.0 / FPS


def test_frame_n_shows_the_face_at_time_n_over_fps(two_state):
    out, _, (first, second), _ = two_state
    frames = video_probe.read_frames(out).astype(float)
    assert len(frames) == FRAMES
    to_first = np.abs(frames - first).mean(axis=(1, 2, 3))
    to_second = np.abs(frames - second).mean(axis=(1, 2, 3))
    # compression changes a frame a little; the other pose is far off
    close, far = np.where(np.arange(FRAMES) < SWITCH, to_first, to_second), \
        np.where(np.arange(FRAMES) < SWITCH, to_second, to_first)
    assert close.max() < 3.0, close
    assert far.min() > 3 * close.max(), (close, far)
    # and the switch is exactly at frame SWITCH: nothing moves within a pose
    steps = np.abs(np.diff(frames, axis=0)).mean(axis=(1, 2, 3))
    assert np.argmax(steps) == SWITCH - 1
    assert np.delete(steps, SWITCH - 1).max() < steps[SWITCH - 1] / 5


def test_the_tone_survives_and_starts_with_the_second_pose(two_state):
    samples, rate = video_probe.read_audio(two_state[0])
    assert rate == RATE
    assert abs(len(samples) / rate - FRAMES / FPS) <= 1.0 / FPS     # padded to the video's length
    tone = samples[int(0.45 * rate):int(0.6 * rate)]
    spectrum = np.abs(np.fft.rfft(tone * np.hanning(len(tone)), n=8 * len(tone)))
    peak = np.fft.rfftfreq(8 * len(tone), 1.0 / rate)[np.argmax(spectrum)]
    assert peak == pytest.approx(TONE_HZ, abs=5.0)
    assert np.sqrt(np.mean(tone ** 2)) == pytest.approx(0.5 / np.sqrt(2), rel=0.15)
    # onset: where a 2 ms moving RMS first reaches half the tone's
    window = int(0.002 * rate)
    rms = np.sqrt(np.convolve(samples ** 2, np.ones(window) / window, mode="same"))
    onset = np.argmax(rms > 0.5 * 0.5 / np.sqrt(2)) / rate
    assert onset == pytest.approx(SWITCH / FPS, abs=0.5 / FPS)
    # silence after the samples ran out (0.6 s) up to the end of the video
    assert np.abs(samples[int(0.61 * rate):]).max() < 0.05


def test_progress_is_reported_for_every_frame(two_state):
    calls = two_state[3]
    assert calls == [(n, FRAMES) for n in range(FRAMES + 1)]


def test_stats_account_for_the_stages(two_state):
    stats = two_state[1]
    assert stats.duration == pytest.approx(FRAMES / FPS)
    assert stats.render > 0 and stats.deform >= 0 and stats.encoder_cpu > 0
    assert stats.total >= stats.render + stats.deform
    assert stats.real_time_factor == pytest.approx(stats.total / stats.duration)


def test_audio_longer_than_the_video_is_cut(head, tmp_path):
    out = tmp_path / "cut.mp4"
    times = np.arange(6) * (1000.0 / FPS)
    video_writer.write_video(out, head, times, np.zeros((6, 1)), ["jaw_open"], FPS,
                      audio=np.full(RATE * 2, 0.1, dtype=np.float32), sample_rate=RATE, size=(64, 48))
    info = video_probe.probe(out)
    assert info.frames == 6
    assert abs(info.audio_duration - 6 / FPS) <= 1.0 / FPS


def test_video_without_audio_and_at_an_odd_frame_rate(head, tmp_path):
    out = tmp_path / "silent.mp4"
    fps = 29.97
    times = np.arange(5) * (1000.0 / fps)
    video_writer.write_video(out, head, times, np.zeros((5, 1)), ["jaw_open"], fps, size=(64, 48))
    info = video_probe.probe(out)
    assert info.frames == 5 and info.audio_duration is None
    assert info.fps == pytest.approx(fps, abs=1e-3)


def test_the_video_starts_at_the_first_frame_time_on_the_audio_clock(head, tmp_path):
    """Frames from 500 ms: the audio is taken from 500 ms on, so the tone (from 333 ms) is on at once."""
    out = tmp_path / "late.mp4"
    times = 500.0 + np.arange(6) * (1000.0 / FPS)
    video_writer.write_video(out, head, times, np.zeros((6, 1)), ["jaw_open"], FPS,
                      audio=silence_then_tone(1.0), sample_rate=RATE, size=(64, 48))
    samples, _ = video_probe.read_audio(out)
    assert np.sqrt(np.mean(samples[int(0.02 * RATE):int(0.15 * RATE)] ** 2)) > 0.25


def test_an_existing_file_is_replaced_whole(head, tmp_path):
    out = tmp_path / "again.mp4"
    out.write_bytes(b"old")
    video_writer.write_video(out, head, [0.0, 1000 / FPS], np.zeros((2, 1)), ["jaw_open"], FPS, size=(64, 48))
    assert video_probe.probe(out).frames == 2
    assert leftovers(tmp_path) == []


# ---------------------------------------------------------------------------
# Errors


def write_small(head, out, **options):
    times, values = two_state_values()
    arguments = dict(size=(64, 48))
    arguments.update(options)
    return video_writer.write_video(out, head, times[:4], values[:4], NAMES, FPS, **arguments)


def test_ffmpeg_missing_names_the_debian_package(head, tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    with pytest.raises(video_writer.FFmpegMissing) as caught:
        write_small(head, tmp_path / "out.mp4")
    assert isinstance(caught.value, UserError)
    assert "apt-get install ffmpeg" in str(caught.value)
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(video_writer.FFmpegMissing, match="ffprobe"):
        video_probe.probe(__file__)


def test_ffmpeg_failing_reports_its_last_words_and_leaves_nothing(head, tmp_path, monkeypatch):
    out = tmp_path / "out.mp4"
    out.write_bytes(b"keep me")
    from engine.outputs.video_encoding import Encoding

    with pytest.raises(video_writer.VideoError) as caught:      # a preset encoding_from would have refused
        write_small(head, out, encoding=Encoding(preset="nonsense"))
    message = str(caught.value)
    assert "ffmpeg failed" in message and "invalid preset 'nonsense'" in message
    assert out.read_bytes() == b"keep me"
    assert leftovers(tmp_path) == []


def test_interrupted_render_kills_ffmpeg_and_leaves_nothing(head, tmp_path):
    out = tmp_path / "out.mp4"

    def interrupt(done, total):
        if done == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_small(head, out, progress=interrupt)
    assert not out.exists()
    assert leftovers(tmp_path) == []
    assert not any(str(tmp_path) in cmdline for cmdline in _process_command_lines())


def _process_command_lines() -> list[str]:
    lines = []
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            with contextlib.suppress(OSError):
                lines.append(Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode("utf-8", "replace"))
    return lines


@pytest.mark.parametrize("options, message", [
    (dict(path="missing/out.mp4"), "folder does not exist"),
    (dict(path="out.avi"), "as .mp4"),
    (dict(size=(65, 48)), "must be even"),
    (dict(view="top"), "unknown view"),
    (dict(fps=0), "positive"),
    (dict(audio=np.zeros(100, dtype=np.float32)), "sample rate"),
    (dict(audio=np.zeros((100, 2), dtype=np.float32), sample_rate=RATE), "one channel"),
    (dict(times=[0.0, 10.0, 20.0, 30.0]), "frame 1 is at 10 ms"),
    (dict(values=np.zeros((4, 3))), "4 frames × 2 parameters"),
])
def test_bad_input_is_a_user_error_before_anything_is_written(head, tmp_path, monkeypatch, options, message):
    monkeypatch.chdir(tmp_path)
    times, values = two_state_values()
    arguments = dict(path="out.mp4", times=times[:4], values=values[:4], fps=FPS, size=(64, 48))
    arguments.update(options)
    path, times, values, fps = (arguments.pop(k) for k in ("path", "times", "values", "fps"))
    with pytest.raises(UserError, match=message):
        video_writer.write_video(path, head, times, values, NAMES, fps, **arguments)
    assert list(tmp_path.iterdir()) == []


def test_unknown_parameter_is_a_parameter_error(head, tmp_path):
    with pytest.raises(ParameterError):
        video_writer.write_video(tmp_path / "out.mp4", head, [0.0], [[0.5]], ["jaw_opne"], FPS, size=(64, 48))


# ---------------------------------------------------------------------------
# Contact sheet and progress


def test_contact_sheet_of_the_video_shows_every_picked_frame(two_state, tmp_path):
    out = two_state[0]
    sheet = video_probe.contact_sheet(out, columns=4, count=8, width=120, path=tmp_path / "sheet.png")
    assert sheet.dtype == np.uint8 and sheet.ndim == 3
    assert (tmp_path / "sheet.png").stat().st_size > 1000
    # 8 thumbnails of 120 × 90 in 2 rows of 4, each with a label strip under it
    assert sheet.shape[1] == 6 + 4 * (120 + 6)
    assert sheet.shape[0] > 2 * 90
    thumb = sheet[6:96, 6:126].astype(int)
    assert np.abs(thumb - thumb[2, 2]).sum(axis=2).max() > 100      # a face, not a blank
    assert (sheet[96:110, 6:126].sum(axis=2) < 200).any()             # the label's dark text


def test_contact_sheet_of_frames_in_memory(two_state):
    _, _, pictures, _ = two_state
    frames = np.stack([pictures[0]] * 3 + [pictures[1]] * 3)
    sheet = video_probe.contact_sheet(frames, columns=3, count=6, width=80, fps=FPS)
    assert sheet.shape[1] == 6 + 3 * (80 + 6)
    with pytest.raises(UserError):
        video_probe.contact_sheet(np.zeros((2, 5, 5)), columns=2)


def test_progress_printer_on_a_log_writes_quarters():
    log = io.StringIO()
    report = video_writer.progress_printer("rendering", stream=log)
    for done in range(101):
        report(done, 100)
    assert log.getvalue().splitlines() == [f"rendering: {q}% ({q}/100 frames)" for q in (25, 50, 75, 100)]


def test_progress_printer_on_a_terminal_redraws_one_line():
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    screen = Terminal()
    report = video_writer.progress_printer("rendering", stream=screen, interval=0.0)
    for done in range(11):
        report(done, 10)
    text = screen.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n")
    assert text.count("\r") == 11
    assert "100% 10/10 frames" in text
