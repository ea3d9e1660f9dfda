"""Offscreen rendering of model poses to images (PNG), with VTK.

VTK is imported inside the functions, never when this module is imported, so
the engine stays free of VTK until something is rendered. Without a display
the renderer uses EGL (or OSMesa) directly, so no X server is needed and VTK
prints no warning about a missing one.

:func:`render_model` draws one pose; :class:`FrameRenderer` keeps one scene
and draws pose after pose into it (video frames: only the vertex positions and
normals change between frames).

>>> from engine import load_model
>>> from engine.outputs.render import FrameRenderer, render_model
>>> head = load_model()
>>> image = render_model(head, {"jaw_open": 0.5}, view="three-quarter",
...                      size=(300, 400))                  # path="jaw.png" writes it too
>>> image.shape, image.dtype
((400, 300, 3), dtype('uint8'))
>>> with FrameRenderer(head, size=(640, 480)) as renderer:         # doctest: +SKIP
...     frames = [renderer.render(head.deform(jaw_open=v)) for v in (0.0, 0.5, 1.0)]
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

from engine.errors import UserError

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
    One picture is one :class:`FrameRenderer` used once; render many poses
    with a :class:`FrameRenderer` of your own instead.
    """
    if view not in VIEWS:
        raise UserError(f"unknown view '{view}' (use {', '.join(VIEWS)})")
    check_size(size)
    if path is not None and Path(path).suffix.lower() != ".png":
        raise UserError("the picture must be written as .png", file=path)
    positions = model.deform(values)
    with FrameRenderer(model, size=size, view=view) as renderer:
        image = renderer.render(positions)
    if path is not None:
        write_png(path, image)
    return image


class FrameRenderer:
    """One offscreen scene of ``model``, drawn again for every pose (video frames).

    The render window, actors, lights and camera are made once; :meth:`render`
    only copies new vertex positions and normals into the meshes' arrays and
    redraws. Use it as a context manager (or call :meth:`close`) so the render
    window is released::

        with FrameRenderer(head, size=(640, 480)) as renderer:
            for values in frames:                       # values in tree order
                image = renderer.render(head.deformer().deform(values))

    ``antialias``: ``True`` (default) draws with 8× multisampling, exactly as
    :func:`render_model` does; ``False`` draws without it, which on a
    software OpenGL (Mesa llvmpipe, no GPU) costs about a third as much per
    frame, at the price of stair-stepped outlines and broken thin eyelashes.

    The camera frames the model's rest pose (as in :func:`render_model`), so
    every pose is seen from the same place. The scene is plain VTK: pyvista's
    plotter would also import matplotlib, which alone takes about a second.
    """

    def __init__(self, model, size: tuple[int, int] = (640, 480), view: str = "front",
                 antialias: bool = True):
        if view not in VIEWS:
            raise UserError(f"unknown view '{view}' (use {', '.join(VIEWS)})")
        self.width, self.height = check_size(size)
        self.model = model
        self.view = view
        self.antialias = bool(antialias)
        self._layout = _PartLayout(model)
        self._window = None
        self._meshes = []
        _choose_offscreen_backend()
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

        self._vtk_to_numpy = vtk_to_numpy
        self._pixels = vtkUnsignedCharArray()
        self._window, self._meshes = _build_scene(model, self._layout, view, self.width, self.height,
                                                  self.antialias)

    # -- use ---------------------------------------------------------------
    def render(self, positions: np.ndarray) -> np.ndarray:
        """The picture of the model with its vertices at ``positions`` (N × 3, mm), as
        a new (height, width, 3) uint8 RGB array."""
        if self._window is None:
            raise RuntimeError("this FrameRenderer is closed")
        positions = np.asarray(positions, dtype=float)
        if positions.shape != (self.model.n_vertices, 3):
            raise ValueError(f"expected ({self.model.n_vertices}, 3) positions, got shape {positions.shape}")
        points, normals = self._layout.points_and_normals(positions)
        for (start, stop), (point_array, point_view, normal_array, normal_view) in zip(
                self._layout.slices, self._meshes):
            point_view[...] = points[start:stop]
            normal_view[...] = normals[start:stop]
            point_array.Modified()
            normal_array.Modified()
        return self._grab()

    def _grab(self) -> np.ndarray:
        """Draw, then read the front buffer (as pyvista's screenshot does: with
        multisampling, it holds the gamma-correct resolve of the frame)."""
        window = self._window
        window.Render()
        window.GetPixelData(0, 0, self.width - 1, self.height - 1, 1, self._pixels, 0)
        image = self._vtk_to_numpy(self._pixels).reshape(self.height, self.width, -1)
        return np.ascontiguousarray(image[::-1, :, :3])

    # -- lifetime ------------------------------------------------------------
    def close(self) -> None:
        """Release the render window and its OpenGL context (idempotent)."""
        window, self._window = self._window, None
        self._meshes = []
        if window is not None:
            window.Finalize()

    def __enter__(self) -> "FrameRenderer":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:     # interpreter shutting down
            pass


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

