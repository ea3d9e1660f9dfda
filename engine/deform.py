"""The animator's deformation (§2.2), vectorised.

Formulation (derivation in ``docs/deformation.md``): with ``P`` the rest
position of vertex *i* (row vector),

1. leaves (group 2) act in the rest frame and superpose (Eq. 2)::

       P1 = P + Σ_leaf w_ik (P · T_k(v_k) − P)          (field translations: + w_ik v_k D_ik)

2. the blended rigid motion of group 1 carries the result::

       P2 = P1 · (I + Σ_group1 w̄_ik (T'_k − I)),    T'_c = T_c · T'_parent,

   with ``w̄`` the group-1 weights normalised to sum 1 per vertex wherever a
   vertex has any.

Using the leaves' own ``T_k`` (not ``T'_k``) in stage 1 is what keeps a leaf
at value 0 from re-applying its ancestors' motion to points that stage 2
moves anyway.

Speed: vertices are grouped once, when the deformer is built, by their
group-1 weights. Vertices bound with weight 1 to a single parameter form
contiguous blocks in an internal vertex order and move with one 3×3 matrix
product per block; only the blended band (neck, jaw line) pays for
per-vertex matrices. Leaves touch only their own regions.
"""

from __future__ import annotations

import numpy as np
from scipy import sparse


class Deformer:
    """Precomputed structure for deforming one :class:`~engine.model.Model` quickly.

    Build it with ``model.deformer()`` (cached until the model changes), then
    call :meth:`deform` with the parameter values in tree order.
    """

    def __init__(self, model):
        self.revision = model.revision
        tree = model.parameters
        self.names = tree.names
        self.params = [tree[n] for n in self.names]
        index = {n: i for i, n in enumerate(self.names)}
        self.parent_index = [index[p.parent] if p.parent is not None else -1 for p in self.params]
        self.topological = [index[n] for n in tree.topological()]
        n = model.n_vertices
        self.n_vertices = n
        group1 = [i for i, nm in enumerate(self.names) if not tree.is_leaf(nm)]
        leaves = [i for i, nm in enumerate(self.names) if tree.is_leaf(nm)]
        self.group1 = group1

        # ---- group-1 weights, normalised per vertex (§2.2) ----
        rows, cols, vals = [], [], []
        for col, k in enumerate(group1):
            region = model.regions[self.names[k]]
            keep = region.weights > 0
            rows.append(region.indices[keep])
            cols.append(np.full(int(keep.sum()), col))
            vals.append(region.weights[keep])
        if group1:
            W = sparse.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                                  shape=(n, len(group1)))
        else:
            W = sparse.csr_matrix((n, 0))
        W.sum_duplicates()
        total = np.asarray(W.sum(axis=1)).ravel()
        nnz_per_row = np.diff(W.indptr)
        W = W.tocsr()
        W.data = W.data / np.repeat(total, nnz_per_row)     # divide (not 1/total: subnormal totals overflow)

        # ---- classify vertices: bound to one parameter, blended, or free ----
        single = nnz_per_row == 1
        single_col = np.full(n, -1)
        single_col[single] = W.indices[W.indptr[:-1][single]]
        key = np.where(single, single_col, np.where(nnz_per_row == 0, len(group1), len(group1) + 1))
        perm = np.argsort(key, kind="stable")
        self.perm = perm
        self.rest = np.ascontiguousarray(model.vertices[perm])
        inv = np.empty(n, dtype=np.int64)
        inv[perm] = np.arange(n)
        bounds = np.searchsorted(key[perm], np.arange(len(group1) + 3))
        # blocks: (parameter index or None, slice in internal order, original indices)
        self.blocks = []
        for col, k in enumerate(group1):
            s = slice(int(bounds[col]), int(bounds[col + 1]))
            if s.stop > s.start:
                self.blocks.append((k, s, _as_index(perm[s])))
        free = slice(int(bounds[len(group1)]), int(bounds[len(group1) + 1]))
        self.free = (free, _as_index(perm[free])) if free.stop > free.start else None
        blend = slice(int(bounds[len(group1) + 1]), n)
        if blend.stop > blend.start:
            Wb = W[perm[blend]].tocsc()
            used = np.flatnonzero(np.diff(Wb.indptr) > 0)          # group-1 columns the band uses
            dense = np.ascontiguousarray(Wb[:, used].toarray())
            self.blend = (blend, [group1[c] for c in used], dense)
        else:
            self.blend = None
        self.inverse = inv

        # ---- leaves: internal indices, weights, cached rest positions ----
        self.leaves = []
        for k in leaves:
            region = model.regions[self.names[k]]
            if len(region.indices) == 0:
                continue
            idx = inv[region.indices]
            order = np.argsort(idx)
            idx = idx[order]
            w = region.weights[order][:, None]
            rest = self.rest[idx]
            disp = None if region.displacements is None else region.displacements[order] * w
            self.leaves.append((k, _as_index(idx), w, rest, disp))
        self._eye4x3 = np.eye(4)[:, :3]

    # ------------------------------------------------------------------
    def transforms(self, values: np.ndarray):
        """Local ``T_k`` and propagated ``T'_k`` for all parameters (lists of 4×4)."""
        local = [p.transform(float(v)) for p, v in zip(self.params, values)]
        world = [None] * len(local)
        for k in self.topological:
            parent = self.parent_index[k]
            world[k] = local[k] if parent < 0 else local[k] @ world[parent]
        return local, world

    def deform(self, values) -> np.ndarray:
        """Deformed vertex positions (N, 3) in the model's vertex order, mm."""
        values = np.asarray(values, dtype=float)
        if values.shape != (len(self.params),):
            raise ValueError(f"expected {len(self.params)} values in tree order, got shape {values.shape}")
        local, world = self.transforms(values)

        # Stage 1: leaves in the rest frame (Eq. 2), in the internal vertex order.
        work = self.rest.copy()
        rows = _rows(work)
        for k, idx, w, rest, disp in self.leaves:
            v = values[k]
            if v == 0.0:
                continue
            if disp is not None:
                delta = v * disp
            else:
                T = local[k]
                delta = rest @ (T[:3, :3] - np.eye(3))
                delta += T[3, :3]
                delta *= w
            if isinstance(idx, slice):
                work[idx] += delta
            else:
                moved = _rows(np.ascontiguousarray(_floats(rows[idx]) + delta))
                rows[idx] = moved

        # Stage 2: blended rigid motion of group 1, block by block (contiguous slices).
        for k, s, _orig in self.blocks:
            T = world[k]
            if not _identity(T):
                block = work[s]
                block[...] = block @ T[:3, :3] + T[3, :3]
        if self.blend is not None:
            s, columns, dense = self.blend
            D = np.stack([world[k][:, :3] - self._eye4x3 for k in columns])   # (K, 4, 3)
            if D.any():
                M = dense @ D.reshape(len(columns), 12)                       # (nb, 12) blended T' - I
                Pb = work[s]
                delta = Pb[:, 0:1] * M[:, 0:3]
                delta += Pb[:, 1:2] * M[:, 3:6]
                delta += Pb[:, 2:3] * M[:, 6:9]
                delta += M[:, 9:12]
                Pb += delta
        # Back to the model's vertex order with one gather of whole rows.
        return _floats(rows[self.inverse])


