"""The compiled motion-capture kernels and their numpy fallbacks (the speed of the §3.1.1 import).

``engine/mocap/_text_table.c`` reads the number table of a marker export in one pass;
``engine/mocap/_rigid_fit.c`` computes every frame's Kabsch rotation. Both must
give what the plain Python/numpy paths give: the same doubles as ``float``
for every cell, and the same rotations as the SVD to rounding.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import engine
from engine.deform.transforms import apply, rotation_about_axis, translation
from engine.mocap import head_motion, text_tables

KERNELS = Path(engine.__file__).parent / "mocap"
text_table = text_tables._text_table
rigid_fit = head_motion._rigid_fit
needs_parser = pytest.mark.skipif(text_table is None, reason="engine.mocap._text_table is not built")
needs_rigid = pytest.mark.skipif(rigid_fit is None, reason="engine.mocap._rigid_fit is not built")


@pytest.mark.parametrize("module, source", [("_text_table", "_text_table.c"), ("_rigid_fit", "_rigid_fit.c")])
def test_kernels_are_built_and_current(module, source):
    """``pip install -e .`` (``./bootstrap``) compiles both; a stale build would test old code."""
    compiled = {"_text_table": text_table, "_rigid_fit": rigid_fit}[module]
    assert compiled is not None, f"engine.mocap.{module} is not built: run .venv/bin/pip install -e . " \
                                 "(needs build-essential and python3-dev)"
    digest = hashlib.sha256((KERNELS / source).read_bytes()).hexdigest()
    assert digest == compiled.SOURCE_SHA256, f"engine.mocap.{module} was built from an older {source}: " \
                                             "run .venv/bin/pip install -e ."


# -- the table reader ----------------------------------------------------------------

def _parse(text: str, n_columns: int, delimiter="\t", empty_is_missing=False, capacity=None):
    rows = capacity if capacity is not None else text.count("\n") + 1
    out = np.full((rows, n_columns), -7.0)
    n = text_table.parse_table(text.encode(), out, n_columns, ord(delimiter) if delimiter else -1,
                               empty_is_missing)
    return n, out[:max(n, 0)]


decimal_cells = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False, width=64).map(repr),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e4, max_value=1e4).map(lambda x: f"{x:.3f}"),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e4, max_value=1e4).map(lambda x: f"{x:.17g}"),
    st.integers(-10**20, 10**20).map(str),
    st.decimals(allow_nan=False, allow_infinity=False, places=20).map(str),
    st.sampled_from(["0", "-0", "-0.000", ".5", "5.", "+1.25", "1e-5", "2E+3", "nan", "-inf", "Infinity",
                     "0.000000000000000000001", "123456789012345678", "9007199254740993", "0.1", "-0.3"]),
)


@needs_parser
@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(decimal_cells, min_size=3, max_size=3), min_size=1, max_size=8))
def test_every_cell_gets_the_double_float_gives(rows):
    text = "\n".join("\t".join(r) for r in rows) + "\n"
    n, out = _parse(text, 3)
    assert n == len(rows)
    expected = np.array([[float(c) for c in r] for r in rows])
    assert np.array_equal(out, expected, equal_nan=True)
    numbers = ~np.isnan(expected)
    assert np.array_equal(np.signbit(out[numbers]), np.signbit(expected[numbers]))     # -0.0 stays -0.0


@needs_parser
def test_blank_rows_carriage_returns_spaces_and_missing_cells():
    n, out = _parse("1\t2\r\n\n  \t \n 3 \t-4.5\n", 2)
    assert n == 2 and out.tolist() == [[1, 2], [3, -4.5]]
    n, out = _parse("1,,3\n,5,\n", 3, ",", empty_is_missing=True)
    assert n == 2 and np.array_equal(out, [[1, np.nan, 3], [np.nan, 5, np.nan]], equal_nan=True)
    n, out = _parse("1   2\t3\n  4 5 6  \n", 3, None)
    assert n == 2 and out.tolist() == [[1, 2, 3], [4, 5, 6]]


@needs_parser
@pytest.mark.parametrize("text, bad_row", [
    ("1\t2\n3\tx\n", 1),            # not a number
    ("1\t2\n3\n", 1),               # too few cells
    ("1\t2\t3\n", 0),               # too many
    ("1\t\n", 0),                   # empty cell where it is not allowed
    ("1\t2\n\n5\t1_0\n", 2),        # Python's float takes 1_0; in a marker file it is a mistake
    ("1e\t2\n", 0),
])
def test_an_irregular_row_is_reported_by_its_index(text, bad_row):
    n, _ = _parse(text, 2)
    assert n == -1 - bad_row


@needs_parser
def test_more_rows_than_room_is_irregular():
    n, _ = _parse("1\n2\n3\n", 1, capacity=2)
    assert n == -1 - 2


@needs_parser
def test_readers_fall_back_to_numpy_with_the_same_result(monkeypatch):
    rng = np.random.default_rng(5)
    table = np.round(rng.normal(0, 300, (200, 12)), 3)
    lines = ["\t".join(f"{x:.3f}" for x in row) for row in table]
    fast = text_tables.parse_rows(lines, 1, 12, Path("x.tsv"))
    monkeypatch.setattr(text_tables, "_text_table", None)
    slow = text_tables.parse_rows(lines, 1, 12, Path("x.tsv"))
    assert np.array_equal(fast, slow) and np.array_equal(fast, table)


@pytest.mark.parametrize("cell", ["abc", "1_0"])
def test_a_bad_cell_still_names_its_line(cell):
    lines = ["1\t2", "3\t4", f"5\t{cell}"]
    with pytest.raises(engine.UserError, match=rf"x\.tsv:12.*'{cell}' is not a number"):
        text_tables.parse_rows(lines, 10, 2, Path("x.tsv"))


# -- Kabsch rotations ------------------------------------------------------------------

def _frames(n, k, seed, noise=0.3):
    rng = np.random.default_rng(seed)
    ref = rng.normal(0, 50, (k, 3)) + np.array([0, 0, 800])
    points = np.empty((n, k, 3))
    truth = []
    for f in range(n):
        T = rotation_about_axis(rng.normal(size=3), rng.normal(0, 100, 3), rng.uniform(-40, 40)) \
            @ translation(rng.normal(0, 20, 3))
        truth.append(T)
        points[f] = apply(T, ref) + rng.normal(0, noise, (k, 3))
    return ref, points, truth


@needs_rigid
@pytest.mark.parametrize("k", [3, 4, 6])
def test_compiled_kabsch_equals_the_svd(monkeypatch, k):
    ref, points, _ = _frames(300, k, seed=k)
    present = np.ones((300, k), bool)
    present[::5, 0] = k == 3          # with three markers every one is needed
    compiled = head_motion.kabsch(points, ref, present)
    monkeypatch.setattr(head_motion, "_rigid_fit", None)
    numpy_svd = head_motion.kabsch(points, ref, present)
    assert np.allclose(compiled, numpy_svd, atol=1e-9, equal_nan=True)
    R = compiled[:, :3, :3]
    assert np.allclose(np.linalg.det(R), 1.0) and np.allclose(R @ R.transpose(0, 2, 1), np.eye(3), atol=1e-12)


@needs_rigid
def test_compiled_kabsch_is_exact_without_noise_and_rejects_lines_and_reflections():
    ref, points, truth = _frames(50, 5, seed=9, noise=0.0)
    A = head_motion.kabsch(points, ref, np.ones((50, 5), bool))
    for f in range(50):
        assert np.allclose(A[f] @ truth[f], np.eye(4), atol=1e-9)   # undoes the motion
    line = np.outer([0.0, 1.0, 2.0, 3.5], [3.0, 1.0, 2.0])
    assert np.isnan(head_motion.kabsch(line[None], line, np.ones((1, 4), bool))).all()
    mirrored = ref * [-1, 1, 1]                                     # a reflection is not a rotation
    R = head_motion.kabsch(mirrored[None], ref, np.ones((1, 5), bool))[0, :3, :3]
    assert np.isclose(np.linalg.det(R), 1.0)


@needs_rigid
def test_compiled_move_equals_numpy(monkeypatch):
    ref, points, _ = _frames(40, 6, seed=3)
    points[3, 2] = np.nan
    A = head_motion.kabsch(points, ref, np.isfinite(points).all(axis=2))
    moved = head_motion.apply_alignment(points, A)
    monkeypatch.setattr(head_motion, "_rigid_fit", None)
    assert np.allclose(moved, head_motion.apply_alignment(points, A), equal_nan=True, atol=1e-9)
    assert np.isnan(moved[3, 2]).all() and np.isfinite(moved[3, 3]).all()
    assert head_motion.apply_alignment(np.zeros((0, 6, 3)), np.zeros((0, 4, 4))).shape == (0, 6, 3)
