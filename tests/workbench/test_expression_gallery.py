"""The expression gallery in a real window: thumbnails, click to play, intensity."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt

import engine
from engine.commands import load_library, parse_commands_text, translate
from engine.timeline.timeline import Timeline

GAPE = """$command = Gape
$description = Astonished: brows up, jaw dropped
$mandatory = at
$optional = amplitude=100, onset=200, apex=600, offset=300
$interp = cosine
brow_raise = 0.8
jaw_open = 0,0; 100,0.5; 200,0.6
$proc = attack-hold-release
"""


def pixels(pixmap) -> np.ndarray:
    image = pixmap.toImage().convertToFormat(pixmap.toImage().Format.Format_RGB888)
    raw = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    return raw.reshape(image.height(), image.bytesPerLine())[:, :3 * image.width()].copy()


def click(qtbot, gallery, name: str) -> None:
    item = gallery.items[name]
    view = item.listWidget()
    view.scrollToItem(item)
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=view.visualItemRect(item).center())


@pytest.fixture
def gallery(window, tmp_path):
    (tmp_path / "Gape.lib").write_text(GAPE)
    window.library_sources.set_folders([tmp_path])
    window.actions_by_id["library.gallery"].trigger()          # Library → Expression gallery
    assert window.expression_gallery_dock.isVisible()
    return window.expression_gallery


def test_every_expression_and_parameter_has_a_thumbnail(window, gallery, qtbot):
    # The synthetic head has no action units: its parameters show, and the onset/apex/offset commands
    # that fit it (shipped ones driving its parameters, and Gape from the user's folder).
    assert [gallery.expressions_list.item(i).text() for i in range(gallery.expressions_list.count())] == \
        ["BrowRaise", "Gape", "HeadTurn", "JawOpen"]
    assert [gallery.units_list.item(i).text() for i in range(gallery.units_list.count())] == \
        ["head_turn", "jaw_open", "brow_raise"]
    with qtbot.waitSignal(gallery.thumbnails.drained, timeout=60000):
        pass                                       # rendered lazily while the dock is visible
    assert set(gallery.thumbnails.pixmaps) == {"BrowRaise", "Gape", "HeadTurn", "JawOpen", "head_turn", "jaw_open",
                                               "brow_raise"}
    pictures = {name: pixels(p) for name, p in gallery.thumbnails.pixmaps.items()}
    assert pictures["jaw_open"].std() > 10                       # a face, not a blank
    assert not np.array_equal(pictures["jaw_open"], pictures["brow_raise"])
    assert not np.array_equal(pictures["Gape"], pictures["head_turn"])
    assert gallery.items["Gape"].icon().cacheKey() != gallery.items["jaw_open"].icon().cacheKey()


def test_clicking_an_expression_plays_it_through_the_player(window, gallery, qtbot, tmp_path):
    click(qtbot, gallery, "Gape")
    player = window.player
    assert player.is_playing and set(player.driven) == {"brow_raise", "jaw_open"}
    player.pause()
    model = window.document.model
    script = parse_commands_text('<commands><Gape at="0"/></commands>')
    expected = Timeline(translate(script, load_library([tmp_path]), model), model)
    assert window.playhead.duration == pytest.approx(expected.end / 1000) == pytest.approx(1.1)
    for seconds in (0.1, 0.5, 0.9):              # onset, apex, offset
        window.playhead.set_time(seconds)
        for name in ("brow_raise", "jaw_open"):
            assert window.document.value(name) == pytest.approx(expected.values_at(seconds * 1000)[name])
    window.playhead.set_time(0.5)
    assert window.document.value("brow_raise") == pytest.approx(0.8)


def test_clicking_a_parameter_plays_onset_apex_offset_and_intensity_scales_it(window, gallery, qtbot):
    click(qtbot, gallery, "jaw_open")
    player = window.player
    assert player.driven == ["jaw_open"]
    player.pause()
    window.playhead.set_time(0.8)                                 # inside the apex
    assert window.document.value("jaw_open") == pytest.approx(1.0)     # the parameter's maximum
    window.playhead.set_time(0.0)
    assert window.document.value("jaw_open") == pytest.approx(0.0)

    gallery.intensity.setValue(40)                                # replays the last preview at 40 %
    player.pause()
    window.playhead.set_time(0.8)
    assert window.document.value("jaw_open") == pytest.approx(0.4)

    click(qtbot, gallery, "Gape")
    player.pause()
    window.playhead.set_time(0.5)
    assert window.document.value("brow_raise") == pytest.approx(0.8 * 0.4)
    assert "40 %" in player.title


DEFAULT_HEAD = engine.default_model_path()


@pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason="default head not built")
def test_default_head_lists_the_35_action_units_and_the_expressions(make_window, qtbot):
    window = make_window(DEFAULT_HEAD)
    gallery = window.expression_gallery
    units = [gallery.units_list.item(i).text() for i in range(gallery.units_list.count())]
    assert len(units) == 35 and all(name.startswith("AU") for name in units)
    expressions = [gallery.expressions_list.item(i).text() for i in range(gallery.expressions_list.count())]
    assert expressions[:9] == ["Neutral", "Happy", "Sad", "Surprise", "Fear", "Anger", "Disgust", "Contempt",
                               "HappySurprise"]
    click(qtbot, gallery, "Happy")
    assert set(window.player.driven) == {"AU6_left", "AU6_right", "AU12_left", "AU12_right"}
    window.player.pause()
    window.playhead.set_time((400 + 750) / 1000)                  # the middle of Happy's apex
    assert window.document.value("AU12_left") == pytest.approx(1.0)
