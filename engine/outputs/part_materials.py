"""How each part of a rendered model looks: colour and shading by the part's name, and the eyes' iris and pupil.

Parts are coloured by ``model.part_colors`` or, failing that, by their names
(skin, eye…, teeth…, tongue, eyelash…). :func:`part_material` gives a part's
colour and shading; :func:`eye_colours` paints an eyeball's iris and pupil per
vertex. Colours are ``#rrggbb`` text or RGB floats in [0, 1].

>>> part_material("teeth_upper")
('#eee4c8', 0.25, 0.75, 0.35, 30.0)
>>> hex_rgb("#ff8000").round(3).tolist()
[1.0, 0.502, 0.0]
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

# (colour, ambient, diffuse, specular, specular power) by the start of a part's name
_MATERIALS = [
    ("eyelash", ("#2a211d", 0.20, 0.80, 0.05, 5.0)),
    ("eyebrow", ("#3b2c24", 0.20, 0.80, 0.05, 5.0)),
    ("brow", ("#3b2c24", 0.20, 0.80, 0.05, 5.0)),
    ("hair", ("#3b2c24", 0.20, 0.80, 0.10, 10.0)),
    ("eye", ("#f3efe8", 0.25, 0.75, 0.60, 60.0)),
    ("teeth", ("#eee4c8", 0.25, 0.75, 0.35, 30.0)),
    ("tooth", ("#eee4c8", 0.25, 0.75, 0.35, 30.0)),
    ("tongue", ("#c4525c", 0.20, 0.80, 0.30, 25.0)),
    ("gum", ("#b85c66", 0.20, 0.80, 0.25, 20.0)),
    ("mouth", ("#9c3f4a", 0.20, 0.80, 0.20, 20.0)),
]
_SKIN = ("#e2ad8f", 0.18, 0.85, 0.12, 12.0)
_PUPIL, _IRIS, _IRIS_RIM = "#141110", "#5b7a8f", "#2e3e49"
_PUPIL_DEGREES, _IRIS_DEGREES = 11.0, 30.0   # half-angles on the eyeball, seen from its centre


def part_material(name: str, colors: Mapping[str, str] | None = None) -> tuple[str, float, float, float, float]:
    """(hex colour, ambient, diffuse, specular, specular power) for a part, by its name."""
    lowered = name.lower()
    material = _SKIN
    for prefix, candidate in _MATERIALS:
        if lowered.startswith(prefix):
            material = candidate
            break
    if colors and name in colors:
        material = (colors[name], *material[1:])
    return material


def colour_rgb(colour: str, fallback: str) -> np.ndarray:
    """A ``#rrggbb`` colour as RGB floats in [0, 1]; the fallback's if it is not one."""
    try:
        return hex_rgb(colour)
    except (ValueError, TypeError, AttributeError, IndexError):
        return hex_rgb(fallback)


def is_eyeball(part: str) -> bool:
    """Whether a part is an eyeball by its name (``eye…``, but not eyelashes, eyebrows or eyelids)."""
    lowered = part.lower()
    return lowered.startswith("eye") and not lowered.startswith(("eyelash", "eyebrow", "eyelid"))


def eye_colours(rest: np.ndarray, sclera: np.ndarray) -> np.ndarray:
    """Per-vertex RGB for an eyeball: pupil and iris around the forward (+Z) pole of the rest pose."""
    centre = (rest.min(axis=0) + rest.max(axis=0)) / 2
    offset = rest - centre
    length = np.linalg.norm(offset, axis=1)
    cos = np.divide(offset[:, 2], length, out=np.zeros(len(rest)), where=length > 0)
    angle = np.degrees(np.arccos(np.clip(cos, -1, 1)))
    colours = np.tile(sclera, (len(rest), 1))
    iris = angle < _IRIS_DEGREES
    # the iris darkens towards its rim, as real irises do
    t = np.clip((angle - _PUPIL_DEGREES) / (_IRIS_DEGREES - _PUPIL_DEGREES), 0, 1)[:, None]
    ring = (1 - t ** 2) * hex_rgb(_IRIS) + t ** 2 * hex_rgb(_IRIS_RIM)
    colours[iris] = ring[iris]
    colours[angle < _PUPIL_DEGREES] = hex_rgb(_PUPIL)
    return np.round(colours * 255).astype(np.uint8)


def hex_rgb(colour: str) -> np.ndarray:
    """A ``#rrggbb`` colour as RGB floats in [0, 1]."""
    colour = colour.lstrip("#")
    return np.array([int(colour[i:i + 2], 16) for i in (0, 2, 4)]) / 255.0