class _PartLayout:
    """Where each part's mesh takes its points from, and how normals are summed.

    Every part is drawn as its own mesh over the model vertices its polygons
    use (a vertex used by two parts appears in both, with each part's own
    normal). The meshes' points, stacked part after part, are ``positions[gather]``;
    part ``k`` is rows ``slices[k]`` of that stack. Smooth normals are the
    area-weighted sum of the fan triangles' normals around each point, one
    sparse product for all parts at once.
    """

    def __init__(self, model):
        from scipy import sparse

        from engine.model.cells import cell_sizes, cell_starts, cells_to_triangles, index_mask

        faces = model.faces
        counts = cell_sizes(faces)
        starts = cell_starts(counts)
        face_part = model.vertex_part[faces[starts + 1]] if len(counts) else counts
        self.parts, self.slices, self.cells = [], [], []
        gather, triangles, offset = [], [], 0
        for part_index, part in enumerate(model.parts):
            keep = face_part == part_index
            if not keep.any():
                continue
            cells = faces[np.repeat(keep, counts + 1)].copy()
            mask = index_mask(cells, counts[keep])
            used = np.unique(cells[mask])
            remap = np.full(model.n_vertices, -1, dtype=np.int64)
            remap[used] = np.arange(len(used))
            cells[mask] = remap[cells[mask]]
            self.parts.append(part)
            self.slices.append((offset, offset + len(used)))
            self.cells.append(cells)
            gather.append(used)
            triangles.append(cells_to_triangles(cells) + offset)
            offset += len(used)
        self.gather = np.concatenate(gather) if gather else np.zeros(0, dtype=np.int64)
        tris = np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)
        self.n_triangles = n_tris = tris.shape[0]
        self._corners = np.ascontiguousarray(tris.T).ravel()   # corner 0 of every triangle, then 1, then 2
        # point × triangle incidence: normals = incidence @ triangle normals
        self.incidence = sparse.csr_matrix(
            (np.ones(3 * n_tris), (self._corners, np.tile(np.arange(n_tris), 3))), shape=(offset, n_tris))
        self._points = np.empty((offset, 3))
        self._cross = np.empty((3, n_tris))

    def used(self, k: int) -> np.ndarray:
        """Model vertex indices of part ``k``'s mesh points."""
        start, stop = self.slices[k]
        return self.gather[start:stop]

    def points_and_normals(self, positions: np.ndarray):
        """The stacked mesh points for ``positions`` and their unit normals (zero where undefined)."""
        points = np.take(positions, self.gather, axis=0, out=self._points)
        # one gather of every corner's coordinates, laid out (xyz, corner, triangle)
        corners = points.T[:, self._corners].reshape(3, 3, self.n_triangles)
        a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
        b -= a                                              # edge vectors, in place
        c -= a
        cross = self._cross                                 # (b − a) × (c − a), by component
        for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
            np.multiply(b[j], c[k], out=cross[i])
            cross[i] -= b[k] * c[j]
        normals = self.incidence @ cross.T
        length = np.sqrt(np.einsum("ij,ij->i", normals, normals))[:, None]
        return points, np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)


