"""Offscreen rendering of model poses to images (PNG), with VTK.

VTK is imported inside the functions, never when this module is imported, so
the engine stays free of VTK until something is rendered. Without a display
the renderer uses EGL (or OSMesa) directly, so no X server is needed and VTK
prints no warning about a missing one.

:func:`render_model` draws one pose; :class:`FrameRenderer` keeps one scene
and draws pose after pose into it (video frames: only the vertex positions and
normals change between frames). The camera's placement is
:mod:`engine.outputs.camera`, the parts' meshes :mod:`engine.outputs.part_layout`,
their colours :mod:`engine.outputs.part_materials` and the PNG writer
:mod:`engine.outputs.png_file`.

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

import contextlib
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any, SupportsInt

import numpy as np

from engine.errors import UserError
from engine.outputs.antialias import fxaa
from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
from engine.outputs.look_actors import OCCLUSION_ARRAY, dress_actor, set_antialias
from engine.outputs.looks import Look, look_from
from engine.outputs.occlusion import model_occlusion
from engine.outputs.part_layout import PartLayout
from engine.outputs.part_materials import colour_rgb, eye_colours, hex_rgb, is_eyeball, part_material
from engine.outputs.png_file import write_png
from engine.outputs.render_backend import choose_offscreen_backend, describe

if TYPE_CHECKING:
    from vtkmodules.vtkCommonCore import vtkDataArray
    from vtkmodules.vtkRenderingCore import vtkRenderWindow

    from engine.model import Model

    _MeshArrays = tuple[vtkDataArray, np.ndarray, vtkDataArray, np.ndarray]
    """A part's VTK points and normals arrays, each with a writable numpy view on it."""

# VIEWS (engine.outputs.camera) and write_png (engine.outputs.png_file) are importable from here too.
__all__ = ["BACKGROUND", "BACKGROUND_AFTER_DRAWING", "CULL_BACK_FACES", "DEFAULT_SIZE", "MAX_SIZE", "VIEWS",
           "FrameRenderer", "aim_camera", "check_size", "copy_pose", "render_model", "scene_renderer", "write_png"]

DEFAULT_SIZE = (600, 800)
MAX_SIZE = 8192
BACKGROUND = ("#cfd1d4", "#eef0f2")   # bottom, top of a faint vertical gradient
#: A physically based look draws no triangle that faces away from the camera: on a software OpenGL (Mesa
#: llvmpipe) that is a fifth of a 720p frame's drawing (docs/export.md, "Speed"), and the picture differs
#: from one drawn with them in a few pixels on the silhouette of a thin fold (tests/engine/test_render_speed.py
#: states the tolerance). The ``legacy`` look keeps drawing them: its pictures stay those of pyvista.
CULL_BACK_FACES = True
#: A physically based look drawn without multisampling draws the head on a clear background and puts it
#: onto the gradient in numpy, where the picture's alpha says nothing was drawn: the gradient, drawn by
#: the renderer once, alone, costs llvmpipe 13–16 ms of CPU a 720p frame, putting it under the head in
#: numpy less than half that (5–7 % of a whole frame saved at 720p and 1080p, docs/export.md "Speed").
#: Without multisampling a pixel is the head's or the background's, so the picture is the same to the byte
#: (tests/engine/test_render_speed.py).
BACKGROUND_AFTER_DRAWING = True


