"""The default head's skin (docs/skin.md "The default head"): the image shipped in
engine/data/default-head/skin.png is what the code computes for the default identity, the shipped head is
given it by put_on_shipped_skin, and the default identity takes it."""

from __future__ import annotations

import numpy as np
import pytest

from engine import load_model, save_model
from engine.formats.default_head_skin import SKIN_FILE, put_on_shipped_skin
from engine.identity import Identity, make_identity_head
from engine.identity.skin import ATLAS_SIZE, SKIN_IMAGE, skin_texture
from engine.identity.skin_atlas import skin_faces
from engine.identity.skin_cache import KEY_CHUNK, read_skin_png, skin_key
from engine.outputs.render import render_model
from engine.paths import default_model_path


def skinned_default_head():
    head = load_model()
    put_on_shipped_skin(head, default_model_path())
    return head


def test_the_shipped_image_is_current():
    """Fails when the skin's code, constants or the head changed: run engine/data/default-head/default_skin.py."""
    from PIL import Image

    with Image.open(SKIN_FILE) as image:
        shipped_key = image.info.get(KEY_CHUNK)
        assert image.size == (ATLAS_SIZE, ATLAS_SIZE) and image.mode == "RGB"
    assert shipped_key == skin_key(load_model(), Identity(), ATLAS_SIZE), \
        "engine/data/default-head/skin.png is stale: run engine/data/default-head/default_skin.py"
    assert SKIN_FILE.stat().st_size < 2_000_000


def test_the_shipped_head_is_given_its_skin():
    head = skinned_default_head()
    assert head.texture is not None and [i.name for i in head.texture.images] == [SKIN_IMAGE]
    shown = np.flatnonzero(head.texture.face_image == 0)
    assert np.array_equal(shown, skin_faces(head)) and len(shown) > 4000
    shipped = read_skin_png(SKIN_FILE, skin_key(head, Identity(), ATLAS_SIZE))
    assert shipped is not None and np.array_equal(head.texture.images[0].pixels, shipped)


def test_the_default_identity_shows_the_same_skin():
    head, person = skinned_default_head(), make_identity_head(Identity())
    assert person.texture is not None and head.texture is not None
    assert np.array_equal(person.texture.images[0].pixels, head.texture.images[0].pixels)
    assert np.array_equal(person.texture.face_image, head.texture.face_image)


def test_only_the_shipped_file_is_given_it_and_a_saved_copy_keeps_its_own(tmp_path):
    head = skinned_default_head()
    assert head.texture is not None
    head.texture.images[0].pixels[:] = 90
    path = save_model(head, tmp_path / "copy.xml")
    copy = load_model(path)
    put_on_shipped_skin(copy, path)
    assert copy.texture is not None and int(copy.texture.images[0].pixels.max()) == 90
    bare = load_model(path)
    assert bare.texture is not None
    bare.texture = type(bare.texture)(bare.texture.corner_uv, [], bare.texture.face_image * 0 - 1)
    put_on_shipped_skin(bare, path)                   # another file's name: left as it is
    assert bare.texture.images == []


def test_the_render_shows_the_skin():
    head, plain = skinned_default_head(), load_model()
    assert plain.texture is not None
    plain.texture.face_image[:] = -1                 # the part colours, as before the skin
    plain.changed()
    a = render_model(head, {}, size=(150, 200)).astype(float)
    b = render_model(plain, {}, size=(150, 200)).astype(float)
    forehead = (slice(40, 60), slice(60, 90))
    assert np.abs(a[forehead] - b[forehead]).mean() > 10


@pytest.mark.slow
def test_the_shipped_image_is_what_the_code_computes():
    computed = skin_texture(load_model(), Identity(), ATLAS_SIZE).pixels
    shipped = skinned_default_head().texture.images[0].pixels
    assert np.abs(computed.astype(int) - shipped).max() <= 1
