"""The ``workbench`` verb of ``artificial-person``, added through the ``artificial_person.verbs`` entry point.

The engine's command line knows nothing of the GUI; the workbench package
registers this verb in ``pyproject.toml``. Nothing here imports Qt until the
verb runs.

>>> from engine.cli import main
>>> main(["workbench", "my-head.xml"])            # doctest: +SKIP
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from engine.cli.common import say_error
from engine.errors import ModelFileError


def add_verbs(verbs: Any) -> None:
    """Add ``workbench [MODEL]`` to the CLI's sub-parsers."""
    p = verbs.add_parser("workbench", help="open the GUI on a model (default head)")
    p.add_argument("model", nargs="?", metavar="MODEL", help="model description (.xml); default: the shipped head")
    p.set_defaults(run=run_workbench)


def run_workbench(args: argparse.Namespace) -> int:
    if args.model is not None and not Path(args.model).exists():
        raise ModelFileError("no such file", file=args.model)
    try:
        from workbench.app import main as workbench_main
    except ImportError as exc:
        say_error(f"cannot start the workbench: {exc}")
        return 1
    return workbench_main(args.model)
