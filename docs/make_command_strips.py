#!/usr/bin/env python3
"""Render every shipped command playing on the default head, for docs/commands.md (run from the project root).

    .venv/bin/python docs/make_command_strips.py                 # every command in library/
    .venv/bin/python docs/make_command_strips.py --only Blink Wink

For each command of the shipped library (every ``engine/library/*.lib``) a one-command
script such as ``<commands><HeadNod at="0" count="2"/></commands>`` is
translated and sampled on a timeline, and two pictures are written to
``docs/images/commands/``:

``<Name>.png``
    a strip of 6–8 frames evenly spread over the command's span (a frame is
    moved onto each extreme of the motion no frame falls on: a nod's bottom,
    both sides of a shake), with the time under each frame and the command as
    the title; on whole-head frames a blue line is the rest pose's outline, so
    that small motions show;
``<Name>.gif``
    the whole command at 25 frames per second, same framing, about 200 px wide,
    holding the last frame a moment before it loops.

Each command is seen from where its motion shows best (``FRAMING``): a nod
from the side, a jaw from three-quarters, eyes and lids close up. A command
without an entry in ``FRAMING`` is shown whole from the front with its default
arguments. Rendering is offscreen (pyvista); no display is needed. All nine
shipped commands take under two minutes on two cores and about 2.5 MB.

The eye and brow close-ups are crops of a larger picture; where to crop comes
from the renderer's own camera placement (``engine.outputs.camera.place_camera``),
so the box stays on the eyes if the framing there changes.
"""

import argparse
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
from PIL import Image, ImageDraw, ImageFont

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import engine  # noqa: E402
from engine.commands import load_library, parse_commands_text, translate  # noqa: E402
from engine.outputs.camera import VIEWS, framed_points, place_camera  # noqa: E402
from engine.outputs.render import render_model  # noqa: E402
from engine.timeline.timeline import Timeline  # noqa: E402

# Command → (arguments besides at="0", view, region). A region crops the
# picture to a part of the face (REGIONS); None shows the whole head.
# Long holds are shortened (apex) so that the strips show the motion, not the wait.
FRAMING = {
    "HeadNod": ({"count": 2}, "side", None),
    "HeadShake": ({"count": 2}, "front", None),
    "HeadTurn": ({"angle": 30, "apex": 400}, "front", None),
    "HeadTilt": ({"angle": 12, "apex": 400}, "front", None),
    "Blink": ({}, "front", "eyes"),
    "Wink": ({"left": 1, "right": 0}, "front", "eyes"),
    "EyesLook": ({"x": 25, "y": 10, "apex": 400}, "front", "eyes"),
    "BrowRaise": ({"apex": 400}, "front", "upper-face"),
    "JawOpen": ({}, "three-quarter", None),
}
DEFAULT_FRAMING = ({}, "front", None)

# Regions of the rest pose, as boxes (x, y in mm) around parts of the default head.
REGIONS = {
    "eyes": dict(parts=("eye_left", "eye_right", "eyelashes_left", "eyelashes_right"), margin=(14.0, 12.0)),
    "upper-face": dict(parts=("eye_left", "eye_right"), margin=(30.0, 14.0), extend_up=45.0),
}

TILE = (220, 260)            # whole-head strip frame, width × height
CROP_TILE_WIDTH = 300        # a cropped strip frame is this wide (its height follows the region)
GIF_WIDTH = 200              # whole-head GIF
CROP_GIF_WIDTH = 240         # cropped GIF (the eye region is short, so a little wider)
FPS = 25
GIF_COLOURS = 96             # one palette shared by all frames
HOLD_MS = 600                # the GIF's last frame stays this long before the loop starts again
FRAME_COUNTS = (7, 8, 6)     # strip lengths tried, in order of preference
SUPERSAMPLE = 1.5            # render this much larger than shown, then shrink (smoother edges)
INK, GREY, PAPER = (35, 35, 35), (110, 110, 110), (255, 255, 255)
OUTLINE = (30, 90, 220)      # the rest pose's silhouette, drawn over whole-head frames


def command_text(name: str, arguments: dict) -> str:
    args = {"at": 0, **arguments}
    return f"<{name} " + " ".join(f'{k}="{v:g}"' for k, v in args.items()) + "/>"


