#!/usr/bin/env python3
"""Contact sheets of the default head's mouth for the Finnish vowels and consonant classes, for docs/default-head.md.

    .venv/bin/python docs/make_mouth_contact_sheets.py       (from the project root)

Each picture is the middle of one phone spoken on its own: its targets in the
shipped table (``engine/library/articulation/finnish.phones``, read by
``engine.speech.articulation``), every parameter the table names. The views
are crops of offscreen renders (``engine.outputs.render``) around the mouth,
front and three-quarter; the camera frames the rest pose, so every picture
of a view is seen from the same place. Writes to ``docs/images/``:

``mouth-vowels.png``
    a e i o u y ä ö (Suopuhe ``@`` = ä, ``7`` = ö) and the rest pose;
``mouth-consonants.png``
    one phone of each class: bilabial p/b/m, labiodental f/v, the
    dental-alveolar t/d/n/l/s (tongue tip up), velar k/g and r;
``mouth-sections.png``
    midsagittal sections of rest, a, i, u, t/d/n, l and k/g: where the
    tongue lies (low at the vowels, its tip up behind the upper incisors for
    t, d, n, l), the teeth and the painted cavity;
``eyes-lids.png``
    the left eye at rest, AU5, AU7, AU6 + AU7 and a half blink (the lashes
    on the lids).

About 30 s on two cores.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402
from engine.speech.articulation import load_articulation  # noqa: E402

OUT = ROOT / "docs" / "images"
RENDER = (900, 1125)
CROP = {"mouth": (150, 110), "eye": (130, 80)}      # half-width, half-height in render pixels
TILE_WIDTH = 260
VOWELS = [("rest", None), ("a", "a"), ("e", "e"), ("i", "i"), ("o", "o"), ("u", "u"), ("y", "y"),
          ("ä", "@"), ("ö", "7")]
CONSONANTS = [("p b m", "p"), ("f v", "f"), ("t d", "t"), ("n", "n"), ("l", "l"), ("s", "s"), ("k g", "k"),
              ("r", "r")]
SECTIONS = [("rest", None), ("a", "a"), ("i", "i"), ("u", "u"), ("t d n", "t"), ("l", "l"), ("k g", "k")]
LIDS = [("rest", {}), ("AU5", {"AU5_left": 1.0, "AU5_right": 1.0}), ("AU7", {"AU7_left": 1.0, "AU7_right": 1.0}),
        ("AU6 + AU7", {"AU6_left": 1.0, "AU6_right": 1.0, "AU7_left": 1.0, "AU7_right": 1.0}),
        ("half blink", {"eyelid_left_close": 0.5, "eyelid_right_close": 0.5})]


def project(model, point, view: str) -> tuple[int, int]:
    """Pixel (column, row) of a rest-pose point in the render of ``view``."""
    width, height = RENDER
    focal, position, up, _ = camera_pose(framed_points(model), VIEWS[view], width, height)
    back = (position - focal) / np.linalg.norm(position - focal)
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    d = np.asarray(point, float) - position
    scale = height / 2 / (-(d @ back) * np.tan(np.radians(VIEW_ANGLE) / 2))
    return int(width / 2 + (d @ right) * scale), int(height / 2 - (d @ np.cross(back, right)) * scale)


def label_font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    """DejaVu Sans where the system has it (it draws ä and ö), else Pillow's own font."""
    try:
        return ImageFont.truetype("DejaVuSans.ttf", size)
    except OSError:
        return ImageFont.load_default(size=size)


def phone_values(table, phone: str | None) -> dict[str, float]:
    return {} if phone is None else {name: table.target(phone, name) for name in table.parameters}


