"""What paint mode draws over the model: the brush cursor, and the heat map's legend.

The cursor is a ring of the brush's radius lying on the surface at the pick
point: two rings (the second one at the mirror image when X-mirror is on)
and a line for the gradient tool, each a VTK actor drawn over the model
without lighting. They are built once; moving them only changes a 4 × 4
matrix, so following the mouse costs no geometry. The legend
(:class:`WeightLegend`) is a colour bar of the weight ramp, 0 … 1, with the
painted parameter's name. One of the workbench's few drawing modules:
pyvista and VTK are imported when the cursor and the legend are built, not with the module.

>>> cursor = BrushCursor(viewport.plotter)                         # doctest: +SKIP
>>> cursor.place(point=(0, 150, 120), normal=(0, 0, 1), radius=15)  # doctest: +SKIP
>>> cursor.hide()                                                  # doctest: +SKIP
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    import pyvista as pv
    from vtkmodules.vtkCommonMath import vtkMatrix4x4

RING_COLOR = "#ffffff"
MIRROR_COLOR = "#ffd34d"
GRADIENT_COLOR = "#ffd34d"
RING_SEGMENTS = 72
LINE_DEPTH_OFFSET = 20000.0   # depth units the lines are pulled towards the camera
LIFT_MM = 0.3       # the ring floats this far above the surface, so the mesh does not hide it
LEGEND_LABELS = 3                 # 0.0, 0.5, 1.0
LEGEND_PLACE = (0.79, 0.30)       # the legend's lower left corner, as fractions of the viewport
LEGEND_SIZE = (0.19, 0.42)        # its width and height (the title's room), as fractions of the viewport
LEGEND_MOST_WIDTH = 170           # px


def _unit_ring() -> pv.PolyData:
    import pyvista as pv

    angles = np.linspace(0.0, 2.0 * np.pi, RING_SEGMENTS, endpoint=False)
    points = np.column_stack([np.cos(angles), np.sin(angles), np.zeros_like(angles)])
    lines = np.concatenate([[RING_SEGMENTS + 1], np.arange(RING_SEGMENTS), [0]])
    return pv.PolyData(points, lines=lines)


def ring_matrix(point, normal, radius: float) -> np.ndarray:
    """4 × 4 matrix taking the unit ring in the XY plane to a ring of ``radius`` at ``point`` facing ``normal``.

    >>> m = ring_matrix((1, 2, 3), (0, 0, 1), 5.0)
    >>> float(np.linalg.norm(m[:3, 0])), m[:3, 3].round(6).tolist()
    (5.0, [1.0, 2.0, 3.3])
    """
    n = np.asarray(normal, dtype=float)
    length = np.linalg.norm(n)
    n = n / length if length > 0 else np.array([0.0, 0.0, 1.0])
    helper = np.array([0.0, 1.0, 0.0]) if abs(n[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(helper, n)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = u * radius, v * radius, n
    m[:3, 3] = np.asarray(point, dtype=float) + LIFT_MM * n
    return m


def _vtk_matrix(m: np.ndarray) -> vtkMatrix4x4:
    from vtkmodules.vtkCommonMath import vtkMatrix4x4

    out = vtkMatrix4x4()
    for i in range(4):
        for j in range(4):
            out.SetElement(i, j, float(m[i, j]))
    return out


class BrushCursor:
    """The rings and gradient line on a pyvista plotter; hidden until :meth:`place`."""

    def __init__(self, plotter: Any):
        import pyvista as pv

        self._plotter = plotter
        ring = _unit_ring()
        self.ring = self._add(ring, RING_COLOR, "paint:cursor")
        self.mirror_ring = self._add(ring.copy(), MIRROR_COLOR, "paint:cursor-mirror")
        self._line = pv.PolyData(np.zeros((2, 3)), lines=np.array([2, 0, 1]))
        self.line = self._add(self._line, GRADIENT_COLOR, "paint:gradient")
        self.hide()

    def _add(self, mesh: pv.PolyData, color: str, name: str):
        actor = self._plotter.add_mesh(mesh, color=color, line_width=2.0, lighting=False, name=name,
                                       pickable=False, reset_camera=False, render=False)
        actor.SetPickable(False)
        # Drawn in front of the surface it lies on, even where a concave patch (a fold) rises above the ring.
        mapper = actor.GetMapper()
        mapper.SetResolveCoincidentTopologyToPolygonOffset()
        mapper.SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -LINE_DEPTH_OFFSET)
        return actor

    @property
    def visible(self) -> bool:
        return bool(self.ring.GetVisibility())

    def place(self, point, normal, radius: float, mirror_point=None, mirror_normal=None) -> None:
        """Show the ring at ``point`` (mm) facing ``normal``; a second ring at ``mirror_point`` if given."""
        self.ring.SetUserMatrix(_vtk_matrix(ring_matrix(point, normal, radius)))
        self.ring.SetVisibility(True)
        if mirror_point is not None:
            self.mirror_ring.SetUserMatrix(_vtk_matrix(ring_matrix(mirror_point, mirror_normal, radius)))
        self.mirror_ring.SetVisibility(mirror_point is not None)

    def show_line(self, start, end) -> None:
        """The gradient tool's line from ``start`` to ``end`` (mm)."""
        points = self._line.GetPoints()
        points.SetPoint(0, *map(float, start))
        points.SetPoint(1, *map(float, end))
        points.Modified()
        self._line.Modified()
        self.line.SetVisibility(True)

    def hide_line(self) -> None:
        self.line.SetVisibility(False)

    def hide(self) -> None:
        for actor in (self.ring, self.mirror_ring, self.line):
            actor.SetVisibility(False)

    def ring_center(self) -> np.ndarray:
        """Where the main ring is drawn (mm) — for tests."""
        m = self.ring.GetUserMatrix()
        return np.array([m.GetElement(i, 3) for i in range(3)])

    def ring_radius(self) -> float:
        m = self.ring.GetUserMatrix()
        return float(np.linalg.norm([m.GetElement(i, 0) for i in range(3)]))


