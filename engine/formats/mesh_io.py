"""Mesh files in and out: import a surface as a :class:`~engine.model.Model`, write posed meshes.

* :func:`read_mesh` reads OBJ, PLY and glTF with our own readers
  (:mod:`~engine.formats.mesh_obj`, :mod:`~engine.formats.mesh_ply`,
  :mod:`~engine.formats.mesh_gltf`), keeping texture coordinates and material
  images, and everything else pyvista reads (STL, VTK/VTP, OFF, …) with VTK in
  a child process (:mod:`~engine.formats.mesh_child`), so that no damaged file
  can crash or hang the caller; :func:`import_mesh` makes the result a model.
* :func:`write_mesh` writes ``.obj``, ``.ply`` (ASCII or binary little-endian)
  and ``.npz`` with our own small writers, keeping the vertex order given.

Lengths are millimetres.

>>> import tempfile, engine
>>> from engine.formats.mesh_io import import_mesh, write_mesh
>>> head = engine.load_model()
>>> posed = write_mesh(f"{tempfile.mkdtemp()}/posed.obj", head.deform(jaw_open=0.5), head.faces,
...                    parts=head.parts, vertex_part=head.vertex_part)
>>> import_mesh(posed).n_vertices == head.n_vertices            # a Z-up scan in metres: up="+Z", scale=1000
True
"""

from __future__ import annotations

import io
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from engine.errors import MeshImportError, UserError
from engine.formats.atomic import atomic_write_bytes
from engine.formats.gltf_document import LFS_POINTER
from engine.formats.mesh_child import read_in_child
from engine.formats.mesh_data import ImportedMesh, RawMesh
from engine.formats.mesh_gltf import read_gltf_mesh
from engine.formats.mesh_obj import read_obj
from engine.formats.mesh_ply import read_ply
from engine.model.cells import cell_sizes, cells_to_triangles, check_cell_array, index_mask, split_cells
from engine.model.model import Model
from engine.model.texture import ModelTexture

WRITE_FORMATS = (".obj", ".ply", ".npz")
_DEFAULT_PART = "surface"


# ---------------------------------------------------------------------------
# Import
# ---------------------------------------------------------------------------

def import_mesh(path: str | Path, scale: float | None = None, name: str | None = None, *,
                keep_units: bool = False, up: str = "+Y", timeout: float | None = None) -> Model:
    """Read a polygon surface as a new :class:`Model` with no parameters.

    The arguments are :func:`read_mesh`'s; ``name`` is the model's name (the
    file's stem by default). The model keeps the file's texture coordinates
    and its material images (:func:`mesh_model`).
    """
    return mesh_model(read_mesh(path, scale, keep_units=keep_units, up=up, timeout=timeout), path, name)


def mesh_model(mesh: ImportedMesh, path: str | Path, name: str | None = None) -> Model:
    """The model :func:`import_mesh` makes of ``mesh`` read from ``path``: the surface, its parts and its
    texture (corner coordinates, the material images loaded, each polygon's image). Images that cannot
    be read are left out with a note added to ``mesh.notes``."""
    from engine.formats.texture_images import model_texture

    path = Path(path)
    model = mesh.to_model(name or path.stem, path.name)
    texture, notes = model_texture(mesh, path)
    mesh.notes += notes
    if texture is not None:
        try:
            texture.check(model.faces)
        except UserError as exc:
            raise MeshImportError(f"texture: {exc.message}", file=path) from None
        model.texture = texture
    return model


