"""The default head's skin, shipped precomputed, and how the shipped head is given it.

The shipped head (``engine/data/default-head/head.xml``) is the default
identity's head, and it shows the skin every identity gets (issue 32 item 1;
:mod:`engine.identity.skin`): worked out once by
``engine/data/default-head/default_skin.py`` into ``skin.png`` beside it (the
image carries the key of what it was computed from,
:mod:`engine.identity.skin_cache`; ``tests/engine/test_skin_default_head.py``
checks it is current). :func:`put_on_shipped_skin` gives a head loaded from
the shipped file that image: a PNG read (about 0.07 s) instead of seconds of
synthesis; any other model file is left as saved (a saved copy of the default
head holds its image in its own arrays). It is not yet called by
``load_model()``: with the skin on, the emotion classifier reads the default
head's closed-lip Happy as neutral (docs/skin.md "The default head").
``make_identity_head(Identity())`` takes the image through the skin cache.

>>> from engine import load_model
>>> head = load_model()
>>> put_on_shipped_skin(head, default_model_path())
>>> [image.name for image in head.texture.images]
['skin']
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np

from engine.errors import ModelFileError
from engine.formats.texture_images import decode_image
from engine.model import Model
from engine.model.cells import cell_sizes, cell_starts
from engine.model.texture import ModelTexture, TextureImage
from engine.paths import DEFAULT_HEAD_DIR, default_model_path

SKIN_FILE = DEFAULT_HEAD_DIR / "skin.png"
SKIN_IMAGE = "skin"
#: The parts the skin image is drawn on.
IMAGE_PARTS = ("skin",)


def skin_polygons(model: Model) -> np.ndarray:
    """The polygons that show a skin image: those of :data:`IMAGE_PARTS` with every corner's (u, v) inside it."""
    assert model.texture is not None, "the head must have texture coordinates"
    counts = cell_sizes(model.faces)
    starts = cell_starts(counts)
    skin = np.isin(model.vertex_part[model.faces[starts + 1]],
                   [model.parts.index(p) for p in IMAGE_PARTS if p in model.parts])
    uv = model.texture.corner_uv
    outside = np.any((uv < 0) | (uv > 1), axis=1)
    bad = np.zeros(len(counts), dtype=bool)
    bad[np.repeat(np.arange(len(counts)), counts)[outside]] = True
    return np.flatnonzero(skin & ~bad & (counts >= 3))


@cache
def _shipped_pixels(stamp: tuple[int, int]) -> np.ndarray:
    del stamp                                     # the file's (mtime, size): a new file is read again
    pixels = decode_image(SKIN_FILE.read_bytes(), SKIN_FILE, ModelFileError)
    pixels.setflags(write=False)
    return pixels


def put_on_shipped_skin(model: Model, path: Path) -> None:
    """Give ``model``, loaded from ``path``, the shipped skin if it is the shipped default head without images."""
    if path.resolve() != default_model_path().resolve() or not SKIN_FILE.is_file():
        return
    texture = model.texture
    if texture is None or texture.images or "skin" not in model.parts:
        return
    status = SKIN_FILE.stat()
    pixels = _shipped_pixels((status.st_mtime_ns, status.st_size))
    face_image = np.full(len(texture.face_image), -1, dtype=np.int64)
    face_image[skin_polygons(model)] = 0
    model.texture = ModelTexture(texture.corner_uv, [TextureImage(SKIN_IMAGE, pixels.copy())], face_image)
