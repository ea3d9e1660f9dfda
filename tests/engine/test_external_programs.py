"""The programs we run (Festival, ffmpeg), looked up where ``AP_FESTIVAL``/``AP_FFMPEG`` say or on ``PATH``.

Missing is made real: the verb runs with ``PATH`` set to an empty folder, so no program is found. It must
end with one line saying what to install on Debian/Ubuntu, Fedora, macOS and conda-forge, status 2; and
the verbs that need no Festival (render, pose, tracks, say --audio, web-export --tracks) must still work.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from engine.programs import PROGRAMS, find_program, locate, missing_message, program_name
from tests.engine.cli_runner import assert_user_error

FESTIVAL = shutil.which("festival")
COMMANDS = '<commands>\n  <HeadNod at="100" amplitude="30" count="1"/>\n</commands>\n'


def run_cli(*args, cwd: Path, path: str, **variables: str) -> subprocess.CompletedProcess:
    """``python -m engine ARGS`` (the interpreter by its full path) with ``PATH=path`` and ``variables``."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "AP_FESTIVAL", "AP_FFMPEG", "AP_FFPROBE")}
    env.update(PATH=path, **variables)
    return subprocess.run([sys.executable, "-m", "engine", *map(str, args)], capture_output=True, text=True,
                          env=env, cwd=cwd, timeout=300, check=False)


@pytest.fixture
def empty_path(tmp_path) -> str:
    folder = tmp_path / "empty-bin"
    folder.mkdir()
    return str(folder)


@pytest.fixture(scope="module")
def recording(tmp_path_factory) -> tuple[Path, Path]:
    """A take (WAV) and its phone labels (CSV), made once by the real Festival."""
    if FESTIVAL is None:
        pytest.skip("Festival is not installed (./bootstrap installs it)")
    folder = tmp_path_factory.mktemp("take")
    made = run_cli("say", "Hyvää päivää", "-o", "take.wav", "--phones", "take.csv", cwd=folder,
                   path=os.environ["PATH"])
    assert made.returncode == 0, made.stderr
    return folder / "take.wav", folder / "take.csv"


# -- the lookup ----------------------------------------------------------------------------------------

def test_the_variable_names_the_program(tmp_path):
    program = tmp_path / "my-festival"
    program.write_text("#!/bin/sh\n")
    program.chmod(0o755)
    assert program_name("festival", {"AP_FESTIVAL": str(program)}) == str(program)
    assert find_program("festival", {"AP_FESTIVAL": str(program), "PATH": ""}) == str(program)
    assert find_program("festival", {"PATH": str(tmp_path)}) is None           # named my-festival, not festival
    assert find_program("festival", {"AP_FESTIVAL": "my-festival", "PATH": str(tmp_path)}) == str(program)


def test_ffprobe_is_found_beside_the_ffmpeg_the_variable_names(tmp_path):
    for name in ("ffmpeg", "ffprobe"):
        (tmp_path / name).write_text("#!/bin/sh\n")
        (tmp_path / name).chmod(0o755)
    environ = {"AP_FFMPEG": str(tmp_path / "ffmpeg"), "PATH": ""}
    assert find_program("ffprobe", environ) == str(tmp_path / "ffprobe")
    assert find_program("ffprobe", {**environ, "AP_FFPROBE": "/nowhere/ffprobe"}) is None


def test_a_file_that_is_not_executable_is_not_a_program(tmp_path):
    (tmp_path / "festival").write_text("not a program")
    assert locate(str(tmp_path / "festival")) is None
    assert locate("festival", path=str(tmp_path)) is None


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_missing_line_names_every_system(name):
    line = missing_message(name, environ={})
    assert "\n" not in line
    assert "Debian/Ubuntu: sudo apt-get install" in line and "Fedora: " in line and "macOS: " in line
    assert "conda-forge: conda install -c conda-forge" in line and PROGRAMS[name].variable in line
    assert f"no program {name!r} on PATH" in line and "Without " in line


