"""The built wheel, installed as a user installs it: a new virtual environment in a temporary folder.

The sdist and the wheel are built from a copy of the packages (``python -m build --no-isolation``: no
network; the wheel is built from the unpacked sdist, so the sdist must carry everything too). A compiled
module of another Python is left in the copy, as a checkout used by two Pythons has, and must not reach
the wheel. The wheel goes into a fresh venv with ``pip install --no-deps``; the venv sees this
environment's dependencies through a ``.pth`` file (a path line adds the folder, but runs none of its own
``.pth`` files, so the checkout's editable install stays out). From another folder the venv's
``artificial-person`` then runs ``info``, ``library``, ``render``, ``say … -o x.wav`` (the real Festival)
and ``web-export``.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: What a wheel may weigh (bytes): the default head's arrays (4 MB) and the web player, compressed.
MAX_WHEEL_BYTES = 8_000_000
SOURCES = ("engine", "workbench", "pyproject.toml", "setup.py", "README.md", "LICENSE", "MANIFEST.in")

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed "
                                                                          "(./bootstrap installs it)")]


def run(command, cwd, env=None, timeout=600) -> subprocess.CompletedProcess:
    return subprocess.run([str(c) for c in command], capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=timeout, check=False)


def shipped_files() -> list[str]:
    """The files of the checkout's packages the wheel must carry (everything but byte code, compiled
    modules, the kernels' C sources and the scripts that derived the shipped data)."""
    found = []
    for top in ("engine", "workbench"):
        for path in sorted((ROOT / top).rglob("*")):
            name = path.relative_to(ROOT).as_posix()
            if not path.is_file() or "__pycache__" in path.parts or path.suffix in (".pyc", ".so", ".c"):
                continue
            if name.startswith("engine/data/") and path.suffix == ".py":
                continue
            if path.suffix == ".py" and not (path.parent / "__init__.py").exists() and "web" not in path.parts:
                continue
            found.append(name)
    return found


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> Path:
    work = tmp_path_factory.mktemp("wheel-build")
    source = work / "src"
    source.mkdir()
    for name in SOURCES:
        if (ROOT / name).is_dir():
            shutil.copytree(ROOT / name, source / name, ignore=shutil.ignore_patterns("*.egg-info"))
        else:
            shutil.copy2(ROOT / name, source / name)
    (source / "engine" / "deform" / "_kernel.cpython-399-x86_64-linux-gnu.so").write_bytes(b"\x7fELF stale")
    built = run([sys.executable, "-m", "build", "--no-isolation", "-o", work / "dist", source], cwd=work)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    wheels = list((work / "dist").glob("*.whl"))
    assert len(wheels) == 1 and list((work / "dist").glob("*.tar.gz")), list((work / "dist").iterdir())
    return wheels[0]


@pytest.fixture(scope="module")
def venv(wheel, tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("user") / "venv"
    made = run([sys.executable, "-m", "venv", "--without-pip", folder], cwd=folder.parent)
    assert made.returncode == 0, made.stderr
    python = folder / "bin" / "python"
    site = Path(run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                    cwd=folder.parent).stdout.strip())
    (site / "main-environment.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    installed = run([sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index", wheel],
                    cwd=folder.parent)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return folder


def user_env() -> dict[str, str]:
    return {k: v for k, v in os.environ.items()
            if k not in ("PYTHONPATH", "DISPLAY", "WAYLAND_DISPLAY", "VIRTUAL_ENV", "PYTHONHOME")}


def test_the_wheel_carries_everything_and_nothing_else(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    print(f"\nwheel {wheel.name}: {wheel.stat().st_size} bytes ({wheel.stat().st_size / 1e6:.2f} MB), "
          f"{len(names)} files")
    assert wheel.stat().st_size < MAX_WHEEL_BYTES
    missing = [name for name in shipped_files() if name not in names]
    assert not missing, missing
    assert not [n for n in names if n.startswith(("tests/", "docs/", "benchmarks/", "examples/", "build/"))]
    assert not [n for n in names if "__pycache__" in n or n.endswith((".pyc", ".c"))
                or any(part in n for part in (".pytest_cache", ".hypothesis", ".egg-info"))]
    assert not [n for n in names if n.startswith("engine/data/") and n.endswith(".py")]
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    compiled = [n for n in names if n.endswith(".so")]
    assert compiled and all(n.endswith(suffix) for n in compiled), compiled
    for needed in ("engine/data/default-head/head.xml", "engine/data/default-head/head.h5",
                   "engine/data/identity/identity-targets.h5", "engine/library/Blink.lib",
                   "engine/library/articulation/finnish.phones", "engine/formats/schemas/model.xsd",
                   "engine/live/schema/protocol-v1.json", "engine/validation/models/fer2013-mini-xception.tflite",
                   "engine/web/vendor/three/LICENSE", "engine/web/player/player.js",
                   "workbench/icon_files/say.svg", "engine/py.typed"):
        assert needed in names, needed


def test_the_installed_wheel_runs_from_another_folder(venv, tmp_path):
    python = venv / "bin" / "python"
    script = venv / "bin" / "artificial-person"
    env = user_env()
    where = run([python, "-c", "import engine, importlib.metadata as m; print(engine.__file__); "
                               "print(m.version('artificial-person'))"], cwd=tmp_path, env=env)
    assert where.returncode == 0, where.stderr
    assert where.stdout.splitlines()[0].startswith(str(venv)), where.stdout          # not the checkout
    assert run([script, "--version"], cwd=tmp_path, env=env).stdout.strip() == \
        f"artificial-person {where.stdout.splitlines()[1]}"

    info = run([script, "info"], cwd=tmp_path, env=env)
    assert info.returncode == 0, info.stderr
    assert info.stdout.startswith("default-head:") and "jaw_open" in info.stdout
    library = run([script, "library"], cwd=tmp_path, env=env)
    assert library.returncode == 0, library.stderr
    assert "Blink" in library.stdout

    rendered = run([script, "render", "-o", "x.png", "--size", "200x150"], cwd=tmp_path, env=env)
    assert rendered.returncode == 0, rendered.stderr
    assert (tmp_path / "x.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

    said = run([script, "say", "Hyvää päivää", "-o", "x.wav", "--phones", "x.csv"], cwd=tmp_path, env=env)
    assert said.returncode == 0, said.stderr
    assert (tmp_path / "x.wav").read_bytes()[:4] == b"RIFF" and (tmp_path / "x.wav").stat().st_size > 10_000
    assert "p" in (tmp_path / "x.csv").read_text()

    site = run([script, "web-export", "--say", "Hei", "-o", "site"], cwd=tmp_path, env=env)
    assert site.returncode == 0, site.stderr
    files = {p.relative_to(tmp_path / "site").as_posix() for p in (tmp_path / "site").rglob("*") if p.is_file()}
    assert "index.html" in files and len(files) >= 4, files
