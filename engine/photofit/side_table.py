"""Each identity parameter's effect on the default head's landmark vertices, shipped precomputed.

The photo fit's landmark model (:class:`engine.photofit.identity_fit.IdentityBasis`) needs, for each
face modifier, its effect per unit on each side of 0 (a MakeHuman target each side), and each macro's
(sex, age, ancestry) about the default identity: one :func:`~engine.identity.identity_vertices` of the
whole head each, some sixty in a fit, about 3.5 s of CPU. They depend only on the default head, the
identity targets and the parameters' ranges, not on the photograph, so they are computed once by
``engine/data/photofit/derive_identity_sides.py`` for every vertex a landmark may name
(:func:`~engine.photofit.face_points.point_vertices`) and shipped as ``engine/data/photofit/identity-sides.h5``
(``tests/engine/test_photofit_side_table.py`` checks that the shipped file is what the script computes now).

The file records a fingerprint of what it was computed from (the head's mesh, the targets file, the
parameters and their ranges): on any other head, or when either changed, :func:`shipped_sides` answers
``None`` and the fit samples the effects itself, as it did before.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from engine.errors import UserError
from engine.identity import Identity, identity_parameter, identity_vertices
from engine.identity.targets import identity_targets_path
from engine.model import Model
from engine.paths import DATA_DIR

FORMAT = "photofit-identity-sides"
VERSION = 1
FIRST_MACRO_STEP = 0.25               # of a macro's range: its first finite difference, about the default identity


def table_path() -> Path:
    """The shipped table."""
    return DATA_DIR / "photofit" / "identity-sides.h5"


def side_effect(base: Model, index: np.ndarray, name: str, sign: int) -> np.ndarray:
    """(L, 3) modifier ``name``'s effect per unit on the side ``sign`` of 0 at vertices ``index`` (MakeHuman's
    target there, sampled at half its extent; none where the range has no such side)."""
    p = identity_parameter(name)
    step = 0.5 * (p.maximum if sign > 0 else -p.minimum)
    if step <= 0:
        return np.zeros((len(index), 3))
    moved = identity_vertices(Identity({name: sign * step}), base)[index]
    return np.asarray((moved - base.vertices[index]) / (sign * step))


def first_macro_effect(base: Model, index: np.ndarray, name: str) -> np.ndarray:
    """(L, 3) macro ``name``'s effect per unit about the default identity at vertices ``index`` (a finite
    difference of :data:`FIRST_MACRO_STEP` of its range, from the default head's vertices)."""
    p = identity_parameter(name)
    step = FIRST_MACRO_STEP * (p.maximum - p.minimum)
    moved_value = p.default + step if p.default + step <= p.maximum else p.default - step
    moved = identity_vertices(Identity({name: float(moved_value)}), base)[index]
    return np.asarray((moved - base.vertices[index]) / (moved_value - p.default))


@dataclass(frozen=True)
class SideTable:
    """The effects at :attr:`vertices`: ``sides[m, 0 or 1]`` modifier m's on its + and − side, ``macros[k]``."""

    vertices: np.ndarray              # (V,) vertex indices, ascending
    modifiers: tuple[str, ...]
    macros: tuple[str, ...]
    sides: np.ndarray                 # (M, 2, V, 3) mm per unit
    macro_effects: np.ndarray         # (K, V, 3) mm per unit
    fingerprint: str

    def rows(self, index: np.ndarray) -> np.ndarray | None:
        """Where each of ``index`` is in :attr:`vertices`, or ``None`` if one is not there."""
        where = np.searchsorted(self.vertices, index)
        where = np.minimum(where, len(self.vertices) - 1)
        return where if np.array_equal(self.vertices[where], index) else None

    def side(self, name: str, sign: int, rows: np.ndarray) -> np.ndarray:
        return np.asarray(self.sides[self.modifiers.index(name), 0 if sign > 0 else 1][rows])

    def macro(self, name: str, rows: np.ndarray) -> np.ndarray:
        return np.asarray(self.macro_effects[self.macros.index(name)][rows])


