"""``python -m workbench [MODEL]``: the same as ``artificial-person workbench [MODEL]``."""

from __future__ import annotations

import argparse
import sys

from .app import main


def run(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m workbench",
                                     description="Open the Artificial Person workbench on a model.")
    parser.add_argument("model", nargs="?", default=None,
                        help="model description (.xml); the shipped default head if left out")
    args = parser.parse_args(argv)
    return main(args.model)


if __name__ == "__main__":
    sys.exit(run())
