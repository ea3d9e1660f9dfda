"""The deformation engine's invariants (§2.2; derived in docs/deformation.md).

Every test names the invariant it checks. The synthetic rigs come from
``synthetic.py``; the last section repeats invariants 1, 2, 3 and 5 on the
shipped default head when ``engine/data/default-head/head.xml`` exists. Positions
are in mm; "exactly" means ``np.array_equal``, otherwise the tolerance is
1e-9 mm on coordinates of about ±100 mm.

Every test runs twice, through each of the engine's two deformation paths: the
compiled vertex pass (``engine.deform._kernel``; skipped when it is not built,
which ``test_deform_kernel.py`` reports as a failure) and the numpy fallback.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine.deform.deformer
from engine.deform.deformer import deform_reference
from engine.deform.transforms import apply
from engine.errors import ParameterError
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree
from tests.engine.synthetic import (
    add_weight,
    bind,
    group1_names,
    leaf_names,
    own_transform,
    pairwise_distances,
    propagated_transform,
    random_model,
    random_values,
    strip_faces,
    zero_values,
)

TOL = 1e-9  # mm

#: (n_vertices, n_parameters, depth, partial weights, contiguous layout)
SHAPES = [
    (12, 2, 2, False, True),
    (30, 4, 2, True, False),
    (40, 6, 3, True, False),
    (40, 6, 3, False, True),
    (50, 9, 4, True, True),
    (60, 9, 5, True, False),
    (25, 5, 1, True, False),   # depth 1: every parameter is a leaf, no group 1
]
SEEDS = [0, 1, 2]
RIGS = [(seed, *shape) for shape in SHAPES for seed in SEEDS]


@pytest.fixture(autouse=True, params=["kernel", "numpy"])
def deform_path(request, monkeypatch):
    """Run the test with the compiled kernel, then with the numpy path (``Deformer(model)``
    picks the kernel exactly when ``engine.deform.deformer.compiled`` is set)."""
    if request.param == "numpy":
        monkeypatch.setattr(engine.deform.deformer, "compiled", None)
    elif engine.deform.deformer.compiled is None:
        pytest.skip("the compiled deformation kernel is not built")
    return request.param


def rig(seed, n_vertices, n_parameters, depth, partial, contiguous, **kw) -> Model:
    return random_model(np.random.default_rng(seed), n_vertices, n_parameters, depth,
                        partial=partial, contiguous=contiguous, **kw)


def with_region(model: Model, name: str, region: InfluenceRegion) -> Model:
    """The same model (same parameter objects) with one region replaced."""
    regions = dict(model.regions)
    regions[name] = region
    return Model(model.vertices, model.faces, model.parts, model.vertex_part, model.parameters, regions,
                 model.landmarks)


def blended_matrix(model: Model, i: int, values) -> np.ndarray:
    """The rigid carry of vertex ``i`` (the paper's stage 1, the engine's stage 2, §2.2):
    ``I + Σ_group1 w̄_ik (T'_k − I)`` with normalised weights, built independently."""
    names = group1_names(model)
    w = np.array([model.regions[n].dense(model.n_vertices)[i] for n in names])
    M = np.eye(4)
    if w.sum() > 0:
        for n, wk in zip(names, w / w.sum(), strict=True):
            M += wk * (propagated_transform(model, n, values) - np.eye(4))
    return M


# ---------------------------------------------------------------------------
# Invariant 1: all values 0 → the rest mesh exactly
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", RIGS)
def test_invariant1_all_values_zero_give_rest_mesh_exactly(seed, n, k, depth, partial, contiguous):
    """Invariant 1 (§2.2): with every parameter at 0 every ``T_k`` is the identity, so
    Eq. 1/2 and both stages leave the rest mesh untouched, bit for bit."""
    model = rig(seed, n, k, depth, partial, contiguous, nonzero_defaults=True)
    assert np.array_equal(model.deform(zero_values(model)), model.vertices)
    assert np.array_equal(model.deformer().deform(np.zeros(len(model.parameters))), model.vertices)
    negative_zero = dict.fromkeys(model.parameters.names, -0.0)
    assert np.array_equal(model.deform(negative_zero), model.vertices)


def test_invariant1_deform_returns_a_fresh_array():
    """Invariant 1 must not be bought by handing out the rest mesh itself: editing the
    result of one call must not change the next one or the model."""
    model = rig(0, 20, 4, 2, True, False)
    first = model.deform(zero_values(model))
    first += 1000.0
    assert np.array_equal(model.deform(zero_values(model)), model.vertices)
    assert not np.shares_memory(first, model.vertices)


# ---------------------------------------------------------------------------
# Invariant 2: a leaf at 0 contributes nothing, whatever its ancestors do
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", [r for r in RIGS if r[3] > 1])
def test_invariant2_leaf_at_zero_contributes_nothing(seed, n, k, depth, partial, contiguous):
    """Invariant 2 (§2.2, and the reason for the engine's formulation): the paper's literal
    stage 2 would apply ``T'_leaf``, which contains the ancestors' motion, to points stage 1
    already moved. Here a leaf at 0, with random values on its ancestors and every other
    parameter, must give exactly what the same model gives with the leaf's region emptied —
    at value 0 and at any other value."""
    model = rig(seed, n, k, depth, partial, contiguous)
    rng = np.random.default_rng(100 + seed)
    for leaf in leaf_names(model):
        for _ in range(3):
            values = random_values(rng, model, zero_fraction=0.1)
            for a in model.parameters.ancestors(leaf):
                values[a] = values[a] or 0.7 * model.parameters[a].maximum
            values[leaf] = 0.0
            with_leaf = model.deform(values)
            emptied = with_region(model, leaf, InfluenceRegion())
            assert np.array_equal(with_leaf, emptied.deform(values)), leaf
            values[leaf] = float(rng.uniform(0.2, 1.0))
            assert np.array_equal(with_leaf, emptied.deform(values)), leaf


def test_literal_stage2_formula_would_move_a_leaf_at_zero():
    """The worked counterexample of docs/deformation.md (§2.2): parent ``p`` turns 90° about
    +z through the origin, its leaf ``c`` (a 10 mm translation along x per unit) is at 0, and
    vertex P = (10, 0, 0) has weight 1 on both. The literal stage-2 formula applies
    ``T'_c = T_c · T_p = T_p`` a second time and lands at (−10, 0, 0); the engine keeps the
    leaf's motion in the rest frame and lands at P · T'_p = (0, 10, 0)."""
    tree = ParameterTree([
        Parameter("p", "rotation", axis=(0, 0, 1), pivot=(0, 0, 0), degrees_per_unit=90),
        Parameter("c", "translation", parent="p", direction=(10, 0, 0)),
    ])
    model = Model([[10.0, 0.0, 0.0]], [], parameters=tree,
                  regions={"p": InfluenceRegion([0], [1.0]), "c": InfluenceRegion([0], [1.0])})
    P = np.array([10.0, 0.0, 0.0])
    T_p, T_c0 = tree["p"].transform(1.0), tree["c"].transform(0.0)
    stage1 = apply(T_p, [P])                                       # (0, 10, 0)
    literal = apply(np.eye(4) + 1.0 * (T_c0 @ T_p - np.eye(4)), stage1)
    np.testing.assert_allclose(literal, [[-10.0, 0.0, 0.0]], atol=1e-12)
    np.testing.assert_allclose(model.deform(p=1.0, c=0.0), [[0.0, 10.0, 0.0]], atol=1e-12)
    # And with the leaf at 1: P · T_c · T'_p = (20, 0, 0) turned = (0, 20, 0).
    np.testing.assert_allclose(model.deform(p=1.0, c=1.0), [[0.0, 20.0, 0.0]], atol=1e-12)


# ---------------------------------------------------------------------------
# Invariant 3: group-1 weight 1 on p, leaf weight 1 on child c → P · T_c · T'_p
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", [r for r in RIGS if r[3] > 1])
@pytest.mark.parametrize("group1_weight", [1.0, 0.3])
def test_invariant3_leaf_motion_is_carried_by_the_parent(seed, n, k, depth, partial, contiguous,
                                                         group1_weight):
    """Invariant 3 (§2.2): leaf motion is authored in the rest pose and carried by the rigid
    motion: a vertex with group-1 weight 1 on ``p`` (or any single weight, which normalisation
    makes 1) and leaf weight 1 on a child ``c`` of ``p`` ends at ``P · T_c · T'_p``, with the
    matrices built here from the parameters' attributes and the tree, not by the Deformer."""
    model = rig(seed, n, k, depth, partial, contiguous)
    tree = model.parameters
    rng = np.random.default_rng(200 + seed)
    pairs = [(tree[c].parent, c) for c in leaf_names(model) if tree[c].parent is not None]
    assert pairs, "every rig with depth > 1 has a leaf with a parent"
    for p, c in pairs:
        vertices = rng.choice(model.n_vertices, size=min(4, model.n_vertices), replace=False)
        bind(model, vertices, group1=p, leaf=c, group1_weight=group1_weight)
        for _ in range(3):
            values = random_values(rng, model, zero_fraction=0.1)
            P = model.vertices[vertices]
            if tree[c].field:
                r = model.regions[c]
                D = r.displacements[np.searchsorted(r.indices, vertices)]
                moved_by_leaf = P + values[c] * D
            else:
                moved_by_leaf = apply(own_transform(tree[c], values[c]), P)
            expected = apply(propagated_transform(model, p, values), moved_by_leaf)
            np.testing.assert_allclose(model.deform(values)[vertices], expected, rtol=0, atol=TOL,
                                       err_msg=f"parent {p}, leaf {c}")


# ---------------------------------------------------------------------------
# Invariant 4: leaf effects superpose linearly in the rest frame (Eq. 2)
# ---------------------------------------------------------------------------

def _split_leaves(rng, model):
    leaves = leaf_names(model)
    mask = rng.random(len(leaves)) < 0.5
    a = [n for n, m in zip(leaves, mask, strict=True) if m]
    b = [n for n, m in zip(leaves, mask, strict=True) if not m]
    return a, b


def _make_leaf_regions_disjoint(model: Model, rng) -> None:
    """Give every vertex to at most one leaf."""
    leaves = leaf_names(model)
    owner = rng.integers(-1, len(leaves), model.n_vertices)
    for j, name in enumerate(leaves):
        r = model.regions[name]
        keep = owner[r.indices] == j
        disp = None if r.displacements is None else r.displacements[keep]
        model.set_region(name, InfluenceRegion(r.indices[keep], r.weights[keep], disp))


def _make_leaf_regions_overlap(model: Model, rng) -> None:
    """Put a few vertices into every leaf's region."""
    shared = rng.choice(model.n_vertices, size=min(5, model.n_vertices), replace=False)
    for name in leaf_names(model):
        new = np.setdiff1d(shared, model.regions[name].indices)
        add_weight(model, name, new, float(rng.uniform(0.3, 1.0)), rng=rng)


@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", RIGS)
@pytest.mark.parametrize("layout", ["overlapping", "disjoint"])
def test_invariant4_leaves_superpose_in_the_rest_frame(seed, n, k, depth, partial, contiguous, layout):
    """Invariant 4, Eq. 2 (§2.2): with every group-1 value at 0 the displacement of a set of
    leaves is the sum of the displacements of its parts (``d(a ∪ b) = d(a) + d(b)``), and the
    displacement of all leaves is the sum over single leaves, whether the leaves' regions
    overlap or not."""
    model = rig(seed, n, k, depth, partial, contiguous)
    rng = np.random.default_rng(300 + seed)
    if layout == "disjoint":
        _make_leaf_regions_disjoint(model, rng)
    else:
        _make_leaf_regions_overlap(model, rng)
    P = model.vertices
    for _ in range(3):
        values = random_values(rng, model, zero_fraction=0.0, names=leaf_names(model))
        a, b = _split_leaves(rng, model)

        def d(names, values=values):
            return model.deform({name: values[name] for name in names}) - P

        np.testing.assert_allclose(d(a + b), d(a) + d(b), rtol=0, atol=TOL)
        np.testing.assert_allclose(d(a + b), sum(d([name]) for name in a + b), rtol=0, atol=TOL)


@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", [r for r in RIGS if r[3] > 1])
def test_invariant4_stage1_superposes_before_the_rigid_carry(seed, n, k, depth, partial, contiguous):
    """Invariant 4 with group-1 motion (§2.2, stage 1 then stage 2): leaves superpose in the
    rest frame and the sum is then carried by each vertex's blended rigid transform ``M_i``:
    ``result_i = (P_i + Σ_leaf d_k,i) · M_i``. Since the carry is affine per vertex, the
    leaf sets' contributions above the rigid-only pose add up too."""
    model = rig(seed, n, k, depth, partial, contiguous)
    rng = np.random.default_rng(400 + seed)
    for _ in range(2):
        rigid = random_values(rng, model, zero_fraction=0.2, names=group1_names(model))
        leaves = random_values(rng, model, zero_fraction=0.0, names=leaf_names(model))
        a, b = _split_leaves(rng, model)

        def pose(names, rigid=rigid, leaves=leaves):
            return model.deform({**rigid, **{name: leaves[name] for name in names}})

        Z, X, Y, R = pose([]), pose(a), pose(b), pose(a + b)
        np.testing.assert_allclose(R - Z, (X - Z) + (Y - Z), rtol=0, atol=TOL)
        rest_frame = model.deform(leaves)   # group 1 at 0: stage 1 alone
        for i in range(model.n_vertices):
            expected = apply(blended_matrix(model, i, rigid), rest_frame[i:i + 1])
            np.testing.assert_allclose(R[i:i + 1], expected, rtol=0, atol=TOL)


@pytest.mark.parametrize("seed", SEEDS)
def test_translation_leaves_are_linear_in_their_values(seed):
    """Eq. 2 with translation parameters (§3.1.2: one translation parameter per principal
    component, so that the superposition is a linear model): with group 1 at rest, the
    displacement is linear in the values of uniform and field translations."""
    model = rig(seed, 40, 8, 2, True, False, kinds=("translation", "field"))
    rng = np.random.default_rng(500 + seed)
    leaves = leaf_names(model)
    u = {n: float(rng.uniform(-1, 1)) for n in leaves}
    v = {n: float(rng.uniform(-1, 1)) for n in leaves}
    P = model.vertices
    du, dv = model.deform(u) - P, model.deform(v) - P
    combined = model.deform({n: 0.5 * u[n] - 2.0 * v[n] for n in leaves}) - P
    np.testing.assert_allclose(combined, 0.5 * du - 2.0 * dv, rtol=0, atol=TOL)


# ---------------------------------------------------------------------------
# Invariant 5: a region rigidly bound to one rotation keeps all pairwise distances
# ---------------------------------------------------------------------------

@pytest.mark.parametrize("seed,n,k,depth,partial,contiguous", RIGS)
def test_invariant5_rigidly_bound_region_keeps_its_shape(seed, n, k, depth, partial, contiguous):
    """Invariant 5 (§2.2, group 1 is "skeletal and other rigid motion"): vertices bound with
    weight 1 to one rotation — a group-1 rotation (carried by its ancestors), a leaf rotation
    alone, or a leaf rotation under its group-1 parent — keep all pairwise distances."""
    model = rig(seed, n, k, depth, partial, contiguous, kinds=("rotation", "translation"))
    tree = model.parameters
    rng = np.random.default_rng(600 + seed)
    rotations = [p.name for p in tree if p.kind == "rotation"]
    for name in rotations:
        vertices = rng.choice(model.n_vertices, size=min(8, model.n_vertices), replace=False)
        if not tree.is_leaf(name):
            bind(model, vertices, group1=name)
        elif tree[name].parent is not None and rng.random() < 0.5:
            bind(model, vertices, group1=tree[name].parent, leaf=name)
        else:
            bind(model, vertices, leaf=name)
        values = random_values(rng, model, zero_fraction=0.1)
        values[name] = values[name] or tree[name].maximum
        before = pairwise_distances(model.vertices[vertices])
        moved = model.deform(values)[vertices]
        assert np.abs(moved - model.vertices[vertices]).max() > 1e-3, "the region moved"
        np.testing.assert_allclose(pairwise_distances(moved), before, rtol=0, atol=TOL, err_msg=name)


# ---------------------------------------------------------------------------
# Group-1 normalisation and propagation
# ---------------------------------------------------------------------------

def _two_bone_rig(weights_a, weights_b) -> Model:
    """Two sibling group-1 rotations ``a`` and ``b`` under a root, each with one leaf."""
    tree = ParameterTree([
        Parameter("root", "translation", direction=(3, -2, 1)),
        Parameter("a", "rotation", parent="root", axis=(0, 0, 1), pivot=(5, 0, 0), degrees_per_unit=40),
        Parameter("b", "rotation", parent="root", axis=(1, 0, 0), pivot=(0, 5, 0), degrees_per_unit=25),
        Parameter("a_leaf", "translation", parent="a", direction=(1, 1, 0)),
        Parameter("b_leaf", "rotation", parent="b", axis=(0, 1, 0), pivot=(0, 0, 3), degrees_per_unit=10),
    ])
    rng = np.random.default_rng(7)
    n = len(weights_a)
    idx = np.arange(n)
    regions = {
        "root": InfluenceRegion(),
        "a": InfluenceRegion(idx, weights_a),
        "b": InfluenceRegion(idx, weights_b),
        "a_leaf": InfluenceRegion(idx, rng.uniform(0, 1, n)),
        "b_leaf": InfluenceRegion(idx, rng.uniform(0, 1, n)),
    }
    return Model(rng.uniform(-20, 20, (n, 3)), strip_faces(n), parameters=tree, regions=regions)


def test_group1_weights_are_normalised_per_vertex():
    """§2.2: "Weights for the parameters in the first group have to be normalized for each
    vertex ... The normalization is done in the animation engine." A vertex with 0.2/0.2 on two
    group-1 parameters moves exactly like one with 0.5/0.5 (or 1/1), and a single partial
    weight 0.3 like 1."""
    values = {"root": 0.8, "a": 0.9, "b": -0.7, "a_leaf": 0.5, "b_leaf": 0.6}
    n = 6
    reference = _two_bone_rig(np.full(n, 0.5), np.full(n, 0.5)).deform(values)
    for wa, wb in [(0.2, 0.2), (1.0, 1.0), (0.05, 0.05)]:
        np.testing.assert_allclose(_two_bone_rig(np.full(n, wa), np.full(n, wb)).deform(values),
                                   reference, rtol=0, atol=1e-12)
    single = _two_bone_rig(np.full(n, 1.0), np.zeros(n)).deform(values)
    np.testing.assert_allclose(_two_bone_rig(np.full(n, 0.3), np.zeros(n)).deform(values),
                               single, rtol=0, atol=1e-12)
    # and the blend is the normalised one: P1 · (0.25 T'_a + 0.75 T'_b) for weights 0.2 / 0.6
    model = _two_bone_rig(np.full(n, 0.2), np.full(n, 0.6))
    rest_frame = model.deform({"a_leaf": 0.5, "b_leaf": 0.6})
    M = 0.25 * propagated_transform(model, "a", values) + 0.75 * propagated_transform(model, "b", values)
    np.testing.assert_allclose(model.deform(values), apply(M, rest_frame), rtol=0, atol=TOL)


def test_tiny_group1_weights_are_normalised_like_any_other():
    """§2.2 normalisation for any positive weights: 1e-310 / 1e-310 behaves like 0.5 / 0.5
    (tiny weights do come out of smooth brush fall-offs such as exp(-d²)). (Regression: the
    Deformer multiplied by 1/total, which overflows to inf for subnormal totals, and blended
    vertices became NaN.)"""
    values = {"root": 0.8, "a": 0.9, "b": -0.7, "a_leaf": 0.5, "b_leaf": 0.6}
    n = 3
    tiny = _two_bone_rig(np.full(n, 1e-310), np.full(n, 1e-310))
    half = _two_bone_rig(np.full(n, 0.5), np.full(n, 0.5))
    np.testing.assert_allclose(deform_reference(tiny, values), half.deform(values), rtol=0, atol=1e-12)
    np.testing.assert_allclose(tiny.deform(values), half.deform(values), rtol=0, atol=1e-12)


def test_group2_weights_are_not_normalised():
    """§2.2: "The weights for the parameters in the second group are not normalized."
    A leaf weight of 0.5 gives half the leaf's displacement."""
    tree = ParameterTree([Parameter("t", "translation", direction=(10, 0, 0))])
    model = Model(np.zeros((2, 3)), [], parameters=tree,
                  regions={"t": InfluenceRegion([0, 1], [0.5, 1.0])})
    np.testing.assert_array_equal(model.deform(t=1.0), [[5.0, 0, 0], [10.0, 0, 0]])


def test_propagation_is_child_first():
    """§2.2: ``T'_c = T_c · T_p`` (row vectors, so the child's own motion applies first, then
    the parent's), recursively ``T'_g = T_g · T_c · T_p`` down a chain. Checked on the
    Deformer's matrices and on a vertex bound to the middle of a chain of non-commuting
    rotations."""
    tree = ParameterTree([
        Parameter("root", "rotation", axis=(0, 0, 1), pivot=(0, 0, 0), degrees_per_unit=90),
        Parameter("mid", "rotation", parent="root", axis=(1, 0, 0), pivot=(0, 10, 0), degrees_per_unit=90),
        Parameter("tip", "translation", parent="mid", direction=(0, 0, 7)),
    ])
    regions = {"root": InfluenceRegion(), "mid": InfluenceRegion([0], [1.0]), "tip": InfluenceRegion()}
    model = Model([[3.0, 4.0, 5.0]], [], parameters=tree, regions=regions)
    values = {"root": 1.0, "mid": 1.0, "tip": 1.0}
    local, world = model.deformer().transforms(model.values_array(values))
    r, m, t = (tree.names.index(x) for x in ("root", "mid", "tip"))
    assert np.array_equal(world[r], local[r])
    assert np.array_equal(world[m], local[m] @ world[r])
    np.testing.assert_allclose(world[t], local[t] @ local[m] @ local[r], rtol=0, atol=1e-12)
    x = np.array([[1.0, 2.0, 3.0]])
    np.testing.assert_allclose(apply(world[t], x), apply(local[r], apply(local[m], apply(local[t], x))),
                               atol=1e-12)
    P = np.array([[3.0, 4.0, 5.0]])
    child_first = apply(local[r], apply(local[m], P))
    parent_first = apply(local[m], apply(local[r], P))
    assert not np.allclose(child_first, parent_first), "the example must not commute"
    np.testing.assert_allclose(model.deform(values), child_first, atol=1e-12)


# ---------------------------------------------------------------------------
# The vectorised Deformer against the literal reference
# ---------------------------------------------------------------------------

@settings(max_examples=80, derandomize=True, deadline=None, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), n_vertices=st.integers(1, 50), n_parameters=st.integers(1, 9),
       depth=st.integers(1, 5), partial=st.booleans(), contiguous=st.booleans(),
       zero_fraction=st.sampled_from([0.0, 0.3, 1.0]), scale=st.sampled_from([1.0, 3.0]))
