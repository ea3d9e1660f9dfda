"""The observers find dlib's trained models without ``pkg_resources`` (docs/validation.md).

``face_recognition_models`` 0.3.0 imports ``pkg_resources`` in its ``__init__``, and setuptools 81 and
later no longer ship it, so a fresh environment with a new setuptools could not load the observers
at all. The models are found from the package's location instead; this runs the real observers in a
Python where importing ``pkg_resources`` fails, whatever setuptools the environment has.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

pytest.importorskip("dlib")

BLOCK_AND_LOAD = """
import importlib.abc, sys

class NoPkgResources(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name == "pkg_resources" or name.startswith("pkg_resources."):
            raise ImportError("pkg_resources is blocked by the test", name=name)
        return None

sys.meta_path.insert(0, NoPkgResources())
from engine.validation.observers import Observers
seen = Observers()
print("loaded", type(seen._points).__name__, type(seen._describer).__name__)
"""


def test_the_observers_load_without_pkg_resources():
    done = subprocess.run([sys.executable, "-c", BLOCK_AND_LOAD], check=False, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["loaded", "shape_predictor", "face_recognition_model_v1"]