def render_model(model: Model, values: Mapping[str, float] | None = None, view: str = "front",
                 size: tuple[int, int] = DEFAULT_SIZE, path: str | Path | None = None,
                 look: str | Look | None = None) -> np.ndarray:
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
    look : a look's name, a :class:`~engine.outputs.looks.Look` or its settings, optional
        How the head is lit and shaded (:mod:`engine.outputs.looks`; default ``portrait``).

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
    with FrameRenderer(model, size=size, view=view, look=look) as renderer:
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

    ``look`` (:mod:`engine.outputs.looks`): the lights, shading, occlusion,
    anti-aliasing method and background; default ``portrait``. ``antialias``:
    ``True`` (default) smooths the edges as the look says, exactly as
    :func:`render_model` does — FXAA for ``portrait`` and ``flat``, 8×
    multisampling for ``legacy``; ``False`` draws without it (on a software
    OpenGL, Mesa llvmpipe, 8× multisampling costs about three times the rest of
    the drawing, FXAA a few per cent: docs/looks.md).

    The camera frames the model's rest pose (as in :func:`render_model`), so
    every pose is seen from the same place. The scene is plain VTK: pyvista's
    plotter would also import matplotlib, which alone takes about a second.
    """

    def __init__(self, model: Model, size: tuple[int, int] = (640, 480), view: str = "front",
                 antialias: bool = True, look: str | Look | None = None) -> None:
        if view not in VIEWS:
            raise UserError(f"unknown view '{view}' (use {', '.join(VIEWS)})")
        self.width, self.height = check_size(size)
        self.model = model
        self.view = view
        self.antialias = bool(antialias)
        self.look = look_from(look)
        self._fxaa = self.antialias and self.look.antialias == "fxaa"      # after the read-back: _grab
        self._layout = PartLayout(model)
        self._window: vtkRenderWindow | None = None
        self._meshes: list[_MeshArrays] = []
        choose_offscreen_backend()
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

        self._vtk_to_numpy = vtk_to_numpy
        self._pixels = vtkUnsignedCharArray()
        self._window, self._meshes = _build_scene(model, self._layout, view, self.width, self.height,
                                                  self.antialias, self.look)
        self._background: np.ndarray | None = None        # see BACKGROUND_AFTER_DRAWING
        if BACKGROUND_AFTER_DRAWING and self.look.shading != "legacy" and not self._window.GetMultiSamples() \
                and sys.byteorder == "little":           # _OPAQUE: alpha is a pixel's top byte
            self._background = _background_alone(self._window)

    # -- use ---------------------------------------------------------------
    def render(self, positions: np.ndarray) -> np.ndarray:
        """The picture of the model with its vertices at ``positions`` (N × 3, mm), as
        a new (height, width, 3) uint8 RGB array."""
        if self._window is None:
            raise RuntimeError("this FrameRenderer is closed")
        positions = np.asarray(positions, dtype=float)
        if positions.shape != (self.model.n_vertices, 3):
            raise ValueError(f"expected ({self.model.n_vertices}, 3) positions, got shape {positions.shape}")
        copy_pose(self._layout, self._meshes, positions)
        return self._grab()

    def _grab(self) -> np.ndarray:
        """Draw, then read the front buffer (as pyvista's screenshot does: with
        multisampling, it holds the gamma-correct resolve of the frame)."""
        window = self._window
        if window is None:
            raise RuntimeError("this FrameRenderer is closed")
        window.Render()
        if self._background is not None:         # the head on a clear background: the gradient put under it
            window.GetRGBACharPixelData(0, 0, self.width - 1, self.height - 1, 1, self._pixels, 0)
            drawn = self._vtk_to_numpy(self._pixels).view(np.uint32).reshape(self.height, self.width)[::-1]
            whole = np.where(drawn >= _OPAQUE, drawn, self._background)          # one RGBA pixel a uint32
            image = rgb_of(whole.view(np.uint8).reshape(self.height, self.width, 4))
            return fxaa(image, copy=False) if self._fxaa else image
        window.GetPixelData(0, 0, self.width - 1, self.height - 1, 1, self._pixels, 0)
        image = self._vtk_to_numpy(self._pixels).reshape(self.height, self.width, -1)
        if self._fxaa:
            return fxaa(image[::-1, :, :3])
        return np.ascontiguousarray(image[::-1, :, :3])

    def backend(self) -> dict[str, str]:
        """Which OpenGL draws these frames (:func:`engine.outputs.render_backend.describe`):
        ``kind`` is e.g. ``software (Mesa llvmpipe)`` or ``GPU (…)``."""
        if self._window is None:
            raise RuntimeError("this FrameRenderer is closed")
        self._window.Render()
        return describe(self._window)

    # -- lifetime ------------------------------------------------------------
    def close(self) -> None:
        """Release the render window and its OpenGL context (idempotent)."""
        window, self._window = self._window, None
        self._meshes = []
        if window is not None:
            window.Finalize()

    def __enter__(self) -> FrameRenderer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        with contextlib.suppress(Exception):     # interpreter shutting down
            self.close()


_OPAQUE = np.frombuffer(bytes([0, 0, 0, 1]), dtype=np.uint32)[0]     # an RGBA uint32 from alpha 1 up


def rgb_of(rgba: np.ndarray) -> np.ndarray:
    """The RGB of an (H, W, 4) picture as a new contiguous (H, W, 3) array, one channel at a time: numpy
    copies that several times faster than the (H, W, 3) slice (2.2 against 10.6 ms at 1280 × 720).

    >>> rgba = np.arange(2 * 3 * 4, dtype=np.uint8).reshape(2, 3, 4)
    >>> bool(np.array_equal(rgb_of(rgba), rgba[:, :, :3]))
    True
    """
    out = np.empty((*rgba.shape[:2], 3), dtype=np.uint8)
    for channel in range(3):
        out[:, :, channel] = rgba[:, :, channel]
    return out


def _background_alone(window: vtkRenderWindow) -> np.ndarray:
    """The window's gradient background drawn once without the head, upright, one RGBA pixel a uint32
    (H × W); the renderer then clears to a transparent background, so that a frame's alpha marks what was
    drawn."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

    renderer = window.GetRenderers().GetFirstRenderer()
    actors = renderer.GetActors()
    shown: list[Any] = [actors.GetItemAsObject(i) for i in range(actors.GetNumberOfItems())]
    visible = [actor.GetVisibility() for actor in shown]
    for actor in shown:
        actor.VisibilityOff()
    window.SetAlphaBitPlanes(1)
    window.Render()
    pixels = vtkUnsignedCharArray()
    width, height = window.GetSize()
    window.GetPixelData(0, 0, width - 1, height - 1, 1, pixels, 0)
    background = np.full((height, width, 4), 255, dtype=np.uint8)
    background[:, :, :3] = vtk_to_numpy(pixels).reshape(height, width, -1)[::-1, :, :3]
    for actor, was in zip(shown, visible, strict=True):
        actor.SetVisibility(was)
    renderer.GradientBackgroundOff()
    renderer.SetBackgroundAlpha(0.0)
    return background.view(np.uint32).reshape(height, width)


