"""Mesh files in and out: import a surface as a :class:`~engine.model.Model`, write posed meshes.

* :func:`import_mesh` reads OBJ with our own reader (VTK's OBJ reader splits
  vertices at texture seams, which would break the vertex order the file
  defines) and everything else pyvista reads (PLY, STL, VTK/VTP, glTF/GLB, …)
  through pyvista, imported lazily so that ``import engine`` loads no VTK.
* :func:`write_mesh` writes ``.obj``, ``.ply`` (ASCII or binary little-endian)
  and ``.npz`` with our own small writers, keeping the vertex order given.

Lengths are millimetres.

>>> import tempfile, engine
>>> from engine.formats.mesh_io import import_mesh, write_mesh
>>> head = engine.load_model()
>>> posed = write_mesh(f"{tempfile.mkdtemp()}/posed.obj", head.deform(jaw_open=0.5), head.faces,
...                    parts=head.parts, vertex_part=head.vertex_part)
>>> import_mesh(posed).n_vertices == head.n_vertices            # a scan in metres: scale=1000.0
True
"""

from __future__ import annotations

import contextlib
import io
import re
import warnings
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.errors import MeshImportError, UserError
from engine.formats.atomic import atomic_write_bytes
from engine.model.cells import cell_sizes, cells_to_triangles, check_cell_array, index_mask, split_cells
from engine.model.model import Model

if TYPE_CHECKING:
    import pyvista as pv

#: What the readers return: vertices (N, 3), flat cell array, part names, each face's part index.
_MeshArrays = tuple[np.ndarray, np.ndarray, list[str], np.ndarray]

WRITE_FORMATS = (".obj", ".ply", ".npz")
_DEFAULT_PART = "surface"


# ---------------------------------------------------------------------------
# Import
# ---------------------------------------------------------------------------

def import_mesh(path: str | Path, scale: float | None = None, name: str | None = None) -> Model:
    """Read a polygon surface as a new :class:`Model` with no parameters.

    Parameters
    ----------
    path : file name
        OBJ, PLY, STL, VTK/VTP, glTF/GLB or any other mesh format pyvista reads.
    scale : float, optional
        Multiplies every coordinate. The file's units are taken to be
        millimetres unless you say otherwise, e.g. ``scale=1000`` for a file
        in metres (glTF files are in metres by that format's convention).
    name : str, optional
        Model name; defaults to the file's stem.

    Polygons are kept as they are (quads stay quads); triangle strips are
    split into triangles; lines and points are dropped, and so are vertices
    that no polygon uses (the others keep their order). Parts: one per OBJ
    group (``g``, or ``o`` where there are no groups) or glTF mesh, otherwise
    one part ``"surface"``.

    Raises :class:`~engine.errors.MeshImportError` naming the file when it
    cannot be read or holds no polygons.
    """
    path = Path(path)
    factor = _check_scale(scale)
    if not path.exists():
        raise MeshImportError("no such file", file=path)
    if path.is_dir():
        raise MeshImportError("is a folder, not a mesh file", file=path)
    if path.suffix.lower() == ".obj":
        vertices, faces, part_names, face_part = _read_obj(path)
    else:
        vertices, faces, part_names, face_part = _read_with_pyvista(path)
    if len(faces) == 0:
        raise MeshImportError("holds no polygons (points and lines alone are not a surface)", file=path)
    vertices, faces, vertex_part, part_names = _compact(vertices, faces, face_part, part_names)
    if not np.all(np.isfinite(vertices)):
        raise MeshImportError("has vertex coordinates that are not finite numbers", file=path)
    try:
        return Model(vertices * factor, faces, part_names, vertex_part,
                     name=name or path.stem, description=f"imported from {path.name}")
    except UserError as exc:
        raise MeshImportError(exc.message, file=path) from None


def _check_scale(scale: float | None) -> float:
    if scale is None:
        return 1.0
    try:
        factor = float(scale)
    except (TypeError, ValueError):
        raise MeshImportError(f"scale must be a number, not {scale!r}") from None
    if not np.isfinite(factor) or factor <= 0:
        raise MeshImportError(f"scale must be a positive number, not {scale!r}")
    return factor


