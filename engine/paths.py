"""Where the toolkit's shipped files live: the default head, the identity targets and the command
library, installed with the package (``engine/data/``, ``engine/library/``).

They are found through :mod:`importlib.resources`, so a normal (non-editable) ``pip install`` of the
wheel finds them in ``site-packages`` as a checkout finds them in its ``engine/`` folder. The engine
reads them with h5py and lxml, which need real files: an installation from a zip (which the wheel
is not made for) is refused with one line.

>>> default_model_path().name
'head.xml'
"""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path


def _package_folder() -> Path:
    root = files("engine")
    if not isinstance(root, Path):      # a zipped install: h5py cannot open a member of a zip
        raise RuntimeError(f"the engine's data must be installed as files, not inside {root}")
    return root


PACKAGE_DIR = _package_folder()
DATA_DIR = PACKAGE_DIR / "data"
LIBRARY_DIR = PACKAGE_DIR / "library"
DEFAULT_HEAD_DIR = DATA_DIR / "default-head"


def default_model_path() -> Path:
    """The XML description of the shipped default head."""
    return DEFAULT_HEAD_DIR / "head.xml"


def reference_poses_path() -> Path:
    """HDF5 file of the default head's reference poses (ARKit-52, MakeHuman expression units)."""
    return DEFAULT_HEAD_DIR / "reference-poses.h5"