def _build_scene(model, layout: _PartLayout, view: str, width: int, height: int, antialias: bool):
    """Render window with the background, one actor per part (at the rest pose),
    lights, camera and anti-aliasing.

    Returns the window and, per part, the VTK points and normals arrays with
    writable numpy views on them, for :meth:`FrameRenderer.render` to fill.

    The settings are those pyvista's ``Plotter`` and ``add_mesh`` used to
    make (the pictures are identical to the pixel), including one quirk:
    parts coloured per vertex keep pyvista's default colour, light blue, as
    their specular colour.
    """
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations of the classes below)
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

    renderer = vtkRenderer()
    renderer.SetBackground(*_hex_rgb(BACKGROUND[0]))
    renderer.SetBackground2(*_hex_rgb(BACKGROUND[1]))
    renderer.GradientBackgroundOn()
    renderer.AutomaticLightCreationOff()
    points, normals = layout.points_and_normals(model.vertices)
    meshes = []
    for k, (part, cells) in enumerate(zip(layout.parts, layout.cells)):
        start, stop = layout.slices[k]
        used = layout.used(k)
        colour, ambient, diffuse, specular, power = part_material(part, model.part_colors)
        colour = _colour_rgb(colour, part_material(part)[0])
        mesh = vtkPolyData()
        point_array = numpy_to_vtk(points[start:stop], deep=True)
        vtk_points = vtkPoints()
        vtk_points.SetData(point_array)
        mesh.SetPoints(vtk_points)
        polys = vtkCellArray()
        polys.ImportLegacyFormat(numpy_to_vtkIdTypeArray(np.ascontiguousarray(cells, dtype=np.int64), deep=True))
        mesh.SetPolys(polys)
        normal_array = numpy_to_vtk(normals[start:stop], deep=True)
        normal_array.SetName("Normals")
        mesh.GetPointData().SetNormals(normal_array)
        if model.vertex_colors is not None:
            rgb = model.vertex_colors[used]
        elif _is_eyeball(part):
            rgb = _eye_colours(model.vertices[used], colour)
        else:
            rgb = None
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(mesh)
        mapper.InterpolateScalarsBeforeMappingOn()
        actor = vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        if rgb is None:
            mapper.ScalarVisibilityOff()
            prop.SetColor(*colour)
        else:
            colours = numpy_to_vtk(np.ascontiguousarray(rgb, dtype=np.uint8), deep=True)
            colours.SetName("Colors")
            mesh.GetPointData().SetScalars(colours)     # unsigned char RGB: drawn as colours, not mapped
            mapper.ScalarVisibilityOn()
            mapper.SetScalarModeToUsePointData()
            prop.SetColor(*_PYVISTA_DEFAULT_COLOUR)
        prop.SetAmbient(ambient)
        prop.SetDiffuse(diffuse)
        prop.SetSpecular(specular)
        prop.SetSpecularPower(power)
        prop.SetPointSize(5.0)
        prop.SetInterpolationToPhong()                  # uses our point normals
        renderer.AddActor(actor)
        meshes.append((point_array, vtk_to_numpy(point_array), normal_array, vtk_to_numpy(normal_array)))
    for position, intensity in _LIGHTS:
        light = vtkLight()
        light.SetLightTypeToCameraLight()
        light.SetPosition(*position)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        light.SetIntensity(intensity)
        renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    focal, position, up, near_far = _camera_pose(_framed_points(model), VIEWS[view], width, height)
    camera.SetFocalPoint(*focal)
    camera.SetPosition(*position)
    camera.SetViewUp(*up)
    camera.SetViewAngle(VIEW_ANGLE)
    camera.SetClippingRange(*near_far)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(8 if antialias else 0)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    return window, meshes


def _colour_rgb(colour: str, fallback: str) -> np.ndarray:
    """A ``#rrggbb`` colour as RGB floats in [0, 1]; the fallback's if it is not one."""
    try:
        return _hex_rgb(colour)
    except (ValueError, TypeError, AttributeError, IndexError):
        return _hex_rgb(fallback)


def _choose_offscreen_backend() -> None:
    """Without a display, ask VTK for EGL (or OSMesa) instead of letting it fail on X first."""
    if not sys.platform.startswith("linux") or os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return
    if ctypes.util.find_library("EGL"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    elif ctypes.util.find_library("OSMesa"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow")


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


# A three-point set-up in camera space (camera at +Z looking at the origin, +Y up):
# (position, intensity) of the key, fill and rim lights, all aimed at the origin
_LIGHTS = [((-1.0, 0.9, 1.2), 0.78), ((1.3, 0.1, 1.0), 0.42), ((0.4, 1.2, -1.4), 0.45)]
_PYVISTA_DEFAULT_COLOUR = (173 / 255, 216 / 255, 230 / 255)   # "lightblue"; see _build_scene


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
    """Set a pyvista camera to :func:`_camera_pose` (perspective, fits every point with a margin)."""
    focal, position, up, near_far = _camera_pose(points, toward_camera, width, height)
    camera.focal_point = tuple(focal)
    camera.position = tuple(position)
    camera.up = tuple(up)
    camera.view_angle = VIEW_ANGLE
    camera.clipping_range = near_far


def _camera_pose(points: np.ndarray, toward_camera, width: int, height: int):
    """Focal point, position, view-up and clipping range (mm) of a perspective camera
    looking along ``-toward_camera`` that fits every point with a margin."""
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
    near = max(distance - (w.max() - cw) - 10.0, distance * 0.01)
    return focal, focal + distance * back, up, (near, distance + (cw - w.min()) + 10.0)


def write_png(path: str | Path, image: np.ndarray) -> Path:
    """Write an (H, W, 3) uint8 RGB array as an 8-bit PNG, atomically."""
    from engine.formats.atomic import atomic_write_bytes

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
