"""The parts of a glTF 2.0 document every reader of ours shares: the GLB container, indices that must
name an element, the files URIs name (never outside the document's folder), buffers and accessors.

:mod:`engine.formats.gltf_read` (our own files read back) and :mod:`engine.formats.mesh_gltf`
(other programs' meshes) both read through these, so a check made here holds for both: every index
a whole number inside its array (a negative one never wraps to the last element), every URI
percent-decoded and resolved before it is opened, every accessor inside its buffer before a byte of
it is read.

>>> def fail(what):
...     raise ValueError(what)
>>> index_of(-1, "accessors", 3, "mesh 0", fail)
Traceback (most recent call last):
ValueError: mesh 0 names accessor -1, which does not exist (the file has 3)
"""

from __future__ import annotations

import base64
import json
import os
import re
import struct
import urllib.parse
from collections.abc import Callable
from pathlib import Path
from typing import NoReturn

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.formats.file_beside import FileOutside, file_beside

GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
COMPONENTS = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


class GltfFileError(UserError):
    """A glTF file is malformed, or is not one this module can read."""


def quaternion_matrix(q: npt.ArrayLike) -> np.ndarray:
    """Rotation matrix of a unit quaternion (x, y, z, w); any length but zero (scaled first, so that
    a quaternion of huge or tiny numbers neither overflows nor underflows its length)."""
    scaled = np.asarray(q, dtype=float) / np.max(np.abs(np.asarray(q, dtype=float)))
    x, y, z, w = scaled / np.linalg.norm(scaled)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def split_glb(blob: bytes, path: Path, strict: bool = True) -> tuple[dict, dict[int, bytes]]:
    """The JSON document and the binary chunk of a GLB. ``strict=False`` (importing other programs'
    files) accepts chunks not padded to 4 bytes and a header length that disagrees with the file,
    as other readers do; every chunk must still lie inside the file."""
    def fail(what: str) -> NoReturn:
        raise GltfFileError(f"not a valid binary glTF: {what}", file=path)

    if len(blob) < 20:
        fail("shorter than its header")
    magic, version, length = struct.unpack_from("<III", blob)
    if magic != GLB_MAGIC or version != 2:
        fail(f"magic {magic:#x}, container version {version} (expected glTF, 2)")
    if length != len(blob) and (strict or length > len(blob)):
        fail(f"the header says {length} bytes, the file has {len(blob)}")
    chunks: list[tuple[int, bytes]] = []
    offset = 12
    while offset < length:
        if offset + 8 > length:
            fail("a chunk header runs past the end")
        size, kind = struct.unpack_from("<II", blob, offset)
        if (strict and size % 4) or offset + 8 + size > length:
            fail("a chunk is misaligned or runs past the end")
        chunks.append((kind, blob[offset + 8:offset + 8 + size]))
        offset += 8 + size
    if not chunks or chunks[0][0] != GLB_JSON:
        fail("the first chunk is not JSON")
    try:
        document = json.loads(chunks[0][1].decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        fail(f"the JSON chunk does not parse: {exc}")
    binary = {0: chunks[1][1]} if len(chunks) > 1 and chunks[1][0] == GLB_BIN else {}
    return document, binary


LFS_POINTER = b"version https://git-lfs.github.com/spec/v1"
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def whole(value: object, what: str, fail: Callable[[str], NoReturn]) -> int:
    """``value`` as an int if it is a JSON whole number (``3`` or ``3.0``; not ``true``, ``2.5`` or ``"3"``)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or (
            isinstance(value, float) and not value.is_integer()):
        fail(f"{what} must be a whole number, not {json.dumps(value)[:40]}")
    if abs(value) > 2**53:
        fail(f"{what} is {json.dumps(value)[:40]}, too large for any file")
    return int(value)


def index_of(value: object, kind: str, count: int, where: str, fail: Callable[[str], NoReturn]) -> int:
    """``value`` as an index into the document's array ``kind`` of ``count`` elements: a whole number from 0
    to ``count − 1``. A negative index would wrap to the end of a Python list, so it is refused like any
    index past the end."""
    singular = kind.removesuffix("es" if kind == "meshes" else "s")
    index = whole(value, f"{where}: {'an' if singular[0] in 'aeiou' else 'a'} {singular} index", fail)
    if not 0 <= index < count:
        fail(f"{where} names {singular} {index}, which does not exist (the file has {count})")
    return index


def element(doc: dict, kind: str, value: object, where: str, fail: Callable[[str], NoReturn]) -> dict:
    """The element of the document's array ``kind`` (``"accessors"``, ``"nodes"`` …) that ``value`` names,
    checked by :func:`index_of`; it must be a JSON object."""
    items = doc.get(kind, [])
    if not isinstance(items, list):
        fail(f"'{kind}' is not a list")
    item = items[index_of(value, kind, len(items), where, fail)]
    if not isinstance(item, dict):
        fail(f"{kind} {value} is not a JSON object")
    return item


def integers(array: np.ndarray, what: str, fail: Callable[[str], NoReturn]) -> np.ndarray:
    """An accessor's values as int64 indices; values that are not whole numbers within int64 (float data
    holding NaN, 1e30 or 0.5) are refused before the cast, which would make them garbage with a warning."""
    if array.dtype.kind == "f" and not (np.all(np.isfinite(array)) and np.all(np.abs(array) <= 2.0**53)
                                        and np.all(array == np.round(array))):
        fail(f"{what} must be whole numbers")
    return array.astype(np.int64)


def document_file(path: Path, uri: str) -> Path:
    """The file a relative ``uri`` of the glTF document at ``path`` names, percent-decoded and with links
    resolved, which must lie in the document's folder or one inside it: the one check for every file a glTF
    reader opens (buffers, images), so that a downloaded model cannot carry a user's file into a model.

    :class:`GltfFileError` (no file: the caller says whose URI) for another scheme (``http://``, ``file:``),
    an absolute path, a backslash (a separator on Windows only), a NUL, bytes that are not UTF-8, and a name
    that leads out of the folder (``../``, ``%2e%2e%2f``, a link pointing elsewhere)."""
    shown = uri[:200]
    try:
        name = urllib.parse.unquote(uri, errors="strict")
    except UnicodeDecodeError:
        raise GltfFileError(f"'{shown}' is not UTF-8 once percent-decoded") from None
    if _SCHEME.match(name) or Path(name).is_absolute():
        raise GltfFileError(f"'{shown}' is not a file beside the document (only relative file names are read)")
    if "\\" in name or "\0" in name:
        raise GltfFileError(f"'{shown}' holds a {'backslash' if chr(92) in name else 'NUL'}, which a file URI "
                            "does not (write '/' between folders)")
    try:
        return file_beside(path, name)
    except FileOutside:
        raise GltfFileError(f"'{shown}' leaves the document's folder (only files in {path.parent}, or in folders "
                            "inside it, are read)") from None


def load_buffer(path: Path, i: int, spec: dict, embedded: dict[int, bytes], fail: Callable[[str], NoReturn]) -> bytes:
    """Buffer ``i`` of the document at ``path``: the GLB's binary chunk, data handed in (a file
    being checked before it is written), a ``data:`` URI or a file beside the document. A
    missing file or a Git LFS pointer in its place is said so plainly."""
    uri, length = spec.get("uri"), whole(spec["byteLength"], f"buffer {i}: byteLength", fail)
    if length < 0:
        fail(f"buffer {i}: byteLength {length} is negative")
    if i in embedded:
        data, slack = embedded[i], 3 if uri is None else 0     # the BIN chunk is padded to 4 bytes
    elif uri is None:
        fail(f"buffer {i} has no uri and there is no binary chunk")
    elif not isinstance(uri, str):
        fail(f"buffer {i}: its uri is not a string")
    elif uri.startswith("data:"):
        try:
            data, slack = base64.b64decode(uri.partition(",")[2], validate=True), 0
        except ValueError:
            fail(f"buffer {i}: its data: URI is not valid base64")
    else:
        data, slack = _buffer_file(path, i, uri, length, fail), 0
    if not length <= len(data) <= length + slack:
        fail(f"buffer {i}: byteLength {length} but its data hold {len(data)} bytes")
    return data[:length]


def _buffer_file(path: Path, i: int, uri: str, length: int, fail: Callable[[str], NoReturn]) -> bytes:
    """The bytes of buffer ``i``'s file (:func:`document_file`), read only when it has the length the
    document gives (a Git LFS pointer named as such)."""
    try:
        target = document_file(path, uri)
    except GltfFileError as exc:
        fail(f"buffer {i}: {exc.message}")
    name = urllib.parse.unquote(uri)
    if not target.is_file():
        fail(f"buffer {i}: cannot read '{name}': the file is missing (it belongs beside {path.name})")
    try:
        with target.open("rb") as stream:
            size = os.fstat(stream.fileno()).st_size
            if stream.read(len(LFS_POINTER)) == LFS_POINTER:
                fail(f"buffer {i}: '{name}' is a Git LFS pointer, not the data (fetch it with 'git lfs pull')")
            if size != length:
                fail(f"buffer {i}: byteLength {length} but its data hold {size} bytes")
            stream.seek(0)
            return stream.read(length + 1)
    except OSError as exc:
        fail(f"buffer {i}: cannot read '{name}': {exc.strerror or exc}")


def decode_accessor(doc: dict, buffer: Callable[[int], bytes], index: int, fail: Callable[[str], NoReturn],
                    check_bounds: bool = True) -> np.ndarray:
    """Accessor ``index`` as an array (N, width), or (N,) for scalars; ``buffer(i)`` gives buffer ``i``.

    Every offset, stride and count is checked against the bytes that exist
    before anything is read. With ``check_bounds`` the accessor's ``min`` and
    ``max`` must match its data (to float32 rounding)."""
    a = element(doc, "accessors", index, "the document", fail)
    where = f"accessor {index}"
    if "sparse" in a or "bufferView" not in a:
        fail(f"{where}: sparse or buffer-less accessors are not supported")
    if a.get("componentType") not in COMPONENTS or a.get("type") not in WIDTHS:
        fail(f"{where}: unknown componentType or type")
    dtype = np.dtype(COMPONENTS[a["componentType"]]).newbyteorder("<")
    width, count = WIDTHS[a["type"]], whole(a["count"], f"{where}: count", fail)
    view = element(doc, "bufferViews", a["bufferView"], where, fail)
    data = buffer(index_of(view["buffer"], "buffers", len(doc.get("buffers", [])), f"bufferView {a['bufferView']}",
                           fail))
    start = whole(view.get("byteOffset", 0), f"bufferView {a['bufferView']}: byteOffset", fail)
    length = whole(view["byteLength"], f"bufferView {a['bufferView']}: byteLength", fail)
    if start < 0 or length < 0 or start + length > len(data):
        fail(f"bufferView {a['bufferView']} runs past the end of buffer {view['buffer']}")
    item = dtype.itemsize * width
    stride = whole(view.get("byteStride", item), f"bufferView {a['bufferView']}: byteStride", fail)
    offset = whole(a.get("byteOffset", 0), f"{where}: byteOffset", fail)
    if count < 1 or offset < 0 or offset % dtype.itemsize or stride < item:
        fail(f"{where}: bad count, offset or stride")
    if offset + stride * (count - 1) + item > length:
        fail(f"{where}: {count} elements do not fit in bufferView {a['bufferView']} ({length} bytes)")
    raw = np.frombuffer(data, dtype=np.uint8, count=stride * (count - 1) + item, offset=start + offset)
    rows = np.lib.stride_tricks.as_strided(raw, shape=(count, item), strides=(stride, 1))
    array = np.ascontiguousarray(rows).view(dtype).reshape(count, width).astype(dtype.newbyteorder("="))
    for key, reduce in (("min", np.min), ("max", np.max)):
        if check_bounds and key in a:
            bound = np.asarray(a[key], dtype=float)
            # other writers may print bounds in decimal: allow float32 rounding, no more
            if bound.shape != (width,) or not np.allclose(reduce(array, axis=0), bound, rtol=1e-6, atol=0):
                fail(f"{where}: {key} {a[key]} does not match its data")
    return array[:, 0] if width == 1 else array
