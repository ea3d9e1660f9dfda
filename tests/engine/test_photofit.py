"""Fit to photographs (issue 19): synthetic ground truth, the fit-photos verb, and bad input refused.

A known identity with a known, detailed texture (a procedural pattern in the
shared atlas) is rendered by the toolkit's own renderer from the front and
the side; its landmarks are projected with that renderer's perspective
camera (:func:`project`) and given a few pixels of noise. The fit must find
the shape, put the landmarks back on their pixels and carry the pattern
back into the atlas.
"""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from PIL import Image

from engine.formats.model_files import load_model
from engine.identity import Identity, make_identity_head
from engine.identity.carry_over import similarity
from engine.model.cells import cell_sizes
from engine.model.texture import ModelTexture, TextureImage
from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
from engine.outputs.render import render_model
from engine.photofit import PhotoFitError, fit_photos, read_photo, read_points
from engine.photofit.points import REQUIRED_FRONT
from engine.photofit.raster import rasterize, sample_bilinear
from engine.photofit.shape import fit_shape
from engine.photofit.silhouette import foreground, profile_moves, profile_vertices
from engine.photofit.texture import skin_triangles
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.fuzz_support import FUZZ, expect_clean

PHOTO_SIZE = (900, 1200)               # width, height: the head about 700 px tall, like a cropped portrait
NOISE_PX = 2.0
TRUE_IDENTITY = {"sex": 0.8, "age": 40, "nose-scale-horiz-decr-incr": 0.5, "mouth-scale-horiz-decr-incr": -0.4,
                 "chin-height-decr-incr": 0.5, "eye-trans-down-up": -0.3}
TRUE_IRIS = np.array([125, 78, 38])   # brown: the default head's irises are blue-grey
FACE_RADIUS = 25.0                     # mm: "the face" is the skin within this distance of a landmark


def project(model, view, width, height, points=None):
    """(N, 2) pixels of ``points`` (the model's rest vertices) in ``render_model``'s picture (perspective)."""
    focal, position, up, _ = camera_pose(framed_points(model), VIEWS[view], width, height)
    back = (position - focal) / np.linalg.norm(position - focal)
    right = np.cross(up, back)
    d = (model.vertices if points is None else points) - position
    depth = -(d @ back)
    f = (height / 2) / np.tan(np.radians(VIEW_ANGLE) / 2)
    return np.stack([width / 2 + f * (d @ right) / depth, height / 2 - f * (d @ up) / depth], axis=1)


def pattern(size=1024):
    y, x = np.mgrid[0:size, 0:size] / size
    rgb = [128 + 100 * np.sin(61 * x), 128 + 100 * np.sin(47 * y), 128 + 90 * np.sin(37 * (x + y))]
    return np.clip(np.stack(rgb, axis=-1), 0, 255).astype(np.uint8)


def skin_face_image(model):
    """Which image each polygon shows: 0 on the skin, -1 (its part's colour) elsewhere."""
    _, _, polygons = skin_triangles(model)
    face_image = np.full(len(cell_sizes(model.faces)), -1)
    face_image[np.unique(polygons)] = 0
    return face_image


def photographed(truth):
    """Front and side pictures of ``truth`` (rendered) and its landmarks in them, with NOISE_PX of noise."""
    rng = np.random.default_rng(19)
    photos, points = {}, {}
    for view in ("front", "side"):
        # the legacy look's plain headlight: the truth's colours come back through a light the fit can undo
        # (the portrait look's key light darkens the irises by 40 %, which is the photograph's business)
        photos[view] = render_model(truth, view=view, size=PHOTO_SIZE, look="legacy")
        pixels = project(truth, view, *PHOTO_SIZE)
        # the side photograph shows the subject's left (+X) and the midline
        ids = [k for k in sorted(truth.landmarks) if view == "front" or truth.vertices[truth.landmarks[k], 0] > -3]
        points[view] = {k: tuple(pixels[truth.landmarks[k]] + rng.normal(0, NOISE_PX, 2)) for k in ids}
    return photos, points


@pytest.fixture(scope="module")
def synthetic():
    truth = make_identity_head(Identity(TRUE_IDENTITY))
    truth.texture = ModelTexture(truth.texture.corner_uv, [TextureImage("pattern", pattern())],
                                 skin_face_image(truth))
    truth.vertex_colors = truth.vertex_colors.copy()
    truth.vertex_colors[np.all(truth.vertex_colors == iris_colour_of(truth), axis=1)] = TRUE_IRIS
    photos, points = photographed(truth)
    landmark_points = truth.vertices[list(truth.landmarks.values())]
    distance = np.linalg.norm(truth.vertices[:, None] - landmark_points[None], axis=2).min(axis=1)
    face = (truth.vertex_part == truth.parts.index("skin")) & (distance < FACE_RADIUS)
    return truth, photos, points, face


