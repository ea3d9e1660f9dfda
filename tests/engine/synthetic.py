"""Small synthetic models for the engine tests: random rigs on random point clouds.

Everything is drawn from a :class:`numpy.random.Generator`, so one seed gives
one model. A rig has

* a parameter tree of a chosen size and depth (non-leaves are group 1, leaves
  group 2, §2.2), with rotations, uniform translations and, among the leaves,
  field translations (per-vertex displacements, §3.1.2);
* group-1 weights of three kinds: vertices bound to one parameter (weight 1,
  or a partial weight that normalisation turns into 1), vertices blended
  between two or three parameters, and free vertices carried by none;
* leaf regions with full (1.0) or partial weights, laid out either as
  contiguous runs of vertex indices (the deformer then uses slices) or
  scattered (fancy indices).

Lengths are millimetres, angles degrees, as in the engine.

>>> rng = np.random.default_rng(1)
>>> model = random_model(rng, n_vertices=30, n_parameters=6, depth=3)
>>> values = random_values(rng, model)
>>> model.deform(values).shape
(30, 3)
"""

from __future__ import annotations

import numpy as np

from engine.deform.transforms import rotation_about_axis, translation
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree

# ---------------------------------------------------------------------------
# Geometry
# ---------------------------------------------------------------------------

def stable_unit_vector(rng: np.random.Generator) -> np.ndarray:
    """A random unit vector that re-normalising leaves bit-identical.

    Dividing by the norm is not idempotent in floating point (``(1, 1, 0)``
    changes in the last bit each time); the engine once re-normalised axes on
    every construction, which broke exact round trips. Drawing fixed points
    keeps the other tests independent of that
    (``test_round_trip_keeps_a_diagonal_axis`` checks it on its own).
    """
    while True:
        a = rng.normal(size=3)
        a = a / np.linalg.norm(a)
        if np.array_equal(a / np.linalg.norm(a), a):
            return a


def random_vertices(rng: np.random.Generator, n: int, scale: float = 100.0) -> np.ndarray:
    """``n`` points in a box of ±``scale`` mm."""
    return rng.uniform(-scale, scale, size=(n, 3))


def strip_faces(n_vertices: int) -> np.ndarray:
    """A valid flat cell array over ``n_vertices`` points: triangles plus one quad.

    The faces only have to be well formed; the deformation never reads them.
    """
    cells: list[int] = []
    for i in range(n_vertices - 2):
        cells += [3, i, i + 1, i + 2]
    if n_vertices >= 4:
        cells += [4, 0, 1, n_vertices - 1, n_vertices - 2]
    return np.array(cells, dtype=np.int64)


# ---------------------------------------------------------------------------
# Parameter trees
# ---------------------------------------------------------------------------

def random_parents(rng: np.random.Generator, n: int, depth: int) -> list[int | None]:
    """Parent index (or None) for ``n`` parameters, no chain longer than ``depth``.

    Parameter 0 is a root; when ``depth > 1`` parameter 1 is its child, so the
    tree always reaches at least two levels (there is a group 1).
    """
    parents: list[int | None] = []
    levels: list[int] = []
    for i in range(n):
        if i == 0 or depth <= 1:
            parent = None
        elif i == 1:
            parent = 0
        else:
            candidates = [j for j in range(i) if levels[j] < depth - 1]
            parent = None if (not candidates or rng.random() < 0.15) else int(rng.choice(candidates))
        parents.append(parent)
        levels.append(0 if parent is None else levels[parent] + 1)
    return parents


def random_parameter(rng: np.random.Generator, name: str, parent: str | None, *, leaf: bool,
                     kinds=("rotation", "translation", "field"), nonzero_defaults: bool = False) -> Parameter:
    """One random parameter; ``"field"`` (a blendshape) is only drawn for leaves."""
    allowed = [k for k in kinds if leaf or k != "field"]
    weights = np.array([3.0 if k == "rotation" else 1.0 for k in allowed])
    kind = allowed[int(rng.choice(len(allowed), p=weights / weights.sum()))]
    lo = -float(rng.choice([0.0, 0.5, 1.0, 1.5]))
    hi = float(rng.choice([0.5, 1.0, 1.5]))
    default = float(rng.uniform(lo, hi)) if nonzero_defaults and rng.random() < 0.3 else 0.0
    common = dict(name=name, parent=parent, minimum=lo, maximum=hi, default=default,
                  description=f"synthetic {kind} parameter" if rng.random() < 0.5 else "")
    if kind == "rotation":
        return Parameter(kind="rotation", axis=stable_unit_vector(rng), pivot=rng.uniform(-50, 50, 3),
                         degrees_per_unit=float(rng.uniform(5, 45)), **common)
    if kind == "translation":
        return Parameter(kind="translation", direction=rng.uniform(-10, 10, 3), **common)
    return Parameter(kind="translation", field=True, **common)


