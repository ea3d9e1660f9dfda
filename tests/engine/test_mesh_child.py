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

pytest.importorskip("pyvista")

#: An unstructured grid whose tetrahedron names point 900000 of 4: VTK's surface filter segfaults on it.
SEGFAULTING_VTK = ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                   "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 900000\nCELL_TYPES 1\n10\n")


def test_a_file_that_crashes_vtk_is_an_error_naming_it(tmp_path):
    path = tmp_path / "broken.vtk"
    path.write_text(SEGFAULTING_VTK)
    with pytest.raises(MeshImportError, match=r"VTK's reader crashed on this file \(SIGSEGV\)") as info:
        import_mesh(path)
    assert str(info.value).startswith(str(path))


def test_the_cli_says_one_line_where_vtk_crashes(tmp_path):
    path = tmp_path / "broken.vtk"
    path.write_text(SEGFAULTING_VTK)
    result = subprocess.run([sys.executable, "-m", "engine", "import-mesh", str(path), "-o", str(tmp_path / "m.xml")],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2
    assert result.stderr.startswith(f"error: {path}: VTK's reader crashed") and result.stderr.count("\n") == 1


def test_a_reader_that_never_returns_is_stopped(tmp_path):
    """A named pipe nobody writes to: VTK's STL reader blocks on it for ever."""
    fifo = tmp_path / "never.stl"
    os.mkfifo(fifo)
    with pytest.raises(MeshImportError, match="did not finish within 3 s") as info:
        read_in_child(fifo, timeout=3)
    assert str(info.value).startswith(str(fifo))


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
    fifo = tmp_path / "never.stl"
    os.mkfifo(fifo)
    script = ("import sys; from pathlib import Path; from engine.formats.mesh_child import read_in_child; "
              f"print('started', flush=True); read_in_child(Path({str(fifo)!r}), timeout=600)")
    parent = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        assert parent.stdout is not None and parent.stdout.readline() == "started\n"
        children: list[int] = []
        for _ in range(600):                        # wait (up to a minute) for the reader to start
            children = _children(parent.pid)
            if children:
                break
            time.sleep(0.1)
        assert children, "the reader was started in a child process"
        os.kill(parent.pid, signal.SIGKILL)
        parent.wait()
        for _ in range(600):                        # it notices the closed pipe at once; allow a minute
            if not any(_alive(c) for c in children):
                break
            time.sleep(0.1)
        assert not any(_alive(c) for c in children), "the reader outlived its parent"
    finally:
        if parent.poll() is None:
            parent.kill()
            parent.wait()
