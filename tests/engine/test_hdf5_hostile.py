"""Hostile and damaged HDF5 input (issue 16 §4): model arrays, mocap sessions, articulation files.

A file may point outside itself (external links, external storage, virtual
datasets), loop (soft links), declare a shape no file could hold, carry
NaN/infinite numbers or the wrong kind of data, or be damaged anywhere. Each
reader must refuse it with its own error class naming the file — never read
another file on the disk, never raise KeyError/RuntimeError/OSError, never
allocate what the file cannot hold.

The fuzz tests mutate the bytes of a small valid file of each kind
(hypothesis) and load it: only the format's error may escape, and its
message names the file. ``AP_FUZZ_EXAMPLES`` sets the number of inputs per
format (200 by default; the release check runs 10000, see docs/model-format.md).
"""

from __future__ import annotations

import os
import tempfile
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import h5py
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from engine import ModelFileError, load_model, save_model
from engine.errors import UserError
from engine.mocap.articulation_file import ArticulationFileError, load_articulation_file, save_articulation_file
from engine.mocap.errors import SessionFileError
from engine.mocap.pca import Articulation
from engine.mocap.session import Session, load_session, save_session
from tests.engine.test_model_files import small_model

FUZZ_EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "200"))
SECRET = b"the contents of some other file on the disk\n" * 4


def small_session() -> Session:
    f, m = 5, 3
    positions = np.arange(f * m * 3, dtype=float).reshape(f, m, 3)
    positions[2, 1] = np.nan
    missing = np.zeros((f, m), bool)
    missing[2, 1] = True
    return Session(markers=["2.1", "8.3", "8.4"], positions=positions, raw=positions.copy(), rate_hz=60,
                   missing=missing, alignment=np.tile(np.eye(4), (f, 1, 1)), phones=[(0.0, 40.0, "a")],
                   source="take.tsv", report={"gaps": 1}, reference=["2.1"])


def small_articulation() -> Articulation:
    rng = np.random.default_rng(3)
    return Articulation(markers=["2.1", "8.3", "8.4"], mean=rng.normal(size=(3, 3)),
                        components=rng.normal(size=(2, 3, 3)), explained_variance_ratio=np.array([0.6, 0.3]),
                        stages=np.array([1, 2]), stage_markers=[["2.1"], ["8.3", "8.4"]],
                        score_std=np.array([1.0, 0.5]), n_frames=50, excluded_missing=0, selection="all",
                        rate_hz=60.0, source="take.h5")


class Kind:
    """One HDF5 file format: how to write a valid file, the HDF5 file to attack, and how to load it."""

    def __init__(self, name: str, error: type[UserError], write: Callable[[Path], Path],
                 arrays: Callable[[Path], Path], load: Callable[[Path], object], dataset: str) -> None:
        self.name, self.error, self.write, self.arrays, self.load = name, error, write, arrays, load
        self.dataset = dataset          # a float dataset of the format, (n, 3) or (n, m, 3)


KINDS = [
    Kind("model", ModelFileError, lambda folder: save_model(small_model(), folder / "m.xml"),
         lambda written: written.with_suffix(".h5"), load_model, "mesh/vertices"),
    Kind("session", SessionFileError, lambda folder: (save_session(small_session(), folder / "s.h5"),
                                                      folder / "s.h5")[1],
         lambda written: written, load_session, "positions"),
    Kind("articulation", ArticulationFileError,
         lambda folder: save_articulation_file(small_articulation(), folder / "a.h5"),
         lambda written: written, load_articulation_file, "components"),
]


@pytest.fixture(params=KINDS, ids=[k.name for k in KINDS])
def kind(request) -> Kind:
    return request.param


def refuse(kind: Kind, written: Path, *words: str) -> UserError:
    """Load ``written``: it must raise the kind's error, naming the HDF5 file, with every one of ``words``."""
    with pytest.raises(kind.error) as caught:
        kind.load(written)
    arrays = kind.arrays(written)
    assert caught.value.file is not None and Path(caught.value.file).resolve() == arrays.resolve(), str(caught.value)
    assert str(caught.value).startswith(f"{caught.value.file}: ")
    for word in words:
        assert word in caught.value.message, caught.value.message
    return caught.value


def replace_dataset(path: Path, name: str, make: Callable[[h5py.File, str], object]) -> None:
    with h5py.File(path, "a") as f:
        del f[name]
        make(f, name)


# -- pointing outside the file ----------------------------------------------------------

