"""The X-mirror vertex map: which vertex is each vertex's mirror image across the x = c plane.

Two passes:

1. **Exact** — mirror every vertex's position (x → 2c − x) and look up the
   nearest vertex in the KD-tree. A pair is accepted when it lies within
   ``tolerance`` mm, both vertices pick each other, and the parts agree
   (``eye_left`` pairs with ``eye_right``, ``skin`` with ``skin``). A
   symmetric mesh is matched completely here; the shipped head is.
2. **Topology-aware fallback** for the vertices left over (a mesh that is
   only nearly symmetric: sculpted, scanned, or with one side edited).
   The mirrored positions are first corrected by a smooth offset field
   (ICP-like: offsets to the nearest vertex averaged over the polygon ring,
   exact pairs pinned at zero), so a smoothly warped side still points at
   its partners. Candidates for vertex i are the ``candidates`` nearest
   left-over vertices to that prediction within ``search_radius``, and the
   neighbours of the partners of i's matched neighbours. A pair (i, j) is
   scored by *neighbourhood consistency* — how many of i's polygon-ring
   neighbours are mirrored onto ring neighbours of j — minus its position
   error in local edge lengths. Pairs that are each other's best choice are
   accepted round by round from the matched front outward: first those
   backed by at least two matched neighbours, then (one per piece of surface
   at a time) those backed by one, then an unambiguous position seed in a
   piece with no match yet (an eyeball). A pair whose finished
   neighbourhood clearly prefers another partner is undone and matched
   again, and a second pass predicts positions from the pairs of the first.
   Vertices that find no partner stay unmatched (−1) and are reported.
   ``docs/painting.md`` §4 has the statistics on perturbed heads.

The map is an involution on the matched vertices (``m[m[i]] == i``);
vertices on the plane map to themselves.

>>> from engine import load_model
>>> from engine.painting import PaintContext
>>> ctx = PaintContext(load_model())
>>> mm = ctx.mirror
>>> mm.n_unmatched, mm.n_exact == ctx.n_vertices
(0, True)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from engine.painting.topology import PaintContext


@dataclass
class MirrorMap:
    """Result of :func:`mirror_map`.

    Attributes
    ----------
    map : (N,) int array
        Mirror vertex of each vertex, −1 where none was found.
    exact : (N,) bool array
        True where the pair was found by position within the tolerance.
    error : (N,) float array
        Distance (mm) between a vertex's mirrored position and its partner;
        NaN where unmatched.
    center : float
        The mirror plane is x = ``center`` (mm).
    tolerance : float
        Exact-match tolerance (mm).
    rounds : int
        Rounds the topology-aware fallback ran (0 for a symmetric mesh).
    """

    map: np.ndarray
    exact: np.ndarray
    error: np.ndarray
    center: float = 0.0
    tolerance: float = 1e-3
    rounds: int = 0

    @property
    def unmatched(self) -> np.ndarray:
        """Indices of vertices without a mirror partner."""
        return np.flatnonzero(self.map < 0)

    @property
    def n_exact(self) -> int:
        return int(self.exact.sum())

    @property
    def n_fallback(self) -> int:
        return int(((self.map >= 0) & ~self.exact).sum())

    @property
    def n_unmatched(self) -> int:
        return int((self.map < 0).sum())

    def summary(self, parts: list[str] | None = None, vertex_part: np.ndarray | None = None) -> str:
        """One line of statistics, with unmatched counts per part when parts are given."""
        n = len(self.map)
        text = (f"{n} vertices: {self.n_exact} mirrored exactly, {self.n_fallback} by topology, "
                f"{self.n_unmatched} unmatched")
        if self.n_fallback:
            err = self.error[(self.map >= 0) & ~self.exact]
            text += f" (topology matches: median error {np.median(err):.3g} mm, max {err.max():.3g} mm)"
        if parts is not None and vertex_part is not None and self.n_unmatched:
            per = np.bincount(vertex_part[self.map < 0], minlength=len(parts))
            text += "; unmatched per part: " + ", ".join(f"{p} {c}" for p, c in zip(parts, per, strict=True) if c)
        return text


def mirrored_points(points: npt.ArrayLike, center: float = 0.0) -> np.ndarray:
    """Points reflected across the plane x = ``center`` (mm)."""
    m = np.array(points, dtype=float, copy=True)
    m[..., 0] = 2.0 * center - m[..., 0]
    return m


def mirrored_vectors(vectors: npt.ArrayLike) -> np.ndarray:
    """Directions (normals, displacements, view directions) reflected across an x = const plane."""
    m = np.array(vectors, dtype=float, copy=True)
    m[..., 0] = -m[..., 0]
    return m


def mirror_map(ctx: PaintContext, *, tolerance: float = 1e-3, center: float = 0.0,
               search_radius: float | None = None, candidates: int = 8, max_rounds: int = 500) -> MirrorMap:
    """Find every vertex's mirror partner across x = ``center`` (see the module docstring).

    Parameters
    ----------
    ctx : PaintContext
    tolerance : float
        Exact-match distance, mm.
    search_radius : float, optional
        How far (mm) from its mirrored position the fallback looks for a
        partner; default three median edge lengths.
    candidates : int
        Candidate partners per vertex in the fallback.
    max_rounds : int
        Upper bound on fallback rounds.
    """
    V = ctx.vertices
    n = len(V)
    M = mirrored_points(V, center)
    part, part_mirror = ctx.vertex_part, ctx.part_mirror
    mapping = np.full(n, -1, dtype=np.int64)
    exact = np.zeros(n, dtype=bool)
    if n == 0:
        return MirrorMap(mapping, exact, np.zeros(0), center, tolerance)
    _, j = ctx.tree.query(M, distance_upper_bound=tolerance)
    found = j < n
    jj = np.where(found, j, 0)
    back = np.where(found[jj], j[jj], -1)
    ok = found & (back == np.arange(n)) & (part_mirror[part] == part[jj])
    mapping[ok] = j[ok]
    exact[ok] = True
    rounds = 0
    if not ok.all():
        radius = 3.0 * ctx.edge_length if search_radius is None else float(search_radius)
        rounds = _topology_fallback(ctx, M, mapping, radius, candidates, max_rounds)
    error = np.full(n, np.nan)
    matched = mapping >= 0
    error[matched] = np.linalg.norm(M[matched] - V[mapping[matched]], axis=1)
    return MirrorMap(mapping, exact, error, float(center), float(tolerance), rounds)


def _topology_fallback(ctx: PaintContext, M: np.ndarray, mapping: np.ndarray, radius: float, candidates: int,
                       max_rounds: int, passes: int = 2) -> int:
    """Grow the matching outward from the matched vertices; see the module docstring."""
    n = len(mapping)
    exact = mapping >= 0
    incident = np.asarray(ctx.adjacency.sum(axis=1)).ravel()
    local = np.where(ctx.degree > 0, incident / np.maximum(ctx.degree, 1), ctx.edge_length)
    # consistency is counted over the polygon ring (vertices sharing a face, quad diagonals included):
    # on a quad grid a vertex just ahead of the matched front then sees three matched neighbours, not one
    ring = _ring_graph(ctx.faces, n)
    rounds = 0
    partners = None
    for _ in range(passes):
        # each pass predicts the partners' positions better: the first from nearest vertices, the next
        # from the partners the previous pass found
        P = _predicted_mirrors(ctx, M, exact, ring, radius, partners)
        mapping[~exact] = -1
        m = _Matcher(ctx, P, mapping, local, ring)
        gi, gj = m.geometric_pairs(np.flatnonzero(~exact), radius, candidates)
        rounds += m.grow(gi, gj, max_rounds)
        rounds += _refine(m, mapping, exact, gi, gj, max_rounds)
        if not (mapping < 0).any() and partners is not None and np.array_equal(partners, mapping):
            break
        partners = mapping.copy()
    return rounds


def _refine(m: _Matcher, mapping: np.ndarray, exact: np.ndarray, gi: np.ndarray, gj: np.ndarray,
            max_rounds: int) -> int:
    """Undo pairs whose neighbourhood now clearly supports another partner, and match them again."""
    n, rounds = len(mapping), 0
    for _ in range(3):
        matched = np.flatnonzero((mapping >= 0) & ~exact)
        # only pairs whose matched neighbourhood does not fully agree can have a better alternative
        matched = matched[m.consistency(matched, mapping[matched]) < m.matched_neighbours(matched)]
        if len(matched) == 0:
            break
        ti, tj = m.topological_pairs(matched, free_only=False)
        c = m.consistency(ti, tj)
        current = mapping[ti] == tj
        support = np.zeros(n)
        support[ti[current]] = c[current]
        better = ~current & (c >= support[ti] + 2)
        doubtful = np.unique(ti[better])
        doubtful = doubtful[~exact[doubtful] & (mapping[doubtful] >= 0)]
        if len(doubtful) == 0:
            break
        partners = mapping[doubtful]
        mapping[doubtful] = -1
        mapping[partners] = -1
        rounds += m.grow(gi, gj, max_rounds)
    return rounds


def _predicted_mirrors(ctx: PaintContext, M: np.ndarray, anchors: np.ndarray, ring: Any, radius: float,
                       partners: np.ndarray | None = None, iterations: int = 4, smoothing: int = 10) -> np.ndarray:
    """Mirrored positions corrected by a smooth offset field (ICP-like), so a smoothly warped side still
    predicts its partners: offsets to the nearest vertex (or to the partner found by an earlier pass)
    are averaged over the polygon ring, exact matches pinned at zero offset, and the lookup repeated
    with the corrected positions."""
    from scipy import sparse  # here, not at import: the workbench loads this module at start

    V = ctx.vertices
    deg = np.diff(ring.indptr)
    mean = (sparse.diags(1.0 / np.maximum(deg, 1)) @ ring + sparse.diags((deg == 0).astype(float))).tocsr()
    P = M.copy()
    for _ in range(iterations if partners is None else 1):
        d, nn = ctx.tree.query(P)
        if partners is not None:
            known = partners >= 0
            nn[known] = partners[known]
            d[known] = 0.0
        r = V[nn] - M
        r[anchors | (d > radius)] = 0.0
        for _ in range(smoothing):
            r = mean @ r
            r[anchors] = 0.0
        P = M + r
    return P


def _ring_graph(faces: np.ndarray, n: int) -> Any:
    """Symmetric CSR graph joining every two vertices of a polygon (sorted column indices)."""
    from scipy import sparse

    from engine.model.cells import cell_sizes, cell_starts

    sizes = cell_sizes(faces)
    starts = cell_starts(sizes)
    rows, cols = [], []
    for k in np.unique(sizes):
        poly = faces[starts[sizes == k][:, None] + np.arange(1, k + 1)]
        for a in range(k):
            for b in range(k):
                if a != b:
                    rows.append(poly[:, a])
                    cols.append(poly[:, b])
    g = sparse.csr_matrix((np.ones(sum(len(r) for r in rows)), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(n, n))
    g.sum_duplicates()
    g.data[:] = 1.0
    g.sort_indices()
    return g


class _Matcher:
    """Candidate pairs, their scores and the round-by-round acceptance of the fallback."""

    def __init__(self, ctx: PaintContext, M: np.ndarray, mapping: np.ndarray, local: np.ndarray, ring: Any):
        self.ctx, self.M, self.mapping, self.local = ctx, M, mapping, local
        self.n = len(mapping)
        self.indptr, self.indices = ring.indptr.astype(np.int64), ring.indices.astype(np.int64)
        self.degree = np.diff(self.indptr)
        rows = np.repeat(np.arange(self.n), self.degree)
        self.edge_keys = rows * self.n + self.indices          # sorted: CSR rows in order, columns sorted

    def _gather(self, vertices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(owner position, neighbour) for every neighbour of every vertex in ``vertices``."""
        counts = self.degree[vertices]
        total = int(counts.sum())
        offsets = np.repeat(self.indptr[vertices] - np.cumsum(counts) + counts, counts) + np.arange(total)
        return np.repeat(np.arange(len(vertices)), counts), self.indices[offsets]

    def _valid(self, pi: np.ndarray, pj: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ctx = self.ctx
        keep = ctx.part_mirror[ctx.vertex_part[pi]] == ctx.vertex_part[pj]
        pi, pj = pi[keep], pj[keep]
        key = np.unique(np.concatenate([pi * self.n + pj, pj * self.n + pi]))    # symmetric candidate sets
        return key // self.n, key % self.n

    def geometric_pairs(self, U: np.ndarray, radius: float, k: int) -> tuple[np.ndarray, np.ndarray]:
        """Each left-over vertex with its ``k`` nearest left-over vertices to its mirrored position."""
        k = min(k, len(U))
        if k == 0:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
        from scipy.spatial import cKDTree  # imported when needed: it costs 0.3 s at launch

        _, loc = cKDTree(self.ctx.vertices[U]).query(self.M[U], k=k, distance_upper_bound=radius)
        loc = loc.reshape(len(U), k)
        valid = loc < len(U)
        return self._valid(np.repeat(U, k)[valid.ravel()], U[loc[valid]])

    def topological_pairs(self, vertices: np.ndarray, free_only: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """(i, j): j a neighbour of the mirror of a matched neighbour of i — where topology predicts i's mirror."""
        owner, nb = self._gather(vertices)
        img = self.mapping[nb]
        ok = img >= 0
        owner, img = owner[ok], img[ok]
        owner2, cand = self._gather(img)
        pi, pj = vertices[owner[owner2]], cand
        if free_only:
            keep = self.mapping[pj] < 0
            pi, pj = pi[keep], pj[keep]
        return self._valid(pi, pj)

    def distance(self, pi: np.ndarray, pj: np.ndarray) -> np.ndarray:
        """Position error of the pair in local edge lengths (symmetric in i and j)."""
        V = self.ctx.vertices
        d = 0.5 * (np.linalg.norm(self.M[pi] - V[pj], axis=1) + np.linalg.norm(self.M[pj] - V[pi], axis=1))
        return d / (0.5 * (self.local[pi] + self.local[pj]))

    def matched_neighbours(self, vertices: np.ndarray) -> np.ndarray:
        owner, nb = self._gather(vertices)
        return np.bincount(owner[self.mapping[nb] >= 0], minlength=len(vertices)).astype(float)

    def consistency(self, pi: np.ndarray, pj: np.ndarray) -> np.ndarray:
        """How many neighbours of i are mirrored onto a neighbour of j (symmetric in i and j)."""
        owner, nb = self._gather(pi)
        img = self.mapping[nb]
        ok = img >= 0
        key = img[ok] * self.n + pj[owner[ok]]
        ek = self.edge_keys
        if len(ek) == 0:
            return np.zeros(len(pi))
        pos = np.minimum(np.searchsorted(ek, key), len(ek) - 1)
        return np.bincount(owner[ok][ek[pos] == key], minlength=len(pi)).astype(float)

    @staticmethod
    def _best(pi: np.ndarray, pj: np.ndarray, score: np.ndarray,
              n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each i's best-scoring partner; returns (i, j, position in the pair arrays) of mutual bests."""
        order = np.lexsort((-score, pi))
        head = np.ones(len(order), dtype=bool)
        head[1:] = pi[order][1:] != pi[order][:-1]
        best = np.full(n, -1, dtype=np.int64)
        bi, bj = pi[order][head], pj[order][head]
        best[bi] = bj
        mutual = best[bj] == bi
        return bi[mutual], bj[mutual], order[head][mutual]

    def grow(self, gi: np.ndarray, gj: np.ndarray, max_rounds: int) -> int:
        """Accept pairs round by round: well-supported first, then weakly supported, then position seeds.

        ``gi``/``gj`` are the geometric candidate pairs, sorted by ``gi``. The
        frontier (free vertices next to matched ones) is kept up to date
        from each round's new pairs, so a round costs what the frontier
        holds, not the mesh size.
        """
        mapping, n = self.mapping, self.n
        g_ptr = np.searchsorted(gi, np.arange(n + 1))
        free = mapping < 0
        front = np.zeros(n, dtype=bool)
        owner, nb = self._gather(np.flatnonzero(free))
        front[np.flatnonzero(free)[owner[mapping[nb] >= 0]]] = True
        level, rounds = 0, 0
        while rounds < max_rounds:
            rounds += 1
            if not free.any():
                break
            if level < 2:
                frontier = np.flatnonzero(front & free)
                ti, tj = self.topological_pairs(frontier)
                counts = g_ptr[frontier + 1] - g_ptr[frontier]
                total = int(counts.sum())
                offsets = np.repeat(g_ptr[frontier] - np.cumsum(counts) + counts, counts) + np.arange(total)
                fi, fj = gi[offsets], gj[offsets]
                both = free[fj] & front[fj]
                pi = np.concatenate([ti, fi[both]])
                pj = np.concatenate([tj, fj[both]])
                key = np.unique(pi * n + pj)
                pi, pj = key // n, key % n
                if len(pi) == 0:
                    level = 2
                    continue
                c = self.consistency(pi, pj)
                ai, aj, pos = self._best(pi, pj, c - self.distance(pi, pj), n)
                ac = c[pos]
                agreed = (ac >= 0.5 * self.matched_neighbours(ai)) & (ac >= 0.5 * self.matched_neighbours(aj))
                accept = agreed & (ac >= (2 if level == 0 else 1))
            else:
                both = free[gi] & free[gj]
                pi, pj = gi[both], gj[both]
                if len(pi) == 0:
                    break
                d = self.distance(pi, pj)
                ai, aj, pos = self._best(pi, pj, -d, n)
                # unambiguous: the second-nearest candidate of either side is much further away
                second = np.full(n, np.inf)
                order = np.lexsort((d, pi))
                si, sd = pi[order], d[order]
                first = np.ones(len(si), dtype=bool)
                first[1:] = si[1:] != si[:-1]
                after_first = ~first & np.concatenate([[False], first[:-1]])
                second[si[after_first]] = sd[after_first]
                bd = d[pos]
                accept = (second[ai] >= 2.0 * bd + 0.25) & (second[aj] >= 2.0 * bd + 0.25)
                ac = np.zeros(len(ai))
            ai, aj = ai[accept], aj[accept]
            if level > 0 and len(ai):
                # weak evidence: take only the most confident pair per piece of surface, then let the
                # well-supported growth (level 0) continue from it
                conf = (ac[accept] if level == 1 else 0.0) - self.distance(ai, aj)
                comp = self.ctx.components[ai]
                order = np.lexsort((-conf, comp))
                first = np.ones(len(order), dtype=bool)
                first[1:] = comp[order][1:] != comp[order][:-1]
                ai, aj = ai[order][first], aj[order][first]
            if len(ai) == 0:
                level += 1
                if level > 2:
                    break
                continue
            level = 0
            mapping[ai], mapping[aj] = aj, ai
            free[ai] = free[aj] = False
            _, nb = self._gather(np.concatenate([ai, aj]))
            front[nb[free[nb]]] = True
        return rounds
