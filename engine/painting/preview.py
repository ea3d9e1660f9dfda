"""Live preview while painting: the posed mesh follows the weights dab by dab.

The workbench can hold the painted parameter (and any others) at chosen
values while the user paints. Writing the region back into the model after
every dab would rebuild the model's :class:`~engine.deform.Deformer` each
time (about 50 ms on the default head, 0.4 s at 94k vertices), so
:class:`LivePreview` keeps the pose fixed, reads the weights being painted
directly, and recomputes only the vertices a dab changed — the same
formulation as ``docs/deformation.md`` §3: leaves in the rest frame, then the
blended, normalised group-1 carry.

>>> import numpy as np
>>> from engine import load_model
>>> from engine.painting import PaintContext, DenseRegion, Brush, Stroke, LivePreview
>>> head = load_model(); ctx = PaintContext(head)
>>> dense = DenseRegion.from_model(head, "brow_raise")
>>> live = LivePreview(head, "brow_raise", dense, {"brow_raise": 1.0})
>>> stroke = Stroke(dense.weights)
>>> change = stroke.dab(ctx, Brush("add", radius=20, strength=0.5), (30.0, 160.0, 125.0))
>>> moved = live.update(change.indices)           # (len(change), 3) new positions, mm
>>> head.set_region("brow_raise", dense.to_region())
>>> bool(np.allclose(live.positions, head.deform({"brow_raise": 1.0})))
True
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

from engine.errors import UserError
from engine.model.model import Model
from engine.painting.weights import DenseRegion


class LivePreview:
    """Posed positions (N, 3, mm) of ``model`` at ``values`` with parameter ``name``'s weights read live.

    Parameters
    ----------
    model : Model
        Its other regions and its parameter tree are read once; rebuild the
        preview after editing them or the values.
    name : str
        The parameter being painted.
    region : DenseRegion
        Its dense weights (and displacements, for a field translation); the
        preview reads them on every :meth:`update`, so paint into
        ``region.weights`` in place (a :class:`~engine.painting.Stroke` does).
    values : mapping name → value, optional
        The pose held while painting (defaults for the rest).
    """

    def __init__(self, model: Model, name: str, region: DenseRegion, values: Mapping[str, float] | None = None):
        tree = model.parameters
        tree[name]
        names = tree.names
        n = model.n_vertices
        if region.weights.shape != (n,):
            raise UserError(f"the painted weights have shape {region.weights.shape}, expected ({n},)")
        self.region = region
        self.painted = names.index(name)
        vals = model.values_array(values)
        local, world = model.deformer().transforms(vals)
        self.rest = np.hstack([model.vertices, np.ones((n, 1))])
        eye = np.eye(4)
        # (k, dense weights or None if painted, delta matrix or None, (value, field or None) or None)
        self.leaves: list[tuple[int, np.ndarray | None, np.ndarray | None, Any]] = []
        for k, nm in enumerate(names):
            if not tree.is_leaf(nm) or vals[k] == 0.0:
                continue                   # a leaf at 0 contributes nothing (invariant 2)
            p = tree[nm]
            w = None if k == self.painted else model.regions[nm].dense(n)
            if p.field:
                if k == self.painted:
                    field = None           # read live from region.displacements
                else:
                    r = model.regions[nm]
                    field = np.zeros((n, 3))
                    field[r.indices] = r.displacements
                self.leaves.append((k, w, None, (vals[k], field)))
            else:
                self.leaves.append((k, w, local[k] - eye, None))
        self.group1 = [k for k, nm in enumerate(names) if not tree.is_leaf(nm)]
        self.G = np.array([model.regions[names[k]].dense(n) for k in self.group1]).reshape(len(self.group1), n)
        self.world_delta = np.array([world[k] - eye for k in self.group1]).reshape(len(self.group1), 4, 4)
        self.painted_row = self.group1.index(self.painted) if self.painted in self.group1 else None
        self.positions = self._compute(np.arange(n))

    def _compute(self, S: np.ndarray) -> np.ndarray:
        P = self.rest[S]
        P1 = P.copy()
        live = self.region.weights[S]
        for _, W, delta, field in self.leaves:
            w = live if W is None else W[S]
            if field is not None:
                value, D = field
                D = self.region.displacements if D is None else D
                if D is not None:
                    P1[:, :3] += (w * value)[:, None] * D[S]
            else:
                P1 += w[:, None] * (P @ delta)
        if len(self.group1):
            G = self.G[:, S]
            if self.painted_row is not None:
                G = G.copy()
                G[self.painted_row] = live
            total = G.sum(axis=0)
            Gn = np.divide(G, total, out=np.zeros_like(G), where=total > 0)
            M = np.einsum("ks,kij->sij", Gn, self.world_delta)
            out = P1[:, :3] + np.einsum("si,sij->sj", P1, M)[:, :3]
        else:
            out = P1[:, :3]
        return out

    def update(self, indices: npt.ArrayLike) -> np.ndarray:
        """Recompute the vertices ``indices`` (e.g. ``change.indices``); returns their new positions."""
        S = np.asarray(indices, dtype=np.int64)
        pos = self._compute(S)
        self.positions[S] = pos
        return pos
