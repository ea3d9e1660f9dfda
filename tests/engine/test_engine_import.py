"""``import engine`` loads no GUI or rendering library.

Each check runs in a fresh interpreter, because this test process may already
have imported Qt or VTK for other tests.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

PROJECT_ROOT = Path(__file__).resolve().parents[2]
FORBIDDEN = ("PySide6", "shiboken6", "vtk", "vtkmodules", "pyvista", "pyvistaqt")

PROBE = """
import importlib, json, sys
for name in {modules!r}:
    importlib.import_module(name)
forbidden = {forbidden!r}
print(json.dumps(sorted(m for m in sys.modules if m.split(".")[0] in forbidden)))
"""


def loaded_forbidden_modules(modules: list[str]) -> list[str]:
    code = PROBE.format(modules=modules, forbidden=FORBIDDEN)
    result = subprocess.run([sys.executable, "-c", code], cwd=PROJECT_ROOT, capture_output=True, text=True,
                            timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("modules", [
    ["engine"],
    ["engine", "engine.formats.model_files", "engine.deform.deformer"],
    ["engine.errors", "engine.deform.transforms", "engine.model.parameters", "engine.model.model", "engine.paths",
     "engine.model.landmarks"],
], ids=["engine", "engine+model_files+deform", "core-modules"])
def test_importing_the_engine_loads_no_gui_or_rendering(modules):
    assert loaded_forbidden_modules(modules) == []


def test_every_engine_module_imports_without_gui_or_rendering():
    """docs/architecture.md: even the modules that render or read meshes through pyvista
    (``engine.outputs.render``, ``engine.formats.mesh_io``) import it inside their functions."""
    import pkgutil

    import engine

    modules = sorted(m.name for m in pkgutil.walk_packages(engine.__path__, "engine.")
                     if not m.name.endswith("__main__"))
    assert "engine.deform.deformer" in modules
    assert loaded_forbidden_modules(modules) == []


def test_loading_and_deforming_a_model_loads_no_gui_or_rendering(tmp_path):
    """Not only the import: reading a model file and deforming it stay Qt- and VTK-free."""
    code = f"""
import json, sys
import numpy as np
import engine
from engine.model.model import InfluenceRegion, Model
from engine.model.parameters import Parameter, ParameterTree
tree = ParameterTree([Parameter("jaw_open", "rotation", axis=(1, 0, 0), degrees_per_unit=20)])
m = Model(np.eye(3), [3, 0, 1, 2], parameters=tree, regions={{"jaw_open": InfluenceRegion([0, 1], [1, 1])}})
path = engine.save_model(m, {str(tmp_path / "m.xml")!r})
engine.load_model(path).deform(jaw_open=0.5)
forbidden = {FORBIDDEN!r}
print(json.dumps(sorted(n for n in sys.modules if n.split(".")[0] in forbidden)))
"""
    result = subprocess.run([sys.executable, "-c", code], cwd=PROJECT_ROOT, capture_output=True, text=True,
                            timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout.strip().splitlines()[-1]) == []


def test_the_probe_does_see_a_rendering_import():
    """Guard against a vacuous check: importing pyvista is reported."""
    found = loaded_forbidden_modules(["pyvista"])
    assert "pyvista" in found and any(name.startswith("vtk") for name in found)
