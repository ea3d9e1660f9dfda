"""Reference vertex normals: VTK's vtkPolyDataNormals over the whole mesh, as the viewport computed them."""

from __future__ import annotations

import numpy as np
import pyvista as pv
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals


def whole_mesh_normals(points, cells) -> np.ndarray:
    normals = vtkPolyDataNormals()
    normals.SetInputData(pv.PolyData(np.array(points), cells))
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.ComputeCellNormalsOff()
    normals.Update()
    return pv.wrap(normals.GetOutput()).point_data["Normals"].astype(float)