def _read_obj(path: Path) -> _MeshArrays:
    """Wavefront OBJ: ``v`` and ``f`` records, ``g``/``o`` as parts; everything else ignored."""
    try:
        text = path.read_bytes().decode("utf-8", errors="replace")
    except OSError as exc:
        raise MeshImportError(f"cannot read file: {exc.strerror or exc}", file=path) from None
    vertices: list[list[float]] = []
    cells: list[int] = []
    face_part: list[int] = []
    part_names: list[str] = []
    part_index: dict[str, int] = {}
    group = object_name = None
    current = -1
    pending, pending_line = "", 0
    for at, raw in enumerate(text.splitlines(), start=1):
        if raw.endswith("\\"):  # a record continued on the next line
            pending, pending_line = pending + raw[:-1] + " ", pending_line or at
            continue
        lineno = pending_line or at
        tokens = (pending + raw).split("#", 1)[0].split()
        pending, pending_line = "", 0
        if not tokens:
            continue
        key = tokens[0]
        if key == "v":
            try:
                vertices.append([float(t) for t in tokens[1:4]])
            except ValueError:
                raise MeshImportError("a vertex coordinate is not a number", file=path, line=lineno) from None
            if len(vertices[-1]) != 3:
                raise MeshImportError("a vertex needs three coordinates", file=path, line=lineno)
        elif key == "f":
            if len(tokens) < 4:
                raise MeshImportError("a face needs at least 3 vertices", file=path, line=lineno)
            n = len(vertices)
            cells.append(len(tokens) - 1)
            for token in tokens[1:]:
                try:
                    i = int(token.split("/", 1)[0])
                except ValueError:
                    raise MeshImportError(f"face vertex '{token}' is not an index", file=path,
                                          line=lineno) from None
                i = i - 1 if i > 0 else n + i
                if not 0 <= i < n:
                    raise MeshImportError(f"face vertex '{token}' names a vertex that is not defined yet",
                                          file=path, line=lineno)
                cells.append(i)
            if current < 0:
                current = _part_slot(group or object_name or _DEFAULT_PART, part_names, part_index)
            face_part.append(current)
        elif key in ("g", "o"):
            label = "_".join(tokens[1:]) or None
            if key == "g":
                group = label
            else:
                object_name, group = label, None
            current = -1
    return (np.array(vertices, dtype=float).reshape(-1, 3), np.array(cells, dtype=np.int64),
            part_names, np.array(face_part, dtype=np.int64))


def _part_slot(label: str, names: list[str], index: dict[str, int]) -> int:
    if label not in index:
        index[label] = len(names)
        names.append(label)
    return index[label]


def _read_with_pyvista(path: Path) -> _MeshArrays:
    import pyvista as pv
    from vtkmodules.vtkCommonCore import vtkObject

    # VTK readers report damaged files through VTK's log, Python's logging and
    # warnings at once; silence all three and report one error of our own.
    shown = vtkObject.GetGlobalWarningDisplay()
    try:
        quiet_log = pv.vtk_verbosity("off") if hasattr(pv, "vtk_verbosity") else contextlib.nullcontext()
        with warnings.catch_warnings(), quiet_log:
            warnings.simplefilter("ignore")
            vtkObject.GlobalWarningDisplayOff()
            data = pv.read(str(path))
    except Exception as exc:  # VTK readers raise assorted errors on damaged or unknown files
        text = str(exc).lower()
        if "automatically read" in text or "not supported" in text or "extension" in text:
            raise MeshImportError(f"unknown mesh format '{path.suffix or path.name}' "
                                  "(try .obj, .ply, .stl, .vtk, .vtp, .gltf or .glb)", file=path) from None
        raise MeshImportError("cannot read as a mesh: the file is empty, damaged or not in the format "
                              "its extension says", file=path) from None
    finally:
        vtkObject.SetGlobalWarningDisplay(shown)

    pieces = list(_leaf_datasets(data, None))
    if not pieces:
        raise MeshImportError("holds no mesh (the file is empty, damaged or not a mesh)", file=path)
    vertex_blocks: list[np.ndarray] = []
    cell_blocks: list[np.ndarray] = []
    part_names: list[str] = []
    face_part: list[np.ndarray] = []
    part_index: dict[str, int] = {}
    offset = 0
    for label, ds in pieces:
        if isinstance(ds, (pv.ImageData, pv.RectilinearGrid)):
            raise MeshImportError(f"holds an image or grid ({type(ds).__name__}), not a polygon surface",
                                  file=path)
        surface = ds if isinstance(ds, pv.PolyData) else _boundary_surface(ds)
        if surface.n_points == 0:
            continue
        cells = _polys_and_strips(surface)
        if len(cells) == 0:
            continue
        counts = cell_sizes(cells)
        shifted = cells.copy()
        shifted[index_mask(cells, counts)] += offset
        slot = _part_slot(label if len(pieces) > 1 else _DEFAULT_PART, part_names, part_index)
        vertex_blocks.append(np.asarray(surface.points, dtype=float))
        cell_blocks.append(shifted)
        face_part.append(np.full(len(counts), slot, dtype=np.int64))
        offset += surface.n_points
    if not cell_blocks:
        return np.zeros((0, 3)), np.zeros(0, dtype=np.int64), [], np.zeros(0, dtype=np.int64)
    return (np.concatenate(vertex_blocks), np.concatenate(cell_blocks), part_names,
            np.concatenate(face_part))


