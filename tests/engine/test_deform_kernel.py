"""The compiled deformation kernel (``engine/deform/_kernel.c``) and its numpy fallback.

``test_invariants.py`` runs every invariant through both paths; this file
checks what is specific to the kernel: that it is built from the current
source, that it agrees with the numpy path and the literal reference also on
segments longer than its inner loops (``CHUNK`` = 128 vertices), with the
vertex order it writes in, that it refuses malformed plans instead of reading
wild memory, and that it can run in several threads at once.
"""

from __future__ import annotations

import hashlib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine.deform.deformer
from engine.deform.deformer import Deformer, deform_reference, optimise_vertex_order
from engine.model.model import InfluenceRegion, Model
from engine.paths import default_model_path
from tests.engine.synthetic import leaf_names, random_model, random_values

SOURCE = Path(engine.deform.deformer.__file__).with_name("_kernel.c")

needs_kernel = pytest.mark.skipif(engine.deform.deformer.compiled is None,
                                  reason="the compiled deformation kernel is not built")


def test_kernel_is_built_and_current():
    """``pip install -e .`` (``./bootstrap`` runs it) compiles the kernel; a C compiler and the
    Python headers come from bootstrap's Debian package list. A build from an older source
    (the C file edited since) must be rebuilt, or the tests would check stale code."""
    assert engine.deform.deformer.compiled is not None, (
        "engine.deform._kernel is not built or its ABI does not match: run .venv/bin/pip install -e . "
        "(needs build-essential and python3-dev)")
    if SOURCE.exists():
        digest = hashlib.sha256(SOURCE.read_bytes()).hexdigest()
        assert digest == engine.deform.deformer.compiled.SOURCE_SHA256, (
            "engine.deform._kernel was built from an older _kernel.c: run .venv/bin/pip install -e .")


def test_model_deform_uses_the_kernel_when_built():
    model = random_model(0, 30, 5, 3)
    assert model.deformer().kernel is (engine.deform.deformer.compiled is not None)
    assert Deformer(model, kernel=False).kernel is False


def test_kernel_required_but_missing_is_an_error(monkeypatch):
    monkeypatch.setattr(engine.deform.deformer, "compiled", None)
    model = random_model(0, 10, 3, 2)
    with pytest.raises(RuntimeError, match="not built"):
        Deformer(model, kernel=True)
    assert not Deformer(model).kernel


def _both(model: Model, values: dict[str, float]):
    v = model.values_array(values)
    return Deformer(model, kernel=True).deform(v), Deformer(model, kernel=False).deform(v)


@needs_kernel
@settings(max_examples=60, derandomize=True, deadline=None, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), n_vertices=st.sampled_from([1, 7, 127, 128, 129, 300, 700]),
       n_parameters=st.integers(1, 9), depth=st.integers(1, 5), partial=st.booleans(),
       contiguous=st.booleans(), zero_fraction=st.sampled_from([0.0, 0.3, 1.0]))
def test_kernel_equals_numpy_path(seed, n_vertices, n_parameters, depth, partial, contiguous, zero_fraction):
    """Kernel and numpy path agree to 1e-12 mm on random rigs, including segments longer than
    the kernel's inner loop and rigs whose vertex order needs the final reordering."""
    rng = np.random.default_rng(seed)
    model = random_model(rng, n_vertices, n_parameters, depth, partial=partial, contiguous=contiguous,
                         landmarks=False)
    values = random_values(rng, model, zero_fraction=zero_fraction)
    fast, slow = _both(model, values)
    np.testing.assert_allclose(fast, slow, rtol=0, atol=1e-12)


@needs_kernel
@pytest.mark.parametrize("seed", range(4))
def test_kernel_equals_reference_on_long_segments(seed):
    """The literal reference on a rig with runs of hundreds of vertices moving alike (several
    inner-loop chunks per segment, with tails), in the built order and in the optimised one."""
    rng = np.random.default_rng(seed)
    model = random_model(rng, 600, 6, 3, partial=True, contiguous=True, landmarks=False)
    values = random_values(rng, model, zero_fraction=0.2)
    expected = deform_reference(model, values)
    d = Deformer(model, kernel=True)
    assert d.kernel and d._plan.n_segments < model.n_vertices / 10, "long segments"
    np.testing.assert_allclose(d.deform(model.values_array(values)), expected, rtol=0, atol=1e-9)
    ordered, order = optimise_vertex_order(model)
    assert Deformer(ordered, kernel=True).identity_order
    np.testing.assert_allclose(ordered.deform(values), expected[order], rtol=0, atol=1e-9)


@needs_kernel
@pytest.mark.parametrize("seed", range(3))
def test_kernel_leaf_at_zero_is_bit_exact_on_long_segments(seed):
    """Invariant 2 bit for bit where emptying a leaf's region moves vertices between segments
    and so between a vectorised loop body and its scalar tail."""
    rng = np.random.default_rng(40 + seed)
    model = random_model(rng, 500, 7, 3, partial=True, contiguous=bool(seed % 2), landmarks=False)
    for leaf in leaf_names(model):
        values = random_values(rng, model, zero_fraction=0.0)
        values[leaf] = 0.0
        regions = dict(model.regions)
        regions[leaf] = InfluenceRegion()
        emptied = Model(model.vertices, model.faces, model.parts, model.vertex_part, model.parameters, regions)
        assert np.array_equal(model.deform(values), emptied.deform(values)), leaf
    assert np.array_equal(model.deform({}), model.vertices)


