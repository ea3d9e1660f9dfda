"""The folders a ``load`` request may read model files from, and the one check that keeps every read inside them.

A client names a model description relative to a served folder (``people/anna.xml``, already
checked by :func:`engine.live.protocol.model_name`); the description names its arrays file
(``arrays="anna.h5"``, relative to the description, or absolute). Both names go through
:meth:`ServedFolders.served_file`: the path with symbolic links followed must lie inside the
folder the description was found in (the description) or inside one of the served folders (its
arrays file), or the ``load`` is refused before anything is read.

>>> import tempfile
>>> folder = Path(tempfile.mkdtemp())
>>> served = ServedFolders([folder])
>>> served.served_file(folder, "../elsewhere.h5", served.folders) is None
True
>>> served.served_file(folder, "anna.h5", served.folders) == (folder / "anna.h5").resolve()
True
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from engine.errors import ModelFileError
from engine.formats.xml_io import parse_xml, source_line
from engine.live.protocol import RequestError, RequestId


class ServedFolders:
    """The served folders (resolved); nothing outside them is opened for a ``load``."""

    def __init__(self, folders: Sequence[str | Path]):
        self.folders = [Path(folder).resolve() for folder in folders]

    @staticmethod
    def served_file(base: Path, name: str, within: Sequence[Path]) -> Path | None:
        """``base / name`` with symbolic links followed, if it lies inside one of ``within``; else ``None``."""
        try:
            candidate = (base / name).resolve()
        except (OSError, RuntimeError, ValueError):       # a link loop, a NUL byte: no file of ours
            return None
        return candidate if any(candidate.is_relative_to(folder) for folder in within) else None

    def model_path(self, name: str, request_id: RequestId = None) -> Path:
        """The description ``name`` in the first served folder that has it, inside that folder."""
        for folder in self.folders:
            candidate = self.served_file(folder, name, [folder])
            if candidate is not None and candidate.is_file():
                return candidate
        raise RequestError(f"no model file {name!r} in the folders this server was started with", request_id)

    def check_named_files(self, path: Path) -> None:
        """Refuse the description at ``path`` (:class:`ModelFileError`, located) if a file it names lies outside the
        served folders. Read with the loader's own parser, so a description it cannot parse is refused the way the
        loader would refuse it."""
        root = parse_xml(path, ModelFileError).getroot()
        arrays = root.get("arrays")
        if arrays is None:                                 # the loader says what is missing
            return
        if self.served_file(path.parent, arrays, self.folders) is None:
            raise ModelFileError(f"its arrays file {arrays!r} lies outside the folders this server was started with",
                                 file=path, line=source_line(root))