def test_vectorised_deformer_equals_literal_reference(seed, n_vertices, n_parameters, depth, partial,
                                                      contiguous, zero_fraction, scale):
    """The :class:`Deformer` (compiled segments, or numpy blocks, blended band and leaves)
    gives the literal per-vertex formulation of §2.2 (``engine.deform.deformer.deform_reference``) to
    1e-9 mm, for random trees, weights, layouts and values (including values beyond the range)."""
    rng = np.random.default_rng(seed)
    model = random_model(rng, n_vertices, n_parameters, depth, partial=partial, contiguous=contiguous,
                         landmarks=False)
    values = random_values(rng, model, zero_fraction=zero_fraction, scale=scale)
    np.testing.assert_allclose(model.deform(values), deform_reference(model, values), rtol=0, atol=TOL)


@pytest.mark.parametrize("seed", SEEDS)
def test_fast_path_runs_indices_and_vertex_orders_agree(seed, monkeypatch):
    """The numpy path applies a leaf through contiguous runs of its internal order, or through
    an index array when a leaf splits into more than ``Deformer.MAX_RUNS`` runs; both paths
    skip the final reordering when the model's vertex order is already their internal order
    (the kernel otherwise writes each vertex to its own row). All layouts give the reference,
    and each other vertex for vertex. (Looks at the numpy ``Deformer.leaves``, whose second
    field is the list of runs or the index array.)"""
    from engine.deform.deformer import Deformer, optimise_vertex_order

    model = rig(seed, 60, 8, 3, False, True)
    assert all(isinstance(leaf[1], list) for leaf in Deformer(model, kernel=False).leaves)
    ordered, order = optimise_vertex_order(model)
    assert ordered.deformer().identity_order
    perm = np.random.default_rng(seed).permutation(model.n_vertices)
    scattered = model.reordered(perm)
    monkeypatch.setattr(Deformer, "MAX_RUNS", 0)
    assert all(isinstance(leaf[1], np.ndarray) for leaf in Deformer(scattered, kernel=False).leaves)
    rng = np.random.default_rng(900 + seed)
    for _ in range(3):
        values = random_values(rng, model)
        runs = model.deform(values)
        np.testing.assert_allclose(runs, deform_reference(model, values), rtol=0, atol=TOL)
        np.testing.assert_allclose(scattered.deform(values), runs[perm], rtol=0, atol=1e-12)
        np.testing.assert_allclose(ordered.deform(values), runs[order], rtol=0, atol=1e-12)


