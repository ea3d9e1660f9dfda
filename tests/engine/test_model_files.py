"""Model files, format version 2 (version 1 read too): XML description + HDF5 arrays (docs/model-format.md).

Round trips are exact (bytes of the XML, every HDF5 dataset, every attribute
of the model, and the deformations); saves are atomic; every error a user can
cause is a :class:`ModelFileError` whose ``str()`` starts with
``<file>:<line>:`` (XML) or ``<file>:`` (HDF5), as the command line prints it;
hostile XML is never expanded.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

import h5py
import numpy as np
import pytest

import engine.formats.atomic as atomic
import engine.formats.model_files as model_files
from engine import ModelFileError, UserError, load_model, save_model
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree
from tests.engine.synthetic import assert_models_equal, random_model, random_values

# ---------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------


def small_model() -> Model:
    """A hand-made model: 6 vertices, 2 parts, 5 parameters of every kind, 2 landmarks."""
    vertices = np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [10, 10, 0], [0, 0, 10], [5, 5, 5.5]])
    faces = [3, 0, 1, 2, 3, 2, 3, 4, 4, 1, 2, 4, 5]
    tree = ParameterTree([
        Parameter("head_turn", "rotation", axis=(0, 1, 0), pivot=(0, 0, 0), degrees_per_unit=57.29577951308232,
                  description="Head turn; value in radians."),
        Parameter("jaw_open", "rotation", parent="head_turn", minimum=-0.2, maximum=1.0, axis=(1, 0, 0),
                  pivot=(0, 10, 5), degrees_per_unit=20.0),
        Parameter("lip_raise", "translation", parent="jaw_open", default=0.25, direction=(0, 2.5, 0)),
        Parameter("smile", "translation", parent="jaw_open", field=True, minimum=0.0, maximum=1.5),
        Parameter("brow_raise", "rotation", parent="head_turn", axis=(-1, 0, 0), pivot=(0, 16.6, 6.2),
                  degrees_per_unit=5.3, description="Brows up along the forehead's curve (§2.2.1)."),
    ])
    regions = {
        "head_turn": InfluenceRegion([0, 1, 2, 3, 5], [1.0, 1.0, 0.5, 1.0, 0.25]),
        "jaw_open": InfluenceRegion([2, 4], [0.5, 1.0]),
        "lip_raise": InfluenceRegion([4], [0.75]),
        "smile": InfluenceRegion([1, 4], [1.0, 0.5], [[1.0, 2.0, 3.0], [-0.5, 0.25, 0.0]]),
        "brow_raise": InfluenceRegion([0, 5], [0.3, 1.0]),
    }
    return Model(vertices, faces, ["skin", "teeth_lower"], [0, 0, 0, 0, 1, 1], tree, regions,
                 {"2.1": 3, "9.3": 0}, name="small", description="A small hand-made model.",
                 part_colors={"skin": "#e3b49c"})


def h5_contents(path: Path) -> list:
    """Every group and dataset with dtype, shape, bytes and attributes, in file order."""
    def attrs(obj):
        return {k: np.asarray(v).tolist() for k, v in obj.attrs.items()}

    with h5py.File(path, "r") as f:
        out = [("/", attrs(f))]

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                data = obj[()]
                out.append((name, obj.dtype.str, data.shape, data.tobytes(), attrs(obj)))
            else:
                out.append((name, "group", attrs(obj)))
        f.visititems(visit)
    return out


def line_of(text: str, needle: str) -> int:
    """1-based line number of the one line containing ``needle``."""
    hits = [i + 1 for i, line in enumerate(text.splitlines()) if needle in line]
    assert len(hits) == 1, f"{needle!r} is on lines {hits}"
    return hits[0]


@pytest.fixture
def saved(tmp_path) -> Path:
    return save_model(small_model(), tmp_path / "small.xml")


def files_in(folder: Path) -> set[str]:
    return {p.name for p in folder.iterdir()}


# ---------------------------------------------------------------------------
# Round trips
# ---------------------------------------------------------------------------

ROUND_TRIP_MODELS = [("small", None)] + [(f"random-{s}", s) for s in range(6)]


def _model(seed) -> Model:
    if seed is None:
        return small_model()
    rng = np.random.default_rng(seed)
    return random_model(rng, int(rng.integers(5, 60)), int(rng.integers(1, 10)), int(rng.integers(1, 5)),
                        partial=bool(seed % 2), nonzero_defaults=True)


@pytest.mark.parametrize("label,seed", ROUND_TRIP_MODELS)
def test_save_load_save_is_byte_identical(tmp_path, label, seed):
    first = save_model(_model(seed), tmp_path / "a" / "m.xml")
    second = save_model(load_model(first), tmp_path / "b" / "m.xml")
    assert first.read_bytes() == second.read_bytes()
    assert h5_contents(first.with_suffix(".h5")) == h5_contents(second.with_suffix(".h5"))


@pytest.mark.parametrize("label,seed", ROUND_TRIP_MODELS)
def test_load_save_load_gives_identical_model_and_deformations(tmp_path, label, seed):
    original = _model(seed)
    first = load_model(save_model(original, tmp_path / "a" / "m.xml"))
    # A model built in code may list its parameters in another order than the file's
    # depth-first tree order; everything else survives the first save exactly.
    assert_models_equal(original, first, order=False)
    second = load_model(save_model(first, tmp_path / "b" / "m.xml"))
    assert_models_equal(first, second, order=True)
    rng = np.random.default_rng(0 if seed is None else seed)
    for _ in range(5):
        values = random_values(rng, first)
        assert np.array_equal(first.deform(values), second.deform(values))
        np.testing.assert_allclose(original.deform(values), first.deform(values), rtol=0, atol=1e-12)


def test_saved_files_follow_format_version_2(saved):
    text = saved.read_text(encoding="utf-8")
    assert text.startswith("<?xml version='1.0' encoding='UTF-8'?>\n<model ")
    assert 'format="artificial-person-model" version="2"' in text
    assert 'arrays="small.h5" units="mm"' in text
    with h5py.File(saved.with_suffix(".h5"), "r") as f:
        assert f.attrs["format"] == "artificial-person-arrays"
        assert int(f.attrs["version"]) == 2
        assert f["mesh/vertices"].shape == (6, 3) and f["mesh/vertices"].dtype == np.float64
        assert f["mesh/faces"].dtype == np.int64 and f["mesh/faces"].ndim == 1
        assert f["mesh/part"].shape == (6,)
        assert list(f["parameters"]) == ["head_turn", "jaw_open", "lip_raise", "smile", "brow_raise"]
        assert f["parameters/smile/displacements"].shape == (2, 3)
        assert "displacements" not in f["parameters/lip_raise"]


def test_save_adds_xml_suffix_and_creates_folders(tmp_path):
    path = save_model(small_model(), tmp_path / "deep" / "folder" / "head")
    assert path == tmp_path / "deep" / "folder" / "head.xml"
    assert files_in(path.parent) == {"head.xml", "head.h5"}


def test_load_from_a_folder_with_one_description(saved, tmp_path):
    assert_models_equal(load_model(tmp_path), load_model(saved))
    (tmp_path / "other.xml").write_text("<x/>")
    with pytest.raises(ModelFileError, match="exactly one"):
        load_model(tmp_path)


def test_load_missing_file_names_it(tmp_path):
    with pytest.raises(ModelFileError) as err:
        load_model(tmp_path / "nothing.xml")
    assert str(err.value).startswith(f"{tmp_path / 'nothing.xml'}:")


# ---------------------------------------------------------------------------
# Atomic saves
# ---------------------------------------------------------------------------

class Boom(RuntimeError):
    pass


def test_failed_arrays_write_leaves_previous_files_and_no_temporaries(saved, monkeypatch):
    folder = saved.parent
    before = {name: (folder / name).read_bytes() for name in files_in(folder)}
    real = model_files._write_arrays

    def half_then_fail(arrays, tmp, generation):
        real(arrays, tmp, generation)
        with h5py.File(tmp, "a") as f:       # the temporary file is really half written
            del f["parameters"]
        raise Boom("disk full")

    monkeypatch.setattr(model_files, "_write_arrays", half_then_fail)
    changed = small_model()
    changed.vertices[:] += 1.0
    with pytest.raises(Boom):
        save_model(changed, saved)
    assert files_in(folder) == set(before)
    assert {name: (folder / name).read_bytes() for name in before} == before
    assert_models_equal(load_model(saved), small_model())


def test_failed_xml_write_leaves_previous_description_and_no_temporaries(saved, monkeypatch):
    folder = saved.parent
    old_xml = saved.read_bytes()
    real = Path.write_bytes

    def half_then_fail(self, data):
        real(self, data[: len(data) // 2])
        raise Boom("disk full")

    monkeypatch.setattr(Path, "write_bytes", half_then_fail)
    model = small_model()
    model.description = "changed"
    with pytest.raises(Boom):
        save_model(model, saved)
    monkeypatch.undo()
    assert files_in(folder) == {"small.xml", "small.h5"}
    assert saved.read_bytes() == old_xml


def test_failed_rename_leaves_previous_files_and_no_temporaries(saved, monkeypatch):
    folder = saved.parent
    before = {name: (folder / name).read_bytes() for name in files_in(folder)}

    def refuse(src, dst):
        raise Boom("rename refused")

    monkeypatch.setattr(atomic.os, "replace", refuse)
    with pytest.raises(Boom):
        save_model(small_model(), saved)
    monkeypatch.undo()
    assert {name: (folder / name).read_bytes() for name in files_in(folder)} == before


def test_failed_xml_write_leaves_the_previous_model_loadable(saved, monkeypatch):
    """The pair is written completely under temporary names before either is renamed into
    place. (Regression: save_model used to rename the new .h5 over the old one before writing
    the XML, so a failure there left the old description beside the new arrays.)"""
    real = Path.write_bytes

    def half_then_fail(self, data):
        real(self, data[: len(data) // 2])
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_bytes", half_then_fail)
    changed = small_model()
    changed.vertices[:] += 1.0
    with pytest.raises(ModelFileError, match="No space left on device"):   # the OSError, naming the file
        save_model(changed, saved)
    monkeypatch.undo()
    assert_models_equal(load_model(saved), small_model())


def test_unsavable_description_is_a_user_error_and_damages_nothing(saved):
    """A control character (fine in a Python str, impossible in XML) is a UserError, raised
    before anything is written. (Regression: it used to be lxml's ValueError, raised after the
    .h5 had already been replaced.)"""
    changed = small_model()
    changed.vertices[:] += 1.0
    changed.description = "bad \x01 byte"
    with pytest.raises(UserError):
        save_model(changed, saved)
    assert files_in(saved.parent) == {"small.xml", "small.h5"}
    assert_models_equal(load_model(saved), small_model())


def test_saved_files_get_normal_permissions(tmp_path):
    """The temporary file behind an atomic save (``mkstemp``, mode 0600) must not make the
    saved model private: the files follow the umask like any other write."""
    old = os.umask(0o022)
    try:
        path = save_model(small_model(), tmp_path / "m.xml")
    finally:
        os.umask(old)
    for p in (path, path.with_suffix(".h5")):
        assert stat.S_IMODE(p.stat().st_mode) == 0o644, oct(p.stat().st_mode)


# ---------------------------------------------------------------------------
# XML errors carry file and line
# ---------------------------------------------------------------------------

# (id, text to replace, replacement, text on the line the error must name — in the broken file,
#  or in the file before the edit with "before:" — and words the message must contain)
XML_ERRORS = [
    ("missing attribute", 'name="jaw_open" type="rotation" min="-0.2" ', 'name="jaw_open" type="rotation" ',
     'name="jaw_open"', "min"),
    ("wrong type", 'name="jaw_open" type="rotation" min="-0.2" max="1.0"',
     'name="jaw_open" type="rotation" min="-0.2" max="wide"', 'name="jaw_open"', "wide"),
    ("unknown element", "  <parts>\n", "  <parts>\n    <wobble/>\n", "<wobble/>", "wobble"),
    ("bad vector", 'axis="1.0 0.0 0.0" pivot="0.0 10.0 5.0"', 'axis="1.0 0.0" pivot="0.0 10.0 5.0"',
     'axis="1.0 0.0"', "axis"),
    ("duplicate parameter", 'name="brow_raise"', 'name="lip_raise"', 'before:name="brow_raise"', "defined twice"),
    ("type/element mismatch", 'name="lip_raise" type="translation"', 'name="lip_raise" type="rotation"',
     'name="lip_raise"', "<translation>"),
    ("missing transform element", '        <translation direction="0.0 2.5 0.0"/>\n', "",
     'name="lip_raise"', "Missing child"),
    ("malformed XML", "  </parts>", "  </partz>", "</partz>", "malformed XML"),
    ("unquoted attribute", '<part name="teeth_lower"/>', "<part name=teeth_lower/>", "name=teeth_lower",
     "malformed XML"),
    ("landmark out of range", '<landmark id="2.1" vertex="3"', '<landmark id="2.1" vertex="999"',
     'id="2.1"', "999"),
    ("negative landmark", '<landmark id="9.3" vertex="0"', '<landmark id="9.3" vertex="-1"', 'id="9.3"', "-1"),
    ("duplicate landmark", '<landmark id="9.3"', '<landmark id="2.1"', 'vertex="0"', "defined twice"),
    ("newer version", 'version="2" name="small"', 'version="3" name="small"', "<model ", "newer"),
    ("minimum above maximum", 'name="jaw_open" type="rotation" min="-0.2"', 'name="jaw_open" type="rotation" min="2"',
     'name="jaw_open"', "above maximum"),
    ("translation without direction", '<translation direction="0.0 2.5 0.0"/>', "<translation/>",
     "<translation/>", "direction"),
    ("duplicate part", '<part name="teeth_lower"/>', '<part name="skin"/>', '<part name="skin"/>', "twice"),
    ("bad colour", 'color="#e3b49c"', 'color="pink"', 'color="pink"', "pink"),
    ("wrong format name", 'format="artificial-person-model"', 'format="something-else"', "<model ", "format"),
]


@pytest.mark.parametrize("label,old,new,needle,words", XML_ERRORS, ids=[e[0] for e in XML_ERRORS])
def test_xml_errors_name_file_and_line(saved, label, old, new, needle, words):
    text = saved.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    broken = text.replace(old, new)
    saved.write_text(broken, encoding="utf-8")
    if needle.startswith("before:"):
        line = line_of(text, needle.removeprefix("before:"))
    else:
        line = line_of(broken, needle)
    with pytest.raises(ModelFileError) as err:
        load_model(saved)
    assert err.value.file == str(saved)
    assert err.value.line == line, str(err.value)
    assert str(err.value).startswith(f"{saved}:{line}: "), str(err.value)
    assert words in err.value.message
    assert "\n" not in str(err.value)


def test_wrong_root_element_is_named_with_its_line(saved):
    text = saved.read_text(encoding="utf-8").replace("<model ", "<modle ").replace("</model>", "</modle>")
    saved.write_text(text, encoding="utf-8")
    with pytest.raises(ModelFileError, match="not a model description") as err:
        load_model(saved)
    assert str(err.value).startswith(f"{saved}:2: ")


def test_xml_error_of_an_empty_file(tmp_path):
    path = tmp_path / "empty.xml"
    path.write_bytes(b"")
    with pytest.raises(ModelFileError) as err:
        load_model(path)
    assert str(err.value).startswith(f"{path}:")


@pytest.mark.parametrize("version", ["+3", " 3 "])
def test_newer_version_is_refused_however_it_is_spelled(saved, version):
    """xs:positiveInteger accepts '+2' and ' 2 '. (Regression: the reader's version.isdigit()
    check let them through and read the file as version 1.)"""
    text = saved.read_text(encoding="utf-8")
    saved.write_text(text.replace('version="2" name="small"', f'version="{version}" name="small"'))
    with pytest.raises(ModelFileError, match="newer") as err:
        load_model(saved)
    assert str(err.value).startswith(f"{saved}:2: ")


def test_field_attribute_is_read_like_the_schema_validates_it(saved):
    """xs:boolean collapses white space, so field=' true' is valid and means true.
    (Regression: the reader compared the raw string and took it as false.)"""
    text = saved.read_text(encoding="utf-8")
    saved.write_text(text.replace('field="true"', 'field=" true"'))
    assert load_model(saved).parameters["smile"].field


def test_parameter_names_the_file_cannot_hold_are_refused_up_front():
    """The schema's name pattern is ``[A-Za-z_][A-Za-z0-9_.-]*``. (Regression: Parameter took
    any non-empty name, and save_model wrote files that load_model then refused.)"""
    for bad in ("jaw open", "1st", "", "a/b", "lip<"):
        with pytest.raises(UserError):
            Parameter(bad, "rotation")


BAD_MODEL_TEXT = [
    ("part name with a space", dict(parts=["lower teeth"])),
    ("part colour not #rrggbb", dict(part_colors={"surface": "red"})),
    ("landmark id with a control character", dict(landmarks={"2.1\x01": 0})),
]


@pytest.mark.parametrize("label,kw", BAD_MODEL_TEXT, ids=[b[0] for b in BAD_MODEL_TEXT])
def test_what_saves_also_loads(tmp_path, label, kw):
    """Either the model (or the save) refuses the value with a UserError and writes nothing,
    or the file it writes loads back. (Regression: Model accepted part names and colours the
    schema refuses, and a landmark id with a control character made save_model raise lxml's
    ValueError.)"""
    try:
        model = Model(np.eye(3), [3, 0, 1, 2], **kw)
        path = save_model(model, tmp_path / "m.xml")
    except UserError:
        assert list(tmp_path.iterdir()) == []
        return
    assert_models_equal(load_model(path), model)


def test_round_trip_keeps_a_diagonal_axis(tmp_path):
    """(Regression: Parameter divided its axis by its norm on every construction, which is not
    idempotent in floating point — (1, 1, 0) went 0.7071067811865475 → …476 → … — so a loaded
    model differed from the saved one in the last bit and saves were not byte-identical.)"""
    model = small_model()
    model.parameters.replace(model.parameters["jaw_open"].copy(axis=np.array([1.0, 1.0, 0.0])))
    model.changed()
    first = save_model(model, tmp_path / "a" / "m.xml")
    loaded = load_model(first)
    second = save_model(loaded, tmp_path / "b" / "m.xml")
    assert first.read_bytes() == second.read_bytes()
    assert np.array_equal(loaded.parameters["jaw_open"].axis, model.parameters["jaw_open"].axis)
    assert np.array_equal(model.copy().parameters["jaw_open"].axis, model.parameters["jaw_open"].axis)


# ---------------------------------------------------------------------------
# HDF5 errors name the arrays file
# ---------------------------------------------------------------------------

def _delete(name):
    def edit(f):
        del f[name]
    return edit


def _replace(name, data):
    def edit(f):
        del f[name]
        f[name] = data
    return edit


def _set_attr(key, value):
    def edit(f):
        f.attrs[key] = value
    return edit


H5_ERRORS = [
    ("missing vertices", _delete("mesh/vertices"), "/mesh/vertices"),
    ("missing faces", _delete("mesh/faces"), "/mesh/faces"),
    ("missing parameter group", _delete("parameters/jaw_open"), "jaw_open"),
    ("missing weights", _delete("parameters/jaw_open/weights"), "weights"),
    ("missing displacements", _delete("parameters/smile/displacements"), "displacements"),
    ("vertices wrong shape", _replace("mesh/vertices", np.zeros((6, 2))), "shape"),
    ("faces wrong shape", _replace("mesh/faces", np.zeros((2, 4), dtype=np.int64)), "shape"),
    ("displacements wrong shape", _replace("parameters/smile/displacements", np.zeros((2, 4))), "shape"),
    ("part labels wrong length", _replace("mesh/part", np.zeros(5, dtype=np.int32)), "/mesh/part"),
    ("part label unknown", _replace("mesh/part", np.full(6, 7, dtype=np.int32)), "part"),
    ("weights and indices differ", _replace("parameters/jaw_open/weights", np.ones(3)), "jaw_open"),
    ("weight above 1", _replace("parameters/jaw_open/weights", np.array([0.5, 2.0])), "weights"),
    ("region outside mesh", _replace("parameters/jaw_open/indices", np.array([2, 60])), "outside"),
    ("face outside mesh", _replace("mesh/faces", np.array([3, 0, 1, 60])), "outside"),
    ("wrong format attribute", _set_attr("format", "something-else"), "format"),
    ("no format attribute", lambda f: f.attrs.__delitem__("format"), "format"),
    ("newer version", _set_attr("version", 3), "version 3"),
    ("group in place of a dataset", lambda f: (f.__delitem__("mesh/faces"), f.create_group("mesh/faces")),
     "not a dataset"),
]


@pytest.mark.parametrize("label,edit,words", H5_ERRORS, ids=[e[0] for e in H5_ERRORS])
def test_hdf5_errors_name_the_arrays_file(saved, label, edit, words):
    arrays = saved.with_suffix(".h5")
    with h5py.File(arrays, "a") as f:
        edit(f)
    with pytest.raises(ModelFileError) as err:
        load_model(saved)
    assert Path(err.value.file) == arrays.resolve()
    assert str(err.value).startswith(f"{err.value.file}: "), str(err.value)
    assert words in err.value.message


def test_arrays_file_that_is_not_hdf5(saved):
    arrays = saved.with_suffix(".h5")
    arrays.write_text("these are not the arrays you are looking for\n")
    with pytest.raises(ModelFileError, match="HDF5") as err:
        load_model(saved)
    assert Path(err.value.file) == arrays.resolve()
    assert str(err.value).startswith(f"{err.value.file}: ")


def test_arrays_file_missing(saved):
    arrays = saved.with_suffix(".h5")
    arrays.unlink()
    with pytest.raises(ModelFileError, match="does not exist") as err:
        load_model(saved)
    assert Path(err.value.file) == arrays.resolve()
    assert str(err.value).startswith(f"{err.value.file}: ")


# ---------------------------------------------------------------------------
# Hostile XML is not expanded
# ---------------------------------------------------------------------------

BILLION_LAUGHS = """<!DOCTYPE model [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
 <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
 <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
 <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
 <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
"""
PASSWD = '<!DOCTYPE model [ <!ENTITY xxe SYSTEM "file:///etc/passwd"> ]>\n'
SMALL_INTERNAL = '<!DOCTYPE model [ <!ENTITY hello "hello"> ]>\n'


def _with_doctype(saved: Path, doctype: str, old: str, new: str) -> None:
    text = saved.read_text(encoding="utf-8")
    head, rest = text.split("\n", 1)
    assert rest.count(old) == 1
    saved.write_text(head + "\n" + doctype + rest.replace(old, new), encoding="utf-8")


def _load_without_expansion(saved: Path, forbidden: str) -> None:
    """Loading may fail, but no string it produces may contain the expansion."""
    try:
        model = load_model(saved)
    except Exception as exc:
        texts = [str(exc)]
    else:
        texts = [model.name, model.description] + [p.description for p in model.parameters]
    assert all(forbidden not in t for t in texts)


@pytest.mark.parametrize("where", ["element", "attribute"])
def test_billion_laughs_is_not_expanded(saved, where):
    old, new = (("<description>A small hand-made model.</description>", "<description>&lol9;</description>")
                if where == "element" else ('name="small"', 'name="&lol9;"'))
    _with_doctype(saved, BILLION_LAUGHS, old, new)
    with pytest.raises(ModelFileError) as err:
        load_model(saved)
    assert str(err.value).startswith(f"{saved}:")
    _load_without_expansion(saved, "lollollol")


@pytest.mark.parametrize("where", ["element", "attribute"])
def test_external_entity_is_not_read(saved, where):
    old, new = (("<description>A small hand-made model.</description>", "<description>&xxe;</description>")
                if where == "element" else ('name="small"', 'name="&xxe;"'))
    _with_doctype(saved, PASSWD, old, new)
    _load_without_expansion(saved, "root:")


def test_external_entity_in_an_attribute_is_a_model_file_error(saved):
    _with_doctype(saved, PASSWD, 'name="small"', 'name="&xxe;"')
    with pytest.raises(ModelFileError) as err:
        load_model(saved)
    assert str(err.value).startswith(f"{saved}:")


@pytest.mark.parametrize("doctype,entity", [(PASSWD, "&xxe;"), (SMALL_INTERNAL, "&hello;")],
                         ids=["external", "internal"])
def test_entity_reference_in_element_content_is_a_model_file_error(saved, doctype, entity):
    """Entity references stay unexpanded, and lxml's schema validator cannot handle the
    reference nodes (XMLSchemaValidateError, "Internal error in XML Schema validation"); the
    loader must turn that into a ModelFileError naming the file, not let lxml's error out."""
    _with_doctype(saved, doctype, "<description>A small hand-made model.</description>",
                  f"<description>{entity}</description>")
    with pytest.raises(ModelFileError) as err:
        load_model(saved)
    assert str(err.value).startswith(f"{saved}:")
