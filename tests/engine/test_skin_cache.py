"""The disk cache of synthesised skin images (engine/identity/skin_cache.py, docs/skin.md): keyed by what the
image is computed from, read back instead of computed, a damaged or foreign file ignored, never a crash."""

from __future__ import annotations

import numpy as np
import pytest

from engine import load_model
from engine.identity import Identity, make_identity_head
from engine.identity.skin import apply_skin, skin_texture
from engine.identity.skin_atlas import skin_atlas, skin_faces
from engine.identity.skin_cache import CACHE_ENV, cache_folder, read_skin_png, skin_key, skin_png_bytes

SIZE = 256
OLD_MAN = Identity({"sex": 1.0, "age": 70.0})


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    return tmp_path / "skin"


def _skinned(identity=OLD_MAN):
    head = load_model()
    apply_skin(head, identity, SIZE)
    assert head.texture is not None
    return head, head.texture.images[0].pixels


def test_the_cache_folder_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.delenv(CACHE_ENV, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache_folder() == tmp_path / "xdg" / "artificial-person" / "skin"
    monkeypatch.setenv(CACHE_ENV, str(tmp_path / "mine"))
    assert cache_folder() == tmp_path / "mine" / "skin"
    monkeypatch.setenv(CACHE_ENV, "off")
    assert cache_folder() is None


def test_an_image_is_kept_under_its_key_and_read_back(cache):
    _, first = _skinned()
    key = skin_key(load_model(), OLD_MAN, SIZE)
    files = list(cache.iterdir())
    assert [f.name for f in files] == [f"{key}.png"]
    fresh = skin_texture(load_model(), OLD_MAN, SIZE).pixels
    assert np.array_equal(first, fresh)
    # the kept file is what the next head shows: replace it by a marked image with the same key
    marked = fresh.copy()
    marked[:8, :8] = (255, 0, 255)
    files[0].write_bytes(skin_png_bytes(marked, key))
    _, second = _skinned()
    assert np.array_equal(second, marked)


def test_a_damaged_or_foreign_file_is_worked_out_again(cache):
    key = skin_key(load_model(), OLD_MAN, SIZE)
    fresh = skin_texture(load_model(), OLD_MAN, SIZE).pixels
    cache.mkdir(parents=True)
    path = cache / f"{key}.png"
    for bad in (b"not a png at all", skin_png_bytes(np.zeros_like(fresh), "another key"),
                skin_png_bytes(fresh, key)[:500]):
        path.write_bytes(bad)
        assert read_skin_png(path, key) is None
        _, shown = _skinned()
        assert np.array_equal(shown, fresh)
        again = read_skin_png(path, key)             # and written again, whole
        assert again is not None and np.array_equal(again, fresh)


def test_the_key_changes_with_what_the_image_is_made_of():
    head = load_model()
    key = skin_key(head, OLD_MAN, SIZE)
    assert key == skin_key(load_model(), Identity({"sex": 1.0, "age": 70.0}), SIZE)
    assert key != skin_key(head, Identity({"sex": 1.0, "age": 71.0}), SIZE)
    assert key != skin_key(head, OLD_MAN, SIZE * 2)
    moved = load_model()
    moved.vertices = moved.vertices + np.array([0.0, 0.01, 0.0])
    assert key != skin_key(moved, OLD_MAN, SIZE)


def test_a_cache_that_cannot_be_written_costs_only_time(tmp_path, monkeypatch):
    blocked = tmp_path / "a file, not a folder"
    blocked.write_text("x")
    monkeypatch.setenv(CACHE_ENV, str(blocked))          # its skin/ folder can never be made
    _, shown = _skinned()
    assert np.array_equal(shown, skin_texture(load_model(), OLD_MAN, SIZE).pixels)
    assert blocked.read_text() == "x"


def test_off_keeps_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv(CACHE_ENV, "off")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    _skinned()
    assert list(tmp_path.iterdir()) == []


def test_the_image_shows_on_the_polygons_the_atlas_draws():
    head = load_model()
    assert np.array_equal(skin_faces(head), skin_atlas(head, SIZE).skin_faces)


def test_an_identity_head_takes_its_skin_from_the_cache(cache):
    first = make_identity_head(OLD_MAN)
    assert len(list(cache.iterdir())) == 1
    second = make_identity_head(OLD_MAN)
    assert first.texture is not None and second.texture is not None
    assert np.array_equal(first.texture.images[0].pixels, second.texture.images[0].pixels)
    assert np.array_equal(first.texture.face_image, second.texture.face_image)
