"""Reading HDF5 files that may be damaged or hostile: local, bounded, and every failure a :class:`UserError`.

The toolkit's HDF5 files (model arrays, motion-capture sessions, articulation
files) hold plain datasets in plain groups. A file from elsewhere may hold
more, and HDF5 would follow it: a soft or external link (to a loop, or to
another file), a dataset whose data live in other files on the disk
(*external storage*) or that is assembled from other files (a *virtual
dataset*), a shape of 10¹² elements that the library would fill in from a
fill value, a damaged heap or object header. :class:`HDF5Reader` refuses all
of these, checks a dataset's kind, rank and size **before** reading it, and
turns any error of the HDF5 library into the caller's error class, naming
the file. Before any of that, the whole file is read once in a child process
with a time limit (:mod:`engine.formats.hdf5_probe`), so a file on which the
library itself hangs or crashes is refused instead (files shipped with the
program are trusted and skip this).

Size bound: a dataset may not declare more bytes than its file could hold
after decompression. Deflate cannot shrink data more than about 1032 : 1,
so :data:`MAX_EXPANSION` × the file's size (plus :data:`SLACK_BYTES`) is
more than any file written with the filters we accept can hold; anything
larger can only come from unwritten chunks or a forged header.

>>> import tempfile, numpy as np
>>> from engine.errors import ModelFileError
>>> path = f"{tempfile.mkdtemp()}/a.h5"
>>> with h5py.File(path, "w") as f:
...     _ = f.create_dataset("mesh/vertices", data=np.zeros((4, 3)))
>>> with HDF5Reader(path, ModelFileError) as reader:
...     reader.array("mesh/vertices", "f", tail=(3,)).shape
(4, 3)
"""

from __future__ import annotations

import math
from pathlib import Path
from types import TracebackType

import h5py
import numpy as np

from engine.errors import UserError
from engine.formats.hdf5_probe import ProbeFailed, probe_in_child
from engine.paths import DATA_DIR

#: Bytes a dataset may declare per byte of its file (deflate's ceiling is about 1032).
MAX_EXPANSION = 1100
#: Bytes any dataset may declare whatever the file's size (small files, uncompressed headers).
SLACK_BYTES = 1 << 20
#: The filters a dataset may use: the ones h5py writes everywhere (deflate, shuffle, Fletcher-32 checksums).
ALLOWED_FILTERS = {1: "deflate", 2: "shuffle", 3: "fletcher32"}
_KIND_NAMES = {"f": "floating-point numbers", "i": "integers", "u": "integers", "b": "true/false values"}


