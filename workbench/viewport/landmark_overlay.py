"""Landmarks on demand (**View ▸ Landmarks**, Ctrl+Shift+L): the model's feature points on the face.

A model names some of its vertices as landmarks — the MPEG-4 feature points
of the paper's motion capture (§3.1: ``2.1`` the chin, ``8.1`` the middle of
the upper lip, …), which ``mocap apply``, the fitting and the exported
landmark tracks use. Shown, each is a dot on its vertex in the current pose,
lifted 1.5 mm off the skin along the vertex normal so the skin does not cover
it, with its id beside it (:meth:`Viewport.show_points`; ids on the far side
of the head are hidden). They follow every pose change, edit and newly
opened model.

>>> window.view_state.set_landmarks(True)           # doctest: +SKIP
>>> window.landmarks.shown_ids()[:3]                # doctest: +SKIP
['2.1', '2.2', '2.3']
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QObject

LANDMARK_COLOR = "#19c3e6"
LIFT_MM = 1.5            # off the surface along the normal, so the skin does not hide the dot
POINTS_NAME = "landmarks"


class LandmarkOverlay(QObject):
    """Keeps the viewport's landmark dots in step with the document while the view state says so."""

    def __init__(self, viewport, document, view_state, parent: QObject | None = None):
        super().__init__(parent)
        self._viewport, self._document, self._view_state = viewport, document, view_state
        self._ids: list[str] = []
        view_state.landmarks_changed.connect(self._refresh)
        # Bound methods, not lambdas, on the document: it may outlive the window.
        document.values_changed.connect(self._refresh)
        document.model_replaced.connect(self._refresh)
        document.parameters_changed.connect(self._refresh)
        document.regions_changed.connect(self._refresh)

    def shown_ids(self) -> list[str]:
        """The ids drawn now (empty while landmarks are off or the model has none)."""
        return list(self._ids) if len(self.shown_points()) else []

    def shown_points(self) -> np.ndarray:
        """(k, 3) mm: where the dots are drawn now, in :meth:`shown_ids` order."""
        return self._viewport.shown_points(POINTS_NAME)

    def _refresh(self, *_args) -> None:
        model = self._document.model
        if not (self._view_state.landmarks and model.landmarks):
            self._viewport.hide_points(POINTS_NAME)
            return
        self._ids = list(model.landmarks)
        indices = [model.landmarks[i] for i in self._ids]
        lift = LIFT_MM * np.nan_to_num(self._viewport.displayed_normals(indices))
        self._viewport.show_points(POINTS_NAME, self._document.vertices()[indices] + lift, LANDMARK_COLOR,
                                   labels=self._ids)
