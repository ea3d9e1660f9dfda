"""The 3-D view of the model: the only workbench module that imports pyvista.

Each part of the model is one actor fed by its own :class:`pyvista.PolyData`
through a ``vtkPolyDataNormals`` filter. The actors are built once per model;
a pose change only writes the new vertex positions into those meshes, so the
normals (smooth shading) follow the deformation and nothing is rebuilt.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pyvista as pv
from pyvistaqt import QtInteractor
from PySide6.QtWidgets import QVBoxLayout, QWidget
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

import engine
from engine.cells import cell_sizes, cell_starts

from .colors import part_color
from .document import ModelDocument
from .view_state import ViewState

# Direction from the model towards the camera for each preset view. The
# default head faces +Z with +Y up, so its left side is +X.
VIEWS: dict[str, tuple[float, float, float]] = {
    "front": (0.0, 0.0, 1.0),
    "side": (1.0, 0.0, 0.0),
    "three-quarter": (1.0, 0.12, 1.1),
}
VERTEX_COLORS = "vertex_colors"  # name of the per-vertex sRGB array on each part mesh
BACKGROUND_BOTTOM = "#5d6670"
BACKGROUND_TOP = "#c9ced4"


@dataclass
class _PartView:
    """One part on screen: its mesh, the normals filter reading it, its actor."""

    vertex_indices: np.ndarray  # model vertex index of each mesh point
    mesh: pv.PolyData
    normals: vtkPolyDataNormals
    actor: object


class Viewport(QWidget):
    """Shows the document's model in its current pose and follows every change."""

    def __init__(self, document: ModelDocument, view_state: ViewState, parent: QWidget | None = None):
        super().__init__(parent)
        self._document = document
        self._view_state = view_state
        self._parts: dict[str, _PartView] = {}
        self._view = "front"
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
        self.plotter.close()

    # -- building --------------------------------------------------------
    def _build(self, model: engine.Model) -> None:
        for view in self._parts.values():
            self.plotter.remove_actor(view.actor, render=False)
        self._parts.clear()
        points = self._document.vertices()
        for part, (indices, cells) in _split_by_part(model).items():
            if len(cells) == 0:
                continue
            mesh = pv.PolyData(np.ascontiguousarray(points[indices]), cells)
            if model.vertex_colors is not None:
                # Painted colours (eyebrows, iris, pupil) win over the part colour, as
                # in engine.render; the normals filter passes them through.
                mesh.point_data[VERTEX_COLORS] = model.vertex_colors[indices]
                colors = dict(scalars=VERTEX_COLORS, rgb=True, show_scalar_bar=False)
            else:
                colors = dict(color=part_color(model, part))
            normals = vtkPolyDataNormals()
            normals.SetInputData(mesh)
            normals.SplittingOff()       # one normal per vertex: smooth, and points stay 1:1
            normals.ConsistencyOff()     # the model's polygons are already consistently wound
            normals.ComputePointNormalsOn()
            normals.ComputeCellNormalsOff()
            actor = self.plotter.add_mesh(
                normals, **colors, smooth_shading=False,
                style="wireframe" if self._view_state.wireframe else "surface",
                specular=0.25 if part != "skin" else 0.12, specular_power=20.0,
                name=f"part:{part}", reset_camera=False, render=False)
            actor.prop.interpolation = "gouraud"
            actor.SetVisibility(self._view_state.is_part_visible(part))
            self._parts[part] = _PartView(indices, mesh, normals, actor)

    # -- listeners -------------------------------------------------------
    def _on_model_replaced(self, model: engine.Model) -> None:
        self._build(model)
        self.set_view(self._view)

    def _on_values_changed(self, _names: list) -> None:
        points = self._document.vertices()
        for view in self._parts.values():
            view.mesh.points[:] = points[view.vertex_indices]
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
