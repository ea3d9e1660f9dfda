"""VTK's readers run in a child process: a crash or a hang there is an error here, and the child dies with us."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from engine.errors import MeshImportError
from engine.formats.mesh_child import read_in_child
from engine.formats.mesh_io import import_mesh

pv = pytest.importorskip("pyvista")

#: An unstructured grid whose tetrahedron names point 900000 of 4: VTK's surface filter segfaults on it.
SEGFAULTING_VTK = ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                   "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 900000\nCELL_TYPES 1\n10\n")


def crashing_interpreter(folder: Path) -> str:
    """A stand-in for the child's Python that dies of SIGSEGV at once, as VTK's reader does on
    :data:`SEGFAULTING_VTK` nearly always (a read past the end crashes only where that memory is unmapped)."""
    script = folder / "python-that-segfaults"
    script.write_text("#!/bin/sh\nkill -SEGV $$\n")
    script.chmod(0o755)
    return str(script)


def test_a_reader_that_crashes_is_an_error_naming_the_file(tmp_path, monkeypatch):
    path = tmp_path / "broken.vtk"
    path.write_text(SEGFAULTING_VTK)
    monkeypatch.setattr(sys, "executable", crashing_interpreter(tmp_path))
    with pytest.raises(MeshImportError, match=r"VTK's reader crashed on this file \(SIGSEGV\)") as info:
        import_mesh(path)
    assert str(info.value).startswith(str(path))


def test_a_file_that_crashes_vtk_is_an_error_naming_it(tmp_path):
    path = tmp_path / "broken.vtk"
    path.write_text(SEGFAULTING_VTK)
    with pytest.raises(MeshImportError) as info:
        import_mesh(path)
    # VTK crashes on it nearly always; where the memory it reads past the end happens to be mapped,
    # the face check that follows refuses the file instead (seen on CI's machine)
    message = str(info.value)
    assert message.startswith((f"{path}: VTK's reader crashed on this file (SIGSEGV)",
                               f"{path}: a face names a vertex outside")), message


def test_the_cli_says_one_line_where_vtk_crashes(tmp_path):
    path = tmp_path / "broken.vtk"
    path.write_text(SEGFAULTING_VTK)
    result = subprocess.run([sys.executable, "-m", "engine", "import-mesh", str(path), "-o", str(tmp_path / "m.xml")],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2
    # VTK's read past the end crashes it nearly always; when the memory it reads happens not to crash it,
    # the face check that follows refuses the file instead: one line naming it either way
    assert result.stderr.startswith((f"error: {path}: VTK's reader crashed",
                                     f"error: {path}: a face names a vertex outside")), result.stderr
    assert result.stderr.count("\n") == 1


def _new_children(of: int, known: set[int]) -> list[int]:
    """New children of ``of`` that already run the reader: a process freshly forked but not yet
    exec'd must not be stopped (its parent waits for the exec, and would wait for ever)."""
    found = []
    for child in _children(of):
        if child in known:
            continue
        try:
            command = Path(f"/proc/{child}/cmdline").read_bytes()
        except FileNotFoundError:
            continue
        if b"\0-m\0engine.formats.mesh_child\0" in command:    # the reader itself, not a fork of its parent
            found.append(child)
    return found


def _freeze_the_reader_when_it_starts(of: int, known: set[int], frozen: list[int]) -> None:
    """Stop (SIGSTOP) the first new child of ``of``: from outside, a reader that never returns."""
    for _ in range(60000):                          # up to ten minutes on a loaded machine
        found = _new_children(of, known)
        if found:
            os.kill(found[0], signal.SIGSTOP)
            frozen.append(found[0])
            return
        time.sleep(0.01)                            # the reader takes far longer than this to start


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="reads the process tree from /proc")
def test_a_reader_that_never_returns_is_stopped(tmp_path):
    import threading

    path = tmp_path / "sphere.stl"
    pv.Sphere().save(path)
    frozen: list[int] = []
    watcher = threading.Thread(target=_freeze_the_reader_when_it_starts,
                               args=(os.getpid(), set(_children(os.getpid())), frozen))
    watcher.start()
    try:
        with pytest.raises(MeshImportError, match="did not finish within 4 s") as info:
            read_in_child(path, timeout=4)
    finally:
        watcher.join()
    assert str(info.value).startswith(str(path))
    assert frozen and not _alive(frozen[0]), "the frozen reader was killed, not left behind"


def test_a_count_asking_for_gigabytes_is_refused_without_taking_them(tmp_path):
    """A FIELD array of 2e9 × 3 floats: VTK would allocate 24 GB; the child's memory cap stops it."""
    path = tmp_path / "greedy.vtk"
    path.write_text("# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                    "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nFIELD f 1\na 2000000000 3 float\n")
    with pytest.raises(MeshImportError) as info:
        import_mesh(path)
    assert str(info.value).startswith(str(path))


def test_devices_and_pipes_are_refused_before_any_reader_opens_them(tmp_path):
    fifo = tmp_path / "pipe.ply"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(MeshImportError, match="not a regular file"):
            import_mesh(path)


def _children(pid: int) -> list[int]:
    found = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        found += [int(c) for c in (task / "children").read_text().split()]
    return found


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except FileNotFoundError:
        return False
    return state != "Z"


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="reads the process tree from /proc")
def test_the_child_dies_when_its_parent_is_killed(tmp_path):
    """The parent reads a good file; its reader is frozen as it starts, the parent is killed -9, the
    reader let go: it must leave at once, not finish reading (which would write mesh.npz)."""
    path = tmp_path / "sphere.stl"
    pv.Sphere().save(path)
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    script = ("import sys; from pathlib import Path; from engine.formats.mesh_child import read_in_child; "
              f"print('started', flush=True); read_in_child(Path({str(path)!r}), timeout=600)")
    parent = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                              env={**os.environ, "TMPDIR": str(scratch)})
    try:
        assert parent.stdout is not None and parent.stdout.readline() == "started\n"
        frozen: list[int] = []
        _freeze_the_reader_when_it_starts(parent.pid, set(), frozen)
        assert frozen, "the reader was started in a child process"
        os.kill(parent.pid, signal.SIGKILL)
        parent.wait()
        os.kill(frozen[0], signal.SIGCONT)
        for _ in range(6000):
            if not _alive(frozen[0]):
                break
            time.sleep(0.1)
        assert not _alive(frozen[0]), "the reader outlived its parent"
        assert not list(scratch.rglob("mesh.npz")), "the reader left because its parent went, not because it finished"
    finally:
        if parent.poll() is None:
            parent.kill()
            parent.wait()
