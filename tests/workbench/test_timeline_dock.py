"""The timeline dock: open animations, scrub, step, draw the tracks, refuse bad files."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QMessageBox

import engine
from engine.commands import load_library, parse_commands_text, translate, write_low_level
from engine.speech.synthesis import Segment
from engine.timeline.timeline import Timeline

DEFAULT_HEAD = engine.default_model_path()
needs_default_head = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="default head not built")
NOD = '<commands>\n  <HeadNod at="1000" amplitude="60" count="2"/>\n</commands>\n'
TWO_TRACKS = """<commands>
  <activate parameter="jaw_open" interp="cosine"><key at="0" value="0"/><key at="200" value="0.9"/>
    <key at="400" value="0"/></activate>
  <activate parameter="brow_raise" interp="linear"><key at="100" value="0"/><key at="300" value="0.8"/>
    <key at="500" value="0"/></activate>
</commands>
"""

def engine_timeline(text: str, model) -> Timeline:
    return Timeline(translate(parse_commands_text(text), load_library(), model), model)


@pytest.fixture
def warnings_shown(monkeypatch):
    shown: list[str] = []

    def warning(parent, title, text, *args, **kwargs):
        shown.append(text)
        return QMessageBox.StandardButton.Ok

    monkeypatch.setattr(QMessageBox, "warning", staticmethod(warning))
    return shown


@needs_default_head
def test_head_nod_file_scrubbed_on_the_ruler_sets_the_timeline_values(make_window, qtbot, tmp_path):
    window = make_window(DEFAULT_HEAD)
    dock = window.timeline_dock
    assert dock.objectName() == "dock:timeline"
    assert window.dockWidgetArea(dock) == Qt.DockWidgetArea.BottomDockWidgetArea
    path = tmp_path / "nod.xml"
    path.write_text(NOD)
    assert dock.open_animation(path)
    timeline = engine_timeline(NOD, window.document.model)
    view = dock.track_view
    assert view.track_names == ["head_nod"]
    assert window.playhead.duration == pytest.approx(2.0)
    for seconds in (1.1665, 1.5, 0.25):
        qtbot.mouseClick(view, Qt.MouseButton.LeftButton, pos=QPoint(round(view.x_of(seconds)), 10))
        now = window.playhead.time
        assert now == pytest.approx(seconds, abs=2.0 / window.playhead.fps)
        assert window.document.value("head_nod") == pytest.approx(timeline.values_at(now * 1000)["head_nod"])
    # The slider dock shows the frame's value (through document.values_changed).
    window.playhead.set_time(1.1665)
    row = window.parameter_panel.row("head_nod")
    assert row.slider.value() == row.position_of(window.document.value("head_nod"))
    assert window.document.value("head_nod") == pytest.approx(0.09)


def test_dragging_scrubs_and_keys_step_and_play(window, qtbot, tmp_path):
    path = tmp_path / "two.xml"
    path.write_text(TWO_TRACKS)
    dock = window.timeline_dock
    assert dock.open_animation(path)
    view = dock.track_view
    qtbot.mousePress(view, Qt.MouseButton.LeftButton, pos=QPoint(round(view.x_of(0.1)), 40))
    qtbot.mouseMove(view, QPoint(round(view.x_of(0.3)), 40))
    qtbot.mouseRelease(view, Qt.MouseButton.LeftButton, pos=QPoint(round(view.x_of(0.3)), 40))
    assert window.playhead.frame == 18
    window.activateWindow()
    view.setFocus()
    qtbot.waitUntil(lambda: window.isActiveWindow() and view.hasFocus())
    qtbot.keyClick(view, Qt.Key.Key_Right)
    assert window.playhead.frame == 19
    qtbot.keyClick(view, Qt.Key.Key_Left)
    qtbot.keyClick(view, Qt.Key.Key_Left)
    assert window.playhead.frame == 17
    qtbot.keyClick(view, Qt.Key.Key_Space)
    assert window.player.is_playing
    assert window.actions_by_id["animation.play_pause"].text() == "&Pause"
    qtbot.keyClick(view, Qt.Key.Key_Space)
    assert window.player.state == "paused"
    dock.buttons["animation.stop"].click()
    assert window.playhead.time == 0.0 and window.player.state == "stopped"


def test_low_level_file_plays_the_same_values(window, tmp_path):
    model = window.document.model
    timeline = engine_timeline(TWO_TRACKS, model)
    path = tmp_path / "low.xml"
    write_low_level(timeline.activations, path)
    assert window.timeline_dock.open_animation(path)
    for frame in (0, 7, 12, 24, 30):
        window.playhead.set_frame(frame)
        expected = timeline.values_at(frame * 1000 / 60)
        for name in ("jaw_open", "brow_raise"):
            assert window.document.value(name) == pytest.approx(expected[name])


def test_tracks_csv_round_trip_plays_the_same_values(window, tmp_path):
    model = window.document.model
    timeline = engine_timeline(TWO_TRACKS, model)
    path = tmp_path / "two.csv"
    timeline.write_tracks(path, fps=50)
    assert window.timeline_dock.open_animation(path)
    assert window.playhead.fps == pytest.approx(50)
    assert window.player.driven == ["jaw_open", "brow_raise"]
    assert window.timeline_dock.track_view.track_names == ["jaw_open", "brow_raise"]
    for frame in range(0, 26, 3):
        window.playhead.set_frame(frame)
        expected = timeline.values_at(frame * 20.0)
        for name in ("jaw_open", "brow_raise"):
            assert window.document.value(name) == pytest.approx(expected[name], abs=1e-9)


@pytest.mark.parametrize("name, text, where", [
    ("unknown.xml", '<commands>\n  <HeadNodd at="1000"/>\n</commands>\n', "unknown.xml:2"),
    ("broken.xml", '<commands>\n  <activate parameter="jaw_open">\n</commands>\n', "broken.xml:"),
    ("words.csv", "time_ms,jaw_open\n0,0\n16.6,zero\n", "words.csv:3"),
    ("columns.csv", "time_ms,jaw_open\n0,0,1\n", "columns.csv:2"),
    ("nobody.csv", "time_ms,no_such_parameter\n0,0\n", "nobody.csv:1"),
])
def test_a_bad_file_shows_where_and_changes_nothing(window, tmp_path, warnings_shown, name, text, where):
    good = tmp_path / "good.xml"
    good.write_text(TWO_TRACKS)
    dock = window.timeline_dock
    assert dock.open_animation(good)
    window.playhead.set_time(0.2)
    timeline, values = window.player.timeline, window.document.values
    bad = tmp_path / name
    bad.write_text(text)
    assert not dock.open_animation(bad)
    assert len(warnings_shown) == 1 and where in warnings_shown[0]
    assert window.player.timeline is timeline
    assert window.playhead.time == pytest.approx(0.2) and window.document.values == values


def test_open_action_asks_for_a_file(window, tmp_path, monkeypatch):
    from PySide6.QtWidgets import QFileDialog

    path = tmp_path / "two.xml"
    path.write_text(TWO_TRACKS)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", staticmethod(lambda *a, **k: (str(path), "")))
    window.actions_by_id["animation.open"].trigger()
    assert window.player.title == "two" and window.playhead.duration == pytest.approx(0.5)


def _colour_count(image, rect, colour: str, tolerance: int = 40) -> int:
    from PySide6.QtGui import QColor, QImage

    from workbench.timeline_dock.track_view import LABEL_WIDTH

    image = image.convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    pixels = pixels[:, :image.width() * 3].reshape(image.height(), image.width(), 3).astype(int)
    ratio = image.devicePixelRatio()
    top, bottom = int(rect.top() * ratio), int(rect.bottom() * ratio)
    region = pixels[top:bottom, int(LABEL_WIDTH * ratio):]
    target = QColor(colour)
    distance = np.abs(region - np.array([target.red(), target.green(), target.blue()])).sum(axis=2)
    return int((distance < tolerance).sum())


def test_track_view_draws_one_curve_per_driven_parameter_and_the_phones(window, qtbot):
    from workbench.timeline_dock.track_view import TRACK_COLORS

    model = window.document.model
    phones = [Segment("#", 0, 100), Segment("m", 100, 250), Segment("a", 250, 500)]
    window.player.load(engine_timeline(TWO_TRACKS, model), phones=phones, title="two")
    view = window.timeline_dock.track_view
    assert view.track_names == ["jaw_open", "brow_raise"]
    assert view.sizeHint().height() > 3 * 34
    image = view.grab().toImage()
    first, second = view.track_rect(0), view.track_rect(1)
    assert _colour_count(image, first, TRACK_COLORS[0]) > 50          # the jaw curve in the first row
    assert _colour_count(image, second, TRACK_COLORS[1]) > 50         # the brow curve in the second
    assert _colour_count(image, first, TRACK_COLORS[1]) < 5
    window.player.load(None)
    assert view.track_names == []
