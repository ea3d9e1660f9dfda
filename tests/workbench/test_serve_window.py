"""``serve --window`` (issue 21): the served head in a window of its own, its frames stamped when presented, with sound.

Real components throughout: the server runs in a subprocess on an X server of the test's
own (Xvfb, which writes its screen to a file with ``-fbdir``, so the test reads what is on the
screen), with real Festival, over real loopback sockets. The sound goes out through PortAudio and
ALSA as on any computer; the test's ALSA configuration (a ``.asoundrc`` in the server's
``$HOME``) makes the default device ALSA's ``file`` plugin, so every sample the window plays
lands in a file the test compares with Festival's own waveform.
"""

from __future__ import annotations

import os
import re
import select
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from engine.live.client import LiveClient
from tests.engine.serve_schema_checks import schema_checked  # noqa: F401  (a fixture)

PROJECT_ROOT = Path(__file__).resolve().parents[2]
SENTENCE = "Pappa ampui pallon"
SCREEN = (480, 400)
needs_xvfb = pytest.mark.skipif(shutil.which("Xvfb") is None, reason="Xvfb is not installed (bootstrap installs it)")
needs_festival = pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")

pytestmark = [needs_xvfb, pytest.mark.usefixtures("schema_checked")]


@dataclass
class Screen:
    display: str
    framebuffer: Path

    def grab(self) -> np.ndarray:
        """What is on the screen now, (height, width, 3) uint8 RGB, read from Xvfb's XWD framebuffer file."""
        return read_xwd(self.framebuffer.read_bytes())


def read_xwd(data: bytes) -> np.ndarray:
    """The pixels of an X window dump (XWD version 7, 24-bit TrueColor at 32 bits per pixel, as Xvfb writes)."""
    header = np.frombuffer(data[:100], dtype=">u4")
    header_size, version, _, depth, width, height = (int(v) for v in header[:6])
    byte_order, bits_per_pixel, bytes_per_line, ncolours = int(header[7]), int(header[11]), int(header[12]), \
        int(header[19])
    assert version == 7 and depth == 24 and bits_per_pixel == 32, "an XWD this reader does not know"
    start = header_size + 12 * ncolours
    rows = np.frombuffer(data[start:start + bytes_per_line * height], dtype=np.uint8).reshape(height, bytes_per_line)
    pixels = rows[:, :4 * width].reshape(height, width, 4)
    return pixels[..., 2::-1].copy() if byte_order == 0 else pixels[..., 1:].copy()      # BGRX / XRGB → RGB


@contextmanager
def screen_of(width: int, height: int, folder: Path) -> Iterator[Screen]:
    """An X server with one screen of ``width`` × ``height``, its pixels in a file in ``folder``."""
    read, write = os.pipe()
    process = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", f"{width}x{height}x24",
                                "-fbdir", str(folder), "-nolisten", "tcp"], pass_fds=(write,),
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    os.close(write)
    try:
        ready, _, _ = select.select([read], [], [], 30)
        number = os.read(read, 64).decode().strip() if ready else ""
        assert number.isdigit(), "Xvfb did not start"
        yield Screen(f":{number}", folder / "Xvfb_screen0")
    finally:
        os.close(read)
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=30)


@pytest.fixture(scope="module")
def screen(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Screen]:
    """An X server of this module's own, its screen in a file."""
    with screen_of(SCREEN[0], SCREEN[1], tmp_path_factory.mktemp("screen")) as opened:
        yield opened


@dataclass
class Served:
    url: str
    process: subprocess.Popen
    stderr_path: Path
    sound_path: Path

    def stderr(self) -> str:
        return self.stderr_path.read_text(encoding="utf-8", errors="replace")

    def sound(self) -> np.ndarray:
        """Every sample the window has played (float32: PortAudio's format, written as it is)."""
        return np.fromfile(self.sound_path, dtype="<f4") if self.sound_path.exists() else np.zeros(0, np.float32)


