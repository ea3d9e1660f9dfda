"""Texture images in and out of mesh files: decoding a material's image, and a mesh's texture as a model's.

:func:`decode_image` reads PNG or JPEG bytes (Pillow) into RGB(A) uint8
pixels, refusing images larger than :data:`engine.model.texture.MAX_IMAGE_SIDE`
per side before decoding them; :func:`model_texture` turns the texture a mesh
reader found (:class:`~engine.formats.mesh_data.MeshTexture`: corner
coordinates, materials and their image files, or images embedded in a glTF)
into a :class:`~engine.model.texture.ModelTexture` with the pixels loaded;
:func:`png_bytes` encodes pixels as PNG for OBJ and glTF export.

>>> import numpy as np
>>> pixels = np.zeros((2, 3, 3), dtype=np.uint8); pixels[0, 0] = (255, 0, 0)
>>> decode_image(png_bytes(pixels), "x.png").tolist()[0][0]
[255, 0, 0]
"""

from __future__ import annotations

import base64
import io
import json
import struct
import warnings
from pathlib import Path
from typing import NoReturn

import numpy as np

from engine.errors import MeshImportError, UserError
from engine.formats.gltf_document import GLB_MAGIC, GltfFileError, load_buffer, split_glb
from engine.formats.mesh_data import ImportedMesh
from engine.model.cells import cell_sizes
from engine.model.texture import MAX_IMAGE_SIDE, ModelTexture, TextureImage, unique_image_names

_EMBEDDED = "embedded:"


def decode_image(data: bytes, source: str | Path, error: type[UserError] = MeshImportError) -> np.ndarray:
    """PNG/JPEG (or any format Pillow reads) ``data`` as (height, width, 3|4) uint8, row 0 at the top.

    Grey and palette images become RGB (RGBA if they have transparency).
    ``error`` naming ``source`` for anything that is not a readable image
    or is larger than :data:`~engine.model.texture.MAX_IMAGE_SIDE` per side.
    """
    from PIL import Image, ImageOps

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", Image.DecompressionBombWarning)
            with Image.open(io.BytesIO(data)) as opened:
                width, height = opened.size
                if not (0 < width <= MAX_IMAGE_SIDE and 0 < height <= MAX_IMAGE_SIDE):
                    raise error(f"the image is {width}×{height} pixels; each side must be 1..{MAX_IMAGE_SIDE}",
                                file=source)
                image = ImageOps.exif_transpose(opened) or opened
                has_alpha = image.mode in ("RGBA", "LA", "PA") or "transparency" in image.info
                converted = image.convert("RGBA" if has_alpha else "RGB")
                pixels = np.asarray(converted, dtype=np.uint8)
    except UserError:
        raise
    except Exception as exc:      # Pillow raises many kinds (OSError, ValueError, SyntaxError, bombs, …)
        raise error(f"not a readable image ({type(exc).__name__}: {str(exc)[:160]})", file=source) from None
    return np.ascontiguousarray(pixels)


def png_bytes(pixels: np.ndarray) -> bytes:
    """(height, width, 3|4) uint8 pixels as a PNG file's bytes."""
    from PIL import Image

    out = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(pixels, dtype=np.uint8)).save(out, format="PNG", compress_level=6)
    return out.getvalue()