@pytest.fixture(scope="module")
def two_views(synthetic):
    _, photos, points, _ = synthetic
    return fit_photos(photos, points)


@pytest.fixture(scope="module")
def front_only(synthetic):
    _, photos, points, _ = synthetic
    return fit_photos({"front": photos["front"]}, {"front": points["front"]})


def iris_colour_of(head, part="eye_left"):
    colours = np.unique(head.vertex_colors[head.vertex_part == head.parts.index(part)], axis=0)
    return colours[np.argsort(colours.astype(float).sum(axis=1))[1]]


def shape_error_mm(head, truth, face):
    """RMS distance (mm) over the face after the best similarity transform: photographs do not show
    a head's absolute size or place (a weak-perspective camera's scale and shift take them)."""
    moved = similarity(head.vertices[face], truth.vertices[face])
    d = moved.point(head.vertices[face]) - truth.vertices[face]
    return float(np.sqrt((d ** 2).sum(axis=1).mean()))


def texture_psnr(head, truth, face, photo=None):
    """PSNR (dB) of the fitted atlas against the true pattern over the front-facing face's texels.

    With ``photo`` (the front rendering): the PSNR of the pattern read back from it at the true surface
    points through the true camera instead, the best any fit can do through the renderer's lighting."""
    tri_v, tri_c, _ = skin_triangles(truth)
    normals_z = np.cross(truth.vertices[tri_v[:, 1]] - truth.vertices[tri_v[:, 0]],
                         truth.vertices[tri_v[:, 2]] - truth.vertices[tri_v[:, 0]])
    normals_z = normals_z[:, 2] / np.maximum(np.linalg.norm(normals_z, axis=1), 1e-12)
    keep = face[tri_v].all(axis=1) & (normals_z > 0.5)
    uv = truth.texture.corner_uv[tri_c[keep]]
    size = truth.texture.images[0].pixels.shape[0]
    hit, bary, _ = rasterize(np.stack([uv[..., 0] * size, (1 - uv[..., 1]) * size], axis=-1), size, size)
    region = hit >= 0
    if photo is None:
        fitted = head.texture.images[0].pixels[region].astype(float)
    else:
        points = np.einsum("nk,nkd->nd", bary[region], truth.vertices[tri_v[keep][hit[region]]])
        fitted = sample_bilinear(photo, project(truth, "front", *PHOTO_SIZE, points))
    known = truth.texture.images[0].pixels[region].astype(float)
    return float(10 * np.log10(255 ** 2 / np.mean((fitted - known) ** 2))), int(region.sum())


def test_two_views_recover_shape_landmarks_and_texture(synthetic, two_views):
    truth, photos, _, face = synthetic
    default = load_model()
    start_error = shape_error_mm(default, truth, face)
    error = shape_error_mm(two_views.head, truth, face)
    psnr, texels = texture_psnr(two_views.head, truth, face)
    best, _ = texture_psnr(two_views.head, truth, face, photos["front"])
    print(f"texture read back through the true camera: {best:.1f} dB")
    print(f"two views: shape {error:.2f} mm RMS (default head {start_error:.2f}), landmarks "
          f"{two_views.shape.error:.2f} px ({two_views.shape.error_before_warp:.2f} before the warp), "
          f"texture {psnr:.1f} dB over {texels} texels, {two_views.seconds}")
    assert error < 0.6 * start_error and error < 1.5
    assert two_views.shape.error < 2.0 * NOISE_PX
    assert texels > 10000 and psnr > best - 1.5


def test_front_only_fit_works(synthetic, front_only):
    truth, photos, _, face = synthetic
    error = shape_error_mm(front_only.head, truth, face)
    psnr, _ = texture_psnr(front_only.head, truth, face)
    best, _ = texture_psnr(front_only.head, truth, face, photos["front"])
    print(f"front only: shape {error:.2f} mm RMS, landmarks {front_only.shape.error:.2f} px, texture {psnr:.1f} dB")
    assert list(front_only.shape.cameras) == ["front"]
    assert error < 0.8 * shape_error_mm(load_model(), truth, face)
    assert front_only.shape.error < 2.0 * NOISE_PX
    assert psnr > best - 1.5