def start_window_server(screen: Screen, folder: Path, *options: str) -> Served:
    """``artificial-person serve --window --port 0`` on ``screen``, its sound going to ``folder/sound.raw``."""
    home = folder / "home"
    home.mkdir(exist_ok=True)
    sound_path = folder / "sound.raw"
    (home / ".asoundrc").write_text(
        f'pcm.!default {{\n  type file\n  slave.pcm "null"\n  file "{sound_path}"\n  format "raw"\n}}\n')
    env = {**os.environ, "DISPLAY": screen.display, "HOME": str(home)}
    env.pop("WAYLAND_DISPLAY", None)
    env.pop("QT_QPA_PLATFORM", None)
    stderr_path = folder / "serve-stderr.txt"
    with stderr_path.open("wb") as stderr:
        process = subprocess.Popen([sys.executable, "-m", "engine", "serve", "--window", "--port", "0", "--size",
                                    "240x320", *options], cwd=PROJECT_ROOT, stdout=subprocess.PIPE, stderr=stderr,
                                   env=env)
    assert process.stdout is not None
    ready, _, _ = select.select([process.stdout], [], [], 120)
    line = process.stdout.readline().decode() if ready else ""
    match = re.search(r"ws://127\.0\.0\.1:\d+", line)
    if match is None or " window " not in line:
        process.kill()
        process.wait()
        pytest.fail(f"the window server did not start: {line!r} {stderr_path.read_text()}")
    return Served(match.group(0), process, stderr_path, sound_path)


