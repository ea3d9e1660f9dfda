"""Export configuration: the model and the command library files it uses, in one folder.

A colleague who receives the folder can open the model in the workbench and
run the same commands on it. The folder holds::

    README.txt                 what is here and how to use it
    model/<name>.xml, .h5      the model
    library/*.lib              shipped library files with a command that fits the model
    library-user-1/*.lib, …    the same from each user library folder, in search order

A library file is exported when at least one command it defines is the one
in force (not overridden by a later folder) and fits the model (every line
drives a parameter the model has); commands that do not fit are listed in
the README. No Qt here: the CLI could offer the same export.

>>> summary = export_configuration(model, "to-anna", ["my-commands"])     # doctest: +SKIP
>>> summary.library_args()                                                # doctest: +SKIP
['-L', 'library', '-L', 'library-user-1']
"""

from __future__ import annotations

import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path

import engine
from engine.commands import load_library
from engine.errors import LibraryError, UserError
from engine.formats.atomic import atomic_write_text
from engine.paths import LIBRARY_DIR

README_NAME = "README.txt"
MODEL_FOLDER = "model"
SHIPPED_LIBRARY_FOLDER = "library"


@dataclass
class ExportSummary:
    """What :func:`export_configuration` wrote, relative to ``folder``."""

    folder: Path
    model: Path
    library_folders: list[Path] = field(default_factory=list)   # in search order
    library_files: list[Path] = field(default_factory=list)
    unfit_commands: list[str] = field(default_factory=list)     # one message per command left out

    def library_args(self) -> list[str]:
        return [arg for folder in self.library_folders for arg in ("-L", folder.as_posix())]


def export_configuration(model: engine.Model, folder: str | Path, library_folders=(),
                         source: str | Path | None = None) -> ExportSummary:
    """Write ``model`` and the library files it uses into ``folder`` (created if needed).

    ``library_folders`` are the user's library folders (or single ``.lib``
    files) searched after the shipped ``library/``. ``source`` names where
    the model came from, for the README. Raises :class:`engine.UserError`
    (e.g. :class:`engine.errors.LibraryError` naming file and line) if a
    library file cannot be read or the folder cannot be written.
    """
    folder = Path(folder)
    library = load_library(library_folders)
    sources = [LIBRARY_DIR] + [Path(f) for f in library_folders]
    targets = [Path(SHIPPED_LIBRARY_FOLDER)] + [Path(f"library-user-{i}") for i in range(1, len(sources))]

    used: dict[Path, str] = {}          # library file → its folder in the export (relative)
    unfit: list[str] = []
    for name in library.names():
        definition = library[name]
        try:
            library.parameters_of(name, model)
        except LibraryError as exc:
            unfit.append(str(exc))
            continue
        path = Path(definition.file).resolve()
        used[path] = targets[_source_index(path, sources)].as_posix()

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UserError(f"cannot create the folder: {exc.strerror or exc}", file=folder) from None
    stem = _safe_stem(model.name)
    model_path = engine.save_model(model, folder / MODEL_FOLDER / f"{stem}.xml")
    summary = ExportSummary(folder, model_path.relative_to(folder), unfit_commands=unfit)
    for path, target in sorted(used.items(), key=lambda item: (item[1], item[0].name)):
        destination = folder / target / path.name
        try:
            destination.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, destination)
        except OSError as exc:
            raise UserError(f"cannot copy library file: {exc.strerror or exc}", file=path) from None
        summary.library_files.append(destination.relative_to(folder))
    summary.library_folders = [t for t in targets if any(f.parent == t for f in summary.library_files)]
    atomic_write_text(folder / README_NAME, readme_text(model, summary, source))
    return summary


def readme_text(model: engine.Model, summary: ExportSummary, source: str | Path | None = None) -> str:
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