def test_fitted_head_is_textured_and_animates(two_views):
    head = two_views.head
    default = load_model()
    assert [p.name for p in head.parameters] == [p.name for p in default.parameters]
    texture = head.texture
    texture.check(head.faces)
    assert texture.images[0].pixels.shape == (1024, 1024, 3) and texture.textured_faces().sum() > 4000
    skin = head.vertex_part == head.parts.index("skin")
    opened = head.deform({"jaw_open": 0.6})
    assert np.abs(opened - head.vertices)[skin].max() > 3.0         # the jaw still opens the mouth
    picture = render_model(head, {"jaw_open": 0.6}, size=(160, 200))
    assert picture.std() > 10


def test_the_profile_meets_the_side_silhouette(synthetic):
    _, photos, points, _ = synthetic
    base = load_model()
    mask = foreground(photos["side"])
    assert mask is not None, "the renderer's backdrop counts as plain"
    gaps = {}
    for label, side_photo in (("landmarks", None), ("silhouette", photos["side"])):
        fit = fit_shape(base, points, side_photo)
        profile = profile_vertices(base, fit.vertices)
        trusted, moves = profile_moves(mask, fit.cameras["side"], fit.vertices[profile])
        gaps[label] = float(np.linalg.norm(moves[trusted], axis=1).mean() * fit.cameras["side"].scale)
        assert trusted.sum() > 20
    print(f"profile to silhouette, mean px: {gaps}")
    assert gaps["silhouette"] < 0.6 * gaps["landmarks"]


def test_a_busy_background_gives_no_silhouette():
    noise = (np.random.default_rng(3).random((200, 150, 3)) * 255).astype(np.uint8)
    assert foreground(noise) is None


def test_iris_colour_is_read_from_the_photograph(two_views):
    default = iris_colour_of(load_model()).astype(float)
    for part in ("eye_left", "eye_right"):
        fitted = iris_colour_of(two_views.head, part).astype(float)
        print(part, fitted, "true", TRUE_IRIS, "default", default)
        assert np.linalg.norm(fitted - TRUE_IRIS) < 0.5 * np.linalg.norm(default - TRUE_IRIS)


def test_fit_photos_verb_writes_a_textured_person(synthetic, tmp_path):
    _, photos, points, _ = synthetic
    Image.fromarray(photos["front"]).save(tmp_path / "front.jpg", quality=92)
    Image.fromarray(photos["side"]).save(tmp_path / "side.png")
    (tmp_path / "points.json").write_text(json.dumps({v: {k: list(p) for k, p in pts.items()}
                                                      for v, pts in points.items()}))
    result = run("fit-photos", "--front", tmp_path / "front.jpg", "--side", tmp_path / "side.png",
                 "--landmarks", tmp_path / "points.json", "-o", tmp_path / "person.xml")
    assert result.returncode == 0, result.stderr
    assert "landmarks" in result.stdout and "→ shape" in result.stdout and "→ texture" in result.stdout
    assert " px RMS" in result.stdout
    person = load_model(tmp_path / "person.xml")
    assert person.texture is not None and person.texture.images[0].name == "photo"


def write_points(path: Path, data) -> Path:
    path.write_text(data if isinstance(data, str) else json.dumps(data))
    return path


def good_front():
    return {"3.5": [180.0, 150.0], "3.6": [120.0, 150.0], "9.3": [150.0, 200.0], "8.3": [175.0, 230.0],
            "8.4": [125.0, 230.0], "2.1": [150.0, 290.0]}


@pytest.mark.parametrize(("data", "words"), [
    ("{", "not valid JSON"),
    ([], "must hold an object"),
    ({"side": {"9.3": [1, 2]}}, "no 'front' view"),
    ({"back": {}}, "unknown view"),
    ({"front": {**good_front(), "99.9": [1, 2]}}, "unknown landmark"),
    ({"front": {**good_front(), "9.3": ["1", 2]}}, "expected [x, y]"),
    ({"front": {**good_front(), "9.3": [1, 2, 3]}}, "expected [x, y]"),
    ({"front": {**good_front(), "9.3": [True, 2]}}, "expected [x, y]"),
    ('{"front": {"9.3": [NaN, 2]}}', "not valid JSON"),
    ({"front": {**good_front(), "9.3": [1e300, 2]}}, "finite"),
    ({"front": {k: v for k, v in good_front().items() if k != "2.1"}}, "needs landmarks 2.1"),
    ({"front": good_front(), "side": {"9.3": [1, 2]}}, "at least 3"),
    ({"front": {k: [100, 100] for k in REQUIRED_FRONT}}, "px apart"),
    ({"front": {**good_front(), "3.5": [120.0, 150.0], "3.6": [180.0, 150.0]}}, "are they swapped"),
    ({"front": {**good_front(), "2.1": [150.0, 100.0]}}, "below the nose tip"),
])
def test_bad_points_are_refused_with_one_line(tmp_path, data, words):
    path = write_points(tmp_path / "points.json", data)
    with pytest.raises(PhotoFitError) as caught:
        read_points(path, known=set(load_model().landmarks))
    assert str(caught.value).startswith(str(path)) and words in str(caught.value)