def strip_times(timeline: Timeline, motion) -> tuple[np.ndarray, list[float]]:
    """6–8 evenly spaced times over the span, and the times among them that show a peak.

    A peak is a stretch where the motion is within 2 % of its largest (a nod's
    bottom, each side of a shake, a held apex). The frame count that catches
    most peaks is used, and a peak no frame falls on moves its nearest inner
    frame onto it, so every extreme of the command is in the strip.
    """
    start, end = timeline.start, timeline.end
    dense = np.linspace(start, end, round(end - start) + 1)
    amount = motion(timeline.sample(dense))
    high = np.concatenate([[False], amount >= 0.98 * amount.max(), [False]])
    edges = np.flatnonzero(np.diff(high.astype(int)))
    peaks = [(dense[a], dense[b - 1]) for a, b in zip(edges[::2], edges[1::2], strict=True)]

    def missed(times):
        return [(lo, hi) for lo, hi in peaks if not ((times >= lo - 1e-6) & (times <= hi + 1e-6)).any()]

    def cost(count):
        times = np.linspace(start, end, count)
        return len(missed(times)), sum(np.abs(times - (lo + hi) / 2).min() for lo, hi in missed(times))

    times = np.linspace(start, end, min(FRAME_COUNTS, key=cost))
    for lo, hi in missed(times):
        inner = np.arange(1, len(times) - 1)
        i = inner[np.argmin(np.abs(times[inner] - (lo + hi) / 2))]
        band = (dense >= lo) & (dense <= hi)
        times[i] = dense[band][np.argmax(amount[band])]      # the very extreme, on a whole ms
    times.sort()
    shown = []
    for lo, hi in peaks:
        inside = times[(times >= lo - 1e-6) & (times <= hi + 1e-6)]
        if inside.size:
            shown.append(float(inside[0]))
    return times, shown


