"""Hair as parts of the head (engine.identity.hair): brows that move with the skin, scalp and facial hair in the
picture, the choice in the model file, and the same hair every time."""

from __future__ import annotations

import numpy as np
import pytest

from engine.formats.model_files import load_model, save_model
from engine.identity import Identity, make_identity_head
from engine.identity.hair import add_hair, grown, without_hair
from engine.identity.hair_style import COLOURS, HairChoice, hair_of
from engine.identity.hair_surface import place
from tests.engine.cli_runner import assert_user_error, run

SHORT = HairChoice.parse(style="short", colour="dark-brown", brows="medium")


@pytest.fixture(scope="module")
def default_head():
    return make_identity_head(Identity())


@pytest.fixture(scope="module")
def haired(default_head):
    return add_hair(default_head, SHORT)


def test_the_brows_are_parts_made_of_hairs(haired):
    for part in ("eyebrow_left", "eyebrow_right", "hair"):
        assert part in haired.parts
        assert len(haired.part_vertices(part)) > 1000
    assert "hair_beard" not in haired.parts       # no beard was asked for
    # the brows take the hair's colour (varied per strand), far darker than the skin
    brow = haired.vertex_colors[haired.part_vertices("eyebrow_left")].astype(float)
    skin = haired.vertex_colors[haired.part_vertices("skin")].astype(float)
    assert brow.mean() < 0.6 * skin.mean()
    assert brow.std(axis=0).max() > 3.0


@pytest.mark.parametrize("values", [
    {"AU1_left": 1.0, "AU1_right": 1.0, "AU2_left": 1.0, "AU2_right": 1.0},
    {"AU4_left": 1.0, "AU4_right": 1.0},
    {"head_nod": 0.3, "head_turn": -0.4},
])
def test_brow_hairs_move_as_the_skin_under_them(default_head, haired, values):
    for part in ("eyebrow_left", "eyebrow_right"):
        piece = grown(part, "medium", SHORT.seed)
        idx = haired.part_vertices(part)
        rest, moved = haired.vertices, haired.deform(values)
        skin_rest = place(default_head.vertices, piece.anchors)
        assert np.allclose(skin_rest, rest[idx], atol=1e-6)        # the hairs sit where their anchors put them
        under = np.einsum("mk,mkd->md", piece.anchors.bary, moved[piece.anchors.corners])
        under_rest = np.einsum("mk,mkd->md", piece.anchors.bary, rest[piece.anchors.corners])
        skin_motion, hair_motion = under - under_rest, moved[idx] - rest[idx]
        assert np.linalg.norm(skin_motion, axis=1).mean() > 0.5      # the pose moves the brow at all
        # each hair keeps its place over its skin point (it is 0.1-0.6 mm above it, so a turn of the head
        # swings it a little more than the point): within a fifth of a millimetre of the skin's own motion
        gap_rest = np.linalg.norm(rest[idx] - under_rest, axis=1)
        assert np.abs(np.linalg.norm(moved[idx] - under, axis=1) - gap_rest).max() < 0.05
        assert np.linalg.norm(hair_motion - skin_motion, axis=1).max() < (0.2 if "AU4_left" in values
                                                                           or "AU1_left" in values else 0.6)
    if "AU1_left" in values:                  # inner and outer brow raisers lift the brows
        assert (moved[idx, 1] - rest[idx, 1]).mean() > 0.5
    if "AU4_left" in values:                  # the lowerer draws them down and together
        left = haired.part_vertices("eyebrow_left")
        motion = moved[left] - rest[left]
        assert motion[:, 1].mean() < -0.2 and motion[:, 0].mean() < 0.0


def test_an_identity_wears_the_hair_on_its_own_skin():
    person = make_identity_head(Identity({"sex": 0.0, "age": 22}),
                                hair=HairChoice.parse(style="long", colour="black"))
    piece = grown("hair", "long", 1)
    assert np.allclose(person.vertices[person.part_vertices("hair")], place(person.vertices, piece.anchors))
    assert hair_of(person.identity).style == "long" and person.identity.value("age") == 22


