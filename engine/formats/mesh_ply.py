"""Stanford PLY read by our own code (ASCII, binary little- and big-endian), so VTK never sees it.

VTK's PLY reader crashes or loops on some damaged files; this one checks every
count against the bytes that are really there before it allocates anything,
and every error names the file (and, in ASCII files, the line).

Read: ``vertex`` x, y, z and texture coordinates (``u``/``v``, ``s``/``t``,
``texture_u``/``texture_v``, ``texture_s``/``texture_t``); ``face``
``vertex_indices`` (or ``vertex_index``) with an optional per-corner
``texcoord`` list; ``tristrips`` ``vertex_indices`` (strips separated by −1);
the texture image from a ``comment TextureFile NAME`` line. Other elements and
properties are skipped.

>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "strip.ply"
>>> _ = path.write_text("ply\\nformat ascii 1.0\\nelement vertex 4\\nproperty float x\\nproperty float y\\n"
...                     "property float z\\nelement tristrips 1\\nproperty list int int vertex_indices\\n"
...                     "end_header\\n0 0 0\\n1 0 0\\n0 1 0\\n1 1 0\\n4 0 1 2 3\\n")
>>> read_ply(path).faces.tolist()
[3, 0, 1, 2, 3, 2, 1, 3]
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn

import numpy as np

from engine.errors import MeshImportError
from engine.formats.mesh_data import MeshMaterial, MeshTexture, RawMesh

_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
          "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
          "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}
_UV_NAMES = (("u", "v"), ("s", "t"), ("texture_u", "texture_v"), ("texture_s", "texture_t"))
_INDEX_NAMES = ("vertex_indices", "vertex_index")


@dataclass
class _Property:
    name: str
    dtype: str                 # numpy type code of the value (of the items, for a list)
    count_dtype: str | None    # numpy type code of a list's length; None for a scalar


@dataclass
class _Element:
    name: str
    count: int
    properties: list[_Property]
    header_line: int


class _Failure:
    def __init__(self, path: Path) -> None:
        self.path = path

    def __call__(self, what: str, line: int | None = None) -> NoReturn:
        raise MeshImportError(what, file=self.path, line=line)


def read_ply(path: Path) -> RawMesh:
    """Read a PLY file (see the module's docstring for what is kept); :class:`MeshImportError` naming
    the file when it is damaged, truncated or holds no polygons."""
    fail = _Failure(path)
    try:
        blob = path.read_bytes()
    except OSError as exc:
        fail(f"cannot read file: {exc.strerror or exc}")
    elements, encoding, comments, body_start, header_lines = _header(blob, fail)
    if encoding == "ascii":
        values = _ascii_body(blob, body_start, header_lines, elements, fail)
    else:
        values = _binary_body(blob, body_start, elements, "<" if encoding == "binary_little_endian" else ">", fail)
    return _assemble(path, values, elements, comments, fail)


# -- header -------------------------------------------------------------------------

def _header(blob: bytes, fail: _Failure) -> tuple[list[_Element], str, list[str], int, int]:
    if not blob.startswith(b"ply"):
        fail("not a PLY file (it does not start with 'ply')")
    end = blob.find(b"end_header")
    if end < 0:
        fail("the PLY header has no 'end_header' line (truncated or not a PLY file)")
    newline = blob.find(b"\n", end)
    body_start = len(blob) if newline < 0 else newline + 1
    lines = blob[:end].decode("ascii", errors="replace").splitlines()
    encoding = ""
    elements: list[_Element] = []
    comments: list[str] = []
    for number, line in enumerate(lines, start=1):
        words = line.split()
        if not words or number == 1:
            continue
        key = words[0]
        if key == "format":
            if len(words) < 2 or words[1] not in ("ascii", "binary_little_endian", "binary_big_endian"):
                fail(f"unknown PLY format {' '.join(words[1:])!r}", number)
            encoding = words[1]
        elif key in ("comment", "obj_info"):
            comments.append(line.split(None, 1)[1] if len(words) > 1 else "")
        elif key == "element":
            if len(words) != 3 or not words[2].isdigit():
                fail("an element needs a name and a count", number)
            elements.append(_Element(words[1], int(words[2]), [], number))
        elif key == "property":
            if not elements:
                fail("a property before any element", number)
            elements[-1].properties.append(_property(words, number, fail))
        else:
            fail(f"unknown PLY header line {line.strip()[:40]!r}", number)
    if not encoding:
        fail("the PLY header has no 'format' line")
    for element in elements:
        if element.count and not element.properties:
            fail(f"the element '{element.name}' has no properties", element.header_line)
    return elements, encoding, comments, body_start, len(lines) + 1


def _property(words: list[str], number: int, fail: _Failure) -> _Property:
    if len(words) == 3 and words[1] in _TYPES:
        return _Property(words[2], _TYPES[words[1]], None)
    if len(words) == 5 and words[1] == "list" and words[2] in _TYPES and words[3] in _TYPES:
        if _TYPES[words[2]][0] == "f":
            fail("a list's length must be an integer type", number)
        return _Property(words[4], _TYPES[words[3]], _TYPES[words[2]])
    fail(f"malformed property line {' '.join(words)[:60]!r}", number)


# -- bodies -------------------------------------------------------------------------

#: Per element: name → one array per scalar property, or a list of arrays (one per row) for a list property.
_Values = dict[str, dict[str, "np.ndarray | list[np.ndarray]"]]


def _ascii_body(blob: bytes, start: int, header_lines: int, elements: list[_Element], fail: _Failure) -> _Values:
    lines = blob[start:].split(b"\n")
    at = 0
    out: _Values = {}
    for element in elements:
        # blank lines are skipped below, so a count above the lines left cannot be met
        if element.count > len(lines) - at:
            fail(f"the header promises {element.count} '{element.name}' rows but the file has at most "
                 f"{max(len(lines) - at, 0)} lines left (truncated?)", element.header_line)
        scalars = all(p.count_dtype is None for p in element.properties)
        table: list[list[float]] = []
        lists: dict[str, list[np.ndarray]] = {p.name: [] for p in element.properties if p.count_dtype}
        columns: dict[str, list[float]] = {p.name: [] for p in element.properties if not p.count_dtype}
        row = 0
        while row < element.count:
            if at >= len(lines):
                fail(f"the file ends after {row} of {element.count} '{element.name}' rows (truncated)")
            words = lines[at].split()
            at += 1
            if not words:
                continue
            line = header_lines + at
            try:
                if scalars:
                    if len(words) < len(element.properties):
                        raise ValueError
                    table.append([float(w) for w in words[:len(element.properties)]])
                else:
                    _ascii_row(words, element, lists, columns)
            except (ValueError, OverflowError, IndexError) as exc:
                found = b" ".join(words)[:60].decode("ascii", "replace")
                reason = str(exc) if str(exc).startswith("the list") else f"expected {_describe(element)}"
                fail(f"{element.name} {row}: {reason}, found {found!r}", line)
            row += 1
        if scalars:
            array = np.array(table, dtype=float).reshape(-1, len(element.properties))
            out[element.name] = {p.name: array[:, k] for k, p in enumerate(element.properties)}
        else:
            out[element.name] = {**{k: np.array(v, dtype=float) for k, v in columns.items()}, **lists}
    return out


def _ascii_row(words: list[bytes], element: _Element, lists: dict[str, list[np.ndarray]],
               columns: dict[str, list[float]]) -> None:
    k = 0
    for p in element.properties:
        if p.count_dtype is None:
            columns[p.name].append(float(words[k]))
            k += 1
            continue
        n = int(words[k])
        if n < 0 or k + 1 + n > len(words):
            raise ValueError(f"the list '{p.name}' says {n} values but the line holds {len(words) - k - 1} "
                             "after it (a cut line?)")
        lists[p.name].append(np.array([float(w) for w in words[k + 1:k + 1 + n]]))
        k += 1 + n
    if k > len(words):
        raise ValueError


def _describe(element: _Element) -> str:
    parts = [f"a list '{p.name}'" if p.count_dtype else p.name for p in element.properties]
    return f"{len(parts)} value(s) ({', '.join(parts)})"


def _binary_body(blob: bytes, start: int, elements: list[_Element], order: str, fail: _Failure) -> _Values:
    at = start
    out: _Values = {}
    for element in elements:
        remaining = len(blob) - at
        minimum = sum(np.dtype(p.count_dtype or p.dtype).itemsize for p in element.properties)
        if element.count and minimum * element.count > remaining:
            fail(f"the header promises {element.count} '{element.name}' rows of at least {minimum} bytes "
                 f"but only {remaining} bytes are left (truncated?)", element.header_line)
        if all(p.count_dtype is None for p in element.properties):
            dtype = np.dtype([(f"p{k}", order + p.dtype) for k, p in enumerate(element.properties)])
            table = np.frombuffer(blob, dtype=dtype, count=element.count, offset=at)
            out[element.name] = {p.name: table[f"p{k}"].astype(float) for k, p in enumerate(element.properties)}
            at += dtype.itemsize * element.count
        else:
            out[element.name], at = _binary_rows(blob, at, element, order, fail)
    return out


def _binary_rows(blob: bytes, at: int, element: _Element, order: str,
                 fail: _Failure) -> tuple[dict[str, np.ndarray | list[np.ndarray]], int]:
    """Rows holding lists: fast when every list has the length of the first row's, else row by row."""
    fixed = _fixed_rows(blob, at, element, order)
    if fixed is not None:
        return fixed
    columns: dict[str, list[float]] = {p.name: [] for p in element.properties if not p.count_dtype}
    lists: dict[str, list[np.ndarray]] = {p.name: [] for p in element.properties if p.count_dtype}
    for row in range(element.count):
        for p in element.properties:
            size = np.dtype(p.count_dtype or p.dtype).itemsize
            if at + size > len(blob):
                fail(f"the file ends inside {element.name} {row} of {element.count} (truncated)")
            if p.count_dtype is None:
                columns[p.name].append(float(np.frombuffer(blob, order + p.dtype, 1, at)[0]))
                at += size
                continue
            n = int(np.frombuffer(blob, order + p.count_dtype, 1, at)[0])
            at += size
            item = np.dtype(p.dtype).itemsize
            if n < 0 or at + n * item > len(blob):
                fail(f"{element.name} {row}: a list of {n} values runs past the end of the file (truncated?)")
            lists[p.name].append(np.frombuffer(blob, order + p.dtype, n, at).astype(float))
            at += n * item
    return {**{k: np.array(v, dtype=float) for k, v in columns.items()}, **lists}, at


def _fixed_rows(blob: bytes, at: int, element: _Element,
                order: str) -> tuple[dict[str, np.ndarray | list[np.ndarray]], int] | None:
    if element.count == 0:
        return {p.name: ([] if p.count_dtype else np.zeros(0)) for p in element.properties}, at
    fields: list[tuple[str, str, tuple[int, ...]]] = []
    offset = at
    for k, p in enumerate(element.properties):
        if p.count_dtype is None:
            fields.append((f"p{k}", order + p.dtype, ()))
            offset += np.dtype(p.dtype).itemsize
            continue
        if offset + np.dtype(p.count_dtype).itemsize > len(blob):
            return None
        n = int(np.frombuffer(blob, order + p.count_dtype, 1, offset)[0])
        if n < 0 or n > len(blob):
            return None
        fields.append((f"n{k}", order + p.count_dtype, ()))
        fields.append((f"p{k}", order + p.dtype, (n,)))
        offset += np.dtype(p.count_dtype).itemsize + n * np.dtype(p.dtype).itemsize
    dtype = np.dtype([(name, code, shape) if shape else (name, code) for name, code, shape in fields])
    if at + dtype.itemsize * element.count > len(blob):
        return None
    table = np.frombuffer(blob, dtype=dtype, count=element.count, offset=at)
    out: dict[str, np.ndarray | list[np.ndarray]] = {}
    for k, p in enumerate(element.properties):
        if p.count_dtype is None:
            out[p.name] = table[f"p{k}"].astype(float)
            continue
        n = dtype[f"p{k}"].shape[0] if dtype[f"p{k}"].shape else 1
        if not np.all(table[f"n{k}"] == n):
            return None
        out[p.name] = list(table[f"p{k}"].astype(float).reshape(element.count, n))
    return out, at + dtype.itemsize * element.count


# -- from values to a mesh ------------------------------------------------------------

def _assemble(path: Path, values: _Values, elements: list[_Element], comments: list[str],
              fail: _Failure) -> RawMesh:
    vertex = values.get("vertex")
    if vertex is None or not all(isinstance(vertex.get(c), np.ndarray) for c in "xyz"):
        fail("the PLY file has no 'vertex' element with x, y and z")
    xyz = np.column_stack([np.asarray(vertex[c], dtype=float) for c in "xyz"]).reshape(-1, 3)
    n = len(xyz)
    vertex_uv = None
    for u, v in _UV_NAMES:
        if isinstance(vertex.get(u), np.ndarray) and isinstance(vertex.get(v), np.ndarray):
            vertex_uv = np.column_stack([vertex[u], vertex[v]]).astype(float)
            break
    polygons: list[np.ndarray] = []
    corners: list[np.ndarray | None] = []
    notes: list[str] = []
    dropped = 0
    face = values.get("face")
    if face is not None:
        indices = next((face[k] for k in _INDEX_NAMES if isinstance(face.get(k), list)), None)
        if indices is None:
            fail("the 'face' element has no 'vertex_indices' list")
        texcoord = face.get("texcoord")
        for row, corner in enumerate(indices):
            if len(corner) < 3:
                dropped += 1
                continue
            polygons.append(_checked(corner, n, f"face {row}", fail))
            uv = texcoord[row] if isinstance(texcoord, list) and row < len(texcoord) else None
            corners.append(uv.reshape(-1, 2) if uv is not None and len(uv) == 2 * len(corner) else None)
    strips = values.get("tristrips")
    if strips is not None:
        lists = next((strips[k] for k in _INDEX_NAMES if isinstance(strips.get(k), list)), None)
        if lists is None:
            fail("the 'tristrips' element has no 'vertex_indices' list")
        for row, strip in enumerate(lists):
            for triangle in _strip_triangles(_checked(strip, n, f"tristrips {row}", fail, restart=True)):
                polygons.append(triangle)
                corners.append(None)
    if dropped:
        notes.append(f"dropped {dropped} face(s) with fewer than 3 corners")
    if polygons:
        faces = np.concatenate([np.concatenate([[len(p)], p]) for p in polygons]).astype(np.int64)
    else:
        faces = np.zeros(0, dtype=np.int64)
    texture = _texture(path, faces, polygons, corners, vertex_uv, comments)
    return RawMesh(xyz, faces, ["surface"], np.zeros(len(polygons), dtype=np.int64), texture, notes)


def _checked(indices: np.ndarray, n: int, where: str, fail: _Failure, restart: bool = False) -> np.ndarray:
    values = np.asarray(indices, dtype=float)
    ok = (values >= -1 if restart else values >= 0) & (values < n) & (values == np.round(values))
    if not np.all(ok):
        bad = values[~ok][0]
        fail(f"{where}: vertex index {bad:g} is not one of the {n} vertices")
    return values.astype(np.int64)


def _strip_triangles(strip: np.ndarray) -> list[np.ndarray]:
    """Triangles of the strips in one list (−1 starts a new strip); every second one flipped so all
    keep the strip's orientation; triangles with a repeated vertex (joins) dropped."""
    out: list[np.ndarray] = []
    for piece in np.split(strip, np.flatnonzero(strip < 0)):
        run = piece[piece >= 0]
        for j in range(len(run) - 2):
            a, b, c = run[j], run[j + 1], run[j + 2]
            if a in (b, c) or b == c:
                continue
            out.append(np.array([a, b, c] if j % 2 == 0 else [b, a, c], dtype=np.int64))
    return out


def _texture(path: Path, faces: np.ndarray, polygons: list[np.ndarray], corners: list[np.ndarray | None],
             vertex_uv: np.ndarray | None, comments: list[str]) -> MeshTexture | None:
    if vertex_uv is None and all(c is None for c in corners):
        return None
    rows = []
    for polygon, corner in zip(polygons, corners, strict=True):
        if corner is not None:
            rows.append(corner)
        elif vertex_uv is not None:
            rows.append(vertex_uv[polygon])
        else:
            rows.append(np.full((len(polygon), 2), np.nan))
    corner_uv = np.concatenate(rows) if rows else np.zeros((0, 2))
    image = next((c.split(None, 1)[1].strip() for c in comments
                  if c.lower().startswith("texturefile") and len(c.split(None, 1)) > 1), None)
    if not image:
        return MeshTexture(corner_uv, [], np.full(len(polygons), -1, dtype=np.int64))
    return MeshTexture(corner_uv, [MeshMaterial("texture", str(path.parent / image))],
                       np.zeros(len(polygons), dtype=np.int64))
