"""The captured markers drawn over the face in the viewport: small spheres in the model's coordinates.

Marker coordinates are not model coordinates. Every marker the model has a
place for — its landmark of the same MPEG-4 id, or a head-fixed point the
engine places on the skin (:func:`engine.mocap.synthetic.marker_vertices`,
the correspondence ``mocap apply`` uses) — pairs the session's median
marker position with that vertex at rest; a similarity transform (scale,
rotation, translation, the engine's Umeyama fit) takes the markers there.

The actors are ours (one point cloud rendered as spheres, per-point colours,
and the markers' labels beside them: the feature point a marker was given);
pyvista is imported here only when the first markers are shown.
:meth:`MarkerOverlay.marker_at` finds the marker drawn under a pixel, for
assigning feature points by clicking on the view.

The markers belong to their recording: while another animation has the
window's player (a library-editor or gallery preview, speech) the overlay is
*inactive* — the face moves by that animation's clock, and markers following
the shared playhead would float beside it — and draws nothing; it keeps the
markers it was last given and draws them again when it is active once more.
"""

from __future__ import annotations

import numpy as np

from engine.errors import UserError

MARKER_COLOR = (255, 214, 0)        # lips and jaw: the markers the PCA analyses
REFERENCE_COLOR = (90, 150, 255)    # head-fixed reference markers
OTHER_COLOR = (80, 220, 120)
HIGHLIGHT_COLOR = (255, 40, 200)    # the marker shown in the coordinate plot
POINT_SIZE = 13.0
LABEL_FONT_SIZE = 12
PICK_RADIUS_PX = 12.0               # a click this close to a marker's centre picks it


def marker_to_model_transform(model, markers, positions) -> tuple[float, np.ndarray, np.ndarray, list[str]]:
    """``(scale, rotation, translation, paired markers)`` with model = scale · R @ marker + t.

    ``positions`` (F, M, 3) mm, NaN where missing; the median over frames of
    each marker pairs with its vertex on the model at rest. With fewer than
    three pairs the markers are only moved so their centre sits on the
    face's landmarks' centre.
    """
    from engine.mocap.marker_alignment import similarity_fit
    from engine.mocap.synthetic import marker_vertices

    places = {}
    for m in markers:
        try:
            places.update(marker_vertices(model, [m]))
        except UserError:
            continue
    median = _median_positions(positions)
    pairs = [m for m in markers if m in places and median is not None and np.isfinite(median[markers.index(m)]).all()]
    if len(pairs) >= 3:
        source = np.array([median[markers.index(m)] for m in pairs])
        target = model.vertices[[places[m] for m in pairs]]
        scale, rotation, translation = similarity_fit(source, target)
        return scale, rotation, translation, pairs
    centre = (model.vertices[list(model.landmarks.values())].mean(axis=0) if model.landmarks
              else model.vertices.mean(axis=0))
    seen = median[np.isfinite(median).all(axis=1)] if median is not None else np.zeros((0, 3))
    offset = centre - (seen.mean(axis=0) if len(seen) else 0.0)
    return 1.0, np.eye(3), np.nan_to_num(offset), pairs


def _median_positions(positions) -> np.ndarray | None:
    """(M, 3): each marker's median position over the frames; NaN for a marker never seen (no warning)."""
    positions = np.where(np.isfinite(positions), positions, np.nan)
    if not len(positions):
        return None
    seen = np.isfinite(positions).all(axis=2).any(axis=0)
    median = np.full(positions.shape[1:], np.nan)
    if seen.any():
        median[seen] = np.nanmedian(positions[:, seen], axis=0)
    return median


def default_colors(markers, reference=()) -> np.ndarray:
    """(M, 3) uint8: yellow lips and jaw (2.x, 8.x), blue reference markers, green others."""
    out = np.empty((len(markers), 3), dtype=np.uint8)
    for i, m in enumerate(markers):
        if m in reference:
            out[i] = REFERENCE_COLOR
        elif m.startswith(("2.", "8.")):
            out[i] = MARKER_COLOR
        else:
            out[i] = OTHER_COLOR
    return out


def error_colors(errors_mm, good_mm: float = 0.5, bad_mm: float = 2.0) -> np.ndarray:
    """(M, 3) uint8 from green (≤ ``good_mm``) through yellow to red (≥ ``bad_mm``); grey for NaN."""
    e = np.asarray(errors_mm, dtype=float)
    t = np.clip((e - good_mm) / (bad_mm - good_mm), 0.0, 1.0)
    red = np.where(t < 0.5, 2 * t, 1.0)
    green = np.where(t < 0.5, 1.0, 2 * (1 - t))
    out = np.stack([red, green, np.zeros_like(t)], axis=1) * 230 + 25
    out[~np.isfinite(e)] = 150
    return out.astype(np.uint8)


