"""View ▸ Landmarks: the model's feature points drawn on the face, following the pose (in the main window).

Real rendering: the spheres are found in the grabbed viewport by their colour.
To refresh the documentation picture:

    AP_SCREENSHOT_DIR=docs/images ./bootstrap test -q tests/workbench/test_landmarks_view.py
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from PySide6.QtGui import QColor, QImage

import engine
from workbench.viewport.landmark_overlay import LANDMARK_COLOR, LIFT_MM


def _landmark_pixels(window) -> int:
    """How many viewport pixels have the landmarks' colour."""
    window.viewport.render_now()
    image = window.viewport.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    pixels = pixels[:, :image.width() * 3].reshape(image.height(), image.width(), 3).astype(int)
    target = np.array(QColor(LANDMARK_COLOR).getRgb()[:3])
    return int((np.abs(pixels - target).max(axis=2) < 40).sum())


def test_landmarks_show_on_demand_and_follow_the_pose(make_window, qtbot, tmp_path):
    window = make_window(engine.default_model_path(), size=(1280, 800))
    model, overlay, action = window.document.model, window.landmarks, window.actions_by_id["view.landmarks"]
    assert len(model.landmarks) > 10 and not action.isChecked() and overlay.shown_ids() == []
    assert action.shortcut().toString() == "Ctrl+Shift+L" and not action.icon().isNull()
    assert _landmark_pixels(window) < 20                   # nothing of that colour on the plain head

    action.trigger()
    assert window.view_state.landmarks and overlay.shown_ids() == list(model.landmarks)
    at_rest = overlay.shown_points()
    vertices = model.vertices[[model.landmarks[i] for i in overlay.shown_ids()]]
    assert np.allclose(np.linalg.norm(at_rest - vertices, axis=1), LIFT_MM, atol=1e-6)   # lifted off the skin
    qtbot.wait(50)
    shot = Path(os.environ.get("AP_SCREENSHOT_DIR") or tmp_path) / "workbench-landmarks.png"
    assert window.grab().toImage().save(str(shot))
    assert _landmark_pixels(window) > 200

    chin = overlay.shown_ids().index("2.1")
    window.document.set_values({"jaw_open": 0.8})
    posed = overlay.shown_points()
    chin_vertex = window.document.vertices()[model.landmarks["2.1"]]
    assert np.linalg.norm(posed[chin] - chin_vertex) < LIFT_MM + 1e-6
    assert np.linalg.norm(posed[chin] - at_rest[chin]) > 3.0             # it went down with the jaw

    action.trigger()
    assert not window.view_state.landmarks and overlay.shown_ids() == []
    assert _landmark_pixels(window) < 20


def test_a_model_without_landmarks_shows_none(window):
    assert window.document.model.landmarks == {}
    window.actions_by_id["view.landmarks"].trigger()
    assert window.view_state.landmarks and window.landmarks.shown_ids() == []
    assert _landmark_pixels(window) < 20
