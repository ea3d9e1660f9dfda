"""The 3-D view of the model: the only workbench module that imports pyvista.

Each part of the model is one actor drawing its own :class:`pyvista.PolyData`,
which holds the points, the polygons, the vertex colours and the vertex
normals (smooth shading). The actors are built once per model; a pose change
writes the new vertex positions into those meshes and recomputes the normals
with a ``vtkPolyDataNormals`` filter that reads only points and polygons
(a live-preview dab, which moves a few points, recomputes only the normals
around them: :mod:`workbench.local_normals`). A
colour change therefore touches the colours alone: VTK re-uploads one array
and recomputes nothing, so a brush dab costs no more to draw than an
unchanged view (``benchmarks/bench_paint_gui.py``).

Every vertex carries a colour (array ``vertex_colors``): its ordinary colour,
or, while a parameter is selected and the heat map is on, the parameter's
weight on the blue → red ramp of :func:`engine.painting.heat_colors`. Tools
may show colours of their own with :meth:`Viewport.show_colors` and change a
few vertices fast with :meth:`Viewport.update_colors` (a brush dab).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import pyvista as pv
from pyvistaqt import QtInteractor
from PySide6.QtWidgets import QVBoxLayout, QWidget
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkCommonCore import reference as vtk_reference
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkStaticCellLocator
from vtkmodules.vtkRenderingCore import vtkCellPicker

import engine
from engine.model.cells import cell_sizes, cell_starts

from engine.painting import heat_colors

from .colors import base_vertex_colors
from .document import ModelDocument
from .local_normals import LocalNormals
from .view_state import ViewState

# Direction from the model towards the camera for each preset view. The
# default head faces +Z with +Y up, so its left side is +X.
VIEWS: dict[str, tuple[float, float, float]] = {
    "front": (0.0, 0.0, 1.0),
    "side": (1.0, 0.0, 0.0),
    "three-quarter": (1.0, 0.12, 1.1),
}
VERTEX_COLORS = "vertex_colors"  # name of the per-vertex sRGB array on each part mesh
POINT_SIZE = 11.0                # dots drawn by Viewport.show_points, px
LABEL_FONT_SIZE = 11
BACKGROUND_BOTTOM = "#5d6670"
BACKGROUND_TOP = "#c9ced4"


class SurfacePick(NamedTuple):
    """Where a ray through a pixel meets the drawn surface."""

    point: np.ndarray   # (3,) mm, on the surface as drawn (the current pose)
    vertex: int         # model index of the vertex of the hit polygon nearest the point
    part: str
    normal: np.ndarray  # (3,) unit normal of the hit polygon, towards the camera side


@dataclass
class _PartView:
    """One part on screen: the mesh its actor draws, the normals filter that shades it, the actor."""

    vertex_indices: np.ndarray  # model vertex index of each mesh point
    mesh: pv.PolyData           # points, polygons, colours and normals: what the mapper draws
    normals: vtkPolyDataNormals  # reads the mesh's points and polygons only (not its colours)
    actor: object
    locator: vtkStaticCellLocator | None = None    # for picking; rebuilt when the points have moved
    locator_points_time: int = -1
    local_normals: LocalNormals | None = None      # for moving a few points (live preview), built on first use

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
        self.mesh.GetPointData().SetNormals(self.normals.GetOutput().GetPointData().GetNormals())

    def update_normals_near(self, moved: np.ndarray) -> None:
        """Recompute only the normals that moving the mesh points ``moved`` changes (a live-preview dab)."""
        if self.local_normals is None:
            self.local_normals = LocalNormals(self.mesh.faces, self.mesh.n_points)
        array = self.mesh.GetPointData().GetNormals()
        normals = pv.convert_array(array)
        self.local_normals.update(np.asarray(self.mesh.points, dtype=float), normals, moved)
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


@dataclass
class _PointSet:
    """Dots drawn over the model (and their labels): one cloud, its actors, what it was built with."""

    cloud: pv.PolyData
    actors: list
    labels: list[str] | None
    color: str


class Viewport(QWidget):
    """Shows the document's model in its current pose and follows every change."""

    def __init__(self, document: ModelDocument, view_state: ViewState, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self._view_state = view_state
        self._parts: dict[str, _PartView] = {}
        self._point_sets: dict[str, _PointSet] = {}
        self._view = "front"
        self._base_colors = np.zeros((0, 3), dtype=np.uint8)
        self._overlay: np.ndarray | None = None      # colours a tool asked for, else None
        self._local_of: dict[str, np.ndarray] | None = None   # per part: model index → mesh point (-1)
        self._multi_samples: int | None = None     # saved while set_fast_rendering(True)
        # auto_update=False: we render after each change ourselves; pyvistaqt's
        # default would also re-render five times a second for nothing.
        self.plotter = QtInteractor(self, auto_update=False)
        if self.plotter.iren is not None:
            # pyvista's default keys ('q' closes the plotter, 'v', 'b', ...) would
            # fight the window's shortcuts.
            self.plotter.iren.clear_key_event_callbacks()
        self.plotter.set_background(BACKGROUND_BOTTOM, top=BACKGROUND_TOP)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.plotter)

        document.model_replaced.connect(self._on_model_replaced)
        document.values_changed.connect(self._on_values_changed)
        # A model edit (tree, weights; also undo and redo) changes the deformation of the pose shown.
        document.parameters_changed.connect(self._on_values_changed)
        document.regions_changed.connect(self._on_values_changed)
        view_state.wireframe_changed.connect(self._on_wireframe_changed)
        view_state.part_visibility_changed.connect(self._on_part_visibility_changed)
        view_state.selected_parameter_changed.connect(self._refresh_colors)
        view_state.heat_map_changed.connect(self._refresh_colors)
        document.regions_changed.connect(self._on_regions_changed)
        document.parameters_changed.connect(self._on_parameters_edited)
        self._picker = vtkCellPicker()
        self._picker.SetTolerance(0.0005)
        self._picker.PickFromListOn()
        self._build(document.model)
        self.set_view("front")

    # -- public ----------------------------------------------------------
    @property
    def part_names(self) -> list[str]:
        return list(self._parts)

    def part_mesh(self, part: str) -> pv.PolyData:
        """The mesh the part's actor draws (points in mm, the part's vertices only)."""
        return self._parts[part].mesh

    def part_actor(self, part: str):
        return self._parts[part].actor

    def displayed_points(self) -> np.ndarray:
        """Vertex positions (N, 3, mm) as the render pipeline holds them, in model order.

        Read back from the data each mapper draws (the end of its pipeline),
        so tests check the screen and not just our own bookkeeping. Vertices
        that no polygon uses are not drawn and come back as NaN.
        """
        out = np.full((self._document.model.n_vertices, 3), np.nan)
        for view in self._parts.values():
            source = view.actor.GetMapper().GetInputAlgorithm()
            source.Update()
            out[view.vertex_indices] = pv.wrap(source.GetOutputDataObject(0)).points
        return out

    def displayed_colors(self) -> np.ndarray:
        """(N, 3) uint8 vertex colours as the render pipeline holds them, in model order."""
        out = np.zeros((self._document.model.n_vertices, 3), dtype=np.uint8)
        for view in self._parts.values():
            source = view.actor.GetMapper().GetInputAlgorithm()
            source.Update()
            out[view.vertex_indices] = pv.wrap(source.GetOutputDataObject(0)).point_data[VERTEX_COLORS]
        return out

    def show_points(self, name: str, points, color: str, labels=None) -> None:
        """Draw ``points`` ((k, 3) mm) as flat dots in ``color``, each with its text from ``labels`` beside it.

        Called again with the same name, labels and colour it moves the dots
        (and labels) in place. Labels of points behind the model are hidden.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        labels = None if labels is None else [str(label) for label in labels]
        entry = self._point_sets.get(name)
        if entry is None or entry.labels != labels or entry.color != color or entry.cloud.n_points != len(points):
            self._remove_points(name)
            cloud = pv.PolyData(points.copy())
            actors = [self.plotter.add_mesh(cloud, color=color, point_size=POINT_SIZE, render_points_as_spheres=True,
                                            lighting=False, name=f"points:{name}", pickable=False,
                                            reset_camera=False, render=False)]
            if labels:
                cloud.point_data["labels"] = np.array(labels)
                actors.append(self.plotter.add_point_labels(
                    cloud, "labels", name=f"labels:{name}", font_size=LABEL_FONT_SIZE, text_color="white",
                    shape_color="#20262c", shape_opacity=0.55, margin=2, show_points=False,
                    always_visible=False, tolerance=0.01, reset_camera=False, render=False))
            entry = self._point_sets[name] = _PointSet(cloud, actors, labels, color)
        else:
            entry.cloud.points[:] = points
            entry.cloud.Modified()
        for actor in entry.actors:
            actor.SetVisibility(True)
        self._schedule_render()

    def hide_points(self, name: str) -> None:
        """Stop drawing the dots (and labels) shown under ``name``, if any."""
        entry = self._point_sets.get(name)
        if entry is not None and entry.actors[0].GetVisibility():
            for actor in entry.actors:
                actor.SetVisibility(False)
            self._schedule_render()

    def shown_points(self, name: str) -> np.ndarray:
        """(k, 3) mm: the dots drawn now under ``name`` (none while hidden)."""
        entry = self._point_sets.get(name)
        if entry is None or not entry.actors[0].GetVisibility():
            return np.zeros((0, 3))
        return np.array(entry.cloud.points)

    def _remove_points(self, name: str) -> None:
        entry = self._point_sets.pop(name, None)
        for actor in entry.actors if entry is not None else ():
            self.plotter.remove_actor(actor, render=False)

    def displayed_normals(self, indices) -> np.ndarray:
        """(k, 3) unit normals of the model vertices ``indices`` as drawn now (NaN where not drawn)."""
        indices = np.asarray(indices, dtype=np.int64).reshape(-1)
        out = np.full((len(indices), 3), np.nan)
        for view, local, rows in self._locate(indices):
            out[rows] = pv.convert_array(view.mesh.GetPointData().GetNormals())[local]
        return out

    def heat_map_colors(self, name: str) -> np.ndarray:
        """(N, 3) uint8: parameter ``name``'s weights as heat colours over the ordinary colours."""
        model = self._document.model
        weights = model.regions[name].dense(model.n_vertices)
        return heat_colors(weights, base=self._base_colors)

    def show_colors(self, colors: np.ndarray | None) -> None:
        """Draw every vertex in ``colors`` ((N, 3) uint8), or go back to the ordinary/heat-map colours (``None``).

        While colours are shown this way, selection and region changes do not repaint.
        """
        if colors is not None:
            colors = np.asarray(colors, dtype=np.uint8)
            if colors.shape != self._base_colors.shape:
                raise ValueError(f"colours must be {self._base_colors.shape}, not {colors.shape}")
            self._overlay = colors.copy()
        else:
            self._overlay = None
        self._refresh_colors()

    def update_colors(self, indices, colors) -> None:
        """Recolour only the vertices ``indices`` (model order) with ``colors`` ((k, 3) uint8), fast.

        For a brush dab: the rest of the mesh keeps what it shows.
        """
        indices = np.asarray(indices, dtype=np.int64).reshape(-1)
        colors = np.asarray(colors, dtype=np.uint8).reshape(-1, 3)
        if self._overlay is not None:
            self._overlay[indices] = colors
        for view, local, rows in self._locate(indices):
            view.mesh.point_data[VERTEX_COLORS][local] = colors[rows]
            view.mesh.GetPointData().GetArray(VERTEX_COLORS).Modified()
        self._schedule_render()

    def base_colors(self) -> np.ndarray:
        """(N, 3) uint8: every vertex's ordinary colour (part colour or painted), what weight 0 shows.

        Read-only; a painting tool colours changed vertices with
        ``heat_colors(weights[idx], base=viewport.base_colors()[idx])``.
        """
        view = self._base_colors.view()
        view.flags.writeable = False
        return view

    def update_points(self, indices, positions) -> None:
        """Move only the vertices ``indices`` (model order) to ``positions`` ((k, 3) mm), fast.

        For live preview while painting: a dab moves a few vertices of the
        posed mesh. The next pose or model change redraws every vertex from
        the document again.
        """
        indices = np.asarray(indices, dtype=np.int64).reshape(-1)
        positions = np.asarray(positions, dtype=float).reshape(-1, 3)
        for view, local, rows in self._locate(indices):
            points = view.mesh.GetPoints()
            array = pv.convert_array(points.GetData())
            array[local] = positions[rows]
            points.Modified()
            view.update_normals_near(local)
        self._schedule_render()

    def set_fast_rendering(self, on: bool) -> None:
        """Draw without multisampling while ``on`` (a brush stroke): 3–4× faster with software OpenGL.

        Anti-aliasing comes back (and the view is redrawn) when switched off again.
        """
        window = self.plotter.render_window
        if window is None:
            return
        if on and self._multi_samples is None:
            self._multi_samples = window.GetMultiSamples()
            window.SetMultiSamples(0)
        elif not on and self._multi_samples is not None:
            window.SetMultiSamples(self._multi_samples)
            self._multi_samples = None
            self._schedule_render()

    def pick_cell(self, x: float, y: float):
        """Like :meth:`pick`, plus the hit polygon: ``(pick, vertices, weights)`` or ``None``.

        ``vertices`` are the polygon's model vertex indices and ``weights``
        the hit point's interpolation weights on them (summing to 1), so the
        same point on another copy of the mesh — the rest mesh, when the
        drawn one is posed — is ``weights @ other[vertices]``.
        """
        found = self._pick(x, y)
        if found is None:
            return None
        hit, view, cell_id = found
        cell = view.mesh.GetCell(cell_id)
        n = cell.GetNumberOfPoints()
        closest, sub_id, pcoords, dist2 = [0.0, 0.0, 0.0], vtk_reference(0), [0.0, 0.0, 0.0], vtk_reference(0.0)
        weights = [0.0] * n
        cell.EvaluatePosition(list(hit.point), closest, sub_id, pcoords, dist2, weights)
        ids = np.array([cell.GetPointId(k) for k in range(n)], dtype=np.int64)
        weights = np.clip(np.asarray(weights, dtype=float), 0.0, None)
        total = weights.sum()
        weights = weights / total if total > 0 else np.full(n, 1.0 / n)
        return hit, view.vertex_indices[ids], weights

    def _local_lookup(self) -> dict[str, np.ndarray]:
        if self._local_of is None:
            n = self._document.model.n_vertices
            self._local_of = {}
            for part, view in self._parts.items():
                lookup = np.full(n, -1, dtype=np.int64)
                lookup[view.vertex_indices] = np.arange(len(view.vertex_indices))
                self._local_of[part] = lookup
        return self._local_of

    def _locate(self, indices: np.ndarray):
        """Per part holding some of ``indices``: (view, mesh point indices, rows of ``indices``)."""
        lookup = self._local_lookup()
        for part, view in self._parts.items():
            local = lookup[part][indices]
            rows = np.flatnonzero(local >= 0)
            if len(rows):
                yield view, local[rows], rows

    def pick(self, x: float, y: float) -> SurfacePick | None:
        """The visible surface under widget pixel (``x``, ``y``) (Qt coordinates, y down), or ``None``."""
        found = self._pick(x, y)
        return None if found is None else found[0]

    def _pick(self, x: float, y: float):
        renderer = self.plotter.renderer
        picker = self._picker
        picker.InitializePickList()
        picker.RemoveAllLocators()
        visible = [part for part, view in self._parts.items() if view.actor.GetVisibility()]
        for part in visible:
            picker.AddPickList(self._parts[part].actor)
            picker.AddLocator(self._parts[part].current_locator())
        if not visible:
            return None
        ratio = self.plotter.devicePixelRatioF() if hasattr(self.plotter, "devicePixelRatioF") else 1.0
        height = renderer.GetRenderWindow().GetSize()[1]
        if not picker.Pick(x * ratio, height - 1 - y * ratio, 0.0, renderer):
            return None
        actor = picker.GetActor()
        part = next((name for name in visible if self._parts[name].actor is actor), None)
        if part is None:
            return None
        view = self._parts[part]
        point = np.array(picker.GetPickPosition())
        cell_id = picker.GetCellId()
        cell = view.mesh.get_cell(cell_id)
        ids = np.asarray(cell.point_ids)
        drawn = view.mesh.points[ids]
        nearest = ids[int(np.argmin(np.linalg.norm(drawn - point, axis=1)))]
        normal = np.array(picker.GetPickNormal())
        return SurfacePick(point, int(view.vertex_indices[nearest]), part, normal), view, cell_id

    def world_to_widget(self, point) -> tuple[float, float]:
        """Widget pixel (x, y; Qt coordinates) where the world point ``point`` (mm) is drawn."""
        renderer = self.plotter.renderer
        renderer.SetWorldPoint(*np.asarray(point, dtype=float), 1.0)
        renderer.WorldToDisplay()
        dx, dy, _ = renderer.GetDisplayPoint()
        ratio = self.plotter.devicePixelRatioF() if hasattr(self.plotter, "devicePixelRatioF") else 1.0
        height = renderer.GetRenderWindow().GetSize()[1]
        return dx / ratio, (height - 1 - dy) / ratio

    def render_now(self) -> None:
        """Render immediately (benchmarks and screenshots; interactive code lets Qt batch renders)."""
        self.plotter.render()

    def set_view(self, name: str) -> None:
        """Frame the whole model from a preset direction: ``front``, ``side`` or ``three-quarter``."""
        if name not in VIEWS:
            raise ValueError(f"unknown view '{name}' (views: {', '.join(VIEWS)})")
        self._view = name
        direction = np.asarray(VIEWS[name], dtype=float)
        direction /= np.linalg.norm(direction)
        rest = self._document.model.vertices
        if len(rest) == 0:
            return
        lo, hi = rest.min(axis=0), rest.max(axis=0)
        center = (lo + hi) / 2
        radius = max(float(np.linalg.norm(hi - lo)) / 2, 1e-6)
        camera = self.plotter.camera
        # Fit the bounding sphere to the narrower of the two view angles, with a margin.
        half_angle = np.deg2rad(camera.view_angle) / 2
        width, height = max(self.plotter.width(), 1), max(self.plotter.height(), 1)
        if width < height:
            half_angle = np.arctan(np.tan(half_angle) * width / height)
        distance = 0.92 * radius / np.sin(half_angle)
        camera.focal_point = tuple(center)
        camera.position = tuple(center + distance * direction)
        camera.up = (0.0, 1.0, 0.0)
        self.plotter.renderer.ResetCameraClippingRange()
        self._schedule_render()

    def close_plotter(self) -> None:
        """Release the VTK render window and every actor (call before the widget goes away)."""
        self._parts.clear()
        self._point_sets.clear()
        self.plotter.close()

    # -- building --------------------------------------------------------
    def _build(self, model: engine.Model) -> None:
        for view in self._parts.values():
            self.plotter.remove_actor(view.actor, render=False)
        self._parts.clear()
        self._local_of = None
        points = self._document.vertices()
        self._overlay = None
        # Painted colours (eyebrows, iris, pupil) win over the part colour, as in engine.outputs.render.
        self._base_colors = base_vertex_colors(model)
        colors = self._current_colors()
        for part, (indices, cells) in _split_by_part(model).items():
            if len(cells) == 0:
                continue
            mesh = pv.PolyData(np.ascontiguousarray(points[indices]), cells)
            mesh.point_data[VERTEX_COLORS] = colors[indices]
            actor = self.plotter.add_mesh(
                mesh, scalars=VERTEX_COLORS, rgb=True, show_scalar_bar=False, smooth_shading=False,
                style="wireframe" if self._view_state.wireframe else "surface",
                specular=0.25 if part != "skin" else 0.12, specular_power=20.0,
                name=f"part:{part}", reset_camera=False, render=False)
            actor.prop.interpolation = "gouraud"
            actor.SetVisibility(self._view_state.is_part_visible(part))
            # The mapper reads the mesh itself: pyvista puts a scalars-selecting step in
            # between that re-runs (in Python, copying the mesh) on every colour change.
            mesh.point_data.active_scalars_name = VERTEX_COLORS
            actor.GetMapper().SetInputData(mesh)
            view = _PartView(indices, mesh, _PartView.shading(mesh), actor)
            view.update_normals()
            self._parts[part] = view

    # -- listeners -------------------------------------------------------
    def _on_model_replaced(self, model: engine.Model) -> None:
        self._build(model)
        self.set_view(self._view)

    def _on_values_changed(self, _names: list) -> None:
        points = self._document.vertices()
        for view in self._parts.values():
            view.mesh.points[:] = points[view.vertex_indices]
            view.update_normals()
        self._schedule_render()

    def _on_regions_changed(self, names: list) -> None:
        if self._view_state.selected_parameter in names:
            self._refresh_colors()

    def _on_parameters_edited(self, _names: list) -> None:
        self._refresh_colors()     # a rename or removal may change what the heat map shows

    def _current_colors(self) -> np.ndarray:
        if self._overlay is not None:
            return self._overlay
        name = self._view_state.selected_parameter
        model = self._document.model
        if self._view_state.heat_map and name is not None and name in model.regions:
            return self.heat_map_colors(name)
        return self._base_colors

    def _refresh_colors(self, *_args) -> None:
        colors = self._current_colors()
        for view in self._parts.values():
            view.mesh.point_data[VERTEX_COLORS][:] = colors[view.vertex_indices]
            view.mesh.GetPointData().GetArray(VERTEX_COLORS).Modified()
        self._schedule_render()

    def _on_wireframe_changed(self, on: bool) -> None:
        for view in self._parts.values():
            view.actor.prop.style = "wireframe" if on else "surface"
        self._schedule_render()

    def _on_part_visibility_changed(self, part: str, visible: bool) -> None:
        view = self._parts.get(part)
        if view is not None:
            view.actor.SetVisibility(visible)
            self._schedule_render()

    def _schedule_render(self) -> None:
        # QWidget.update(): one paint (= one VTK render) at the next turn of the
        # event loop, however many changes arrive before it. plotter.render()
        # would render now and then again in the paint it triggers.
        self.plotter.update()


def _split_by_part(model: engine.Model) -> dict[str, tuple[np.ndarray, np.ndarray]]:
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
