"""Offscreen rendering of a model pose to an image (PNG), with pyvista.

pyvista (and so VTK) is imported inside the functions, never when this module
is imported, so the engine stays free of VTK until something is rendered.
Without a display the renderer uses EGL (or OSMesa) directly, so no X server
is needed and VTK prints no warning about a missing one.

>>> from engine import load_model
>>> from engine.render import render_model
>>> head = load_model()                                             # doctest: +SKIP
>>> image = render_model(head, {"jaw_open": 0.5}, view="three-quarter",
...                      size=(600, 800), path="jaw.png")           # (800, 600, 3) uint8
"""

from __future__ import annotations

import ctypes.util
import os
import struct
import sys
import zlib
from pathlib import Path
from typing import Mapping

import numpy as np

from .errors import UserError

VIEWS = {
    # direction from the head towards the camera; the head faces +Z, +Y up,
    # and the subject's left is +X
    "front": (0.0, 0.0, 1.0),
    "side": (1.0, 0.0, 0.0),
    "three-quarter": (np.sqrt(0.5), 0.0, np.sqrt(0.5)),
}
DEFAULT_SIZE = (600, 800)
MAX_SIZE = 8192
BACKGROUND = ("#cfd1d4", "#eef0f2")   # bottom, top of a faint vertical gradient
VIEW_ANGLE = 20.0                      # degrees, vertical; a portrait lens
MARGIN = 0.06                          # fraction of the picture kept free around the model
NECK_SHOWN = 0.10                      # neck shown below the chin, as a fraction of chin-to-crown height

# (colour, ambient, diffuse, specular, specular power) by the start of a part's name
_MATERIALS = [
    ("eyelash", ("#2a211d", 0.20, 0.80, 0.05, 5.0)),
    ("eyebrow", ("#3b2c24", 0.20, 0.80, 0.05, 5.0)),
    ("brow", ("#3b2c24", 0.20, 0.80, 0.05, 5.0)),
    ("hair", ("#3b2c24", 0.20, 0.80, 0.10, 10.0)),
    ("eye", ("#f3efe8", 0.25, 0.75, 0.60, 60.0)),
    ("teeth", ("#eee4c8", 0.25, 0.75, 0.35, 30.0)),
    ("tooth", ("#eee4c8", 0.25, 0.75, 0.35, 30.0)),
    ("tongue", ("#c4525c", 0.20, 0.80, 0.30, 25.0)),
    ("gum", ("#b85c66", 0.20, 0.80, 0.25, 20.0)),
    ("mouth", ("#9c3f4a", 0.20, 0.80, 0.20, 20.0)),
]
_SKIN = ("#e2ad8f", 0.18, 0.85, 0.12, 12.0)
_PUPIL, _IRIS, _IRIS_RIM = "#141110", "#5b7a8f", "#2e3e49"
_PUPIL_DEGREES, _IRIS_DEGREES = 11.0, 30.0   # half-angles on the eyeball, seen from its centre


def render_model(model, values: Mapping[str, float] | None = None, view: str = "front",
                 size: tuple[int, int] = DEFAULT_SIZE, path: str | Path | None = None) -> np.ndarray:
    """Render one pose of ``model`` offscreen and return the picture.

    Parameters
    ----------
    model : engine.Model
        Lengths in mm; the head is expected to face +Z with +Y up.
    values : mapping name → value, optional
        Parameter values (dimensionless; rotations turn by
        ``value × degrees_per_unit`` degrees); parameters left out take their
        default. Values are applied as given: call ``model.check_values``
        first to refuse values out of range.
    view : ``"front"``, ``"side"`` (from the subject's left, +X) or ``"three-quarter"``
        (45° between the two).
    size : (width, height)
        In pixels.
    path : file name, optional
        Also write the picture there as PNG (atomically).

    Returns
    -------
    (height, width, 3) uint8 array, RGB.

    The camera frames the model's rest pose, so every pose of one model is
    seen from the same place. Parts are coloured by ``model.part_colors`` or,
    failing that, by their names (skin, eye…, teeth…, tongue, eyelash…).
    """
    if view not in VIEWS:
        raise UserError(f"unknown view '{view}' (use {', '.join(VIEWS)})")
    width, height = check_size(size)
    if path is not None and Path(path).suffix.lower() != ".png":
        raise UserError("the picture must be written as .png", file=path)
    positions = model.deform(values)
    image = _draw(model, positions, view, width, height)
    if path is not None:
        write_png(path, image)
    return image


