"""A picture of the components of a multistage PCA as marker displacements (§3.1.2).

:func:`plot_components` draws one row per component, front and side views,
the mean markers with the shapes at ± a few standard deviations; it returns
the image and, given a path, writes it as PNG. Lengths are mm, sizes pixels.
"""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path

import numpy as np

from engine.mocap.pca import Articulation
from engine.outputs.png_file import write_png
from engine.outputs.raster import draw_box, draw_dot, draw_line, draw_text

LIP_CONTOUR = ("8.4", "8.6", "8.1", "8.5", "8.3", "8.7", "8.2", "8.8", "8.4")   # around the mouth

PANEL = 300            # pixels per panel side
HEADER = 22            # pixels of text above each row


def plot_components(art: Articulation, path: str | Path | None = None, amplitude: float = 2.0) -> np.ndarray:
    """A picture of every component as marker displacements: one row per component, front and side views.

    Grey: the mean markers (the lip contour 8.x joined in order); red: the
    shape at ``+amplitude`` standard deviations, blue at ``−amplitude``, with
    a line from each mean marker to its ``+`` position. Both views use one
    scale (true mm), the front view with the subject's left on the right,
    the side view with the face to the right. A component whose largest
    motion would be too small to see is magnified, and its row says by how
    much (``X5``). Returns the (H, W, 3) uint8
    image and, with ``path``, writes it as PNG.
    """
    views = (("FRONT", 0, 1), ("SIDE", 2, 1))
    # Small components are drawn magnified (×2, ×5, ×10 …, shown in the row's title) so that
    # their largest marker motion is at least 4 % of the picture's span.
    span = max(float(np.ptp(art.mean, axis=0).max()), 1e-6)
    gains = [_gain(amplitude * np.abs(c).max(), 0.04 * span) for c in art.components]
    shapes = [art.mean] + [art.mean + s * g * amplitude * c for c, g in zip(art.components, gains, strict=True)
                         for s in (1, -1)]
    pts = np.concatenate(shapes)
    n_rows = art.n_components
    width, height = 2 * PANEL, n_rows * (PANEL + HEADER) + 2 * HEADER
    image = np.full((height, width, 3), 255, dtype=np.uint8)
    extent = max(float(np.ptp(pts, axis=0).max()), 1e-6)
    scale = 0.8 * PANEL / extent
    grey, red, blue = (150, 150, 150), (210, 30, 30), (30, 60, 210)
    draw_text(image, "GREY MEAN", 8, 4, grey)
    draw_text(image, f"RED +{amplitude:g} SD", 140, 4, red)
    draw_text(image, f"BLUE -{amplitude:g} SD", 290, 4, blue)
    for col, (title, _, _) in enumerate(views):
        draw_text(image, title, col * PANEL + PANEL // 2 - 6 * len(title) // 2, HEADER + 4, (0, 0, 0))
    contour = [art.markers.index(m) for m in LIP_CONTOUR if m in art.markers]
    for k in range(n_rows):
        top = 2 * HEADER + k * (PANEL + HEADER)
        label = f"PC{k + 1}  STAGE {art.stages[k]}  {100 * art.explained_variance_ratio[k]:.1f}%"
        if gains[k] != 1:
            label += f"  X{gains[k]:g}"
        draw_text(image, label, 8, top + 6, (0, 0, 0))
        shown = gains[k] * amplitude * art.components[k]
        for col, (_, ax, ay) in enumerate(views):
            left = col * PANEL
            centre = np.array([pts[:, ax].min() + pts[:, ax].max(), pts[:, ay].min() + pts[:, ay].max()]) / 2

            def to_px(p: np.ndarray, left: int = left, ax: int = ax, ay: int = ay, centre: np.ndarray = centre,
                      top: int = top) -> np.ndarray:
                return np.column_stack([left + PANEL / 2 + (p[:, ax] - centre[0]) * scale,
                                        top + HEADER + PANEL / 2 - (p[:, ay] - centre[1]) * scale])

            draw_box(image, left, top + HEADER, PANEL, PANEL - 2, (225, 225, 225))
            mean_px = to_px(art.mean)
            plus_px = to_px(art.mean + shown)
            minus_px = to_px(art.mean - shown)
            for shape, colour in ((mean_px, grey), (minus_px, blue), (plus_px, red)):
                if len(contour) > 1:
                    for a, b in pairwise(contour):
                        draw_line(image, shape[a], shape[b], colour)
            for i in range(len(art.markers)):
                draw_line(image, mean_px[i], plus_px[i], red)
                draw_dot(image, minus_px[i], blue, 2)
                draw_dot(image, plus_px[i], red, 2)
                draw_dot(image, mean_px[i], (60, 60, 60), 2)
    if path is not None:
        write_png(path, image)
    return image


def _gain(largest: float, wanted: float) -> float:
    """1, or the smallest of 2, 5, 10, 20, 50 … that makes ``largest`` at least ``wanted``."""
    if largest <= 0 or largest >= wanted:
        return 1.0
    for exponent in range(7):
        for step in (1, 2, 5):
            gain = step * 10.0 ** exponent
            if gain > 1 and largest * gain >= wanted:
                return gain
    return 1e6
