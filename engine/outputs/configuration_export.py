"""Export configuration: the model and the command library files it uses, in one folder.

The paper's configuration tool exports "configuration files" for the
animator (§2.4); here they are the model and its library. A colleague who
receives the folder can open the model in the workbench and run the same
commands on it. The folder holds::

    README.txt                 what is here and how to use it
    model/<stem>.xml, .h5      the model, named after the file it was opened from
    engine/library/*.lib              shipped library files with a command that fits the model
    library-user-1/*.lib, …    the same from each user library folder, in search order

A library file is exported when at least one command it defines is the one
in force (not overridden by a later folder) and fits the model (every line
drives a parameter the model has); commands that do not fit are listed in
the README. Every file is written atomically and all of them together: a
failure half-way leaves the folder as it was. The workbench's File → Export →
Configuration… and ``artificial-person export-config`` both call
:func:`export_configuration`; ``docs/export.md`` describes the folder.

>>> import tempfile
>>> from engine import load_model
>>> summary = export_configuration(load_model(), tempfile.mkdtemp())
>>> summary.model.as_posix(), summary.library_args()
('model/default-head.xml', ['-L', 'library'])
>>> export_configuration(load_model(), tempfile.mkdtemp(), stem="painted").model.as_posix()
'model/painted.xml'
"""

from __future__ import annotations

import contextlib
import shutil
import time
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from engine.commands.library import load_library
from engine.errors import LibraryError, UserError
from engine.formats.atomic import atomic_files
from engine.formats.model_files import write_model_files
from engine.model.model import Model
from engine.paths import LIBRARY_DIR

README_NAME = "README.txt"
MODEL_FOLDER = "model"
SHIPPED_LIBRARY_FOLDER = "library"


@dataclass
class ExportSummary:
    """What :func:`export_configuration` wrote; paths other than ``folder`` are relative to it."""

    folder: Path
    model: Path
    library_folders: list[Path] = field(default_factory=list)   # in search order
    library_files: list[Path] = field(default_factory=list)
    unfit_commands: list[str] = field(default_factory=list)     # one message per command left out

    def library_args(self) -> list[str]:
        """The ``-L`` options that give the exported library, in search order."""
        return [arg for folder in self.library_folders for arg in ("-L", folder.as_posix())]


def export_configuration(model: Model, folder: str | Path, library_folders: Iterable[str | Path] = (),
                         source: str | Path | None = None, stem: str | None = None) -> ExportSummary:
    """Write ``model`` and the library files it uses into ``folder`` (created if needed).

    ``library_folders`` are the user's library folders (or single ``.lib``
    files) searched after the shipped ``library/``. ``source`` names where
    the model came from, for the README. ``stem`` names the model's files
    (``model/<stem>.xml`` and ``.h5``): the stem of the file the user opened
    (``painted`` for ``painted.xml``), so the export carries the name the
    user knows; left out, the model's own name (``model.name``), which a
    copy saved under another name still has. Files of the same names already in
    ``folder`` are replaced. Raises :class:`engine.errors.UserError` (e.g. a
    :class:`engine.errors.LibraryError` naming file and line) if a library
    file cannot be read or the folder cannot be written; nothing is written then.
    """
    folder = Path(folder)
    user_folders = [Path(f) for f in library_folders]
    library = load_library(user_folders)
    sources = [LIBRARY_DIR, *user_folders]
    targets = [Path(SHIPPED_LIBRARY_FOLDER)] + [Path(f"library-user-{i}") for i in range(1, len(sources))]

    used: dict[Path, Path] = {}          # library file → its folder in the export (relative)
    unfit: list[str] = []
    for name in library.names():
        definition = library[name]
        try:
            library.parameters_of(name, model)
        except LibraryError as exc:
            unfit.append(str(exc))
            continue
        path = Path(definition.file).resolve()
        used[path] = targets[_source_index(path, sources)]

    description = exported_model_path(model, stem)
    arrays = description.with_suffix(".h5")
    summary = ExportSummary(folder, description, unfit_commands=unfit)
    copies = sorted(used.items(), key=lambda item: (item[1].as_posix(), item[0].name))
    summary.library_files = [target / path.name for path, target in copies]
    summary.library_folders = [t for t in targets if any(f.parent == t for f in summary.library_files)]
    readme = readme_text(model, summary, source)

    model.validate()
    created = _make_folders(folder, [folder / MODEL_FOLDER] + [folder / f for f in summary.library_folders])
    try:
        written = [folder / description, folder / arrays, *(folder / f for f in summary.library_files),
                   folder / README_NAME]
        with atomic_files(written) as temporary:
            write_model_files(model, temporary[folder / description], temporary[folder / arrays], arrays.name)
            for (path, _), relative in zip(copies, summary.library_files, strict=True):
                _copy(path, temporary[folder / relative])
            temporary[folder / README_NAME].write_text(readme, encoding="utf-8")
    except BaseException:
        for made in reversed(created):
            _remove_if_empty(made)
        raise
    return summary


