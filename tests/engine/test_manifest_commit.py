"""A stimulus set's manifest names the toolkit's commit only when it runs from the toolkit's own
checkout: installed in a venv inside some other repository, it says ``None``, not that repository's."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from engine.stimuli.manifest import git_commit

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")


def _repository(folder: Path) -> str:
    def git(*args: str) -> str:
        return subprocess.run(["git", "-C", str(folder), *args], capture_output=True, text=True,
                              check=True).stdout.strip()

    git("init", "-q")
    (folder / "README").write_text("a lab's project\n")
    git("add", "README")
    git("-c", "user.name=Lab", "-c", "user.email=lab@example.org", "commit", "-q", "-m", "first")
    return git("rev-parse", "HEAD")


def test_the_toolkits_own_checkout_gives_its_commit(tmp_path):
    commit = _repository(tmp_path)
    assert git_commit(tmp_path) == commit


def test_a_package_installed_inside_another_repository_gives_none(tmp_path):
    _repository(tmp_path)
    site_packages = tmp_path / ".venv" / "lib" / "python3.11" / "site-packages"
    site_packages.mkdir(parents=True)
    assert git_commit(site_packages) is None


def test_no_repository_at_all_gives_none(tmp_path):
    assert git_commit(tmp_path) is None


def test_this_checkout_is_found_as_it_runs():
    top = Path(__file__).resolve().parents[2]
    if not (top / ".git").exists():
        pytest.skip("not run from a git checkout")
    assert git_commit() is not None and len(git_commit() or "") == 40
