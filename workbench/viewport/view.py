"""The 3-D view of the model: the viewport widget (with its parts, picking and points modules, the drawing
modules of the workbench that import pyvista).

Each part of the model is one actor drawing its own :class:`pyvista.PolyData`,
which holds the points, the polygons, the vertex colours and the vertex
normals (smooth shading). The actors are built once per model; a pose change
writes the new vertex positions into those meshes and recomputes the normals
with a ``vtkPolyDataNormals`` filter that reads only points and polygons
(a live-preview dab, which moves a few points, recomputes only the normals
around them: :mod:`workbench.viewport.local_normals`). A
colour change therefore touches the colours alone: VTK re-uploads one array
and recomputes nothing, so a brush dab costs no more to draw than an
unchanged view (``benchmarks/bench_paint_gui.py``).

Every vertex carries a colour (array ``vertex_colors``): its ordinary colour,
or, while a parameter is selected and the heat map is on, the parameter's
weight on the blue → red ramp of :func:`engine.painting.heat_colors`. Tools
may show colours of their own with :meth:`Viewport.show_colors` and change a
few vertices fast with :meth:`Viewport.update_colors` (a brush dab).

The view is lit and shaded in a look (:mod:`engine.outputs.looks`, View → Look): by default the one
``render`` draws with, so the head on screen is the head of the pictures and videos (its lights, its
materials and shader, its baked occlusion, FXAA, its background; :func:`~workbench.viewport.parts.dress_view`);
``set_look(None)`` gives the workbench's own shading (pyvista's light kit, Gouraud).

A textured model (``model.texture``) is drawn as one mesh per part and image
(:func:`~workbench.viewport.parts.part_pieces`: a point for each distinct
vertex and (u, v), so seams stay sharp; the points of one vertex share its
normal). Its textured meshes show their image while the ordinary colours are
shown, and the vertex colours instead while a heat map or a tool's colours
are, so painting and weights look as on any model.
"""

from __future__ import annotations

import numpy as np
import pyvista as pv
from PySide6.QtWidgets import QVBoxLayout, QWidget
from pyvistaqt import QtInteractor

import engine
from engine.outputs.looks import Look, look_from
from engine.outputs.render import vtk_texture
from engine.painting import heat_colors

from ..document.model_document import ModelDocument
from ..document.view_state import ViewState
from .colors import base_vertex_colors
from .keys import keep_keys_from_vtk
from .parts import VERTEX_COLORS, PartView, dress_scene, part_pieces, show_texture
from .picking import SurfacePick, cell_weights, new_cell_picker, pick_surface
from .points import PointOverlays

# Direction from the model towards the camera for each preset view. The
# default head faces +Z with +Y up, so its left side is +X.
VIEWS: dict[str, tuple[float, float, float]] = {
    "front": (0.0, 0.0, 1.0),
    "side": (1.0, 0.0, 0.0),
    "three-quarter": (1.0, 0.12, 1.1),
}
BACKGROUND_BOTTOM = "#5d6670"
BACKGROUND_TOP = "#c9ced4"
TEXTURE_SIDE = 4096       # images larger than this are reduced once before they are shown


