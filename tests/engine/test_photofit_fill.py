"""What no photograph sees takes the colour and shading of the skin it meets (issue 19, "Texture").

Before, the unseen skin (the back and top of the head in a front-only fit,
the far side of the ears) became one flat mean colour, so a shaded face met a
pale, even scalp. :func:`engine.photofit.texture.skin_fill` now continues the
seen skin over the head: where nothing sees it, each vertex's colour is the
average of its neighbours'. Measured on the synthetic truth of
``test_photofit.py`` fitted from its front photograph only.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import sparse

from engine.photofit.texture import (
    GRAZING,
    DepthBuffer,
    all_triangles,
    skin_fill,
    skin_triangles,
    vertex_normals,
)
from tests.engine.test_photofit import front_only, synthetic  # noqa: F401

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def filled(synthetic, front_only):  # noqa: F811
    _, photos, _, _ = synthetic
    head = front_only.head
    cameras = {"front": front_only.shape.cameras["front"]}
    photos = {"front": photos["front"]}
    vertices = head.vertices
    occluders = all_triangles(head)
    normals = vertex_normals(vertices, occluders)
    tri_v, _, _ = skin_triangles(head)
    skin = np.unique(tri_v)
    camera = cameras["front"]
    weight = np.zeros(len(vertices))
    weight[skin] = np.clip((normals[skin] @ camera.toward_camera() - GRAZING) / (1 - GRAZING), 0, None) ** 2
    weight[skin] *= DepthBuffer.of(vertices, occluders, camera, photos["front"].shape[:2]).visible(vertices[skin])
    mean = np.array([180.0, 140.0, 120.0])
    fill = skin_fill(head, vertices, photos, cameras, normals, occluders, mean)
    edges = np.concatenate([tri_v[:, [0, 1]], tri_v[:, [1, 2]], tri_v[:, [2, 0]]])
    n = len(vertices)
    adjacency = sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
    adjacency = ((adjacency + adjacency.T) > 0).astype(float).tocsr()
    return fill, weight, skin, adjacency, mean


def test_unseen_skin_is_the_average_of_its_neighbours(filled):
    fill, weight, skin, adjacency, _ = filled
    unseen = skin[weight[skin] == 0]
    assert len(unseen) > 500, "a front photograph leaves the back of the head unseen"
    degree = np.asarray(adjacency.sum(axis=1)).ravel()
    neighbours_mean = (adjacency @ fill) / np.maximum(degree, 1)[:, None]
    np.testing.assert_allclose(fill[unseen], neighbours_mean[unseen], atol=0.05)


def test_the_fill_meets_the_seen_skin_without_an_edge(filled):
    """At the border of what the photograph sees, the fill is the colour beside it, not a mean of the face."""
    fill, weight, skin, adjacency, _ = filled
    seen = np.zeros(len(fill), bool)
    seen[skin] = weight[skin] > 0.25
    unseen = np.zeros(len(fill), bool)
    unseen[skin] = weight[skin] == 0
    border = np.flatnonzero(unseen & (adjacency @ seen.astype(float) > 0))
    assert len(border) > 20
    rows = adjacency[border].multiply(seen[None, :].astype(float)).tocsr()
    beside = (rows @ fill) / np.asarray(rows.sum(axis=1))
    step = np.linalg.norm(fill[border] - beside, axis=1)
    seen_mean = fill[seen].mean(axis=0)
    flat_step = np.linalg.norm(seen_mean[None, :] - beside, axis=1)
    assert np.median(step) < 12.0, f"median colour step at the border {np.median(step):.1f} (0–255 levels)"
    assert np.median(step) < 0.5 * np.median(flat_step), "a flat mean colour would step more"


def test_the_fill_keeps_the_photograph_where_it_sees_the_skin(filled, synthetic):  # noqa: F811
    fill, weight, skin, _, _ = filled
    well_seen = skin[weight[skin] > 0.8]
    spread = np.ptp(fill[well_seen], axis=0)
    assert len(well_seen) > 200 and np.all(spread > 20), "seen skin keeps the photograph's variation"