def test_bad_inputs_end_with_status_2(tmp_path):
    photo = tmp_path / "front.png"
    Image.fromarray(np.zeros((400, 300, 3), dtype=np.uint8)).save(photo)
    gif = tmp_path / "front.gif"
    Image.fromarray(np.zeros((40, 30, 3), dtype=np.uint8)).save(gif)
    text = write_points(tmp_path / "notes.jpg", "not a picture")
    points = write_points(tmp_path / "points.json", {"front": good_front()})
    outside = write_points(tmp_path / "outside.json", {"front": {**good_front(), "2.1": [150, 5000]}})
    with_side = write_points(tmp_path / "side.json", {"front": good_front(), "side": good_front()})
    out = tmp_path / "p.xml"
    cases = [
        (("--front", gif, "--landmarks", points), "JPEG or PNG"),
        (("--front", text, "--landmarks", points), "not a picture"),
        (("--front", tmp_path / "missing.jpg", "--landmarks", points), "cannot read"),
        (("--front", photo, "--landmarks", outside), "outside the 300×400"),
        (("--front", photo, "--landmarks", with_side), "no --side photograph"),
        (("--front", photo, "--side", photo, "--landmarks", points), "no 'side' points"),
        (("--front", photo, "--landmarks", tmp_path / "none.json"), "cannot read the landmark file"),
    ]
    for args, words in cases:
        line = assert_user_error(run("fit-photos", *args, "-o", out))
        assert words in line, line


def test_exif_orientation_is_honoured(tmp_path):
    pixels = np.zeros((20, 60, 3), dtype=np.uint8)
    pixels[:, :10] = 255                                     # a white band on the stored picture's left
    image = Image.fromarray(pixels)
    exif = Image.Exif()
    exif[0x0112] = 6                                         # "rotate 90° clockwise to view"
    path = tmp_path / "portrait.jpg"
    image.save(path, exif=exif.tobytes(), quality=95)
    upright = read_photo(path)
    assert upright.shape == (60, 20, 3)
    assert upright[:10].mean() > 200 and upright[-10:].mean() < 50      # the band is now at the top


JSON_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers(-10**9, 10**9) | st.floats() | st.text(max_size=8),
    lambda inner: st.one_of(st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=6), inner, max_size=4)),
    max_leaves=20)
LANDMARK_IDS = st.sampled_from([*REQUIRED_FRONT, "2.2", "9.1", "nose", "", "3.5 "])
PLAUSIBLE = st.dictionaries(st.sampled_from(["front", "side", "back"]), st.dictionaries(
    LANDMARK_IDS, st.lists(st.floats() | st.integers() | st.text(max_size=3), min_size=0, max_size=3)))


@FUZZ
@given(st.one_of(JSON_VALUES.map(json.dumps), PLAUSIBLE.map(json.dumps), st.binary(max_size=200).map(
    lambda b: b.decode("latin-1"))))
def test_fuzz_points_reader(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("fuzz") / "points.json"
    path.write_text(text, encoding="utf-8")
    expect_clean(lambda: read_points(path, model_landmarks()), PhotoFitError, str(path))


@cache
def model_landmarks():
    return frozenset(load_model().landmarks)


@pytest.mark.parametrize("mode", ["L", "RGBA", "P", "CMYK"])
def test_photographs_of_any_mode_are_read_as_rgb(tmp_path, mode):
    image = Image.fromarray(np.tile(np.arange(0, 250, 10, dtype=np.uint8)[None, :, None], (8, 1, 3))).convert(mode)
    path = tmp_path / ("p.jpg" if mode in ("L", "CMYK") else "p.png")
    image.save(path)
    pixels = read_photo(path)
    assert pixels.shape == (8, 25, 3) and pixels.dtype == np.uint8
    assert pixels[:, -1].mean() > pixels[:, 0].mean() + 150


def test_a_truncated_jpeg_is_refused_in_one_line(tmp_path):
    whole = tmp_path / "whole.jpg"
    Image.fromarray((np.random.default_rng(0).random((300, 200, 3)) * 255).astype(np.uint8)).save(whole)
    cut = tmp_path / "cut.jpg"
    cut.write_bytes(whole.read_bytes()[:2000])
    with pytest.raises(PhotoFitError) as caught:
        read_photo(cut)
    assert str(caught.value).startswith(str(cut))