def test_the_missing_line_says_the_variable_named_it(tmp_path):
    line = missing_message("ffmpeg", environ={"AP_FFMPEG": str(tmp_path / "ffmpeg")})
    assert f"not installed at {tmp_path / 'ffmpeg'} (no such program; AP_FFMPEG names it)" in line


# -- the verbs, with PATH emptied -------------------------------------------------------------------------

@pytest.mark.slow
def test_say_without_festival_says_what_to_install(tmp_path, empty_path):
    line = assert_user_error(run_cli("say", "Hyvää päivää", "-o", "x.wav", cwd=tmp_path, path=empty_path))
    assert "Festival is not installed (no program 'festival' on PATH, and AP_FESTIVAL is not set)" in line
    assert "sudo apt-get install festival festvox-suopuhe-lj" in line and "sudo dnf install festival" in line
    assert "conda install -c conda-forge festival" in line
    assert "render, pose, tracks, say --audio and web-export --tracks still work" in line
    assert not (tmp_path / "x.wav").exists()


@pytest.mark.slow
def test_web_export_of_text_without_festival_says_what_to_install(tmp_path, empty_path):
    line = assert_user_error(run_cli("web-export", "--say", "Hei", "-o", "site", cwd=tmp_path, path=empty_path))
    assert "Festival is not installed" in line and "AP_FESTIVAL" in line


@pytest.mark.slow
def test_a_festival_the_variable_names_is_used_with_path_empty(tmp_path, empty_path):
    if FESTIVAL is None:
        pytest.skip("Festival is not installed (./bootstrap installs it)")
    done = run_cli("say", "Hei", "-o", "x.wav", cwd=tmp_path, path=empty_path, AP_FESTIVAL=FESTIVAL)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "x.wav").read_bytes()[:4] == b"RIFF"
    wrong = run_cli("say", "Hei", "-o", "y.wav", cwd=tmp_path, path=empty_path,
                    AP_FESTIVAL=str(tmp_path / "no-festival"))
    line = assert_user_error(wrong)
    assert f"Festival is not installed at {tmp_path / 'no-festival'}" in line and "AP_FESTIVAL names it" in line


@pytest.mark.slow
def test_the_verbs_that_need_no_festival_work_with_path_empty(tmp_path, empty_path, recording):
    take, labels = recording
    rendered = run_cli("render", "-o", "x.png", "--size", "160x120", cwd=tmp_path, path=empty_path)
    assert rendered.returncode == 0, rendered.stderr
    assert (tmp_path / "x.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    posed = run_cli("pose", "--set", "jaw_open=0.4", "-o", "x.obj", cwd=tmp_path, path=empty_path)
    assert posed.returncode == 0, posed.stderr
    (tmp_path / "nod.xml").write_text(COMMANDS)
    tracked = run_cli("tracks", "nod.xml", "-o", "nod.csv", cwd=tmp_path, path=empty_path)
    assert tracked.returncode == 0, tracked.stderr
    assert (tmp_path / "nod.csv").read_text().startswith("time_ms,")
    spoken = run_cli("say", "--audio", take, "--labels", labels, "--tracks", "take-tracks.csv", "-o", "take.xml",
                     cwd=tmp_path, path=empty_path)
    assert spoken.returncode == 0, spoken.stderr
    assert len((tmp_path / "take-tracks.csv").read_text().splitlines()) > 10
    site = run_cli("web-export", "--tracks", "take-tracks.csv", "--audio", take, "-o", "site", cwd=tmp_path,
                   path=empty_path)
    assert site.returncode == 0, site.stderr
    assert (tmp_path / "site" / "index.html").is_file()


@pytest.mark.slow
def test_video_without_ffmpeg_says_what_to_install(tmp_path, empty_path, recording):
    take, labels = recording
    line = assert_user_error(run_cli("say", "--audio", take, "--labels", labels, "-o", "x.mp4", "--quiet",
                                     cwd=tmp_path, path=empty_path))
    assert "ffmpeg is not installed (no program 'ffmpeg' on PATH, and AP_FFMPEG is not set)" in line
    assert "brew install ffmpeg" in line and "RPM Fusion" in line and "conda-forge ffmpeg" in line
    assert not (tmp_path / "x.mp4").exists()
