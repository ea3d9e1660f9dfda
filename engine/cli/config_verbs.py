"""The ``export-config`` verb: the model and the library files it uses, in one folder (docs/export.md).

The same export as the workbench's File → Export → Configuration…
(:func:`engine.outputs.configuration_export.export_configuration`).

>>> from engine.cli import main
>>> main(["export-config", "-L", "my-commands", "-o", "to-anna"])              # doctest: +SKIP
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from engine.cli.common import add_library_option, add_model_option, load_model_argument


def add_verbs(verbs: Any) -> None:
    """Add ``export-config`` to the CLI's sub-parsers."""
    p = verbs.add_parser("export-config",
                         help="write the model and the command library files it uses into a folder, with a README")
    add_model_option(p)
    add_library_option(p)
    p.add_argument("-o", "--output", required=True, metavar="FOLDER",
                   help="the folder to write (created if needed; files of the same names are replaced)")
    p.set_defaults(run=run_export_config)


def run_export_config(args: argparse.Namespace) -> int:
    """Export the model (``-m``, default the shipped head) and its library (``-L``) into ``-o FOLDER``.

    The model's files are named after the file given with ``-m``
    (``-m painted.xml`` writes ``model/painted.xml``); the shipped head's
    after its name, ``default-head``.
    """
    from engine.outputs.configuration_export import README_NAME, export_configuration
    from engine.paths import default_model_path

    model = load_model_argument(args.model)
    source = Path(args.model) if args.model is not None else default_model_path()
    stem = Path(args.model).stem if args.model is not None else None
    summary = export_configuration(model, args.output, args.library, source=source, stem=stem)
    folders = ", ".join(f.as_posix() for f in summary.library_folders) or "none"
    print(f"wrote {summary.folder}: {summary.model.as_posix()}, {len(summary.library_files)} library files "
          f"({folders}), {README_NAME}")
    if summary.unfit_commands:
        print(f"{len(summary.unfit_commands)} commands left out (they drive parameters the model lacks; "
              f"see {README_NAME})")
    return 0
