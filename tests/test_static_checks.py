"""The layering, the style and the types are checked by tools, as part of the test command.

* ``lint-imports`` (import-linter) keeps the contracts in ``pyproject.toml``: the
  engine imports no Qt and no workbench, VTK only where it renders or reads
  meshes, its stages only the stages before them, and no package has an
  import cycle; in the workbench only the viewport and the named drawing
  modules import pyvista.
* ``ruff check`` keeps the style and catches likely bugs (the rule set and its
  reasons are in ``pyproject.toml``).
* ``mypy`` checks the engine's types (every function annotated).

Each tool is also run on a copy of the sources broken on purpose, to show it
would fail: a test that cannot fail protects nothing.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

PROJECT_ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
CONFIG = PROJECT_ROOT / "pyproject.toml"


def run_tool(name: str, *args: str, cwd: Path = PROJECT_ROOT, path: Path | None = None) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    if path is not None:
        env["PYTHONPATH"] = str(path)
    return subprocess.run([str(BIN / name), *args], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=600, check=False)


def copy_sources(destination: Path) -> Path:
    """engine/ and workbench/ (sources only) and pyproject.toml, copied into ``destination``."""
    ignore = shutil.ignore_patterns("__pycache__", "*.so", "*.pyc")
    for package in ("engine", "workbench"):
        shutil.copytree(PROJECT_ROOT / package, destination / package, ignore=ignore)
    shutil.copy(CONFIG, destination / "pyproject.toml")
    return destination


def append(path: Path, text: str) -> None:
    path.write_text(path.read_text() + "\n" + text + "\n")


def test_import_contracts_are_kept():
    result = run_tool("lint-imports", "--no-cache")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "BROKEN" not in result.stdout


def test_ruff_finds_nothing():
    result = run_tool("ruff", "check", "--no-cache", ".")
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_finds_nothing_in_the_engine():
    result = run_tool("mypy", "--config-file", str(CONFIG))
    assert result.returncode == 0, result.stdout + result.stderr


BREAKAGES = {
    # breakage: (file, code appended to it, the contract that must break, the import it must name)
    "engine imports Qt": ("engine/model/cells.py", "import PySide6.QtCore",
                          "imports neither the workbench nor Qt", "engine.model.cells -> PySide6"),
    "engine imports the workbench": ("engine/deform/transforms.py", "def f():\n    import workbench.app",
                                     "imports neither the workbench nor Qt", "engine.deform.transforms -> workbench"),
    "an early stage imports a later one": ("engine/model/landmarks.py", "def f():\n    import engine.speech.say",
                                           "depend only on the stages before them",
                                           "engine.model.landmarks -> engine.speech.say"),
    "engine renders outside its renderer": ("engine/timeline/timeline.py", "def f():\n    import pyvista",
                                            "pyvista/VTK only where pictures are rendered",
                                            "engine.timeline.timeline -> pyvista"),
    "a cycle inside a package": ("engine/commands/interpolation.py",
                                 "def f():\n    import engine.commands.translator",
                                 "No import cycles", ".interpolation -> .translator"),
    "a workbench widget draws with pyvista": ("workbench/parameter_panel/slider.py", "import pyvista",
                                              "only in the viewport and the drawing modules",
                                              "workbench.parameter_panel.slider -> pyvista"),
    "a workbench tool imports another": ("workbench/look_menu.py", "def f():\n    import workbench.painting",
                                         "tools import none of each other",
                                         "workbench.look_menu -> workbench.painting"),
}


@pytest.fixture(scope="module")
def broken_layering(tmp_path_factory) -> str:
    """The "Broken contracts" part of one ``lint-imports`` run on a copy of the sources with every one of
    :data:`BREAKAGES` made at once (one run, not one per breakage: each breakage is a different import,
    and every broken import of every contract is listed)."""
    root = copy_sources(tmp_path_factory.mktemp("broken-layering"))
    for where, code, _contract, _evidence in BREAKAGES.values():
        append(root / where, code)
    result = run_tool("lint-imports", "--no-cache", "--config", str(root / "pyproject.toml"), cwd=root, path=root)
    assert result.returncode != 0, result.stdout
    return result.stdout


@pytest.mark.slow
@pytest.mark.parametrize("breakage", list(BREAKAGES))
def test_lint_imports_fails_on_a_broken_layering(broken_layering, breakage):
    _where, _code, contract, evidence = BREAKAGES[breakage]
    broken = " ".join(broken_layering.split("Broken contracts")[-1].split())
    assert contract in broken and evidence in broken, broken_layering


@pytest.mark.parametrize("code, rule", [
    ("from PySide6.QtCore import QObject\n", "TID251"),          # Qt in the engine
    ("import pyvista\n", "TID253"),                              # VTK at module level in the engine
    ("from ..errors import UserError\n", "TID252"),              # a relative import in the engine
    ("import os  # noqa: E501\n", "RUF100"),                     # a noqa no rule needs
])
def test_ruff_fails_on_a_broken_rule(tmp_path, code, rule):
    module = tmp_path / "engine" / "model" / "probe.py"
    module.parent.mkdir(parents=True)
    module.write_text('"""A probe."""\n\n' + code)
    result = run_tool("ruff", "check", "--no-cache", "--config", str(CONFIG), "--output-format", "concise",
                      str(module), cwd=tmp_path)
    assert result.returncode != 0
    assert rule in result.stdout, result.stdout


def test_mypy_fails_on_a_type_error_and_an_unannotated_function(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text("def untyped(x):\n    return x\n\n\ndef wrong() -> int:\n    return 'one'\n")
    result = run_tool("mypy", "--config-file", str(CONFIG), "--no-incremental", str(probe), cwd=tmp_path)
    assert result.returncode != 0
    assert "[no-untyped-def]" in result.stdout and "[return-value]" in result.stdout, result.stdout
