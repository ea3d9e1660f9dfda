"""Where the project's shipped files live (data/, library/)."""

from __future__ import annotations

from pathlib import Path

PROJECT_ROOT = Path(__file__).resolve().parent.parent
DATA_DIR = PROJECT_ROOT / "data"
LIBRARY_DIR = PROJECT_ROOT / "library"
DEFAULT_HEAD_DIR = DATA_DIR / "default-head"


def default_model_path() -> Path:
    """The XML description of the shipped default head."""
    return DEFAULT_HEAD_DIR / "head.xml"


def reference_poses_path() -> Path:
    """HDF5 file of the default head's reference poses (ARKit-52, MakeHuman expression units)."""
    return DEFAULT_HEAD_DIR / "reference-poses.h5"
