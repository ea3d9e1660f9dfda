"""The default head's own checks, gathered so another head can be checked by them (identities, fitted heads).

A test module that does ``from tests.engine.default_head_checks import *``
and defines its own ``head`` fixture collects every check below again, run
on its head: the tests are imported, not copied, so they cannot drift apart.
:func:`known_failures` marks the checks a head is known to fail (strictly: a
listed check that passes fails the run, so the list only shrinks).
"""

from __future__ import annotations

from collections.abc import Callable, Collection
from typing import Any

import pytest

from tests.engine.test_action_units import (
    rest,
    test_a_left_action_unit_moves_only_the_left_side,
    test_au1_raises_the_inner_brows,
    test_au2_raises_the_outer_brows,
    test_au4_lowers_the_brows_and_draws_them_together,
    test_au5_raises_the_upper_lid_and_au41_lowers_it,
    test_au6_raises_the_cheek,
    test_au7_raises_the_lower_lid,
    test_au9_raises_the_nose_wings_and_lowers_the_inner_brows,
    test_au10_raises_the_upper_lip,
    test_au12_pulls_the_lip_corners_up_and_out,
    test_au15_pulls_the_lip_corners_down,
    test_au16_lowers_the_lower_lip,
    test_au17_raises_the_chin_and_the_lower_lip,
    test_au20_stretches_the_lips_sideways,
    test_au23_and_au24_narrow_and_press_the_lips,
    test_au26_is_the_jaw_and_lowers_the_chin,
    test_the_lids_stay_off_the_eyeball,
)
from tests.engine.test_articulatory_parameters import (
    lips,
    test_closure_survives_the_neighbouring_vowels_lip_shape,
    test_closure_with_the_jaw_barely_open,
    test_lip_contours_keep_their_vertical_order_when_closed,
    test_lip_protrude_rounds_and_pushes_the_lips_forward,
    test_lower_lip_raise_closes_the_lips,
    test_mouth_widen_pulls_the_corners_apart,
    test_no_value_in_range_makes_the_lips_cross,
    test_open_vowel_jaw_opening_gives_a_clear_gap,
    test_upper_lip_raise_lifts_the_upper_lip_only,
)
from tests.engine.test_default_head import (
    test_brow_raise_lifts_both_brows,
    test_eyelid_closes_onto_the_lower_lid,
    test_faces_plus_z_with_y_up,
    test_gaze_turns_the_eyes_and_not_the_lashes,
    test_head_motion_directions_and_fixed_neck_base,
    test_jaw_opens_the_mouth_and_leaves_the_upper_lip,
    test_landmarks_are_mirror_images,
    test_lip_landmarks_in_anatomical_order,
    test_teeth_move_rigidly_with_their_bone,
)
from tests.engine.test_speech_acceptance import (
    measured,
    test_lips_close_at_the_middle_of_every_bilabial,
    test_open_vowels_open_the_mouth,
)


def known_failures(names: Collection[str], reason: str) -> Callable[..., Any]:
    """An autouse fixture marking the tests called ``names`` (with their parameters) as strict expected failures."""
    @pytest.fixture(autouse=True)
    def _known_failure(request: pytest.FixtureRequest) -> None:
        if request.node.name in names:
            request.applymarker(pytest.mark.xfail(strict=True, reason=reason))
    return _known_failure


__all__ = [
    "lips",
    "measured",
    "rest",
    "test_a_left_action_unit_moves_only_the_left_side",
    "test_au1_raises_the_inner_brows",
    "test_au2_raises_the_outer_brows",
    "test_au4_lowers_the_brows_and_draws_them_together",
    "test_au5_raises_the_upper_lid_and_au41_lowers_it",
    "test_au6_raises_the_cheek",
    "test_au7_raises_the_lower_lid",
    "test_au9_raises_the_nose_wings_and_lowers_the_inner_brows",
    "test_au10_raises_the_upper_lip",
    "test_au12_pulls_the_lip_corners_up_and_out",
    "test_au15_pulls_the_lip_corners_down",
    "test_au16_lowers_the_lower_lip",
    "test_au17_raises_the_chin_and_the_lower_lip",
    "test_au20_stretches_the_lips_sideways",
    "test_au23_and_au24_narrow_and_press_the_lips",
    "test_au26_is_the_jaw_and_lowers_the_chin",
    "test_brow_raise_lifts_both_brows",
    "test_closure_survives_the_neighbouring_vowels_lip_shape",
    "test_closure_with_the_jaw_barely_open",
    "test_eyelid_closes_onto_the_lower_lid",
    "test_faces_plus_z_with_y_up",
    "test_gaze_turns_the_eyes_and_not_the_lashes",
    "test_head_motion_directions_and_fixed_neck_base",
    "test_jaw_opens_the_mouth_and_leaves_the_upper_lip",
    "test_landmarks_are_mirror_images",
    "test_lip_contours_keep_their_vertical_order_when_closed",
    "test_lip_landmarks_in_anatomical_order",
    "test_lip_protrude_rounds_and_pushes_the_lips_forward",
    "test_lips_close_at_the_middle_of_every_bilabial",
    "test_lower_lip_raise_closes_the_lips",
    "test_mouth_widen_pulls_the_corners_apart",
    "test_no_value_in_range_makes_the_lips_cross",
    "test_open_vowel_jaw_opening_gives_a_clear_gap",
    "test_open_vowels_open_the_mouth",
    "test_teeth_move_rigidly_with_their_bone",
    "test_the_lids_stay_off_the_eyeball",
    "test_upper_lip_raise_lifts_the_upper_lip_only",
]
