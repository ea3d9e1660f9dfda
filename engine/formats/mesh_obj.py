"""Wavefront OBJ (and its MTL materials) read by our own code, keeping the file's vertex order.

VTK's OBJ reader splits vertices at texture seams, which would break the
vertex order the file defines; this reader keeps one vertex per ``v`` record
and the texture coordinates per polygon corner (``f v/vt/vn``). Groups
(``g``, or ``o`` where there are no groups) become parts; ``usemtl`` gives
each polygon its material and ``mtllib`` files beside the OBJ give each
material its colour image (``map_Kd``, options such as ``-s 1 1 1`` skipped).

>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "skin.mtl").write_text("newmtl skin\\nmap_Kd -s 1 1 1 photo.png\\n")
>>> _ = (folder / "tri.obj").write_text("mtllib skin.mtl\\nv 0 0 0\\nv 1 0 0\\nv 0 1 0\\n"
...                                     "vt 0 0\\nvt 1 0\\nvt 0 1\\nusemtl skin\\nf 1/1 2/2 3/3\\n")
>>> mesh = read_obj(folder / "tri.obj")
>>> mesh.texture.corner_uv.tolist(), pathlib.Path(mesh.texture.images()[0]).name
([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 'photo.png')
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from engine.errors import MeshImportError
from engine.formats.file_beside import FileOutside, file_beside
from engine.formats.mesh_data import MeshMaterial, MeshTexture, RawMesh

_DEFAULT_PART = "surface"
_MTL_LIMIT = 10_000_000     # bytes of an MTL file read; material lists are a few kB
#: map_Kd options and how many values follow each
_MAP_OPTIONS = {"-blendu": 1, "-blendv": 1, "-bm": 1, "-boost": 1, "-cc": 1, "-clamp": 1, "-imfchan": 1,
                "-mm": 2, "-o": 3, "-s": 3, "-t": 3, "-texres": 1, "-type": 1}


def read_obj(path: Path) -> RawMesh:
    """``v``, ``vt`` and ``f`` records, ``g``/``o`` as parts, ``usemtl``/``mtllib`` materials;
    everything else ignored. :class:`MeshImportError` names the file and line of a mistake."""
    try:
        text = path.read_bytes().decode("utf-8", errors="replace")
    except OSError as exc:
        raise MeshImportError(f"cannot read file: {exc.strerror or exc}", file=path) from None
    reader = _ObjReader(path)
    pending, pending_line = "", 0
    for at, raw in enumerate(text.splitlines(), start=1):
        if raw.endswith("\\"):  # a record continued on the next line
            pending, pending_line = pending + raw[:-1] + " ", pending_line or at
            continue
        lineno = pending_line or at
        tokens = (pending + raw).split("#", 1)[0].split()
        pending, pending_line = "", 0
        if tokens:
            reader.record(tokens, lineno)
    return reader.result()


class _ObjReader:
    def __init__(self, path: Path) -> None:
        self.path = path
        self.vertices: list[list[float]] = []
        self.uvs: list[list[float]] = []
        self.cells: list[int] = []
        self.corner_uv: list[tuple[float, float]] = []
        self.face_part: list[int] = []
        self.face_material: list[int] = []
        self.part_names: list[str] = []
        self.part_index: dict[str, int] = {}
        self.materials: list[MeshMaterial] = []
        self.material_index: dict[str, int] = {}
        self.libraries: list[str] = []
        self.group: str | None = None
        self.object_name: str | None = None
        self.current_part = -1
        self.current_material = -1
        self.notes: list[str] = []
        self.bad_uv_lines = 0

    def fail(self, what: str, line: int) -> MeshImportError:
        return MeshImportError(what, file=self.path, line=line)

    def record(self, tokens: list[str], line: int) -> None:
        key = tokens[0]
        if key == "v":
            try:
                self.vertices.append([float(t) for t in tokens[1:4]])
            except ValueError:
                raise self.fail("a vertex coordinate is not a number", line) from None
            if len(self.vertices[-1]) != 3:
                raise self.fail("a vertex needs three coordinates", line)
        elif key == "vt":
            try:
                uv = [float(t) for t in tokens[1:3]]
            except ValueError:
                raise self.fail("a texture coordinate is not a number", line) from None
            self.uvs.append(uv + [0.0] * (2 - len(uv)) if uv else [np.nan, np.nan])
        elif key == "f":
            self.face(tokens[1:], line)
        elif key in ("g", "o"):
            label = "_".join(tokens[1:]) or None
            if key == "g":
                self.group = label
            else:
                self.object_name, self.group = label, None
            self.current_part = -1
        elif key == "usemtl":
            name = " ".join(tokens[1:])
            self.current_material = _slot(name, self.materials, self.material_index)
        elif key == "mtllib":
            self.library(" ".join(tokens[1:]), line)

    def library(self, name: str, line: int) -> None:
        """An ``mtllib`` file, if it lies beside the OBJ (or in a folder inside its folder)."""
        try:
            file_beside(self.path, name.replace("\\", "/"))
        except FileOutside as exc:
            self.notes.append(f"line {line}: material library {exc}: not read, its materials have no images "
                              "(copy it beside the OBJ)")
            return
        self.libraries.append(name)

    def face(self, corners: list[str], line: int) -> None:
        if len(corners) < 3:
            raise self.fail("a face needs at least 3 vertices", line)
        self.cells.append(len(corners))
        for token in corners:
            fields = token.split("/")
            self.cells.append(self.index(fields[0], len(self.vertices), token, "vertex", line))
            k = self.uv_index(fields[1], token, line) if len(fields) > 1 and fields[1] else None
            self.corner_uv.append((np.nan, np.nan) if k is None else (self.uvs[k][0], self.uvs[k][1]))
        if self.current_part < 0:
            label = self.group or self.object_name or _DEFAULT_PART
            if label not in self.part_index:
                self.part_index[label] = len(self.part_names)
                self.part_names.append(label)
            self.current_part = self.part_index[label]
        self.face_part.append(self.current_part)
        self.face_material.append(self.current_material)

    def index(self, text: str, n: int, token: str, what: str, line: int) -> int:
        try:
            i = int(text)
        except ValueError:
            raise self.fail(f"face vertex '{token}' is not an index", line) from None
        i = i - 1 if i > 0 else n + i
        if not 0 <= i < n:
            raise self.fail(f"face vertex '{token}' names a {what} that is not defined yet", line)
        return i

    def uv_index(self, text: str, token: str, line: int) -> int | None:
        """The texture coordinate a corner names, or ``None`` (with a note) where it names none that
        exists: the geometry is still good, as other readers agree."""
        try:
            return self.index(text, len(self.uvs), token, "texture coordinate", line)
        except MeshImportError:
            if not self.bad_uv_lines:
                self.notes.append(f"line {line}: face corner '{token}' names a texture coordinate that is not "
                                  "defined; such corners have none")
            self.bad_uv_lines += 1
            return None

    def result(self) -> RawMesh:
        texture = None
        corner_uv = np.array(self.corner_uv, dtype=float).reshape(-1, 2)
        notes = self.notes + [f"material library '{name}' not found beside the file: its materials have no "
                              "images" for name in self.libraries if not (self.path.parent / name).is_file()]
        if self.materials:
            images = _material_images(self.path, self.libraries, notes)
            for material in self.materials:
                material.image = images.get(material.name)
        if (len(corner_uv) and not np.all(np.isnan(corner_uv))) or self.materials:
            texture = MeshTexture(corner_uv, self.materials, np.array(self.face_material, dtype=np.int64))
        return RawMesh(np.array(self.vertices, dtype=float).reshape(-1, 3), np.array(self.cells, dtype=np.int64),
                       self.part_names, np.array(self.face_part, dtype=np.int64), texture, notes)


def _slot(name: str, materials: list[MeshMaterial], index: dict[str, int]) -> int:
    if name not in index:
        index[name] = len(materials)
        materials.append(MeshMaterial(name))
    return index[name]


def _material_images(obj_path: Path, libraries: list[str], notes: list[str]) -> dict[str, str]:
    """Material name → colour image path (``map_Kd``) from the MTL files that exist; a missing or
    unreadable MTL file leaves its materials without images (the mesh itself is still fine)."""
    images: dict[str, str] = {}
    for library in libraries:
        mtl = obj_path.parent / library
        try:
            if not mtl.is_file():       # missing, or a device or pipe that would never end
                continue
            with mtl.open("rb") as stream:
                text = stream.read(_MTL_LIMIT).decode("utf-8", errors="replace")
        except OSError:
            continue
        current = None
        for at, raw in enumerate(text.splitlines(), start=1):
            tokens = raw.split("#", 1)[0].split()
            if not tokens:
                continue
            if tokens[0] == "newmtl":
                current = " ".join(tokens[1:])
            elif tokens[0].lower() == "map_kd" and current is not None and current not in images:
                name = _map_file_name(tokens[1:])
                if not name:
                    continue
                try:
                    images[current] = str(file_beside(mtl, name.replace("\\", "/")))
                except FileOutside as exc:
                    notes.append(f"{mtl.name} line {at}: image {exc}: material '{current}' has none "
                                 "(copy the image beside the OBJ)")
    return images


def _map_file_name(tokens: list[str]) -> str:
    k = 0
    while k < len(tokens) - 1 and tokens[k] in _MAP_OPTIONS:
        most = _MAP_OPTIONS[tokens[k]]
        k += 2                              # the option and its first value
        for _ in range(most - 1):           # -o/-s/-t/-mm take further numbers, which may be left out
            if k < len(tokens) - 1 and _is_number(tokens[k]):
                k += 1
    return " ".join(tokens[k:])


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
