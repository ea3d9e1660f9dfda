"""Writing files so that a failure never leaves a half-written file behind.

Everything the toolkit writes (models, poses, pictures, command files,
tracks) goes through :func:`atomic_write_bytes` or :func:`atomic_write_text`:
the data go to a temporary file beside the target, which is then renamed over
it. A crash, a full disk or a bad value half-way leaves the old file intact.

>>> from engine.formats.atomic import atomic_write_text
>>> atomic_write_text("/tmp/example.txt", "hello\\n")            # doctest: +SKIP
"""

from __future__ import annotations

import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

from engine.errors import UserError


def atomic_write_text(path: str | Path, text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    atomic_write_bytes(path, text.encode("utf-8"))


@contextmanager
def atomic_path(path: str | Path, error: type[UserError] = UserError):
    """A temporary path beside ``path`` to write a file to (e.g. with h5py); renamed over ``path`` on success.

    >>> with atomic_path("/tmp/out.h5") as tmp:                      # doctest: +SKIP
    ...     with h5py.File(tmp, "w") as f: ...

    If the block raises, the temporary file is removed and ``path`` is untouched;
    an ``OSError`` (disk full, permissions) becomes ``error`` naming ``path``.
    """
    path = Path(path)
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise error("cannot write: the folder does not exist", file=path)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise error(f"cannot write: {exc.strerror or exc}", file=path) from None
    os.close(fd)
    try:
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the file the usual permissions
        yield tmp
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        _unlink_quietly(tmp)
        raise error(f"cannot write: {exc.strerror or exc}", file=path) from None
    except BaseException:
        _unlink_quietly(tmp)
        raise


def atomic_write_bytes(path: str | Path, data: bytes) -> None:
    """Write ``data`` to a temporary file beside ``path``, then rename it over ``path``."""
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        fh.write(data)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _unlink_quietly(path: str) -> None:
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
