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

import io
from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn

import numpy as np

from engine.errors import MeshImportError
from engine.formats.file_beside import FileOutside, file_beside
from engine.formats.mesh_data import MeshMaterial, MeshTexture, RawMesh
from engine.model.cells import cell_starts

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
        # float32 → float64 of a signalling NaN raises numpy's "invalid value" warning: it stays NaN (refused
        # below as a coordinate that is not a finite number), without the warning reaching the user
        with np.errstate(invalid="ignore"):
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

@dataclass
class _ListColumn:
    """A list property of every row: the lengths, and all the values one after the other."""

    sizes: np.ndarray
    flat: np.ndarray

    @classmethod
    def of_rows(cls, rows: list[np.ndarray]) -> _ListColumn:
        sizes = np.array([len(r) for r in rows], dtype=np.int64)
        return cls(sizes, np.concatenate(rows).astype(float) if rows else np.zeros(0))

    def row(self, i: int) -> np.ndarray:
        start = int(self.sizes[:i].sum())
        return self.flat[start:start + int(self.sizes[i])]


#: Per element: name → one array per scalar property, or a :class:`_ListColumn` for a list property.
_Values = dict[str, dict[str, "np.ndarray | _ListColumn"]]


def _ascii_body(blob: bytes, start: int, header_lines: int, elements: list[_Element], fail: _Failure) -> _Values:
    lines = blob[start:].split(b"\n")
    at = 0
    out: _Values = {}
    for element in elements:
        # blank lines are skipped below, so a count above the lines left cannot be met
        if element.count > len(lines) - at:
            fail(f"the header promises {element.count} '{element.name}' rows but the file has at most "
                 f"{max(len(lines) - at, 0)} lines left (truncated?)", element.header_line)
        fast = _ascii_block(lines[at:at + element.count], element)
        if fast is not None:
            out[element.name] = fast
            at += element.count
            continue
        values, at = _ascii_rows(lines, at, header_lines, element, fail)
        out[element.name] = values
    return out


def _ascii_block(block: list[bytes], element: _Element) -> dict[str, np.ndarray | _ListColumn] | None:
    """The rows parsed at once (numpy's C parser) when they are all alike: no blank lines, one width,
    every list as long as in the first row. ``None`` otherwise (the row-by-row reader says why)."""
    if not block or not all(line.strip() for line in block):
        return None if block else {p.name: (_ListColumn(np.zeros(0, np.int64), np.zeros(0)) if p.count_dtype
                                             else np.zeros(0)) for p in element.properties}
    try:
        table = np.loadtxt(io.BytesIO(b"\n".join(block)), dtype=float, ndmin=2, comments=None)
    except (ValueError, OverflowError):
        return None
    out: dict[str, np.ndarray | _ListColumn] = {}
    k = 0
    for p in element.properties:
        if k >= table.shape[1]:
            return None
        if p.count_dtype is None:
            out[p.name] = table[:, k]
            k += 1
            continue
        n = table[0, k]
        if n < 0 or n != int(n) or not np.all(table[:, k] == n) or k + 1 + int(n) > table.shape[1]:
            return None
        n = int(n)
        out[p.name] = _ListColumn(np.full(len(table), n, dtype=np.int64), table[:, k + 1:k + 1 + n].reshape(-1))
        k += 1 + n
    return out if k <= table.shape[1] else None


def _ascii_rows(lines: list[bytes], at: int, header_lines: int, element: _Element,
                fail: _Failure) -> tuple[dict[str, np.ndarray | _ListColumn], int]:
    """Row by row, naming the line of the first row that does not fit the header."""
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
        try:
            _ascii_row(words, element, lists, columns)
        except (ValueError, OverflowError, IndexError) as exc:
            found = b" ".join(words)[:60].decode("ascii", "replace")
            reason = str(exc) if str(exc).startswith("the list") else f"expected {_describe(element)}"
            fail(f"{element.name} {row}: {reason}, found {found!r}", header_lines + at)
        row += 1
    values: dict[str, np.ndarray | _ListColumn] = {k: np.array(v, dtype=float) for k, v in columns.items()}
    values.update({k: _ListColumn.of_rows(v) for k, v in lists.items()})
    return values, at


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
                 fail: _Failure) -> tuple[dict[str, np.ndarray | _ListColumn], int]:
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
    values: dict[str, np.ndarray | _ListColumn] = {k: np.array(v, dtype=float) for k, v in columns.items()}
    values.update({k: _ListColumn.of_rows(v) for k, v in lists.items()})
    return values, at


