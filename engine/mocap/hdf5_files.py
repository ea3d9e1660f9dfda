"""Opening the versioned HDF5 files of the motion-capture pipeline (sessions, articulation files).

>>> from engine.mocap.errors import SessionFileError
>>> from engine.mocap.hdf5_files import open_versioned
>>> with open_versioned("take.h5", "artificial-person-mocap-session", 1, SessionFileError,
...                     "a motion-capture session", "mocap import") as f: ...   # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

import h5py

from engine.errors import UserError


def open_versioned(path: str | Path, fmt: str, version: int, error: type[UserError], what: str,
                   writer: str) -> h5py.File:
    """Open ``path`` for reading after checking its ``format`` and ``version`` attributes.

    Raises ``error`` (a :class:`~engine.errors.UserError` subclass) naming the
    file for a missing or unreadable file, another format, or another version.
    ``what`` names the kind of file ("a motion-capture session"), ``writer``
    the verb that writes it ("mocap import").
    """
    path = Path(path)
    if not path.exists():
        raise error("no such file", file=path)
    try:
        f = h5py.File(path, "r")
    except OSError:
        raise error(f"not a readable HDF5 file (is it {what} written by '{writer}'?)", file=path) from None
    try:
        found = text_attribute(f.attrs.get("format"))
        if found != fmt:
            raise error(f"not {what} (format attribute is {found!r}, expected '{fmt}')", file=path)
        try:
            found_version = int(f.attrs.get("version"))
        except (TypeError, ValueError):
            raise error("the file has no valid 'version' attribute", file=path) from None
        if found_version != version:
            raise error(f"{what} format version {found_version} is not one this program reads "
                        f"(it reads version {version})", file=path)
    except BaseException:
        f.close()
        raise
    return f


def text_attribute(value: object) -> str | None:
    """An HDF5 string attribute as ``str`` (h5py may give ``bytes``)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    return None if value is None else str(value)
