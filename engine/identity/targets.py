"""The identity space's shape targets file (``engine/data/identity/identity-targets.h5``), read and summed.

The file holds MakeHuman's targets cut to the head (see
``engine/data/identity/derive_identity_targets.py``): per target its sparse
displacements in mm and the motion of the neck joint, which is taken back so
the head stays on its origin. How identity values weight the targets is
:mod:`engine.identity.weights`.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from pathlib import Path

import numpy as np

from engine.formats.hdf5_reading import HDF5Reader
from engine.identity.errors import IdentityError
from engine.paths import DATA_DIR

FORMAT = "artificial-person-identity-targets"
VERSION = 1


def identity_targets_path() -> Path:
    """The shipped identity targets file."""
    return DATA_DIR / "identity" / "identity-targets.h5"


class IdentityTargets:
    """The targets file, read whole: per target its sparse displacements (mm) and the neck joint's motion."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        with HDF5Reader(self.path, IdentityError) as f:
            if f.attribute("format") != FORMAT:
                raise f.fail(f"not an identity targets file (format is not '{FORMAT}')")
            version = f.attribute("version")
            if version != VERSION:
                raise f.fail(f"identity targets format version {version} is not one this program reads ({VERSION})")
            self.source_version = str(f.attribute("source_version"))
            self.source = str(f.attribute("source"))
            self.modifiers_json = str(f.attribute("modifiers"))
            self.hm08_vertex = f.array("hm08_vertex", "iu", ndim=1).astype(np.int64)
            n = len(self.hm08_vertex)
            self.rest = f.array("rest", "f", tail=(3,))
            self.eye_helpers = {part: f.array(f"eye_helpers/{part}", "iu", ndim=1).astype(np.int64)
                                for part in ("eye_left", "eye_right")}
            names = f.strings("target_names")
            offsets = f.array("target_offsets", "iu", ndim=1).astype(np.int64)
            index = f.array("target_index", "iu", ndim=1).astype(np.int64)
            delta = f.array("target_delta", "f", tail=(3,)).astype(np.float64)
            motion = f.array("neck_joint_motion", "f", tail=(3,))
            if (len(offsets) != len(names) + 1 or len(motion) != len(names) or offsets[0] != 0
                    or np.any(np.diff(offsets) < 0) or offsets[-1] != len(index) or len(delta) != len(index)
                    or (len(index) and (index.min() < 0 or index.max() >= n))):
                raise f.fail("the targets' offsets, indices and displacements do not fit together")
            self.targets: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]] = {
                name: (index[a:b], delta[a:b], motion[k])
                for k, (name, a, b) in enumerate(zip(names, offsets[:-1], offsets[1:], strict=True))}
        if self.rest.shape != (n, 3):
            raise IdentityError(f"rest positions do not fit the {n} vertices", file=self.path)

    def displacement(self, weights: Mapping[str, float]) -> np.ndarray:
        """Σ weight × target, with the neck joint kept in place: (n, 3) mm on :attr:`hm08_vertex`."""
        D = np.zeros((len(self.hm08_vertex), 3))
        shift = np.zeros(3)
        for key, w in weights.items():
            if w == 0.0:
                continue
            try:
                index, delta, motion = self.targets[key]
            except KeyError:
                raise IdentityError(f"the identity targets file has no target '{key}'", file=self.path) from None
            D[index] += w * delta
            shift += w * motion
        return D - shift


@cache
def shipped_targets() -> IdentityTargets:
    """The shipped targets file, read once per process."""
    return IdentityTargets(identity_targets_path())
