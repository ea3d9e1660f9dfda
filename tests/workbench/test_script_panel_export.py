"""Export speech…: MP4 with audio, WAV, tracks and landmarks CSV; Cancel leaves nothing.

One Festival run for the whole module (``spoken``); the window gets it as its
last result, as if Say had just been pressed.
"""

from __future__ import annotations

import csv
import shutil

import numpy as np
import pytest
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QApplication, QMessageBox, QPushButton

import engine
from engine.errors import UserError

DEFAULT_HEAD = engine.default_model_path()
SENTENCE = "Hyvää <Blink/> huomenta, mitä kuuluu?"
pytestmark = [
    pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="the default head is not built"),
    pytest.mark.skipif(shutil.which("festival") is None or shutil.which("ffmpeg") is None,
                       reason="Festival or ffmpeg is not installed"),
]


@pytest.fixture(scope="module")
def spoken(tmp_path_factory):
    from engine.speech.requests import SayRequest, run_say

    # With visual prosody (seeded): its brows and nods go into the files too.
    return run_say(SayRequest(SENTENCE, engine.load_model(), prosody_seed=3), tmp_path_factory.mktemp("said"))


@pytest.fixture
def said_window(make_window, spoken):
    window = make_window(DEFAULT_HEAD)
    window.script_panel.adopt(spoken)
    return window


def export_through_dialog(qtbot, window, folder, *, base="hello", fps=15.0, size=(160, 120), kinds=None):
    """Open Speech > Export speech…, fill the dialog in as a user would, press Export."""
    def fill():
        dialog = QApplication.activeModalWidget()
        assert dialog.objectName() == "script_panel.export_dialog"
        dialog.folder_edit.setText(str(folder))
        dialog.base_edit.setText(base)
        dialog.fps_box.setValue(fps)
        dialog.width_box.setValue(size[0])
        dialog.height_box.setValue(size[1])
        for kind, box in dialog.kind_boxes.items():
            box.setChecked(kind in (kinds or ("mp4", "wav", "tracks", "landmarks")))
        dialog.accept()
    action = window.actions_by_id["speech.export"]
    assert action.isEnabled()
    QTimer.singleShot(0, fill)
    action.trigger()


