"""Atomic writes of one or several files (engine.formats.atomic): all or nothing, with the usual permissions.

A failure inside the block (an exception, Ctrl-C) or while renaming leaves
every old file as it was and no temporary file behind; success gives every
new file the permissions a plain ``open`` would (0666 less the umask).
"""

from __future__ import annotations

import json
import os
import re
import signal
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import engine.formats.atomic as atomic
from engine.errors import ModelFileError, UserError
from engine.formats.atomic import (
    atomic_files,
    atomic_path,
    atomic_write_bytes,
    atomic_write_text,
    finish_interrupted_writes,
)


class DiskFullError(Exception):
    pass


def write_all(targets: list[Path], data: bytes = b"new", failure: BaseException | None = None,
              error: type[UserError] = UserError) -> None:
    """Write ``data`` to every target through one atomic_files block, raising ``failure`` at its end."""
    with atomic_files(targets, error) as temporary:
        for path in temporary.values():
            path.write_bytes(data)
        if failure is not None:
            raise failure


def contents(folder: Path) -> dict[str, bytes]:
    """Every file in ``folder``, hidden ones included, with its bytes."""
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


@pytest.fixture
def old_files(tmp_path) -> dict[str, bytes]:
    (tmp_path / "a.txt").write_bytes(b"old a")
    (tmp_path / "b.csv").write_bytes(b"old b")
    return contents(tmp_path)


def test_success_writes_every_file_and_leaves_no_temporaries(tmp_path, old_files):
    targets = [tmp_path / "a.txt", tmp_path / "b.csv", tmp_path / "c.bin"]
    with atomic_files(targets) as temporary:
        assert list(temporary) == targets
        for target, path in temporary.items():
            assert path.parent == tmp_path and path.name.startswith(f".{target.name}.") and path.exists()
            assert not target.exists() or target.read_bytes().startswith(b"old")    # nothing renamed yet
            path.write_bytes(b"new " + target.name.encode())
    assert contents(tmp_path) == {"a.txt": b"new a.txt", "b.csv": b"new b.csv", "c.bin": b"new c.bin"}


@pytest.mark.parametrize("failure", [DiskFullError("disk full"), KeyboardInterrupt()])
def test_a_failure_in_the_block_leaves_the_old_files_and_no_temporaries(tmp_path, old_files, failure):
    targets = [tmp_path / "a.txt", tmp_path / "b.csv", tmp_path / "new.txt"]
    with pytest.raises(type(failure)):
        write_all(targets, b"half", failure)
    assert contents(tmp_path) == old_files


def test_an_os_error_in_the_block_is_a_user_error_naming_the_target(tmp_path, old_files):
    target = tmp_path / "a.txt"

    def disk_full() -> None:
        with atomic_files([tmp_path / "b.csv", target], ModelFileError) as temporary:
            raise OSError(28, "No space left on device", str(temporary[target]))

    with pytest.raises(ModelFileError) as caught:
        disk_full()
    assert str(caught.value) == f"{target}: cannot write: No space left on device"
    assert contents(tmp_path) == old_files


def test_a_failed_rename_leaves_no_temporaries(tmp_path, old_files, monkeypatch):
    real = os.replace
    calls = []

    def second_fails(src, dst):
        calls.append(dst)
        if len(calls) == 2:
            raise OSError(13, "Permission denied")
        real(src, dst)

    monkeypatch.setattr(atomic.os, "replace", second_fails)
    with pytest.raises(UserError, match=re.escape("b.csv: cannot write: Permission denied")):
        write_all([tmp_path / "a.txt", tmp_path / "b.csv"])
    monkeypatch.undo()
    # Each rename is atomic, the set is not: the first file is the complete new one, the second the old one.
    assert contents(tmp_path) == {"a.txt": b"new", "b.csv": b"old b"}


def test_every_file_is_synced_before_any_is_renamed(tmp_path, monkeypatch):
    events = []
    real_fsync, real_replace = os.fsync, os.replace
    monkeypatch.setattr(atomic.os, "fsync", lambda fd: events.append("fsync") or real_fsync(fd))
    monkeypatch.setattr(atomic.os, "replace", lambda a, b: events.append("rename") or real_replace(a, b))
    write_all([tmp_path / "a", tmp_path / "b"])
    # the two files, then the journal of the renames and its folder, then the renames
    assert events[:6] == ["fsync", "fsync", "fsync", "fsync", "rename", "rename"]