def check_size(size) -> tuple[int, int]:
    """``(width, height)`` as two ints in 1..8192 pixels, or :class:`UserError`."""
    try:
        width, height = (int(s) for s in size)
    except (TypeError, ValueError):
        raise UserError(f"size must be two whole numbers (width, height), not {size!r}") from None
    if not (0 < width <= MAX_SIZE and 0 < height <= MAX_SIZE):
        raise UserError(f"size {width}x{height} is outside 1..{MAX_SIZE} pixels")
    return width, height


def part_material(name: str, colors: Mapping[str, str] | None = None):
    """(hex colour, ambient, diffuse, specular, specular power) for a part, by its name."""
    lowered = name.lower()
    material = _SKIN
    for prefix, candidate in _MATERIALS:
        if lowered.startswith(prefix):
            material = candidate
            break
    if colors and name in colors:
        material = (colors[name],) + material[1:]
    return material


# ---------------------------------------------------------------------------

def _draw(model, positions: np.ndarray, view: str, width: int, height: int) -> np.ndarray:
    from .cells import cell_sizes, cell_starts

    _choose_offscreen_backend()
    import pyvista as pv

    counts = cell_sizes(model.faces)
    starts = cell_starts(counts)
    face_part = model.vertex_part[model.faces[starts + 1]] if len(counts) else counts
    plotter = pv.Plotter(off_screen=True, window_size=(width, height), lighting="none")
    try:
        plotter.set_background(BACKGROUND[0], top=BACKGROUND[1])
        for part_index, part in enumerate(model.parts):
            keep = face_part == part_index
            if not keep.any():
                continue
            colour, ambient, diffuse, specular, power = part_material(part, model.part_colors)
            colour = _rgb(pv, colour, part_material(part)[0])
            mesh, used = _part_mesh(pv, model.faces, counts, keep, positions)
            style = dict(ambient=ambient, diffuse=diffuse, specular=specular, specular_power=power,
                         smooth_shading=False, show_scalar_bar=False)
            if model.vertex_colors is not None:
                actor = plotter.add_mesh(mesh, scalars=model.vertex_colors[used], rgb=True, **style)
            elif _is_eyeball(part):
                rgb = _eye_colours(model.vertices[used], colour)
                actor = plotter.add_mesh(mesh, scalars=rgb, rgb=True, **style)
            else:
                actor = plotter.add_mesh(mesh, color=colour, **style)
            actor.prop.interpolation = "phong"   # uses our point normals
        for light in _lights(pv):
            plotter.add_light(light)
        _place_camera(plotter.camera, _framed_points(model), VIEWS[view], width, height)
        plotter.enable_anti_aliasing("msaa", multi_samples=8)
        image = plotter.screenshot(return_img=True)
    finally:
        plotter.close()
    return np.ascontiguousarray(image[:, :, :3], dtype=np.uint8)


def _rgb(pv, colour: str, fallback: str) -> np.ndarray:
    """A colour pyvista understands (hex or name) as RGB floats in [0, 1]; the fallback if it does not."""
    try:
        return np.array(pv.Color(colour).float_rgb)
    except (ValueError, TypeError):
        return np.array(pv.Color(fallback).float_rgb)


