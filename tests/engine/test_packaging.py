"""The distribution's parts: a core that pulls no GUI, extras by feature, and a verb whose extra is missing.

The missing extra is made real: the verb runs in a fresh interpreter whose import system refuses the
extra's modules (a ``sitecustomize`` on ``PYTHONPATH`` puts a finder into ``sys.meta_path`` that raises
``ModuleNotFoundError`` for them, as for a module that is not installed). The verb must end with one line
naming the ``pip install 'artificial-person[EXTRA]'`` and status 2, never a traceback.
"""

from __future__ import annotations

import importlib.metadata
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from engine.cli.extras import EXTRA_MODULES, EXTRA_NAMED, NEEDS, extra_for_import_error, needs_of
from tests.engine.cli_runner import assert_user_error

ROOT = Path(__file__).resolve().parents[2]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
#: Distributions only the GUI or the services need: none of them may be a core dependency.
NOT_CORE = ("PySide6", "PySide6-Essentials", "pyvistaqt", "sounddevice", "websockets", "distributed", "pylsl",
            "dlib-bin", "face_recognition_models", "ai-edge-litert", "matplotlib")
BLOCKER = '''
import os, sys


class RefuseModules:
    """Every module named in AP_TEST_BLOCK is 'not installed'."""

    def __init__(self, names):
        self.names = names

    def find_spec(self, name, path=None, target=None):
        if name.partition(".")[0] in self.names:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None


sys.meta_path.insert(0, RefuseModules({n for n in os.environ.get("AP_TEST_BLOCK", "").split(",") if n}))
'''


def requirement_name(text: str) -> str:
    return re.split(r"[\s<>=!~\[;]", text.strip(), maxsplit=1)[0]