def _fixed_rows(blob: bytes, at: int, element: _Element,
                order: str) -> tuple[dict[str, np.ndarray | _ListColumn], int] | None:
    if element.count == 0:
        return {p.name: (_ListColumn(np.zeros(0, np.int64), np.zeros(0)) if p.count_dtype else np.zeros(0))
                for p in element.properties}, at
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
    out: dict[str, np.ndarray | _ListColumn] = {}
    for k, p in enumerate(element.properties):
        if p.count_dtype is None:
            out[p.name] = table[f"p{k}"].astype(float)
            continue
        n = dtype[f"p{k}"].shape[0] if dtype[f"p{k}"].shape else 0
        if not np.all(table[f"n{k}"] == n):
            return None
        out[p.name] = _ListColumn(np.full(element.count, n, dtype=np.int64),
                                  table[f"p{k}"].astype(float).reshape(-1))
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
    for u_name, v_name in _UV_NAMES:
        u, v = vertex.get(u_name), vertex.get(v_name)
        if isinstance(u, np.ndarray) and isinstance(v, np.ndarray):
            vertex_uv = np.column_stack([u, v]).astype(float)
            break
    sizes, flat = np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    corner_uv: np.ndarray | None = None
    notes: list[str] = []
    face = values.get("face")
    if face is not None:
        indices = next((face[k] for k in _INDEX_NAMES if isinstance(face.get(k), _ListColumn)), None)
        if not isinstance(indices, _ListColumn):
            fail("the 'face' element has no 'vertex_indices' list")
        _check_indices(indices, n, "face", fail)
        keep = indices.sizes >= 3
        if not keep.all():
            notes.append(f"dropped {int((~keep).sum())} face(s) with fewer than 3 corners")
        sizes = indices.sizes[keep]
        flat = indices.flat[np.repeat(keep, indices.sizes)].astype(np.int64)
        texcoord = face.get("texcoord")
        if isinstance(texcoord, _ListColumn) and len(texcoord.sizes) == len(keep):
            corner_uv = _corner_texcoords(texcoord, indices.sizes, keep)
    strips = values.get("tristrips")
    if strips is not None:
        lists = next((strips[k] for k in _INDEX_NAMES if isinstance(strips.get(k), _ListColumn)), None)
        if not isinstance(lists, _ListColumn):
            fail("the 'tristrips' element has no 'vertex_indices' list")
        _check_indices(lists, n, "tristrips", fail, restart=True)
        triangles = _strip_triangles(lists.flat.astype(np.int64), lists.sizes)
        if len(triangles):
            if corner_uv is not None:
                corner_uv = np.concatenate([corner_uv, np.full((triangles.size, 2), np.nan)])
            sizes = np.concatenate([sizes, np.full(len(triangles), 3, dtype=np.int64)])
            flat = np.concatenate([flat, triangles.reshape(-1)])
    faces = np.zeros(int(sizes.sum()) + len(sizes), dtype=np.int64)
    starts = cell_starts(sizes)
    mask = np.ones(len(faces), dtype=bool)
    mask[starts] = False
    faces[starts], faces[mask] = sizes, flat
    if corner_uv is None and vertex_uv is not None:
        corner_uv = vertex_uv[flat]
    elif corner_uv is not None and vertex_uv is not None:
        missing = np.isnan(corner_uv[:, 0])
        corner_uv[missing] = vertex_uv[flat[missing]]
    texture = None if corner_uv is None else _texture(path, corner_uv, len(sizes), comments, notes)
    return RawMesh(xyz, faces, ["surface"], np.zeros(len(sizes), dtype=np.int64), texture, notes)


def _check_indices(column: _ListColumn, n: int, what: str, fail: _Failure, restart: bool = False) -> None:
    values = column.flat
    ok = (values >= (-1 if restart else 0)) & (values < n) & (values == np.round(values))
    if not np.all(ok):
        at = int(np.flatnonzero(~ok)[0])
        row = int(np.searchsorted(np.cumsum(column.sizes), at, side="right"))
        fail(f"{what} {row}: vertex index {values[at]:g} is not one of the {n} vertices")


def _corner_texcoords(texcoord: _ListColumn, sizes: np.ndarray, keep: np.ndarray) -> np.ndarray:
    """Per-corner (u, v) of the kept faces from a ``texcoord`` list; NaN for a face whose list
    does not hold two numbers per corner."""
    fits = texcoord.sizes == 2 * sizes
    if fits.all():
        return texcoord.flat.reshape(-1, 2)[np.repeat(keep, sizes)]
    out = []
    starts = np.concatenate([[0], np.cumsum(texcoord.sizes)])
    for i in np.flatnonzero(keep):
        if fits[i]:
            out.append(texcoord.flat[starts[i]:starts[i + 1]].reshape(-1, 2))
        else:
            out.append(np.full((int(sizes[i]), 2), np.nan))
    return np.concatenate(out) if out else np.zeros((0, 2))


def _strip_triangles(flat: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """Triangles (T, 3) of the strips in every row (−1 also starts a new strip); every second one
    turned so all keep the strip's orientation; triangles with a repeated vertex (joins) dropped."""
    out: list[np.ndarray] = []
    for row in np.split(flat, np.cumsum(sizes)[:-1]) if len(sizes) else []:
        for piece in np.split(row, np.flatnonzero(row < 0)):
            run = piece[piece >= 0]
            if len(run) < 3:
                continue
            j = np.arange(len(run) - 2)
            even = j % 2 == 0
            tri = np.column_stack([np.where(even, run[j], run[j + 1]), np.where(even, run[j + 1], run[j]),
                                   run[j + 2]])
            out.append(tri[(tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])])
    return np.concatenate(out).astype(np.int64) if out else np.zeros((0, 3), dtype=np.int64)


def _texture(path: Path, corner_uv: np.ndarray, n_faces: int, comments: list[str],
             notes: list[str]) -> MeshTexture:
    image = next((c.split(None, 1)[1].strip() for c in comments
                  if c.lower().startswith("texturefile") and len(c.split(None, 1)) > 1), None)
    if image:
        try:
            image_file = file_beside(path, image.replace("\\", "/"))
            return MeshTexture(corner_uv, [MeshMaterial("texture", str(image_file))], np.zeros(n_faces, dtype=np.int64))
        except FileOutside as exc:
            notes.append(f"texture file {exc}: not read (copy the image beside the PLY)")
    return MeshTexture(corner_uv, [], np.full(n_faces, -1, dtype=np.int64))
