"""The player: the playhead drives the pose, playing runs in real time, audio sets the range."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import engine
from engine.commands import load_library, parse_commands_text, translate
from engine.speech.synthesis import Segment, wav_bytes
from engine.timeline.timeline import Timeline

DEFAULT_HEAD = engine.default_model_path()
JAW_SCRIPT = """<commands>
  <activate parameter="jaw_open" interp="linear"><key at="0" value="0"/><key at="150" value="0.8"/>
    <key at="300" value="0"/></activate>
</commands>"""

def timeline_of(text: str, model) -> Timeline:
    return Timeline(translate(parse_commands_text(text), load_library(), model), model)


@pytest.fixture
def no_sound_device(monkeypatch):
    """Play as on a machine without an audio output, whatever this one has."""
    from workbench.playback.audio_output import AudioOutput

    monkeypatch.setattr(AudioOutput, "available", staticmethod(lambda: False))


@pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="default head not built")
def test_head_nod_scrubbed_sets_the_engine_timeline_values(make_window):
    window = make_window(DEFAULT_HEAD)
    model = window.document.model
    timeline = timeline_of('<commands><HeadNod at="1000" amplitude="60" count="2"/></commands>', model)
    window.player.load(timeline, title="HeadNod")
    assert window.playhead.duration == pytest.approx(2.0)
    assert window.player.driven == ["head_nod"]
    for seconds in (0.5, 1.1665, 1.4, 1.9, 2.0):
        window.playhead.set_time(seconds)
        assert window.document.value("head_nod") == pytest.approx(timeline.values_at(seconds * 1000)["head_nod"])
    window.playhead.set_time(1.1665)
    assert window.document.value("head_nod") == pytest.approx(0.09)       # the paper's key, §2.3
    assert window.document.value("jaw_open") == model.parameters["jaw_open"].default   # not driven
    window.player.stop()
    assert window.playhead.time == 0.0
    assert window.document.value("head_nod") == model.parameters["head_nod"].default


def test_play_advances_to_the_end_and_pauses_there(window, qtbot, no_sound_device):
    timeline = timeline_of(JAW_SCRIPT, window.document.model)
    player = window.player
    player.load(timeline)
    seen: list[float] = []
    window.playhead.time_changed.connect(seen.append)
    with qtbot.waitSignal(player.finished, timeout=10000):
        player.play()
    assert player.state == "paused"
    assert window.playhead.time == pytest.approx(0.3)
    assert seen == sorted(seen) and seen[-1] == pytest.approx(0.3)  # forward only, to the end
    assert window.document.value("jaw_open") == pytest.approx(timeline.values_at(300.0)["jaw_open"])
    player.play()                                                    # at the end: starts over
    assert player.is_playing and window.playhead.time == 0.0
    player.stop()


class FakeClock:
    def __init__(self):
        self.now = 100.0

    def monotonic(self) -> float:
        return self.now


def test_the_playhead_follows_the_clock_not_the_ticks(window, monkeypatch, no_sound_device):
    """A late tick drops frames instead of slowing the animation down; speed scales the clock."""
    import workbench.playback.player as player_module

    clock = FakeClock()
    monkeypatch.setattr(player_module, "_time", clock)
    player = window.player
    timeline = timeline_of(JAW_SCRIPT, window.document.model)
    player.load(timeline)
    finished: list[bool] = []
    player.finished.connect(lambda: finished.append(True))
    player.play()
    player._timer.stop()                        # the test ticks by hand
    clock.now += 0.1
    player._tick()
    assert window.playhead.time == pytest.approx(0.1)
    clock.now += 0.125                          # a long frame: 7 frames skipped, not slowed down
    player._tick()
    assert window.playhead.time == pytest.approx(0.225)
    assert window.document.value("jaw_open") == pytest.approx(timeline.values_at(225.0)["jaw_open"])
    player.set_speed(0.5)
    clock.now += 0.1
    player._tick()
    assert window.playhead.time == pytest.approx(0.275)
    clock.now += 1.0
    player._tick()
    assert window.playhead.time == pytest.approx(0.3) and player.state == "paused" and finished


def test_loop_starts_over(window, qtbot, no_sound_device):
    player = window.player
    player.load(timeline_of(JAW_SCRIPT, window.document.model))
    player.set_loop(True)
    seen: list[float] = []
    window.playhead.time_changed.connect(seen.append)
    player.play()
    qtbot.waitUntil(lambda: any(b < a for a, b in itertools.pairwise(seen)), timeout=10000)
    assert player.is_playing                                         # still playing after the end
    player.stop()
    assert player.state == "stopped" and window.playhead.time == 0.0
    assert window.document.value("jaw_open") == window.document.model.parameters["jaw_open"].default


def test_frame_step_moves_one_frame_and_sets_that_pose(window):
    timeline = timeline_of(JAW_SCRIPT, window.document.model)
    window.player.load(timeline, fps=50)
    window.player.step(1)
    assert window.playhead.frame == 1 and window.playhead.time == pytest.approx(0.02)
    window.player.step(3)
    window.player.step(-1)
    assert window.playhead.frame == 3
    assert window.document.value("jaw_open") == pytest.approx(timeline.values_at(60.0)["jaw_open"])


def test_audio_without_a_device_plays_silently_to_its_end(window, qtbot, tmp_path, no_sound_device):
    wav = tmp_path / "tone.wav"
    rate = 16000
    wav.write_bytes(wav_bytes(0.2 * np.sin(np.arange(int(0.5 * rate)) * 0.1), rate))
    phones = [Segment("#", 0, 100), Segment("a", 100, 400), Segment("#", 400, 500)]
    player = window.player
    player.load(timeline_of(JAW_SCRIPT, window.document.model), audio=wav, phones=phones, title="tone")
    assert window.playhead.duration == pytest.approx(0.5)             # the audio is longer than the animation
    assert player.audio == wav and player.phones == phones and player.title == "tone"
    with qtbot.waitSignal(player.finished, timeout=10000):
        player.play()
    assert not player.sound_on
    assert window.playhead.time == pytest.approx(0.5)


def test_audio_only(window, tmp_path, no_sound_device):
    wav = tmp_path / "short.wav"
    wav.write_bytes(wav_bytes(np.zeros(8000), 8000))
    before = window.document.values
    window.player.load(None, audio=str(wav))
    assert window.playhead.duration == pytest.approx(1.0)
    window.playhead.set_time(0.5)
    assert window.document.values == before


def test_a_bad_wav_changes_nothing(window, tmp_path):
    from engine.errors import UserError

    timeline = timeline_of(JAW_SCRIPT, window.document.model)
    window.player.load(timeline)
    bad = tmp_path / "bad.wav"
    bad.write_text("not audio")
    with pytest.raises(UserError, match=r"bad\.wav"):
        window.player.load(None, audio=bad)
    assert window.player.timeline is timeline and window.playhead.duration == pytest.approx(0.3)


def test_speed_is_clamped_and_scrubbing_while_playing_goes_on_from_there(window, no_sound_device):
    player = window.player
    player.load(timeline_of(JAW_SCRIPT, window.document.model))
    player.set_speed(5)
    assert player.speed == 2.0
    player.set_speed(0.1)
    assert player.speed == 0.25
    player.play()
    window.playhead.set_time(0.2)
    assert player.is_playing and player._anchor_time == pytest.approx(0.2)
    player.pause()
    assert player.state == "paused"


def test_on_a_machine_without_output_the_real_audio_path_is_silent(tmp_path):
    """No monkeypatching: PortAudio itself finds no output device here (CI, servers)."""
    from workbench.playback.audio_output import AudioOutput, load_clip, output_available

    if output_available():
        pytest.skip("this machine has an audio output")
    wav = tmp_path / "a.wav"
    wav.write_bytes(wav_bytes(np.zeros(4000), 8000))
    clip = load_clip(wav)
    assert clip.duration == pytest.approx(0.5) and clip.source == str(wav)
    output = AudioOutput()
    assert output.start(clip, 0.1) is False
    assert output.position() is None and not output.is_playing
    output.stop()


def test_another_model_stops_and_keeps_only_what_it_can_drive(window, synthetic_model_path):
    player = window.player
    player.load(timeline_of(JAW_SCRIPT, window.document.model))
    player.play()
    model = engine.load_model(synthetic_model_path)
    window.document.replace_model(model, synthetic_model_path)
    assert player.state == "stopped" and window.playhead.time == 0.0
    window.playhead.set_time(0.15)
    assert window.document.value("jaw_open") == pytest.approx(0.8)
