"""POINTS.json: landmarks a user placed on the front (and side) photograph.

The file is ``{"front": {"<MPEG-4 id>": [x, y], ...}, "side": {...}}`` in
pixels of the photograph at its stored size, turned upright by its EXIF
orientation as :func:`engine.photofit.photos.read_photo` reads it (origin at
the top left, x right, y down). Any subset of the model's landmarks is accepted; the front photograph
needs at least :data:`REQUIRED_FRONT` (pupils, nose tip, mouth corners,
chin). The side view is optional.

>>> import json, tempfile, os
>>> path = os.path.join(tempfile.mkdtemp(), "p.json")
>>> front = {"3.5": [120, 50], "3.6": [80, 50], "9.3": [100, 80], "8.3": [115, 95], "8.4": [85, 95],
...          "2.1": [100, 130]}
>>> with open(path, "w") as f:
...     json.dump({"front": front}, f)
>>> points = read_points(path, known={*REQUIRED_FRONT, "2.2"})
>>> sorted(points), points["front"]["9.3"]
(['front'], (100.0, 80.0))
"""

from __future__ import annotations

import json
import math
from collections.abc import Collection
from pathlib import Path

from engine.photofit.errors import PhotoFitError
from engine.photofit.photos import read_input_bytes

#: What the front photograph must show: pupils, nose tip, mouth corners, chin.
REQUIRED_FRONT = ("3.5", "3.6", "9.3", "8.3", "8.4", "2.1")
VIEWS = ("front", "side")
MAX_FILE_BYTES = 1 << 20
MAX_COORDINATE = 1e6
MIN_PUPIL_DISTANCE = 8.0               # px: closer pupils leave too few pixels to fit a face to

PhotoPoints = dict[str, dict[str, tuple[float, float]]]


def read_points(path: str | Path, known: Collection[str]) -> PhotoPoints:
    """The landmarks of ``path``: view → MPEG-4 id → (x, y) pixels; ``known`` the model's landmark ids.

    Raises :class:`PhotoFitError` (one line, naming the file) for anything else.
    """
    path = Path(path)
    data = read_input_bytes(path, MAX_FILE_BYTES, "landmark file")   # no folder, device or pipe; bounded
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise PhotoFitError(f"cannot read the landmark file: {exc}", file=path,
                            line=data[:exc.start].count(b"\n") + 1) from None
    try:
        data = json.loads(text, parse_constant=_refuse_constant)
    except (ValueError, RecursionError) as exc:
        line = getattr(exc, "lineno", None)
        raise PhotoFitError(f"not valid JSON: {getattr(exc, 'msg', str(exc))[:200]}", file=path, line=line) from None
    return parse_points(data, known, path)


def parse_points(data: object, known: Collection[str], path: str | Path) -> PhotoPoints:
    """Validate decoded POINTS.json ``data`` (see :func:`read_points`)."""
    if not isinstance(data, dict):
        raise PhotoFitError('the landmark file must hold an object {"front": {...}, "side": {...}}', file=path)
    for view in data:
        if view not in VIEWS:
            raise PhotoFitError(f"unknown view {_short(view)} (use 'front' and, optionally, 'side')", file=path)
    if "front" not in data:
        raise PhotoFitError("the landmark file has no 'front' view", file=path)
    out: PhotoPoints = {}
    for view, points in data.items():
        if not isinstance(points, dict):
            raise PhotoFitError(f"'{view}' must be an object of landmark id → [x, y]", file=path)
        parsed: dict[str, tuple[float, float]] = {}
        for key, xy in points.items():
            if key not in known:
                raise PhotoFitError(f"'{view}': unknown landmark {_short(key)} (the model has "
                                    f"{', '.join(sorted(known, key=_id_order))})", file=path)
            if (not isinstance(xy, list) or len(xy) != 2
                    or not all(isinstance(c, int | float) and not isinstance(c, bool) for c in xy)):
                raise PhotoFitError(f"'{view}' landmark {key}: expected [x, y] pixels, got {_short(xy)}", file=path)
            x, y = float(xy[0]), float(xy[1])
            if not (math.isfinite(x) and math.isfinite(y)) or max(abs(x), abs(y)) > MAX_COORDINATE:
                raise PhotoFitError(f"'{view}' landmark {key}: coordinates must be finite and within "
                                    f"±{MAX_COORDINATE:g} pixels", file=path)
            parsed[key] = (x, y)
        out[view] = parsed
    missing = [k for k in REQUIRED_FRONT if k not in out["front"]]
    if missing:
        raise PhotoFitError(f"the front view needs landmarks {', '.join(missing)} (pupils 3.5 3.6, nose tip 9.3, "
                            "mouth corners 8.3 8.4, chin 2.1)", file=path)
    _check_front_layout(out["front"], path)
    if "side" in out and 0 < len(out["side"]) < 3:
        raise PhotoFitError("the side view needs at least 3 landmarks (or leave it out)", file=path)
    return out


def _check_front_layout(front: dict[str, tuple[float, float]], path: str | Path) -> None:
    """Refuse a front view no upright face gives: swapped sides, the chin above the eyes, points on one spot."""
    (lx, ly), (rx, ry) = front["3.5"], front["3.6"]
    eyes = math.hypot(lx - rx, ly - ry)
    if eyes < MIN_PUPIL_DISTANCE:
        raise PhotoFitError(f"the pupils 3.5 and 3.6 are {eyes:.3g} px apart in the front view; at least "
                            f"{MIN_PUPIL_DISTANCE} px are needed", file=path)
    if lx <= rx:
        raise PhotoFitError("in the front view 3.5 (the subject's LEFT pupil) must be right of 3.6, as the "
                            "photograph shows them; are they swapped?", file=path)
    eye_y = (ly + ry) / 2
    if not (eye_y < front["9.3"][1] < front["2.1"][1]):
        raise PhotoFitError("in the front view the nose tip 9.3 must lie below the pupils and the chin 2.1 "
                            "below the nose tip (y grows downwards)", file=path)


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number JSON allows")


def _short(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _id_order(key: str) -> tuple[int, ...]:
    try:
        return tuple(int(p) for p in key.split("."))
    except ValueError:
        return (1 << 30,)
