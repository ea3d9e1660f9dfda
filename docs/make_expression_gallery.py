#!/usr/bin/env python3
"""Render the action units and the expressions of the default head, for docs/expressions.md.

    .venv/bin/python docs/make_expression_gallery.py       (from the project root)

Everything comes from the committed configuration: the model
(``engine/data/default-head/head.xml``) and the shipped library (``engine/library/*.lib``).
Writes to ``docs/images/expressions/``:

``action-units.png``
    every AU of Table 1 at full intensity, both sides (AU25/26/27 as
    ``jaw_open`` 0.1 / 0.5 / 1, AU39 as ``AU38`` −1, AU41 as
    ``eyelid_*_close`` 0.4), front and three-quarter views side by side;
``action-units-left.png``
    every left/right AU on the subject's left only, front view;
``expressions.png``
    every expression command at the middle of its apex (translated and
    sampled on a timeline like any script), front and three-quarter, plus a
    one-sided smile and an even blend of two commands.

The views are crops of offscreen renders (``engine.outputs.render``); the camera
frames the rest pose, so every picture of a view is seen from the same place.
About a minute on two cores.
"""

import argparse
import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.commands import load_library, parse_commands_text, translate  # noqa: E402
from engine.outputs.render import FrameRenderer  # noqa: E402
from engine.timeline.timeline import Timeline  # noqa: E402

OUT = ROOT / "docs" / "images" / "expressions"
RENDER = (800, 1000)
FACE = {"front": (0.24, 0.2, 0.76, 0.88), "three-quarter": (0.04, 0.19, 0.56, 0.87)}   # forehead to chin, fractions


def both(name, value=1.0):
    """Both sides of an AU: ``AU12`` → AU12_left and AU12_right; ``AU9*_nose`` → AU9_left_nose, …"""
    stem, _, suffix = name.partition("*")
    return {f"{stem}_left{suffix}": value, f"{stem}_right{suffix}": value}


# Every row of Table 1, at full intensity on both sides.
ACTION_UNITS = [
    ("AU1 inner brow raiser", both("AU1")),
    ("AU2 outer brow raiser", both("AU2")),
    ("AU4 brow lowerer", both("AU4")),
    ("AU5 upper lid raiser", both("AU5")),
    ("AU41 lid droop", {"eyelid_left_close": 0.4, "eyelid_right_close": 0.4}),
    ("AU6 cheek raiser", both("AU6")),
    ("AU7 lid tightener", both("AU7")),
    ("AU9 nose wrinkler", {**both("AU9*_nose"), **both("AU9*_brow")}),
    ("AU10 upper lip raiser", {**both("AU10"), "AU10_middle": 1.0}),
    ("AU11 nasolabial deepener", both("AU11")),
    ("AU12 lip corner puller", both("AU12")),
    ("AU15 lip corner depressor", both("AU15")),
    ("AU16 lower lip depressor", both("AU16")),
    ("AU17 chin raiser", {"AU17": 1.0}),
    ("AU20 lip stretcher", both("AU20")),
    ("AU23 lip tightener", {"AU23": 1.0}),
    ("AU24 lip presser", both("AU24")),
    ("AU25 lips part (jaw 0.1)", {"jaw_open": 0.1}),
    ("AU26 jaw drop (jaw 0.5)", {"jaw_open": 0.5}),
    ("AU27 mouth stretch (jaw 1)", {"jaw_open": 1.0}),
    ("AU38 nostril dilator", both("AU38")),
    ("AU39 nostril compressor", both("AU38", -1.0)),
]
LEFT = ["AU1_left", "AU2_left", "AU4_left", "AU5_left", "AU6_left", "AU7_left", "AU9_left_nose", "AU9_left_brow",
        "AU10_left", "AU11_left", "AU12_left", "AU15_left", "AU16_left", "AU20_left", "AU24_left", "AU38_left"]
# (label, script): each expression at its defaults, then a one-sided variant and an even blend.
EXPRESSIONS = [(name, f'<{name} at="0"/>') for name in
               ("Neutral", "Happy", "HappyOpen", "Sad", "Surprise", "SurpriseWide", "Fear", "Anger", "AngerOpen",
                "Disgust", "Contempt", "HappySurprise")]
EXTRAS = [
    ("Happy left=1 right=0", '<Happy at="0" right="0"/>'),
    ("Happy 50 % + Surprise 50 %", '<Happy at="0" amplitude="50"/><Surprise at="0" amplitude="50"/>'),
]