def test_deformer_refuses_wrong_number_of_values_and_unknown_names():
    model = rig(0, 10, 3, 2, True, False)
    with pytest.raises(ValueError, match="expected 3 values in tree order"):
        model.deformer().deform(np.zeros(len(model.parameters) + 1))
    with pytest.raises(ParameterError, match="unknown parameter"):
        model.deform({"no_such_parameter": 1.0})


# ---------------------------------------------------------------------------
# The deformer cache follows the model's edits
# ---------------------------------------------------------------------------

def _check(model: Model, rng) -> None:
    values = random_values(rng, model)
    np.testing.assert_allclose(model.deform(values), deform_reference(model, values), rtol=0, atol=TOL)


def test_deformer_is_cached_until_the_model_changes():
    model = rig(1, 30, 5, 3, True, False)
    first = model.deformer()
    model.deform(random_values(np.random.default_rng(0), model))
    assert model.deformer() is first
    model.changed()
    assert model.deformer() is not first


def test_deformer_cache_invalidates_after_add_parameter():
    """Adding a child to a leaf turns the leaf into a group-1 parameter (§2.2: the group is a
    consequence of the tree), so its weights must now be normalised and carry the child."""
    rng = np.random.default_rng(11)
    model = rig(1, 30, 5, 3, True, False, kinds=("rotation", "translation"))
    model.deform(random_values(rng, model))
    old = model.deformer()
    leaf = leaf_names(model)[0]
    model.add_parameter(Parameter("new_child", "rotation", parent=leaf, axis=(0, 1, 0), degrees_per_unit=30),
                        InfluenceRegion(np.arange(0, 30, 3), np.full(10, 1.0)))
    assert model.parameters.group(leaf) == 1
    assert model.deformer() is not old
    _check(model, rng)
    values = random_values(rng, model, zero_fraction=0.0)
    assert not np.allclose(model.deform({**values, "new_child": 0.0}), model.deform(values))


