"""The hair contact sheet of docs/hair.md: heads with and without hair, neutral and with the brows raised and
lowered, front and three-quarter. Run: ``xvfb-run -a python docs/make_hair_gallery.py``."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

from engine.identity import Identity, make_identity_head
from engine.identity.hair_style import HairChoice
from engine.outputs.render import render_model

OUT = Path(__file__).parent / "images" / "hair"
HEADS = [
    ("default head, short dark-brown hair", Identity(), dict(style="short", colour="dark-brown")),
    ("woman of 22, long hair", Identity({"sex": 0.0, "age": 22}), dict(style="long")),
    ("man of 60, short grey hair, beard", Identity({"sex": 1.0, "age": 60}),
     dict(style="short", colour="grey", beard="beard", brows="thick")),
    ("man of 35, tied brown hair, stubble", Identity({"sex": 1.0, "age": 35, "asian": 1.0}),
     dict(style="tied", colour="brown", beard="stubble")),
    ("default head, bald, thin brows", Identity(), dict(style="none", brows="thin")),
]
POSES = [("neutral", "front", {}), ("three-quarter", "three-quarter", {}),
         ("AU1+2 (brows up)", "front", {"AU1_left": 1, "AU1_right": 1, "AU2_left": 1, "AU2_right": 1}),
         ("AU4 (brows down)", "front", {"AU4_left": 1, "AU4_right": 1})]
SIZE = (300, 400)


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    sheet = Image.new("RGB", (SIZE[0] * len(POSES) + 10, (SIZE[1] + 22) * len(HEADS)), "white")
    draw = ImageDraw.Draw(sheet)
    for row, (label, identity, hair) in enumerate(HEADS):
        head = make_identity_head(identity, hair=HairChoice.parse(**hair))
        for col, (pose, view, values) in enumerate(POSES):
            started = time.perf_counter()
            picture = render_model(head, values, view=view, size=SIZE)
            print(f"{label} / {pose}: {time.perf_counter() - started:.2f} s, {head.n_vertices} vertices")
            sheet.paste(Image.fromarray(np.asarray(picture)), (5 + col * SIZE[0], row * (SIZE[1] + 22) + 20))
            draw.text((8 + col * SIZE[0], row * (SIZE[1] + 22) + 4), f"{label}: {pose}" if col == 0 else pose,
                      fill="black")
    sheet.save(OUT / "contact-sheet.png")


if __name__ == "__main__":
    main()
