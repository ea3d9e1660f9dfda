"""Which verbs need which optional part (``pip install 'artificial-person[EXTRA]'``), checked before they run.

A plain ``pip install artificial-person`` is the engine and the command line: ``info``, ``render``,
``pose``, ``say``, ``tracks``, ``web-export``, ``stimuli`` and the rest work with it (``docs/install.md``).
The GUI and the services come as extras, named in ``pyproject.toml``'s ``[project.optional-dependencies]``;
a verb (or an option of one) whose extra is missing ends, before any work, with one line naming the
``pip install`` to run and exit status 2, never an ``ImportError`` traceback.

>>> needs_of("serve", window=True, lsl=False)
['live', 'workbench']
>>> missing_line("workbench", ["PySide6"], "the workbench")
"the workbench needs the extra 'workbench' (PySide6 is not installed): pip install 'artificial-person[workbench]'"
"""

from __future__ import annotations

import argparse
import importlib.util
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from engine.errors import UserError

DISTRIBUTION = "artificial-person"

#: The modules each extra brings (import names), as ``pyproject.toml`` lists their distributions.
EXTRA_MODULES: dict[str, tuple[str, ...]] = {
    "workbench": ("PySide6", "pyvistaqt", "pyvista"),
    "live": ("websockets",),
    "lsl": ("pylsl",),
    "dask": ("distributed",),
    "validate": ("dlib", "face_recognition_models", "ai_edge_litert", "matplotlib"),
    "figures": ("matplotlib",),     # part of 'validate': study-analyse draws its figures with matplotlib
}
#: The extra to name in the message for a pseudo-extra that is part of a real one.
EXTRA_NAMED = {"figures": "validate"}


@dataclass(frozen=True)
class Need:
    """Verb ``verb`` needs ``extra`` (for ``what``) when ``when(args)`` holds."""

    verb: str
    extra: str
    what: str
    when: Callable[[Any], bool] = lambda args: True


NEEDS: tuple[Need, ...] = (
    Need("workbench", "workbench", "the workbench"),
    Need("serve", "live", "serve"),
    Need("serve", "workbench", "serve --window", lambda args: bool(getattr(args, "window", False))),
    Need("serve", "lsl", "serve --lsl", lambda args: bool(getattr(args, "lsl", False))),
    Need("stimuli", "dask", "stimuli --scheduler", lambda args: getattr(args, "scheduler", None) is not None),
    Need("validate", "validate", "validate"),
    Need("study-analyse", "figures", "study-analyse (its figures)"),
)

#: A module a verb imports deep down, and the extra that brings it: an ImportError of one becomes the same line.
MODULE_EXTRA = {module: EXTRA_NAMED.get(extra, extra) for extra, modules in EXTRA_MODULES.items()
                for module in modules if extra != "workbench" or module != "pyvista"}
MODULE_EXTRA.update({"shiboken6": "workbench", "sounddevice": "workbench"})


def needs_of(verb: str, **options: Any) -> list[str]:
    """The extras ``verb`` with ``options`` (its parsed arguments' attributes) needs, sorted."""
    args = argparse.Namespace(**options)
    return sorted({need.extra for need in NEEDS if need.verb == verb and need.when(args)})


def check_extras(args: argparse.Namespace) -> None:
    """:class:`UserError` naming the ``pip install`` when the parsed command needs an extra that is missing."""
    verb = getattr(args, "verb", None)
    for need in NEEDS:
        if need.verb != verb or not need.when(args):
            continue
        missing = [module for module in EXTRA_MODULES[need.extra] if not importable(module)]
        if missing:
            raise UserError(missing_line(EXTRA_NAMED.get(need.extra, need.extra), missing, need.what))


def importable(module: str) -> bool:
    """Whether ``module`` is installed (found by the import system), without importing it."""
    try:
        return importlib.util.find_spec(module) is not None
    except (ImportError, ValueError):          # a finder that refuses it, or a half-imported module
        return False


def missing_line(extra: str, modules: list[str], what: str) -> str:
    """The one line for ``what`` lacking ``modules`` of ``extra``."""
    names = ", ".join(modules)
    verb = "is" if len(modules) == 1 else "are"
    return (f"{what} needs the extra '{extra}' ({names} {verb} not installed): "
            f"pip install '{DISTRIBUTION}[{extra}]'")


def extra_for_import_error(exc: ImportError) -> str | None:
    """The line for an ImportError of a module an extra brings, raised while a verb ran; ``None`` for others."""
    name = (exc.name or "").partition(".")[0]
    extra = MODULE_EXTRA.get(name)
    return None if extra is None else missing_line(extra, [name], "this command")