class WeightLegend:
    """The heat map's colour bar at the viewport's right edge while painting: weight 0 … 1, titled with the
    parameter painted. A VTK scalar bar over the weight ramp; hidden until :meth:`show`."""

    def __init__(self, plotter: Any):
        from vtkmodules.vtkCommonCore import vtkLookupTable
        from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor

        from engine.painting import WEIGHT_RAMP

        table = vtkLookupTable()
        table.SetNumberOfTableValues(len(WEIGHT_RAMP))
        table.SetTableRange(0.0, 1.0)
        table.Build()
        for k, (r, g, b) in enumerate(WEIGHT_RAMP):
            table.SetTableValue(k, r / 255.0, g / 255.0, b / 255.0, 1.0)
        bar = self.actor = vtkScalarBarActor()
        bar.SetLookupTable(table)
        bar.SetOrientationToVertical()
        bar.SetNumberOfLabels(LEGEND_LABELS)
        bar.SetLabelFormat("%.1f")
        bar.SetUnconstrainedFontSize(True)
        bar.SetTextPositionToPrecedeScalarBar()      # labels left of the bar, the title above it
        coordinate = bar.GetPositionCoordinate()
        coordinate.SetCoordinateSystemToNormalizedViewport()
        coordinate.SetValue(*LEGEND_PLACE)
        bar.SetWidth(LEGEND_SIZE[0])
        bar.SetHeight(LEGEND_SIZE[1])
        bar.SetBarRatio(0.18)
        bar.SetVerticalTitleSeparation(8)
        bar.SetMaximumWidthInPixels(LEGEND_MOST_WIDTH)
        for prop, size, bold in ((bar.GetTitleTextProperty(), 14, True), (bar.GetLabelTextProperty(), 12, False)):
            prop.SetColor(1.0, 1.0, 1.0)
            prop.SetFontSize(size)
            prop.SetBold(bold)
            prop.SetItalic(False)
            prop.SetShadow(True)
        bar.SetPickable(False)
        bar.SetVisibility(False)
        self._plotter = plotter
        plotter.add_actor(bar, reset_camera=False, name="paint:legend", pickable=False, render=False)

    @property
    def visible(self) -> bool:
        return bool(self.actor.GetVisibility())

    @property
    def title(self) -> str:
        return self.actor.GetTitle() or ""

    def show(self, parameter: str) -> None:
        """The legend of ``parameter``'s weights."""
        self.actor.SetTitle(parameter)
        self.actor.SetVisibility(True)

    def hide(self) -> None:
        self.actor.SetVisibility(False)
