#!/usr/bin/env python3
"""Pictures of the default head's articulatory parameters, for docs/default-head.md.

Run from the project root::

    .venv/bin/python engine/data/default-head/articulation_pictures.py

Writes into ``docs/images/``:

* ``articulation.png`` — close-ups of the mouth at rest and with each articulatory
  parameter at 1, from the front, three-quarter and side;
* ``articulation-speech.png`` — combinations as the speech tables use them (open,
  spread and rounded vowels, and lip closure after a rounded and a spread vowel);
* ``articulation-sections.png`` — sagittal sections through the lips (upper lip blue,
  lower lip red) at rest and closed, showing that the lips meet without crossing.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]      # the checkout: engine/data/default-head → the project
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

import engine  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402

SINGLE = [
    ("rest", {}),
    ("mouth_widen 1", {"mouth_widen": 1.0}),
    ("lip_protrude 1", {"lip_protrude": 1.0}),
    ("upper_lip_raise 1", {"upper_lip_raise": 1.0}),
    ("lower_lip_raise 1", {"lower_lip_raise": 1.0}),
]
SPEECH = [
    ("open: jaw_open 0.6", {"jaw_open": 0.6}),
    ("spread: jaw 0.18, widen 0.9", {"jaw_open": 0.18, "mouth_widen": 0.9}),
    ("rounded: jaw 0.22, protrude 1", {"jaw_open": 0.22, "lip_protrude": 1.0}),
    ("closed after rounded", {"lip_protrude": 1.0, "lower_lip_raise": 1.0}),
    ("closed after spread", {"mouth_widen": 0.9, "lower_lip_raise": 1.0}),
]
VIEWS = ["front", "three-quarter", "side"]
RENDER_SIZE = (1200, 1600)
BACKGROUND = (255, 255, 255)


def mouth_centre_and_size(model, renderer, rest_image):
    """Pixel box of the lips in this view: where pushing the lip vertices away changes the picture."""
    P = model.vertices
    lm = model.landmarks
    c = P[[lm[k] for k in ("8.3", "8.4", "8.1", "8.2")]]
    margin = np.array([0, 1, 30])
    lo, hi = c.min(axis=0) - margin, c.max(axis=0) + margin
    lips = np.all((lo <= P) & (hi >= P), axis=1) & (model.vertex_part == model.parts.index("skin"))
    hidden = P.copy()
    hidden[lips] += [0.0, 0.0, -80.0]
    changed = np.abs(renderer.render(hidden).astype(int) - rest_image.astype(int)).sum(axis=-1) > 30
    ys, xs = np.nonzero(changed)
    return ((xs.min() + xs.max()) // 2, (ys.min() + ys.max()) // 2), xs.max() - xs.min()


def close_ups(model, poses, views=VIEWS):
    """{view: [image per pose]}, all cropped to the same size around the mouth."""
    out, half = {}, None
    for view in views:
        with FrameRenderer(model, size=RENDER_SIZE, view=view) as renderer:
            rest = renderer.render(model.vertices)
            (cx, cy), width = mouth_centre_and_size(model, renderer, rest)
            if half is None:                      # the front view sets the crop for every view
                hx = int(0.8 * width) + 20
                half = (hx, int(0.62 * hx))
            hx, hy = half

            def crop(image, cx=cx, cy=cy, hx=hx, hy=hy):
                padded = np.pad(image, ((hy, hy), (hx, hx), (0, 0)), mode="edge")
                return padded[cy:cy + 2 * hy, cx:cx + 2 * hx]
            out[view] = [crop(renderer.render(model.deform(values))) for _, values in poses]
    return out


def sheet(rows, column_labels, row_labels, scale=0.5, pad=6, label_height=26, label_width=110):
    tiles = [[Image.fromarray(t).resize((int(t.shape[1] * scale), int(t.shape[0] * scale)), Image.LANCZOS)
              for t in row] for row in rows]
    w, h = tiles[0][0].size
    W = label_width + len(column_labels) * (w + pad) + pad
    H = label_height + len(rows) * (h + pad) + pad
    out = Image.new("RGB", (W, H), BACKGROUND)
    draw = ImageDraw.Draw(out)
    for j, text in enumerate(column_labels):
        draw.text((label_width + pad + j * (w + pad) + 4, 8), text, fill=(20, 20, 20))
    for i, (label, row) in enumerate(zip(row_labels, tiles, strict=False)):
        y = label_height + pad + i * (h + pad)
        draw.text((8, y + h // 2 - 6), label, fill=(20, 20, 20))
        for j, tile in enumerate(row):
            out.paste(tile, (label_width + pad + j * (w + pad), y))
    return out


def sections_picture(model, states, xs=(0.0, 6.0, 12.0, 17.0), cell=(330, 200), window=(22.0, 13.0), pad=6):
    """Sagittal sections through the lips (forward = right, up = up), one row per state, one column per x.

    Upper lip blue, lower lip red, as ``engine.identity.lip_contact.LipContact`` tells them apart; the same
    scale in every cell, each window following the front of the lips."""
    from engine.identity.lip_contact import LipContact

    n = model.n_vertices
    jaw = model.regions["jaw_open"].dense(n)
    total = jaw + model.regions["head_tilt"].dense(n) + model.regions["neck_lean"].dense(n)
    share = np.divide(jaw, total, out=np.zeros(n), where=total > 0)
    skin = model.vertex_part == model.parts.index("skin")
    contact = LipContact(model.vertices, model.triangles(), skin, share, model.landmarks)
    lm = model.landmarks
    label_width, label_height = 170, 24
    W = label_width + len(xs) * (cell[0] + pad) + pad
    H = label_height + len(states) * (cell[1] + pad) + pad
    out = Image.new("RGB", (W, H), BACKGROUND)
    draw = ImageDraw.Draw(out)
    scale = cell[0] / window[0]                      # px per mm
    for j, x in enumerate(xs):
        draw.text((label_width + pad + j * (cell[0] + pad) + 4, 6), f"x = {x:g} mm", fill=(20, 20, 20))
    draw.text((W - 120, 6), f"1 mm = {scale:.0f} px", fill=(90, 90, 90))
    for i, (label, values) in enumerate(states):
        P = model.deform(values)
        y0 = label_height + pad + i * (cell[1] + pad)
        gap = np.linalg.norm(P[lm["2.2"]] - P[lm["2.3"]])
        draw.text((8, y0 + cell[1] // 2 - 14), label, fill=(20, 20, 20))
        draw.text((8, y0 + cell[1] // 2 + 2), f"2.2-2.3: {gap:.2f} mm", fill=(90, 90, 90))
        for j, x in enumerate(xs):
            upper, lower = contact.section(P, x + 1e-4)
            points = np.concatenate([upper.reshape(-1, 2), lower.reshape(-1, 2)])
            near = points[np.abs(points[:, 1] - contact.mouth_line(x)) < 4]
            z_front = near[:, 0].max() + 5.0                          # the window follows the lips
            y_mid = contact.mouth_line(x)
            tile = Image.new("RGB", cell, (250, 250, 250))
            tdraw = ImageDraw.Draw(tile)

            def to_px(p, z_front=z_front, y_mid=y_mid):
                return (cell[0] - (z_front - p[0]) * scale, cell[1] / 2 - (p[1] - y_mid) * scale)
            for segments, colour in ((upper, (40, 80, 200)), (lower, (210, 50, 50))):
                for a, b in segments:
                    tdraw.line([to_px(a), to_px(b)], fill=colour, width=2)
            crossings = contact.crossings(upper, lower)
            tdraw.text((4, 4), f"crossings {crossings}", fill=(170, 0, 0) if crossings else (90, 90, 90))
            tdraw.rectangle([0, 0, cell[0] - 1, cell[1] - 1], outline=(200, 200, 200))
            out.paste(tile, (label_width + pad + j * (cell[0] + pad), y0))
    return out


def main() -> int:
    out = ROOT / "docs" / "images"
    out.mkdir(parents=True, exist_ok=True)
    head = engine.load_model()
    crops = close_ups(head, SINGLE)
    sheet([crops[v] for v in VIEWS], [label for label, _ in SINGLE], VIEWS).save(out / "articulation.png")
    crops = close_ups(head, SPEECH, views=["front", "three-quarter"])
    sheet([crops[v] for v in ("front", "three-quarter")], [label for label, _ in SPEECH],
          ["front", "three-quarter"]).save(out / "articulation-speech.png")
    sections_picture(head, [("rest", {}), ("lower_lip_raise 1", {"lower_lip_raise": 1.0}),
                            ("+ lip_protrude 1", {"lower_lip_raise": 1.0, "lip_protrude": 1.0}),
                            ("lower_lip_raise 1.3 (beyond)", {"lower_lip_raise": 1.3})]
                     ).save(out / "articulation-sections.png")
    print("wrote", ", ".join(f"docs/images/{n}" for n in ("articulation.png", "articulation-speech.png",
                                                         "articulation-sections.png")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