def check_size(size: Iterable[SupportsInt]) -> tuple[int, int]:
    """``(width, height)`` as two ints in 1..8192 pixels, or :class:`UserError`."""
    try:
        width, height = (int(s) for s in size)
    except (TypeError, ValueError):
        raise UserError(f"size must be two whole numbers (width, height), not {size!r}") from None
    if not (0 < width <= MAX_SIZE and 0 < height <= MAX_SIZE):
        raise UserError(f"size {width}x{height} is outside 1..{MAX_SIZE} pixels")
    return width, height


def _build_scene(model: Model, layout: PartLayout, view: str, width: int, height: int,
                 antialias: bool, look: Look) -> tuple[vtkRenderWindow, list[_MeshArrays]]:
    """An offscreen render window with :func:`scene_renderer`'s scene in it, and anti-aliasing.

    Returns the window and, per part, the VTK points and normals arrays with
    writable numpy views on them, for :meth:`FrameRenderer.render` to fill.
    """
    from vtkmodules.vtkRenderingCore import vtkRenderWindow

    renderer, meshes = scene_renderer(model, layout, view, width, height, look, antialias=False)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    set_antialias(window, renderer, look, antialias)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    return window, meshes


def scene_renderer(model: Model, layout: PartLayout, view: str, width: int, height: int,
                   look: str | Look | None = None, antialias: bool = True) -> tuple[Any, list[_MeshArrays]]:
    """A VTK renderer with the background, one actor per part (at the rest pose),
    lights and the camera of ``view`` for a ``width`` × ``height`` picture, to put
    in a render window of one's own (an on-screen one: ``serve --window``).

    Returns the renderer and, per part, the VTK points and normals arrays with
    writable numpy views on them (:func:`copy_pose` fills them).

    ``look`` (:mod:`engine.outputs.looks`; default ``portrait``) lights and shades
    the parts; a look smoothed by FXAA has it switched on here while ``antialias``
    (multisampling is the window's: :func:`_build_scene`). The ``legacy`` look's
    settings are those pyvista's ``Plotter`` and ``add_mesh`` used to make (the
    pictures are identical to the pixel), including one quirk: parts coloured per
    vertex keep pyvista's default colour, light blue, as their specular colour.
    """
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations of the classes below)
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer

    look = look_from(look)
    legacy = look.shading == "legacy"
    renderer = vtkRenderer()
    renderer.SetBackground(*hex_rgb(BACKGROUND[0] if legacy else look.background[0]))
    renderer.SetBackground2(*hex_rgb(BACKGROUND[1] if legacy else look.background[1]))
    renderer.GradientBackgroundOn()
    renderer.AutomaticLightCreationOff()
    points, normals = layout.points_and_normals(model.vertices)
    occlusion = None if legacy else model_occlusion(model, look.occlusion_radius_mm, layout)
    meshes: list[_MeshArrays] = []
    textures: dict[int, Any] = {}           # image index → its vtkTexture, shared by the meshes showing it
    for k, part in enumerate(layout.parts):
        start, stop = layout.slices[k]
        used = layout.used(k)
        colour_name, ambient, diffuse, specular, power = part_material(part, model.part_colors)
        colour = colour_rgb(colour_name, part_material(part)[0])
        mesh, point_array, normal_array = _part_mesh(layout, k, points[start:stop], normals[start:stop])
        textured = layout.uv[k] is not None and model.texture is not None
        if textured:
            rgb = None
        elif model.vertex_colors is not None:
            rgb = model.vertex_colors[used]
        elif is_eyeball(part):
            rgb = eye_colours(model.vertices[used], colour)
        else:
            rgb = None
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(mesh)
        mapper.InterpolateScalarsBeforeMappingOn()
        actor = vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        texture = None
        if textured and model.texture is not None:
            image = layout.image[k]
            if image not in textures:
                textures[image] = vtk_texture(model.texture.images[image].pixels, 2 * max(width, height))
                if not legacy:
                    textures[image].UseSRGBColorSpaceOn()          # PBR: decoded to linear light
            texture = textures[image]
            mapper.ScalarVisibilityOff()
            prop.SetColor(1.0, 1.0, 1.0)              # the image's colours, lit
        elif rgb is None:
            mapper.ScalarVisibilityOff()
            prop.SetColor(*(colour if legacy else colour ** 2.2))   # PBR takes it as linear, vertex colours not
        else:
            colours = numpy_to_vtk(np.ascontiguousarray(rgb, dtype=np.uint8), deep=True)
            colours.SetName("Colors")
            mesh.GetPointData().SetScalars(colours)     # unsigned char RGB: drawn as colours, not mapped
            mapper.ScalarVisibilityOn()
            mapper.SetScalarModeToUsePointData()
            prop.SetColor(*_PYVISTA_DEFAULT_COLOUR)
        if legacy:
            if texture is not None:
                actor.SetTexture(texture)
            prop.SetAmbient(ambient)
            prop.SetDiffuse(diffuse)
            prop.SetSpecular(specular)
            prop.SetSpecularPower(power)
            prop.SetPointSize(5.0)
            prop.SetInterpolationToPhong()              # uses our point normals
        else:
            assert occlusion is not None
            values = numpy_to_vtk(np.ascontiguousarray(occlusion[start:stop], dtype=np.float32), deep=True)
            values.SetName(OCCLUSION_ARRAY)
            mesh.GetPointData().AddArray(values)
            dress_actor(actor, look, part, texture)
            prop.SetBackfaceCulling(CULL_BACK_FACES)    # see CULL_BACK_FACES
        renderer.AddActor(actor)
        meshes.append((point_array, vtk_to_numpy(point_array), normal_array, vtk_to_numpy(normal_array)))
    # a physically based look lights with its own uniforms; VTK writes its lighting code (which the
    # look's shader replaces) only where the renderer has a light
    for light_position, intensity in _LIGHTS if legacy else [((0.0, 0.0, 1.0), 1.0)]:
        light = vtkLight()
        light.SetLightTypeToCameraLight()
        light.SetPosition(*light_position)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        light.SetIntensity(intensity)
        renderer.AddLight(light)
    if antialias and look.antialias == "fxaa":
        renderer.UseFXAAOn()                    # a window of one's own (FrameRenderer smooths its frames itself)
    aim_camera(renderer, model, view, width, height)
    return renderer, meshes