def _choose_offscreen_backend() -> None:
    """Without a display, ask VTK for EGL (or OSMesa) instead of letting it fail on X first."""
    if not sys.platform.startswith("linux") or os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return
    if ctypes.util.find_library("EGL"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    elif ctypes.util.find_library("OSMesa"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow")


def _part_mesh(pv, faces: np.ndarray, counts: np.ndarray, keep: np.ndarray, positions: np.ndarray):
    """PolyData of the polygons flagged by ``keep``, with smooth point normals, and the model vertices it uses."""
    from .cells import index_mask

    cells = faces[np.repeat(keep, counts + 1)].copy()
    mask = index_mask(cells, counts[keep])
    used = np.unique(cells[mask])
    remap = np.full(len(positions), -1, dtype=np.int64)
    remap[used] = np.arange(len(used))
    cells[mask] = remap[cells[mask]]
    mesh = pv.PolyData(positions[used], cells)
    mesh.point_data["Normals"] = _vertex_normals(positions[used], cells)
    mesh.point_data.active_normals_name = "Normals"
    return mesh, used


def _vertex_normals(points: np.ndarray, cells: np.ndarray) -> np.ndarray:
    """Area-weighted vertex normals of fan-triangulated polygons (smooth shading)."""
    from .cells import cells_to_triangles

    tris = cells_to_triangles(cells)
    a, b, c = points[tris[:, 0]], points[tris[:, 1]], points[tris[:, 2]]
    face_normals = np.cross(b - a, c - a)
    normals = np.zeros_like(points)
    for k in range(3):
        np.add.at(normals, tris[:, k], face_normals)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    return np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)


def _is_eyeball(part: str) -> bool:
    lowered = part.lower()
    return lowered.startswith("eye") and not lowered.startswith(("eyelash", "eyebrow", "eyelid"))


def _eye_colours(rest: np.ndarray, sclera: np.ndarray) -> np.ndarray:
    """Per-vertex RGB for an eyeball: pupil and iris around the forward (+Z) pole of the rest pose."""
    centre = (rest.min(axis=0) + rest.max(axis=0)) / 2
    offset = rest - centre
    length = np.linalg.norm(offset, axis=1)
    cos = np.divide(offset[:, 2], length, out=np.zeros(len(rest)), where=length > 0)
    angle = np.degrees(np.arccos(np.clip(cos, -1, 1)))
    colours = np.tile(sclera, (len(rest), 1))
    iris = angle < _IRIS_DEGREES
    # the iris darkens towards its rim, as real irises do
    t = np.clip((angle - _PUPIL_DEGREES) / (_IRIS_DEGREES - _PUPIL_DEGREES), 0, 1)[:, None]
    ring = (1 - t ** 2) * _hex_rgb(_IRIS) + t ** 2 * _hex_rgb(_IRIS_RIM)
    colours[iris] = ring[iris]
    colours[angle < _PUPIL_DEGREES] = _hex_rgb(_PUPIL)
    return np.round(colours * 255).astype(np.uint8)


def _hex_rgb(colour: str) -> np.ndarray:
    colour = colour.lstrip("#")
    return np.array([int(colour[i:i + 2], 16) for i in (0, 2, 4)]) / 255.0


def _lights(pv):
    """A three-point set-up in camera space (camera at +Z looking at the origin, +Y up)."""
    key = pv.Light(position=(-1.0, 0.9, 1.2), focal_point=(0, 0, 0), intensity=0.78,
                   light_type="camera light")
    fill = pv.Light(position=(1.3, 0.1, 1.0), focal_point=(0, 0, 0), intensity=0.42,
                    light_type="camera light")
    rim = pv.Light(position=(0.4, 1.2, -1.4), focal_point=(0, 0, 0), intensity=0.45,
                   light_type="camera light")
    return [key, fill, rim]


def _framed_points(model) -> np.ndarray:
    """Rest-pose points the camera must show: the head down to a little below the chin.

    With a chin landmark (MPEG-4 2.1) the neck below it is left to be cropped, so
    the face fills more of the picture; without one the whole model is framed.
    """
    points = model.vertices
    chin = model.landmarks.get("2.1")
    if chin is None:
        return points
    chin_y = points[chin, 1]
    top = points[:, 1].max()
    if top <= chin_y:
        return points
    keep = points[:, 1] >= chin_y - NECK_SHOWN * (top - chin_y)
    return points[keep]


def _place_camera(camera, points: np.ndarray, toward_camera, width: int, height: int) -> None:
    """Perspective camera that fits every point with a margin (mm), looking along ``-toward_camera``."""
    back = np.asarray(toward_camera, dtype=float)
    back /= np.linalg.norm(back)
    up = np.array([0.0, 1.0, 0.0])
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    u, v, w = points @ right, points @ up, points @ back
    cu, cv, cw = (u.min() + u.max()) / 2, (v.min() + v.max()) / 2, (w.min() + w.max()) / 2
    tan_y = np.tan(np.radians(VIEW_ANGLE) / 2) * (1 - 2 * MARGIN)
    tan_x = tan_y * width / height
    # distance from the focal plane such that every point projects inside the picture
    distance = max(np.max((w - cw) + np.abs(u - cu) / tan_x), np.max((w - cw) + np.abs(v - cv) / tan_y), 1.0)
    focal = cu * right + cv * up + cw * back
    camera.focal_point = tuple(focal)
    camera.position = tuple(focal + distance * back)
    camera.up = tuple(up)
    camera.view_angle = VIEW_ANGLE
    near = max(distance - (w.max() - cw) - 10.0, distance * 0.01)
    camera.clipping_range = (near, distance + (cw - w.min()) + 10.0)


def write_png(path: str | Path, image: np.ndarray) -> Path:
    """Write an (H, W, 3) uint8 RGB array as an 8-bit PNG, atomically."""
    from .files import atomic_write_bytes

    image = np.ascontiguousarray(image, dtype=np.uint8)
    if image.ndim != 3 or image.shape[2] != 3:
        raise ValueError(f"expected an (H, W, 3) image, got shape {image.shape}")
    h, w = image.shape[:2]
    raw = np.concatenate([np.zeros((h, 1), dtype=np.uint8), image.reshape(h, w * 3)], axis=1).tobytes()

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    path = Path(path)
    atomic_write_bytes(path, png)
    return path
