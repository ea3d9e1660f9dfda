"""Pictures a user hands us (photographs, renders, frames), read with bounds and turned upright.

:func:`read_picture` reads any still picture Pillow knows (PNG, JPEG, a camera's MPO — its
first picture —, TIFF, BMP, WebP, GIF's first frame …) as (height, width, 3) uint8 RGB, with
the EXIF orientation applied. It refuses, with a :class:`~engine.errors.UserError` (or the
subclass the caller names) naming the file:

* what is not a regular file (a folder, a device, a pipe: checked before opening, so a pipe
  cannot block) or is larger than ``max_bytes``;
* a picture of more than ``max_pixels`` pixels, before its pixels are decoded (a 30 000 × 30 000
  PNG of a few kB would need 2.7 GB);
* what is not a picture, or a picture cut short.

>>> import numpy as np, tempfile, os
>>> from PIL import Image
>>> path = os.path.join(tempfile.mkdtemp(), "p.png")
>>> Image.fromarray(np.zeros((3, 5, 3), dtype=np.uint8)).save(path)
>>> read_picture(path).shape
(3, 5, 3)
>>> read_picture("/dev/zero")
Traceback (most recent call last):
engine.errors.UserError: /dev/zero: not a regular file (a device, folder or pipe cannot be read as input)
"""

from __future__ import annotations

import io
import re
import struct
import warnings
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.formats.text_files import read_bounded_bytes

MAX_PICTURE_BYTES = 500_000_000
"""The largest picture file read (500 MB): a 100-megapixel camera's raw TIFF is about 300 MB."""
MAX_PICTURE_PIXELS = 100_000_000
"""The largest picture decoded (100 megapixels, 300 MB of RGB)."""


def read_picture(path: str | Path, max_pixels: int = MAX_PICTURE_PIXELS, max_bytes: int = MAX_PICTURE_BYTES,
                 error: type[UserError] = UserError, formats: tuple[str, ...] | None = None) -> np.ndarray:
    """(height, width, 3) uint8 RGB of the picture in ``path``, upright by its EXIF orientation.

    ``formats`` limits the Pillow formats taken (``("JPEG", "PNG", "MPO")``); None takes any."""
    data = read_bounded_bytes(path, limit=max_bytes, error=error, what="picture")
    return decode_picture(data, path, max_pixels, error, formats)


def decode_picture(data: bytes, source: str | Path, max_pixels: int = MAX_PICTURE_PIXELS,
                   error: type[UserError] = UserError, formats: tuple[str, ...] | None = None) -> np.ndarray:
    """:func:`read_picture` of bytes already read (``source`` names them in messages)."""
    from PIL import Image, ImageOps, UnidentifiedImageError

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            with Image.open(io.BytesIO(data)) as image:
                if formats is not None and image.format not in formats:
                    shown = " or ".join(f for f in formats if f != "MPO")      # an MPO is a camera's JPEG
                    raise error(f"a {image.format} picture; use a {shown} picture", file=source)
                width, height = image.size
                if width * height > max_pixels:
                    raise error(f"{width} × {height} pixels is more than the {max_pixels:,} pixels read",
                                file=source)
                if getattr(image, "n_frames", 1) > 1:
                    image.seek(0)                  # an MPO's or a GIF's first picture
                upright = ImageOps.exif_transpose(image)
                pixels = np.asarray(upright.convert("RGB"), dtype=np.uint8)
    except UnidentifiedImageError:
        raise error("not a picture Pillow can read", file=source) from None
    except (Image.DecompressionBombWarning, Image.DecompressionBombError) as exc:
        raise error(too_many_pixels(exc, max_pixels), file=source) from None
    except (OSError, SyntaxError, ValueError, EOFError, struct.error) as exc:
        raise error(f"cannot read the picture: {getattr(exc, 'strerror', None) or exc}", file=source) from None
    return np.ascontiguousarray(pixels)



def too_many_pixels(exc: Exception, max_pixels: int) -> str:
    """The message for Pillow's decompression-bomb refusal, with the size it names where it names one."""
    found = re.search(r"\((\d+) pixels\)", str(exc))
    size = f"{int(found.group(1)):,} pixels" if found else "the picture"
    return f"{size} is more than the {max_pixels:,} pixels read"
