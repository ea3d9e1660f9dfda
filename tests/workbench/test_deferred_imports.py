"""Modules pyvista imports but the workbench does not use run on first use (launch time).

``workbench.deferred_imports`` hands out ``matplotlib.pyplot`` as an empty
module that runs pyplot's code the first time a name is read from it. These
tests check that the module really is deferred through a whole pyvista and
pyvistaqt import, that it works in full once used, and the mechanism itself
on a throw-away module: one run, on first use, never on a second ``import``.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

from workbench import deferred_imports


def run_python(code: str) -> str:
    result = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
                            timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_pyvista_and_pyvistaqt_import_without_running_pyplot_and_pyplot_works_when_used():
    out = run_python("""
        import sys
        import workbench                     # installs the deferral
        import PySide6.QtWidgets, pyvista, pyvista.plotting, pyvistaqt
        plt = sys.modules["matplotlib.pyplot"]
        print("ran before use:", "figure" in plt.__dict__, "matplotlib.axes" in sys.modules)
        import matplotlib.pyplot as again     # a second import statement must not run it either
        print("same module:", again is plt, "figure" in plt.__dict__)
        figure = plt.figure(figsize=(1, 1))
        print("ran after use:", "figure" in plt.__dict__, type(figure).__name__)
        print("cycler:", len(pyvista.plotting.colors.get_default_cycler()))
    """)
    assert "ran before use: False False" in out
    assert "same module: True False" in out
    assert "ran after use: True Figure" in out
    assert "cycler: 10" in out


@pytest.fixture
def throwaway_module(tmp_path, monkeypatch):
    name = "ap_deferred_probe"
    (tmp_path / f"{name}.py").write_text("import builtins\n"
                                         "builtins.ap_deferred_runs = getattr(builtins, 'ap_deferred_runs', 0) + 1\n"
                                         "VALUE = 42\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import builtins
    monkeypatch.setattr(builtins, "ap_deferred_runs", 0, raising=False)
    yield name, builtins
    sys.modules.pop(name, None)
    deferred_imports._finder.names.discard(name)


def test_a_deferred_module_runs_once_on_first_use(throwaway_module):
    name, builtins = throwaway_module
    deferred_imports.install([name])
    module = __import__(name)
    __import__(name)
    assert builtins.ap_deferred_runs == 0
    assert module.__spec__.name == name and module.__name__ == name     # no run for these
    assert builtins.ap_deferred_runs == 0
    assert module.VALUE == 42
    assert builtins.ap_deferred_runs == 1
    assert module.VALUE == 42 and __import__(name) is module
    assert builtins.ap_deferred_runs == 1
    with pytest.raises(AttributeError):
        _ = module.missing


def test_an_already_imported_module_is_left_alone(throwaway_module):
    name, builtins = throwaway_module
    __import__(name)
    assert builtins.ap_deferred_runs == 1
    deferred_imports.install([name])
    assert name not in deferred_imports._finder.names


def test_listing_or_star_importing_a_deferred_module_runs_it(throwaway_module):
    name, builtins = throwaway_module
    deferred_imports.install([name])
    module = __import__(name)
    assert not hasattr(module, "__wrapped__")          # what PySide's import hook asks: no run
    assert builtins.ap_deferred_runs == 0
    assert "VALUE" in dir(module)
    assert builtins.ap_deferred_runs == 1
    namespace: dict = {}
    exec(f"from {name} import *", namespace)
    assert namespace["VALUE"] == 42 and builtins.ap_deferred_runs == 1
