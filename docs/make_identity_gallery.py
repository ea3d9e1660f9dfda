#!/usr/bin/env python3
"""Render eight contrasting identities neutral, speaking ``a``, Happy and Surprise, for docs/identity.md.

Each wears hair (docs/hair.md; one bald man), its own skin and iris colour (docs/skin.md).

    .venv/bin/python docs/make_identity_gallery.py       (from the project root)

Everything comes from the committed configuration: the default head, the
identity targets (``engine/data/identity``), the Finnish phone table (the ``a`` row)
and the shipped library (Happy, Surprise at the middle of their apex).
Writes ``docs/images/identity/gallery.png`` (front views) and prints the
inner-lip gap of each identity at rest, at ``a`` and at the bilabial closure.
"""

import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from engine.commands import load_library  # noqa: E402
from engine.identity import Identity, make_identity_head  # noqa: E402
from engine.identity.hair_style import HairChoice  # noqa: E402
from engine.outputs.render import render_model  # noqa: E402
from engine.speech.articulation import load_articulation  # noqa: E402
from engine.timeline.expressions import gallery_entries  # noqa: E402

OUT = ROOT / "docs" / "images" / "identity"
SIZE = (300, 380)
ONLY = {"african": 0.0, "asian": 0.0, "caucasian": 0.0}
PEOPLE = [      # label, identity values, hair (style, beard, brows; the colour chosen from the person)
    ("woman 25, African", {**ONLY, "sex": 0.0, "age": 25, "african": 1.0}, ("tied", "none", "medium")),
    ("man 25, African", {**ONLY, "sex": 1.0, "age": 25, "african": 1.0}, ("short", "stubble", "medium")),
    ("woman 28, Asian", {**ONLY, "sex": 0.0, "age": 28, "asian": 1.0}, ("long", "none", "thin")),
    ("man 60, Asian", {**ONLY, "sex": 1.0, "age": 60, "asian": 1.0}, ("short", "moustache", "thick")),
    ("woman 70, European", {**ONLY, "sex": 0.0, "age": 70, "caucasian": 1.0}, ("short", "none", "thin")),
    ("man 30, European", {**ONLY, "sex": 1.0, "age": 30, "caucasian": 1.0, "muscle": 0.8}, ("short", "beard", "thick")),
    ("woman 45, mixed, heavy", {"sex": 0.1, "age": 45, "weight": 0.9}, ("long", "none", "medium")),
    ("man 80, European, thin", {**ONLY, "sex": 1.0, "age": 80, "caucasian": 1.0, "weight": 0.15},
     ("none", "none", "medium")),
]


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    table = load_articulation()
    a_vowel = {p: table.target("a", p) for p in table.parameters}
    library = load_library()
    columns = ["neutral", "a", "Happy", "Surprise"]
    rows = []
    for label, values, (style, beard, brows) in PEOPLE:
        head = make_identity_head(Identity(values), hair=HairChoice.parse(style=style, beard=beard, brows=brows))
        poses = {e.name: e.pose(head) for e in gallery_entries(library, head) if e.name in ("Happy", "Surprise")}
        tiles = [render_model(head, pose, size=SIZE)
                 for pose in ({}, a_vowel, poses["Happy"], poses["Surprise"])]
        lm = {name: head.landmark_positions(v) for name, v in
              (("rest", {}), ("a", a_vowel), ("closed", {"lower_lip_raise": 1.0}))}
        gaps = {k: float(np.linalg.norm(v["2.2"] - v["2.3"])) for k, v in lm.items()}
        print(f"{label:26s} inner lip gap: rest {gaps['rest']:.2f} mm, a {gaps['a']:.2f} mm, "
              f"closed {gaps['closed']:.2f} mm")
        rows.append((label, tiles))
    w, h = SIZE
    sheet = Image.new("RGB", (w * len(columns) + 170, h * len(rows) + 30), "white")
    draw = ImageDraw.Draw(sheet)
    for c, name in enumerate(columns):
        draw.text((170 + c * w + w // 2 - 20, 8), name, fill="black")
    for r, (label, tiles) in enumerate(rows):
        draw.text((8, 30 + r * h + h // 2), label, fill="black")
        for c, tile in enumerate(tiles):
            sheet.paste(Image.fromarray(tile), (170 + c * w, 30 + r * h))
    sheet.save(OUT / "gallery.png")
    print(OUT / "gallery.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
