"""Reading and writing models: XML description + HDF5 arrays (format version 2; version 1 is read too).

``head.xml`` (validated against ``engine/formats/schemas/model.xsd``) holds the
parameter tree, parts and landmarks; the HDF5 file it names in ``arrays``
holds the rest mesh, faces, per-vertex parts, sparse weights and displacement
fields, and (version 2) the texture: every polygon corner's texture
coordinates, each polygon's image and the images' pixels. Both carry a
format version; readers refuse versions they do not know.
Saves are atomic for the pair, even under ``kill -9``: both files are written
under temporary names and renamed under a journal that the next save or load
finishes (:mod:`engine.formats.atomic`), and both carry the same
``generation`` token, so a description beside another save's arrays is
refused. The arrays file is read as untrusted input
(:mod:`engine.formats.hdf5_reading`). See ``docs/model-format.md``.

>>> import tempfile
>>> from engine import load_model, save_model
>>> head = load_model()                                  # the shipped head; load_model(path) for others
>>> path = save_model(head, f"{tempfile.mkdtemp()}/my-head.xml")   # writes my-head.xml + my-head.h5
>>> load_model(path).n_vertices == head.n_vertices
True
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import h5py
import numpy as np
from lxml import etree

from engine.errors import ModelFileError, ParameterError, UserError
from engine.formats.atomic import atomic_files, finish_interrupted_writes
from engine.formats.hair_element import read_hair, write_hair
from engine.formats.hdf5_reading import HDF5Reader
from engine.formats.hdf5_reading import text as hdf5_text
from engine.formats.identity_drawn import read_drawn, write_drawn
from engine.formats.xml_io import parse_xml, source_line, validate
from engine.model.cells import check_cell_array
from engine.model.identity_record import IdentityRecord
from engine.model.landmarks import FEATURE_POINTS
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree
from engine.model.texture import ModelTexture, TextureImage

FORMAT = "artificial-person-model"
ARRAYS_FORMAT = "artificial-person-arrays"
VERSION = 2
#: Format versions this program reads: 1 (no texture) and 2 (texture, identity).
READABLE_VERSIONS = (1, 2)
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
    finish_interrupted_writes(path if path.is_dir() else path.parent)   # a save killed half-way is finished first
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
    if arrays_path.parent != path.parent.resolve():
        finish_interrupted_writes(arrays_path.parent)
    vertices, faces, vertex_part, regions, colors_rgb, generation, texture = _read_arrays(arrays_path, tree,
                                                                                          len(parts))
    described = root.get("generation")
    if described is not None and generation != described:
        raise ModelFileError(
            f"the description and its arrays file {arrays_path.name} come from different saves (generation "
            f"{described} here, {generation or 'none'} there): the pair was mixed by copying one file, or a "
            "save is under way; load it again, or restore both files from one save",
            file=path, line=source_line(root))
    n = len(vertices)
    for key, v in landmarks.items():
        if v >= n:
            raise ModelFileError(f"landmark {key}: vertex {v} is outside the mesh (0..{n - 1})",
                                 file=path, line=landmark_lines[key])
    desc = root.findtext("description") or ""
    identity = _read_identity(root, path)
    try:
        model = Model(vertices, faces, parts, vertex_part, tree, regions, landmarks,
                      name=_required(root, "name", path), description=desc.strip(), part_colors=colors,
                      vertex_colors=colors_rgb, texture=texture)
    except UserError as exc:
        raise ModelFileError(exc.message, file=arrays_path) from None
    model.identity = identity
    return model


def _read_identity(root: etree._Element, path: Path) -> IdentityRecord | None:
    """The ``<identity>`` record, if any: finite values, each name once."""
    el = root.find("identity")
    if el is None:
        return None
    values: dict[str, float] = {}
    for v in el.findall("value"):
        name = _required(v, "name", path)
        if name in values:
            raise ModelFileError(f"identity value '{name}' is given twice", file=path, line=source_line(v))
        number = float(_required(v, "value", path))
        if not math.isfinite(number):
            raise ModelFileError(f"identity value '{name}' must be a finite number", file=path, line=source_line(v))
        values[name] = number
    return read_hair(el, read_drawn(el, IdentityRecord(values, _required(el, "source", path)), path), path)


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
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict[str, InfluenceRegion], np.ndarray | None,
                            str | None, ModelTexture | None]:
    """The arrays file's contents, checked (kind, shape, size, finite values) before and after reading.

    Returns vertices, faces, per-vertex parts, regions, vertex colours, the
    file's ``generation`` attribute (None in files written before it existed)
    and the texture (None if the file has none; version 1 files never do).
    """
    if not path.exists():
        raise ModelFileError("the arrays file named by the model description does not exist", file=path)
    with HDF5Reader(path, ModelFileError) as f:
        fmt = hdf5_text(f.attribute("format"))
        if fmt != ARRAYS_FORMAT:
            raise f.fail(f"not an Artificial Person arrays file (format attribute is {fmt!r})")
        version = _integer(hdf5_text(f.attribute("version")))
        if version not in READABLE_VERSIONS:
            raise f.fail(f"arrays format version {version} is not one this program reads ({VERSION})")
        generation = hdf5_text(f.attribute("generation"))

        vertices = f.array("mesh/vertices", "f", tail=(3,)).astype(float)
        faces = f.array("mesh/faces", "iu").astype(np.int64)
        vertex_part = f.array("mesh/part", "iu").astype(np.int64)
        if len(vertex_part) != len(vertices):
            raise f.fail(f"'/mesh/part' has {len(vertex_part)} entries for {len(vertices)} vertices")
        if len(vertex_part) and (vertex_part.max() >= n_parts or vertex_part.min() < 0):
            raise f.fail(f"'/mesh/part' names part {vertex_part.max()} but the model has {n_parts} parts")
        colors: np.ndarray | None = None
        if f.has("mesh/colors"):
            colors = f.array("mesh/colors", "iu", tail=(3,))
            if len(colors) != len(vertices) or (colors.size and (colors.min() < 0 or colors.max() > 255)):
                raise f.fail("'/mesh/colors' must hold one sRGB triple (0-255) per vertex")
            colors = colors.astype(np.uint8)
        regions: dict[str, InfluenceRegion] = {}
        for p in tree:
            base = f"parameters/{p.name}"
            if not f.has(base):
                raise f.fail(f"missing HDF5 group '/{base}' for parameter '{p.name}'")
            idx = f.array(f"{base}/indices", "iu").astype(np.int64)
            w = f.array(f"{base}/weights", "f").astype(float)
            disp = f.array(f"{base}/displacements", "f", tail=(3,)).astype(float) if p.field else None
            try:
                regions[p.name] = InfluenceRegion(idx, w, disp)
            except UserError as exc:
                raise f.fail(f"parameter '{p.name}': {exc.message}") from None
        texture = _read_texture(f, faces, len(vertices)) if version >= 2 and f.has("texture") else None
    return vertices, faces, vertex_part, regions, colors, generation, texture


def _read_texture(f: HDF5Reader, faces: np.ndarray, n_vertices: int) -> ModelTexture:
    """The ``/texture`` group: corner coordinates, each polygon's image, the images (raw RGB(A) pixels)."""
    corner_uv = f.array("texture/corner_uv", "f", tail=(2,)).astype(float)
    face_image = f.array("texture/face_image", "iu").astype(np.int64)
    names = f.strings("texture/image_names")
    images: list[TextureImage] = []
    for index, name in enumerate(names):
        node = f"texture/images/{index}"
        pixels = f.array(node, "u", ndim=3)
        if pixels.dtype != np.uint8:
            raise f.fail(f"dataset '/{node}' holds {pixels.dtype} pixels, expected 8-bit (uint8)")
        try:
            images.append(TextureImage(name, pixels))
        except UserError as exc:
            raise f.fail(exc.message) from None
    if f.has(f"texture/images/{len(names)}"):
        raise f.fail(f"'/texture/images' holds more images than the {len(names)} names in '/texture/image_names'")
    texture = ModelTexture(corner_uv, images, face_image)
    try:
        check_cell_array(faces, n_vertices)
        texture.check(faces)
    except UserError as exc:
        raise f.fail(exc.message) from None
    return texture


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
    arrays_content = _arrays_of(model)
    unmarked = model_to_xml(model, arrays_name)     # a UserError here, before the arrays are written
    generation = save_generation(unmarked, arrays_content)
    _write_arrays(arrays_content, arrays, generation)
    Path(description).write_bytes(model_to_xml(model, arrays_name, generation))