@needs_kernel
def test_kernel_equals_numpy_path_on_the_default_head():
    path = default_model_path()
    if not path.exists():
        pytest.skip("the default head is not built yet")
    from engine import load_model

    head = load_model(path)
    rng = np.random.default_rng(5)
    for _ in range(5):
        values = {p.name: float(rng.uniform(p.minimum, p.maximum)) for p in head.parameters}
        fast, slow = _both(head, values)
        np.testing.assert_allclose(fast, slow, rtol=0, atol=1e-12)


@needs_kernel
@pytest.mark.parametrize("n_vertices,n_parameters", [(0, 3), (5, 0), (0, 0)])
def test_kernel_handles_empty_models(n_vertices, n_parameters):
    model = random_model(1, max(n_vertices, 1), max(n_parameters, 1), 2)
    if n_vertices == 0:
        model = Model(np.zeros((0, 3)), [], parameters=model.parameters if n_parameters else None)
    elif n_parameters == 0:
        model = Model(model.vertices, [])
    d = Deformer(model, kernel=True)
    out = d.deform(np.ones(len(model.parameters)))
    assert out.shape == (model.n_vertices, 3)
    assert np.array_equal(out, model.vertices)


@needs_kernel
def test_kernel_runs_in_threads():
    """The pass releases the GIL; its scratch is per call, so threads sharing one deformer
    get the same results as one after the other."""
    model = random_model(3, 400, 8, 3, landmarks=False)
    d = model.deformer()
    rng = np.random.default_rng(3)
    frames = [model.values_array(random_values(rng, model)) for _ in range(16)]
    expected = [d.deform(v) for v in frames]
    with ThreadPoolExecutor(4) as pool:
        for _ in range(5):
            got = list(pool.map(d.deform, frames))
            assert all(np.array_equal(a, b) for a, b in zip(got, expected, strict=True))


@needs_kernel
def test_plan_refuses_malformed_structure():
    """A Plan checks every index it will follow, so bad input raises instead of crashing."""
    Plan = engine.deform.deformer.compiled.Plan
    i64 = np.int64

    def plan(**change):
        args = dict(kind=np.zeros(1, i64), parent=np.full(1, -1, i64), topo=np.zeros(1, i64),
                    axis=np.array([[1.0, 0, 0]]), pivot=np.zeros((1, 3)), scale=np.ones(1),
                    direction=np.zeros((1, 3)), rest=np.zeros((3, 4)), order=np.zeros(0, i64),
                    segments=np.array([[0, 4, 0, 0, 0, 0, 1]], i64), entries=np.array([[0, 0]], i64),
                    data=np.ones(4))
        args.update(change)
        return Plan(**args)

    good = plan()
    out = np.empty((4, 3))
    good.deform(np.array([0.5]), out)
    assert np.array_equal(out, np.zeros((4, 3)))
    bad = [
        (dict(segments=np.array([[0, 3, 0, 0, 0, 0, 1]], i64)), "segments: must cover"),  # does not cover the vertices
        (dict(segments=np.array([[0, 4, 5, 0, 0, 0, 1]], i64)), "segments: bad carry"),   # carry parameter out of range
        (dict(segments=np.array([[0, 4, 0, 0, 0, 0, 2]], i64)), "segments: bad entry"),   # entries beyond the table
        (dict(entries=np.array([[3, 0]], i64)), "entries: parameter index"),              # parameter out of range
        (dict(entries=np.array([[0, 1]], i64)), "entries: data offset"),                  # weights beyond data
        (dict(order=np.array([0, 1, 2, 4], i64)), "order: vertex index"),                 # output row out of range
        (dict(parent=np.array([0], i64)), "parameters: bad kind, parent"),                # its own parent
        (dict(kind=np.array([7], i64)), "parameters: bad kind, parent"),                  # unknown kind
        (dict(rest=np.zeros(13)), "rest must be 3 × N"),                                  # not 3 × N
    ]
    for change, message in bad:
        with pytest.raises(ValueError, match=message):
            plan(**change)
    with pytest.raises(TypeError):
        plan(kind=np.zeros(1, np.int32))
    with pytest.raises(ValueError, match="values: expected 1 float64"):
        good.deform(np.zeros(2), out)
    with pytest.raises(ValueError, match="out: expected 4 × 3 float64"):
        good.deform(np.zeros(1), np.empty((3, 3)))
    with pytest.raises((TypeError, ValueError, BufferError)):
        good.deform(np.zeros(1), np.empty((4, 3))[:, :2])


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 300), st.integers(1, 140), st.floats(0.0, 1.0), st.integers(0, 2 ** 32 - 1))
def test_pattern_ranks_number_rows_as_numpy_unique_does(n_rows, n_columns, density, seed):
    """The deformer groups vertices by the leaves acting on them with ``pattern_ranks``: the same
    numbering as ``np.unique(..., axis=0)`` over the packed rows, across 64-bit word boundaries."""
    rows = np.random.default_rng(seed).random((n_rows, n_columns)) < density
    expected = (np.unique(np.packbits(rows, axis=1), axis=0, return_inverse=True)[1].ravel()
                if n_rows else np.zeros(0, dtype=np.int64))
    assert np.array_equal(engine.deform.deformer.pattern_ranks(rows), expected)
