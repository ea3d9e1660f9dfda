"""Skin that belongs to the person (docs/skin.md): tone by ancestry, age and sex, redder lips and cheeks,
the fine detail as relief in the physically based looks, the same identity to the byte, photographs kept.

Each test measures the pictures or the skin image, so a skin that is lost (not applied, one colour for
everyone, the detail not reaching the shader) fails here.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.errors import UserError
from engine.identity import Identity, make_identity_head
from engine.identity.skin import SKIN_IMAGE, apply_skin, skin_regions, skin_texture, skin_tone
from engine.identity.skin_atlas import skin_atlas
from engine.identity.skin_optics import skin_albedo
from engine.model.texture import ModelTexture, TextureImage
from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
from engine.outputs.look_shader import material_uniforms, shading_source
from engine.outputs.looks import look_from
from engine.outputs.render import render_model

ONLY = {"african": 0.0, "asian": 0.0, "caucasian": 0.0}
PEOPLE = {
    "woman 22 African": {**ONLY, "sex": 0.0, "age": 22, "african": 1.0},
    "man 60 European": {**ONLY, "sex": 1.0, "age": 60, "caucasian": 1.0},
    "man 35 Asian": {**ONLY, "sex": 1.0, "age": 35, "asian": 1.0},
}
SIZE = (300, 380)


@pytest.fixture(scope="module")
def heads():
    return {name: make_identity_head(Identity(values)) for name, values in PEOPLE.items()}


@pytest.fixture(scope="module")
def renders(heads):
    return {name: render_model(head, {}, size=SIZE) for name, head in heads.items()}


def pixel_of(head, point):
    """Where the front render of ``head`` at :data:`SIZE` shows a 3-D ``point`` (x right, y down, pixels)."""
    focal, position, up, _ = camera_pose(framed_points(head), VIEWS["front"], *SIZE)
    back = (position - focal) / np.linalg.norm(position - focal)
    right = np.cross(up, back)
    relative = np.asarray(point, dtype=float) - position
    depth = -(relative @ back)
    focal_px = SIZE[1] / 2 / np.tan(np.radians(VIEW_ANGLE) / 2)
    return (round(float(SIZE[0] / 2 + focal_px * (relative @ right) / depth)),
            round(float(SIZE[1] / 2 - focal_px * (relative @ up) / depth)))


def patch(image, head, point, half=4):
    """The mean sRGB colour of a (2·half)² patch of ``image`` about a 3-D ``point`` of ``head``."""
    x, y = pixel_of(head, point)
    return image[y - half:y + half, x - half:x + half].reshape(-1, 3).astype(float).mean(axis=0)


def places(head):
    """Surface points of the forehead, a cheek and the upper lip (mm), from the feature points."""
    lm = {k: head.vertices[v] for k, v in head.landmarks.items()}
    near = head.vertices[head.part_vertices("skin")]

    def on_skin(p):
        flat = near[np.argsort(np.linalg.norm((near - p)[:, :2], axis=1))[:12]]
        return flat[np.argmax(flat[:, 2])]

    brows = (lm["4.1"] + lm["4.2"]) / 2
    forehead = on_skin(brows + np.array([0, 18, 0]))
    cheek = on_skin(np.array([lm["3.7"][0] * 0.85, (lm["3.7"][1] + lm["8.3"][1]) / 2, 0]))
    lip = on_skin((lm["8.1"] + lm["2.2"]) / 2)
    return {"forehead": forehead, "cheek": cheek, "lip": lip}


def luminance(rgb):
    return float(rgb @ [0.2126, 0.7152, 0.0722])


def test_every_identity_gets_a_skin_image_and_the_default_head_too(heads):
    for head in [*heads.values(), make_identity_head(Identity())]:
        assert head.texture is not None and [i.name for i in head.texture.images] == [SKIN_IMAGE]
        skin_faces = head.vertex_part[head.faces[_cell_starts(head) + 1]] == head.parts.index("skin")
        shown = head.texture.face_image >= 0
        assert shown.sum() > 0.95 * skin_faces.sum() and not (shown & ~skin_faces).any()


def _cell_starts(model):
    from engine.model.cells import cell_sizes, cell_starts

    return cell_starts(cell_sizes(model.faces))


def test_skin_is_darker_with_more_melanin_in_the_render(heads, renders):
    tones = {name: skin_tone(heads[name].identity) for name in heads}
    assert tones["woman 22 African"].melanin > 5 * tones["man 35 Asian"].melanin > 5 * tones["man 60 European"].melanin
    light = {name: np.mean([luminance(patch(renders[name], heads[name], places(heads[name])[k]))
                            for k in ("forehead", "cheek")]) for name in heads}
    assert light["woman 22 African"] < 0.7 * light["man 35 Asian"]
    assert light["man 35 Asian"] < light["man 60 European"]


def test_lips_are_redder_than_cheeks_redder_than_the_forehead(heads, renders):
    for name in ("man 60 European", "man 35 Asian"):
        colours = {k: patch(renders[name], heads[name], p, half=2) for k, p in places(heads[name]).items()}
        redness = {k: c[0] / c[1] for k, c in colours.items()}           # R/G: the lighting's level cancels
        assert redness["lip"] > redness["cheek"] > redness["forehead"], (name, redness)
    # and in the skin image itself, region by region
    head = heads["woman 22 African"]
    atlas = skin_atlas(head, 512)
    image = skin_texture(head, head.identity, 512).pixels.reshape(-1, 3).astype(float)[atlas.texel_index]
    regions = {k: atlas.interpolate(w) for k, w in skin_regions(head).items()}
    mean = {k: image[regions[k] > 0.8].mean(axis=0) for k in ("lips", "cheeks", "forehead")}
    ratio = {k: c[0] / c[1] for k, c in mean.items()}
    assert ratio["lips"] > ratio["cheeks"] > ratio["forehead"], ratio


def test_age_and_sex_change_the_skin():
    woman, man = skin_tone(Identity({"sex": 0.0})), skin_tone(Identity({"sex": 1.0}))
    young, old = skin_tone(Identity({"age": 20})), skin_tone(Identity({"age": 75}))
    assert man.melanin > woman.melanin and man.blood > woman.blood
    assert old.blood < young.blood and old.yellow > young.yellow
    light, dark = skin_albedo(np.array([0.02, 0.3]), np.array([0.06, 0.06]))
    assert np.all(dark < light) and light[0] > light[1] > light[2]


def test_age_lines_deepen_with_age():
    young, old = (make_identity_head(Identity({"age": a})) for a in (22, 75))
    lm = {k: old.vertices[v] for k, v in old.landmarks.items()}
    atlas = skin_atlas(old, 512)
    texels = atlas.interpolate(old.vertices)
    forehead = (texels[:, 1] > lm["4.3"][1] + 9) & (texels[:, 1] < lm["4.3"][1] + 40) \
        & (np.abs(texels[:, 0]) < 35) & (texels[:, 2] > lm["8.3"][2])

    def fine_contrast(head):
        pixels = skin_texture(head, head.identity, 512).pixels.reshape(-1, 3).astype(float)
        lum = pixels[atlas.texel_index][forehead] @ [0.2126, 0.7152, 0.0722]
        return float(np.percentile(lum, 90) - np.percentile(lum, 5))

    assert fine_contrast(old) > 1.5 * fine_contrast(young)


def test_the_detail_map_is_applied_on_the_skin_and_not_the_background(heads):
    head = heads["man 60 European"]
    plain = render_model(head, {}, size=SIZE, look=look_from({"preset": "portrait", "skin_detail": 0.0}))
    detailed = render_model(head, {}, size=SIZE)
    again = render_model(head, {}, size=SIZE)
    assert np.array_equal(detailed, again)

    def fine(image):
        grey = image.astype(float) @ [0.2126, 0.7152, 0.0722]
        blurred = (grey[:-2, 1:-1] + grey[2:, 1:-1] + grey[1:-1, :-2] + grey[1:-1, 2:] + grey[1:-1, 1:-1]) / 5
        return np.abs(grey[1:-1, 1:-1] - blurred)

    lm = {k: head.vertices[v] for k, v in head.landmarks.items()}
    brows = (lm["4.1"] + lm["4.2"]) / 2
    top, bottom = pixel_of(head, brows + np.array([0, 38, 0])), pixel_of(head, brows + np.array([0, 8, 0]))
    forehead = (slice(top[1], bottom[1]), slice(top[0] - 35, top[0] + 35))     # its lines, in relief
    assert fine(detailed)[forehead].mean() > 1.15 * fine(plain)[forehead].mean()
    corner = (slice(0, 25), slice(0, 25))
    assert np.array_equal(detailed[corner], plain[corner])


def test_the_look_records_the_detail_setting():
    look = look_from({"preset": "portrait", "skin_detail": 0.5})
    assert look.settings()["skin_detail"] == 0.5 and look_from(look.settings()) == look
    assert look_from("portrait").settings()["skin_detail"] == 1.0
    assert material_uniforms(look, "skin")["lookDetail"] == 0.5
    assert material_uniforms(look, "eye_left")["lookDetail"] == 0.0
    assert material_uniforms(look_from("legacy"), "skin")["lookDetail"] == 0.0
    assert "LOOK_VIEW_POSITION" in shading_source(look)
    with pytest.raises(UserError, match="skin_detail"):
        look_from({"preset": "portrait", "skin_detail": -1})


def test_the_same_identity_gives_the_same_skin_to_the_byte(heads, renders):
    values = PEOPLE["man 35 Asian"]
    again = make_identity_head(Identity(values))
    assert again.texture.images[0].pixels.tobytes() == heads["man 35 Asian"].texture.images[0].pixels.tobytes()
    assert np.array_equal(render_model(again, {}, size=SIZE), renders["man 35 Asian"])
    other = make_identity_head(Identity({**values, "age": 36}))
    assert other.texture.images[0].pixels.tobytes() != again.texture.images[0].pixels.tobytes()


def test_a_photo_textured_head_keeps_its_photographs(heads):
    head = heads["man 35 Asian"].copy()
    photo = TextureImage("photo", np.full((64, 64, 3), 77, np.uint8))
    face_image = head.texture.face_image.copy()
    head.texture = ModelTexture(head.texture.corner_uv, [photo], face_image)
    apply_skin(head, head.identity)
    assert [i.name for i in head.texture.images] == ["photo"]
    assert np.array_equal(head.texture.images[0].pixels, photo.pixels)
    assert np.array_equal(head.texture.face_image, face_image)