def _part_mesh(layout: PartLayout, k: int, points: np.ndarray, normals: np.ndarray) -> tuple[Any, Any, Any]:
    """Mesh ``k`` of ``layout`` as VTK polygons with the given points and normals (and its (u, v) if it has
    them); returns it with its points and normals arrays."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    mesh = vtkPolyData()
    point_array = numpy_to_vtk(points, deep=True)
    vtk_points = vtkPoints()
    vtk_points.SetData(point_array)
    mesh.SetPoints(vtk_points)
    polys = vtkCellArray()
    polys.ImportLegacyFormat(numpy_to_vtkIdTypeArray(np.ascontiguousarray(layout.cells[k], dtype=np.int64),
                                                     deep=True))
    mesh.SetPolys(polys)
    normal_array = numpy_to_vtk(normals, deep=True)
    normal_array.SetName("Normals")
    mesh.GetPointData().SetNormals(normal_array)
    uv = layout.uv[k]
    if uv is not None:
        coordinates = numpy_to_vtk(np.ascontiguousarray(uv, dtype=np.float32), deep=True)
        coordinates.SetName("TextureCoordinates")
        mesh.GetPointData().SetTCoords(coordinates)
    return mesh, point_array, normal_array


def aim_camera(renderer: Any, model: Model, view: str, width: int, height: int) -> None:
    """Point ``renderer``'s camera as ``render --view`` does for a ``width`` × ``height`` picture
    (framing the rest pose: every pose is seen from the same place)."""
    camera = renderer.GetActiveCamera()
    focal, position, up, near_far = camera_pose(framed_points(model), VIEWS[view], width, height)
    camera.SetFocalPoint(*focal)
    camera.SetPosition(*position)
    camera.SetViewUp(*up)
    camera.SetViewAngle(VIEW_ANGLE)
    camera.SetClippingRange(*near_far)


def copy_pose(layout: PartLayout, meshes: list[_MeshArrays], positions: np.ndarray) -> None:
    """Put the vertices at ``positions`` (N × 3, mm) into a scene's meshes, with their normals."""
    points, normals = layout.points_and_normals(positions)
    for (start, stop), (point_array, point_view, normal_array, normal_view) in zip(
            layout.slices, meshes, strict=True):
        point_view[...] = points[start:stop]
        normal_view[...] = normals[start:stop]
        point_array.Modified()
        normal_array.Modified()


