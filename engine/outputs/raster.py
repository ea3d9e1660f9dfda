"""Drawing on RGB pictures held as numpy arrays: a 5 × 7 bitmap font, lines, dots, boxes.

Enough for labels on contact sheets and diagrams without a plotting or font
library. Everything clips to the picture.

>>> import numpy as np
>>> image = np.zeros((20, 60, 3), np.uint8)
>>> draw_text(image, "PC1 0.5s", 1, 1, (255, 255, 255), scale=1)
>>> bool(image.any())
True
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

Colour = Sequence[int] | np.ndarray
"""An RGB colour: three values 0–255."""
Point = Sequence[float] | np.ndarray
"""A point (x, y) in pixels."""

_ROWS = {
    "0": "01110 10001 10011 10101 11001 10001 01110", "1": "00100 01100 00100 00100 00100 00100 01110",
    "2": "01110 10001 00001 00010 00100 01000 11111", "3": "11110 00001 00001 01110 00001 00001 11110",
    "4": "00010 00110 01010 10010 11111 00010 00010", "5": "11111 10000 11110 00001 00001 10001 01110",
    "6": "00110 01000 10000 11110 10001 10001 01110", "7": "11111 00001 00010 00100 01000 01000 01000",
    "8": "01110 10001 10001 01110 10001 10001 01110", "9": "01110 10001 10001 01111 00001 00010 01100",
    "A": "01110 10001 10001 11111 10001 10001 10001", "B": "11110 10001 10001 11110 10001 10001 11110",
    "C": "01110 10001 10000 10000 10000 10001 01110", "D": "11110 10001 10001 10001 10001 10001 11110",
    "E": "11111 10000 10000 11110 10000 10000 11111", "F": "11111 10000 10000 11110 10000 10000 10000",
    "G": "01110 10001 10000 10111 10001 10001 01111", "I": "01110 00100 00100 00100 00100 00100 01110",
    "L": "10000 10000 10000 10000 10000 10000 11111", "M": "10001 11011 10101 10101 10001 10001 10001",
    "N": "10001 11001 10101 10011 10001 10001 10001", "O": "01110 10001 10001 10001 10001 10001 01110",
    "P": "11110 10001 10001 11110 10000 10000 10000", "R": "11110 10001 10001 11110 10100 10010 10001",
    "S": "01111 10000 10000 01110 00001 00001 11110", "T": "11111 00100 00100 00100 00100 00100 00100",
    "U": "10001 10001 10001 10001 10001 10001 01110", "X": "00000 10001 01010 00100 01010 10001 00000",
    "Y": "10001 10001 01010 00100 00100 00100 00100", "s": "00000 00000 01111 10000 01110 00001 11110",
    ".": "00000 00000 00000 00000 00000 01100 01100", "#": "01010 01010 11111 01010 11111 01010 01010",
    "%": "11000 11001 00010 00100 01000 10011 00011", "+": "00000 00100 00100 11111 00100 00100 00000",
    "-": "00000 00000 00000 11111 00000 00000 00000", " ": "00000 00000 00000 00000 00000 00000 00000",
}
GLYPHS = {ch: np.array([[bit == "1" for bit in row] for row in rows.split()]) for ch, rows in _ROWS.items()}
"""Character → 7 × 5 boolean mask."""


def glyph(ch: str) -> np.ndarray:
    """The mask of a character: itself, else its upper-case form, else a blank."""
    return GLYPHS.get(ch, GLYPHS.get(ch.upper(), GLYPHS[" "]))


def draw_text(image: np.ndarray, text: str, x: int, y: int, colour: Colour, scale: int = 2) -> None:
    """Write ``text`` with its top left at (x, y); each glyph is 5 × 7 cells of ``scale`` pixels."""
    for ch in text:
        mask = glyph(ch).repeat(scale, 0).repeat(scale, 1)
        y0, x0 = max(y, 0), max(x, 0)
        region = image[y0:y + mask.shape[0], x0:x + mask.shape[1]]
        part = mask[y0 - y:y0 - y + region.shape[0], x0 - x:x0 - x + region.shape[1]]
        region[part] = colour
        x += 6 * scale


def draw_line(image: np.ndarray, a: Point, b: Point, colour: Colour, thick: bool = True) -> None:
    """A straight line from point ``a`` to ``b`` (x, y), two pixels thick unless ``thick=False``."""
    n = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
    t = np.linspace(0.0, 1.0, n + 1)
    xs = np.round(a[0] + t * (b[0] - a[0])).astype(int)
    ys = np.round(a[1] + t * (b[1] - a[1])).astype(int)
    h, w = image.shape[:2]
    for dx, dy in ((0, 0), (1, 0), (0, 1)) if thick else ((0, 0),):
        x, y = xs + dx, ys + dy
        keep = (x >= 0) & (x < w) & (y >= 0) & (y < h)
        image[y[keep], x[keep]] = colour


def draw_dot(image: np.ndarray, p: Point, colour: Colour, radius: int) -> None:
    """A filled square of side ``2·radius + 1`` centred on ``p`` (x, y)."""
    x, y = round(float(p[0])), round(float(p[1]))
    h, w = image.shape[:2]
    image[max(y - radius, 0):min(y + radius + 1, h), max(x - radius, 0):min(x + radius + 1, w)] = colour


def draw_box(image: np.ndarray, x: int, y: int, w: int, h: int, colour: Colour) -> None:
    """The outline of a ``w`` × ``h`` rectangle with its top left at (x, y)."""
    image[y, x:x + w] = colour
    image[min(y + h, image.shape[0] - 1), x:x + w] = colour
    image[y:y + h, x] = colour
    image[y:y + h, min(x + w - 1, image.shape[1] - 1)] = colour