def random_tree(rng: np.random.Generator, n_parameters: int = 6, depth: int = 3, *,
                kinds=("rotation", "translation", "field"), nonzero_defaults: bool = False) -> ParameterTree:
    """A random tree with names ``p0, p1, …`` (valid XML names, so models can be saved)."""
    parents = random_parents(rng, n_parameters, depth)
    has_child = {p for p in parents if p is not None}
    params = [random_parameter(rng, f"p{i}", None if parents[i] is None else f"p{parents[i]}",
                               leaf=i not in has_child, kinds=kinds, nonzero_defaults=nonzero_defaults)
              for i in range(n_parameters)]
    return ParameterTree(params)


# ---------------------------------------------------------------------------
# Influence regions
# ---------------------------------------------------------------------------

def random_regions(rng: np.random.Generator, tree: ParameterTree, n_vertices: int, *,
                   partial: bool = True, contiguous: bool = False,
                   free_fraction: float = 0.15, blend_fraction: float = 0.25,
                   leaf_fraction: float = 0.4) -> dict[str, InfluenceRegion]:
    """Random influence regions for every parameter of ``tree``.

    Group 1: each vertex is free (no weight), bound to one parameter or
    blended between two or three. With ``partial`` the weights are arbitrary
    numbers in (0, 1] that the engine must normalise; without, a bound vertex
    has weight exactly 1. With ``contiguous`` the bound vertices of each
    parameter form one run of indices and every leaf region is one run.
    Leaves: a random subset (or run) of vertices with weights in [0, 1]
    (``partial``) or exactly 1; field translations get displacements in ±5 mm.
    """
    group1 = [p.name for p in tree if not tree.is_leaf(p.name)]
    leaves = [p.name for p in tree if tree.is_leaf(p.name)]
    g1_idx: dict[str, list[int]] = {n: [] for n in group1}
    g1_w: dict[str, list[float]] = {n: [] for n in group1}

    if group1:
        n_free = round(free_fraction * n_vertices)
        n_blend = round(blend_fraction * n_vertices) if len(group1) > 1 else 0
        n_bound = n_vertices - n_free - n_blend
        owner = np.sort(rng.integers(0, len(group1), n_bound))  # sorted: one run per parameter
        kinds = np.concatenate([owner, np.full(n_free, -1), np.full(n_blend, -2)])
        if not contiguous:
            kinds = rng.permutation(kinds)
        for v, k in enumerate(kinds):
            if k >= 0:
                w = float(rng.uniform(0.05, 1.0)) if partial and rng.random() < 0.5 else 1.0
                g1_idx[group1[k]].append(v)
                g1_w[group1[k]].append(w)
            elif k == -2:
                m = int(rng.integers(2, min(3, len(group1)) + 1))
                for j in rng.choice(len(group1), m, replace=False):
                    g1_idx[group1[j]].append(v)
                    g1_w[group1[j]].append(float(rng.uniform(0.05, 1.0)))

    regions = {n: InfluenceRegion(g1_idx[n], g1_w[n]) for n in group1}
    for name in leaves:
        size = max(1, round(leaf_fraction * n_vertices * rng.uniform(0.5, 1.5)))
        size = min(size, n_vertices)
        if contiguous:
            start = int(rng.integers(0, n_vertices - size + 1))
            idx = np.arange(start, start + size)
        else:
            idx = np.sort(rng.choice(n_vertices, size, replace=False))
        if partial:
            w = rng.uniform(0.0, 1.0, size)
            w[rng.random(size) < 0.3] = 1.0
            w[rng.random(size) < 0.1] = 0.0
        else:
            w = np.ones(size)
        disp = rng.uniform(-5, 5, (size, 3)) if tree[name].field else None
        regions[name] = InfluenceRegion(idx, w, disp)
    return regions


# ---------------------------------------------------------------------------
# Models and values
# ---------------------------------------------------------------------------

def random_model(rng: np.random.Generator | int, n_vertices: int = 40, n_parameters: int = 6,
                 depth: int = 3, *, partial: bool = True, contiguous: bool = False,
                 kinds=("rotation", "translation", "field"), nonzero_defaults: bool = False,
                 landmarks: bool = True) -> Model:
    """A random rigged model (see the module docstring). ``rng`` may be a seed."""
    rng = np.random.default_rng(rng)
    tree = random_tree(rng, n_parameters, depth, kinds=kinds, nonzero_defaults=nonzero_defaults)
    vertices = random_vertices(rng, n_vertices)
    regions = random_regions(rng, tree, n_vertices, partial=partial, contiguous=contiguous)
    parts = ["skin", "rigid_part"]
    vertex_part = (rng.random(n_vertices) < 0.3).astype(np.int64)
    marks = {"2.1": int(rng.integers(n_vertices)), "9.3": int(rng.integers(n_vertices))} if landmarks else {}
    return Model(vertices, strip_faces(n_vertices), parts, vertex_part, tree, regions, marks,
                 name="synthetic", description="a random rig for tests", part_colors={"skin": "#e3b49c"})


