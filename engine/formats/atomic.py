"""Writing files so that a failure, or a kill, never leaves a half-written file or a mixed set behind.

Everything the toolkit writes (models, poses, pictures, videos, command
files, tables) goes through :func:`atomic_files`, or through
:func:`atomic_path`, :func:`atomic_write_bytes` and :func:`atomic_write_text`,
which are built on it. The data go to temporary files beside the targets
(hidden names, ``.<name>.<host>-<pid>-<random>.tmp``); when every one is
complete, each is flushed to the disk (``fsync``) and renamed over its
target. An error, a full disk or Ctrl-C half-way leaves the old files intact
and no temporary file behind. New files get the usual permissions (``0666``
less the umask), as a plain ``open`` would give them.

Several files written together are renamed under a *journal*
(``.<first name>.<host>-<pid>-<random>.journal`` beside the first target),
written and flushed before the first rename and removed after the last: a
process killed between two renames (``kill -9``, a power cut) leaves the
journal, and :func:`finish_interrupted_writes` — which every write and every
model load runs on the folders it touches — completes the renames, so the set
ends up all new, never mixed. It also removes temporary files whose writing
process is gone. A file is judged by the host and process id in its name:
files of a live process, of this process, or of another host are left alone.

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
import hashlib
import json
import os
import re
import secrets
import socket
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from engine.errors import UserError

#: How many random names to try before giving up on a folder (a clash is already a one-in-4-billion event).
NAME_ATTEMPTS = 100
JOURNAL_FORMAT = "artificial-person-rename-journal"
JOURNAL_VERSION = 1

#: This host, as it appears in temporary names: processes of other hosts (a shared folder) are never judged.
HOST_TAG = hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:6]
_OWNED_NAME = re.compile(r"^\.(?P<name>.+)\.(?P<host>[0-9a-f]{6})-(?P<pid>[0-9]+)-[0-9a-f]{8}\.(?P<kind>tmp|journal)$")


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
    With several targets the renames are recorded in a journal first, so a
    process killed between two renames leaves a set that the next write to
    the folder, or the next model load, completes (see the module notes).
    Should a rename fail with an error (not a kill), the files renamed so far
    are complete new files and the others their complete old selves.
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
    folders = list(dict.fromkeys(_folder(target) for target in targets))
    for folder in folders:
        finish_interrupted_writes(folder)
    temporaries: dict[Path, Path] = {}
    journal: Path | None = None
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
        current = targets[0] if targets else None
        if len(temporaries) > 1:
            journal = _write_journal(targets[0], temporaries)
        for target, temporary in list(temporaries.items()):
            current = target
            os.replace(temporary, target)
            del temporaries[target]
        for folder in folders:
            _fsync_folder(folder)
        if journal is not None:
            _remove([journal])
    except OSError as exc:
        _remove(temporaries.values())
        if journal is not None:
            _remove([journal])
        where = current or _target_of(exc, temporaries) or (targets[0] if targets else None)
        raise error(f"cannot write: {exc.strerror or exc}", file=where) from None
    except BaseException:
        _remove(temporaries.values())
        if journal is not None:
            _remove([journal])
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


def finish_interrupted_writes(folder: str | Path) -> list[Path]:
    """Complete the renames of sets whose writer was killed, and remove its temporary files; the paths touched.

    Looks only at the hidden files :func:`atomic_files` names
    (``.<name>.<host>-<pid>-<random>.tmp`` / ``.journal``) that this user
    owns and whose process, on this host, is gone. A complete journal's renames are done (each temporary
    file still there is renamed over its target, unless the target was
    written after the journal, by a program that does not keep journals); a
    journal that was being written when the process died (nothing was renamed
    yet) is dropped. Then the dead processes' remaining temporary files are
    removed. Never raises for a file it cannot touch (a read-only folder, a
    race with another cleaner): that file stays for a later attempt.

    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> dead = folder / f".head.h5.{HOST_TAG}-999999999-0123abcd.tmp"    # no process has this id
    >>> _ = dead.write_bytes(b"half")
    >>> [p.name for p in finish_interrupted_writes(folder)] == [dead.name], list(folder.iterdir())
    (True, [])
    """
    folder = Path(folder)
    touched: list[Path] = []
    owned = _dead_owners_files(folder)
    for journal in (p for p in owned if p.name.endswith(".journal")):
        touched += _replay_journal(journal)
        if _remove_quietly(journal):
            touched.append(journal)
    for temporary in (p for p in owned if p.name.endswith(".tmp")):
        if temporary.exists() and _remove_quietly(temporary):
            touched.append(temporary)
    return touched


def _dead_owners_files(folder: Path) -> list[Path]:
    """The files of :func:`atomic_files`' naming in ``folder`` whose process (on this host) no longer runs."""
    try:
        names = [entry.name for entry in os.scandir(folder) if entry.name.startswith(".")]
    except OSError:
        return []
    found = []
    for name in sorted(names):
        match = _OWNED_NAME.match(name)
        if match and match["host"] == HOST_TAG and _ours(folder / name) and not _process_runs(int(match["pid"])):
            found.append(folder / name)
    return found