def exported_model_path(model: Model, stem: str | None = None) -> Path:
    """Where :func:`export_configuration` puts the model's description in the folder, e.g.
    ``model/painted.xml`` (its arrays beside it as ``.h5``); ``stem`` as there, made safe for a file name."""
    return Path(MODEL_FOLDER) / f"{_safe_stem(model.name if stem is None else stem)}.xml"


def readme_text(model: Model, summary: ExportSummary, source: str | Path | None = None) -> str:
    """The README.txt that explains the exported folder to whoever receives it."""
    model_file = summary.model.as_posix()
    lines = [f"Artificial Person configuration: {model.name}",
             "",
             f"Exported {time.strftime('%Y-%m-%d %H:%M')}" + (f" from {source}" if source else "") + ".",
             "",
             "What is here",
             f"  {model_file} (with {summary.model.with_suffix('.h5').as_posix()})",
             f"      the model: mesh, parts, parameter tree and influence regions "
             f"({model.n_vertices} vertices, {len(model.parameters)} parameters)."]
    for library_folder in summary.library_folders:
        files = [f.name for f in summary.library_files if f.parent == library_folder]
        lines.append(f"  {library_folder.as_posix()}/  command library files: {', '.join(files)}")
    library_args = " ".join(summary.library_args())
    lines += ["",
              "How to use it",
              f"  Open the model in the workbench:   artificial-person workbench {model_file}",
              "  Make it speak with these commands:",
              f"    artificial-person say \"Hyvää päivää <HeadNod/>\" -m {model_file} {library_args} -o talk.mp4",
              "  Library folders given later with -L override commands of the same name given earlier,",
              "  so keep the order above."]
    if summary.unfit_commands:
        lines += ["", "Commands left out (they drive parameters this model does not have)"]
        lines += [f"  {message}" for message in summary.unfit_commands]
    return "\n".join(lines) + "\n"


def _source_index(path: Path, sources: list[Path]) -> int:
    """Which search-path entry a library file came from (the last that holds it)."""
    for i in range(len(sources) - 1, -1, -1):
        source = sources[i].resolve()
        if path == source or path.parent == source:
            return i
    return 0


def _safe_stem(name: str) -> str:
    stem = "".join(c if c.isalnum() or c in "-_." else "_" for c in name).strip("._")
    return stem or "model"


def _make_folders(folder: Path, folders: list[Path]) -> list[Path]:
    """Create ``folder`` and ``folders`` as needed; returns the ones this call created, parents first."""
    created: list[Path] = []
    for wanted in [folder, *folders]:
        missing = [p for p in [wanted, *wanted.parents] if not p.exists()]
        try:
            wanted.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            for made in reversed(created):
                _remove_if_empty(made)
            raise UserError(f"cannot create the folder: {exc.strerror or exc}", file=wanted) from None
        created += reversed(missing)
    return created


def _remove_if_empty(folder: Path) -> None:
    with contextlib.suppress(OSError):
        folder.rmdir()


def _copy(source: Path, destination: Path) -> None:
    try:
        shutil.copyfile(source, destination)
        shutil.copystat(source, destination)
    except OSError as exc:
        raise UserError(f"cannot copy library file: {exc.strerror or exc}", file=source) from None
