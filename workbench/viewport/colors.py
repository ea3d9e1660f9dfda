"""Display colours of a model's parts.

A model with painted per-vertex colours (:attr:`engine.Model.vertex_colors`:
eyebrows, iris, pupil) is drawn in those, as ``engine.outputs.render`` does; this
module is for models without them. A model file may give each part a colour (``<part name="skin"
color="#e0ac94"/>``, kept in :attr:`engine.Model.part_colors`); parts
without one get a default chosen from their name, so the default head's
skin, eyes, teeth, tongue and eyelashes look right without any colours in
the file.

>>> default_part_color("eyelashes_left")
'#2b211c'
"""

from __future__ import annotations

import re

import engine

SKIN = "#e0ac94"
EYE = "#f3f0ea"
TEETH = "#efe6cc"
TONGUE = "#c4525e"
EYELASHES = "#2b211c"
FALLBACK = "#c9c4bd"

# First match wins, so the more specific names ("eyelashes", "eyebrow") come before "eye".
_RULES: tuple[tuple[str, str], ...] = (
    (r"lash|brow|hair", EYELASHES),
    (r"eye|iris|sclera|cornea", EYE),
    (r"teeth|tooth", TEETH),
    (r"tongue", TONGUE),
    (r"skin|head|face|body|neck", SKIN),
)
_HEX = re.compile(r"#[0-9a-fA-F]{6}")


def default_part_color(part: str) -> str:
    """A hex colour for a part, judged from its name alone."""
    name = part.lower()
    for pattern, color in _RULES:
        if re.search(pattern, name):
            return color
    return FALLBACK


def part_color(model: engine.Model, part: str) -> str:
    """The colour to draw ``part`` with: the model's own, else the default for its name."""
    color = model.part_colors.get(part)
    if color is not None and _HEX.fullmatch(color):
        return color
    return default_part_color(part)


def hex_to_rgb(color: str) -> tuple[int, int, int]:
    """``"#e0ac94"`` → ``(224, 172, 148)``."""
    return int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16)


def base_vertex_colors(model: engine.Model):
    """(N, 3) uint8: each vertex's ordinary colour (the model's painted colours, else its part's)."""
    import numpy as np

    if model.vertex_colors is not None:
        return np.ascontiguousarray(model.vertex_colors, dtype=np.uint8)
    table = np.array([hex_to_rgb(part_color(model, part)) for part in model.parts] or [[0, 0, 0]],
                     dtype=np.uint8)
    return table[model.vertex_part]
