"""Writing files so that a failure never leaves a half-written file behind.

Everything the toolkit writes (models, poses, pictures, videos, command
files, tables) goes through :func:`atomic_files`, or through
:func:`atomic_path`, :func:`atomic_write_bytes` and :func:`atomic_write_text`,
which are built on it. The data go to temporary files beside the targets
(hidden names, ``.<name>.<random>.tmp``); when every one is complete, each is
flushed to the disk (``fsync``) and renamed over its target. An error, a full
disk or Ctrl-C half-way leaves the old files intact and no temporary file
behind. New files get the usual permissions (``0666`` less the umask), as a
plain ``open`` would give them.

>>> import tempfile
>>> from pathlib import Path
>>> folder = Path(tempfile.mkdtemp())
>>> with atomic_files([folder / "a.txt", folder / "b.txt"]) as temporary:
...     for target, path in temporary.items():
...         _ = path.write_text(f"this is {target.name}\\n")
>>> sorted(p.name for p in folder.iterdir()), (folder / "b.txt").read_text()
(['a.txt', 'b.txt'], 'this is b.txt\\n')
>>> atomic_write_text(folder / "a.txt", "hello\\n")
>>> (folder / "a.txt").read_text()
'hello\\n'
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from engine.errors import UserError

#: How many random names to try before giving up on a folder (a clash is already a one-in-4-billion event).
NAME_ATTEMPTS = 100


@contextmanager
def atomic_files(paths: Iterable[str | Path], error: type[UserError] = UserError) -> Iterator[dict[Path, Path]]:
    """Write several files together: a temporary path for each target, renamed over it when the block succeeds.

    Yields ``{Path(target): temporary path}`` in the order given; the block
    writes each temporary file (it exists, empty, when the block starts, so
    a writer may open it for writing or replace it). When the block ends
    without an exception, every temporary file is flushed to the disk and
    then renamed over its target, in the order given. If the block raises
    anything (``KeyboardInterrupt`` included), every temporary file is
    removed and every target is untouched.

    An ``OSError`` (a folder that does not exist, a full disk, permissions),
    in the block or while renaming, becomes ``error`` (a
    :class:`~engine.errors.UserError` subclass) naming the target it concerns.
    Renaming is atomic for each file, not for the set: should the disk fail
    between two renames, the files renamed so far are complete new files,
    and the others are their complete old selves.
    """
    targets = [Path(p) for p in paths]
    if len(set(targets)) != len(targets):
        raise error("cannot write the same file twice in one go",
                    file=next(t for t in targets if targets.count(t) > 1))
    for target in targets:
        if not _folder(target).is_dir():
            raise error("cannot write: the folder does not exist", file=target)
        if target.is_dir():
            raise error("cannot write: this is a folder", file=target)
    temporaries: dict[Path, Path] = {}
    current: Path | None = targets[0] if targets else None
    try:
        for target in targets:
            current = target
            temporaries[target] = _new_temporary(target)
        current = None
        yield dict(temporaries)
        for target, temporary in temporaries.items():
            current = target
            _fsync(temporary)
        for target, temporary in list(temporaries.items()):
            current = target
            os.replace(temporary, target)
            del temporaries[target]
        for folder in {_folder(target) for target in targets}:
            _fsync_folder(folder)
    except OSError as exc:
        _remove(temporaries.values())
        where = current or _target_of(exc, temporaries) or (targets[0] if targets else None)
        raise error(f"cannot write: {exc.strerror or exc}", file=where) from None
    except BaseException:
        _remove(temporaries.values())
        raise


@contextmanager
def atomic_path(path: str | Path, error: type[UserError] = UserError) -> Iterator[str]:
    """A temporary file name beside ``path`` to write a file to (e.g. with h5py); renamed over ``path`` on success.

    >>> with atomic_path("/tmp/out.h5") as tmp:                      # doctest: +SKIP
    ...     with h5py.File(tmp, "w") as f: ...

    :func:`atomic_files` for one file: if the block raises, the temporary file
    is removed and ``path`` is untouched; an ``OSError`` (disk full,
    permissions) becomes ``error`` naming ``path``.
    """
    target = Path(path)
    with atomic_files([target], error) as temporary:
        yield str(temporary[target])


def atomic_write_bytes(path: str | Path, data: bytes, error: type[UserError] = UserError) -> None:
    """Write ``data`` to ``path`` atomically (see :func:`atomic_files`)."""
    target = Path(path)
    with atomic_files([target], error) as temporary:
        temporary[target].write_bytes(data)


def atomic_write_text(path: str | Path, text: str, error: type[UserError] = UserError) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically (see :func:`atomic_files`)."""
    atomic_write_bytes(path, text.encode("utf-8"), error)


def _folder(path: Path) -> Path:
    return path.parent if str(path.parent) else Path(".")


def _new_temporary(target: Path) -> Path:
    """A new empty file beside ``target`` with a hidden random name.

    Created with mode 0666 (not ``mkstemp``'s 0600): the kernel then applies
    the umask (and any default ACL) exactly as for a plain ``open``, without
    this process changing its umask, which other threads may be relying on.
    """
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    for _ in range(NAME_ATTEMPTS):
        candidate = _folder(target) / f".{target.name}.{secrets.token_hex(4)}.tmp"
        try:
            os.close(os.open(candidate, flags, 0o666))
        except FileExistsError:
            continue
        return candidate
    raise FileExistsError(f"no free temporary name after {NAME_ATTEMPTS} attempts")


def _fsync(path: Path) -> None:
    with open(path, "rb") as handle:
        os.fsync(handle.fileno())


def _fsync_folder(folder: Path) -> None:
    """Make the renames durable; some file systems cannot sync a folder, which costs only durability."""
    try:
        handle = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        with contextlib.suppress(OSError):
            os.fsync(handle)
    finally:
        os.close(handle)


def _target_of(exc: OSError, temporaries: dict[Path, Path]) -> Path | None:
    """The target whose temporary file ``exc`` names, if any."""
    named = {str(os.fspath(n)) for n in (exc.filename, exc.filename2) if isinstance(n, (str, os.PathLike))}
    return next((target for target, temporary in temporaries.items() if str(temporary) in named), None)


def _remove(paths: Iterable[Path]) -> None:
    for path in list(paths):
        with contextlib.suppress(FileNotFoundError):
            os.unlink(path)