def _ours(path: Path) -> bool:
    """True if this user owns ``path``: another user's files in a shared folder are never renamed or removed."""
    getuid = getattr(os, "getuid", None)
    try:
        return getuid is None or path.lstat().st_uid == getuid()
    except OSError:
        return False


def _process_runs(pid: int) -> bool:
    if pid == os.getpid():
        return True                     # our own threads may be writing
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, OSError):
        return True                     # another user's process, or a question we cannot ask: assume it runs
    return True


def _write_journal(first_target: Path, temporaries: dict[Path, Path]) -> Path:
    """Record the renames about to be done, durably, before the first one (see :func:`finish_interrupted_writes`)."""
    folder = _folder(first_target)
    renames = [[os.path.relpath(temporary, folder), os.path.relpath(target, folder)]
               for target, temporary in temporaries.items()]
    text = json.dumps({"format": JOURNAL_FORMAT, "version": JOURNAL_VERSION, "renames": renames}) + "\n"
    journal = _new_temporary(first_target, ".journal")
    try:
        with open(journal, "wb") as handle:
            handle.write(text.encode("utf-8"))
            handle.flush()
            os.fsync(handle.fileno())
    except BaseException:
        _remove([journal])              # a full disk: no rename will follow, so no journal either
        raise
    _fsync_folder(folder)
    return journal


def _replay_journal(journal: Path) -> list[Path]:
    """Do the renames a dead writer's complete journal lists; [] for an incomplete one (nothing was renamed)."""
    folder = journal.parent
    try:
        written_ns = journal.stat().st_mtime_ns
        data = json.loads(journal.read_text(encoding="utf-8"))
        if data.get("format") != JOURNAL_FORMAT or data.get("version") != JOURNAL_VERSION:
            return []
        renames = [(folder / str(a), folder / str(b)) for a, b in data["renames"]]
    except (OSError, ValueError, TypeError, KeyError, AttributeError):
        return []
    done = []
    for temporary, target in renames:
        if not _OWNED_NAME.match(temporary.name) or not _ours(temporary):
            continue                    # renamed before the kill (or not ours: never follow a foreign name)
        with contextlib.suppress(OSError):
            if target.exists() and target.stat().st_mtime_ns > written_ns:
                continue                # written since, by someone else: newer than this set
            os.replace(temporary, target)
            done.append(target)
    for changed in {_folder(target) for _, target in renames}:
        _fsync_folder(changed)
    return done


def _folder(path: Path) -> Path:
    return path.parent if str(path.parent) else Path(".")


def _new_temporary(target: Path, suffix: str = ".tmp") -> Path:
    """A new empty file beside ``target`` with a hidden name that says which process writes it.

    Created with mode 0666 (not ``mkstemp``'s 0600): the kernel then applies
    the umask (and any default ACL) exactly as for a plain ``open``, without
    this process changing its umask, which other threads may be relying on.
    """
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    for _ in range(NAME_ATTEMPTS):
        candidate = _folder(target) / f".{target.name}.{HOST_TAG}-{os.getpid()}-{secrets.token_hex(4)}{suffix}"
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


def _remove_quietly(path: Path) -> bool:
    try:
        os.unlink(path)
    except OSError:
        return False
    return True
