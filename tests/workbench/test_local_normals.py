"""Live-preview shading: normals recomputed around moved vertices equal vtkPolyDataNormals over the whole mesh."""

from __future__ import annotations

import numpy as np
import pytest

from tests.workbench.normals import whole_mesh_normals
from workbench.viewport.local_normals import LocalNormals


@pytest.mark.parametrize("seed", range(4))
def test_moving_a_patch_gives_the_whole_mesh_normals(head, seed):
    rng = np.random.default_rng(seed)
    local = LocalNormals(head.faces, head.n_vertices)
    normals = whole_mesh_normals(head.vertices, head.faces)
    before = normals.copy()
    centre = head.vertices[rng.integers(head.n_vertices)]
    moved = np.flatnonzero(np.linalg.norm(head.vertices - centre, axis=1) < 12.0)     # a brush-sized patch
    points = head.vertices.copy()
    points[moved] += rng.normal(scale=0.3, size=3)                                     # what a dab does
    rewritten = local.update(points, normals, moved)
    assert np.allclose(normals, whole_mesh_normals(points, head.faces), atol=1e-6)
    untouched = np.setdiff1d(np.arange(head.n_vertices), rewritten)
    assert np.array_equal(normals[untouched], before[untouched])
    assert set(moved) <= set(rewritten)


def test_every_point_moved_is_the_whole_mesh_computation(head):
    """Equal to VTK's to 1e-6, except on the lash fringes: thin strips folded on themselves, where the face
    normals around a vertex nearly cancel and VTK's float32 result is good to about 1e-5."""
    normals = np.zeros((head.n_vertices, 3))
    LocalNormals(head.faces, head.n_vertices).update(head.vertices, normals, np.arange(head.n_vertices))
    lashes = np.isin(head.vertex_part, [k for k, p in enumerate(head.parts) if p.startswith("eyelashes")])
    vtk = whole_mesh_normals(head.vertices, head.faces)
    assert np.allclose(normals[~lashes], vtk[~lashes], atol=1e-6)
    assert np.allclose(normals[lashes], vtk[lashes], atol=1e-4)