def _rows(a: np.ndarray) -> np.ndarray:
    """View an (N, 3) float64 array as N opaque 24-byte rows (fast fancy indexing)."""
    return a.view(np.dtype((np.void, 24))).reshape(-1)


def _floats(rows: np.ndarray) -> np.ndarray:
    return rows.view(np.float64).reshape(-1, 3)


def _identity(T: np.ndarray) -> bool:
    return T[0, 0] == 1.0 and T[1, 1] == 1.0 and T[2, 2] == 1.0 and np.array_equal(T, np.eye(4))


def _as_index(idx: np.ndarray):
    """A slice when the indices are one increasing run (cheaper than fancy indexing)."""
    idx = np.asarray(idx, dtype=np.int64)
    if len(idx) and idx[-1] - idx[0] == len(idx) - 1 and np.all(np.diff(idx) == 1):
        return slice(int(idx[0]), int(idx[-1]) + 1)
    return idx


def deform_reference(model, values=None) -> np.ndarray:
    """The same deformation written literally, one vertex at a time.

    Slow (pure Python loops over vertices); used by the tests to check the
    vectorised :class:`Deformer` against an independent implementation of
    the formulation in ``docs/deformation.md``.
    """
    tree = model.parameters
    vals = dict(zip(tree.names, model.values_array(values)))
    local = {n: tree[n].transform(vals[n]) for n in tree.names}
    world: dict[str, np.ndarray] = {}
    for n in tree.topological():
        parent = tree[n].parent
        world[n] = local[n] if parent is None else local[n] @ world[parent]
    n_vertices = model.n_vertices
    group1 = [n for n in tree.names if not tree.is_leaf(n)]
    leaves = [n for n in tree.names if tree.is_leaf(n)]
    dense = {n: model.regions[n].dense(n_vertices) for n in tree.names}
    fields = {}
    for n in leaves:
        r = model.regions[n]
        if r.displacements is not None:
            f = np.zeros((n_vertices, 3))
            f[r.indices] = r.displacements
            fields[n] = f
    out = np.empty((n_vertices, 3))
    for i in range(n_vertices):
        P = np.append(model.vertices[i], 1.0)
        P1 = P.copy()
        for n in leaves:
            w = dense[n][i]
            if w == 0:
                continue
            if n in fields:
                P1[:3] += w * vals[n] * fields[n][i]
            else:
                P1 += w * (P @ local[n] - P)
        total = sum(dense[n][i] for n in group1)
        M = np.eye(4)
        if total > 0:
            for n in group1:
                M += dense[n][i] / total * (world[n] - np.eye(4))
        out[i] = (P1 @ M)[:3]
    return out

