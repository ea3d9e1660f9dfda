"""A neutral rest face from a smiling photograph (issue 33, item 3): the expression fitted, and taken out of the
texture too.

The photograph's expression (the jaw and the mouth's action units, :mod:`engine.photofit.expression_fit`) is
fitted with the identity, so the head at rest is the person's neutral face and the photograph shows it posed.
The texture is read through the posed head; the pixels between the photograph's inner lips (teeth, tongue) are
not read (:func:`mouth_opening`), the mouth's inside keeps the head's own colours (:func:`mouth_bag`), and the
shadows under the nose and along the creases to the mouth corners are evened out (:func:`even_shadows`).

Synthetic: a known identity posed with a smile and an open jaw, its landmarks projected through the renderer's
perspective camera with 2 px of noise. Real: Joe Biden's official portrait (public domain,
``benchmarks/data/portraits/README.md``), smiling with his teeth showing, its points found by dlib.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from engine.formats.model_files import load_model
from engine.identity import Identity, make_identity_head
from engine.photofit import fit_photos
from engine.photofit.auto_landmarks import find_face_points
from engine.photofit.expression_fit import posed
from engine.photofit.face_points import known_ids, point_vertices
from engine.photofit.initial_points import visible_landmarks
from engine.photofit.raster import sample_bilinear
from engine.photofit.shape import fit_shape
from engine.photofit.texture import bake_texture
from engine.photofit.texture_cleanup import SHADOW_KEEP, even_shadows, mouth_bag, mouth_opening, shadow_vertices
from tests.engine.test_photofit import NOISE_PX, PHOTO_SIZE, TRUE_IDENTITY, project
from tests.engine.test_photofit_real_portrait import _vertex_uv

pytestmark = pytest.mark.slow

PORTRAITS = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "portraits"
SMILE = {"AU12_left": 0.6, "AU12_right": 0.6, "jaw_open": 0.25}
LUMINANCE = np.array([0.299, 0.587, 0.114])


def mouth_width(vertices, where):
    return float(np.linalg.norm(vertices[where["8.3"]] - vertices[where["8.4"]]))


def lip_gap(vertices, where):
    return float(np.linalg.norm(vertices[where["2.2"]] - vertices[where["2.3"]]))


@pytest.fixture(scope="module")
def truth():
    return make_identity_head(Identity(TRUE_IDENTITY))


def photographed_points(truth, pose):
    where = point_vertices(truth)
    pixels = project(truth, "front", *PHOTO_SIZE, points=truth.deform(pose) if pose else truth.vertices)
    rng = np.random.default_rng(33)
    return {"front": {k: tuple(pixels[where[k]] + rng.normal(0, NOISE_PX, 2)) for k in visible_landmarks(truth,
                                                                                                         "front")}}


def test_a_smile_is_fitted_as_expression_and_the_head_at_rest_does_not_smile(truth):
    """Smiling with the jaw a little open, the mouth is 8 mm wider and the lips 6 mm apart; fitted as identity
    (before) that was the person's rest face. Now the expression comes back within 0.15 and the head at rest has
    the truth's mouth width within 1.5 mm and its lip gap within 1 mm."""
    where = point_vertices(truth)
    fit = fit_shape(load_model(), photographed_points(truth, SMILE))
    posed_truth = truth.deform(SMILE)
    print(f"expression {fit.expression}; mouth width at rest {mouth_width(fit.vertices, where):.1f} mm (truth "
          f"{mouth_width(truth.vertices, where):.1f}, smiling {mouth_width(posed_truth, where):.1f}); lip gap "
          f"{lip_gap(fit.vertices, where):.1f} mm (truth {lip_gap(truth.vertices, where):.1f}, smiling "
          f"{lip_gap(posed_truth, where):.1f})")
    for name, value in SMILE.items():
        assert fit.expression.get(name, 0.0) == pytest.approx(value, abs=0.15), name
    assert mouth_width(posed_truth, where) - mouth_width(truth.vertices, where) > 5      # the smile is a smile
    assert abs(mouth_width(fit.vertices, where) - mouth_width(truth.vertices, where)) < 1.5
    assert abs(lip_gap(fit.vertices, where) - lip_gap(truth.vertices, where)) < 1.0
    assert fit.error_before_warp < 2 * NOISE_PX


