"""The documentation screenshot of the main window: docs/images/workbench-main.png.

It writes into a temporary folder, so test runs leave the tree clean; to
refresh the picture in the docs, point it at docs/images:

    AP_SCREENSHOT_DIR=docs/images xvfb-run -a .venv/bin/pytest tests/workbench/test_screenshot.py

It uses the default head when it exists, the synthetic test head otherwise.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PySide6.QtGui import QImage

import engine

SCREENSHOT_NAME = "workbench-main.png"


def test_screenshot_of_the_main_window(make_window, synthetic_model_path, qtbot, tmp_path):
    SCREENSHOT = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / SCREENSHOT_NAME
    head = engine.default_model_path()
    window = make_window(head if head.exists() else synthetic_model_path, size=(1280, 800))
    panel = window.parameter_panel
    for name, fraction in (("jaw_open", 0.35), ("brow_raise", 0.6)):
        if name in panel.rows:
            row = panel.row(name)
            row.slider.setValue(row.position_of(row.parameter.maximum * fraction))
    # An unsaved edit, so the picture shows the Edit menu's state: Undo enabled, the title marked.
    from workbench.document.undo_commands import WeightsChangedCommand

    document = window.document
    name = "jaw_open"
    region = document.model.regions[name]
    document.push(WeightsChangedCommand(document, name, region.indices, region.weights))
    assert window.actions_by_id["edit.undo"].isEnabled() and window.isWindowModified()
    assert window.autosaver.autosave_now()
    assert window.statusBar().currentMessage().startswith("Autosaved")
    qtbot.wait(50)  # let the last repaint land before grabbing

    SCREENSHOT.parent.mkdir(parents=True, exist_ok=True)
    image = window.grab().toImage()
    assert image.save(str(SCREENSHOT))

    # The viewport must show the model, not an empty background or a black GL surface.
    view = window.viewport.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(view.constBits(), np.uint8).reshape(view.height(), view.bytesPerLine())
    pixels = pixels[:, :view.width() * 3].reshape(view.height(), view.width(), 3).astype(int)
    center = pixels[view.height() // 2 - 20:view.height() // 2 + 20, view.width() // 2 - 20:view.width() // 2 + 20]
    corner = pixels[5:25, 5:25]
    assert pixels.std() > 10
    red_minus_blue = center[..., 0].mean() - center[..., 2].mean()
    assert red_minus_blue > 20, "the middle of the view should be skin, warmer than the blue-grey background"
    assert corner[..., 2].mean() >= corner[..., 0].mean()
