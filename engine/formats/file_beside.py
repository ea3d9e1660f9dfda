"""The one check for every file a mesh document names (glTF buffers and images, OBJ material
libraries and their images, a PLY's texture file): it must lie in the document's folder or a folder
inside it, links resolved, so that a downloaded model cannot carry a user's other files into a model
they then share.

>>> from pathlib import Path
>>> file_beside(Path("/data/head/head.obj"), "skin.mtl")               # doctest: +SKIP
PosixPath('/data/head/skin.mtl')
>>> file_beside(Path("/data/head/head.obj"), "../../etc/passwd")       # doctest: +SKIP
Traceback (most recent call last):
FileOutside: '../../etc/passwd' leaves the document's folder (only files in /data/head, or in folders ...
"""

from __future__ import annotations

import os
from pathlib import Path

from engine.errors import UserError

_SHOWN = 200            # characters of a hostile name repeated in a message


class FileOutside(UserError):
    """A name in a document points outside the document's folder, or is absolute."""


def file_beside(document: Path, name: str) -> Path:
    """The file ``name`` (relative, ``/`` between folders) names beside ``document``, links resolved;
    :class:`FileOutside` for an absolute name, a NUL, or one that leads out of the document's folder."""
    shown = name[:_SHOWN]
    if "\0" in name:
        raise FileOutside(f"'{shown}' holds a NUL, which no file name does")
    if Path(name).is_absolute() or name.startswith("/"):
        raise FileOutside(f"'{shown}' is an absolute path (only files beside the document are read)")
    folder = Path(os.path.realpath(document.parent))
    target = Path(os.path.realpath(folder / name))
    if not target.is_relative_to(folder):
        raise FileOutside(f"'{shown}' leaves the document's folder (only files in {document.parent}, or in "
                          "folders inside it, are read)")
    return target
