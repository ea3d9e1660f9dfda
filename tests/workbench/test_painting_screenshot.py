"""Documentation screenshots of weight painting: docs/images/workbench-painting.png and workbench-heatmap.png.

They are written to a temporary folder, so test runs leave the tree clean; to
refresh the pictures in the docs:

    AP_SCREENSHOT_DIR=docs/images xvfb-run -a .venv/bin/pytest tests/workbench/test_painting_screenshot.py
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtGui import QImage

import engine


@pytest.fixture(autouse=True)
def _painting_only(monkeypatch):
    from workbench import features

    monkeypatch.setattr(features, "INSTALLERS", ["painting:install"])


def _pixels(widget) -> np.ndarray:
    image = widget.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    data = np.frombuffer(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    return data[:, :image.width() * 3].reshape(image.height(), image.width(), 3).astype(int)


def test_screenshots_of_weight_painting(make_window, qtbot, tmp_path):
    folder = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    window = make_window(engine.default_model_path(), size=(1280, 800))
    viewport, paint = window.viewport, window.paint
    window.view_state.select_parameter("jaw_open")
    viewport.set_view("three-quarter")
    viewport.render_now()
    qtbot.wait(50)
    assert window.grab().save(str(folder / "workbench-heatmap.png"))

    viewport.set_view("front")
    paint.set_active(True)
    paint.set_brush(mode="add", radius=12.0, strength=0.35, mirror=True)
    model = window.document.model
    nose = model.vertices[model.landmarks["9.3"]]
    viewport.render_now()
    # A stroke over the left cheek (mirrored onto the right), then the cursor resting on the cheek.
    start = viewport.world_to_widget(nose + np.array([28, -8, -15]))
    end = viewport.world_to_widget(nose + np.array([45, -35, -30]))
    paint.press(*start)
    for t in np.linspace(0, 1, 12)[1:]:
        paint.drag(start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
    paint.release()
    paint.hover(*viewport.world_to_widget(nose + np.array([32, -20, -20])))
    assert paint.cursor.visible
    viewport.render_now()
    qtbot.wait(50)
    assert window.grab().save(str(folder / "workbench-painting.png"))
    pixels = _pixels(viewport)
    white = (pixels > 235).all(axis=2)                 # the brush ring is drawn white
    assert white.sum() > 50
    assert window.tool_options.current_tool == "paint"
