"""A model's texture: coordinates for every polygon corner, the images, and which image each polygon shows.

Texture coordinates are kept **per polygon corner**, one (u, v) pair for each
vertex index in the model's flat cell array ``faces`` and in the same order,
because the MakeHuman base mesh (and most scanned or authored meshes) give a
vertex different coordinates on either side of a texture seam while the model
keeps one vertex there (so that the deformation of §2.2 moves it once). (u, v)
follow OBJ's convention: u from the image's left edge, v from its **bottom**
edge, both 0..1 (values outside repeat the image).

``face_image`` names, for every polygon, the image it shows (an index into
``images``) or −1 for a polygon drawn in its part's colour; a part may show
several images on different polygons.

>>> import numpy as np
>>> checker = TextureImage("checker", np.zeros((4, 4, 3), dtype=np.uint8))
>>> texture = ModelTexture(np.array([[0, 0], [1, 0], [0, 1.0]]), [checker], np.array([0]))
>>> texture.check(np.array([3, 0, 1, 2]))
>>> texture.images[0].channels, texture.textured_faces().tolist()
(3, [True])
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.cells import cell_sizes

IMAGE_NAME_PATTERN = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.\-]{0,127}")
MAX_IMAGE_SIDE = 16384


@dataclass
class TextureImage:
    """One image: a name (letters, digits, ``_ . -``; used for the file it is written to) and
    its pixels, (height, width, 3) RGB or (height, width, 4) RGBA uint8 (sRGB), row 0 at the top."""

    name: str
    pixels: np.ndarray

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not IMAGE_NAME_PATTERN.fullmatch(self.name):
            raise UserError(f"texture image name {self.name!r} is not allowed: use up to 128 letters, digits, "
                            "'_', '.' and '-', not starting with '.' or '-'")
        pixels = np.asarray(self.pixels)
        if pixels.dtype != np.uint8 or pixels.ndim != 3 or pixels.shape[2] not in (3, 4):
            raise UserError(f"texture image '{self.name}' must be (height, width, 3 or 4) 8-bit pixels, "
                            f"not {pixels.dtype} of shape {pixels.shape}")
        height, width = pixels.shape[:2]
        if not (0 < height <= MAX_IMAGE_SIDE and 0 < width <= MAX_IMAGE_SIDE):
            raise UserError(f"texture image '{self.name}' is {width}×{height} pixels; each side must be "
                            f"1..{MAX_IMAGE_SIDE}")
        self.pixels = np.ascontiguousarray(pixels)

    @property
    def channels(self) -> int:
        return int(self.pixels.shape[2])

    def copy(self) -> TextureImage:
        return TextureImage(self.name, self.pixels.copy())


@dataclass
class ModelTexture:
    """Texture coordinates (K, 2) of every polygon corner, the images, and each polygon's image (F,)."""

    corner_uv: np.ndarray
    images: list[TextureImage] = field(default_factory=list)
    face_image: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    def __post_init__(self) -> None:
        self.corner_uv = np.ascontiguousarray(np.asarray(self.corner_uv, dtype=float).reshape(-1, 2))
        self.face_image = np.asarray(self.face_image, dtype=np.int64).reshape(-1)
        self.images = list(self.images)

    def check(self, faces: npt.ArrayLike) -> None:
        """Raise :class:`UserError` unless this texture fits the flat cell array ``faces``."""
        faces = np.asarray(faces, dtype=np.int64).reshape(-1)
        counts = cell_sizes(faces)
        corners = int(counts.sum())
        if self.corner_uv.shape != (corners, 2):
            raise UserError(f"texture coordinates: {len(self.corner_uv)} pairs for {corners} polygon corners")
        if not np.all(np.isfinite(self.corner_uv)):
            raise UserError("texture coordinates must be finite numbers")
        if len(self.face_image) != len(counts):
            raise UserError(f"texture: {len(self.face_image)} polygon images for {len(counts)} polygons")
        if len(self.face_image) and (self.face_image.min() < -1 or self.face_image.max() >= len(self.images)):
            raise UserError(f"texture: a polygon names image {int(self.face_image.max())} but there are "
                            f"{len(self.images)} images (−1 means none)")
        names = [image.name for image in self.images]
        if len(set(names)) != len(names):
            raise UserError("texture image names must be unique")

    def textured_faces(self) -> np.ndarray:
        """(F,) bool: the polygons that show an image."""
        return self.face_image >= 0

    def copy(self) -> ModelTexture:
        return ModelTexture(self.corner_uv.copy(), [image.copy() for image in self.images], self.face_image.copy())

    def image_named(self, name: str) -> TextureImage:
        for image in self.images:
            if image.name == name:
                return image
        raise UserError(f"no texture image named '{name}' (images: {', '.join(i.name for i in self.images)})")


def unique_image_names(names: Sequence[str]) -> list[str]:
    """``names`` made valid as texture image names and unique (``skin.png`` → ``skin``).

    >>> unique_image_names(["skin.png", "skin.jpg", "../eye map.PNG", ""])
    ['skin', 'skin_2', 'eye_map', 'image']
    """
    out: list[str] = []
    for raw in names:
        stem = re.sub(r"\.[A-Za-z0-9]{1,5}$", "", raw.replace("\\", "/").rsplit("/", 1)[-1])
        name = re.sub(r"[^A-Za-z0-9_.\-]", "_", stem).lstrip(".-")[:120] or "image"
        base, k = name, 2
        while name in out:
            name, k = f"{base}_{k}", k + 1
        out.append(name)
    return out