def test_a_neutral_face_is_given_no_expression(truth):
    fit = fit_shape(load_model(), photographed_points(truth, {}))
    print(f"expression of a neutral face: {fit.expression}")
    assert all(abs(v) < 0.15 for v in fit.expression.values()), fit.expression


@pytest.fixture(scope="module")
def biden():
    photo = np.asarray(Image.open(PORTRAITS / "biden.jpg").convert("RGB"))
    points = {"front": find_face_points(photo, known_ids(load_model())).pixels}
    return photo, points, fit_photos({"front": photo}, points)


def test_the_smiling_portrait_gives_a_neutral_head_that_can_smile(biden):
    _, _, fit = biden
    head, expression = fit.head, fit.shape.expression
    where = point_vertices(head)
    print(f"the portrait's expression: {expression}")
    assert expression.get("AU12_left", 0) > 0.3 and expression.get("AU12_right", 0) > 0.3
    assert expression.get("jaw_open", 0) > 0.2
    seen = posed(head, expression)
    assert mouth_width(seen, where) - mouth_width(head.vertices, where) > 4          # at rest it does not smile
    assert lip_gap(head.vertices, where) < 4.0                                       # the lips (nearly) meet
    smiling = head.deform({"AU12_left": 1.0, "AU12_right": 1.0})                      # and the rig still smiles
    for corner in ("8.3", "8.4"):
        assert smiling[where[corner], 1] - head.vertices[where[corner], 1] > 2, corner


def _atlas_at(head, atlas, vertices):
    uv = _vertex_uv(head)[vertices]
    return sample_bilinear(atlas, np.stack([uv[:, 0] * atlas.shape[1], (1 - uv[:, 1]) * atlas.shape[0]],
                                           axis=1)).astype(float)


def _green_texels(atlas):
    a = atlas.astype(int)
    return int(np.sum((a[..., 1] - a[..., 0] > 120) & (a[..., 1] - a[..., 2] > 120)))


def test_the_teeth_between_the_lips_are_not_read_into_the_texture(biden):
    """The photograph's mouth opening (inside its inner lips) painted green: read without the opening left out,
    green texels land in the atlas (the lips' edge over the teeth); with it (as the fit bakes), none."""
    photo, points, fit = biden
    head, cameras = fit.head, fit.shape.cameras
    opening = mouth_opening(photo.shape, points["front"], cameras["front"].scale)
    assert opening.sum() > 500                                        # his teeth show
    painted = photo.copy()
    painted[opening] = (0, 255, 0)
    seen = posed(head, fit.shape.expression)
    read, _ = bake_texture(head, seen, {"front": painted}, cameras, own_colours=mouth_bag(load_model()))
    left_out, _ = bake_texture(head, seen, {"front": painted}, cameras, hidden={"front": opening},
                               own_colours=mouth_bag(load_model()))
    counts = _green_texels(read.images[0].pixels), _green_texels(left_out.images[0].pixels)
    print(f"green texels: read {counts[0]}, left out {counts[1]}")
    assert counts[0] > 30 and counts[1] <= 3


