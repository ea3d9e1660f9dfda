"""The shipped table of identity effects at the landmark vertices (engine/data/photofit/identity-sides.h5)."""

from __future__ import annotations

import h5py
import numpy as np
import pytest

from engine.errors import UserError
from engine.photofit import side_table
from engine.photofit.face_points import point_vertices
from engine.photofit.identity_fit import FITTED_PARAMETERS, MACROS, MODIFIERS, IdentityBasis
from engine.photofit.side_table import derive_table, read_table, shipped_sides, table_path, write_table


def test_the_shipped_table_is_what_the_derivation_computes_now(head):
    shipped = read_table(table_path())
    derived = derive_table(head, sorted(set(point_vertices(head).values())), MODIFIERS, MACROS)
    assert shipped.fingerprint == derived.fingerprint
    assert shipped.modifiers == derived.modifiers and shipped.macros == derived.macros
    assert np.array_equal(shipped.vertices, derived.vertices)
    np.testing.assert_allclose(shipped.sides, derived.sides, rtol=0, atol=1e-9)
    np.testing.assert_allclose(shipped.macro_effects, derived.macro_effects, rtol=0, atol=1e-9)
    assert np.abs(shipped.sides).max() > 1.0          # mm per unit: the targets do move the landmarks


def test_the_fit_takes_its_effects_from_the_table_on_the_default_head(head, monkeypatch):
    def never(*args, **kwargs):
        raise AssertionError("sampled although the table has it")

    monkeypatch.setattr("engine.photofit.identity_fit.side_effect", never)
    monkeypatch.setattr("engine.photofit.identity_fit.first_macro_effect", never)
    basis = IdentityBasis(head, sorted(point_vertices(head)))
    assert basis.table is not None and basis.rows is not None
    k = FITTED_PARAMETERS.index("nose-scale-horiz-decr-incr")
    table = read_table(table_path())
    rows = table.rows(basis.index)
    assert rows is not None
    np.testing.assert_array_equal(basis.side(k, -1), table.sides[MODIFIERS.index(FITTED_PARAMETERS[k]), 1][rows])


def test_another_head_samples_its_own_effects(head):
    moved = head.copy()
    moved.vertices = moved.vertices + np.array([0.0, 1.0, 0.0])
    assert shipped_sides(head, MODIFIERS, MACROS) is not None
    assert shipped_sides(moved, MODIFIERS, MACROS) is None
    assert shipped_sides(head, (*MODIFIERS, "not-a-parameter"), MACROS) is None


def test_a_table_of_another_version_or_with_bad_numbers_is_refused(head, tmp_path):
    table = read_table(table_path())
    path = tmp_path / "sides.h5"
    write_table(table, path)
    assert read_table(path).fingerprint == table.fingerprint
    with h5py.File(path, "a") as f:
        f.attrs["version"] = side_table.VERSION + 1
    with pytest.raises(UserError, match="version"):
        read_table(path)
    bad = side_table.SideTable(table.vertices, table.modifiers, table.macros, table.sides * np.nan,
                               table.macro_effects, table.fingerprint)
    write_table(bad, path)
    with pytest.raises(UserError, match="not finite"):
        read_table(path)
    shuffled = side_table.SideTable(table.vertices[::-1], table.modifiers, table.macros, table.sides,
                                    table.macro_effects, table.fingerprint)
    write_table(shuffled, path)
    with pytest.raises(UserError, match="do not fit together"):
        read_table(path)
