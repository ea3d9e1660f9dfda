"""The viewport's meshes, one per part of the model: points, polygons, colours, normals and a locator for picking.

:func:`split_by_part` divides the model's polygons among its parts;
:func:`part_pieces` does the same for a textured model, one mesh per part
and image, with a point for each distinct (vertex, u, v) so that texture seams
stay sharp (the engine's :class:`~engine.outputs.part_layout.PartLayout`);
:class:`PartView` holds what one mesh's actor draws and keeps its normals
and its cell locator up to date when the points move. Lengths are mm.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pyvista as pv
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

import engine
from engine.model.cells import cell_sizes, cell_starts

from .local_normals import LocalNormals

VERTEX_COLORS = "vertex_colors"  # name of the per-vertex sRGB array on each part mesh


@dataclass
class PartView:
    """One part on screen: the mesh its actor draws, the normals filter that shades it, the actor."""

    vertex_indices: np.ndarray  # model vertex index of each mesh point
    mesh: pv.PolyData           # points, polygons, colours and normals: what the mapper draws
    normals: vtkPolyDataNormals  # reads the mesh's points and polygons only (not its colours)
    actor: object
    locator: vtkStaticCellLocator | None = None    # for picking; rebuilt when the points have moved
    locator_points_time: int = -1
    local_normals: LocalNormals | None = None      # for moving a few points (live preview), built on first use
    part: str = ""                                 # the model part drawn (several meshes for a textured part)
    texture: object | None = None                  # the vtkTexture shown while no heat map or tool colours are
    seam_groups: np.ndarray | None = None          # per point, its model vertex's row: points sharing a normal

    @classmethod
    def shading(cls, mesh: pv.PolyData) -> vtkPolyDataNormals:
        """A normals filter over ``mesh``'s own points and polygons (shared, not copied)."""
        geometry = vtkPolyData()
        geometry.SetPoints(mesh.GetPoints())
        geometry.SetPolys(mesh.GetPolys())
        normals = vtkPolyDataNormals()
        normals.SetInputData(geometry)
        normals.SplittingOff()       # one normal per vertex: smooth, and points stay 1:1
        normals.ConsistencyOff()     # the model's polygons are already consistently wound
        normals.ComputePointNormalsOn()
        normals.ComputeCellNormalsOff()
        return normals

    def update_normals(self) -> None:
        """Recompute the vertex normals after the points moved (the filter sees the shared points change)."""
        self.normals.GetInputDataObject(0, 0).Modified()
        self.normals.Update()
        normals = self.normals.GetOutput().GetPointData().GetNormals()
        self._join_seams(pv.convert_array(normals))
        normals.Modified()
        self.mesh.GetPointData().SetNormals(normals)

    def _join_seams(self, values: np.ndarray) -> None:
        """Give the points of one vertex (a texture seam) the mean of their normals, in place."""
        if self.seam_groups is None:
            return
        summed = np.zeros((int(self.seam_groups.max(initial=-1)) + 1, 3))
        np.add.at(summed, self.seam_groups, values)
        length = np.linalg.norm(summed, axis=1, keepdims=True)
        summed = np.divide(summed, length, out=np.zeros_like(summed), where=length > 0)
        values[:] = summed[self.seam_groups]

    def update_normals_near(self, moved: np.ndarray) -> None:
        """Recompute only the normals that moving the mesh points ``moved`` changes (a live-preview dab)."""
        if self.local_normals is None:
            self.local_normals = LocalNormals(self.mesh.faces, self.mesh.n_points)
        array = self.mesh.GetPointData().GetNormals()
        normals = pv.convert_array(array)
        self.local_normals.update(np.asarray(self.mesh.points, dtype=float), normals, moved)
        self._join_seams(normals)
        array.Modified()

    def current_locator(self) -> vtkStaticCellLocator:
        """A cell locator over the mesh as drawn now: a pick at 94k vertices takes 0.5 ms instead of 30."""
        points_time = self.mesh.GetPoints().GetMTime()
        if self.locator is None or self.locator_points_time != points_time:
            self.locator = vtkStaticCellLocator()
            self.locator.SetDataSet(self.mesh)
            # Rebuilt here when the points move; VTK on its own would also rebuild after every
            # colour change (the mesh's time stamp counts its arrays): 12 ms per dab at 94k.
            self.locator.UseExistingSearchStructureOn()
            self.locator.BuildLocator()
            self.locator_points_time = points_time
        return self.locator


