"""The teeth read as teeth (issue 32; engine/outputs/occlusion.py "The teeth", docs/looks.md): measured from the
pixels of front renders of the default head. Between lips parted with the jaw nearly closed (AU10, as in
Disgust and Anger) the front teeth are light enamel, lighter than the skin, not a grey slab; in an open
mouth the side teeth at the mouth's corners are darker than the front ones, not two light patches
("fangs"). The lip-reader's measure of the open mouth (tests/engine/test_mouth_and_eyes.py) still holds."""

from __future__ import annotations

import numpy as np
import pytest

from engine import load_model
from engine.outputs.render import render_model

SIZE = (600, 800)
LIPS_APART = {"AU10_left": 1.0, "AU10_right": 1.0, "AU10_middle": 1.0, "jaw_open": 0.05}
OPEN = {"jaw_open": 0.4}


def luminance(rgb: np.ndarray) -> np.ndarray:
    return np.asarray(rgb.astype(float) @ [0.2126, 0.7152, 0.0722])


def teeth_pixels(values):
    """The render of ``values`` and where it shows the teeth (found in a render with green teeth)."""
    head, marked = load_model(), load_model()
    assert marked.vertex_colors is not None
    colours = marked.vertex_colors.copy()
    for part in ("teeth_upper", "teeth_lower"):
        colours[marked.vertex_part == marked.parts.index(part)] = (0, 255, 0)
    marked.vertex_colors = colours
    marked.changed()
    picture = render_model(head, values, size=SIZE)
    green = render_model(marked, values, size=SIZE).astype(int)
    teeth = (green[..., 1] > green[..., 0] + 60) & (green[..., 1] > green[..., 2] + 60)
    return picture, teeth


@pytest.fixture(scope="module")
def lips_apart():
    return teeth_pixels(LIPS_APART)


@pytest.fixture(scope="module")
def mouth_open():
    return teeth_pixels(OPEN)


def test_parted_lips_show_light_enamel_not_a_grey_slab(lips_apart):
    picture, teeth = lips_apart
    assert teeth.sum() > 400, "the teeth must show between the parted lips"
    rows, cols = np.nonzero(teeth)
    middle = teeth & (np.abs(np.arange(SIZE[0]) - cols.mean()) < (cols.max() - cols.min()) / 6)[None, :]
    enamel = picture[middle].astype(float)
    below = picture[rows.max() + 25:rows.max() + 35, int(cols.mean()) - 10:int(cols.mean()) + 10].reshape(-1, 3)
    chin_skin = float(luminance(below).mean())
    shown = float(luminance(enamel).mean())
    # measured: 154 against the skin's 127 (it was 106, darker than the skin: the grey slab)
    assert shown > 140 and shown > 1.1 * chin_skin, f"front teeth {shown:.0f}, skin below the lip {chin_skin:.0f}"
    spread = float((enamel.max(axis=1) - enamel.min(axis=1)).mean())
    assert spread < 40, f"enamel is near white, not tinted ({spread:.0f})"


def test_an_open_mouth_has_no_light_patches_at_its_corners(mouth_open):
    picture, teeth = mouth_open
    cols = np.nonzero(teeth)[1]
    left, right = cols.min(), cols.max()
    width = right - left
    x = np.arange(SIZE[0])[None, :]
    centre = teeth & (np.abs(x - (left + right) / 2) < width / 6)
    corners = teeth & ((x < left + width / 6) | (x > right - width / 6))
    assert centre.sum() > 30 and corners.sum() > 30
    front, sides = float(luminance(picture[centre]).mean()), float(luminance(picture[corners]).mean())
    # measured: 139 against 147 (it was 186 against 118: two light patches at the corners)
    assert sides < front, f"the corner teeth {sides:.0f} are lighter than the front teeth {front:.0f}"
