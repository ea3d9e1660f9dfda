"""Writing pictures as PNG files, with no imaging library: an (H, W, 3) uint8 RGB array → an 8-bit PNG.

>>> import tempfile, numpy as np
>>> from pathlib import Path
>>> with tempfile.TemporaryDirectory() as folder:
...     path = write_png(Path(folder) / "black.png", np.zeros((2, 3, 3), dtype=np.uint8))
...     path.read_bytes()[1:4]
b'PNG'
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np


def write_png(path: str | Path, image: np.ndarray) -> Path:
    """Write an (H, W, 3) uint8 RGB array as an 8-bit PNG, atomically."""
    from engine.formats.atomic import atomic_write_bytes

    path = Path(path)
    atomic_write_bytes(path, png_bytes(image))
    return path


def png_bytes(image: np.ndarray) -> bytes:
    """An (H, W, 3) uint8 RGB array as the bytes of an 8-bit PNG file."""
    image = np.ascontiguousarray(image, dtype=np.uint8)
    if image.ndim != 3 or image.shape[2] != 3:
        raise ValueError(f"expected an (H, W, 3) image, got shape {image.shape}")
    h, w = image.shape[:2]
    raw = np.concatenate([np.zeros((h, 1), dtype=np.uint8), image.reshape(h, w * 3)], axis=1).tobytes()

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
