"""Reading a user's input file whole, with a bound: no ``/dev/zero``, no endless pipe, no 40 GB log.

Every text format the toolkit reads whole (command files, library files,
tracks tables, label files, scripts) goes through :func:`read_bounded_bytes`
or :func:`read_bounded_text`. They refuse, with a :class:`~engine.errors.UserError`
(or the subclass the caller names) that names the file:

* a path that is not a regular file (a folder, a device such as ``/dev/zero``,
  a named pipe) — checked before the file is opened, so a pipe with no writer
  cannot block;
* a file larger than ``limit`` bytes (:data:`MAX_TEXT_BYTES` unless the caller
  says otherwise) — at most ``limit + 1`` bytes are ever read, even from a
  file that grows while it is read;
* a name the system cannot take (too long, a NUL byte) or cannot read.

>>> read_bounded_bytes("/dev/zero")
Traceback (most recent call last):
engine.errors.UserError: /dev/zero: not a regular file (a device, folder or pipe cannot be read as input)
>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "big.xml"
>>> _ = path.write_bytes(b"x" * 2000)
>>> read_bounded_bytes(path, limit=1000)                          # doctest: +ELLIPSIS
Traceback (most recent call last):
engine.errors.UserError: .../big.xml: file too large: 2000 bytes, at most 1000 are read
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

from engine.errors import UserError

MAX_TEXT_BYTES = 100_000_000
"""The largest text file read whole (100 MB): a command file or tracks table of hours of animation
is a few MB; anything larger is a mistake (a wrong file, a device)."""


def read_bounded_bytes(path: str | Path, limit: int = MAX_TEXT_BYTES, error: type[UserError] = UserError,
                       what: str = "file") -> bytes:
    """The bytes of the regular file ``path``, refusing anything else or anything above ``limit`` bytes."""
    shown = str(path)
    try:
        info = os.stat(path)
    except (OSError, ValueError) as exc:
        raise error(_reason(exc, what), file=shown) from None
    if not stat.S_ISREG(info.st_mode):
        raise error("not a regular file (a device, folder or pipe cannot be read as input)", file=shown)
    if info.st_size > limit:
        raise error(_too_large(info.st_size, limit), file=shown)
    try:
        with open(path, "rb") as stream:
            data = stream.read(limit + 1)
    except (OSError, ValueError) as exc:
        raise error(_reason(exc, what), file=shown) from None
    if len(data) > limit:
        raise error(_too_large(len(data), limit, grew=True), file=shown)
    return data


def read_bounded_text(path: str | Path, limit: int = MAX_TEXT_BYTES, error: type[UserError] = UserError,
                      what: str = "file", encoding: str = "utf-8-sig") -> str:
    """The text of ``path`` (UTF-8 by default, a byte-order mark dropped), bounded as :func:`read_bounded_bytes`.

    Bytes that are not valid in ``encoding`` are an error naming the line they are on.
    """
    data = read_bounded_bytes(path, limit, error, what)
    try:
        return data.decode(encoding)
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise error(f"cannot read the {what}: it is not {encoding.removesuffix('-sig').upper()} text "
                    f"(byte {exc.start + 1}: {exc.reason})", file=str(path), line=line) from None


def _reason(exc: OSError | ValueError, what: str) -> str:
    if isinstance(exc, ValueError):               # e.g. "embedded null byte"
        return f"cannot read the {what}: {exc}"
    if exc.errno == errno.ENOENT:
        return "no such file"
    if exc.errno == errno.ENAMETOOLONG:
        return "the file name is too long for the system"
    return f"cannot read the {what}: {exc.strerror or exc}"


def _too_large(size: int, limit: int, grew: bool = False) -> str:
    shown = f"more than {limit} bytes (it grew while being read)" if grew else f"{size} bytes"
    return f"file too large: {shown}, at most {limit} are read"
