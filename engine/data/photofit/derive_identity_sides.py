#!/usr/bin/env python3
"""Derive ``identity-sides.h5``: each fitted identity parameter's effect on the default head's landmark vertices.

Run from the project root after the default head, the identity targets or the parameters' ranges change::

    .venv/bin/python engine/data/photofit/derive_identity_sides.py

The photo fit reads the table (:mod:`engine.photofit.side_table`) instead of building the head's vertices
some sixty times per fit; ``tests/engine/test_photofit_side_table.py`` fails when the shipped file is no
longer what this script computes. The input is the toolkit's own data only (no download).
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3]))


def main() -> None:
    from engine.formats.model_files import load_model
    from engine.photofit.face_points import point_vertices
    from engine.photofit.identity_fit import MACROS, MODIFIERS
    from engine.photofit.side_table import derive_table, table_path, write_table

    base = load_model()
    table = derive_table(base, sorted(set(point_vertices(base).values())), MODIFIERS, MACROS)
    write_table(table, table_path())
    print(f"{table_path()}: {len(table.modifiers)} modifiers × 2 sides and {len(table.macros)} macros at "
          f"{len(table.vertices)} vertices")


if __name__ == "__main__":
    main()
