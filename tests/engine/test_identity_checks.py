"""Every identity animates as the default head does (issue 18 §2): the default head's geometric checks, re-run.

The tests below are the default head's own (imported from their modules, so
they cannot drift apart), collected here a second time with ``head`` a made
identity: three contrasting people — a young woman of Asian ancestry, an
older heavier man of European ancestry, and a middle-aged woman of African
ancestry with a wider mouth and nose. Lips must close at p/b/m without
passing through each other and open at a; each action unit moves its
landmarks as FACS describes; the eyelids close onto the lower lids; the
teeth ride rigidly on their bone; speech by real Festival closes the lips at
every bilabial.

All 216 pass. :data:`KNOWN_FAILURES` lists, per identity, the checks
that fail (strict: a listed check that starts to pass fails the run, so the
list only shrinks); it is empty. The last to leave it was AU9 on the
smallest face: the check asks the nose wings to rise > 1 mm, an absolute
figure, and the carried-over sneer shrinks with that face's shorter, flatter
nose (its local map at the wing scales heights by 0.68), so the artist's weak
sneer (1.3 mm on the default head) gave 0.84 mm there. The default head's
AU9 nose part is now 1.7 times the artist's sneer, as FACS describes AU9 at
full intensity (docs/default-head.md, "Action units"): 2.2–2.4 mm on the
default head, 1.4–2.0 mm on that face.
"""

from __future__ import annotations

import pytest

from engine.identity import Identity, make_identity_head
from tests.engine.default_head_checks import *  # noqa: F403  (the default head's checks, collected again here)
from tests.engine.default_head_checks import known_failures

IDENTITIES = {
    "young-woman-asian": {"sex": 0.0, "age": 28, "asian": 1.0, "african": 0.0, "caucasian": 0.0},
    "older-man-european": {"sex": 1.0, "age": 60, "caucasian": 1.0, "african": 0.0, "asian": 0.0,
                           "weight": 0.7},
    "woman-african-wide-mouth": {"sex": 0.1, "age": 45, "african": 1.0, "asian": 0.0, "caucasian": 0.0,
                                 "mouth-scale-horiz-decr-incr": 0.4, "nose-scale-horiz-decr-incr": 0.4},
}


@pytest.fixture(scope="module", params=list(IDENTITIES))
def head(request):
    return make_identity_head(Identity(IDENTITIES[request.param]))


KNOWN_FAILURES: frozenset[str] = frozenset()


_known_failure = known_failures(KNOWN_FAILURES, "known gap of the identity rig (issue 18)")