def test_export_writes_a_playable_video_with_audio_and_the_tables(said_window, spoken, qtbot, tmp_path):
    from engine.outputs.video_probe import probe, read_frames
    from engine.speech.synthesis import read_wav

    window = said_window
    with qtbot.waitSignal(window.speech_exporter.ended, timeout=120000) as ended:
        export_through_dialog(qtbot, window, tmp_path)
    assert ended.args == ["written"]
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["hello-landmarks.csv", "hello-tracks.csv", "hello.mp4", "hello.wav"]
    assert "hello.mp4" in window.statusBar().currentMessage()

    seconds = spoken.speech.end_ms / 1000.0         # the audio, or the last command if that ends later
    assert seconds >= spoken.duration
    frames = int(np.ceil(seconds * 15 - 1e-9))
    info = probe(tmp_path / "hello.mp4")
    assert (info.width, info.height, info.fps) == (160, 120, 15)
    assert info.frames == frames
    assert info.audio_codec == "aac" and info.audio_duration == pytest.approx(frames / 15, abs=0.05)
    # The mouth moves: the open ä of "Hyvää" and the closed m of "huomenta" look different.
    phones = spoken.speech.utterance.phones
    open_frame = int(next(p for p in phones if p.label == "@:").mid_ms * 15 / 1000)
    closed_frame = int(next(p for p in phones if p.label == "m").mid_ms * 15 / 1000)
    pictures = read_frames(tmp_path / "hello.mp4", [open_frame, closed_frame]).astype(float)
    assert np.abs(pictures[0] - pictures[1]).mean() > 0.5

    samples, rate = read_wav(tmp_path / "hello.wav")
    assert len(samples) / rate == pytest.approx(spoken.duration, abs=1e-3)     # the WAV is the speech alone
    np.testing.assert_allclose(samples, spoken.speech.utterance.samples, atol=1 / 32767)

    with open(tmp_path / "hello-tracks.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][0] == "time_ms" and {"jaw_open", "eyelid_left_close", "brow_raise"} <= set(rows[0])
    brows = [float(row[rows[0].index("brow_raise")]) for row in rows[1:]]
    assert max(brows) > 0.1
    assert len(rows) - 1 == frames
    jaw = rows[0].index("jaw_open")
    assert float(rows[1 + open_frame][jaw]) == pytest.approx(
        spoken.speech.timeline.values_at(open_frame * 1000 / 15)["jaw_open"], abs=1e-3)
    with open(tmp_path / "hello-landmarks.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][:2] == ["frame", "time_ms"] and len(rows) - 1 == frames


def test_cancel_during_export_leaves_no_file(said_window, qtbot, tmp_path, monkeypatch):
    monkeypatch.setattr(QMessageBox, "question", staticmethod(lambda *a, **k: QMessageBox.StandardButton.Yes))
    (tmp_path / "long.wav").write_bytes(b"an older file of the same name")
    window = said_window
    exporter = window.speech_exporter
    export_through_dialog(qtbot, window, tmp_path, base="long", fps=60.0, size=(320, 240),
                          kinds=("wav", "tracks", "landmarks", "mp4"))
    assert exporter.busy
    dialog = exporter.progress_dialog
    qtbot.waitUntil(lambda: dialog.value() >= 2, timeout=60000)     # the video is being rendered
    cancel_button = dialog.findChild(QPushButton)
    assert cancel_button.text() == "Cancel"
    with qtbot.waitSignal(exporter.ended, timeout=60000) as ended:
        qtbot.mouseClick(cancel_button, Qt.MouseButton.LeftButton)
    assert ended.args == ["cancelled"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long.wav"]        # no partial or hidden files
    assert (tmp_path / "long.wav").read_bytes() == b"an older file of the same name"
    assert "cancelled" in window.statusBar().currentMessage()


# An impossible export (a missing folder, a bad name) keeps the dialog open: test_script_panel_export_folder.py


def test_export_plan_checks():
    from engine.outputs.speech_files import ExportPlan

    plan = ExportPlan(DEFAULT_HEAD.parent, "x", {"mp4"}, size=(161, 120))
    with pytest.raises(UserError, match="even"):
        plan.check()
    with pytest.raises(UserError, match="nothing to export"):
        ExportPlan(DEFAULT_HEAD.parent, "x", set()).check()
    with pytest.raises(UserError, match="not a file name"):
        ExportPlan(DEFAULT_HEAD.parent, "a/b", {"wav"}).check()


def test_form_labels_show_their_mnemonics_and_alt_letter_moves_to_the_field(said_window, qtbot):
    """No literal '&' on screen ("&Folder:", "Frame &size (px):"); Alt+F, Alt+B, … focus the field named."""
    from PySide6.QtWidgets import QFormLayout, QLabel
    from pytestqt.exceptions import TimeoutError as QtBotTimeout

    labels_seen, focused = {}, {}

    def look():
        dialog = QApplication.activeModalWidget()
        assert dialog.objectName() == "script_panel.export_dialog"
        form = dialog.findChild(QFormLayout)
        for row in range(form.rowCount()):
            label = form.itemAt(row, QFormLayout.ItemRole.LabelRole).widget()
            plain = QLabel(label.text().replace("&", ""))
            plain.setFont(label.font())
            # a mnemonic is drawn as an underline, not as a character: the label is as wide as its plain text
            labels_seen[plain.text()] = (label.buddy() is not None or "&" not in label.text(),
                                         label.sizeHint().width() == plain.sizeHint().width())
        dialog.activateWindow()
        qtbot.waitUntil(lambda: QApplication.activeWindow() is dialog)     # the mnemonics work in the active window
        for letter, field in (("F", dialog.folder_edit), ("S", dialog.width_box), ("B", dialog.base_edit),
                              ("R", dialog.fps_box), ("C", dialog.view_box)):
            # through the QWindow, as the window system delivers keys, so Qt's shortcut map sees them
            qtbot.keyClick(dialog.windowHandle(), getattr(Qt.Key, f"Key_{letter}"), Qt.KeyboardModifier.AltModifier)
            try:
                qtbot.waitUntil(field.hasFocus, timeout=2000)
                focused[letter] = True
            except QtBotTimeout:
                focused[letter] = False
        dialog.reject()

    QTimer.singleShot(0, look)
    said_window.actions_by_id["speech.export"].trigger()
    rows = ("Files:", "Folder:", "Base name:", "Frame size (px):", "Frame rate:", "Camera:")
    assert labels_seen == dict.fromkeys(rows, (True, True))      # (a buddy where there is a mnemonic, no '&' drawn)
    assert focused == dict.fromkeys("FSBRC", True)