def _leaf_datasets(data: pv.DataObject | None, label: str | None) -> Iterator[tuple[str, pv.DataObject]]:
    """(name, dataset) for every non-empty dataset in a possibly nested MultiBlock."""
    import pyvista as pv

    if data is None:
        return
    if isinstance(data, pv.MultiBlock):
        for key, block in zip(data.keys(), data, strict=True):
            yield from _leaf_datasets(block, key or label)
    elif data.n_points:
        yield (label or _DEFAULT_PART), data


def _boundary_surface(ds: pv.DataObject) -> pv.PolyData:
    """The outer surface of a volume mesh or grid, as PolyData (VTK's filter, stable across pyvista versions)."""
    import pyvista as pv
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter

    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(ds)
    surface.Update()
    return pv.wrap(surface.GetOutput())


def _polys_and_strips(ds: pv.PolyData) -> np.ndarray:
    """The polygons of a PolyData as a flat cell array, triangle strips split into triangles."""
    polys = np.asarray(ds.faces, dtype=np.int64) if ds.GetNumberOfPolys() else np.zeros(0, dtype=np.int64)
    if not ds.GetNumberOfStrips():
        return polys
    tris = []
    for strip in split_cells(np.asarray(ds.strips, dtype=np.int64)):
        for j in range(len(strip) - 2):
            a, b, c = strip[j], strip[j + 1], strip[j + 2]
            tris.append((3, a, b, c) if j % 2 == 0 else (3, b, a, c))
    return np.concatenate([polys, np.array(tris, dtype=np.int64).reshape(-1)])


def _compact(vertices: np.ndarray, faces: np.ndarray, face_part: np.ndarray,
             part_names: list[str]) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """Drop vertices no polygon uses (keeping order) and give every vertex the part of its first face."""
    counts = cell_sizes(faces)
    mask = index_mask(faces, counts)
    indices = faces[mask]
    owner = np.repeat(np.asarray(face_part, dtype=np.int64), counts)
    used = np.zeros(len(vertices), dtype=bool)
    used[indices] = True
    vertex_part = np.full(len(vertices), -1, dtype=np.int64)
    named, first = np.unique(indices, return_index=True)   # the first face naming a vertex wins
    vertex_part[named] = owner[first]
    if not used.all():
        remap = np.cumsum(used) - 1
        faces = faces.copy()
        faces[mask] = remap[indices]
        vertices, vertex_part = vertices[used], vertex_part[used]
    present = np.unique(vertex_part)
    if len(present) < len(part_names):  # a part whose vertices all went to earlier parts
        relabel = np.full(len(part_names), -1, dtype=np.int64)
        relabel[present] = np.arange(len(present))
        vertex_part = relabel[vertex_part]
        part_names = [part_names[i] for i in present]
    return vertices, faces, vertex_part, _part_names(part_names)


def _part_names(labels: list[str]) -> list[str]:
    """Labels made valid as model part names (``[A-Za-z_][A-Za-z0-9_.-]*``) and unique."""
    out: list[str] = []
    for label in labels:
        name = re.sub(r"[^A-Za-z0-9_.\-]", "_", label.strip()) or _DEFAULT_PART
        if not re.match(r"[A-Za-z_]", name):
            name = "part_" + name
        base, k = name, 2
        while name in out:
            name, k = f"{base}_{k}", k + 1
        out.append(name)
    return out


# ---------------------------------------------------------------------------
# Cell-array helpers
# ---------------------------------------------------------------------------

# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------