class Viewport(QWidget):
    """Shows the document's model in its current pose and follows every change."""

    def __init__(self, document: ModelDocument, view_state: ViewState, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self._view_state = view_state
        self._parts: dict[str, PartView] = {}
        self._view = "front"
        self._base_colors = np.zeros((0, 3), dtype=np.uint8)
        self._overlay: np.ndarray | None = None      # colours a tool asked for, else None
        # per mesh: its points sorted by model vertex (order, sorted vertex indices), for finding a vertex's points
        self._local_of: dict[str, tuple[np.ndarray, np.ndarray]] | None = None
        self._multi_samples: int | None = None     # saved while set_fast_rendering(True)
        self._look: Look | None = look_from(None)   # None: the workbench's own shading
        # auto_update=False: we render after each change ourselves; pyvistaqt's
        # default would also re-render five times a second for nothing.
        self.plotter = QtInteractor(self, auto_update=False)
        if self.plotter.iren is not None:
            # pyvista's default keys ('q' closes the plotter, 'v', 'b', ...) would
            # fight the window's shortcuts.
            self.plotter.iren.clear_key_event_callbacks()
        keep_keys_from_vtk(self.plotter)     # nor VTK's own ('w' wireframe, '3' stereo, 'p' pick box, ...)
        self.plotter.set_background(BACKGROUND_BOTTOM, top=BACKGROUND_TOP)
        self._points = PointOverlays(self.plotter)
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
        self._picker = new_cell_picker()
        self._build(document.model)
        self.set_view("front")

    # -- public ----------------------------------------------------------
    @property
    def part_names(self) -> list[str]:
        return list(dict.fromkeys(view.part for view in self._parts.values()))

    def part_mesh(self, part: str) -> pv.PolyData:
        """The mesh the part's actor draws (points in mm, the part's vertices only); for a textured part,
        its first mesh (or give the key ``"part@image"``)."""
        return self._view_of(part).mesh

    def part_actor(self, part: str):
        return self._view_of(part).actor

    def part_keys(self) -> list[str]:
        """The meshes drawn: a part's name, or ``"part@image"`` for its polygons showing an image."""
        return list(self._parts)

    def _view_of(self, key: str) -> PartView:
        if key in self._parts:
            return self._parts[key]
        for view in self._parts.values():
            if view.part == key:
                return view
        raise KeyError(key)

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
        self._points.show(name, points, color, labels)
        self._schedule_render()

    def hide_points(self, name: str) -> None:
        """Stop drawing the dots (and labels) shown under ``name``, if any."""
        if self._points.hide(name):
            self._schedule_render()

    def shown_points(self, name: str) -> np.ndarray:
        """(k, 3) mm: the dots drawn now under ``name`` (none while hidden)."""
        return self._points.shown(name)

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
            if 2 * len(local) > view.mesh.n_points:
                view.update_normals()           # most of the part moved (an identity preview): the whole-part
            else:                               # filter is faster than the local update
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
        found = pick_surface(self._picker, self.plotter, self._parts, x, y)
        if found is None:
            return None
        hit, view, cell_id = found
        vertices, weights = cell_weights(view, cell_id, hit.point)
        return hit, vertices, weights

    def _local_lookup(self) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        if self._local_of is None:
            self._local_of = {}
            for key, view in self._parts.items():
                order = np.argsort(view.vertex_indices, kind="stable")
                self._local_of[key] = (order, view.vertex_indices[order])
        return self._local_of

    def _locate(self, indices: np.ndarray):
        """Per mesh holding some of ``indices``: (view, mesh point indices, rows of ``indices``); a vertex
        drawn as several points (a texture seam) gives a row for each."""
        lookup = self._local_lookup()
        for key, view in self._parts.items():
            order, ordered = lookup[key]
            first = np.searchsorted(ordered, indices, side="left")
            counts = np.searchsorted(ordered, indices, side="right") - first
            rows = np.repeat(np.arange(len(indices)), counts)
            if len(rows):
                starts = np.repeat(first - np.cumsum(counts) + counts, counts)
                yield view, order[starts + np.arange(len(rows))], rows

    def pick(self, x: float, y: float) -> SurfacePick | None:
        """The visible surface under widget pixel (``x``, ``y``) (Qt coordinates, y down), or ``None``."""
        found = pick_surface(self._picker, self.plotter, self._parts, x, y)
        return None if found is None else found[0]

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

    @property
    def look(self) -> Look | None:
        """The look the view is drawn in (``None``: the workbench's own shading)."""
        return self._look

    def set_look(self, look: str | Look | None) -> None:
        """Draw the model in ``look`` (a name, a :class:`~engine.outputs.looks.Look`, or ``None``)."""
        self._look = None if look is None else look_from(look)
        self._build(self._document.model)
        self._schedule_render()

    def close_plotter(self) -> None:
        """Release the VTK render window and every actor (call before the widget goes away)."""
        self._parts.clear()
        self._points.clear()
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
        textures: dict[int, object] = {}
        for piece in part_pieces(model):
            part, indices, cells = piece.part, piece.vertex_indices, piece.cells
            if len(cells) == 0:
                continue
            mesh = pv.PolyData(np.ascontiguousarray(points[indices]), cells)
            mesh.point_data[VERTEX_COLORS] = colors[indices]
            actor = self.plotter.add_mesh(
                mesh, scalars=VERTEX_COLORS, rgb=True, show_scalar_bar=False, smooth_shading=False,
                style="wireframe" if self._view_state.wireframe else "surface",
                specular=0.25 if part != "skin" else 0.12, specular_power=20.0,
                name=f"part:{piece.key}", reset_camera=False, render=False)
            actor.prop.interpolation = "gouraud"
            actor.SetVisibility(self._view_state.is_part_visible(part))
            # The mapper reads the mesh itself: pyvista puts a scalars-selecting step in
            # between that re-runs (in Python, copying the mesh) on every colour change.
            mesh.point_data.active_scalars_name = VERTEX_COLORS
            actor.GetMapper().SetInputData(mesh)
            view = PartView(indices, mesh, PartView.shading(mesh), actor, part=part)
            if piece.uv is not None and model.texture is not None:
                mesh.active_texture_coordinates = np.ascontiguousarray(piece.uv, dtype=np.float32)
                if piece.image not in textures:
                    textures[piece.image] = vtk_texture(model.texture.images[piece.image].pixels, TEXTURE_SIDE)
                view.texture = textures[piece.image]
                view.seam_groups = np.unique(indices, return_inverse=True)[1].reshape(-1)
            view.update_normals()
            self._parts[piece.key] = view
        dress_scene(self.plotter, list(self._parts.values()), model, self._look, (BACKGROUND_BOTTOM, BACKGROUND_TOP),
                    keep_samples=self._multi_samples is not None)
        self._show_textures(colors is self._base_colors)

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
        self._show_textures(colors is self._base_colors)
        self._schedule_render()

    def _show_textures(self, on: bool) -> None:
        """Textured meshes show their image (``on``: the ordinary colours are shown) or their vertex colours."""
        physically_based = self._look is not None and self._look.shading != "legacy"
        for view in self._parts.values():
            if view.texture is not None:
                show_texture(view, on, physically_based)

    def textures_shown(self) -> list[str]:
        """The keys of the meshes drawing an image now."""
        return [key for key, view in self._parts.items()
                if view.actor.GetTexture() is not None or view.actor.GetProperty().GetTexture("albedoTex")]

    def _on_wireframe_changed(self, on: bool) -> None:
        for view in self._parts.values():
            view.actor.prop.style = "wireframe" if on else "surface"
        self._schedule_render()

    def _on_part_visibility_changed(self, part: str, visible: bool) -> None:
        views = [view for view in self._parts.values() if view.part == part]
        for view in views:
            view.actor.SetVisibility(visible)
        if views:
            self._schedule_render()

    def _schedule_render(self) -> None:
        # QWidget.update(): one paint (= one VTK render) at the next turn of the
        # event loop, however many changes arrive before it. plotter.render()
        # would render now and then again in the paint it triggers.
        self.plotter.update()