def sheet(model, rows: list[tuple[str, dict[str, float]]], centre_of, crop: tuple[int, int], title: str) -> Image.Image:
    """One column per pose, one row per view (front, three-quarter), labelled."""
    font = label_font(18)
    hx, hy = crop
    tile_height = round(TILE_WIDTH * hy / hx)
    views = ["front", "three-quarter"]
    out = Image.new("RGB", (90 + TILE_WIDTH * len(rows), 40 + 30 + tile_height * len(views)), "white")
    draw = ImageDraw.Draw(out)
    draw.text((8, 8), title, fill="black", font=font)
    for r, view in enumerate(views):
        draw.text((8, 70 + r * tile_height + tile_height // 2 - 10), "front" if view == "front" else "3/4",
                  fill="black", font=font)
        cx, cy = project(model, centre_of(model), view)
        if view != "front":
            cx += hx // 4            # seen from the side, more face to the right of the mouth than to its left
        with FrameRenderer(model, size=RENDER, view=view) as renderer:
            for c, (label, values) in enumerate(rows):
                image = np.pad(renderer.render(model.deform(values)), ((hy, hy), (hx, hx), (0, 0)), mode="edge")
                tile = Image.fromarray(image[cy:cy + 2 * hy, cx:cx + 2 * hx]).resize((TILE_WIDTH, tile_height),
                                                                                   Image.LANCZOS)
                out.paste(tile, (90 + c * TILE_WIDTH, 70 + r * tile_height))
                if r == 0:
                    draw.text((90 + c * TILE_WIDTH + TILE_WIDTH // 2, 45), label, fill="black", font=font,
                              anchor="mt")
    return out


def section_segments(positions: np.ndarray, triangles: np.ndarray, x: float) -> tuple[np.ndarray, np.ndarray]:
    """Where the plane X = ``x`` cuts the triangles: (segments (k, 2, 2) in (z, y) mm, triangle index per segment)."""
    side = positions[triangles, 0] > x
    cut = np.flatnonzero(side.any(axis=1) & ~side.all(axis=1))
    segments = []
    for t in cut:
        ends = []
        for i, j in ((0, 1), (1, 2), (2, 0)):
            a, b = positions[triangles[t, i]], positions[triangles[t, j]]
            if (a[0] > x) != (b[0] > x):
                f = (x - a[0]) / (b[0] - a[0])
                p = a + f * (b - a)
                ends.append((p[2], p[1]))
        segments.append(ends[:2])
    return np.array(segments), cut


def sections(model, rows: list[tuple[str, dict[str, float]]], title: str) -> Image.Image:
    """Midsagittal sections (1 mm off the midline) through the mouth: skin, the painted cavity, teeth, tongue."""
    font = label_font(18)
    scale, (z0, z1), (y0, y1) = 4.0, (60.0, 165.0), (35.0, 115.0)
    width, height = round((z1 - z0) * scale), round((y1 - y0) * scale)
    out = Image.new("RGB", (width * len(rows), 40 + 30 + height), "white")
    draw = ImageDraw.Draw(out)
    draw.text((8, 8), title, fill="black", font=font)
    triangles = model.triangles()
    part = model.vertex_part[triangles[:, 0]]
    colours = model.vertex_colors[triangles].mean(axis=1) if model.vertex_colors is not None else None
    names = {name: k for k, name in enumerate(model.parts)}
    for c, (label, values) in enumerate(rows):
        positions = model.deform(values)
        segments, which = section_segments(positions, triangles, 1.0)
        draw.text((c * width + width // 2, 45), label, fill="black", font=font, anchor="mt")
        tile = Image.new("RGB", (width, height), "white")
        pen = ImageDraw.Draw(tile)
        for (ends, t) in zip(segments, which, strict=True):
            (za, ya), (zb, yb) = ends
            k = part[t]
            if k == names.get("tongue"):
                colour = (200, 40, 50)
            elif k in (names.get("teeth_upper"), names.get("teeth_lower")):
                colour = (40, 90, 200)
            elif colours is not None and k == names.get("skin") and colours[t] @ [0.299, 0.587, 0.114] < 110:
                colour = (60, 10, 20)
            elif k == names.get("skin"):
                colour = (170, 140, 120)
            else:
                continue
            pen.line([((za - z0) * scale, (y1 - ya) * scale), ((zb - z0) * scale, (y1 - yb) * scale)],
                     fill=colour, width=3)
        pen.rectangle([0, 0, width - 1, height - 1], outline=(200, 200, 200))
        out.paste(tile, (c * width, 70))
    return out


def mouth_centre(model) -> np.ndarray:
    lm, P = model.landmarks, model.vertices
    return (P[lm["2.2"]] + P[lm["2.3"]]) / 2 + np.array([0.0, -6.0, 0.0])


def left_eye_centre(model) -> np.ndarray:
    return model.vertices[model.landmarks["3.5"]] + np.array([0.0, 1.0, 0.0])


def main() -> int:
    model = engine.load_model()
    table = load_articulation()
    OUT.mkdir(parents=True, exist_ok=True)
    vowels = [(label, phone_values(table, phone)) for label, phone in VOWELS]
    consonants = [(label, phone_values(table, phone)) for label, phone in CONSONANTS]
    sheet(model, vowels, mouth_centre, CROP["mouth"],
          "Finnish vowels at the middle of the phone (finnish.phones)").save(OUT / "mouth-vowels.png", optimize=True)
    sheet(model, consonants, mouth_centre, CROP["mouth"],
          "Consonant classes at the middle of the phone (finnish.phones)").save(OUT / "mouth-consonants.png",
                                                                              optimize=True)
    cut = [(label, phone_values(table, phone)) for label, phone in SECTIONS]
    sections(model, cut, "Midsagittal sections: skin, oral cavity (dark), teeth (blue), tongue (red)").save(
        OUT / "mouth-sections.png", optimize=True)
    sheet(model, LIDS, left_eye_centre, CROP["eye"], "The subject's left eye: lids and lashes").save(
        OUT / "eyes-lids.png", optimize=True)
    for name in ("mouth-vowels.png", "mouth-consonants.png", "mouth-sections.png", "eyes-lids.png"):
        print(OUT / name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