@pytest.mark.parametrize("mask", [0o022, 0o077, 0o002])
def test_new_files_get_the_usual_permissions(tmp_path, mask):
    old = os.umask(mask)
    try:
        write_all([tmp_path / "a", tmp_path / "b"])
        atomic_write_text(tmp_path / "c", "x")
    finally:
        os.umask(old)
    for name in "abc":
        assert stat.S_IMODE((tmp_path / name).stat().st_mode) == 0o666 & ~mask


def test_a_missing_folder_or_a_folder_as_target_is_refused_before_anything_is_written(tmp_path):
    (tmp_path / "sub").mkdir()
    with pytest.raises(UserError, match=re.escape("missing/a.txt: cannot write: the folder does not exist")):
        write_all([tmp_path / "ok.txt", tmp_path / "missing" / "a.txt"])
    with pytest.raises(UserError, match="this is a folder"):
        atomic_write_text(tmp_path / "sub", "x")
    with pytest.raises(UserError, match="the same file twice"):
        write_all([tmp_path / "x", tmp_path / "x"])
    assert [p.name for p in tmp_path.iterdir()] == ["sub"]


def test_single_file_helpers_are_built_on_atomic_files(tmp_path, monkeypatch):
    atomic_write_bytes(tmp_path / "a.bin", b"\x00\x01")
    atomic_write_text(tmp_path / "b.txt", "päivää\n")
    with atomic_path(tmp_path / "c.h5") as name:
        assert isinstance(name, str) and Path(name).parent == tmp_path
        Path(name).write_bytes(b"h5")
    assert contents(tmp_path) == {"a.bin": b"\x00\x01", "b.txt": "päivää\n".encode(), "c.h5": b"h5"}

    def refuse(*_):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(atomic.os, "fsync", refuse)
    with pytest.raises(UserError, match=re.escape("a.bin: cannot write: No space left on device")):
        atomic_write_bytes(tmp_path / "a.bin", b"never")
    monkeypatch.undo()
    assert contents(tmp_path)["a.bin"] == b"\x00\x01" and len(contents(tmp_path)) == 3


def test_the_engine_has_one_place_that_renames_files_into_place():
    """Every writer goes through engine.formats.atomic: no other engine module renames temporary files.
    Scripts in folders that are no package (engine/web/study/run-lab.py) are not engine modules but what a
    study folder carries: run-lab.py runs on a lab computer with Python alone, so it saves atomically itself."""
    engine_dir = Path(atomic.__file__).resolve().parents[1]
    renaming = sorted(str(p.relative_to(engine_dir)) for p in engine_dir.rglob("*.py")
                      if p.name != "atomic.py" and (p.parent / "__init__.py").exists()
                      and any(word in p.read_text(encoding="utf-8")
                                                       for word in ("os.replace(", "os.rename(", "mkstemp(")))
    assert renaming == []


# ---------------------------------------------------------------------------
# kill -9: a set of files is finished by the next writer; dead writers' temporaries are removed
# ---------------------------------------------------------------------------

WRITER = """
import os, signal, sys
from pathlib import Path
import engine.formats.atomic as atomic
folder, mode = Path(sys.argv[1]), sys.argv[2]
real_replace, renames = os.replace, []
def replace(src, dst):
    renames.append(dst)
    if mode == "kill-at-rename-2" and len(renames) == 2:
        os.kill(os.getpid(), signal.SIGKILL)
    real_replace(src, dst)
atomic.os.replace = replace
with atomic.atomic_files([folder / "a.txt", folder / "b.csv", folder / "c.bin"]) as temporary:
    for target, path in temporary.items():
        path.write_bytes(b"new " + target.name.encode())
    if mode == "wait":
        print("ready", flush=True)
        sys.stdin.read()
"""


def run_writer(folder: Path, mode: str, **kw) -> subprocess.Popen:
    root = Path(__file__).resolve().parents[2]
    env = dict(os.environ, PYTHONPATH=str(root))
    return subprocess.Popen([sys.executable, "-c", WRITER, str(folder), mode], cwd=root, env=env, text=True, **kw)


NEW = {"a.txt": b"new a.txt", "b.csv": b"new b.csv", "c.bin": b"new c.bin"}