def model_texture(mesh: ImportedMesh, source: Path) -> tuple[ModelTexture | None, list[str]]:
    """The texture of an imported mesh as a model keeps it, and notes for the user.

    Polygons with a corner the file gives no coordinates, or whose material
    has no image that can be read, show no image (they are drawn in their
    part's colour); an image that cannot be read is named in a note. A mesh
    without texture coordinates gives ``None``.
    """
    texture = mesh.texture
    if texture is None or not texture.has_coordinates:
        return None, []
    notes: list[str] = []
    counts = cell_sizes(mesh.faces)
    corner_uv = np.asarray(texture.corner_uv, dtype=float)
    missing = np.logical_or.reduceat(~np.isfinite(corner_uv).all(axis=1), np.r_[0, np.cumsum(counts)[:-1]]) \
        if len(counts) else np.zeros(0, dtype=bool)
    corner_uv = np.where(np.isfinite(corner_uv), corner_uv, 0.0)
    embedded = _embedded_gltf_images(source) if any(
        (m.image or "").startswith(_EMBEDDED) for m in texture.materials) else {}
    sources = texture.images()
    names = unique_image_names([Path(s).name if not s.startswith(_EMBEDDED) else "embedded" for s in sources])
    images: list[TextureImage] = []
    slot: dict[str, int] = {}
    for image_source, name in zip(sources, names, strict=True):
        try:
            if image_source.startswith(_EMBEDDED):
                owner = next(m.name for m in texture.materials if m.image == image_source)
                if owner not in embedded:
                    raise MeshImportError("the embedded image cannot be found", file=source)
                pixels = decode_image(embedded[owner], source)
            else:
                pixels = decode_image(_read_bytes(Path(image_source)), image_source)
        except UserError as exc:
            notes.append(f"image '{image_source}' left out: {exc.message}")
            continue
        slot[image_source] = len(images)
        images.append(TextureImage(name, pixels))
    material_image = np.array([slot.get(m.image or "", -1) for m in texture.materials] + [-1], dtype=np.int64)
    face_material = np.asarray(texture.face_material, dtype=np.int64)
    if len(face_material) != len(counts):
        face_material = np.full(len(counts), -1, dtype=np.int64)
    face_image = material_image[np.where(face_material >= 0, face_material, -1)]
    face_image[missing] = -1
    return ModelTexture(corner_uv, images, face_image), notes


def _read_bytes(path: Path) -> bytes:
    if not path.is_file():
        raise MeshImportError("the image file is missing", file=path)
    size = path.stat().st_size
    if size > 512 * 1024 * 1024:
        raise MeshImportError(f"the image file is {size:,} bytes, too large for a texture", file=path)
    try:
        return path.read_bytes()
    except OSError as exc:
        raise MeshImportError(f"cannot read: {exc.strerror or exc}", file=path) from None


def _embedded_gltf_images(path: Path) -> dict[str, bytes]:
    """Material name → the bytes of its base-colour image, for images inside a glTF (data URIs or
    buffer views); materials named as :mod:`engine.formats.mesh_gltf` names them."""
    def fail(what: str) -> NoReturn:
        raise MeshImportError(what, file=path)

    try:
        blob = path.read_bytes()
        if blob[:4] == struct.pack("<I", GLB_MAGIC):
            document, embedded = split_glb(blob, path, strict=False)
        else:
            document, embedded = json.loads(blob.decode("utf-8")), {}
        out: dict[str, bytes] = {}
        for index, spec in enumerate(document.get("materials", [])):
            name = str(spec.get("name") or f"material_{index}")
            texture = spec.get("pbrMetallicRoughness", {}).get("baseColorTexture")
            if texture is None:
                continue
            source = document["textures"][int(texture["index"])].get("source")
            if source is None:
                continue
            image = document["images"][int(source)]
            uri = image.get("uri")
            if isinstance(uri, str) and uri.startswith("data:"):
                out[name] = base64.b64decode(uri.partition(",")[2], validate=True)
            elif uri is None:
                view = document["bufferViews"][int(image["bufferView"])]
                data = load_buffer(path, int(view["buffer"]), document["buffers"][int(view["buffer"])],
                                   embedded, fail)
                start = int(view.get("byteOffset", 0))
                length = int(view["byteLength"])
                if start < 0 or length < 0 or start + length > len(data):
                    continue
                out[name] = bytes(data[start:start + length])
        return out
    except (GltfFileError, MeshImportError):
        return {}
    except (OSError, KeyError, IndexError, TypeError, ValueError, AttributeError, RecursionError):
        return {}