def test_an_external_link_to_another_file_is_refused(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    other = tmp_path / "elsewhere.h5"
    with h5py.File(arrays, "r") as f, h5py.File(other, "w") as g:
        g.create_dataset("data", data=f[kind.dataset][()] + 1000.0)        # would load fine if followed
    replace_dataset(arrays, kind.dataset, lambda f, name: f.__setitem__(name, h5py.ExternalLink(str(other), "data")))
    refuse(kind, written, "external link", "refused")


def test_external_storage_that_would_read_another_file_is_refused(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    secret = tmp_path / "secret.bin"
    secret.write_bytes(SECRET)
    with h5py.File(arrays, "r") as f:
        shape = f[kind.dataset].shape
    replace_dataset(arrays, kind.dataset, lambda f, name: f.create_dataset(
        name, shape=shape, dtype=np.uint8, external=[(str(secret), 0, h5py.h5f.UNLIMITED)]))
    refuse(kind, written, "external files", "refused")


def test_a_virtual_dataset_is_refused(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    other = tmp_path / "source.h5"
    with h5py.File(arrays, "r") as f, h5py.File(other, "w") as g:
        data = f[kind.dataset][()]
        g.create_dataset("data", data=data)
    layout = h5py.VirtualLayout(shape=data.shape, dtype=data.dtype)
    layout[...] = h5py.VirtualSource(str(other), "data", shape=data.shape)
    replace_dataset(arrays, kind.dataset, lambda f, name: f.create_virtual_dataset(name, layout))
    refuse(kind, written, "virtual dataset", "refused")


def test_soft_links_and_their_loops_are_refused(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    replace_dataset(arrays, kind.dataset, lambda f, name: (f.__setitem__(name, h5py.SoftLink("/loop_b")),
                                                         f.__setitem__("loop_b", h5py.SoftLink(f"/{name}"))))
    refuse(kind, written, "soft link")


def test_a_soft_link_to_a_real_dataset_is_refused_too(tmp_path, kind):
    """We write no soft links; following one means reading what the file's author chose, not what we wrote."""
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    with h5py.File(arrays, "a") as f:
        f.move(kind.dataset, "moved")
        f[kind.dataset] = h5py.SoftLink("/moved")
    refuse(kind, written, "soft link")


# -- sizes, kinds and values -------------------------------------------------------------

def test_a_shape_no_file_could_hold_is_refused_before_reading(tmp_path, kind):
    """10⁹ rows, no chunk written: HDF5 would fill 24 GB with the fill value (a hang, then MemoryError)."""
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    with h5py.File(arrays, "r") as f:
        tail = f[kind.dataset].shape[1:]
    replace_dataset(arrays, kind.dataset, lambda f, name: f.create_dataset(
        name, shape=(10**9, *tail), dtype=float, chunks=(1024, *tail)))
    refuse(kind, written, "declares", "bytes", "refused")
    assert arrays.stat().st_size < 100_000


@pytest.mark.parametrize("value", [np.inf, -np.inf, np.nan])
def test_non_finite_numbers_are_refused(tmp_path, kind, value):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    with h5py.File(arrays, "a") as f:
        data = f[kind.dataset][()]
        data.flat[1] = value
        f[kind.dataset][...] = data
    if kind.name == "session" and np.isnan(value):
        assert np.isnan(kind.load(written).positions.flat[1])      # NaN is a missing sample there
        return
    refuse(kind, written, "finite" if np.isnan(value) or kind.name != "session" else "infinite")


def test_a_displacement_field_must_be_finite(tmp_path):
    written = save_model(small_model(), tmp_path / "m.xml")
    with h5py.File(written.with_suffix(".h5"), "a") as f:
        f["parameters/smile/displacements"][0, 1] = np.inf
    refuse(KINDS[0], written, "/parameters/smile/displacements", "finite")


@pytest.mark.parametrize("label,make", [
    ("text", lambda f, name: f.create_dataset(name, data=np.array(["a", "b", "c"], dtype=object),
                                              dtype=h5py.string_dtype())),
    ("compound", lambda f, name: f.create_dataset(name, data=np.zeros(3, dtype=[("x", "f8"), ("y", "i4")]))),
    ("scalar", lambda f, name: f.create_dataset(name, data=1.0)),
    ("empty", lambda f, name: f.create_dataset(name, data=h5py.Empty("f8"))),
])
def test_the_wrong_kind_of_data_is_refused(tmp_path, kind, label, make):
    written = kind.write(tmp_path)
    replace_dataset(kind.arrays(written), kind.dataset, make)
    refuse(kind, written, kind.dataset)


def test_a_filter_we_do_not_read_is_refused(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    with h5py.File(arrays, "r") as f:
        data = f[kind.dataset][()]
    replace_dataset(arrays, kind.dataset, lambda f, name: f.create_dataset(name, data=data, compression="lzf"))
    refuse(kind, written, "filter 32000")


def test_a_truncated_file_is_the_formats_error(tmp_path, kind):
    written = kind.write(tmp_path)
    arrays = kind.arrays(written)
    data = arrays.read_bytes()
    for keep in (0, 8, 100, len(data) // 2, len(data) - 1):
        arrays.write_bytes(data[:keep])
        refuse(kind, written)


# -- fuzzing -------------------------------------------------------------------------------

FUZZ_COUNTS: dict[str, Counter[str]] = {}
_FUZZ_FOLDER = Path(tempfile.mkdtemp(prefix="ap-hdf5-fuzz-"))


def _fuzz_source(kind: Kind) -> tuple[Path, bytes]:
    folder = _FUZZ_FOLDER / kind.name
    folder.mkdir(exist_ok=True)
    written = kind.write(folder)
    return written, kind.arrays(written).read_bytes()


edits = st.lists(st.tuples(st.integers(0, 2**31), st.integers(0, 255)), min_size=1, max_size=8)
cuts = st.one_of(st.none(), st.integers(0, 2**31))


@pytest.mark.parametrize("kind", KINDS, ids=[k.name for k in KINDS])
def test_mutated_bytes_give_only_the_formats_error(kind):
    written, original = _fuzz_source(kind)
    arrays = kind.arrays(written)
    counts = FUZZ_COUNTS.setdefault(kind.name, Counter())

    @settings(max_examples=FUZZ_EXAMPLES, deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow])
    @given(edits=edits, cut=cuts)
    def load_mutated(edits, cut):
        data = bytearray(original)
        for position, value in edits:
            data[position % len(data)] = value
        if cut is not None:
            del data[cut % (len(data) + 1):]
        arrays.write_bytes(bytes(data))
        counts["inputs"] += 1
        refused: UserError | None = None
        try:
            kind.load(written)
        except kind.error as exc:
            refused = exc
        counts["refused" if refused else "loaded"] += 1
        if refused is not None and "did not finish" in refused.message:
            counts["hangs stopped"] += 1
        if refused is not None and "crashed" in refused.message:
            counts["crashes contained"] += 1
        if refused is not None:
            assert refused.file is not None and Path(refused.file).name in (written.name, arrays.name), str(refused)
            assert str(refused).startswith(f"{refused.file}: ")

    load_mutated()
    print(f"\n{kind.name}: {counts['inputs']} mutated inputs, {counts['refused']} refused with "
          f"{kind.error.__name__} (of which the library hung on {counts['hangs stopped']} and crashed on "
          f"{counts['crashes contained']}, stopped in the child), {counts['loaded']} loaded, 0 other exceptions")
    assert counts["inputs"] >= FUZZ_EXAMPLES


def test_a_file_the_hdf5_library_hangs_on_is_refused(tmp_path, monkeypatch):
    """Found by fuzzing: one byte of a global heap object's size (the "mm" of the ``units`` attribute,
    2 → 193) sends HDF5 into an endless loop reading a string attribute. The file is read in a child
    process first, which is stopped after the time limit."""
    written = save_model(small_model(), tmp_path / "m.xml")
    arrays = written.with_suffix(".h5")
    data = bytearray(arrays.read_bytes())
    size_of_mm = data.find(b"\x02\x00\x00\x00\x00\x00\x00\x00mm\x00")
    assert size_of_mm > 0
    data[size_of_mm] = 0xC1
    arrays.write_bytes(bytes(data))
    monkeypatch.setenv("AP_HDF5_PROBE_SECONDS", "2")
    refuse(KINDS[0], written, "did not finish", "hangs")


def test_a_crash_of_the_library_while_reading_is_the_formats_error(tmp_path, monkeypatch):
    """The child that reads the file first dies of a real SIGSEGV here (as the library would on a file
    it crashes on): the load is refused, the program goes on."""
    import signal

    from engine.formats import hdf5_probe

    written = save_model(small_model(), tmp_path / "m.xml")
    monkeypatch.setattr(hdf5_probe, "_one_thread", lambda: True)
    monkeypatch.setattr(hdf5_probe, "read_everything", lambda *_: os.kill(os.getpid(), signal.SIGSEGV))
    refuse(KINDS[0], written, "crashed", f"signal {int(signal.SIGSEGV)}")


@pytest.mark.parametrize("where", ["helper", "fresh interpreter"])
def test_the_probe_away_from_here_reads_good_files_and_stops_hanging_ones(tmp_path, monkeypatch, where):
    """Where forking is not safe (threads, a Qt application) the file is read by a reader the helper
    forks, or, where no helper can be had, by a new interpreter."""
    from engine.formats import hdf5_probe, hdf5_probe_helper

    monkeypatch.setattr(hdf5_probe, "_one_thread", lambda: False)
    if where == "fresh interpreter":
        monkeypatch.setattr(hdf5_probe_helper, "ask_helper", lambda *_: None)
    written = save_model(small_model(), tmp_path / "m.xml")
    assert load_model(written).n_vertices == 6
    data = bytearray(written.with_suffix(".h5").read_bytes())
    data[data.find(b"\x02\x00\x00\x00\x00\x00\x00\x00mm\x00")] = 0xC1
    written.with_suffix(".h5").write_bytes(bytes(data))
    monkeypatch.setenv("AP_HDF5_PROBE_SECONDS", "2")
    refuse(KINDS[0], written, "did not finish")