def crop_box(model, view: str, region: str | None, size: tuple[int, int]):
    """(left, top, right, bottom) in pixels of ``region`` in a picture of ``size``, or None for the whole picture.

    Uses the renderer's own camera placement so that the box matches what it draws.
    """
    if region is None:
        return None
    spec = REGIONS[region]
    keep = np.isin(model.vertex_part, [model.parts.index(p) for p in spec["parts"] if p in model.parts])
    points = model.vertices[keep]
    (x0, y0, z0), (x1, y1, z1) = points.min(axis=0), points.max(axis=0)
    mx, my = spec["margin"]
    y1 += spec.get("extend_up", 0.0)
    corners = np.array([[x, y, z] for x in (x0 - mx, x1 + mx) for y in (y0 - my, y1 + my) for z in (z0, z1)])
    width, height = size
    camera = SimpleNamespace()
    place_camera(camera, framed_points(model), VIEWS[view], width, height)
    position, focal = np.array(camera.position), np.array(camera.focal_point)
    forward = (focal - position) / np.linalg.norm(focal - position)
    right = np.cross(forward, camera.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rel = corners - position
    depth = rel @ forward
    scale = (height / 2) / np.tan(np.radians(camera.view_angle) / 2)
    u = width / 2 + scale * (rel @ right) / depth
    v = height / 2 - scale * (rel @ up) / depth
    return (max(0, int(np.floor(u.min()))), max(0, int(np.floor(v.min()))),
            min(width, int(np.ceil(u.max()))), min(height, int(np.ceil(v.max()))))


def render_size(model, view: str, region: str | None, shown_width: int):
    """Size to render at, the crop box in it, and the size of one shown frame."""
    if region is None:
        scale = shown_width / TILE[0]
        shown = (shown_width, round(TILE[1] * scale))
        return (round(shown[0] * SUPERSAMPLE), round(shown[1] * SUPERSAMPLE)), None, shown
    base = (600, 700)
    left, _top, right, _bottom = crop_box(model, view, region, base)
    factor = SUPERSAMPLE * shown_width / (right - left)
    size = (round(base[0] * factor), round(base[1] * factor))
    box = crop_box(model, view, region, size)
    shown = (shown_width, round(shown_width * (box[3] - box[1]) / (box[2] - box[0])))
    return size, box, shown


def rest_outline(model, view: str, size: tuple[int, int]) -> np.ndarray:
    """Mask of the rest pose's silhouette edge (about 2 px wide at ``size``).

    The background is a vertical gradient, so each row's background colour is
    its first pixel (the framing keeps the head off the picture's sides).
    """
    rest = render_model(model, {}, view=view, size=size).astype(int)
    head = np.abs(rest - rest[:, :1]).sum(axis=2) > 30
    inside = head.copy()
    for axis in (0, 1):
        for shift in (-1, 1, -2, 2):
            inside &= np.roll(head, shift, axis=axis)
    return head & ~inside


def frames(model, timeline: Timeline, times, view: str, region: str | None, shown_width: int) -> list[Image.Image]:
    """The command at ``times``; whole-head frames carry the rest pose's outline, so small motions show."""
    size, box, shown = render_size(model, view, region, shown_width)
    outline = rest_outline(model, view, size) if region is None else None
    images = []
    for row in timeline.sample(times):
        picture = render_model(model, dict(zip(timeline.parameters, row, strict=True)), view=view, size=size)
        if outline is not None:
            picture[outline] = (0.45 * picture[outline] + 0.55 * np.array(OUTLINE)).astype(np.uint8)
        picture = Image.fromarray(picture)
        if box is not None:
            picture = picture.crop(box)
        images.append(picture.resize(shown, Image.LANCZOS))
    return images


def font(size: int):
    return ImageFont.load_default(size=size)


def strip(tiles, times, peaks, title: str, subtitle: str) -> Image.Image:
    w, h = tiles[0].size
    gap, head, foot = 4, 52, 24
    sheet = Image.new("RGB", (len(tiles) * w + (len(tiles) - 1) * gap, head + h + foot), PAPER)
    draw = ImageDraw.Draw(sheet)
    draw.text((8, 6), title, fill=INK, font=font(17))
    draw.text((8, 29), subtitle, fill=GREY, font=font(13))
    for i, (tile, t) in enumerate(zip(tiles, times, strict=True)):
        x = i * (w + gap)
        sheet.paste(tile, (x, head))
        label = f"{t:.0f} ms" + ("  (peak)" if any(abs(t - p) < 1e-6 for p in peaks) else "")
        draw.text((x + w / 2, head + h + 4), label, fill=INK, font=font(13), anchor="ma")
    return sheet


def shared_palette(images) -> Image.Image:
    """One palette for every frame of a GIF, so that the unchanging background compresses to nothing.

    Small but telling areas (irises, the outline) would lose their colour to the
    skin's many shades, so the pixels the first palette renders worst count
    more in a second choice.
    """
    step = max(1, len(images) // 6)
    sample = np.concatenate([np.asarray(im) for im in images[::step]]).astype(np.uint8)
    palette = Image.fromarray(sample).quantize(colors=GIF_COLOURS, method=Image.Quantize.MEDIANCUT)
    pixels = sample.reshape(-1, 3).astype(int)
    for _ in range(2):
        error = np.abs(pixels - np.asarray(Image.fromarray(sample).quantize(palette=palette, dither=Image.Dither.NONE)
                                           .convert("RGB")).reshape(-1, 3)).sum(axis=1)
        poor = pixels[error > 30]
        if not len(poor):
            break
        width = sample.shape[1]
        extra = np.resize(poor, (max(len(pixels) // 4 // width, 1) * width, 3))
        weighted = np.concatenate([sample.reshape(-1, 3), extra]).reshape(-1, width, 3).astype(np.uint8)
        palette = Image.fromarray(weighted).quantize(colors=GIF_COLOURS, method=Image.Quantize.MEDIANCUT)
    return palette


def write_gif(path: Path, images, times) -> None:
    labelled = []
    for image, t in zip(images, times, strict=True):
        stamped = image.copy()
        ImageDraw.Draw(stamped).text((5, stamped.height - 4), f"{t:.0f} ms", fill=INK, font=font(11), anchor="ld")
        labelled.append(stamped)
    palette = shared_palette(labelled)
    paletted = [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in labelled]
    durations = [1000 // FPS] * (len(paletted) - 1) + [HOLD_MS]
    paletted[0].save(path, save_all=True, append_images=paletted[1:], duration=durations, loop=0,
                     optimize=True, disposal=1)


def motion_measure(timeline: Timeline):
    """How far a row of values is from rest: parameters weighted by their range."""
    tree = timeline.model.parameters
    default = np.array([tree[n].default for n in timeline.parameters])
    span = np.array([tree[n].maximum - tree[n].minimum for n in timeline.parameters])
    return lambda values: (np.abs(values - default) / span).sum(axis=1)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "images" / "commands",
                        help="folder for <Name>.png and <Name>.gif (default: docs/images/commands)")
    parser.add_argument("--only", nargs="+", metavar="NAME", help="render only these commands")
    options = parser.parse_args()

    options.out.mkdir(parents=True, exist_ok=True)
    head = engine.load_model()
    library = load_library()
    names = library.names()
    if options.only:
        unknown = sorted(set(options.only) - set(names))
        if unknown:
            parser.error(f"not in the library: {', '.join(unknown)} (it has {', '.join(names)})")
        names = [n for n in names if n in options.only]
    begun = time.monotonic()
    for name in names:
        definition = library[name]
        arguments, view, region = FRAMING.get(name, DEFAULT_FRAMING)
        missing = [a for a in definition.mandatory if a != "at" and a not in arguments]
        if missing:
            print(f"{name}: skipped, needs {', '.join(missing)} (add it to FRAMING)")
            continue
        text = command_text(name, arguments)
        timeline = Timeline(translate(parse_commands_text(f"<commands>{text}</commands>"), library, head), head)
        if timeline.end <= timeline.start:
            print(f"{name}: skipped, it does not move")
            continue
        started = time.monotonic()
        times, peaks = strip_times(timeline, motion_measure(timeline))
        tiles = frames(head, timeline, times, view, region, TILE[0] if region is None else CROP_TILE_WIDTH)
        subtitle = (definition.description or f"{name} ({Path(definition.file).name})") + f"  ·  {view} view"
        subtitle += f", {region}" if region else ", blue line: rest pose"
        png = options.out / f"{name}.png"
        strip(tiles, times, peaks, text, subtitle).save(png, optimize=True)
        gif_times = timeline.frame_times(FPS, timeline.start, timeline.end)
        gif = options.out / f"{name}.gif"
        write_gif(gif, frames(head, timeline, gif_times, view, region,
                              GIF_WIDTH if region is None else CROP_GIF_WIDTH), gif_times)
        print(f"{name:10s} {text:45s} strip {len(times)} frames {png.stat().st_size / 1024:5.0f} kB, "
              f"gif {len(gif_times)} frames {gif.stat().st_size / 1024:5.0f} kB  ({time.monotonic() - started:.0f} s)")
    print(f"done in {time.monotonic() - begun:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
