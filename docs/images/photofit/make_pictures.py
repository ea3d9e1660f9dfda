#!/usr/bin/env python3
"""The pictures of docs/photofit.md: a real photograph fitted front-only, and the synthetic ground truth.

Run from the project root (needs scikit-image for its public-domain ``astronaut`` portrait)::

    .venv/bin/python docs/images/photofit/make_pictures.py

``astronaut_points.json`` holds the landmarks placed by eye on ``skimage.data.astronaut()``.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2]))

SPEAKING = {"jaw_open": 0.35}          # an open vowel's jaw, to show the fitted head still animates


def panel(pictures: list[np.ndarray], height: int = 400) -> Image.Image:
    tiles = [Image.fromarray(p).resize((round(p.shape[1] * height / p.shape[0]), height), Image.LANCZOS)
             for p in pictures]
    out = Image.new("RGB", (sum(t.width for t in tiles), height), "white")
    x = 0
    for tile in tiles:
        out.paste(tile, (x, 0))
        x += tile.width
    return out


def main() -> None:
    from skimage import data

    from engine.formats.model_files import load_model
    from engine.outputs.render import render_model
    from engine.photofit import fit_photo_files

    with tempfile.TemporaryDirectory() as folder:
        photo = Path(folder) / "astronaut.png"
        Image.fromarray(data.astronaut()).save(photo)
        result = fit_photo_files(photo, None, HERE / "astronaut_points.json")
    head = result.head
    print(f"astronaut: landmark error {result.shape.error:.2f} px, {result.seconds}, {result.shape.identity.values}")
    size = (480, 600)
    crop = data.astronaut()[10:230, 110:310]
    pictures = [crop, render_model(load_model(), size=size), render_model(head, size=size),
                render_model(head, view="three-quarter", size=size), render_model(head, SPEAKING, size=size)]
    panel(pictures).save(HERE / "astronaut.png")

    from tests.engine import test_photofit as synthetic

    _, photos, points, _ = synthetic.synthetic.__wrapped__()
    from engine.photofit import fit_photos

    fitted = fit_photos(photos, points).head
    panel([photos["front"], render_model(fitted, size=size), photos["side"], render_model(fitted, view="side",
                                                                                              size=size)]
          ).save(HERE / "synthetic.png")


if __name__ == "__main__":
    main()