def test_deformer_cache_invalidates_after_set_region_and_remove_parameter():
    rng = np.random.default_rng(12)
    model = rig(2, 30, 6, 3, True, False)
    _check(model, rng)
    name = group1_names(model)[0]
    model.set_region(name, InfluenceRegion(np.arange(10), np.linspace(0.1, 1.0, 10)))
    _check(model, rng)
    leaf = leaf_names(model)[-1]
    add_weight(model, leaf, np.setdiff1d(np.arange(30), model.regions[leaf].indices)[:5], 0.5)
    _check(model, rng)
    model.remove_parameter(name)
    _check(model, rng)


def test_deformer_cache_invalidates_after_changed():
    """In-place edits (rest mesh, weights, a parameter's pivot) take effect after ``changed()``."""
    rng = np.random.default_rng(13)
    model = rig(3, 30, 6, 3, True, False)
    values = random_values(rng, model, zero_fraction=0.0)
    model.deform(values)
    model.vertices[:] += np.array([1.0, -2.0, 3.0])
    model.regions[leaf_names(model)[0]].weights[:] *= 0.5
    rotation = next(p for p in model.parameters if p.kind == "rotation")
    rotation.pivot = rotation.pivot + 5.0
    model.changed()
    np.testing.assert_allclose(model.deform(values), deform_reference(model, values), rtol=0, atol=TOL)