def read_mesh(path: str | Path, scale: float | None = None, *, keep_units: bool = False, up: str = "+Y",
              timeout: float | None = None) -> ImportedMesh:
    """Read a polygon surface: vertices in mm with +Y up, polygons, parts, texture.

    Parameters
    ----------
    path : file name
        OBJ (+ MTL), PLY, glTF/GLB (read by our own code), or STL, VTK/VTP/VTU,
        OFF or any other format pyvista reads (read by VTK in a child process
        that is stopped after ``timeout`` seconds, so no file can crash or
        hang the caller).
    scale : float, optional
        Multiplies every coordinate, whatever the format says. By default a
        glTF file is in metres (its specification says so) and is scaled by
        1000; every other format is taken to be in millimetres.
    keep_units : bool
        Keep the file's numbers as they are (no metres → mm for glTF).
    up : ``"+Y"``, ``"-Y"``, ``"+Z"``, ``"-Z"``, ``"+X"`` or ``"-X"``
        The file's up direction; the mesh is turned (a rotation, never a
        mirror) so that it points along +Y, the model's up. ``"+Z"`` maps
        (x, y, z) to (x, z, −y): a Z-up scan facing −Y ends facing +Z.

    Polygons are kept as they are (quads stay quads); triangle strips are
    split into triangles; lines and points are dropped, and so are vertices
    that no polygon uses (the others keep their order). Parts: one per OBJ
    group (``g``, or ``o`` where there are no groups) or glTF mesh, otherwise
    one part ``"surface"``. Texture coordinates (OBJ ``vt``, PLY u/v, s/t,
    texture_u/texture_v or per-corner ``texcoord``, glTF ``TEXCOORD_0``) and
    colour images (MTL ``map_Kd``, PLY ``comment TextureFile``, glTF
    ``baseColorTexture``) are in ``texture``, one (u, v) per polygon corner.

    Raises :class:`~engine.errors.MeshImportError` naming the file when it
    cannot be read or holds no polygons.
    """
    path = Path(path)
    factor = _check_scale(scale)
    rotation = up_rotation(up)
    # NaN and infinite numbers in a file (a signalling NaN's cast to float64, a transform of an infinity) are
    # refused below as coordinates that are not finite; numpy's warnings about them must not reach the user
    with np.errstate(invalid="ignore", over="ignore"):
        raw = _read_raw(path, timeout)
    if len(raw.faces) == 0:
        raise MeshImportError("holds no polygons (points and lines alone are not a surface)", file=path)
    try:
        check_cell_array(raw.faces, len(raw.vertices))
        vertices, faces, vertex_part, part_names = _compact(raw.vertices, raw.faces, raw.face_part,
                                                            raw.part_names)
    except UserError as exc:
        raise MeshImportError(exc.message, file=path) from None
    if not np.all(np.isfinite(vertices)):
        raise MeshImportError("has vertex coordinates that are not finite numbers", file=path)
    if scale is None:
        factor = 1000.0 if raw.units == "m" and not keep_units else 1.0
    with np.errstate(over="ignore", invalid="ignore"):      # 1e308 in the file, × 1000 to mm: refused below
        scaled = vertices @ rotation.T * factor
    if not np.all(np.isfinite(scaled)):
        raise MeshImportError(f"has vertex coordinates too large to scale by {factor:g} (they pass the largest "
                              "number)", file=path)
    if raw.texture is not None:
        raw.notes += [f"image '{image}' is missing" for image in raw.texture.images()
                      if not image.startswith("embedded:") and not Path(image).is_file()]
    return ImportedMesh(scaled, faces, part_names, vertex_part, raw.texture, factor, normalise_up(up), raw.notes)


def up_rotation(up: str) -> np.ndarray:
    """The rotation (3×3) taking a file's ``up`` direction to +Y, the model's up.

    >>> up_rotation("+Z") @ [0, 0, 1]
    array([0., 1., 0.])
    """
    text = normalise_up(up)
    if text not in _UP_ROTATIONS:
        raise MeshImportError(f"up must be one of {', '.join(_UP_ROTATIONS)}, not {up!r}")
    return np.array(_UP_ROTATIONS[text], dtype=float)


def normalise_up(up: str) -> str:
    """``"+Z"`` for ``"z"``, ``"+z"``, ``"Z+"``; ``"-Z"`` for ``"-z"`` and ``"Z-"`` (a sign after the
    axis lets a command line say ``--up Z-``, which argparse would take ``-Z`` for an option)."""
    text = str(up).strip().upper()
    if len(text) == 2 and text[1] in "+-":
        text = text[1] + text[0]
    return text if text[:1] in ("+", "-") else "+" + text


_UP_ROTATIONS = {
    "+Y": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    "-Y": [[1, 0, 0], [0, -1, 0], [0, 0, -1]],     # half a turn about X
    "+Z": [[1, 0, 0], [0, 0, 1], [0, -1, 0]],      # a quarter turn about X: +Z → +Y, −Y → +Z
    "-Z": [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
    "+X": [[0, -1, 0], [1, 0, 0], [0, 0, 1]],      # a quarter turn about Z
    "-X": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]],
}