def test_a_set_killed_between_two_renames_is_finished_by_the_next_write(tmp_path, old_files):
    writer = run_writer(tmp_path, "kill-at-rename-2")
    assert writer.wait() == -signal.SIGKILL
    left = contents(tmp_path)
    assert left["a.txt"] == b"new a.txt" and left["b.csv"] == b"old b"        # the mix the kill left...
    assert any(name.endswith(".journal") for name in left)
    atomic_write_text(tmp_path / "other.txt", "x")                              # ...finished by any write here
    assert contents(tmp_path) == {**NEW, "other.txt": b"x"}


def test_a_live_writers_temporaries_are_left_alone_and_a_dead_ones_removed(tmp_path, old_files):
    writer = run_writer(tmp_path, "wait", stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    assert writer.stdout is not None and writer.stdout.readline().strip() == "ready"
    temporaries = set(contents(tmp_path)) - set(old_files)
    assert len(temporaries) == 3
    assert finish_interrupted_writes(tmp_path) == []
    assert set(contents(tmp_path)) == set(old_files) | temporaries
    writer.kill()
    writer.wait()
    assert sorted(p.name for p in finish_interrupted_writes(tmp_path)) == sorted(temporaries)
    assert contents(tmp_path) == old_files


def test_files_of_another_host_or_another_naming_are_never_touched(tmp_path):
    other_host = "000000" if atomic.HOST_TAG != "000000" else "111111"
    names = [f".a.txt.{other_host}-999999999-0123abcd.tmp", ".a.txt.0123abcd.tmp", ".hidden.tmp",
             f".a.txt.{other_host}-999999999-0123abcd.journal"]
    for name in names:
        (tmp_path / name).write_bytes(b"x")
    assert finish_interrupted_writes(tmp_path) == []
    assert sorted(contents(tmp_path)) == sorted(names)


def dead_name(target: str, kind: str) -> str:
    return f".{target}.{atomic.HOST_TAG}-999999999-{os.urandom(4).hex()}.{kind}"


def test_a_journal_never_overwrites_a_file_written_after_it(tmp_path):
    stale = tmp_path / dead_name("a.txt", "tmp")
    stale.write_bytes(b"stale")
    journal = tmp_path / dead_name("a.txt", "journal")
    journal.write_text(json.dumps({"format": atomic.JOURNAL_FORMAT, "version": atomic.JOURNAL_VERSION,
                                   "renames": [[stale.name, "a.txt"]]}))
    later = journal.stat().st_mtime_ns + 10**9
    (tmp_path / "a.txt").write_bytes(b"written later by another program")
    os.utime(tmp_path / "a.txt", ns=(later, later))
    finish_interrupted_writes(tmp_path)
    assert contents(tmp_path) == {"a.txt": b"written later by another program"}


def test_a_journal_cut_short_renames_nothing(tmp_path, old_files):
    temporary = tmp_path / dead_name("a.txt", "tmp")
    temporary.write_bytes(b"new")
    (tmp_path / dead_name("a.txt", "journal")).write_text('{"format": "artificial-person-rename-jo')
    finish_interrupted_writes(tmp_path)
    assert contents(tmp_path) == old_files


def test_a_journal_names_only_files_beside_it_of_our_naming(tmp_path, old_files):
    """A journal planted to rename some other file over a target is not followed."""
    (tmp_path / "evil.txt").write_bytes(b"planted")
    (tmp_path / dead_name("a.txt", "journal")).write_text(json.dumps(
        {"format": atomic.JOURNAL_FORMAT, "version": atomic.JOURNAL_VERSION, "renames": [["evil.txt", "a.txt"]]}))
    finish_interrupted_writes(tmp_path)
    assert contents(tmp_path) == {**old_files, "evil.txt": b"planted"}


def test_a_journal_that_cannot_be_written_leaves_the_old_files_and_nothing_else(tmp_path, old_files, monkeypatch):
    real_fsync, calls = os.fsync, []

    def third_fails(fd):                  # the two files sync; the journal's sync finds the disk full
        calls.append(fd)
        if len(calls) == 3:
            raise OSError(28, "No space left on device")
        real_fsync(fd)

    monkeypatch.setattr(atomic.os, "fsync", third_fails)
    with pytest.raises(UserError, match="No space left on device"):
        write_all([tmp_path / "a.txt", tmp_path / "b.csv"])
    monkeypatch.undo()
    assert contents(tmp_path) == old_files
