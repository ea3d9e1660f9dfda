"""The selected parameter's axis and pivot drawn in the viewport: a sphere at the pivot, an arrow along the axis.

For a rotation the arrow is an axle through the pivot, pointing along the
axis (the right-hand rule gives the positive turn); for a translation it
starts at the weighted centre of the influence region and points along the
direction; a displacement field (blendshape) has only the sphere. The gizmo
moves with the parameter's parents in the current pose (a jaw's axis turns
with the head), follows edits, undo and redo, and is hidden when nothing is
selected.

The actors live in ``viewport.plotter``'s renderer (so they are shaded and
hidden by the face like anything else) and, as translucent twins sharing
their meshes, in an overlay layer drawn over the face, so a pivot inside the
head still shows through. Like the viewport, this module talks to pyvista
(imported when the gizmo is built, not with the module); no other
tree-editor module does.
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QObject

import engine

# Colours the heat map (blue → cyan → green → yellow → red) never uses.
PIVOT_COLOR = "#ffffff"
ROTATION_COLOR = "#ff2fd0"
TRANSLATION_COLOR = "#a066ff"
GHOST_OPACITY = 0.7
ARROW_FRACTION = 0.32   # arrow length, as a fraction of the model's bounding radius
SPHERE_FRACTION = 0.035


class ParameterGizmo(QObject):
    """Draws ``view_state.selected_parameter`` of ``document`` in ``viewport``."""

    def __init__(self, viewport, document, view_state, parent: QObject | None = None):
        import pyvista as pv
        from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer

        super().__init__(parent)
        self._viewport = viewport
        self._document = document
        self._view_state = view_state
        plotter = viewport.plotter
        self.pivot_mesh = pv.Sphere(radius=1.0, theta_resolution=24, phi_resolution=16)
        self.arrow_mesh = pv.Arrow()
        self.pivot_actor = plotter.add_mesh(self.pivot_mesh, color=PIVOT_COLOR, smooth_shading=True,
                                            name="tree-editor:gizmo-pivot", pickable=False,
                                            render=False, reset_camera=False)
        self.arrow_actor = plotter.add_mesh(self.arrow_mesh, color=ROTATION_COLOR, smooth_shading=True,
                                            name="tree-editor:gizmo-axis", pickable=False,
                                            render=False, reset_camera=False)
        self._overlay = vtkRenderer()
        self._overlay.SetLayer(1)
        self._overlay.InteractiveOff()
        self._overlay.SetActiveCamera(plotter.renderer.GetActiveCamera())
        self._ghosts = []
        for actor in (self.pivot_actor, self.arrow_actor):
            ghost = vtkActor()
            ghost.SetMapper(actor.GetMapper())
            ghost.GetProperty().DeepCopy(actor.GetProperty())
            ghost.GetProperty().SetOpacity(GHOST_OPACITY)
            ghost.PickableOff()
            self._overlay.AddActor(ghost)
            self._ghosts.append(ghost)
        window = plotter.render_window
        if window is not None:
            window.SetNumberOfLayers(max(2, window.GetNumberOfLayers()))
            window.AddRenderer(self._overlay)

        view_state.selected_parameter_changed.connect(self.refresh)
        document.parameters_changed.connect(self.refresh)
        document.regions_changed.connect(self.refresh)
        document.values_changed.connect(self.refresh)
        document.model_replaced.connect(self.refresh)
        self.refresh()

    # -- state (for tests and the docs) -----------------------------------------
    @property
    def visible(self) -> bool:
        return bool(self.pivot_actor.GetVisibility())

    @property
    def arrow_visible(self) -> bool:
        return bool(self.arrow_actor.GetVisibility())

    def pivot_position(self) -> np.ndarray:
        """Centre of the drawn pivot sphere (mm)."""
        return np.asarray(self.pivot_mesh.center)

    def arrow_direction(self) -> np.ndarray:
        """Unit vector from the arrow's tail to its tip."""
        points = np.asarray(self.arrow_mesh.points, dtype=float)
        along = points @ self._direction
        span = along.max() - along.min()
        tip = points[along >= along.max() - 1e-4 * span].mean(axis=0)      # the cone's apex
        tail = points[along <= along.min() + 1e-4 * span].mean(axis=0)     # the middle of the shaft's end
        d = tip - tail
        return d / np.linalg.norm(d)

    # -- drawing ---------------------------------------------------------------
    def refresh(self, *_args) -> None:
        """Redraw for the current selection, model and pose."""
        if getattr(self._viewport.plotter, "_closed", False):
            return                   # the window is closing: nothing to draw into
        model = self._document.model
        name = self._view_state.selected_parameter
        if name is None or name not in model.parameters or model.n_vertices == 0:
            self._show(False, False)
            return
        import pyvista as pv

        p = model.parameters[name]
        carry = _parents_transform(model.parameters, name, self._document.values)
        lo, hi = model.vertices.min(axis=0), model.vertices.max(axis=0)
        size = max(float(np.linalg.norm(hi - lo)) / 2, 1e-6)
        length = ARROW_FRACTION * size
        if p.kind == "rotation":
            centre = _point(p.pivot, carry)
            direction = _vector(p.axis, carry)
            start, scale, color = centre - length * direction, 2 * length, ROTATION_COLOR
        else:
            centre = self._region_centre(name, (lo + hi) / 2)
            direction = _vector(p.direction, carry)
            start, scale, color = centre, length, TRANSLATION_COLOR
        self.pivot_mesh.copy_from(pv.Sphere(radius=SPHERE_FRACTION * size, center=centre,
                                            theta_resolution=24, phi_resolution=16))
        norm = float(np.linalg.norm(direction))
        has_arrow = not p.field and norm > 0
        if has_arrow:
            self._direction = direction / norm
            self.arrow_mesh.copy_from(pv.Arrow(start=start, direction=self._direction, scale=scale,
                                               tip_length=0.18, tip_radius=0.06, shaft_radius=0.022,
                                               tip_resolution=24, shaft_resolution=16))
            for actor in (self.arrow_actor, self._ghosts[1]):
                actor.GetProperty().SetColor(pv.Color(color).float_rgb)
        self._show(True, has_arrow)

    def _region_centre(self, name: str, fallback: np.ndarray) -> np.ndarray:
        region = self._document.model.regions[name]
        if len(region.indices) == 0 or not np.any(region.weights > 0):
            return fallback
        points = self._document.vertices()[region.indices]
        return np.average(points, axis=0, weights=region.weights)

    def _show(self, pivot: bool, arrow: bool) -> None:
        self.pivot_actor.SetVisibility(pivot)
        self._ghosts[0].SetVisibility(pivot)
        self.arrow_actor.SetVisibility(arrow)
        self._ghosts[1].SetVisibility(arrow)
        self._viewport.plotter.update()

    _direction = np.array([1.0, 0.0, 0.0])


def _parents_transform(tree: engine.ParameterTree, name: str, values: dict) -> np.ndarray:
    """``T'`` of ``name``'s parent at ``values`` (row convention, 4×4): how its frame moves now."""
    carry = np.eye(4)
    for ancestor in reversed(tree.ancestors(name)):          # root first: T' = T_child · T'_parent
        carry = tree[ancestor].transform(values.get(ancestor, tree[ancestor].default)) @ carry
    return carry


def _point(p, carry: np.ndarray) -> np.ndarray:
    return (np.append(np.asarray(p, dtype=float), 1.0) @ carry)[:3]


def _vector(v, carry: np.ndarray) -> np.ndarray:
    return (np.append(np.asarray(v, dtype=float), 0.0) @ carry)[:3]
