"""Picking in the viewport: which part, polygon and vertex of the drawn surface lie under a pixel.

The pick goes through a cell locator per part (:meth:`PartView.current_locator`),
rebuilt only when the drawn points move, so a pick at 94k vertices takes
0.5 ms instead of 30.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from vtkmodules.vtkCommonCore import reference as vtk_reference
from vtkmodules.vtkRenderingCore import vtkCellPicker

from .parts import PartView

PICK_TOLERANCE = 0.0005     # of the window's diagonal


class SurfacePick(NamedTuple):
    """Where a ray through a pixel meets the drawn surface."""

    point: np.ndarray   # (3,) mm, on the surface as drawn (the current pose)
    vertex: int         # model index of the vertex of the hit polygon nearest the point
    part: str
    normal: np.ndarray  # (3,) unit normal of the hit polygon, towards the camera side


def new_cell_picker() -> vtkCellPicker:
    """A picker that tests only the actors it is given (the parts), with the viewport's tolerance."""
    picker = vtkCellPicker()
    picker.SetTolerance(PICK_TOLERANCE)
    picker.PickFromListOn()
    return picker


def pick_surface(picker: vtkCellPicker, plotter, parts: dict[str, PartView], x: float, y: float):
    """The visible surface of ``parts`` under widget pixel (``x``, ``y``) (Qt coordinates, y down).

    Returns ``(pick, part view, cell id)``, or ``None`` where no visible part is hit.
    """
    renderer = plotter.renderer
    picker.InitializePickList()
    picker.RemoveAllLocators()
    visible = [part for part, view in parts.items() if view.actor.GetVisibility()]
    for part in visible:
        picker.AddPickList(parts[part].actor)
        picker.AddLocator(parts[part].current_locator())
    if not visible:
        return None
    ratio = plotter.devicePixelRatioF() if hasattr(plotter, "devicePixelRatioF") else 1.0
    height = renderer.GetRenderWindow().GetSize()[1]
    if not picker.Pick(x * ratio, height - 1 - y * ratio, 0.0, renderer):
        return None
    actor = picker.GetActor()
    part = next((name for name in visible if parts[name].actor is actor), None)
    if part is None:
        return None
    view = parts[part]
    point = np.array(picker.GetPickPosition())
    cell_id = picker.GetCellId()
    cell = view.mesh.get_cell(cell_id)
    ids = np.asarray(cell.point_ids)
    drawn = view.mesh.points[ids]
    nearest = ids[int(np.argmin(np.linalg.norm(drawn - point, axis=1)))]
    normal = np.array(picker.GetPickNormal())
    return SurfacePick(point, int(view.vertex_indices[nearest]), view.part or part, normal), view, cell_id


def cell_weights(view: PartView, cell_id: int, point) -> tuple[np.ndarray, np.ndarray]:
    """The hit polygon's model vertex indices and the interpolation weights of ``point`` (mm) on them (sum 1)."""
    cell = view.mesh.GetCell(cell_id)
    n = cell.GetNumberOfPoints()
    closest, sub_id, pcoords, dist2 = [0.0, 0.0, 0.0], vtk_reference(0), [0.0, 0.0, 0.0], vtk_reference(0.0)
    weights = [0.0] * n
    cell.EvaluatePosition(list(point), closest, sub_id, pcoords, dist2, weights)
    ids = np.array([cell.GetPointId(k) for k in range(n)], dtype=np.int64)
    weights = np.clip(np.asarray(weights, dtype=float), 0.0, None)
    total = weights.sum()
    weights = weights / total if total > 0 else np.full(n, 1.0 / n)
    return view.vertex_indices[ids], weights