def save_generation(description: bytes, arrays: list[tuple[str, np.ndarray, dict[str, Any]]]) -> str:
    """The token that marks the two files of one save: a digest of their contents (16 hex digits).

    Written as ``generation`` on ``<model>`` and as the arrays file's root
    attribute; a description whose token differs from its arrays file's was
    not saved with it, and :func:`load_model` refuses the pair. Derived from
    the contents, so saving the same model twice gives the same bytes.
    """
    digest = hashlib.sha256(description)
    for name, data, _ in sorted(arrays, key=lambda item: item[0]):     # in any order the model lists them
        digest.update(f"\0{name}\0{data.dtype.str}\0{data.shape}\0".encode())
        digest.update(np.ascontiguousarray(data).tobytes())
    return digest.hexdigest()[:16]


def model_to_xml(model: Model, arrays_name: str, generation: str | None = None) -> bytes:
    """The model description (format version :data:`VERSION`) naming ``arrays_name`` as its arrays file.

    ``generation``: the token of :func:`save_generation` shared with the arrays file, if any.
    """
    root = etree.Element("model", format=FORMAT, version=str(VERSION), name=_xml_text(model.name, "the model name"),
                         arrays=arrays_name, units="mm")
    if generation is not None:
        root.set("generation", generation)
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
    if model.identity is not None:
        ident = etree.SubElement(root, "identity", source=_xml_text(model.identity.source, "the identity's source"))
        for name, value in model.identity.values.items():
            etree.SubElement(ident, "value", name=_xml_text(name, "an identity parameter name"), value=repr(value))
        write_drawn(ident, model.identity)
        write_hair(ident, model.identity)
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