def font(size):
    try:
        return ImageFont.load_default(size=size)
    except TypeError:                     # Pillow < 10.1: the fixed bitmap font
        return ImageFont.load_default()


def crop(image, view, size):
    h, w = image.shape[:2]
    x0, y0, x1, y1 = FACE[view]
    tile = Image.fromarray(image).crop((int(x0 * w), int(y0 * h), int(x1 * w), int(y1 * h)))
    return tile.resize(size, Image.LANCZOS)


def labelled(tile, text, size=15):
    """``tile`` under a white strip holding ``text``."""
    out = Image.new("RGB", (tile.width, tile.height + size + 8), "white")
    out.paste(tile, (0, size + 8))
    ImageDraw.Draw(out).text((6, 3), text, fill=(30, 30, 30), font=font(size))
    return out


def sheet(tiles, columns, title=None):
    w, h = tiles[0].size
    top = 34 if title else 0
    rows = (len(tiles) + columns - 1) // columns
    out = Image.new("RGB", (w * columns, top + h * rows), "white")
    if title:
        ImageDraw.Draw(out).text((8, 6), title, fill=(0, 0, 0), font=font(20))
    for i, tile in enumerate(tiles):
        out.paste(tile, ((i % columns) * w, top + (i // columns) * h))
    return out


def apex_values(script, library, head):
    """Parameter values in the middle of the time every command of ``script`` holds its apex."""
    commands = parse_commands_text(f"<commands>{script}</commands>")
    timeline = Timeline(translate(commands, library, head), head)
    start, end = -np.inf, np.inf
    for command in commands:
        args = {**library[command.name].optional, **command.arguments}
        begin = args.get("at", 0.0) + args["onset"]
        start, end = max(start, begin), min(end, begin + args["apex"])
    if start > end:
        raise SystemExit(f"the commands of {script} never hold their apex together")
    return timeline.values_at((start + end) / 2)


def render_all(head, poses, renderers, size):
    """``{view: [tile, …]}`` for every pose (a values dict) in every view."""
    return {view: [crop(r.render(head.deform(values)), view, size) for values in poses]
            for view, r in renderers.items()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", help="another model file (default: the shipped default head)")
    parser.add_argument("--out", type=Path, default=OUT, help=f"the folder to write to (default: {OUT})")
    args = parser.parse_args()
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    head = engine.load_model(args.model) if args.model else engine.load_model()
    library = load_library()
    problems = library.check(head)
    if problems:
        raise SystemExit(f"the library does not bind to the default head: {problems[0]}")
    expressions = [(label, apex_values(script, library, head)) for label, script in EXPRESSIONS + EXTRAS]
    small, face = (200, 327), (240, 392)
    renderers = {view: FrameRenderer(head, size=RENDER, view=view) for view in FACE}
    try:
        au = render_all(head, [v for _, v in ACTION_UNITS], renderers, small)
        tiles = []
        for k, (label, _) in enumerate(ACTION_UNITS):
            pair = Image.new("RGB", (2 * small[0], small[1]), "white")
            pair.paste(au["front"][k], (0, 0))
            pair.paste(au["three-quarter"][k], (small[0], 0))
            tiles.append(labelled(pair, label))
        sheet(tiles, 4, "Action units of Table 1 at full intensity, both sides (front | three-quarter)").save(
            out / "action-units.png", optimize=True)
        print("action-units.png")

        left = [crop(renderers["front"].render(head.deform({name: 1.0})), "front", small) for name in LEFT]
        sheet([labelled(t, n) for t, n in zip(left, LEFT, strict=True)], 8,
              "The subject's left side only (front)").save(out / "action-units-left.png", optimize=True)
        print("action-units-left.png")

        ex = render_all(head, [v for _, v in expressions], renderers, face)
    finally:
        for r in renderers.values():
            r.close()
    tiles = []
    for k, (label, _) in enumerate(expressions):
        pair = Image.new("RGB", (2 * face[0], face[1]), "white")
        pair.paste(ex["front"][k], (0, 0))
        pair.paste(ex["three-quarter"][k], (face[0], 0))
        tiles.append(labelled(pair, label))
    sheet(tiles, 4, "Expressions at the middle of their apex (front | three-quarter)").save(
        out / "expressions.png", optimize=True)
    print("expressions.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
