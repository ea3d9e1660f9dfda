"""Photographs read as the user sees them: JPEG or PNG, EXIF orientation applied, RGB.

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

from engine.photofit.errors import PhotoFitError

FORMATS = ("JPEG", "PNG")
MAX_PIXELS = 80_000_000


def read_photo(path: str | Path) -> np.ndarray:
    """(height, width, 3) uint8 RGB of the photograph ``path``, turned upright by its EXIF orientation."""
    from PIL import Image, ImageOps, UnidentifiedImageError

    path = Path(path)
    try:
        with Image.open(path) as image:
            if image.format not in FORMATS:
                raise PhotoFitError(f"a {image.format} picture; use a JPEG or PNG photograph", file=path)
            if image.width * image.height > MAX_PIXELS:
                raise PhotoFitError(f"{image.width}×{image.height} pixels is more than {MAX_PIXELS} pixels",
                                    file=path)
            upright = ImageOps.exif_transpose(image)
            pixels = np.asarray(upright.convert("RGB"), dtype=np.uint8)
    except UnidentifiedImageError:
        raise PhotoFitError("not a picture (use a JPEG or PNG photograph)", file=path) from None
    except (OSError, SyntaxError, ValueError, Image.DecompressionBombError) as exc:
        raise PhotoFitError(f"cannot read the photograph: {getattr(exc, 'strerror', None) or exc}",
                            file=path) from None
    return np.ascontiguousarray(pixels)
