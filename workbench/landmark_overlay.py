"""Landmarks on demand (**View ▸ Landmarks**, Ctrl+Shift+L): the model's feature points on the face.

A model names some of its vertices as landmarks — the MPEG-4 feature points
of the paper's motion capture (§3.1: ``2.1`` the chin, ``8.1`` the middle of
the upper lip, …), which ``mocap apply``, the fitting and the exported
landmark tracks use. Shown, each is a small sphere on its vertex in the
current pose, lifted 1.5 mm off the skin along the vertex normal so the skin
does not cover it, with its id beside it. The ids of landmarks on the far side
of the head are hidden (VTK tests them against the depth buffer). Both follow
every pose change, edit and newly opened model.

>>> window.view_state.set_landmarks(True)           # doctest: +SKIP
>>> window.landmarks.shown_ids()[:3]                # doctest: +SKIP
['2.1', '2.2', '2.3']
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QObject

LANDMARK_COLOR = "#19c3e6"
LIFT_MM = 1.5            # off the surface along the normal, so the skin does not hide the sphere
POINT_SIZE = 11.0
LABEL_FONT_SIZE = 11


class LandmarkOverlay(QObject):
    """Draws the document's landmarks in the viewport while the view state says so."""

    def __init__(self, viewport, document, view_state, parent: QObject | None = None):
        super().__init__(parent)
        self._viewport, self._document, self._view_state = viewport, document, view_state
        self._cloud = None          # pv.PolyData: the points, and their ids as a string array
        self._actors: list = []
        self._ids: list[str] = []
        view_state.landmarks_changed.connect(self._refresh)
        # Bound methods, not lambdas, on the document: it may outlive the window.
        document.values_changed.connect(self._refresh)
        document.model_replaced.connect(self._rebuild)
        document.parameters_changed.connect(self._refresh)
        document.regions_changed.connect(self._refresh)

    def shown_ids(self) -> list[str]:
        """The ids drawn now (empty while landmarks are off)."""
        return list(self._ids) if self._visible() else []

    def shown_points(self) -> np.ndarray:
        """(k, 3) mm: where the spheres are drawn now, in :meth:`shown_ids` order."""
        return np.array(self._cloud.points) if self._visible() else np.zeros((0, 3))

    def _visible(self) -> bool:
        return bool(self._actors) and bool(self._actors[0].GetVisibility())

    def _positions(self) -> np.ndarray:
        model = self._document.model
        indices = [model.landmarks[i] for i in self._ids]
        points = self._document.vertices()[indices]
        normals = np.nan_to_num(self._viewport.displayed_normals(indices))
        return points + LIFT_MM * normals

    def _rebuild(self, *_args) -> None:
        plotter = self._viewport.plotter
        for actor in self._actors:
            plotter.remove_actor(actor, render=False)
        self._actors, self._cloud = [], None
        self._refresh()

    def _refresh(self, *_args) -> None:
        on = self._view_state.landmarks and bool(self._document.model.landmarks)
        if not on:
            if self._visible():
                for actor in self._actors:
                    actor.SetVisibility(False)
                self._viewport.plotter.update()
            return
        ids = list(self._document.model.landmarks)
        if self._cloud is None or ids != self._ids:
            self._build(ids)
        else:
            self._cloud.points[:] = self._positions()
            self._cloud.Modified()
        for actor in self._actors:
            actor.SetVisibility(True)
        self._viewport.plotter.update()

    def _build(self, ids: list[str]) -> None:
        import pyvista as pv

        plotter = self._viewport.plotter
        for actor in self._actors:
            plotter.remove_actor(actor, render=False)
        self._ids = ids
        self._cloud = pv.PolyData(self._positions())
        self._cloud.point_data["landmark_ids"] = np.array(ids)
        spheres = plotter.add_mesh(self._cloud, color=LANDMARK_COLOR, point_size=POINT_SIZE,
                                   render_points_as_spheres=True, lighting=False, name="landmarks", pickable=False,
                                   reset_camera=False, render=False)
        labels = plotter.add_point_labels(self._cloud, "landmark_ids", name="landmark-ids",
                                          font_size=LABEL_FONT_SIZE, text_color="white", shape_color="#20262c",
                                          shape_opacity=0.55, margin=2, show_points=False, always_visible=False,
                                          tolerance=0.01, reset_camera=False, render=False)
        self._actors = [spheres, labels]