def vtk_texture(pixels: np.ndarray, largest: int) -> Any:
    """A VTK texture of (height, width, 3|4) uint8 sRGB pixels (row 0 at the top), repeated outside 0..1
    and interpolated (bilinear).

    An image with a side longer than ``largest`` pixels (twice the picture's
    longer side) is first reduced to it with a box filter, once: a texture
    seen smaller than that would sparkle without it. VTK's mipmaps would do
    the same per pixel, but on a software OpenGL (Mesa llvmpipe) they double
    the frame time (benchmarks/bench_textured_render.py).
    """
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkRenderingCore import vtkTexture

    height, width, channels = pixels.shape
    if max(height, width) > largest:
        from PIL import Image

        scale = largest / max(height, width)
        size = (max(1, round(width * scale)), max(1, round(height * scale)))
        pixels = np.asarray(Image.fromarray(pixels).resize(size, Image.Resampling.BOX), dtype=np.uint8)
        height, width = pixels.shape[:2]
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    data = numpy_to_vtk(np.ascontiguousarray(pixels[::-1].reshape(-1, channels)), deep=True)   # VTK: bottom row first
    data.SetName("Pixels")
    image.GetPointData().SetScalars(data)
    texture = vtkTexture()
    texture.SetInputData(image)
    texture.InterpolateOn()
    texture.RepeatOn()
    texture.SetColorModeToDirectScalars()
    return texture


# A three-point set-up in camera space (camera at +Z looking at the origin, +Y up):
# (position, intensity) of the key, fill and rim lights, all aimed at the origin
_LIGHTS = [((-1.0, 0.9, 1.2), 0.78), ((1.3, 0.1, 1.0), 0.42), ((0.4, 1.2, -1.4), 0.45)]
_PYVISTA_DEFAULT_COLOUR = (173 / 255, 216 / 255, 230 / 255)   # "lightblue"; see _build_scene