# ---------------------------------------------------------------------------
# The shipped default head (skipped until engine/data/default-head/head.xml exists)
# ---------------------------------------------------------------------------

@pytest.fixture
def default_head(head_copy, deform_path):
    """The default head (a copy, so the test's deformation path builds its deformer afresh)."""
    return head_copy


def _head_values(head: Model, rng, names=None, fraction: float = 0.8) -> dict[str, float]:
    """Random values within each parameter's range, for ``names`` (all by default)."""
    names = head.parameters.names if names is None else names
    return {n: fraction * float(rng.uniform(head.parameters[n].minimum, head.parameters[n].maximum))
            for n in names}


def _rigid_check(head: Model, vertices: np.ndarray, values: dict[str, float], what: str) -> np.ndarray:
    moved = head.deform(values)[vertices]
    before = pairwise_distances(head.vertices[vertices])
    np.testing.assert_allclose(pairwise_distances(moved), before, rtol=0, atol=1e-9, err_msg=what)
    return moved


def test_head_invariant1_all_values_zero_give_rest_mesh(default_head):
    """Invariant 1 (§2.2) on the default head."""
    assert np.array_equal(default_head.deform(zero_values(default_head)), default_head.vertices)


def test_head_invariant2_leaf_at_zero_contributes_nothing(default_head):
    """Invariant 2 (§2.2) on the default head: each leaf at 0, with its ancestors and every
    other parameter at random values, gives exactly the pose of the head without that leaf."""
    rng = np.random.default_rng(21)
    for leaf in leaf_names(default_head):
        values = _head_values(default_head, rng)
        values[leaf] = 0.0
        emptied = with_region(default_head, leaf, InfluenceRegion())
        assert np.array_equal(default_head.deform(values), emptied.deform(values)), leaf


