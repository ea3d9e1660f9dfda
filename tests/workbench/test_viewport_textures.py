"""The viewport draws a textured model with its images, and its heat map and tools' colours as on any model."""

from __future__ import annotations

import numpy as np
from PySide6.QtGui import QImage

import engine
from engine.model import Model
from engine.model.texture import ModelTexture, TextureImage
from tests.engine.test_textures import red_blue, textured_plane


def _viewport_pixels(window) -> np.ndarray:
    view = window.viewport.grab().toImage().convertToFormat(QImage.Format.Format_RGB888)
    pixels = np.frombuffer(view.constBits(), np.uint8).reshape(view.height(), view.bytesPerLine())
    return pixels[:, :view.width() * 3].reshape(view.height(), view.width(), 3).astype(int)


def _left_right(pixels: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    h, w = pixels.shape[:2]
    rows = slice(h // 2 - 5, h // 2 + 5)
    return (pixels[rows, w // 2 - 60:w // 2 - 30].reshape(-1, 3).mean(axis=0),
            pixels[rows, w // 2 + 10:w // 2 + 40].reshape(-1, 3).mean(axis=0))


def test_textured_model_shows_its_image_until_a_heat_map_is_shown(make_window, tmp_path, qtbot):
    path = engine.save_model(textured_plane(), tmp_path / "plane.xml")
    window = make_window(path, size=(900, 700))
    viewport = window.viewport
    assert viewport.textures_shown() == ["surface@red_blue"]
    assert viewport.part_keys() == ["surface", "surface@red_blue"] and viewport.part_names == ["surface"]
    qtbot.wait(50)
    left, right = _left_right(_viewport_pixels(window))
    assert left[0] > 120 and left[0] > 2 * left[2], left
    assert right[2] > 120 and right[2] > 2 * right[0], right
    window.view_state.select_parameter("lift")           # the heat map of its weights replaces the image
    assert viewport.textures_shown() == []
    model = window.document.model
    from engine.painting import heat_colors

    window.view_state.set_heat_map(False)
    assert viewport.textures_shown() == ["surface@red_blue"]
    ordinary = viewport.displayed_colors()
    window.view_state.set_heat_map(True)
    expected = heat_colors(model.regions["lift"].dense(model.n_vertices), base=ordinary)
    assert np.array_equal(viewport.displayed_colors(), expected)


def test_a_seam_vertex_moves_and_hides_as_one(make_window, tmp_path):
    texture = ModelTexture([[0, 0], [.25, 0], [.25, 1], [0, 1], [.75, 0], [1, 0], [1, 1], [.75, 1]],
                           [TextureImage("halves", red_blue(64, 8))], [0, 0])
    model = Model([[-50, -50, 0], [0, -50, 0], [0, 50, 0], [-50, 50, 0], [50, -50, 0], [50, 50, 0]],
                  [4, 0, 1, 2, 3, 4, 1, 4, 5, 2], texture=texture)
    window = make_window(engine.save_model(model, tmp_path / "seam.xml"), size=(900, 700))
    viewport = window.viewport
    mesh = viewport.part_mesh("surface@halves")
    assert mesh.n_points == 8                          # vertices 1 and 2 are drawn twice (the seam)
    viewport.update_points([1], [[0.0, -50.0, 10.0]])
    copies = mesh.points[viewport._parts["surface@halves"].vertex_indices == 1]
    np.testing.assert_allclose(copies, [[0, -50, 10], [0, -50, 10]])
    np.testing.assert_allclose(viewport.displayed_points()[1], [0, -50, 10])
    # both copies of a seam vertex have one normal: no shading seam
    normals = viewport.displayed_normals([2, 2])
    assert np.all(np.isfinite(normals))
    drawn = np.asarray(mesh.point_data["Normals"])[viewport._parts["surface@halves"].vertex_indices == 2]
    np.testing.assert_allclose(drawn[0], drawn[1], atol=1e-6)
    window.view_state.set_part_visible("surface", False)
    assert not viewport.part_actor("surface@halves").GetVisibility()
