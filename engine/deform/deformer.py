"""The animator's deformation (§2.2): a compiled vertex pass, with a vectorised numpy fallback.

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
group-1 weights and the leaves acting on them (the internal vertex order).
When the C extension ``engine.deform._kernel`` (``engine/deform/_kernel.c``,
built by ``pip install -e .``) imports, a frame is one call into it: it
builds every ``T_k`` and ``T'_k`` and makes one pass over the vertices, in
segments of vertices that move alike (same group-1 class, same leaves), with
each vertex's weights read from one array. Otherwise the numpy path moves
vertices bound to a single parameter in contiguous blocks with one 3×3
matrix product per block, pays for per-vertex matrices only in the blended
band (neck, jaw line), and lets leaves touch only their own regions. Both
give :func:`deform_reference` to rounding.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import ModuleType
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from engine.deform.transforms import is_identity

if TYPE_CHECKING:
    from engine.deform._kernel import Plan
    from engine.model.model import Model

#: The Plan interface this module builds (``KERNEL_ABI`` in ``_kernel.c``).
KERNEL_ABI = 1

#: The compiled kernel module ``engine.deform._kernel``, or None (numpy path only).
compiled: ModuleType | None
try:
    from engine.deform import _kernel as compiled
except ImportError:        # not compiled (no C compiler at install time)
    compiled = None
if compiled is not None and getattr(compiled, "ABI", None) != KERNEL_ABI:
    compiled = None        # built from an older source: re-run ``pip install -e .``


def pattern_ranks(rows: np.ndarray) -> np.ndarray:
    """For each row of a boolean matrix, the rank of its pattern among the distinct rows.

    The numbering of ``np.unique(np.packbits(rows, axis=1), axis=0,
    return_inverse=True)``, with the bits packed into big-endian 64-bit words
    and sorted as numbers: ten times faster on a 100k-vertex mesh.

    >>> pattern_ranks(np.array([[1, 0], [0, 1], [1, 0]], dtype=bool)).tolist()
    [1, 0, 1]
    """
    packed = np.packbits(rows, axis=1)
    n, n_bytes = packed.shape
    padded = np.zeros((n, max(8, -(-n_bytes // 8) * 8)), dtype=np.uint8)
    padded[:, :n_bytes] = packed
    words = padded.view(">u8")                     # numeric order of the words = order of the bytes
    if words.shape[1] == 1:
        return np.unique(words[:, 0], return_inverse=True)[1].ravel().astype(np.int64)
    order = np.lexsort(words.T[::-1])
    ordered = words[order]
    rank = np.cumsum(np.r_[True, (ordered[1:] != ordered[:-1]).any(axis=1)]) - 1
    out = np.empty(n, dtype=np.int64)
    out[order] = rank
    return out


class Deformer:
    """Precomputed structure for deforming one :class:`~engine.model.Model` quickly.

    Build it with ``model.deformer()`` (cached until the model changes), then
    call :meth:`deform` with the parameter values in tree order.

    Internally vertices are sorted by how they move: first by their group-1
    class (bound to one parameter, free, or blended), then by the set of
    leaves acting on them. The compiled kernel walks this order segment by
    segment (a run with one class and one set of leaves). The numpy path
    moves every block and most leaf regions as contiguous runs with one BLAS
    product each, keeping points homogeneous (N × 4, last column 1) so a
    product includes the translation. When the model's own vertex order is
    already this order (see :func:`optimise_vertex_order`), no final
    reordering is needed.

    ``kernel``: ``None`` (default) uses the compiled vertex pass when
    ``engine.deform._kernel`` is importable and the numpy path otherwise;
    ``True`` requires the kernel, ``False`` forces numpy. :attr:`kernel`
    tells which one this deformer uses.
    """

    MAX_RUNS = 64      # a leaf split into more runs than this uses index arrays instead

    def __init__(self, model: Model, kernel: bool | None = None) -> None:
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
        leaves = [i for i, nm in enumerate(self.names)
                  if tree.is_leaf(nm) and len(model.regions[nm].indices)]
        self.group1 = group1

        # ---- group-1 weights, normalised per vertex (§2.2) ----
        # (vertex, column, weight) triplets, columns in group-1 order, so each
        # vertex's total adds its weights in parameter order.
        row_parts: list[np.ndarray] = []
        col_parts: list[np.ndarray] = []
        val_parts: list[np.ndarray] = []
        for col, k in enumerate(group1):
            region = model.regions[self.names[k]]
            keep = region.weights > 0
            row_parts.append(region.indices[keep])
            col_parts.append(np.full(int(keep.sum()), col, dtype=np.int64))
            val_parts.append(region.weights[keep])
        rows = np.concatenate(row_parts) if row_parts else np.zeros(0, dtype=np.int64)
        cols = np.concatenate(col_parts) if col_parts else np.zeros(0, dtype=np.int64)
        vals = np.concatenate(val_parts) if val_parts else np.zeros(0)
        nnz_per_row = np.bincount(rows, minlength=n)
        total = np.bincount(rows, weights=vals, minlength=n)
        vals = vals / total[rows]     # divide (not 1/total: subnormal totals overflow)

        # ---- the internal order: group-1 class, then the set of leaves acting ----
        single = nnz_per_row == 1
        single_col = np.full(n, -1)
        single_col[rows[single[rows]]] = cols[single[rows]]
        cls = np.where(single, single_col, np.where(nnz_per_row == 0, len(group1), len(group1) + 1))
        if leaves:
            member = np.zeros((n, len(leaves)), dtype=bool)
            for j, k in enumerate(leaves):
                member[model.regions[self.names[k]].indices, j] = True
            signature = pattern_ranks(member)
        else:
            member = np.zeros((n, 0), dtype=bool)
            signature = np.zeros(n, dtype=np.int64)
        perm = np.lexsort((np.arange(n), signature, cls))
        self.perm = perm
        self.identity_order = bool(np.array_equal(perm, np.arange(n)))
        inv = np.empty(n, dtype=np.int64)
        inv[perm] = np.arange(n)
        self.inverse = inv
        self._leaf_params = leaves
        blended = nnz_per_row[rows] > 1
        band = (rows[blended], cols[blended], vals[blended])    # the blended vertices' normalised weights

        # Rodrigues' terms per rotation, so every frame builds all matrices in a few array operations.
        self._rot = np.array([i for i, p in enumerate(self.params) if p.kind == "rotation"], dtype=np.int64)
        axes = np.array([self.params[i].axis for i in self._rot]).reshape(-1, 3)
        self._rot_pivot = np.array([self.params[i].pivot for i in self._rot]).reshape(-1, 3)
        self._rot_scale = np.radians([self.params[i].degrees_per_unit for i in self._rot])
        self._rot_uu = axes[:, :, None] * axes[:, None, :]
        cross = np.zeros((len(axes), 3, 3))
        cross[:, 0, 1], cross[:, 0, 2], cross[:, 1, 2] = -axes[:, 2], axes[:, 1], -axes[:, 0]
        cross[:, 1, 0], cross[:, 2, 0], cross[:, 2, 1] = axes[:, 2], -axes[:, 1], axes[:, 0]
        self._rot_cross = cross
        self._trans = [(i, p.direction) for i, p in enumerate(self.params) if p.kind != "rotation" and not p.field]

        if kernel is None:
            kernel = compiled is not None
        elif kernel and compiled is None:
            raise RuntimeError("the compiled deformation kernel engine.deform._kernel is not built "
                               "(pip install -e . needs a C compiler and the Python headers)")
        self.kernel = bool(kernel)
        self._plan: Plan | None = self._build_plan(model, band, cls, signature, member) if self.kernel else None
        if not self.kernel:
            self._build_numpy(model, band, cls)

    # ------------------------------------------------------------------
    def _build_plan(self, model: Model, band: tuple[np.ndarray, np.ndarray, np.ndarray], cls: np.ndarray,
                    signature: np.ndarray, member: np.ndarray) -> Plan:
        """The compiled kernel's static structure (layout in ``engine/deform/_kernel.c``).

        Segments are the runs of the internal order with one group-1 class and one
        set of leaves; each gets its group-1 columns (blended band only) and its
        leaves as entries pointing at per-vertex weights in ``data``. Built with
        array operations throughout, with one loop over the leaves: a Python loop
        per segment and entry cost 0.2 s on the default head, most of the
        workbench's start-up beyond its imports.
        """
        n, perm, inv = self.n_vertices, self.perm, self.inverse
        group1 = np.asarray(self.group1, dtype=np.int64)
        leaf_params = np.asarray(self._leaf_params, dtype=np.int64)
        params = self.params
        kind = np.array([0 if p.kind == "rotation" else 2 if p.field else 1 for p in params], dtype=np.int64)

        def vec(attr: str) -> np.ndarray:
            return np.ascontiguousarray(np.array([getattr(p, attr) for p in params], dtype=float)
                                        .reshape(len(params), 3))

        key = np.stack([cls[perm], signature[perm]], axis=1)
        starts = np.flatnonzero(np.r_[True, (key[1:] != key[:-1]).any(axis=1)]) if n else np.zeros(0, int)
        stops = np.r_[starts[1:], n].astype(int) if n else np.zeros(0, int)
        lengths = stops - starts
        n_seg, n_group1 = len(starts), len(group1)
        segment_of = np.repeat(np.arange(n_seg), lengths)          # internal position → its segment
        within = np.arange(n) - np.repeat(starts, lengths)         # internal position → index in its segment
        seg_cls = cls[perm[starts]]
        # the group-1 parameter carrying each run: its own, -1 for free vertices, -2 for the blended band
        carry = np.r_[group1, -1, -2][seg_cls]

        # entries per segment: its blended band's group-1 columns, then its leaves, each ascending
        band_rows, band_cols, band_vals = band
        band_pos = inv[band_rows]
        uses = np.zeros((n_seg, n_group1), dtype=bool)
        uses[segment_of[band_pos], band_cols] = True
        seg_leaves = member[perm[starts]]                           # a run shares its first vertex's leaves
        seg_b, col_b = np.nonzero(uses)
        seg_l, leaf_l = np.nonzero(seg_leaves)
        n_band, n_leaf = uses.sum(axis=1), seg_leaves.sum(axis=1)
        seg_first = (np.cumsum(n_band + n_leaf) - (n_band + n_leaf)).astype(np.int64)   # exclusive sums
        entry_b = seg_first[seg_b] + np.arange(len(seg_b)) - (np.cumsum(n_band) - n_band)[seg_b]
        entry_l = (seg_first[seg_l] + n_band[seg_l]
                   + np.arange(len(seg_l)) - (np.cumsum(n_leaf) - n_leaf)[seg_l])
        n_entries = int((n_band + n_leaf).sum())
        entry_param = np.empty(n_entries, dtype=np.int64)
        entry_param[entry_b] = group1[col_b]
        entry_param[entry_l] = leaf_params[leaf_l]
        rows_per_leaf = np.array([1 if model.regions[self.names[k]].displacements is None else 3
                                  for k in leaf_params], dtype=np.int64)
        entry_size = np.empty(n_entries, dtype=np.int64)
        entry_size[entry_b] = lengths[seg_b]
        entry_size[entry_l] = lengths[seg_l] * rows_per_leaf[leaf_l]
        offset = (np.cumsum(entry_size) - entry_size).astype(np.int64)

        # per-vertex weights (zero where a band column does not reach a vertex)
        data = np.zeros(int(entry_size.sum()))
        band_entry = np.full((n_seg, n_group1), -1, dtype=np.int64)
        band_entry[seg_b, col_b] = entry_b
        data[offset[band_entry[segment_of[band_pos], band_cols]] + within[band_pos]] = band_vals
        leaf_entry = np.full((n_seg, len(leaf_params)), -1, dtype=np.int64)
        leaf_entry[seg_l, leaf_l] = entry_l
        for j, k in enumerate(leaf_params):
            region = model.regions[self.names[k]]
            pos = inv[region.indices]                  # exactly the positions in segments this leaf acts on
            seg = segment_of[pos]
            first = offset[leaf_entry[seg, j]] + within[pos]
            if region.displacements is None:
                data[first] = region.weights
            else:
                moved = region.displacements * region.weights[:, None]
                for axis in range(3):
                    data[first + axis * lengths[seg]] = moved[:, axis]
        segments = np.stack([starts, stops, carry, seg_first, n_band, seg_first + n_band, n_leaf], axis=1)
        entries = np.stack([entry_param, offset], axis=1)
        i64 = np.int64
        assert compiled is not None        # __init__ builds a plan only when the kernel imported
        return compiled.Plan(
            kind=kind,
            parent=np.asarray(self.parent_index, dtype=i64),
            topo=np.asarray(self.topological, dtype=i64),
            axis=vec("axis"), pivot=vec("pivot"),
            scale=np.radians(np.array([p.degrees_per_unit for p in params], dtype=float)),
            direction=vec("direction"),
            rest=np.ascontiguousarray(model.vertices[perm].T, dtype=float),
            order=np.zeros(0, dtype=i64) if self.identity_order else perm.astype(i64),
            segments=np.ascontiguousarray(segments, dtype=i64).reshape(-1, 7),
            entries=np.ascontiguousarray(entries, dtype=i64).reshape(-1, 2),
            data=data,
        )

    def _build_numpy(self, model: Model, band: tuple[np.ndarray, np.ndarray, np.ndarray], cls: np.ndarray) -> None:
        """Blocks, blended band and leaf runs of the numpy path."""
        n, perm, inv, group1 = self.n_vertices, self.perm, self.inverse, self.group1
        leaves = self._leaf_params
        self.rest4 = np.ones((n, 4))
        self.rest4[:, :3] = model.vertices[perm]

        bounds = np.searchsorted(cls[perm], np.arange(len(group1) + 3))
        self.blocks: list[tuple[int, slice]] = []
        for col, k in enumerate(group1):
            s = slice(int(bounds[col]), int(bounds[col + 1]))
            if s.stop > s.start:
                self.blocks.append((k, s))
        free = slice(int(bounds[len(group1)]), int(bounds[len(group1) + 1]))
        self.free: slice | None = free if free.stop > free.start else None
        blend = slice(int(bounds[len(group1) + 1]), n)
        self.blend: tuple[slice, list[int], np.ndarray] | None
        if blend.stop > blend.start:
            band_rows, band_cols, band_vals = band
            used = np.unique(band_cols)                            # group-1 columns the band uses
            column = np.searchsorted(used, band_cols)
            weights_t = np.zeros((len(used), blend.stop - blend.start))   # (K, nb)
            weights_t[column, inv[band_rows] - blend.start] = band_vals
            self.blend = (blend, [group1[c] for c in used], weights_t)
        else:
            self.blend = None

        # ---- leaves: runs in the internal order, cached rest points and weights ----
        # (parameter, where: contiguous (rows, part) runs or an index array, weights, rest points, field)
        self.leaves: list[tuple[int, list[tuple[slice, slice]] | np.ndarray, np.ndarray, np.ndarray,
                                np.ndarray | None]] = []
        for k in leaves:
            region = model.regions[self.names[k]]
            idx = inv[region.indices]
            order = np.argsort(idx)
            idx = idx[order]
            w = region.weights[order]
            breaks = np.flatnonzero(np.diff(idx) != 1) + 1
            starts = np.concatenate([[0], breaks])
            stops = np.concatenate([breaks, [len(idx)]])
            where: list[tuple[slice, slice]] | np.ndarray
            if len(starts) <= self.MAX_RUNS:
                where = [(slice(int(idx[a]), int(idx[b - 1]) + 1), slice(int(a), int(b)))
                         for a, b in zip(starts, stops, strict=True)]
            else:
                where = idx
            rest4 = np.ascontiguousarray(self.rest4[idx])
            w4 = np.ascontiguousarray(np.repeat(w[:, None], 4, axis=1))
            disp = None
            if region.displacements is not None:
                disp = np.zeros((len(idx), 4))
                disp[:, :3] = region.displacements[order] * w[:, None]
            self.leaves.append((k, where, w4, rest4, disp))
        self._eye4x3 = np.eye(4)[:, :3]

    # ------------------------------------------------------------------
    def local_transforms(self, values: np.ndarray) -> np.ndarray:
        """Every parameter's own ``T_k(v_k)`` as a (K, 4, 4) array (row convention)."""
        local = np.zeros((len(self.params), 4, 4))
        local[:] = np.eye(4)
        if len(self._rot):
            theta = values[self._rot] * self._rot_scale
            cos, sin = np.cos(theta)[:, None, None], np.sin(theta)[:, None, None]
            R = cos * np.eye(3) + sin * self._rot_cross + (1 - cos) * self._rot_uu     # column convention
            Rt = np.swapaxes(R, 1, 2)
            moving = theta != 0.0            # exact identities at value 0 (invariant 1)
            local[self._rot[moving], :3, :3] = Rt[moving]
            c = self._rot_pivot[moving]
            local[self._rot[moving], 3, :3] = c - np.einsum("ki,kij->kj", c, Rt[moving])
        for i, direction in self._trans:
            local[i, 3, :3] = values[i] * direction
        return local

    def transforms(self, values: npt.ArrayLike) -> tuple[np.ndarray, list[np.ndarray]]:
        """Local ``T_k`` and propagated ``T'_k`` for all parameters (4×4 each)."""
        local = self.local_transforms(np.asarray(values, dtype=float))
        world = list(local)               # every entry is replaced below, parents first
        for k in self.topological:
            parent = self.parent_index[k]
            world[k] = local[k] if parent < 0 else local[k] @ world[parent]
        return local, world

    def deform(self, values: npt.ArrayLike) -> np.ndarray:
        """Deformed vertex positions (N, 3) in the model's vertex order, mm."""
        values = np.asarray(values, dtype=float)
        if values.shape != (len(self.params),):
            raise ValueError(f"expected {len(self.params)} values in tree order, got shape {values.shape}")
        if self._plan is not None:
            out = np.empty((self.n_vertices, 3))
            self._plan.deform(np.ascontiguousarray(values), out)
            return out
        local, world = self.transforms(values)

        # Stage 1: leaves in the rest frame (Eq. 2), in the internal vertex order.
        work = self.rest4
        for k, where, w4, rest4, disp in self.leaves:
            v = values[k]
            if v == 0.0:
                continue
            if work is self.rest4:
                work = self.rest4.copy()
            if disp is not None:
                delta = v * disp
            else:
                delta = rest4 @ (local[k] - np.eye(4))      # [P·(A − I) + b, 0], one product
                delta *= w4
            if isinstance(where, list):                     # whole 4-wide rows: one contiguous loop each
                for run, part in where:
                    work[run] += delta[part]
            else:
                work[where] += delta

        # Stage 2: blended rigid motion of group 1.
        out = np.empty((self.n_vertices, 3))
        for k, s in self.blocks:
            T = world[k]
            if is_identity(T):
                out[s] = work[s, :3]
            else:
                np.matmul(work[s], T[:, :3], out=out[s])
        if self.free is not None:
            out[self.free] = work[self.free, :3]
        if self.blend is not None:
            s, columns, weights_t = self.blend
            D = np.stack([world[k][:, :3] - self._eye4x3 for k in columns])   # (K, 4, 3): T' − I
            if not D.any():
                out[s] = work[s, :3]
            else:
                M = D.reshape(len(columns), 12).T @ weights_t                 # (12, nb): blended T' − I
                x, y, z = (np.ascontiguousarray(work[s, c]) for c in range(3))
                for c, p in enumerate((x, y, z)):
                    moved = p + M[9 + c]
                    moved += x * M[c]
                    moved += y * M[3 + c]
                    moved += z * M[6 + c]
                    out[s, c] = moved
        if self.identity_order:
            return out
        # Back to the model's vertex order with one gather of whole rows.
        return _floats(_rows(out)[self.inverse])