def _forehead_top(image: np.ndarray) -> np.ndarray:
    """Mean RGB of the middle of the head's silhouette near its top (the band above the forehead)."""
    background = image[2, 2].astype(int)
    head = np.abs(image.astype(int) - background).sum(axis=2) > 40
    rows = np.flatnonzero(head[:, image.shape[1] // 2])
    top = rows[0]
    band = image[top + 8: top + 30, image.shape[1] // 2 - 20: image.shape[1] // 2 + 20]
    return band.reshape(-1, 3).mean(axis=0)


def test_the_hair_is_in_the_picture_and_a_bald_head_stays_bald(default_head, haired):
    from engine.outputs.render import render_model

    bald = add_hair(default_head, HairChoice.parse(style="none", brows="medium"))
    assert "hair" not in bald.parts and "eyebrow_left" in bald.parts
    with_hair = _forehead_top(render_model(haired, size=(320, 240)))
    skin = _forehead_top(render_model(bald, size=(320, 240)))
    dark_brown = np.array(COLOURS["dark-brown"], float)
    assert np.linalg.norm(with_hair - dark_brown) < 60, with_hair
    assert skin.mean() > with_hair.mean() + 50, (skin, with_hair)
    assert skin[0] > skin[2] + 20                 # skin is warm; dark-brown hair is near grey


def test_renders_are_the_same_twice(default_head):
    from engine.outputs.render import render_model

    choice = HairChoice.parse(style="tied", beard="stubble", brows="thick", colour="red")
    a = render_model(add_hair(default_head, choice), size=(160, 120))
    b = render_model(add_hair(make_identity_head(Identity()), choice), size=(160, 120))
    assert np.array_equal(a, b)


def test_the_model_file_keeps_the_hair(haired, tmp_path):
    path = save_model(haired, tmp_path / "person.xml")
    text = path.read_text()
    assert '<hair style="short" colour="dark-brown" beard="none" brows="medium" seed="1"/>' in text
    back = load_model(path)
    assert hair_of(back.identity) == SHORT
    assert back.parts == haired.parts and np.array_equal(back.vertices, haired.vertices)
    assert np.array_equal(back.vertex_colors, haired.vertex_colors)
    # hair can be taken off again, leaving the head as it was
    assert without_hair(back).n_vertices == make_identity_head(Identity()).n_vertices


def test_an_unknown_style_in_a_model_file_names_its_line(haired, tmp_path):
    path = save_model(haired, tmp_path / "person.xml")
    lines = path.read_text().splitlines()
    line = next(k for k, text in enumerate(lines, 1) if "<hair " in text)
    path.write_text(path.read_text().replace('style="short"', 'style="mohawk"'))
    message = assert_user_error(run("info", "-m", path))
    assert f"person.xml:{line}:" in message and "mohawk" in message and "short, long, tied" in message


def test_the_identity_verb_grows_hair_and_refuses_a_bad_name(tmp_path):
    made = run("identity", "--set", "sex=1", "--set", "age=60", "--hair", "short", "--hair-colour", "grey",
               "--beard", "beard", "--brows", "thick", "-o", tmp_path / "man.xml")
    assert made.returncode == 0, made.stderr
    assert "short grey hair, beard, thick brows" in made.stdout
    head = load_model(tmp_path / "man.xml")
    assert {"hair", "hair_beard", "eyebrow_left", "eyebrow_right"} <= set(head.parts)
    bald = run("identity", "--hair", "none", "--brows", "none", "-o", tmp_path / "bald.xml")
    assert bald.returncode == 0, bald.stderr
    assert not {"hair", "eyebrow_left"} & set(load_model(tmp_path / "bald.xml").parts)
    message = assert_user_error(run("identity", "--beard", "goatee", "-o", tmp_path / "x.xml"))
    assert "goatee" in message and "stubble, moustache, beard" in message


def test_a_stimulus_design_asks_for_hair_in_its_identity_table(tmp_path):
    from engine.errors import UserError
    from engine.stimuli.design import parse_design
    from engine.stimuli.heads import stimulus_head

    text = ('[factors]\ntext = ["Moi."]\nidentity = [{sex = 1.0, age = 60, hair = "short", beard = "stubble"},'
            ' {sex = 1.0, age = 60}]\n[output]\nkinds = ["png"]\n')
    design = parse_design(text, tmp_path / "d.toml")
    haired, bald = (stimulus_head(design, s.levels) for s in design.stimuli)
    assert {"hair", "beard_stubble", "eyebrow_left"} <= set(haired.parts)
    assert "hair" not in bald.parts                         # no hair keys: the head as before
    assert haired.identity.value("age") == 60 and hair_of(haired.identity).beard == "stubble"
    with pytest.raises(UserError) as bad:
        parse_design(text.replace('"short"', '"mullet"'), tmp_path / "d.toml")
    assert "d.toml:3" in str(bad.value) and "mullet" in str(bad.value)