@pytest.fixture(scope="module")
def served(screen: Screen, tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    server = start_window_server(screen, tmp_path_factory.mktemp("window"))
    yield server
    server.process.send_signal(signal.SIGTERM)
    assert server.process.wait(timeout=30) == 0, server.stderr()
    assert server.process.stdout is not None
    server.process.stdout.close()
    assert "Traceback" not in server.stderr() and "internal error" not in server.stderr(), server.stderr()


def applied(head: LiveClient, values: dict[str, float]) -> dict:
    """Set ``values`` and wait for their ``applied`` event."""
    request_id = head.set(values)["id"]
    return next(e for e in head.events_until(request_id, "applied") if e.get("id") == request_id)


def screen_when(screen: Screen, settled: object, seconds: float = 20.0) -> np.ndarray:
    """The screen, once ``settled(picture)`` says it shows what it must (polled; fails after ``seconds``)."""
    deadline = time.monotonic() + seconds
    while True:
        picture = screen.grab()
        if settled(picture):
            return picture
        if time.monotonic() > deadline:
            from engine.outputs.png_file import write_png

            write_png(screen.framebuffer.with_name("never-settled.png"), picture)
            pytest.fail(f"the screen never showed it (what it showed: {screen.framebuffer.parent}/never-settled.png)")
        time.sleep(0.02)


def test_the_window_shows_each_pose_a_client_sets_and_stamps_it_presented(served, screen):
    with LiveClient(served.url) as head:
        capabilities = head.capabilities()
        assert capabilities["mode"] == "window" and capabilities["clock"]["fps"] >= 20
        rest_event = applied(head, {"jaw_open": 0.0})
        time.sleep(0.3)
        rest = screen.grab()
        assert (rest.reshape(-1, 3).std(axis=0) > 10).all(), "the head is on the screen (not one flat colour)"
        opened_event = applied(head, {"jaw_open": 1.0})
        opened = screen_when(screen, lambda picture: (np.abs(picture.astype(int) - rest).max(axis=2) > 40).sum() > 30)
        changed = np.abs(opened.astype(int) - rest).max(axis=2) > 40
        assert opened[changed].mean() < rest[changed].mean(), "the open mouth is darker than the closed one"
        rows = np.nonzero(changed)[0]
        assert rows.mean() > np.nonzero(rest.astype(int).sum(axis=2) > 60)[0].mean(), "the change is low in the face"
        closed_event = applied(head, {"jaw_open": 0.0})
        screen_when(screen, lambda picture: (np.abs(picture.astype(int) - rest).max(axis=2) > 40).sum() == 0)
    for event in (rest_event, opened_event, closed_event):
        assert event["presented_t"] >= event["t"], "a frame is presented after its moment, never before"
    assert rest_event["presented_t"] < opened_event["presented_t"] < closed_event["presented_t"]


@needs_festival
def test_speech_in_a_window_plays_festivals_samples_and_stamps_every_event(served):
    before = len(served.sound())
    with LiveClient(served.url) as head:
        request_id = head.say(SENTENCE)
        events = [e for e in head.events_until(request_id) if e.get("id") == request_id]
    kinds = [e["event"] for e in events]
    assert kinds[0] == "speech_start" and kinds[-1] == "finished"
    assert [e["word"] for e in events if e["event"] == "word"] == SENTENCE.split()
    presented = [e["presented_t"] for e in events]
    assert presented == sorted(presented), "events leave in the order their frames were shown"
    assert all(e["presented_t"] >= e["t"] for e in events)
    start = events[0]
    assert start["audio_t"] is not None, "the sound device (ALSA's file plugin) played it"
    rate = start["sample_rate"]
    assert start["audio_t"] >= start["t"] - 1000.0 / 60, "the first sample goes out when its frame is drawn, or later"
    from engine.speech.festival import FestivalSynthesizer

    spoken = FestivalSynthesizer().synthesize(SENTENCE).samples
    played = wait_for_sound(served, before, len(spoken))
    lead = first_sound(played) - first_sound(spoken)   # > 0: the device's priming silence; < 0: a late first frame
    assert -rate // 10 < lead < rate // 10, "played from its first sample (or the few its late frame had passed)"
    assert not played[:max(lead, 0)].any(), "nothing but silence before the utterance"
    played, spoken = played[max(lead, 0):], spoken[max(-lead, 0):]
    length = min(len(played), len(spoken))
    assert length > 0.9 * len(spoken)
    np.testing.assert_allclose(played[:length], spoken[:length], atol=1e-6,
                               err_msg="Festival's waveform, sample for sample")


def first_sound(samples: np.ndarray) -> int:
    return int(np.flatnonzero(np.abs(samples) > 1e-3)[0])


def wait_for_sound(served: Served, before: int, samples: int) -> np.ndarray:
    """The samples played since ``before``, once an utterance of ``samples`` (less what a late start skips) is in."""
    deadline = time.monotonic() + 30
    while True:
        sound = served.sound()[before:]
        if len(sound) >= samples * 0.9 or time.monotonic() > deadline:
            return sound
        time.sleep(0.05)


@needs_festival
def test_the_gaze_cue_example_runs_against_the_window_and_its_log_agrees_with_what_was_presented(served, tmp_path):
    from tests.engine.test_serve import check_gaze_cue_log, run_gaze_cue_example

    rows = run_gaze_cue_example(served.url, tmp_path / "log.csv")
    check_gaze_cue_log(rows)
    [start] = [r for r in rows if r["event"] == "speech_start"]
    assert float(start["audio_t"]) >= float(start["t"]) - 1000.0 / 60      # the sound device played it
    assert any(float(r["presented_t"]) > float(r["t"]) for r in rows), "window frames are stamped at their swap"


def test_fullscreen_fills_the_screen_and_the_window_ends_its_server_when_closed(screen, tmp_path):
    served = start_window_server(screen, tmp_path, "--fullscreen")
    try:
        with LiveClient(served.url) as head:
            applied(head, {"jaw_open": 0.3})
        picture = screen_when(screen, lambda picture: (picture.sum(axis=2) == 0).mean() < 0.001)
        assert picture.shape[:2] == (SCREEN[1], SCREEN[0])      # the whole screen is the window: no bare root left
    finally:
        served.process.send_signal(signal.SIGINT)
        assert served.process.wait(timeout=30) == 0
        assert served.process.stdout is not None
        served.process.stdout.close()
    assert "Traceback" not in served.stderr()


def test_without_a_display_the_window_is_refused_in_one_line():
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")}
    result = subprocess.run([sys.executable, "-m", "engine", "serve", "--window", "--port", "0"], cwd=PROJECT_ROOT,
                            capture_output=True, text=True, timeout=120, check=False, env=env)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.startswith("error: --window needs a display") and result.stderr.count("\n") == 1
