"""Dots drawn over the model in the viewport, with their labels: landmarks, markers, brush points.

:class:`PointOverlays` keeps one cloud per name; showing it again with the
same labels and colour moves the dots in place instead of rebuilding them.
Positions are mm.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pyvista as pv

POINT_SIZE = 11.0                # dots drawn by Viewport.show_points, px
LABEL_FONT_SIZE = 11


@dataclass
class PointSet:
    """Dots drawn over the model (and their labels): one cloud, its actors, what it was built with."""

    cloud: pv.PolyData
    actors: list
    labels: list[str] | None
    color: str


class PointOverlays:
    """The named dot clouds (and labels) a viewport's plotter draws over the model."""

    def __init__(self, plotter):
        self._plotter = plotter
        self._sets: dict[str, PointSet] = {}

    def show(self, name: str, points, color: str, labels=None) -> None:
        """Draw ``points`` ((k, 3) mm) as flat dots in ``color``, each with its text from ``labels`` beside it.

        Called again with the same name, labels and colour it moves the dots
        (and labels) in place. Labels of points behind the model are hidden.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        labels = None if labels is None else [str(label) for label in labels]
        entry = self._sets.get(name)
        if entry is None or entry.labels != labels or entry.color != color or entry.cloud.n_points != len(points):
            self.remove(name)
            cloud = pv.PolyData(points.copy())
            actors = [self._plotter.add_mesh(cloud, color=color, point_size=POINT_SIZE, render_points_as_spheres=True,
                                             lighting=False, name=f"points:{name}", pickable=False,
                                             reset_camera=False, render=False)]
            if labels:
                cloud.point_data["labels"] = np.array(labels)
                actors.append(self._plotter.add_point_labels(
                    cloud, "labels", name=f"labels:{name}", font_size=LABEL_FONT_SIZE, text_color="white",
                    shape_color="#20262c", shape_opacity=0.55, margin=2, show_points=False,
                    always_visible=False, tolerance=0.01, reset_camera=False, render=False))
            entry = self._sets[name] = PointSet(cloud, actors, labels, color)
        else:
            entry.cloud.points[:] = points
            entry.cloud.Modified()
        for actor in entry.actors:
            actor.SetVisibility(True)

    def hide(self, name: str) -> bool:
        """Stop drawing the dots (and labels) shown under ``name``; whether any were shown."""
        entry = self._sets.get(name)
        if entry is not None and entry.actors[0].GetVisibility():
            for actor in entry.actors:
                actor.SetVisibility(False)
            return True
        return False

    def shown(self, name: str) -> np.ndarray:
        """(k, 3) mm: the dots drawn now under ``name`` (none while hidden)."""
        entry = self._sets.get(name)
        if entry is None or not entry.actors[0].GetVisibility():
            return np.zeros((0, 3))
        return np.array(entry.cloud.points)

    def remove(self, name: str) -> None:
        """Take the dots (and labels) drawn under ``name`` out of the scene."""
        entry = self._sets.pop(name, None)
        for actor in entry.actors if entry is not None else ():
            self._plotter.remove_actor(actor, render=False)

    def clear(self) -> None:
        """Forget every cloud (the plotter is going away)."""
        self._sets.clear()