def write_mesh(path: str | Path, vertices: npt.ArrayLike, faces: npt.ArrayLike, *,
               parts: Sequence[str] | None = None, vertex_part: npt.ArrayLike | None = None,
               binary: bool = True, name: str | None = None) -> Path:
    """Write a polygon mesh as ``.obj``, ``.ply`` or ``.npz``, chosen by the file's extension.

    Parameters
    ----------
    vertices : (N, 3) array
        Positions in mm, written in the order given (so a posed mesh keeps the
        model's vertex order).
    faces : 1-D int array
        Flat cell array ``[n, i0, …, i(n-1), n, …]``; polygons are kept as they are.
    parts, vertex_part : optional
        Part names and each vertex's index into them. OBJ writes a ``g`` line
        whenever the part of the faces (the part of a face's first vertex)
        changes; NPZ stores both arrays.
    binary : bool
        PLY only: binary little-endian (default) or ASCII.
    name : str, optional
        OBJ only: an ``o`` line naming the object.

    An ``.npz`` holds ``vertices`` (N×3 float64, mm), ``faces`` (the flat cell
    array, int64) and ``triangles`` (T×3 int64, polygons fan-triangulated).
    The file is written atomically. Returns the path written.
    """
    path = Path(path)
    ext = path.suffix.lower()
    if ext not in WRITE_FORMATS:
        raise UserError(f"unknown mesh format '{ext or path.name}': use {', '.join(WRITE_FORMATS)}", file=path)
    vertices = np.asarray(vertices, dtype=float)
    if vertices.ndim != 2 or vertices.shape[1] != 3:
        raise UserError(f"vertices must be an (N, 3) array, not shape {vertices.shape}")
    faces = np.asarray(faces, dtype=np.int64).reshape(-1)
    check_cell_array(faces, len(vertices))
    if vertex_part is not None:
        vertex_part = np.asarray(vertex_part, dtype=np.int64).reshape(-1)
        if len(vertex_part) != len(vertices):
            raise UserError(f"{len(vertex_part)} part labels for {len(vertices)} vertices")
    if ext == ".obj":
        data = _obj_bytes(vertices, faces, parts, vertex_part, name)
    elif ext == ".ply":
        data = _ply_bytes(vertices, faces, binary)
    else:
        data = _npz_bytes(vertices, faces, parts, vertex_part)
    atomic_write_bytes(path, data)
    return path


def _obj_bytes(vertices: np.ndarray, faces: np.ndarray, parts: Sequence[str] | None,
               vertex_part: np.ndarray | None, name: str | None) -> bytes:
    out = io.StringIO()
    out.write("# Artificial Person mesh; units: mm\n")
    if name:
        out.write(f"o {name}\n")
    out.write("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices.tolist()))
    polygons = split_cells(faces)
    last = None
    for poly in polygons:
        if parts is not None and vertex_part is not None:
            part = int(vertex_part[poly[0]])
            if part != last:
                out.write(f"g {parts[part]}\n")
                last = part
        out.write("f " + " ".join(str(i + 1) for i in poly.tolist()) + "\n")
    return out.getvalue().encode("utf-8")


def _ply_bytes(vertices: np.ndarray, faces: np.ndarray, binary: bool) -> bytes:
    counts = cell_sizes(faces)
    count_type = "uchar" if not len(counts) or counts.max() <= 255 else "int"
    header = (
        "ply\n"
        f"format {'binary_little_endian' if binary else 'ascii'} 1.0\n"
        "comment Artificial Person mesh; units: mm\n"
        f"element vertex {len(vertices)}\n"
        "property double x\nproperty double y\nproperty double z\n"
        f"element face {len(counts)}\n"
        f"property list {count_type} int vertex_indices\n"
        "end_header\n").encode("ascii")
    if not binary:
        body = "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in vertices.tolist())
        body += "".join(f"{len(p)} " + " ".join(map(str, p.tolist())) + "\n" for p in split_cells(faces))
        return header + body.encode("ascii")
    vertex_bytes = np.ascontiguousarray(vertices, dtype="<f8").tobytes()
    # One byte (or four) for each count, four for each index, packed in cell-array order.
    mask = index_mask(faces, counts)
    count_size = 1 if count_type == "uchar" else 4
    sizes = np.where(mask, 4, count_size)
    starts = np.concatenate([[0], np.cumsum(sizes[:-1])]) if len(faces) else np.zeros(0, dtype=np.int64)
    buf = np.zeros(int(sizes.sum()), dtype=np.uint8)
    idx_bytes = faces[mask].astype("<i4").view(np.uint8).reshape(-1, 4)
    buf[starts[mask][:, None] + np.arange(4)] = idx_bytes
    cnt = faces[~mask]
    if count_size == 1:
        buf[starts[~mask]] = cnt.astype(np.uint8)
    else:
        buf[starts[~mask][:, None] + np.arange(4)] = cnt.astype("<i4").view(np.uint8).reshape(-1, 4)
    return header + vertex_bytes + buf.tobytes()


def _npz_bytes(vertices: np.ndarray, faces: np.ndarray, parts: Sequence[str] | None,
               vertex_part: np.ndarray | None) -> bytes:
    arrays = {"vertices": np.ascontiguousarray(vertices, dtype=np.float64), "faces": faces,
              "triangles": cells_to_triangles(faces).astype(np.int64)}
    if parts is not None and vertex_part is not None:
        arrays["parts"] = np.array(list(parts), dtype=str)
        arrays["vertex_part"] = vertex_part
    out = io.BytesIO()
    # numpy's stub types **kwds against the allow_pickle flag; these keys are array names only
    np.savez_compressed(out, **arrays)  # type: ignore[arg-type]
    return out.getvalue()
