#!/usr/bin/env python3
"""Render the default head's gallery into docs/images/ (run from the project root).

    .venv/bin/python docs/make_gallery.py

One PNG per pose (``gallery-<name>.png``) and a labelled contact sheet
(``gallery.png``) used by the README and docs/default-head.md.
"""

import sys
from pathlib import Path

from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.outputs.render import render_model  # noqa: E402

POSES = [
    ("neutral", "neutral", {}, "front"),
    ("jaw-open", "jaw open", {"jaw_open": 0.8}, "front"),
    ("nod", "nod", {"head_nod": 0.3}, "side"),
    ("turn", "turn", {"head_turn": 0.6}, "front"),
    ("gaze-left", "gaze left", {"eye_left_turn": 0.45, "eye_right_turn": 0.45}, "front"),
    ("eyes-closed", "eyes closed", {"eyelid_left_close": 1.0, "eyelid_right_close": 1.0}, "front"),
    ("brows-up", "brows up", {"brow_raise": 1.0}, "front"),
    ("three-quarter", "three-quarter", {"jaw_open": 0.3, "brow_raise": 0.6}, "three-quarter"),
]


def main() -> int:
    out = ROOT / "docs" / "images"
    out.mkdir(parents=True, exist_ok=True)
    head = engine.load_model()
    tiles = []
    for key, label, values, view in POSES:
        image = render_model(head, values, view=view, size=(480, 600), path=out / f"gallery-{key}.png")
        tile = Image.fromarray(image).resize((240, 300), Image.LANCZOS)
        ImageDraw.Draw(tile).text((8, 6), label, fill=(40, 40, 40))
        tiles.append(tile)
        print(f"gallery-{key}.png  {values}")
    columns = 4
    sheet = Image.new("RGB", (240 * columns, 300 * ((len(tiles) + columns - 1) // columns)), "white")
    for i, tile in enumerate(tiles):
        sheet.paste(tile, ((i % columns) * 240, (i // columns) * 300))
    sheet.save(out / "gallery.png", optimize=True)
    print("gallery.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
