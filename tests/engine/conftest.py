"""Fixtures the engine's tests share: the shipped default head, loaded once per run.

``head`` is shared by every test that asks for it, so it must not be edited:
a test that changes a model takes ``head_copy`` (a fresh copy each time).
The guard below fails a test that edits the shared head anyway, naming it,
instead of letting a later test see the edit.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

import engine
from engine.model import Model


@pytest.fixture(scope="session")
def head() -> Model:
    """The shipped default head (``engine/data/default-head/head.xml``), read-only."""
    if not engine.default_model_path().exists():
        pytest.skip("the default head (engine/data/default-head/head.xml) is not built yet")
    return engine.load_model()


@pytest.fixture
def head_copy(head: Model) -> Model:
    """A copy of the default head that the test may edit."""
    return head.copy()


@pytest.fixture(autouse=True)
def _shared_head_stays_unedited(request: pytest.FixtureRequest) -> Iterator[None]:
    if "head" not in request.fixturenames:
        yield
        return
    shared = request.getfixturevalue("head")
    revision = shared.revision
    yield
    assert shared.revision == revision, "the test edited the shared default head: take head_copy instead"