def test_the_mouth_inside_keeps_the_heads_own_colours(biden):
    """The skin of the mouth's inside shows the default head's own (dark red, shaded by depth) colours, not the
    photograph's teeth or the fill."""
    photo, _, fit = biden
    base = load_model()
    bag = np.flatnonzero(mouth_bag(base))
    assert len(bag) > 100
    off = np.abs(_atlas_at(fit.head, fit.head.texture.images[0].pixels, bag) - base.vertex_colors[bag]).mean(axis=1)
    seen = posed(fit.head, fit.shape.expression)
    plain, _ = bake_texture(fit.head, seen, {"front": photo}, fit.shape.cameras)
    plain_off = np.abs(_atlas_at(fit.head, plain.images[0].pixels, bag) - base.vertex_colors[bag]).mean(axis=1)
    print(f"mouth's inside: {np.median(off):.1f} RGB from the head's own colours (read as skin: "
          f"{np.median(plain_off):.1f})")
    assert np.median(off) < 3 and np.percentile(off, 90) < 15
    assert np.median(plain_off) > 30


def test_the_photographs_shadows_under_the_nose_and_in_the_creases_are_lifted(biden):
    """Baked with and without the shadows evened out: where the shadow weight is 1 the texture is brighter,
    where it is 0 it is the same."""
    photo, points, fit = biden
    head = fit.head
    where = point_vertices(head)
    weights = shadow_vertices(head, head.vertices, where)
    skin = np.flatnonzero(head.vertex_part == head.parts.index("skin"))
    shaded, elsewhere = skin[weights[skin] > 0.9], skin[weights[skin] == 0]
    assert len(shaded) > 20
    seen = posed(head, fit.shape.expression)
    opening = mouth_opening(photo.shape, points["front"], fit.shape.cameras["front"].scale)
    kept, _ = bake_texture(head, seen, {"front": photo}, fit.shape.cameras, hidden={"front": opening},
                           own_colours=mouth_bag(load_model()))
    evened, unevened = (_atlas_at(head, atlas, shaded) @ LUMINANCE for atlas in (head.texture.images[0].pixels,
                                                                                  kept.images[0].pixels))
    print(f"luminance where the shadows are: {unevened.mean():.1f} → {evened.mean():.1f}")
    assert evened.mean() - unevened.mean() > 2.0 and np.all(evened >= unevened - 1.0)
    same = np.abs(_atlas_at(head, head.texture.images[0].pixels, elsewhere)
                  - _atlas_at(head, kept.images[0].pixels, elsewhere))
    assert same.mean() < 0.5


def test_shadow_weights_lie_under_the_nose_and_beside_the_mouth_not_on_the_forehead():
    head = load_model()
    where = point_vertices(head)
    weights = shadow_vertices(head, head.vertices, where)
    under_nose = (head.vertices[where["9.15"]] + head.vertices[where["8.1"]]) / 2
    nearest = np.linalg.norm(head.vertices - under_nose, axis=1).argmin()
    assert weights[nearest] > 0.9
    assert weights[where["4.1"]] == 0 and weights[where["3.5"]] == 0 and weights[where["2.1"]] == 0


def test_even_shadows_lifts_a_dark_stripe_only_where_asked():
    """A flat atlas of 180 with a dark stripe of 100: inside the region the stripe keeps SHADOW_KEEP of its
    darkening (measured against its smoothed surroundings), outside it and where it is brighter nothing moves."""
    size = 200
    atlas = np.full((size, size, 3), 180.0)
    atlas[95:105, :] = 100.0
    atlas[20:24, :] = 240.0                                # a highlight: not lowered
    region = np.zeros((size, size))
    region[:, :100] = 1.0
    region[20:24, :] = 1.0
    covered = np.ones((size, size), dtype=bool)
    before = atlas.copy()
    even_shadows(atlas, region, covered, texels_per_mm=1.0)
    stripe_in, stripe_out = atlas[100, 40] @ LUMINANCE, atlas[100, 160] @ LUMINANCE
    assert stripe_out == pytest.approx(100.0)
    assert 100.0 + 0.4 * (1 - SHADOW_KEEP) * 80 < stripe_in < 180.0
    assert np.allclose(atlas[20:24], before[20:24])
    assert np.allclose(atlas[:60, 150:], before[:60, 150:])
