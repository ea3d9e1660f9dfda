"""Reading a mesh with VTK's readers in a child process, so a damaged file cannot crash or hang us.

VTK's readers (STL, legacy VTK, VTP/VTU, OFF, …) segfault or loop forever on
some damaged files. :func:`read_in_child` runs the reader in a fresh Python
process and waits at most ``timeout`` seconds: a crash, a hang or an
exception there becomes a :class:`~engine.errors.MeshImportError` naming the
file here, and the workbench keeps its unsaved work. The child's address
space is capped (2 GiB plus 50 bytes per byte of the file), so a damaged count
cannot make it take the machine's memory. The child dies with its parent: it
watches its stdin, a pipe only the parent holds open, and exits when that
closes, whatever ended the parent (even ``kill -9``).

Run as ``python -m engine.formats.mesh_child MESH OUT.npz`` (the parent does
this); the arrays come back in an ``.npz`` (no pickles).

>>> from engine.formats.mesh_child import read_in_child
>>> read_in_child(Path("scan.stl")).vertices.shape                 # doctest: +SKIP
(1202, 3)
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import tempfile
import threading
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from engine.errors import MeshImportError, UserError
from engine.formats.mesh_data import RawMesh
from engine.model.cells import cell_sizes, index_mask, split_cells

if TYPE_CHECKING:
    import pyvista as pv

_DEFAULT_PART = "surface"
_USER_ERROR_STATUS = 3
#: Seconds allowed for starting Python and VTK, plus one second for every 20 MB of file.
_BASE_TIMEOUT_S, _BYTES_PER_SECOND = 60.0, 20e6
#: Address space the child may use: 2 GiB (Python, VTK and a small mesh take 0.4) plus 50 bytes per file byte.
_BASE_MEMORY, _MEMORY_PER_FILE_BYTE = 2 << 30, 50


def default_timeout(path: Path) -> float:
    """How long a reader may take on ``path`` before it is taken to hang (seconds)."""
    try:
        size = path.stat().st_size
    except OSError:
        size = 0
    return _BASE_TIMEOUT_S + size / _BYTES_PER_SECOND


def read_in_child(path: Path, timeout: float | None = None) -> RawMesh:
    """Read ``path`` with pyvista/VTK in a child process (see the module docstring)."""
    limit = default_timeout(path) if timeout is None else timeout
    with tempfile.TemporaryDirectory(prefix="ap-mesh-") as folder:
        out = Path(folder) / "mesh.npz"
        messages = Path(folder) / "stderr.txt"
        with messages.open("wb") as stderr:
            child = subprocess.Popen([sys.executable, "-m", "engine.formats.mesh_child", str(path), str(out)],
                                     stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=stderr,
                                     env={**os.environ, "PYTHONPATH": _import_root()})
            try:
                status = child.wait(timeout=limit)
            except subprocess.TimeoutExpired:
                child.kill()
                child.wait()
                raise MeshImportError(f"VTK's reader did not finish within {limit:.0f} s (it loops on some "
                                      "damaged files): the file is damaged or far too big", file=path) from None
            except BaseException:          # Ctrl-C and the like: the child must not outlive the wait
                child.kill()
                child.wait()
                raise
            finally:
                if child.stdin is not None:
                    child.stdin.close()
        if status == _USER_ERROR_STATUS:
            lines = messages.read_text(errors="replace").strip().splitlines()
            raise MeshImportError(lines[-1] if lines else "cannot read as a mesh", file=path)
        if status < 0:
            name = signal.Signals(-status).name if -status in signal.Signals._value2member_map_ else str(-status)
            raise MeshImportError(f"VTK's reader crashed on this file ({name}): it is damaged, not in the "
                                  "format its extension says, or asks for more memory than its size can "
                                  "explain", file=path)
        if status != 0 or not out.exists():
            raise MeshImportError(f"VTK's reader failed on this file (exit status {status}): it is damaged or "
                                  "not in the format its extension says", file=path)
        with np.load(out, allow_pickle=False) as data:
            return RawMesh(data["vertices"], data["faces"], [str(s) for s in data["part_names"]],
                           data["face_part"])


def _import_root() -> str:
    """The folder holding the ``engine`` package, first on the child's path (an installed or a
    source-tree toolkit alike), then what the parent had."""
    root = str(Path(__file__).resolve().parents[2])
    rest = os.environ.get("PYTHONPATH")
    return root if not rest else root + os.pathsep + rest


# ---------------------------------------------------------------------------
# In the child
# ---------------------------------------------------------------------------

def _exit_when_parent_goes() -> None:
    """Block on stdin (only the parent holds its other end) and end the process when it closes."""
    with contextlib.suppress(OSError):
        while os.read(0, 65536):          # the raw descriptor: no buffered-stream lock held at exit
            pass
    os._exit(70)


def _limit_memory(path: Path) -> None:
    """Cap the child's address space: a damaged count makes VTK allocate tens of GB, which on a
    shared machine would push everything else out of memory before any timeout fires."""
    try:
        import resource
    except ImportError:         # not on Windows: the timeout alone guards there
        return
    size = path.stat().st_size if path.is_file() else 0
    limit = _BASE_MEMORY + _MEMORY_PER_FILE_BYTE * size
    _soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        limit = min(limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def _child_main(argv: list[str]) -> int:
    threading.Thread(target=_exit_when_parent_goes, daemon=True).start()
    path, out = Path(argv[0]), Path(argv[1])
    _limit_memory(path)
    try:
        vertices, faces, part_names, face_part = read_with_pyvista(path)
    except UserError as exc:
        print(exc.message, file=sys.stderr)
        return _USER_ERROR_STATUS
    np.savez(out, vertices=vertices, faces=faces, part_names=np.array(part_names, dtype=str),
             face_part=face_part)
    return 0


def read_with_pyvista(path: Path) -> tuple[np.ndarray, np.ndarray, list[str], np.ndarray]:
    """Vertices, flat cell array, part names and each polygon's part, as pyvista reads ``path``.
    Run this only in a child process: VTK may crash or hang on a damaged file."""
    import pyvista as pv
    from vtkmodules.vtkCommonCore import vtkObject

    # VTK readers report damaged files through VTK's log, Python's logging and
    # warnings at once; silence all three and report one error of our own.
    vtkObject.GlobalWarningDisplayOff()
    try:
        quiet_log = pv.vtk_verbosity("off") if hasattr(pv, "vtk_verbosity") else contextlib.nullcontext()
        with warnings.catch_warnings(), quiet_log:
            warnings.simplefilter("ignore")
            data = pv.read(str(path))
    except Exception as exc:  # VTK readers raise assorted errors on damaged or unknown files
        text = str(exc).lower()
        if "automatically read" in text or "not supported" in text or "extension" in text:
            raise UserError(f"unknown mesh format '{path.suffix or path.name}' "
                            "(try .obj, .ply, .stl, .vtk, .vtp, .gltf or .glb)") from None
        raise UserError("cannot read as a mesh: the file is empty, damaged or not in the format "
                        "its extension says") from None
    pieces = list(_leaf_datasets(data, None))
    if not pieces:
        raise UserError("holds no mesh (the file is empty, damaged or not a mesh)")
    vertex_blocks: list[np.ndarray] = []
    cell_blocks: list[np.ndarray] = []
    part_names: list[str] = []
    face_part: list[np.ndarray] = []
    offset = 0
    for label, ds in pieces:
        if isinstance(ds, (pv.ImageData, pv.RectilinearGrid)):
            raise UserError(f"holds an image or grid ({type(ds).__name__}), not a polygon surface")
        surface = ds if isinstance(ds, pv.PolyData) else _boundary_surface(ds)
        if surface.n_points == 0:
            continue
        cells = _polys_and_strips(surface)
        if len(cells) == 0:
            continue
        counts = cell_sizes(cells)
        shifted = cells.copy()
        shifted[index_mask(cells, counts)] += offset
        name = label if len(pieces) > 1 else _DEFAULT_PART
        if name not in part_names:
            part_names.append(name)
        vertex_blocks.append(np.asarray(surface.points, dtype=float))
        cell_blocks.append(shifted)
        face_part.append(np.full(len(counts), part_names.index(name), dtype=np.int64))
        offset += surface.n_points
    if not cell_blocks:
        return np.zeros((0, 3)), np.zeros(0, dtype=np.int64), [], np.zeros(0, dtype=np.int64)
    return (np.concatenate(vertex_blocks), np.concatenate(cell_blocks), part_names,
            np.concatenate(face_part))


def _leaf_datasets(data: pv.DataObject | None, label: str | None) -> Iterator[tuple[str, pv.DataObject]]:
    """(name, dataset) for every non-empty dataset in a possibly nested MultiBlock."""
    import pyvista as pv

    if data is None:
        return
    if isinstance(data, pv.MultiBlock):
        for key, block in zip(data.keys(), data, strict=True):
            yield from _leaf_datasets(block, key or label)
    elif data.n_points:
        yield (label or _DEFAULT_PART), data


def _boundary_surface(ds: pv.DataObject) -> pv.PolyData:
    """The outer surface of a volume mesh or grid, as PolyData (VTK's filter, stable across pyvista versions)."""
    import pyvista as pv
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter

    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(ds)
    surface.Update()
    return pv.wrap(surface.GetOutput())


def _polys_and_strips(ds: pv.PolyData) -> np.ndarray:
    """The polygons of a PolyData as a flat cell array, triangle strips split into triangles."""
    polys = np.asarray(ds.faces, dtype=np.int64) if ds.GetNumberOfPolys() else np.zeros(0, dtype=np.int64)
    if not ds.GetNumberOfStrips():
        return polys
    tris = []
    for strip in split_cells(np.asarray(ds.strips, dtype=np.int64)):
        for j in range(len(strip) - 2):
            a, b, c = strip[j], strip[j + 1], strip[j + 2]
            tris.append((3, a, b, c) if j % 2 == 0 else (3, b, a, c))
    return np.concatenate([polys, np.array(tris, dtype=np.int64).reshape(-1)])


if __name__ == "__main__":
    exit_status = _child_main(sys.argv[1:])
    sys.stderr.flush()
    os._exit(exit_status)               # no interpreter shutdown while the watching thread blocks
