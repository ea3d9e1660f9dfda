#!/usr/bin/env python3
"""The strip of docs/capture-streams.md: frames of a real Live Link Face take on the default head.

    .venv/bin/python docs/make_capture_strip.py

Reads the two excerpts of a public range-of-motion take in
``tests/data/capture_streams/`` (see the README there), maps them with
``engine.capture`` exactly as ``capture animate`` does, picks the frame where
each of six shapes peaks, and renders those frames from the front with the
shape's recorded value under each. Writes ``docs/images/capture/llf_strip.png``.
"""

import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.capture.readers import read_capture  # noqa: E402
from engine.capture.retarget import retarget  # noqa: E402
from engine.outputs.render import render_model  # noqa: E402

DATA = ROOT / "tests" / "data" / "capture_streams"
OUT = ROOT / "docs" / "images" / "capture" / "llf_strip.png"
PICKS = [  # (take, channel that peaks, label)
    ("llf_rom_mouth.csv", None, "first frame"),
    ("llf_rom_mouth.csv", "jawOpen", "jawOpen"),
    ("llf_rom_mouth.csv", "mouthSmileLeft", "mouthSmileLeft"),
    ("llf_rom_mouth.csv", "mouthPucker", "mouthPucker"),
    ("llf_rom_mouth.csv", "browInnerUp", "browInnerUp"),
    ("llf_rom_eyes.csv", "eyeBlinkLeft", "eyeBlinkLeft"),
    ("llf_rom_eyes.csv", "eyeLookOutLeft", "eyeLookOutLeft"),
]
SIZE = (300, 340)


def main() -> None:
    head = engine.load_model()
    tiles = []
    for name, channel, label in PICKS:
        take = read_capture(DATA / name)
        mapped = retarget(take, head)
        frame = 0 if channel is None else int(np.argmax(take.channels[channel]))
        values = dict(zip(mapped.parameters, mapped.values[frame], strict=True))
        picture = Image.fromarray(render_model(head, values, view="front", size=SIZE))
        draw = ImageDraw.Draw(picture)
        caption = label if channel is None else f"{label} {take.channels[channel][frame]:.2f}"
        draw.text((8, SIZE[1] - 34), caption, fill=(0, 0, 0))
        draw.text((8, SIZE[1] - 18), f"{name.removesuffix('.csv')} t={take.times_ms[frame] / 1000:.2f}s",
                  fill=(60, 60, 60))
        tiles.append(picture)
    strip = Image.new("RGB", (SIZE[0] * len(tiles), SIZE[1]), "white")
    for i, tile in enumerate(tiles):
        strip.paste(tile, (i * SIZE[0], 0))
    OUT.parent.mkdir(parents=True, exist_ok=True)
    strip.save(OUT, optimize=True)
    print(f"wrote {OUT} ({OUT.stat().st_size // 1024} KB)")


if __name__ == "__main__":
    main()
