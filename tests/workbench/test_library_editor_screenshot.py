"""Documentation screenshots of the library editor and the expression gallery.

They write into a temporary folder, so test runs leave the tree clean; to
refresh the pictures in the docs:

    AP_SCREENSHOT_DIR=docs/images ./bootstrap test -q tests/workbench/test_library_editor_screenshot.py

They use the default head when it exists, the synthetic test head otherwise.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget

import engine

SMILE = """# A lopsided smile: the subject's left lip corner higher, the cheeks a little raised.
$command = LopsidedSmile
$description = a half smile, stronger on the left
$mandatory = at
$optional = amplitude=100, onset=300, apex=900, offset=500, left=1
$interp = cosine
AU12_left * left = 0,0; 200,0.9; 300,1; 600,0
AU12_right = 0,0; 400,0.4
AU6_left = 0.5
$proc = attack-hold-release

$command = Smirk
$mandatory = at
$optional = amplitude=100, onset=300, apex=900, offset=500
AU12_lef = 0.6      # misspelt: the model has no such parameter
$proc = attack-hold-release
"""
SYNTHETIC = SMILE.replace("AU12_left", "jaw_open").replace("AU12_right", "brow_raise").replace("AU6_left", "head_turn")


def _model_path(synthetic_model_path) -> Path:
    head = engine.default_model_path()
    return head if head.exists() else synthetic_model_path


def _out(tmp_path, name: str) -> Path:
    path = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    return path


def test_screenshot_of_the_library_editor(make_window, synthetic_model_path, qtbot, tmp_path):
    path = _model_path(synthetic_model_path)
    window = make_window(path, size=(1500, 1000))
    window.library_editor_dock.show()
    window.resizeDocks([window.library_editor_dock], [480], Qt.Orientation.Vertical)
    timeline = window.findChild(QDockWidget, "dock:timeline")
    if timeline is not None:
        window.resizeDocks([timeline, window.library_editor_dock], [470, 1030], Qt.Orientation.Horizontal)
    editor = window.library_editor
    text = SMILE if path != synthetic_model_path else SYNTHETIC
    editor.set_text(text, tmp_path / "LopsidedSmile.lib")
    editor.form.set_value("left", 0.8)
    assert editor.text.error_lines() == [15]
    assert len(editor.plot.curves) == 3
    assert editor.preview()
    window.player.pause()
    window.playhead.set_time(0.7)
    qtbot.wait(100)
    shot = _out(tmp_path, "workbench-library-editor.png")
    assert window.grab().save(str(shot))
    image = editor.plot.grab().toImage()
    assert image.width() > 200


def test_screenshot_of_the_expression_gallery(make_window, synthetic_model_path, qtbot, tmp_path):
    path = _model_path(synthetic_model_path)
    window = make_window(path, size=(1400, 940))
    dock = window.expression_gallery_dock
    for other in window.findChildren(QDockWidget):
        if other is not dock and window.dockWidgetArea(other) == Qt.DockWidgetArea.LeftDockWidgetArea:
            window.tabifyDockWidget(dock, other)             # one tab group: the gallery gets the column
    dock.show()
    dock.raise_()
    window.resizeDocks([dock], [420], Qt.Orientation.Horizontal)
    gallery = window.expression_gallery
    gallery.thumbnails.render_all()
    assert set(gallery.thumbnails.pixmaps) == set(gallery.entries)
    name = "Happy" if "Happy" in gallery.entries else next(iter(gallery.entries))
    gallery.items[name].listWidget().setCurrentItem(gallery.items[name])
    timeline = gallery.preview(name)
    window.player.pause()
    window.playhead.set_time(gallery.entries[name].apex_time / 1000)
    assert np.isclose(window.document.value(timeline.activations[0].parameter),
                      timeline.values_at(gallery.entries[name].apex_time)[timeline.activations[0].parameter])
    qtbot.wait(100)
    shot = _out(tmp_path, "workbench-expression-gallery.png")
    assert window.grab().save(str(shot))