def test_head_invariant3_leaf_motion_is_carried_by_the_parent(default_head):
    """Invariant 3 (§2.2) on the default head: wherever a vertex has group-1 weight only on
    ``p`` and leaf weight exactly 1 on a child ``c`` of ``p`` (and no other leaf), it ends at
    ``P · T_c · T'_p`` — e.g. the eyes under eye_left_turn / eye_left_raise."""
    tree = default_head.parameters
    n = default_head.n_vertices
    g1 = group1_names(default_head)
    leaves = leaf_names(default_head)
    g1_dense = np.array([default_head.regions[name].dense(n) for name in g1])
    leaf_dense = np.array([default_head.regions[name].dense(n) for name in leaves])
    rng = np.random.default_rng(22)
    checked = 0
    for j, c in enumerate(leaves):
        p = tree[c].parent
        if p is None or tree[c].field:
            continue
        only_p = (g1_dense[g1.index(p)] > 0) & ((g1_dense > 0).sum(0) == 1)
        only_c = (leaf_dense[j] == 1.0) & ((leaf_dense > 0).sum(0) == 1)
        vertices = np.flatnonzero(only_p & only_c)
        if not len(vertices):
            continue
        for _ in range(3):
            values = _head_values(default_head, rng)
            expected = apply(propagated_transform(default_head, p, values),
                             apply(own_transform(tree[c], values[c]), default_head.vertices[vertices]))
            np.testing.assert_allclose(default_head.deform(values)[vertices], expected, rtol=0, atol=1e-9, err_msg=c)
        checked += 1
    if not checked:
        pytest.skip("no vertex of the default head has weight 1 on a leaf and only its parent in group 1")


