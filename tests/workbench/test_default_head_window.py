"""The workbench on the shipped default head (skipped until engine/data/default-head/head.xml exists)."""

from __future__ import annotations

import numpy as np
import pytest

import engine

DEFAULT_HEAD = engine.default_model_path()
pytestmark = pytest.mark.skipif(not DEFAULT_HEAD.exists(), reason=f"default head not built yet ({DEFAULT_HEAD})")

EXPECTED_PARAMETERS = {"neck_lean", "head_turn", "head_nod", "head_tilt", "jaw_open", "tongue_raise",
                       "eye_left_turn", "eye_left_raise", "eye_right_turn", "eye_right_raise",
                       "eyelid_left_close", "eyelid_right_close", "brow_raise"}
EXPECTED_PARTS = {"skin", "eye_left", "eye_right", "eyelashes_left", "eyelashes_right",
                  "teeth_upper", "teeth_lower", "tongue"}


def test_default_head_opens_and_its_jaw_moves(make_window):
    window = make_window(DEFAULT_HEAD)
    model = window.document.model
    assert set(window.parameter_panel.rows) >= EXPECTED_PARAMETERS
    assert set(window.viewport.part_names) >= EXPECTED_PARTS
    assert set(window.parts_menu.part_actions) == set(model.parts)
    shown = np.isfinite(window.viewport.displayed_points()).all(axis=1)
    assert shown.mean() > 0.99                       # every vertex that belongs to a polygon is drawn

    row = window.parameter_panel.row("jaw_open")
    row.slider.setValue(row.position_of(row.parameter.maximum * 0.6))
    expected = model.deform({"jaw_open": window.document.value("jaw_open")})
    assert not np.array_equal(expected, model.vertices)
    np.testing.assert_array_equal(window.viewport.displayed_points()[shown], expected[shown])

    window.actions_by_id["pose.reset_all"].trigger()
    np.testing.assert_array_equal(window.viewport.displayed_points()[shown], model.vertices[shown])