def fingerprint(base: Model, modifiers: Sequence[str], macros: Sequence[str]) -> str:
    """What the table depends on: the head's mesh, the identity targets file, the parameters and their ranges."""
    digest = hashlib.blake2b(digest_size=16)
    digest.update(np.ascontiguousarray(base.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(base.vertex_part, dtype=np.int64).tobytes())
    digest.update("\0".join(base.parts).encode())
    digest.update(identity_targets_path().read_bytes())
    for name in (*modifiers, *macros):
        p = identity_parameter(name)
        digest.update(f"{name}:{p.minimum!r}:{p.maximum!r}:{p.default!r};".encode())
    return digest.hexdigest()


def derive_table(base: Model, vertices: Sequence[int], modifiers: Sequence[str], macros: Sequence[str]) -> SideTable:
    """The table computed: every effect at ``vertices`` (about sixty builds of the head's vertices)."""
    index = np.unique(np.asarray(vertices, dtype=np.int64))
    sides = np.array([[side_effect(base, index, m, sign) for sign in (1, -1)] for m in modifiers])
    macro_effects = np.array([first_macro_effect(base, index, k) for k in macros])
    return SideTable(index, tuple(modifiers), tuple(macros), sides, macro_effects,
                     fingerprint(base, modifiers, macros))


def write_table(table: SideTable, path: str | Path) -> None:
    """Write ``table`` as HDF5, atomically (the derivation script)."""
    import h5py

    from engine.formats.atomic import atomic_path

    with atomic_path(path) as temporary, h5py.File(temporary, "w", track_order=True) as f:
        f.attrs["format"] = FORMAT
        f.attrs["version"] = VERSION
        f.attrs["units"] = "mm per unit of each parameter"
        f.attrs["fingerprint"] = table.fingerprint
        f.attrs["modifiers"] = json.dumps(list(table.modifiers))
        f.attrs["macros"] = json.dumps(list(table.macros))
        f.attrs["source"] = "derived by engine/data/photofit/derive_identity_sides.py from the default head and " \
                            "engine/data/identity/identity-targets.h5"
        f.create_dataset("vertices", data=table.vertices.astype(np.int32))
        f.create_dataset("sides", data=table.sides, compression="gzip", shuffle=True)
        f.create_dataset("macro_effects", data=table.macro_effects, compression="gzip", shuffle=True)


def read_table(path: str | Path) -> SideTable:
    """The table in ``path``, checked (format, version, shapes, finite numbers): :class:`UserError` if not."""
    from engine.formats.hdf5_reading import HDF5Reader

    with HDF5Reader(path, UserError) as f:
        if f.attribute("format") != FORMAT:
            raise f.fail(f"not a photo-fit identity table (format is not '{FORMAT}')")
        if f.attribute("version") != VERSION:
            raise f.fail(f"photo-fit identity table version {f.attribute('version')} is not {VERSION}")
        modifiers = tuple(json.loads(str(f.attribute("modifiers"))))
        macros = tuple(json.loads(str(f.attribute("macros"))))
        vertices = f.array("vertices", "iu", ndim=1).astype(np.int64)
        sides = f.array("sides", "f", tail=(2, len(vertices), 3))
        macro_effects = f.array("macro_effects", "f", tail=(len(vertices), 3))
        stamp = str(f.attribute("fingerprint"))
        if (sides.shape[0] != len(modifiers) or macro_effects.shape[0] != len(macros)
                or np.any(np.diff(vertices) <= 0)):
            raise f.fail("the table's vertices, parameters and effects do not fit together")
    return SideTable(vertices, modifiers, macros, np.asarray(sides, dtype=float),
                     np.asarray(macro_effects, dtype=float), stamp)


def shipped_sides(base: Model, modifiers: Sequence[str], macros: Sequence[str]) -> SideTable | None:
    """The shipped table if it was computed from ``base`` and the current targets and ranges, else ``None``."""
    table = _shipped()
    if table is None or not set(modifiers) <= set(table.modifiers) or not set(macros) <= set(table.macros):
        return None
    if table.fingerprint != fingerprint(base, table.modifiers, table.macros):
        return None
    return table


@cache
def _shipped() -> SideTable | None:
    path = table_path()
    if not path.is_file():
        return None
    try:
        return read_table(path)
    except UserError:
        return None
