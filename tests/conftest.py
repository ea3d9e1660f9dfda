"""What every test shares: a cache of its own.

The toolkit keeps synthesised skin images in the user's cache folder (``engine/identity/skin_cache.py``).
A test run keeps them in a folder of its own, removed at the end, so the suite neither writes into the
user's ``~/.cache`` nor depends on what an earlier run left there. Processes the tests start inherit it.
A run started with ``ARTIFICIAL_PERSON_CACHE`` set keeps that setting.
"""

from __future__ import annotations

import os
import shutil
import tempfile

import pytest

from engine.identity.skin_cache import CACHE_ENV

_made: list[str] = []


def pytest_configure(config: pytest.Config) -> None:
    if CACHE_ENV not in os.environ:
        _made.append(tempfile.mkdtemp(prefix="artificial-person-test-cache-"))
        os.environ[CACHE_ENV] = _made[-1]


def pytest_unconfigure(config: pytest.Config) -> None:
    for folder in _made:
        shutil.rmtree(folder, ignore_errors=True)
        if os.environ.get(CACHE_ENV) == folder:
            del os.environ[CACHE_ENV]
