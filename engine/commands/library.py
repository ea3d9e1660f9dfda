"""The command library: every ``*.lib`` file on the search path, and how its lines meet a model.

The search path is the shipped ``library/`` folder, then the user's folders
(``-L DIR`` on the command line) in the order given; a command defined in a
later folder overrides one of the same name in an earlier folder, so a user
can replace a shipped ``HeadNod`` without touching it. Two files in one
folder defining the same command is an error.

How a line meets a model parameter (§2.3: the paper's ``HeadNod`` file has a
single line called ``amplitude``): a line called ``amplitude`` drives the
parameter named by ``$parameter``, else the parameter named like the command
(``HeadNod``), else its snake_case form (``head_nod``). Any other line names
a model parameter directly.

>>> from engine import load_model
>>> from engine.commands import load_library
>>> library = load_library()
>>> library["HeadNod"].procedure
'periodic'
>>> library.parameters_of("HeadNod", load_model())
['head_nod']
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from engine.commands.library_format import AMPLITUDE, CommandDefinition, Curve, load_library_file
from engine.errors import LibraryError
from engine.paths import LIBRARY_DIR

if TYPE_CHECKING:
    from engine.model.model import Model

LIBRARY_SUFFIX = ".lib"


class Library:
    """Command definitions by name, with the file each came from."""

    def __init__(self, definitions: Iterable[CommandDefinition] = ()) -> None:
        self._definitions: dict[str, CommandDefinition] = {}
        self.overridden: dict[str, list[CommandDefinition]] = {}
        """Definitions replaced by a later folder, by command name."""
        for definition in definitions:
            self.add(definition)

    def add(self, definition: CommandDefinition) -> None:
        """Add a definition; one of the same name is replaced (and remembered in ``overridden``)."""
        old = self._definitions.get(definition.name)
        if old is not None:
            self.overridden.setdefault(definition.name, []).append(old)
        self._definitions[definition.name] = definition

    def __contains__(self, name: str) -> bool:
        return name in self._definitions

    def __getitem__(self, name: str) -> CommandDefinition:
        return self._definitions[name]

    def __iter__(self) -> Iterator[str]:
        return iter(sorted(self._definitions))

    def __len__(self) -> int:
        return len(self._definitions)

    def names(self) -> list[str]:
        return sorted(self._definitions)

    def parameters_of(self, command: str, model: Model) -> list[str]:
        """The model parameter each line of ``command`` drives, in line order.

        Raises :class:`LibraryError` (file and line of the line) when the model lacks one.
        """
        definition = self._definitions[command]
        return [parameter_of_line(definition, curve, model) for curve in definition.curves]

    def check(self, model: Model) -> list[LibraryError]:
        """Every problem binding the library to ``model`` would raise, without raising."""
        problems: list[LibraryError] = []
        for name in self.names():
            try:
                self.parameters_of(name, model)
            except LibraryError as exc:
                problems.append(exc)
        return problems

    def bind(self, model: Model) -> Library:
        """Check every command against ``model``; raises the first problem. Returns ``self``."""
        problems = self.check(model)
        if problems:
            raise problems[0]
        return self


def load_library(folders: Iterable[str | Path] = (), shipped: bool = True) -> Library:
    """The library from the shipped folder (unless ``shipped=False``) and then ``folders``.

    A folder contributes its ``*.lib`` files; an entry may also be a single ``.lib`` file.
    """
    library = Library()
    sources = ([LIBRARY_DIR] if shipped else []) + [Path(f) for f in folders]
    for source in sources:
        for definition in _definitions_in(source):
            library.add(definition)
    return library


def _definitions_in(source: Path) -> list[CommandDefinition]:
    if source.is_file():
        return load_library_file(source)
    if not source.is_dir():
        raise LibraryError("library folder does not exist", file=source)
    found: dict[str, CommandDefinition] = {}
    for path in sorted(source.glob("*" + LIBRARY_SUFFIX)):
        for definition in load_library_file(path):
            if definition.name in found:
                first = found[definition.name]
                raise LibraryError(f"command {definition.name} is defined twice in one library folder "
                                   f"(also in {first.file}:{first.line})", file=definition.file, line=definition.line)
            found[definition.name] = definition
    return list(found.values())


def parameter_of_line(definition: CommandDefinition, curve: Curve, model: Model) -> str:
    """The model parameter one library line drives (see the module docstring)."""
    tree = model.parameters
    if curve.name != AMPLITUDE:
        if curve.name not in tree:
            raise LibraryError(f"command {definition.name}: line '{curve.name}' names a parameter the model "
                               f"'{model.name}' does not have", file=definition.file, line=curve.line)
        return curve.name
    if definition.parameter is not None:
        if definition.parameter not in tree:
            raise LibraryError(f"command {definition.name}: $parameter names '{definition.parameter}', which "
                               f"the model '{model.name}' does not have", **definition.where("parameter"))
        return definition.parameter
    candidates = [definition.name, snake_case(definition.name)]
    for name in candidates:
        if name in tree:
            return name
    raise LibraryError(f"command {definition.name}: its line 'amplitude' drives no parameter — the model "
                       f"'{model.name}' has neither '{candidates[0]}' nor '{candidates[1]}'; name one with "
                       "'$parameter = …'", file=definition.file, line=curve.line)


def snake_case(name: str) -> str:
    """``HeadNod`` → ``head_nod``; ``EyesLookAt`` → ``eyes_look_at``."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).lower()
