"""A real studio portrait fitted front-only: its face is in the texture (issue 19, "Texture").

``skimage.data.astronaut()`` (public domain, NASA) with the landmarks of ``docs/images/photofit``. Her
skin is nearly as pale as the backdrop and meets it along the jaw and the neck, so a colour test alone
takes most of the face for backdrop: the texture then showed the fill's brown with a few pale patches
where the photograph got through. The face's texels must be the photograph's: each skin vertex of the
face (between the brows and the chin, the eye corners and the mouth corners) is sampled in the atlas at
its texture coordinate and in the photograph where the fitted camera projects it: 3.5 RGB apart on
average now, 30 before.

Two causes, each tested here: the fitted head's outline (and its z-buffer and normals) were drawn from
half of every quad (``all_triangles`` fanned from a repeated corner), and the backdrop test knew nothing
of where the head is (:func:`engine.photofit.backdrop.subject_weight`'s ``inside``).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image
from skimage import data

from engine.formats.model_files import load_model
from engine.photofit import fit_photo_files
from engine.photofit.raster import sample_bilinear
from tests.engine.test_photofit_outline import ASTRONAUT_POINTS

pytestmark = pytest.mark.slow

TOLERANCE_RGB = 10.0                # mean distance, atlas ↔ photograph, over the face's vertices
FACING = 0.7                        # n · v above which a vertex faces the camera squarely (not a fold's inside)


@pytest.fixture(scope="module")
def astronaut(tmp_path_factory):
    photo = data.astronaut()
    path = tmp_path_factory.mktemp("portrait") / "astronaut.png"
    Image.fromarray(photo).save(path)
    return photo, fit_photo_files(path, None, ASTRONAUT_POINTS)


def face_vertices(head, camera, points) -> np.ndarray:
    """Skin vertices whose projection lies inside the face: between the brows and the chin, the outer eye
    corners and the mouth corners (the landmarks placed on the photograph)."""
    skin = np.flatnonzero(head.vertex_part == head.parts.index("skin"))
    from engine.photofit.texture import all_triangles, vertex_normals

    normals = vertex_normals(head.vertices, all_triangles(head))[skin]
    facing = normals @ np.asarray(camera.toward_camera()) > FACING
    xy = camera.project(head.vertices[skin])
    left = min(points["3.12"][0], points["8.3"][0])
    right = max(points["3.7"][0], points["8.4"][0])
    top, bottom = min(points["3.12"][1], points["3.7"][1]) - 10, points["2.1"][1] - 5
    inside = (xy[:, 0] > left) & (xy[:, 0] < right) & (xy[:, 1] > top) & (xy[:, 1] < bottom) & facing
    # the front of the face only: vertices nearer the camera than the eyes' corners
    depth = camera.depth(head.vertices[skin])
    return skin[inside & (depth >= np.median(depth[inside]) - 5.0)]


def test_the_face_of_a_real_portrait_is_the_photographs(astronaut):
    photo, fit = astronaut
    head, camera = fit.head, fit.shape.cameras["front"]
    points = json.loads(ASTRONAUT_POINTS.read_text())["front"]
    chosen = face_vertices(head, camera, points)
    # the texture is read through the head in the photograph's expression; the shadows evened out, the open
    # mouth and the mouth's inside are not the photograph's on purpose (test_photofit_neutral.py)
    from engine.photofit.face_points import point_vertices
    from engine.photofit.texture_cleanup import mouth_bag, shadow_vertices

    chosen = chosen[(shadow_vertices(head, head.vertices, point_vertices(head))[chosen] < 0.5)
                    & ~mouth_bag(load_model())[chosen]]        # the bag of the default head's closed lips
    assert len(chosen) > 100
    atlas = head.texture.images[0].pixels
    uv = _vertex_uv(head)[chosen]
    texels = sample_bilinear(atlas, np.stack([uv[:, 0] * atlas.shape[1], (1 - uv[:, 1]) * atlas.shape[0]], axis=1))
    seen = sample_bilinear(photo, camera.project(head.deform(fit.shape.expression)[chosen]))
    distance = np.linalg.norm(texels.astype(float) - seen.astype(float), axis=1)
    print(f"face vertices {len(chosen)}: atlas ↔ photograph {distance.mean():.1f} RGB on average, "
          f"{np.percentile(distance, 90):.1f} at the 90th percentile")
    assert distance.mean() < TOLERANCE_RGB


def _vertex_uv(head) -> np.ndarray:
    from engine.model.cells import cell_sizes, cell_starts

    sizes = cell_sizes(head.faces)
    starts = cell_starts(sizes)
    uv = np.zeros((len(head.vertices), 2))
    corner = 0
    for n, s in zip(sizes, starts, strict=True):
        uv[head.faces[s + 1:s + 1 + n]] = head.texture.corner_uv[corner:corner + n]
        corner += n
    return uv


def test_every_polygon_is_drawn_whole(head):
    """Each polygon of n corners is n − 2 triangles of its own corners, none with a corner twice."""
    from engine.model.cells import cell_sizes, cell_starts
    from engine.photofit.texture import all_triangles

    triangles = all_triangles(head)
    sizes = cell_sizes(head.faces)
    assert len(triangles) == int((sizes - 2).sum())
    assert np.all((triangles[:, 0] != triangles[:, 1]) & (triangles[:, 1] != triangles[:, 2])
                  & (triangles[:, 0] != triangles[:, 2]))
    first = cell_starts(sizes)[0]
    corners = set(head.faces[first + 1:first + 1 + sizes[0]].tolist())
    assert set(triangles[:sizes[0] - 2].ravel().tolist()) == corners


def test_a_face_as_pale_as_the_backdrop_is_the_person_inside_the_fitted_outline():
    from engine.photofit.backdrop import subject_weight

    photo = np.full((120, 90, 3), 228, dtype=np.uint8)
    photo[10:40, 20:70] = (120, 90, 60)                       # hair, unlike the backdrop
    photo[40:110, 25:65] = (226, 205, 196)                   # a pale face and neck meeting the backdrop
    inside = np.zeros(photo.shape[:2], dtype=bool)
    inside[20:95, 30:60] = True                              # the fitted head, well inside its outline
    alone, told = subject_weight(photo), subject_weight(photo, inside)
    assert alone is not None and told is not None
    assert alone[70, 45] == 0.0, "by colour alone the pale face is backdrop"
    assert told[70, 45] == 1.0 and told[60, 5] == 0.0