def test_head_invariant5_lower_teeth_ride_rigidly_on_the_jaw(default_head):
    """Invariant 5 (§2.2) on the default head: the lower teeth (part ``teeth_lower``) keep
    their shape under jaw_open, alone and together with the head's other motions, and the jaw
    really carries them."""
    rng = np.random.default_rng(23)
    teeth = default_head.part_vertices("teeth_lower")
    assert len(teeth) > 3
    jaw = default_head.parameters["jaw_open"]
    moved = _rigid_check(default_head, teeth, {"jaw_open": jaw.maximum}, "jaw_open alone")
    assert np.abs(moved - default_head.vertices[teeth]).max() > 1.0, "jaw_open moves the lower teeth"
    for _ in range(3):
        values = _head_values(default_head, rng, names=group1_names(default_head))
        values["jaw_open"] = float(rng.uniform(jaw.minimum, jaw.maximum))
        _rigid_check(default_head, teeth, values, "jaw_open with the head's motion")


def test_head_invariant5_left_eye_turns_rigidly_about_its_centre(default_head):
    """Invariant 5 (§2.2) on the default head: the left eyeball (part ``eye_left``) keeps its
    shape under eye_left_turn and eye_left_raise, alone, together and with the head's motion;
    both rotations pivot on the eyeball's centre (the middle of its bounding box, which a
    cornea bulge may shift a little), so turning the eye leaves the eyeball where it was."""
    rng = np.random.default_rng(24)
    eye = default_head.part_vertices("eye_left")
    rest = default_head.vertices[eye]
    centre = 0.5 * (rest.min(0) + rest.max(0))
    radius = 0.5 * (rest.max(0) - rest.min(0))[:2].mean()
    turn, raise_ = default_head.parameters["eye_left_turn"], default_head.parameters["eye_left_raise"]
    for p in (turn, raise_):
        assert p.kind == "rotation"
        assert np.linalg.norm(p.pivot - centre) < 0.1 * radius, f"{p.name} pivots on the eye's centre"
    for values in ({"eye_left_turn": turn.maximum}, {"eye_left_raise": raise_.minimum},
                   {"eye_left_turn": turn.minimum, "eye_left_raise": raise_.maximum}):
        moved = _rigid_check(default_head, eye, values, str(values))
        assert np.abs(moved - rest).max() > 1.0, f"{values} turns the eye"
        moved_centre = 0.5 * (moved.min(0) + moved.max(0))
        assert np.linalg.norm(moved_centre - centre) < 0.2 * radius, "the eye turns in place"
    for _ in range(3):
        values = _head_values(default_head, rng, names=group1_names(default_head))
        values.update(_head_values(default_head, rng, names=["eye_left_turn", "eye_left_raise"], fraction=1.0))
        _rigid_check(default_head, eye, values, "eye with the head's motion")
