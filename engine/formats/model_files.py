"""Reading and writing models: XML description + HDF5 arrays (format version 1).

``head.xml`` (validated against ``engine/formats/schemas/model.xsd``) holds the
parameter tree, parts and landmarks; the HDF5 file it names in ``arrays``
holds the rest mesh, faces, per-vertex parts, sparse weights and displacement
fields. Both carry a format version; readers refuse versions they do not know.
Saves are atomic: each file is written to a temporary name and renamed. See
``docs/model-format.md``.

>>> import tempfile
>>> from engine import load_model, save_model
>>> head = load_model()                                  # the shipped head; load_model(path) for others
>>> path = save_model(head, f"{tempfile.mkdtemp()}/my-head.xml")   # writes my-head.xml + my-head.h5
>>> load_model(path).n_vertices == head.n_vertices
True
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

import h5py
import numpy as np
import numpy.typing as npt
from lxml import etree

from engine.errors import ModelFileError, ParameterError, UserError
from engine.formats.atomic import atomic_files
from engine.formats.xml_io import parse_xml, source_line, validate
from engine.model.landmarks import FEATURE_POINTS
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree

FORMAT = "artificial-person-model"
ARRAYS_FORMAT = "artificial-person-arrays"
VERSION = 1
SCHEMA_NAME = "model.xsd"


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

def load_model(path: str | Path | None = None) -> Model:
    """Load a model from its XML description (and the HDF5 file it names).

    ``path=None`` loads the shipped default head.
    Raises :class:`ModelFileError` naming file and line for anything wrong.
    """
    from engine.paths import default_model_path

    path = Path(path) if path is not None else default_model_path()
    if path.is_dir():
        candidates = sorted(path.glob("*.xml"))
        if len(candidates) != 1:
            raise ModelFileError("a model folder must hold exactly one .xml description", file=path)
        path = candidates[0]
    if not path.exists():
        raise ModelFileError("no such file", file=path)
    doc = parse_xml(path, ModelFileError)
    root = doc.getroot()
    if root.tag != "model":
        raise ModelFileError(f"not a model description: root element is <{root.tag}>, expected <model>",
                             file=path, line=source_line(root))
    version = _integer(root.get("version"))
    if version is not None and version > VERSION:
        raise ModelFileError(f"model format version {version} is newer than this program reads ({VERSION})",
                             file=path, line=source_line(root))
    validate(doc, SCHEMA_NAME, path, ModelFileError)

    parts: list[str] = []
    colors: dict[str, str] = {}
    for el in _child(root, "parts", path):
        if not isinstance(el.tag, str):
            continue
        name = _required(el, "name", path)
        if name in parts:
            raise ModelFileError(f"part '{name}' is defined twice", file=path, line=source_line(el))
        parts.append(name)
        color = el.get("color")
        if color:
            colors[name] = color

    params: list[Parameter] = []
    lines: dict[str, int | None] = {}

    def read_param(el: etree._Element, parent: str | None) -> None:
        name = _required(el, "name", path)
        if name in lines:
            raise ModelFileError(f"parameter '{name}' is defined twice (first on line {lines[name]})",
                                 file=path, line=source_line(el))
        lines[name] = source_line(el)
        kind = _required(el, "type", path)
        body = el.find(kind)
        if body is None:
            other = "translation" if kind == "rotation" else "rotation"
            raise ModelFileError(f"parameter '{name}' has type=\"{kind}\" but a <{other}> element",
                                 file=path, line=source_line(el))
        desc = el.findtext("description") or ""
        kw: dict[str, Any] = dict(
            name=name, kind=kind, parent=parent, minimum=float(_required(el, "min", path)),
            maximum=float(_required(el, "max", path)), default=float(el.get("default", "0")),
            description=desc.strip())
        if kind == "rotation":
            kw.update(axis=_vec(_required(body, "axis", path)), pivot=_vec(_required(body, "pivot", path)),
                      degrees_per_unit=float(_required(body, "degrees-per-unit", path)))
        else:
            is_field = body.get("field", "false").strip() in ("true", "1")
            if not is_field and body.get("direction") is None:
                raise ModelFileError(f"translation '{name}' needs a direction or field=\"true\"",
                                     file=path, line=source_line(body))
            kw.update(field=is_field, direction=_vec(body.get("direction") or "0 0 0"))
        try:
            params.append(Parameter(**kw))
        except ParameterError as exc:
            raise ModelFileError(exc.message, file=path, line=source_line(el)) from None
        for child in el.findall("parameter"):
            read_param(child, name)

    for el in _child(root, "parameters", path).findall("parameter"):
        read_param(el, None)
    try:
        tree = ParameterTree(params)
    except ParameterError as exc:
        raise ModelFileError(exc.message, file=path) from None

    landmarks: dict[str, int] = {}
    landmark_lines: dict[str, int | None] = {}
    lm_root = root.find("landmarks")
    if lm_root is not None:
        for el in lm_root.findall("landmark"):
            key = _required(el, "id", path)
            if key in landmarks:
                raise ModelFileError(f"landmark {key} is defined twice", file=path, line=source_line(el))
            landmarks[key] = int(_required(el, "vertex", path))
            landmark_lines[key] = source_line(el)

    arrays_path = (path.parent / _required(root, "arrays", path)).resolve()
    vertices, faces, vertex_part, regions, colors_rgb = _read_arrays(arrays_path, tree, len(parts))
    n = len(vertices)
    for key, v in landmarks.items():
        if v >= n:
            raise ModelFileError(f"landmark {key}: vertex {v} is outside the mesh (0..{n - 1})",
                                 file=path, line=landmark_lines[key])
    desc = root.findtext("description") or ""
    try:
        return Model(vertices, faces, parts, vertex_part, tree, regions, landmarks,
                     name=_required(root, "name", path), description=desc.strip(), part_colors=colors,
                     vertex_colors=colors_rgb)
    except UserError as exc:
        raise ModelFileError(exc.message, file=arrays_path) from None


def _child(el: etree._Element, tag: str, path: Path) -> etree._Element:
    """The child ``<tag>`` the schema requires (validated before, so this only guards against a mistake)."""
    child = el.find(tag)
    if child is None:
        raise ModelFileError(f"<{el.tag}> has no <{tag}>", file=path, line=source_line(el))
    return child


def _required(el: etree._Element, key: str, path: Path) -> str:
    """Attribute ``key`` the schema requires (validated before, so this only guards against a mistake)."""
    value = el.get(key)
    if value is None:
        raise ModelFileError(f"<{el.tag}> has no '{key}' attribute", file=path, line=source_line(el))
    return value


def _integer(text: str | None) -> int | None:
    """An xs:integer attribute as int (whitespace and a leading '+' allowed), or None if it is not one."""
    try:
        return int(text.strip()) if text is not None else None
    except ValueError:
        return None


def _vec(text: str) -> np.ndarray:
    return np.array([float(t) for t in text.split()])


def _read_arrays(path: Path, tree: ParameterTree, n_parts: int
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict[str, InfluenceRegion], np.ndarray | None]:
    if not path.exists():
        raise ModelFileError("the arrays file named by the model description does not exist", file=path)
    try:
        f = h5py.File(path, "r")
    except OSError:
        raise ModelFileError("not a readable HDF5 file", file=path) from None
    with f:
        fmt = f.attrs.get("format")
        if isinstance(fmt, bytes):
            fmt = fmt.decode()
        if fmt != ARRAYS_FORMAT:
            raise ModelFileError(f"not an Artificial Person arrays file (format attribute is {fmt!r})", file=path)
        version = int(f.attrs.get("version", 0))
        if version > VERSION or version < 1:
            raise ModelFileError(f"arrays format version {version} is not one this program reads ({VERSION})",
                                 file=path)

        def dataset(name: str, dtype: npt.DTypeLike, shape_tail: tuple[int, ...] | None = None) -> np.ndarray:
            if name not in f:
                raise ModelFileError(f"missing HDF5 dataset '/{name}'", file=path)
            data = f[name]
            if not isinstance(data, h5py.Dataset):
                raise ModelFileError(f"'/{name}' is not a dataset", file=path)
            arr = np.asarray(data[()])
            if shape_tail is not None and (arr.ndim != 1 + len(shape_tail) or arr.shape[1:] != shape_tail):
                raise ModelFileError(f"dataset '/{name}' has shape {arr.shape}, expected (n, "
                                     f"{', '.join(map(str, shape_tail))})", file=path)
            if shape_tail is None and arr.ndim != 1:
                raise ModelFileError(f"dataset '/{name}' has shape {arr.shape}, expected one dimension", file=path)
            return arr.astype(dtype)

        vertices = dataset("mesh/vertices", float, (3,))
        faces = dataset("mesh/faces", np.int64)
        vertex_part = dataset("mesh/part", np.int64)
        if len(vertex_part) != len(vertices):
            raise ModelFileError(f"'/mesh/part' has {len(vertex_part)} entries for {len(vertices)} vertices",
                                 file=path)
        if len(vertex_part) and vertex_part.max() >= n_parts:
            raise ModelFileError(f"'/mesh/part' names part {vertex_part.max()} but the model has {n_parts} parts",
                                 file=path)
        colors: np.ndarray | None = None
        if "mesh/colors" in f:
            colors = dataset("mesh/colors", np.int64, (3,))
            if len(colors) != len(vertices) or colors.min() < 0 or colors.max() > 255:
                raise ModelFileError("'/mesh/colors' must hold one sRGB triple (0-255) per vertex", file=path)
            colors = colors.astype(np.uint8)
        regions: dict[str, InfluenceRegion] = {}
        for p in tree:
            base = f"parameters/{p.name}"
            if base not in f:
                raise ModelFileError(f"missing HDF5 group '/{base}' for parameter '{p.name}'", file=path)
            idx = dataset(f"{base}/indices", np.int64)
            w = dataset(f"{base}/weights", float)
            disp = dataset(f"{base}/displacements", float, (3,)) if p.field else None
            try:
                regions[p.name] = InfluenceRegion(idx, w, disp)
            except UserError as exc:
                raise ModelFileError(f"parameter '{p.name}': {exc.message}", file=path) from None
    return vertices, faces, vertex_part, regions, colors


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------

def save_model(model: Model, path: str | Path) -> Path:
    """Save ``model`` as ``path`` (XML) plus ``path`` with suffix ``.h5``; both atomically, together.

    A missing folder is created. Returns the XML path. Raises
    :class:`ModelFileError` naming the file when it cannot be written (the
    files that were there stay as they were).
    """
    path, arrays = model_file_paths(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ModelFileError(f"cannot create the folder: {exc.strerror or exc}", file=path.parent) from None
    model.validate()
    # Both files are written completely under temporary names, then renamed into place: a failure
    # while writing leaves the previous model as it was.
    with atomic_files([arrays, path], ModelFileError) as temporary:
        write_model_files(model, temporary[path], temporary[arrays], arrays.name)
    return path


def model_file_paths(path: str | Path) -> tuple[Path, Path]:
    """The description (``.xml``) and arrays (``.h5``) files :func:`save_model` writes for ``path``.

    >>> model_file_paths("people/anna")
    (PosixPath('people/anna.xml'), PosixPath('people/anna.h5'))
    """
    path = Path(path)
    if path.suffix.lower() != ".xml":
        path = path.with_suffix(".xml")
    return path, path.with_suffix(".h5")


def write_model_files(model: Model, description: str | Path, arrays: str | Path, arrays_name: str) -> None:
    """Write ``model``'s XML to ``description`` and its HDF5 arrays to ``arrays``, directly (not atomically).

    For callers that write a model together with other files through
    :func:`engine.formats.atomic.atomic_files`; ``arrays_name`` is the name
    the description gives the arrays file (where it will end up, relative to
    the description). Use :func:`save_model` otherwise.
    """
    xml = model_to_xml(model, arrays_name)          # a UserError here, before the arrays are written
    _write_arrays(model, arrays)
    Path(description).write_bytes(xml)


def model_to_xml(model: Model, arrays_name: str) -> bytes:
    """The model description (format version :data:`VERSION`) naming ``arrays_name`` as its arrays file."""
    root = etree.Element("model", format=FORMAT, version=str(VERSION), name=_xml_text(model.name, "the model name"),
                         arrays=arrays_name, units="mm")
    if model.description:
        etree.SubElement(root, "description").text = _xml_text(model.description, "the model description")
    parts = etree.SubElement(root, "parts")
    for name in model.parts:
        el = etree.SubElement(parts, "part", name=name)
        if name in model.part_colors:
            el.set("color", model.part_colors[name])
    params = etree.SubElement(root, "parameters")
    tree = model.parameters

    def write(name: str, parent_el: etree._Element) -> None:
        p = tree[name]
        el = etree.SubElement(parent_el, "parameter", name=p.name, type=p.kind, min=_num(p.minimum),
                              max=_num(p.maximum), default=_num(p.default))
        if p.description:
            etree.SubElement(el, "description").text = _xml_text(p.description, f"parameter '{p.name}' description")
        if p.kind == "rotation":
            etree.SubElement(el, "rotation", {"axis": _nums(p.axis), "pivot": _nums(p.pivot),
                                              "degrees-per-unit": _num(p.degrees_per_unit)})
        elif p.field:
            etree.SubElement(el, "translation", field="true")
        else:
            etree.SubElement(el, "translation", direction=_nums(p.direction))
        for child in tree.children(name):
            write(child, el)

    for name in tree.roots():
        write(name, params)
    if model.landmarks:
        lm = etree.SubElement(root, "landmarks")
        for key in sorted(model.landmarks, key=_landmark_order):
            el = etree.SubElement(lm, "landmark", id=key, vertex=str(model.landmarks[key]))
            if key in FEATURE_POINTS:
                el.set("description", FEATURE_POINTS[key])
    etree.indent(root, space="  ")
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def _xml_text(value: str, what: str) -> str:
    """``value`` if XML can carry it, else a :class:`UserError` naming ``what``."""
    try:
        etree.Element("probe").text = value
    except ValueError:
        raise UserError(f"{what} contains characters XML cannot hold (control characters or NUL)") from None
    return value


def _landmark_order(key: str) -> tuple[tuple[int, ...], str]:
    try:
        return tuple(int(t) for t in key.split(".")), key
    except ValueError:
        return (10 ** 6,), key


def _num(x: float) -> str:
    return repr(float(x))


def _nums(v: Iterable[float]) -> str:
    return " ".join(_num(x) for x in v)


def _write_arrays(model: Model, path: str | Path) -> None:
    with h5py.File(path, "w", track_order=True) as f:
        f.attrs["format"] = ARRAYS_FORMAT
        f.attrs["version"] = VERSION
        f.attrs["units"] = "mm"
        mesh = f.create_group("mesh")
        mesh.create_dataset("vertices", data=model.vertices, compression="gzip", shuffle=True)
        mesh.create_dataset("faces", data=model.faces, compression="gzip", shuffle=True)
        mesh.create_dataset("part", data=model.vertex_part.astype(np.int32), compression="gzip")
        if model.vertex_colors is not None:
            mesh.create_dataset("colors", data=model.vertex_colors, compression="gzip")
        params = f.create_group("parameters", track_order=True)
        for p in model.parameters:
            r = model.regions[p.name]
            g = params.create_group(p.name)
            g.create_dataset("indices", data=r.indices.astype(np.int64))
            g.create_dataset("weights", data=r.weights)
            if r.displacements is not None:
                g.create_dataset("displacements", data=r.displacements)