def _read_raw(path: Path, timeout: float | None) -> RawMesh:
    """The reader for the file's format: our own for OBJ, PLY and glTF, VTK's in a child otherwise."""
    if not path.exists():
        raise MeshImportError("no such file", file=path)
    if path.is_dir():
        raise MeshImportError("is a folder, not a mesh file", file=path)
    if not path.is_file():
        raise MeshImportError("is not a regular file (a device or a pipe?), not a mesh file", file=path)
    try:
        with path.open("rb") as stream:
            head = stream.read(len(LFS_POINTER))
    except OSError as exc:
        raise MeshImportError(f"cannot read file: {exc.strerror or exc}", file=path) from None
    if head == LFS_POINTER:
        raise MeshImportError("is a Git LFS pointer, not the mesh itself (fetch it with 'git lfs pull')", file=path)
    suffix = path.suffix.lower()
    if suffix == ".obj":
        return read_obj(path)
    if suffix == ".ply":
        return read_ply(path)
    if suffix in (".gltf", ".glb"):
        return read_gltf_mesh(path)
    return read_in_child(path, timeout)


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
               binary: bool = True, name: str | None = None, texture: ModelTexture | None = None) -> Path:
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
    texture : ModelTexture, optional
        OBJ only: the texture coordinates (``vt``, one per distinct corner
        (u, v)) and, beside the OBJ, an MTL file (the OBJ's name with
        ``.mtl``) with one material per image (``map_Kd``) and the images as
        PNG (``<obj stem>_<image name>.png``); polygons without an image use
        the material ``untextured``. All files are written together,
        atomically. Blender, MeshLab and our own reader open it textured.

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
    if ext == ".obj" and texture is not None:
        texture.check(faces)
        _write_textured_obj(path, vertices, faces, parts, vertex_part, name, texture)
        return path
    if ext == ".obj":
        data = _obj_bytes(vertices, faces, parts, vertex_part, name)
    elif ext == ".ply":
        data = _ply_bytes(vertices, faces, binary)
    else:
        data = _npz_bytes(vertices, faces, parts, vertex_part)
    atomic_write_bytes(path, data)
    return path


def _obj_bytes(vertices: np.ndarray, faces: np.ndarray, parts: Sequence[str] | None,
               vertex_part: np.ndarray | None, name: str | None, texture: ModelTexture | None = None,
               mtl_name: str | None = None) -> bytes:
    out = io.StringIO()
    out.write("# Artificial Person mesh; units: mm\n")
    if mtl_name:
        out.write(f"mtllib {mtl_name}\n")
    if name:
        out.write(f"o {name}\n")
    out.write("".join(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices.tolist()))
    polygons = split_cells(faces)
    corner_vt: np.ndarray | None = None
    if texture is not None:
        table, inverse = np.unique(texture.corner_uv, axis=0, return_inverse=True)
        corner_vt = inverse.reshape(-1) + 1
        out.write("".join(f"vt {u!r} {v!r}\n" for u, v in table.tolist()))
    last = None
    last_material: int | None = None
    corner = 0
    for index, poly in enumerate(polygons):
        if parts is not None and vertex_part is not None:
            part = int(vertex_part[poly[0]])
            if part != last:
                out.write(f"g {parts[part]}\n")
                last = part
        if texture is None or corner_vt is None:
            out.write("f " + " ".join(str(i + 1) for i in poly.tolist()) + "\n")
            continue
        image = int(texture.face_image[index])
        if image != last_material:
            out.write(f"usemtl {texture.images[image].name if image >= 0 else _UNTEXTURED}\n")
            last_material = image
        vt = corner_vt[corner:corner + len(poly)].tolist()
        corner += len(poly)
        out.write("f " + " ".join(f"{i + 1}/{t}" for i, t in zip(poly.tolist(), vt, strict=True)) + "\n")
    return out.getvalue().encode("utf-8")


_UNTEXTURED = "untextured"


def _write_textured_obj(path: Path, vertices: np.ndarray, faces: np.ndarray, parts: Sequence[str] | None,
                        vertex_part: np.ndarray | None, name: str | None, texture: ModelTexture) -> None:
    """The OBJ, its MTL and one PNG per image, written together (see :func:`write_mesh`)."""
    from engine.formats.atomic import atomic_files
    from engine.formats.texture_images import png_bytes

    mtl = path.with_suffix(".mtl")
    image_files = {image.name: path.with_name(f"{path.stem}_{image.name}.png") for image in texture.images}
    lines = ["# Artificial Person materials", f"newmtl {_UNTEXTURED}", "Kd 0.8 0.8 0.8", ""]
    for image in texture.images:
        lines += [f"newmtl {image.name}", "Ka 1 1 1", "Kd 1 1 1", "Ks 0 0 0", "illum 1",
                  f"map_Kd {image_files[image.name].name}", ""]
    contents = {path: _obj_bytes(vertices, faces, parts, vertex_part, name, texture, mtl.name),
                mtl: "\n".join(lines).encode("utf-8")}
    contents.update({image_files[image.name]: png_bytes(image.pixels) for image in texture.images})
    with atomic_files(list(contents), UserError) as temporary:
        for target, data in contents.items():
            temporary[target].write_bytes(data)


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
