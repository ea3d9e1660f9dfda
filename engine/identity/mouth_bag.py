"""The skin of the mouth's inside (the "bag" behind the lips), found on the mesh's own topology.

MakeHuman's skin closes the mouth with a bag of skin (palate, cheeks, floor)
behind the lips. :func:`oral_cavity` finds it: cut along the edge loop that
runs round the mouth through the upper lip's lowest midline vertex (landmark
2.2), the skin falls apart into the face and the bag. The default head's
derivation paints the bag dark by its depth behind that rim
(``engine/data/default-head/mouth_interior.py``); :mod:`engine.identity` moves it
with the face around it, so a new face's thinner cheeks do not let it show
through.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Sequence

import numpy as np
from scipy import sparse
from scipy.sparse.csgraph import connected_components, dijkstra


def polygon_graph(polygons: Sequence[np.ndarray], n: int) -> sparse.csr_matrix:
    """Edge graph over the polygons' own edges (not their triangulation's diagonals)."""
    edges = np.array([(p[i], p[(i + 1) % len(p)]) for p in polygons for i in range(len(p))])
    return sparse.coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n)).tocsr()


def edge_loop(polygons: Sequence[np.ndarray], start: int, first: int) -> list[int]:
    """The quad edge loop from ``start`` through ``first``, walked straight on at every
    four-valent vertex until it closes or meets a pole."""
    faces_of: defaultdict[int, list[int]] = defaultdict(list)
    neighbours: defaultdict[int, set[int]] = defaultdict(set)
    for f, p in enumerate(polygons):
        for i in range(len(p)):
            a, b = int(p[i]), int(p[(i + 1) % len(p)])
            faces_of[a].append(f)
            neighbours[a].add(b)
            neighbours[b].add(a)
    path = [int(start), int(first)]
    while len(neighbours[path[-1]]) == 4:
        u, v = path[-2], path[-1]
        beside = {int(x) for f in faces_of[v] if u in polygons[f] for x in polygons[f]}
        ahead = [w for w in neighbours[v] if w not in beside]
        if len(ahead) != 1 or ahead[0] in path:
            break
        path.append(ahead[0])
    return path


def oral_cavity(vertices: np.ndarray, polygons: Sequence[np.ndarray], is_skin: np.ndarray,
                upper_lip_vertex: int) -> tuple[np.ndarray, np.ndarray]:
    """The skin vertices of the mouth bag and each one's depth (mm, along the surface) behind the lip rim."""
    n = len(vertices)
    skin_polygons = [p for p in polygons if is_skin[p].all()]
    graph = polygon_graph(skin_polygons, n)
    graph = ((graph + graph.T) > 0).astype(float).tocoo()
    length = np.linalg.norm(vertices[graph.row] - vertices[graph.col], axis=1)
    distances = sparse.csr_matrix((length, (graph.row, graph.col)), shape=(n, n))
    sideways = [int(v) for v in distances[upper_lip_vertex].indices if vertices[v, 0] > vertices[upper_lip_vertex, 0]]
    if not sideways:
        return np.zeros(0, dtype=np.int64), np.zeros(0)
    rim = np.array(edge_loop(skin_polygons, upper_lip_vertex, sideways[0]))
    keep = np.ones(n, bool)
    keep[rim] = False
    cut = distances.multiply(keep[:, None]).multiply(keep[None, :]).tocsr()
    cut.eliminate_zeros()
    _count, label = connected_components(cut, directed=False)
    skin = np.flatnonzero(is_skin)
    face = label[skin[np.argmax(vertices[skin, 1])]]
    bag = np.flatnonzero(is_skin & keep & (label != face))
    depth = dijkstra(distances, indices=rim, min_only=True)
    return bag, np.asarray(depth[bag])
