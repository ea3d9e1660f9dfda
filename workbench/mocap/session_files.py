"""Where the motion-capture tool suggests writing its files: beside the project, not beside the lab's data.

A capture session (and a marker map) belongs with the model it is analysed
for: the folder of the open model's file, or — while the open model is the
shipped default head or was never saved — the folder of the model last
opened or saved (File ▸ Open recent), else the working folder. The marker
files themselves often sit on a share or a read-only archive, which is why
the session is not written beside them.

>>> default_session_path(window.document, "/lab/takes/Facial-Sing.c3d")   # doctest: +SKIP
PosixPath('/home/me/heads/Facial-Sing.h5')
"""

from __future__ import annotations

from pathlib import Path

from engine.paths import DATA_DIR

from ..window.recent_files import recent_files


def _shipped(path: str | Path) -> bool:
    """Inside the project's shipped ``data/`` (the default head): no place for a user's files."""
    return Path(path).resolve().is_relative_to(DATA_DIR.resolve())


def project_folder(document) -> Path:
    """The folder of the open model's file, else of the last model opened or saved, else the working folder."""
    path = document.path
    if path is not None and not _shipped(path):
        return Path(path).resolve().parent
    for recent in recent_files():
        if not _shipped(recent):
            return recent.parent
    return Path.cwd()


def default_session_path(document, source: str | Path) -> Path:
    """``<project folder>/<marker file's name>.h5``."""
    return project_folder(document) / (Path(source).stem + ".h5")