@pytest.fixture(scope="module")
def blocker(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("blocker")
    (folder / "sitecustomize.py").write_text(BLOCKER)
    return folder


def run_without(blocker: Path, modules: list[str], *args, cwd: Path) -> subprocess.CompletedProcess:
    """``python -m engine ARGS`` in a fresh interpreter in which ``modules`` cannot be imported."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY", "PYTHONPATH")}
    env.update(PYTHONPATH=f"{blocker}{os.pathsep}{ROOT}", AP_TEST_BLOCK=",".join(modules))
    return subprocess.run([sys.executable, "-m", "engine", *map(str, args)], capture_output=True, text=True,
                          env=env, cwd=cwd, timeout=120, check=False)


# -- pyproject.toml --------------------------------------------------------------------------------

def test_the_core_pulls_no_gui_and_no_service():
    core = {requirement_name(r) for r in PROJECT["dependencies"]}
    assert core.isdisjoint(NOT_CORE), core & set(NOT_CORE)
    assert {"numpy", "scipy", "h5py", "lxml", "vtk", "pyvista", "pillow"} <= core


def test_extras_by_feature_and_test_has_them_all():
    extras = PROJECT["optional-dependencies"]
    assert {"workbench", "live", "lsl", "dask", "validate", "test"} <= set(extras)
    workbench = {requirement_name(r) for r in extras["workbench"]}
    assert {"PySide6-Essentials", "pyvista", "pyvistaqt", "sounddevice"} <= workbench
    assert {requirement_name(r) for r in extras["live"]} == {"websockets"}
    assert "pylsl" in {requirement_name(r) for r in extras["lsl"]}
    assert {requirement_name(r) for r in extras["dask"]} == {"distributed"}
    test = " ".join(extras["test"])
    for extra in ("workbench", "live", "lsl", "dask", "validate"):
        assert re.search(rf"artificial-person\[[^\]]*\b{extra}\b", test), extra
    assert "build" in {requirement_name(r) for r in extras["test"]}


def test_every_extra_the_cli_names_exists_in_pyproject():
    extras = PROJECT["optional-dependencies"]
    for need in NEEDS:
        assert EXTRA_NAMED.get(need.extra, need.extra) in extras, need
    assert set(EXTRA_MODULES) - set(EXTRA_NAMED) <= set(extras)


def test_the_modules_each_extra_brings_are_installed_here():
    """The test extra installs every extra: each module the CLI checks for is there (else the table is wrong)."""
    import importlib.util

    for extra, modules in EXTRA_MODULES.items():
        for module in modules:
            assert importlib.util.find_spec(module) is not None, (extra, module)


def test_version_comes_from_the_package_metadata():
    import engine

    assert engine.__version__ == importlib.metadata.version("artificial-person") == PROJECT["version"]
    done = subprocess.run([sys.executable, "-m", "engine", "--version"], capture_output=True, text=True,
                          timeout=60, check=False)
    assert done.returncode == 0 and done.stdout.strip() == f"artificial-person {PROJECT['version']}"


def test_version_without_metadata_reads_the_checkout(tmp_path):
    code = ("import importlib.metadata as m\n"
            "def gone(name): raise m.PackageNotFoundError(name)\n"
            "m.version = gone\n"
            "import engine; print(engine.__version__)")
    done = subprocess.run([sys.executable, "-I", "-c", f"import sys; sys.path.insert(0, {str(ROOT)!r})\n{code}"],
                          capture_output=True, text=True, timeout=60, check=False, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"{PROJECT['version']}+source"


# -- which verb needs what -----------------------------------------------------------------------------

def test_needs_of_options():
    assert needs_of("serve", window=False, lsl=False) == ["live"]
    assert needs_of("serve", window=True, lsl=True) == ["live", "lsl", "workbench"]
    assert needs_of("stimuli", scheduler=None) == []
    assert needs_of("stimuli", scheduler="tcp://h:1") == ["dask"]
    assert needs_of("render") == [] and needs_of("say") == [] and needs_of("web-export") == []


def test_an_import_error_deep_in_a_verb_names_the_extra():
    line = extra_for_import_error(ModuleNotFoundError("No module named 'websockets.asyncio'",
                                                      name="websockets.asyncio"))
    assert line is not None and "pip install 'artificial-person[live]'" in line
    assert extra_for_import_error(ModuleNotFoundError("No module named 'numpyx'", name="numpyx")) is None


# -- verbs run with an extra's modules not importable ------------------------------------------------

def test_the_blocker_really_blocks(blocker, tmp_path):
    env = {**os.environ, "PYTHONPATH": str(blocker), "AP_TEST_BLOCK": "PySide6"}
    done = subprocess.run([sys.executable, "-c", "import PySide6"], capture_output=True, text=True, env=env,
                          timeout=60, check=False, cwd=tmp_path)
    assert done.returncode == 1 and "ModuleNotFoundError: No module named 'PySide6'" in done.stderr


@pytest.mark.slow
@pytest.mark.parametrize("blocked, args, extra, what", [
    (["PySide6"], ["workbench"], "workbench", "the workbench"),
    (["pyvistaqt"], ["workbench"], "workbench", "the workbench"),
    (["websockets"], ["serve", "--headless"], "live", "serve"),
    (["PySide6"], ["serve", "--window"], "workbench", "serve --window"),
    (["pylsl"], ["serve", "--headless", "--lsl"], "lsl", "serve --lsl"),
    (["dlib", "ai_edge_litert"], ["validate", "x.png", "-o", "v.csv"], "validate", "validate"),
    (["distributed"], ["stimuli", "design.toml", "-o", "set", "--scheduler", "tcp://127.0.0.1:1"], "dask",
     "stimuli --scheduler"),
    (["matplotlib"], ["study-analyse", "results.csv", "-o", "report"], "validate", "study-analyse"),
])
def test_a_verb_whose_extra_is_missing_says_which_pip_install(blocker, tmp_path, blocked, args, extra, what):
    line = assert_user_error(run_without(blocker, blocked, *args, cwd=tmp_path))
    assert line.startswith(f"error: {what}")
    assert line.endswith(f"pip install 'artificial-person[{extra}]'"), line
    assert all(module in line for module in blocked), line
    assert not any(tmp_path.iterdir()), "nothing is written before the check"


@pytest.mark.slow
def test_the_core_verbs_work_with_every_extra_missing(blocker, tmp_path):
    everything = sorted({m for modules in EXTRA_MODULES.values() for m in modules if m != "pyvista"}
                        | {"shiboken6", "sounddevice"})
    info = run_without(blocker, everything, "info", "--json", cwd=tmp_path)
    assert info.returncode == 0, info.stderr
    assert '"vertices"' in info.stdout
    helped = run_without(blocker, everything, "--help", cwd=tmp_path)
    assert helped.returncode == 0 and "workbench" in helped.stdout and "serve" in helped.stdout
    tracks = run_without(blocker, everything, "pose", "--set", "jaw_open=0.5", "-o", tmp_path / "pose.obj",
                         cwd=tmp_path)
    assert tracks.returncode == 0, tracks.stderr
    assert (tmp_path / "pose.obj").stat().st_size > 10_000