class HDF5Reader:
    """An HDF5 file opened for reading, where every surprise becomes ``error`` naming the file.

    Use as a context manager; errors raised inside the ``with`` block by
    the HDF5 library (``OSError``, ``KeyError``, ``RuntimeError``, …) are
    turned into ``error`` too, so a damaged file never escapes as a
    traceback. ``not_hdf5`` is the message for a file HDF5 cannot open.
    """

    def __init__(self, path: str | Path, error: type[UserError],
                 not_hdf5: str = "not a readable HDF5 file") -> None:
        self.path = Path(path)
        self.error = error
        self._not_hdf5 = not_hdf5
        self._file: h5py.File | None = None
        self.budget = SLACK_BYTES

    def __enter__(self) -> HDF5Reader:
        try:
            size = self.path.stat().st_size
        except OSError as exc:
            raise self.error(f"cannot read: {exc.strerror or exc}", file=self.path) from None
        self.budget = SLACK_BYTES + MAX_EXPANSION * size
        try:
            is_hdf5 = h5py.is_hdf5(self.path)
        except Exception:            # a file that cannot be read at all
            is_hdf5 = False
        if not is_hdf5:
            raise self.error(self._not_hdf5, file=self.path)
        if not _shipped(self.path):
            try:
                probe_in_child(self.path, self.budget, frozenset(ALLOWED_FILTERS))
            except ProbeFailed as exc:
                raise self.error(f"damaged HDF5 file: {exc.reason}", file=self.path) from None
            except OSError as exc:       # no process could be started to read it (out of memory, limits)
                raise self.error(f"cannot check the file: no process to read it in ({exc.strerror or exc})",
                                 file=self.path) from None
        try:
            self._file = h5py.File(self.path, "r")
        except Exception:            # h5py reports a damaged superblock in many ways
            raise self.error(self._not_hdf5, file=self.path) from None
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None,
                 traceback: TracebackType | None) -> None:
        file, self._file = self._file, None
        try:
            if file is not None:
                file.close()
        except Exception:            # closing a damaged file may fail too
            if exc is None:
                raise self.error("damaged HDF5 file (it cannot be closed cleanly)", file=self.path) from None
        if exc is None or isinstance(exc, UserError) or not isinstance(exc, Exception):
            return                   # ours, or Ctrl-C / SystemExit: let it through as it is
        raise self.error(f"damaged HDF5 file ({_describe(exc)})", file=self.path) from None

    @property
    def file(self) -> h5py.File:
        if self._file is None:
            raise RuntimeError("HDF5Reader used outside its with block")
        return self._file

    def fail(self, message: str) -> UserError:
        """The error to raise for ``message`` (``raise reader.fail("...")``)."""
        return self.error(message, file=self.path)

    # -- objects ---------------------------------------------------------------------

    def has(self, name: str) -> bool:
        """True if ``/name`` exists, reached through hard links only (soft and external links are refused)."""
        return self._walk(name, missing_ok=True) is not None

    def group(self, name: str) -> h5py.Group:
        node = self._walk(name)
        if not isinstance(node, h5py.Group):
            raise self.fail(f"'/{name}' is not a group")
        return node

    def dataset(self, name: str) -> h5py.Dataset:
        """The dataset ``/name``, after checking its data live in this file, in a way we can read."""
        node = self._walk(name)
        if not isinstance(node, h5py.Dataset):
            raise self.fail(f"'/{name}' is not a dataset")
        plist = node.id.get_create_plist()
        if plist.get_layout() == h5py.h5d.VIRTUAL:
            raise self.fail(f"dataset '/{name}' is a virtual dataset (its data would come from other files); "
                            "refused")
        if plist.get_external_count() > 0:
            raise self.fail(f"dataset '/{name}' keeps its data in external files; refused")
        for index in range(plist.get_nfilters()):
            code = plist.get_filter(index)[0]
            if code not in ALLOWED_FILTERS:
                raise self.fail(f"dataset '/{name}' uses HDF5 filter {code}, which this program does not read "
                                f"(it reads {', '.join(sorted(ALLOWED_FILTERS.values()))})")
        return node

    def attribute(self, key: str, node: str = "") -> object:
        """The attribute ``key`` of ``/node`` (the root by default), or None."""
        target = self.file if not node else self._walk(node)
        if target is None:
            raise self.fail(f"missing HDF5 object '/{node}'")
        return target.attrs.get(key, None)

    # -- data ------------------------------------------------------------------------

    def array(self, name: str, kinds: str, ndim: int | None = None, tail: tuple[int, ...] | None = None,
              shape: tuple[int, ...] | None = None, allow_nan: bool = False) -> np.ndarray:
        """Dataset ``/name`` read whole, after checking its kind, rank and size; never a copy larger than the file.

        ``kinds``: numpy kind letters it may hold (``"f"`` floats, ``"iu"``
        integers, ``"b"`` booleans; integers are accepted where floats are).
        ``tail``: the shape after the first axis; ``shape``: the whole shape;
        ``ndim`` the rank (from ``tail`` or ``shape`` if given; 1 otherwise).
        Floating-point data must be finite (``allow_nan``: NaN, "missing",
        is allowed; infinities never are).
        """
        data = self.dataset(name)
        allowed = kinds + ("iu" if "f" in kinds else "")
        if data.dtype.kind not in allowed:
            what = " or ".join(dict.fromkeys(_KIND_NAMES[k] for k in kinds))
            raise self.fail(f"dataset '/{name}' does not hold numbers of the right kind: it holds "
                            f"{_dtype_text(data.dtype)}, expected {what}")
        found = tuple(int(n) for n in data.shape) if data.shape is not None else ()
        if shape is not None:
            fits, wanted = found == tuple(shape), str(tuple(shape))
        elif tail is not None:
            fits = len(found) == 1 + len(tail) and found[1:] == tuple(tail)
            wanted = f"(n, {', '.join(map(str, tail))})"
        else:
            rank = ndim or 1
            fits, wanted = len(found) == rank, "one dimension" if rank == 1 else f"{rank} dimensions"
        if not fits:
            raise self.fail(f"dataset '/{name}' has shape {found}, expected {wanted}")
        self._check_size(name, found, data.dtype.itemsize)
        arr = np.asarray(data[()])
        if arr.dtype.kind == "f" and not np.all(np.isfinite(arr)):
            if not allow_nan:
                raise self.fail(f"dataset '/{name}' holds values that are not finite numbers (NaN or infinite)")
            if np.any(np.isinf(arr)):
                raise self.fail(f"dataset '/{name}' holds infinite values")
        return arr

    def strings(self, name: str) -> list[str]:
        """A one-dimensional dataset of text (variable- or fixed-length strings) as a list of ``str``."""
        data = self.dataset(name)
        if h5py.check_string_dtype(data.dtype) is None and data.dtype.kind not in "SU":
            raise self.fail(f"dataset '/{name}' holds {_dtype_text(data.dtype)}, expected text")
        found = tuple(int(n) for n in data.shape) if data.shape is not None else ()
        if len(found) != 1:
            raise self.fail(f"dataset '/{name}' has shape {found}, expected a list of names")
        self._check_size(name, found, data.dtype.itemsize)
        return [text(v) or "" for v in np.asarray(data[()]).tolist()]

    def text(self, name: str) -> str:
        """A scalar text dataset as ``str``."""
        data = self.dataset(name)
        if h5py.check_string_dtype(data.dtype) is None and data.dtype.kind not in "SU":
            raise self.fail(f"dataset '/{name}' holds {_dtype_text(data.dtype)}, expected text")
        if data.shape != ():
            raise self.fail(f"dataset '/{name}' has shape {data.shape}, expected one text")
        return text(data[()]) or ""

    # -- inside ----------------------------------------------------------------------

    def _walk(self, name: str, missing_ok: bool = False) -> h5py.Group | h5py.Dataset | None:
        node: h5py.Group | h5py.Dataset = self.file
        walked = ""
        for part in (p for p in name.split("/") if p):
            walked += "/" + part
            if not isinstance(node, h5py.Group):
                raise self.fail(f"'{walked.rsplit('/', 1)[0]}' is not a group")
            link = node.get(part, getlink=True)
            if link is None:
                if missing_ok:
                    return None
                raise self.fail(f"missing HDF5 {'dataset' if walked == '/' + name.strip('/') else 'group'} "
                                f"'{walked}'")
            if isinstance(link, h5py.ExternalLink):
                raise self.fail(f"'{walked}' is an external link to another file ({link.filename}); refused")
            if isinstance(link, h5py.SoftLink):
                raise self.fail(f"'{walked}' is a soft link ({link.path}); this program writes none and "
                                "follows none")
            if not isinstance(link, h5py.HardLink):
                raise self.fail(f"'{walked}' is a link of a kind this program does not follow")
            child = node[part]
            if not isinstance(child, (h5py.Group, h5py.Dataset)):
                raise self.fail(f"'{walked}' is neither a group nor a dataset")
            node = child
        return node

    def _check_size(self, name: str, shape: tuple[int, ...], itemsize: int) -> None:
        declared = math.prod(shape) * max(int(itemsize), 1)
        if declared > self.budget:
            raise self.fail(f"dataset '/{name}' declares {declared:,} bytes ({shape}), more than a file of "
                            f"{self.path.stat().st_size:,} bytes can hold; refused")


def _shipped(path: Path) -> bool:
    """True for the files shipped with the program (the default head), which need no probe."""
    try:
        return path.resolve().is_relative_to(DATA_DIR.resolve())
    except OSError:
        return False


def text(value: object) -> str | None:
    """An HDF5 string (attribute or element) as ``str``; h5py may give ``bytes``."""
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return text(value[()])
    return None if value is None else str(value)


def _dtype_text(dtype: np.dtype) -> str:
    if dtype.kind == "V":
        return "compound or opaque data"
    if dtype.kind == "O":
        return "variable-length data"
    return _KIND_NAMES.get(dtype.kind, f"data of type {dtype}")


def _describe(exc: BaseException) -> str:
    message = " ".join(str(exc).split())
    if len(message) > 160:
        message = message[:157] + "..."
    return f"{type(exc).__name__}: {message}" if message else type(exc).__name__
