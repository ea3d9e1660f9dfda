"""No backdrop baked into the texture (issue 19, "Texture").

Where the fitted head lies a little outside the true one in a photograph (the
top of the scalp, the rims of the ears and the neck), its texels projected
into the photograph land on the backdrop. Before, they took its pale grey;
now a photograph on a plain backdrop gives such texels no weight
(:mod:`engine.photofit.backdrop`) and the fill takes them. Measured on the
synthetic truth of ``test_photofit.py``: the atlas texels whose colour is the
backdrop's (within 15 RGB of a colour of the photographs' backdrops) are
painted red on a black texture, and the fitted head is rendered with it from
the front and three-quarter: the red pixels near the head's outline are the
backdrop a viewer sees. A face as pale as the backdrop must still take its
colour from the photograph (``test_a_face_as_pale_as_the_backdrop_is_the_person``).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.ndimage import binary_erosion

from engine.model.texture import ModelTexture, TextureImage
from engine.outputs.render import render_model
from engine.photofit import fit_photos, texture
from engine.photofit.backdrop import subject_weight
from engine.photofit.silhouette import BORDER
from tests.engine.test_photofit import synthetic, two_views  # noqa: F401

pytestmark = pytest.mark.slow

TOLERANCE = 15.0                    # RGB distance from a backdrop colour that counts as the backdrop
RIM_PX = 12                         # px inside the rendered head's outline that count as its rim
VIEWS = ("front", "three-quarter")


def backdrop_colours(photos):
    return np.unique(np.round(np.concatenate([np.median(p[:, :max(int(p.shape[1] * BORDER), 1)].astype(float),
                                                        axis=1) for p in photos.values()])), axis=0)


def backdrop_pixels(head, colours):
    """Pixels of the rendered head's rim (front, three-quarter) whose texel has the backdrop's colour.

    The rim is what lies within RIM_PX of the head's outline in the render: where a fit a little
    outside the person takes the backdrop. (Inside the face the synthetic skin's pattern has a pale
    patch as pale as the backdrop, which is the person and belongs in the texture.)"""
    atlas = head.texture.images[0].pixels.astype(float)
    nearest = np.min([np.linalg.norm(atlas - c, axis=2) for c in colours], axis=0)
    marks = np.zeros(atlas.shape, dtype=np.uint8)
    marks[nearest < TOLERANCE] = (255, 0, 0)
    counts = {}
    for view in VIEWS:
        picture = render_model(_with_image(head, marks), view=view, size=(450, 600)).astype(int)
        white = render_model(_with_image(head, np.full_like(marks, 255)), view=view, size=(450, 600)).astype(int)
        on_head = np.abs(white - render_model(_with_image(head, np.zeros_like(marks)), view=view,
                                              size=(450, 600)).astype(int)).max(axis=2) > 30
        rim = on_head & ~binary_erosion(on_head, iterations=RIM_PX)
        red = (picture[..., 0] - picture[..., 1] > 60) & (picture[..., 0] - picture[..., 2] > 60)
        counts[view] = int((red & rim).sum())
    return counts


def _with_image(head, pixels):
    marked = head.copy()
    marked.texture = ModelTexture(head.texture.corner_uv, [TextureImage("marks", pixels)], head.texture.face_image)
    return marked


def test_no_backdrop_is_baked_into_the_texture(synthetic, two_views, monkeypatch):  # noqa: F811
    _, photos, points, _ = synthetic
    colours = backdrop_colours(photos)
    after = backdrop_pixels(two_views.head, colours)
    monkeypatch.setattr(texture, "subject_weight", lambda *_: None)        # every pixel used, as before
    before = backdrop_pixels(fit_photos(photos, points).head, colours)
    print(f"rendered pixels of backdrop colour: before {before}, after {after}")
    for view in VIEWS:
        assert before[view] > 500, "the measure must see the rim the unmasked texture has"
        assert after[view] < 100 and after[view] < 0.05 * before[view]


def test_a_pale_highlight_inside_the_head_is_still_the_person():
    photo = np.full((120, 90, 3), 228, dtype=np.uint8)
    photo[20:100, 20:70] = (180, 130, 110)
    photo[50:56, 40:46] = 228                                # a highlight exactly the backdrop's colour
    weight = subject_weight(photo)
    assert weight is not None
    assert weight[53, 43] == 1.0 and weight[60, 5] == 0.0 and weight[60, 20] == 0.0


def test_a_busy_backdrop_uses_every_pixel():
    noise = (np.random.default_rng(5).random((200, 150, 3)) * 255).astype(np.uint8)
    assert subject_weight(noise) is None
