"""Opening the versioned HDF5 files of the motion-capture pipeline (sessions, articulation files).

The file is read through :class:`engine.formats.hdf5_reading.HDF5Reader`:
links to other files, external storage, virtual datasets, oversized shapes
and any damage the HDF5 library reports become the caller's error class,
naming the file. Before opening, the file's folder is cleared of what a
killed writer left (:func:`engine.formats.atomic.finish_interrupted_writes`).

>>> from engine.mocap.errors import SessionFileError
>>> from engine.mocap.hdf5_files import open_versioned
>>> with open_versioned("take.h5", "artificial-person-mocap-session", 1, SessionFileError,
...                     "a motion-capture session", "mocap import") as f: ...   # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from engine.errors import UserError
from engine.formats.atomic import finish_interrupted_writes
from engine.formats.hdf5_reading import HDF5Reader
from engine.formats.hdf5_reading import text as text_attribute

__all__ = ["open_versioned", "text_attribute"]


@contextmanager
def open_versioned(path: str | Path, fmt: str, version: int, error: type[UserError], what: str,
                   writer: str) -> Iterator[HDF5Reader]:
    """Open ``path`` for reading after checking its ``format`` and ``version`` attributes.

    Raises ``error`` (a :class:`~engine.errors.UserError` subclass) naming the
    file for a missing or unreadable file, another format, another version,
    or anything the HDF5 library reports while the block reads it. ``what``
    names the kind of file ("a motion-capture session"), ``writer`` the verb
    that writes it ("mocap import").
    """
    path = Path(path)
    finish_interrupted_writes(path.parent)
    if not path.exists():
        raise error("no such file", file=path)
    with HDF5Reader(path, error, f"not a readable HDF5 file (is it {what} written by '{writer}'?)") as reader:
        found = text_attribute(reader.attribute("format"))
        if found != fmt:
            raise error(f"not {what} (format attribute is {found!r}, expected '{fmt}')", file=path)
        try:
            found_version = int(reader.attribute("version"))  # type: ignore[call-overload]
        except (TypeError, ValueError):
            raise error("the file has no valid 'version' attribute", file=path) from None
        if found_version != version:
            raise error(f"{what} format version {found_version} is not one this program reads "
                        f"(it reads version {version})", file=path)
        yield reader
