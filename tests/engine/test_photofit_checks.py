"""A head fitted to photographs animates as the default head does (issue 19): the default head's checks, re-run.

The same checks ``test_identity_checks.py`` re-runs on made identities
(imported from their modules, so they cannot drift apart), here with
``head`` the head fitted to the synthetic front and side photographs of
``test_photofit.py``: a fitted identity plus the residual warp, the rig
carried over both, its articulation and eyelids refitted after the warp.
71 of 72 pass; :data:`KNOWN_FAILURES` lists the 1 that fails today (strict:
the list only shrinks).
"""

from __future__ import annotations

import pytest

from engine.photofit import fit_photos
from tests.engine.default_head_checks import *  # noqa: F403  (the default head's checks, collected again here)
from tests.engine.default_head_checks import known_failures
from tests.engine.test_photofit import synthetic  # noqa: F401


@pytest.fixture(scope="module")
def head(synthetic):  # noqa: F811
    _, photos, points, _ = synthetic
    return fit_photos(photos, points).head


KNOWN_FAILURES = frozenset({
    # the photographed face is not symmetric (the landmarks' placement noise and the warp), and a real
    # person's need not be: the default head's symmetry does not apply to a fitted head
    "test_landmarks_are_mirror_images",
})


_known_failure = known_failures(KNOWN_FAILURES, "known gap of the fitted head's rig (issue 19)")
