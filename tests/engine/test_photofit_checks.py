"""A head fitted to photographs animates as the default head does (issue 19): the default head's checks, re-run.

The same checks ``test_identity_checks.py`` re-runs on made identities
(imported from their modules, so they cannot drift apart), here with
``head`` the head fitted to the synthetic front and side photographs of
``test_photofit.py``: a fitted identity plus the residual warp, the rig
carried over both, its articulation and eyelids refitted after the warp.
All 72 pass. One is the fitted head's own: the default head's landmarks are
mirror images to 0.5 mm, but a photographed face need not be symmetric, and
this one's are placed with 2 px of noise; here the truth is symmetric, so the
fitted pairs must be mirror images to within the fit's error (2 mm).
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.photofit import fit_photos
from tests.engine.default_head_checks import *  # noqa: F403  (the default head's checks, collected again here)
from tests.engine.default_head_checks import known_failures
from tests.engine.test_photofit import synthetic  # noqa: F401


@pytest.fixture(scope="module")
def head(synthetic):  # noqa: F811
    _, photos, points, _ = synthetic
    return fit_photos(photos, points).head


KNOWN_FAILURES: frozenset[str] = frozenset()


def test_landmarks_are_mirror_images(head):
    """The symmetric synthetic face comes back symmetric to within the fit's error (it replaces the default
    head's check of the same name, which asks 0.5 mm of a face built symmetric)."""
    lm = head.landmark_positions()
    for left, right in [("8.3", "8.4"), ("8.5", "8.6"), ("8.7", "8.8"), ("3.5", "3.6"), ("4.1", "4.2"),
                        ("4.3", "4.4"), ("4.5", "4.6"), ("9.1", "9.2")]:
        assert np.linalg.norm(lm[left] * [-1, 1, 1] - lm[right]) < 2.0, f"{left}/{right}"
    for mid in ("2.1", "2.2", "2.3", "8.1", "8.2", "9.3", "9.15"):
        assert abs(lm[mid][0]) < 0.5, f"{mid} lies on the midline"


_known_failure = known_failures(KNOWN_FAILURES, "known gap of the fitted head's rig (issue 19)")