def split_by_part(model: engine.Model) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Per part: (model vertex indices, flat cell array indexing into them).

    A polygon belongs to the part of its first vertex. A part's mesh holds
    its own vertices plus any other vertex its polygons use, so a polygon
    that straddles two parts is still drawn whole.
    """
    faces = model.faces
    n_parts = len(model.parts)
    if len(faces) == 0:
        return {}
    sizes = cell_sizes(faces)
    starts = cell_starts(sizes)
    cell_part = model.vertex_part[faces[starts + 1]]
    cell_of_entry = np.repeat(np.arange(len(starts)), sizes + 1)
    is_count = np.zeros(len(faces), dtype=bool)
    is_count[starts] = True
    out = {}
    for p in range(n_parts):
        entries = faces[cell_part[cell_of_entry] == p]
        counts = is_count[cell_part[cell_of_entry] == p]
        used = entries[~counts]
        own = np.flatnonzero(model.vertex_part == p)
        indices = np.union1d(own, used)
        lookup = np.full(model.n_vertices, -1, dtype=np.int64)
        lookup[indices] = np.arange(len(indices))
        cells = entries.copy()
        cells[~counts] = lookup[used]
        out[model.parts[p]] = (indices, cells)
    return out


@dataclass
class Piece:
    """One mesh to draw: its key in the viewport, its part, its points' model vertices, its polygons
    over them, and for a textured mesh its (u, v) per point and image index (else ``None``, −1)."""

    key: str
    part: str
    vertex_indices: np.ndarray
    cells: np.ndarray
    uv: np.ndarray | None = None
    image: int = -1


def part_pieces(model: engine.Model) -> list[Piece]:
    """The meshes the viewport draws: one per part (:func:`split_by_part`), or for a textured model one
    per part and image (``key`` ``"part"`` for the polygons without an image, ``"part@image"`` for the
    others)."""
    if model.texture is None:
        return [Piece(part, part, indices, cells) for part, (indices, cells) in split_by_part(model).items()]
    from engine.outputs.part_layout import PartLayout

    layout = PartLayout(model)
    pieces = []
    for k, part in enumerate(layout.parts):
        image = layout.image[k]
        key = part if layout.uv[k] is None else f"{part}@{model.texture.images[image].name}"
        pieces.append(Piece(key, part, layout.used(k), layout.cells[k], layout.uv[k], image))
    return pieces


def dress_scene(plotter, views: list[PartView], model: engine.Model, look, own_background: tuple[str, str],
                keep_samples: bool = False) -> None:
    """Light and shade the viewport's meshes ``views`` (just made) in ``look``, with its background and
    anti-aliasing; ``look`` ``None``: the workbench's own shading and ``own_background``.
    ``keep_samples``: leave the window's multisampling alone (a brush stroke has it off for now)."""
    renderer, window = plotter.renderer, plotter.render_window
    if look is None:
        plotter.set_background(own_background[0], top=own_background[1])
        if renderer.GetUseFXAA() or renderer.GetLights().GetNumberOfItems() != 5:
            renderer.UseFXAAOff()
            plotter.enable_lightkit()
            if window is not None and not keep_samples:
                window.SetMultiSamples(pv.global_theme.multi_samples)
        return
    from engine.outputs.occlusion import part_vertex_occlusion

    plotter.set_background(look.background[0], top=look.background[1])
    camera_lights(renderer, look)
    renderer.SetUseFXAA(look.antialias == "fxaa")          # on the screen: VTK's own FXAA pass
    if window is not None and look.antialias == "fxaa" and not keep_samples:
        window.SetMultiSamples(0)
    occlusion = part_vertex_occlusion(model, look.occlusion_radius_mm) if look.shading != "legacy" else {}
    for view in views:
        dress_view(view, look, occlusion.get(view.part, np.ones(model.n_vertices)))


def dress_view(view: PartView, look, occlusion: np.ndarray) -> None:
    """Shade one mesh as ``look`` (an :class:`engine.outputs.looks.Look`) shades it in ``render``.

    A physically based look gets the engine's shader and, as the point array it reads, the baked
    occlusion of the mesh's vertices (``occlusion``: the part's value per model vertex); ``legacy`` gets
    the renderer's Phong materials of the part (its colours stay the viewport's).
    """
    from vtkmodules.util.numpy_support import numpy_to_vtk

    from engine.outputs.look_actors import OCCLUSION_ARRAY, dress_actor
    from engine.outputs.part_materials import part_material

    if look.shading == "legacy":
        _, ambient, diffuse, specular, power = part_material(view.part)
        prop = view.actor.GetProperty()
        prop.SetInterpolationToPhong()
        prop.SetAmbient(ambient)
        prop.SetDiffuse(diffuse)
        prop.SetSpecular(specular)
        prop.SetSpecularPower(power)
        return
    values = numpy_to_vtk(np.ascontiguousarray(occlusion[view.vertex_indices], dtype=np.float32), deep=True)
    values.SetName(OCCLUSION_ARRAY)
    view.mesh.GetPointData().AddArray(values)
    old = view.actor.GetMapper()
    if not hasattr(old, "MapDataArrayToVertexAttribute"):
        # pyvista's vtkDataSetMapper: the shader's attribute needs a polydata mapper
        from vtkmodules.vtkRenderingCore import vtkPolyDataMapper

        mapper = vtkPolyDataMapper()
        mapper.ShallowCopy(old)                   # colours: the same array, mode and visibility
        mapper.SetInputData(view.mesh)
        view.actor.SetMapper(mapper)
    if view.texture is not None:
        view.texture.UseSRGBColorSpaceOn()         # decoded to linear light, as the renderer's PBR does
    dress_actor(view.actor, look, view.part)


def show_texture(view: PartView, on: bool, physically_based: bool) -> None:
    """Draw a textured mesh with its image (``on``) or with its vertex colours; in a physically based look
    the image is the PBR base colour, otherwise the actor's texture."""
    view.actor.GetMapper().SetScalarVisibility(not on)
    prop = view.actor.GetProperty()
    if physically_based:
        view.actor.SetTexture(None)
        if on:
            prop.SetBaseColorTexture(view.texture)
        else:
            prop.RemoveTexture("albedoTex")
    else:
        view.actor.SetTexture(view.texture if on else None)
    prop.SetColor(1.0, 1.0, 1.0)


def camera_lights(renderer, look) -> None:
    """The renderer's lights for ``look``: the legacy look's three camera lights (a physically based look
    brings its own in its shader and needs one VTK light only for VTK to write lighting code)."""
    from vtkmodules.vtkRenderingCore import vtkLight

    from engine.outputs.looks import Light

    renderer.RemoveAllLights()
    lights = look.lights if look.shading == "legacy" else [Light((0.0, 0.0, 1.0))]
    for light in lights:
        vtk_light = vtkLight()
        vtk_light.SetLightTypeToCameraLight()
        vtk_light.SetPosition(*light.direction)
        vtk_light.SetFocalPoint(0.0, 0.0, 0.0)
        vtk_light.SetIntensity(light.intensity)
        renderer.AddLight(vtk_light)