def optimise_vertex_order(model: Model) -> tuple[Model, np.ndarray]:
    """A copy of ``model`` whose vertex order is the deformer's internal order, and that order.

    Deforming the copy skips the final reordering of every frame (about a
    third of the time on a large mesh). ``order[i]`` is the original index of
    new vertex ``i``; landmarks, regions and faces are renumbered to match.
    """
    order = Deformer(model).perm
    return model.reordered(order), order


def _rows(a: np.ndarray) -> np.ndarray:
    """View an (N, 3) float64 array as N opaque 24-byte rows (fast fancy indexing)."""
    return a.view(np.dtype((np.void, 24))).reshape(-1)


def _floats(rows: np.ndarray) -> np.ndarray:
    return rows.view(np.float64).reshape(-1, 3)


def deform_reference(model: Model, values: Mapping[str, float] | None = None) -> np.ndarray:
    """The same deformation written literally, one vertex at a time.

    Slow (pure Python loops over vertices); used by the tests to check the
    vectorised :class:`Deformer` against an independent implementation of
    the formulation in ``docs/deformation.md``.
    """
    tree = model.parameters
    vals = dict(zip(tree.names, model.values_array(values), strict=True))
    local = {n: tree[n].transform(vals[n]) for n in tree.names}
    world: dict[str, np.ndarray] = {}
    for n in tree.topological():
        parent = tree[n].parent
        world[n] = local[n] if parent is None else local[n] @ world[parent]
    n_vertices = model.n_vertices
    group1 = [n for n in tree.names if not tree.is_leaf(n)]
    leaves = [n for n in tree.names if tree.is_leaf(n)]
    dense = {n: model.regions[n].dense(n_vertices) for n in tree.names}
    fields: dict[str, np.ndarray] = {}
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

