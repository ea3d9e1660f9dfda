"""Synthesised skin images kept on disk, keyed by everything they are computed from (issue 32 item 1).

Working out a person's skin (:mod:`engine.identity.skin`) takes seconds: the
atlas is drawn, the spectra integrated, the detail placed. The image depends
only on the head's geometry and texture coordinates, its feature points and
vertex colours, the identity's values, the image's size and the skin code
itself, so :func:`skin_key` hashes exactly those (the code by the bytes of
its four modules, so any change to a constant or a formula makes a new key)
and :func:`cached_skin_pixels` keeps each image as a PNG named by its key in
the user's cache folder:

* ``$ARTIFICIAL_PERSON_CACHE`` if set (``off`` keeps nothing), else
  ``$XDG_CACHE_HOME/artificial-person``, else ``~/.cache/artificial-person``;
  the images go in its ``skin/`` folder;
* written atomically (a temporary file renamed), each PNG carrying its key in
  a text chunk: a file that is damaged, foreign or of another key is ignored
  and worked out again, and a folder that cannot be written only costs time;
* the folder is kept under :data:`CACHE_LIMIT_BYTES` (the oldest images go first);
* the default head's own skin ships precomputed (``engine/data/default-head/skin.png``,
  made by ``default_skin.py`` beside it) and is taken from there while its key is current.

>>> import numpy as np, os, tempfile
>>> before = os.environ.get("ARTIFICIAL_PERSON_CACHE")
>>> os.environ["ARTIFICIAL_PERSON_CACHE"] = tempfile.mkdtemp()
>>> made = cached_skin_pixels("0" * 64, lambda: np.full((4, 4, 3), 7, dtype=np.uint8))
>>> again = cached_skin_pixels("0" * 64, lambda: np.zeros((4, 4, 3), dtype=np.uint8))
>>> int(again[0, 0, 0])                                  # the kept image, not computed again
7
>>> if before is None: del os.environ["ARTIFICIAL_PERSON_CACHE"]
... else: os.environ["ARTIFICIAL_PERSON_CACHE"] = before
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
from collections.abc import Callable
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.formats.atomic import atomic_write_bytes
from engine.identity.parameters import Identity
from engine.model import Model
from engine.paths import DEFAULT_HEAD_DIR

CACHE_ENV = "ARTIFICIAL_PERSON_CACHE"
FORMAT = "artificial-person-skin 1"
KEY_CHUNK = "artificial-person-skin-key"
CACHE_LIMIT_BYTES = 512 * 1024 * 1024
SHIPPED_SKIN = DEFAULT_HEAD_DIR / "skin.png"
#: The modules whose code the image is computed by: their bytes are part of every key.
SKIN_MODULES = ("skin.py", "skin_optics.py", "skin_detail.py", "skin_atlas.py")


def cache_folder() -> Path | None:
    """Where skin images are kept, or None if the user switched the cache off (``ARTIFICIAL_PERSON_CACHE=off``)."""
    chosen = os.environ.get(CACHE_ENV)
    if chosen:
        return None if chosen.strip().lower() == "off" else Path(chosen) / "skin"
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "artificial-person" / "skin"


def _code_digest() -> bytes:
    here = Path(__file__).parent
    digest = hashlib.sha256()
    for name in SKIN_MODULES:
        digest.update(name.encode() + b"\0" + (here / name).read_bytes())
    return digest.digest()


def skin_key(model: Model, identity: Identity, size: int) -> str:
    """The hex key of ``identity``'s skin image of ``size`` on ``model`` (see the module's docstring)."""
    assert model.texture is not None
    digest = hashlib.sha256(FORMAT.encode())
    digest.update(_code_digest())
    digest.update(repr((size, list(model.parts), model.part_colors.get("skin"),
                        sorted((k, int(v)) for k, v in model.landmarks.items()),
                        sorted((k, repr(float(v))) for k, v in identity.values.items()))).encode())
    arrays: tuple[np.ndarray | None, ...] = (model.vertices, model.faces, model.vertex_part,
                                             model.texture.corner_uv, model.vertex_colors)
    for array in arrays:
        digest.update(b"-" if array is None else np.ascontiguousarray(array).tobytes())
    return digest.hexdigest()


def read_skin_png(path: Path, key: str) -> np.ndarray | None:
    """The (size, size, 3) pixels of the skin PNG at ``path`` if it is one and carries ``key``, else None."""
    from PIL import Image

    try:
        data = path.read_bytes()
        with Image.open(io.BytesIO(data)) as image:
            if image.format != "PNG" or image.info.get(KEY_CHUNK) != key or image.mode != "RGB":
                return None
            pixels = np.asarray(image, dtype=np.uint8)
    except (OSError, ValueError, SyntaxError):      # missing, damaged, not an image
        return None
    if pixels.ndim != 3 or pixels.shape[2] != 3 or pixels.shape[0] != pixels.shape[1]:
        return None
    return np.ascontiguousarray(pixels)


def skin_png_bytes(pixels: np.ndarray, key: str, level: int = 6) -> bytes:
    """``pixels`` as a PNG carrying ``key`` in its text chunk."""
    from PIL import Image
    from PIL.PngImagePlugin import PngInfo

    info = PngInfo()
    info.add_text(KEY_CHUNK, key)
    out = io.BytesIO()
    Image.fromarray(pixels, "RGB").save(out, "PNG", pnginfo=info, compress_level=level)
    return out.getvalue()


def _write(folder: Path, key: str, pixels: np.ndarray) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
        atomic_write_bytes(folder / f"{key}.png", skin_png_bytes(pixels, key, level=4))   # the engine's one way
        _prune(folder)
    except (OSError, UserError):        # a read-only or full disk: the image is only not kept
        return


def _prune(folder: Path) -> None:
    entries = [(e.stat().st_mtime, e.stat().st_size, e.path) for e in os.scandir(folder)
               if e.name.endswith(".png") and e.is_file()]
    total = sum(size for _, size, _ in entries)
    for _, size, path in sorted(entries):
        if total <= CACHE_LIMIT_BYTES:
            break
        with contextlib.suppress(OSError):
            os.unlink(path)
        total -= size


def cached_skin_pixels(key: str, compute: Callable[[], np.ndarray]) -> np.ndarray:
    """The skin image of ``key``: from the cache folder or the shipped default skin if kept, else
    ``compute()``d and kept."""
    folder = cache_folder()
    if folder is not None:
        kept = read_skin_png(folder / f"{key}.png", key)
        if kept is not None:
            return kept
    shipped = read_skin_png(SHIPPED_SKIN, key)
    if shipped is not None:
        return shipped
    pixels = np.ascontiguousarray(compute(), dtype=np.uint8)
    if folder is not None:
        _write(folder, key, pixels)
    return pixels
