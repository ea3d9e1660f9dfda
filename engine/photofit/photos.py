"""Photographs read as the user sees them: JPEG (a camera's MPO too) or PNG, EXIF orientation applied, RGB.

Every file the photo-fit reads goes through :func:`read_input_bytes`: a
folder, a device (``/dev/zero``) or a named pipe is refused before it is
opened, and no more than a bound is ever read (the photographs
:data:`MAX_PHOTO_BYTES`, the landmark file its own bound). A photograph is
then decoded from those bytes, refused above :data:`MAX_PIXELS` pixels,
whatever its format claims, before its pixels are decoded (Pillow's
decompression-bomb warning and error become the same one line). An MPO file
(the JPEG with a second picture, or a depth map, many cameras write) is read
as its first picture, the one every viewer shows.

>>> import numpy as np, tempfile, os
>>> from PIL import Image
>>> path = os.path.join(tempfile.mkdtemp(), "p.png")
>>> Image.fromarray(np.zeros((3, 5, 3), dtype=np.uint8)).save(path)
>>> read_photo(path).shape
(3, 5, 3)
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.formats.pictures import decode_picture
from engine.formats.text_files import read_bounded_bytes
from engine.photofit.errors import PhotoFitError

FORMATS = ("JPEG", "PNG", "MPO")
MAX_PIXELS = 80_000_000
"""The largest photograph (80 megapixels, above any portrait camera's; the fit itself works at 600 px)."""
MAX_PHOTO_BYTES = 256 << 20
"""The largest photograph file read (256 MiB: an 80-megapixel JPEG is 20–60 MB, a PNG of it up to 240 MB)."""


def read_input_bytes(path: str | Path, limit: int, what: str) -> bytes:
    """The bytes of the regular file ``path`` (at most ``limit``), or one :class:`PhotoFitError` naming it.

    A folder, device or pipe is refused before it is opened, so a FIFO with no
    writer cannot block and ``/dev/zero`` is not read.
    """
    try:
        return read_bounded_bytes(path, limit, PhotoFitError, what)
    except PhotoFitError as exc:
        if exc.message.startswith("cannot read"):
            raise
        raise PhotoFitError(f"cannot read the {what}: {exc.message}", file=path) from None


def read_photo(path: str | Path) -> np.ndarray:
    """(height, width, 3) uint8 RGB of the photograph ``path``, turned upright by its EXIF orientation."""
    data = read_input_bytes(path, MAX_PHOTO_BYTES, "photograph")
    return decode_picture(data, path, MAX_PIXELS, PhotoFitError, FORMATS)