class MarkerOverlay:
    """Spheres at marker positions in the viewport's plotter, moved and recoloured in place.

    ``shown_points`` and ``shown_colors`` are the markers of the frame now (model
    coordinates, missing ones left out); they are on screen while the overlay is
    :attr:`active` and not hidden.
    """

    def __init__(self, viewport):
        self._viewport = viewport
        self._mesh = None
        self._actor = None
        self._label_cloud = None
        self._label_actor = None
        self._label_texts: list[str] = []
        self.active = True          # False while another animation has the player: draw nothing
        self.transform = (1.0, np.eye(3), np.zeros(3))
        self.shown_points = np.zeros((0, 3))      # model coordinates of the markers of the frame now
        self.shown_colors = np.zeros((0, 3), dtype=np.uint8)
        self.shown_names: list[str] = []          # the marker of each shown point
        self.shown_labels: list[str] = []         # the text beside each shown point ("" for none)

    def set_transform(self, scale: float, rotation, translation) -> None:
        self.transform = (float(scale), np.asarray(rotation, float), np.asarray(translation, float))

    def to_model(self, points) -> np.ndarray:
        scale, rotation, translation = self.transform
        return scale * np.asarray(points, dtype=float) @ rotation.T + translation

    def show(self, points, colors, names=None, labels=None) -> None:
        """Markers at ``points`` (M, 3, marker space; NaN rows are hidden) with ``colors`` (M, 3) uint8.

        ``names``: the marker of each row (for :meth:`marker_at`); ``labels``:
        the text drawn beside each ("" for none). Drawn now if the overlay is
        active, else kept for when it is.
        """
        points = self.to_model(points)
        present = np.isfinite(points).all(axis=1)
        self.shown_points = points[present]
        self.shown_colors = np.asarray(colors, dtype=np.uint8)[present]
        rows = np.flatnonzero(present)
        self.shown_names = [str(names[i]) for i in rows] if names is not None else []
        self.shown_labels = [str(labels[i] or "") for i in rows] if labels is not None else [""] * len(rows)
        if self.active:
            self._draw()

    def hide(self) -> None:
        """Forget the markers (no session): nothing is drawn until :meth:`show` again."""
        self.shown_points = np.zeros((0, 3))
        self.shown_colors = np.zeros((0, 3), dtype=np.uint8)
        self.shown_names, self.shown_labels = [], []
        self._take_off_screen()

    def marker_at(self, x: float, y: float, to_widget) -> str | None:
        """The marker drawn nearest widget pixel (``x``, ``y``), within :data:`PICK_RADIUS_PX`, or ``None``.

        ``to_widget(point)`` is where a model point is drawn (``Viewport.world_to_widget``). Only markers
        on screen count (none while hidden or inactive).
        """
        if not (self.visible and self.shown_names):
            return None
        pixels = np.array([to_widget(p) for p in self.shown_points], dtype=float).reshape(-1, 2)
        distance = np.hypot(pixels[:, 0] - x, pixels[:, 1] - y)
        nearest = int(np.argmin(distance))
        return self.shown_names[nearest] if distance[nearest] <= PICK_RADIUS_PX else None

    @property
    def labels_visible(self) -> list[str]:
        """The labels on screen now."""
        if self._label_actor is None or not self._label_actor.GetVisibility():
            return []
        return list(self._label_texts)

    def set_active(self, active: bool) -> None:
        """Draw the markers (``True``) or keep them off screen while another animation plays (``False``)."""
        active = bool(active)
        if active == self.active:
            return
        self.active = active
        if active and len(self.shown_points):
            self._draw()
        else:
            self._take_off_screen()

    @property
    def visible(self) -> bool:
        """Whether markers are on screen now."""
        return self._actor is not None and bool(self._actor.GetVisibility())

    def _draw(self) -> None:
        import pyvista as pv

        cloud = pv.PolyData(self.shown_points if len(self.shown_points) else np.zeros((0, 3)))
        cloud.point_data["marker_colors"] = self.shown_colors if len(self.shown_colors) else np.zeros((0, 3), np.uint8)
        plotter = self._viewport.plotter
        if self._mesh is None:
            self._mesh = cloud
            self._actor = plotter.add_mesh(self._mesh, scalars="marker_colors", rgb=True, point_size=POINT_SIZE,
                                           render_points_as_spheres=True, render=False, reset_camera=False,
                                           name="mocap-markers", pickable=False)
        else:
            self._mesh.copy_from(cloud)
        self._actor.SetVisibility(bool(len(self.shown_points)))
        self._draw_labels(plotter)
        self._viewport.render_now()

    def _draw_labels(self, plotter) -> None:
        """The labels beside their markers: moved in place while the texts stay, built again when they change."""
        import pyvista as pv

        rows = [i for i, text in enumerate(self.shown_labels) if text]
        texts = [self.shown_labels[i] for i in rows]
        if not rows:
            if self._label_actor is not None:
                self._label_actor.SetVisibility(False)
            return
        points = self.shown_points[rows]
        if self._label_actor is None or texts != self._label_texts:
            if self._label_actor is not None:
                plotter.remove_actor(self._label_actor, render=False)
            self._label_cloud = pv.PolyData(points.copy())
            self._label_cloud.point_data["labels"] = np.array(texts)
            self._label_actor = plotter.add_point_labels(
                self._label_cloud, "labels", name="mocap-marker-labels", font_size=LABEL_FONT_SIZE,
                text_color="white", shape_color="#20262c", shape_opacity=0.6, margin=2, show_points=False,
                always_visible=True, reset_camera=False, render=False)
            self._label_texts = texts
        else:
            self._label_cloud.points[:] = points
            self._label_cloud.Modified()
        self._label_actor.SetVisibility(True)

    def _take_off_screen(self) -> None:
        labels_on, markers_on = bool(self.labels_visible), self.visible
        if labels_on:
            self._label_actor.SetVisibility(False)
        if markers_on:
            self._actor.SetVisibility(False)
        if labels_on or markers_on:
            self._viewport.render_now()