def _arrays_of(model: Model) -> list[tuple[str, np.ndarray, dict[str, Any]]]:
    """Every dataset of the arrays file, in file order: ``(path, data, h5py storage options)``."""
    packed: dict[str, Any] = {"compression": "gzip", "shuffle": True}
    out: list[tuple[str, np.ndarray, dict[str, Any]]] = [
        ("mesh/vertices", np.asarray(model.vertices), packed),
        ("mesh/faces", np.asarray(model.faces), packed),
        ("mesh/part", model.vertex_part.astype(np.int32), {"compression": "gzip"}),
    ]
    if model.vertex_colors is not None:
        out.append(("mesh/colors", np.asarray(model.vertex_colors), {"compression": "gzip"}))
    if model.texture is not None:
        # Images as raw pixels, deflated: read back through the same shape and size checks as every other
        # array, with no image decoder between a hostile file and us, and bit for bit what was saved.
        texture = model.texture
        out.append(("texture/corner_uv", texture.corner_uv, packed))
        out.append(("texture/face_image", texture.face_image.astype(np.int32), {"compression": "gzip"}))
        out.append(("texture/image_names", np.array([i.name.encode("ascii") for i in texture.images], dtype="S"), {}))
        out.extend((f"texture/images/{index}", image.pixels, {"compression": "gzip", "compression_opts": 6})
                   for index, image in enumerate(texture.images))
    for p in model.parameters:
        r = model.regions[p.name]
        out.append((f"parameters/{p.name}/indices", r.indices.astype(np.int64), {}))
        out.append((f"parameters/{p.name}/weights", np.asarray(r.weights), {}))
        if r.displacements is not None:
            out.append((f"parameters/{p.name}/displacements", np.asarray(r.displacements), {}))
    return out


def _write_arrays(arrays: list[tuple[str, np.ndarray, dict[str, Any]]], path: str | Path, generation: str) -> None:
    with h5py.File(path, "w", track_order=True) as f:
        f.attrs["format"] = ARRAYS_FORMAT
        f.attrs["version"] = VERSION
        f.attrs["units"] = "mm"
        f.attrs["generation"] = generation
        f.create_group("mesh")
        f.create_group("parameters", track_order=True)
        for name, data, storage in arrays:
            group, _, leaf = name.rpartition("/")
            if group not in f:
                f.create_group(group)
            f[group].create_dataset(leaf, data=data, **storage)