def random_values(rng: np.random.Generator, model: Model, *, zero_fraction: float = 0.25,
                  names=None, scale: float = 1.0) -> dict[str, float]:
    """Random values (in each parameter's range, times ``scale``) for ``names`` (all by default).

    About ``zero_fraction`` of them are exactly 0, so the deformer's
    "nothing to do" paths are exercised too.
    """
    names = model.parameters.names if names is None else list(names)
    out = {}
    for n in names:
        p = model.parameters[n]
        out[n] = 0.0 if rng.random() < zero_fraction else scale * float(rng.uniform(p.minimum, p.maximum))
    return out


def zero_values(model: Model) -> dict[str, float]:
    return dict.fromkeys(model.parameters.names, 0.0)


def group1_names(model: Model) -> list[str]:
    tree = model.parameters
    return [n for n in tree.names if not tree.is_leaf(n)]


def leaf_names(model: Model) -> list[str]:
    tree = model.parameters
    return [n for n in tree.names if tree.is_leaf(n)]


# ---------------------------------------------------------------------------
# Editing rigs for a test's purpose
# ---------------------------------------------------------------------------

def unbind(model: Model, vertices) -> None:
    """Remove ``vertices`` from every influence region (they stay put)."""
    vertices = np.asarray(vertices)
    for name in model.parameters.names:
        r = model.regions[name]
        keep = ~np.isin(r.indices, vertices)
        disp = None if r.displacements is None else r.displacements[keep]
        model.set_region(name, InfluenceRegion(r.indices[keep], r.weights[keep], disp))


def add_weight(model: Model, name: str, vertices, weight: float = 1.0, rng=None) -> None:
    """Give ``vertices`` (not yet in ``name``'s region) weight ``weight`` on ``name``.

    Field translations get random displacements (±5 mm) for the new vertices.
    """
    vertices = np.asarray(vertices, dtype=np.int64)
    r = model.regions[name]
    idx = np.concatenate([r.indices, vertices])
    w = np.concatenate([r.weights, np.full(len(vertices), weight)])
    disp = None
    if model.parameters[name].field:
        rng = np.random.default_rng(0) if rng is None else rng
        old = r.displacements if r.displacements is not None else np.zeros((0, 3))
        disp = np.concatenate([old, rng.uniform(-5, 5, (len(vertices), 3))])
    model.set_region(name, InfluenceRegion(idx, w, disp))


def bind(model: Model, vertices, group1: str | None = None, leaf: str | None = None,
         group1_weight: float = 1.0, leaf_weight: float = 1.0) -> None:
    """Make ``vertices`` move with exactly one group-1 parameter and/or one leaf."""
    unbind(model, vertices)
    if group1 is not None:
        add_weight(model, group1, vertices, group1_weight)
    if leaf is not None:
        add_weight(model, leaf, vertices, leaf_weight)


# ---------------------------------------------------------------------------
# Independent transforms (from the parameters' attributes, not Parameter.transform)
# ---------------------------------------------------------------------------

def own_transform(p: Parameter, value: float) -> np.ndarray:
    """``T_k(v)`` built straight from the parameter's attributes (row convention)."""
    if p.kind == "rotation":
        return rotation_about_axis(p.axis, p.pivot, value * p.degrees_per_unit)
    if p.field:
        return np.eye(4)
    return translation(value * p.direction)


def propagated_transform(model: Model, name: str, values) -> np.ndarray:
    """``T'_k = T_k · T_parent · T_grandparent · …`` (§2.2, child first)."""
    tree = model.parameters
    T = own_transform(tree[name], values.get(name, tree[name].default))
    for a in tree.ancestors(name):
        T = T @ own_transform(tree[a], values.get(a, tree[a].default))
    return T


def pairwise_distances(points: np.ndarray) -> np.ndarray:
    d = points[:, None, :] - points[None, :, :]
    return np.sqrt((d * d).sum(-1))


def assert_models_equal(a: Model, b: Model, *, order: bool = True) -> None:
    """Every piece of data two models hold is identical (exact, no tolerance)."""
    assert np.array_equal(a.vertices, b.vertices)
    assert a.vertices.dtype == b.vertices.dtype
    assert np.array_equal(a.faces, b.faces)
    assert a.parts == b.parts
    assert np.array_equal(a.vertex_part, b.vertex_part)
    assert a.part_colors == b.part_colors
    assert a.name == b.name
    assert a.description == b.description
    assert a.landmarks == b.landmarks
    names_a, names_b = a.parameters.names, b.parameters.names
    assert (names_a == names_b) if order else (sorted(names_a) == sorted(names_b))
    for n in names_a:
        p, q = a.parameters[n], b.parameters[n]
        for attr in ("name", "kind", "parent", "minimum", "maximum", "default", "degrees_per_unit",
                     "field", "description"):
            assert getattr(p, attr) == getattr(q, attr), (n, attr, getattr(p, attr), getattr(q, attr))
        for attr in ("axis", "pivot", "direction"):
            assert np.array_equal(getattr(p, attr), getattr(q, attr)), (n, attr)
        ra, rb = a.regions[n], b.regions[n]
        assert np.array_equal(ra.indices, rb.indices), n
        assert np.array_equal(ra.weights, rb.weights), n
        assert (ra.displacements is None) == (rb.displacements is None), n
        if ra.displacements is not None:
            assert np.array_equal(ra.displacements, rb.displacements), n
