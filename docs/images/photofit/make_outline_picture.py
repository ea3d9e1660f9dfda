#!/usr/bin/env python3
"""docs/images/photofit/outline.png: the side silhouette fitted all round (issue 19).

The side photograph of the bald, skin-coloured synthetic truth of
``tests/engine/test_photofit_outline.py``, with the outline of the head fitted
without (left) and with (right) the outline drawn over it in red, through the
fit's own side camera. Run from the project root.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from PIL import Image
from scipy.ndimage import binary_fill_holes

sys.path.insert(0, str(Path(__file__).resolve().parents[3]))

from engine.formats.model_files import load_model
from engine.photofit.raster import rasterize
from engine.photofit.texture import all_triangles
from tests.engine import test_photofit_outline as synthetic


def outline_mask(vertices: np.ndarray, camera, shape: tuple[int, int]) -> np.ndarray:
    hit, _, _ = rasterize(camera.project(vertices)[all_triangles(load_model())], shape[1], shape[0])
    drawn = binary_fill_holes(hit >= 0)
    inner = drawn & np.roll(drawn, 1, 0) & np.roll(drawn, -1, 0) & np.roll(drawn, 1, 1) & np.roll(drawn, -1, 1)
    edge = drawn & ~inner
    return edge | np.roll(edge, 1, 0) | np.roll(edge, 1, 1)


def main() -> None:
    truth, photos, points = synthetic.synthetic(False)
    photo = photos["side"]
    panels = []
    for fit in synthetic.fits(truth, photos, points):
        picture = photo.copy()
        picture[outline_mask(fit.vertices, fit.cameras["side"], photo.shape[:2])] = (230, 20, 20)
        panels.append(picture[::2, ::2])
    out = Path(__file__).with_name("outline.png")
    Image.fromarray(np.concatenate(panels, axis=1)).save(out)
    print(out)


if __name__ == "__main__":
    main()
