"""The viewport shows the head in the look ``render`` draws it in (View → Look), and its own shading on request.

The head on screen, with the viewport's camera put where ``render``'s is, is compared with the engine's
render of the same pose in the same look: the same shader, lights, baked occlusion and background give
the same picture within a few grey levels (what differs: VTK's FXAA pass on the screen against our FXAA
on the read-back frame, and the normals the viewport computes itself). The controls — another look, the
occlusion taken away, the workbench's own shading — must each be farther off.
``AP_SCREENSHOT_DIR=DIR`` also writes the screenshots there.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtGui import QImage

from engine.outputs.look_actors import OCCLUSION_ARRAY
from engine.outputs.looks import DEFAULT_LOOK
from engine.outputs.render import aim_camera, render_model
from engine.paths import default_model_path

SIZE = (360, 480)
TOLERANCE = 3.0                 # mean |viewport − render| over the picture, of 255


def _pixels(window) -> np.ndarray:
    image = window.viewport.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    return pixels[:, :image.width() * 3].reshape(image.height(), image.width(), 3).copy()


def _as_render(window, qtbot) -> np.ndarray:
    """The viewport's picture with its camera where ``render --view front`` puts it for the viewport's size."""
    viewport = window.viewport
    width, height = viewport.plotter.width(), viewport.plotter.height()
    aim_camera(viewport.plotter.renderer, window.document.model, "front", width, height)
    viewport.render_now()
    qtbot.wait(30)
    return _pixels(window)


def _keep(name: str, picture: np.ndarray) -> None:
    folder = os.environ.get("AP_SCREENSHOT_DIR")
    if folder:
        from engine.outputs.png_file import write_png

        Path(folder).mkdir(parents=True, exist_ok=True)
        write_png(Path(folder) / name, picture)


@pytest.fixture
def head_window(make_window):
    window = make_window(default_model_path(), size=None)
    window.resize(900, 700)
    return window


def _difference(window, qtbot, look, face: bool = False) -> tuple[float, np.ndarray, np.ndarray]:
    """Mean |viewport − render| over the picture (``face``: over the eyes, nose and mouth only)."""
    screen = _as_render(window, qtbot)
    height, width = screen.shape[:2]
    render = render_model(window.document.model, {}, size=(width, height), look=look)
    difference = np.abs(screen.astype(int) - render.astype(int))
    if face:
        difference = difference[int(0.38 * height):int(0.75 * height), int(0.3 * width):int(0.7 * width)]
    return float(difference.mean()), screen, render


def test_the_viewport_starts_in_the_default_look_and_the_view_menu_offers_every_look(head_window):
    viewport = head_window.viewport
    assert viewport.look is not None and viewport.look.name == DEFAULT_LOOK
    menu = head_window.look_menu
    assert list(menu.look_actions) == ["portrait", "flat", "legacy", "workbench"]
    assert menu.look_actions[DEFAULT_LOOK].isChecked()
    assert menu in [action.menu() for action in head_window.menus["&View"].actions() if action.menu()]


@pytest.mark.parametrize("name", ["portrait", "flat"])
def test_the_viewport_draws_a_look_as_render_does(head_window, qtbot, name):
    head_window.look_menu.choose(name)
    viewport = head_window.viewport
    assert viewport.look.name == name and QSettings().value("view/look") == name
    for key in viewport.part_keys():                  # every mesh: the shader, and the occlusion it reads
        actor = viewport.part_actor(key)
        assert actor.GetProperty().GetInterpolationAsString() == "Physically based rendering"
        assert viewport.part_mesh(key).GetPointData().GetArray(OCCLUSION_ARRAY) is not None
    assert viewport.plotter.renderer.GetUseFXAA()
    difference, screen, render = _difference(head_window, qtbot, name)
    _keep(f"viewport-{name}.png", screen)
    _keep(f"viewport-{name}-render.png", render)
    other = "flat" if name == "portrait" else "portrait"
    control = float(np.abs(screen.astype(int) - render_model(head_window.document.model, {},
                                                             size=screen.shape[1::-1], look=other)).mean())
    face, _, _ = _difference(head_window, qtbot, name, face=True)
    print(f"{name}: viewport against render {difference:.2f} grey levels ({face:.2f} over the face); "
          f"against {other} {control:.2f}")
    assert difference < TOLERANCE and face < TOLERANCE
    assert control > 2 * TOLERANCE


def test_occlusion_lost_in_the_viewport_shows(head_window, qtbot):
    """A viewport that dropped the baked occlusion (every point open sky) no longer matches the render:
    it is farther from it than the matching viewport is, and lighter (occlusion only darkens). How many
    grey levels the occlusion takes off depends on the skin's own lightness, so the control is held
    against the matching viewport's own difference, not a fixed figure."""
    head_window.look_menu.choose("portrait")
    viewport = head_window.viewport
    matched, _, _ = _difference(head_window, qtbot, "portrait", face=True)
    for key in viewport.part_keys():
        values = viewport.part_mesh(key).GetPointData().GetArray(OCCLUSION_ARRAY)
        values.Fill(1.0)
        values.Modified()
    difference, screen, render = _difference(head_window, qtbot, "portrait", face=True)
    height, width = screen.shape[:2]
    lighter = float((screen.astype(int) - render.astype(int))[int(0.38 * height):int(0.75 * height),
                                                              int(0.3 * width):int(0.7 * width)].mean())
    print(f"portrait without occlusion: {difference:.2f} grey levels from the render over the face "
          f"(matching: {matched:.2f}), {lighter:.2f} lighter")
    assert difference > matched + 1.0 and lighter > 1.0


def test_the_workbench_shading_comes_back_and_is_remembered(head_window, qtbot):
    menu = head_window.look_menu
    menu.choose("workbench")
    viewport = head_window.viewport
    assert viewport.look is None and QSettings().value("view/look") == "workbench"
    actor = viewport.part_actor("skin")
    assert actor.GetProperty().GetInterpolationAsString() != "Physically based rendering"
    assert viewport.plotter.renderer.GetLights().GetNumberOfItems() == 5      # pyvista's light kit
    assert not viewport.plotter.renderer.GetUseFXAA()
    difference, screen, _ = _difference(head_window, qtbot, "portrait")
    _keep("viewport-workbench.png", screen)
    assert difference > TOLERANCE
    menu.choose("legacy")
    assert viewport.look.name == "legacy" and viewport.plotter.renderer.GetLights().GetNumberOfItems() == 3
    menu.choose("portrait")
    assert viewport.look.name == "portrait"
    assert viewport.part_mesh("skin").GetPointData().GetArray(OCCLUSION_ARRAY) is not None
