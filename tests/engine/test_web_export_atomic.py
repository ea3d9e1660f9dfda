"""``web-export`` writes its site through the project's atomic writer (engine/formats/atomic.py).

Before, each file went to a fixed temporary name (``.NAME.part``) beside it, which a symbolic link
planted there redirected to any file the user may write; ``three/`` was removed and copied again; and
a killed export left a mixed site that the next export did not finish. Now every file of the site
(the player included) is written under one journal: a planted link is never followed, a folder of the
site that is a link is refused, and an export killed half-way is finished (or, killed before its
first rename, undone) by the next export into the folder.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from engine.errors import UserError
from engine.speech.synthesis import wav_bytes
from engine.web.site import MARKER, check_folder, write_folder, write_site
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, made_set, run

ROOT = Path(__file__).resolve().parents[2]
VICTIM = b"the user's file, which an export must never touch\n"


def site(head, out: Path, stimulus: bool = False) -> dict[str, int]:
    """A small real site: the default head opening its jaw, 100 ms of silence (``stimulus``: and a file in
    ``stimuli/``, as a stimulus set's site has)."""
    values = np.array([[0.0], [0.6], [0.0]])
    sizes = write_site(head, ["jaw_open"], values, 50.0, wav_bytes(np.zeros(1600, np.float32), 16000), out)
    if stimulus:
        write_folder(out, (out / "head.glb").read_bytes(), {"stimuli/s1.wav": b"RIFF"}, "animation.json")
    return sizes


def files_of(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture
def victim(tmp_path) -> Path:
    path = tmp_path / "victim.txt"
    path.write_bytes(VICTIM)
    return path


@pytest.mark.parametrize("name", ["index.html", "player.js", "three-LICENSE.txt", "head.glb", "animation.json",
                                  "speech.wav", "stimuli/s1.wav"])
def test_a_link_planted_at_the_old_temporary_name_is_not_followed(head, tmp_path, victim, name):
    out = tmp_path / "site"
    site(head, out, stimulus=True)                          # an earlier site, re-exported into
    planted = out / Path(name).parent / f".{Path(name).name}.part"
    planted.symlink_to(victim)
    site(head, out, stimulus=True)
    assert victim.read_bytes() == VICTIM
    assert planted.is_symlink()                             # left as it was: not ours
    assert (out / name).is_file() and not (out / name).is_symlink()


def test_a_link_in_place_of_a_sites_file_is_replaced_not_followed(head, tmp_path, victim):
    out = tmp_path / "site"
    site(head, out)
    (out / "speech.wav").unlink()
    (out / "speech.wav").symlink_to(victim)
    site(head, out)
    assert victim.read_bytes() == VICTIM
    assert not (out / "speech.wav").is_symlink() and (out / "speech.wav").read_bytes()[:4] == b"RIFF"


@pytest.mark.parametrize("folder", ["stimuli", "stimuli/inner"])
def test_a_sites_folder_that_is_a_link_is_refused(head, tmp_path, folder):
    out, elsewhere = tmp_path / "site", tmp_path / "elsewhere"
    site(head, out)
    elsewhere.mkdir()
    (elsewhere / "mine.txt").write_bytes(VICTIM)
    link = out / folder
    link.parent.mkdir(exist_ok=True)
    link.symlink_to(elsewhere)
    files = {f"{folder}/s1.wav": b"RIFF", "stimuli.json": b"{}"}
    with pytest.raises(UserError, match="symbolic link") as raised:
        write_folder(out, b"glb", {"animation.json": b"{}", "speech.wav": b"RIFF", **files}, "animation.json")
    assert raised.value.file == str(link)
    assert files_of(elsewhere) == {"mine.txt": VICTIM}


def test_the_cli_refuses_a_linked_folder_in_one_line(head, tmp_path):
    out = tmp_path / "site"
    (tmp_path / "made").mkdir()
    set_folder = made_set(tmp_path / "made", '[factors]\ntext = ["Pappa."]\n[output]\nkinds = ["wav", "tracks"]\n')
    assert run("web-export", "--stimuli", set_folder / "set", "-o", out).returncode == 0
    os.rename(out / "stimuli", tmp_path / "old-stimuli")
    (out / "stimuli").symlink_to(tmp_path)
    line = assert_user_error(run_in_process("web-export", "--stimuli", set_folder / "set", "-o", out))
    assert line.startswith(f"error: {out / 'stimuli'}: ") and "symbolic link" in line, line


def test_a_site_written_again_leaves_no_temporary_and_every_file(head, tmp_path):
    out = tmp_path / "site"
    first = site(head, out)
    site(head, out)
    names = set(files_of(out))
    assert {"index.html", "player.js", "three-LICENSE.txt", "head.glb", "animation.json", "speech.wav"} == names
    assert not list(out.rglob(".*")), "temporary files or journals left behind"
    assert first == {name: len(data) for name, data in files_of(out).items()}


# -- killed half-way: finished by the next export, or undone ----------------------------------------------------

KILLED = """
import os, signal, sys
from pathlib import Path
from engine.web.site import write_folder
out, kill_at, stage = Path(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
real_replace, real_fsync, calls = os.replace, os.fsync, []
def replace(src, dst):
    calls.append(dst)
    if stage == "rename" and len(calls) == kill_at:
        os.kill(os.getpid(), signal.SIGKILL)
    real_replace(src, dst)
def fsync(fd):
    if stage == "write":
        os.kill(os.getpid(), signal.SIGKILL)
    real_fsync(fd)
os.replace, os.fsync = replace, fsync
write_folder(out, b"new glb", {"animation.json": b"new animation", "speech.wav": b"new wav",
                               "stimuli/s1.wav": b"new s1"}, "animation.json")
"""


def killed_export(out: Path, kill_at: int, stage: str = "rename") -> None:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    writer = subprocess.run([sys.executable, "-c", KILLED, str(out), str(kill_at), stage], cwd=ROOT, env=env,
                            capture_output=True, text=True, check=False)
    assert writer.returncode == -signal.SIGKILL, writer.stderr


def old_site(out: Path) -> dict[str, bytes]:
    write_folder(out, b"old glb", {"animation.json": b"old animation", "speech.wav": b"old wav",
                                   "stimuli/s1.wav": b"old s1"}, "animation.json")
    return files_of(out)


NEW = {"head.glb": b"new glb", "animation.json": b"new animation", "speech.wav": b"new wav",
       "stimuli/s1.wav": b"new s1"}


def test_an_export_killed_between_two_renames_is_finished_by_the_next_one(tmp_path):
    out = tmp_path / "site"
    old = old_site(out)
    killed_export(out, kill_at=5)           # index.html, player.js, three-LICENSE.txt and head.glb renamed
    mixed = files_of(out)
    assert any(mixed.get(n) == old[n] for n in NEW) and any(mixed.get(n) == v for n, v in NEW.items())
    check_folder(out)                                       # what every export does first
    now = files_of(out)
    assert {n: now[n] for n in NEW} == NEW, "the killed export was not finished"
    assert not list(out.rglob(".*"))
    assert MARKER in now["index.html"].decode()


def test_an_export_killed_before_any_rename_leaves_the_old_site_and_is_undone(tmp_path):
    out = tmp_path / "site"
    old = old_site(out)
    killed_export(out, kill_at=0, stage="write")
    check_folder(out)
    assert files_of(out) == old
    assert not list(out.rglob(".*"))


def test_a_new_folder_killed_before_any_rename_can_be_exported_into_again(tmp_path):
    out = tmp_path / "site"
    killed_export(out, kill_at=0, stage="write")
    check_folder(out)                                       # neither "not empty" nor anything left
    assert files_of(out) == {}
    old_site(out)
    assert files_of(out)["head.glb"] == b"old glb"


def test_a_user_file_in_a_sites_folder_still_means_the_folder_is_not_a_site(tmp_path):
    out = tmp_path / "site"
    (out / "three").mkdir(parents=True)
    (out / "three" / "notes.txt").write_bytes(VICTIM)
    with pytest.raises(UserError, match="not empty"):
        check_folder(out)
