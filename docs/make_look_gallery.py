#!/usr/bin/env python3
"""Render the three looks side by side on the default head, for docs/looks.md.

    xvfb-run -a .venv/bin/python docs/make_look_gallery.py      (from the project root)

Writes ``docs/images/looks/presets.png``: ``portrait``, ``flat`` and ``legacy``,
left to right, at rest (top row) and with the jaw half open (bottom row),
front view, each 360 × 480. Every picture is ``engine.outputs.render.render_model``
of the committed default head; nothing else changes between the columns.
"""

import sys
from pathlib import Path

import numpy as np
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import engine
from engine.outputs.render import render_model

LOOKS = ("portrait", "flat", "legacy")
SIZE = (360, 480)


def main() -> int:
    model = engine.load_model()
    poses = [None, {"jaw_open": 0.5} if "jaw_open" in {p.name for p in model.parameters} else None]
    rows = [np.concatenate([render_model(model, pose, size=SIZE, look=look)[..., :3] for look in LOOKS], axis=1)
            for pose in poses]
    out = Path(__file__).resolve().parent / "images" / "looks" / "presets.png"
    out.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(np.concatenate(rows, axis=0).astype(np.uint8)).save(out, optimize=True)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
