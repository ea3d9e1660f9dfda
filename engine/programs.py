"""The programs the toolkit runs (Festival, ffmpeg, ffprobe): where they are, and what to say when one is missing.

Each is looked up where its environment variable says (``AP_FESTIVAL=/opt/festival/bin/festival``), else
on ``PATH``. A missing one is a :class:`~engine.errors.UserError` of its caller (``SynthesisError``,
``FFmpegMissing``) whose one line says what to install on Debian/Ubuntu, Fedora, macOS (Homebrew) and
conda-forge, and which verbs still work without it (``docs/install.md`` has the same table).

>>> program_name("festival", {"AP_FESTIVAL": "/opt/festival/bin/festival"})
'/opt/festival/bin/festival'
>>> program_name("ffmpeg", {})
'ffmpeg'
>>> "apt-get install ffmpeg" in missing_message("ffmpeg", {})
True
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Program:
    """One program we run, how to get it on each system, and what works without it."""

    name: str
    variable: str
    title: str
    debian: str
    fedora: str
    macos: str
    conda: str
    without: str


PROGRAMS: dict[str, Program] = {
    "festival": Program(
        "festival", "AP_FESTIVAL", "Festival",
        debian="sudo apt-get install festival festvox-suopuhe-lj festvox-suopuhe-mv",
        fedora="sudo dnf install festival (the Finnish Suopuhe voices from their own site)",
        macos="untested: conda-forge's festival (below) or a build from festvox.org",
        conda="conda install -c conda-forge festival",
        without="Without Festival, render, pose, tracks, say --audio and web-export --tracks still work"),
    "ffmpeg": Program(
        "ffmpeg", "AP_FFMPEG", "ffmpeg",
        debian="sudo apt-get install ffmpeg",
        fedora="sudo dnf install ffmpeg from RPM Fusion (Fedora's ffmpeg-free has no H.264 encoder)",
        macos="brew install ffmpeg",
        conda="conda install -c conda-forge ffmpeg",
        without="Without ffmpeg, everything but video (.mp4) works: say -o x.wav, render, web-export, tracks"),
    "ffprobe": Program(
        "ffprobe", "AP_FFPROBE", "ffprobe",
        debian="sudo apt-get install ffmpeg",
        fedora="sudo dnf install ffmpeg from RPM Fusion",
        macos="brew install ffmpeg",
        conda="conda install -c conda-forge ffmpeg",
        without="Without ffprobe, everything but reading videos (validate on .mp4) works"),
}


def program_name(name: str, environ: Mapping[str, str] | None = None) -> str:
    """The program to run for ``name``: its variable's value when set (a path or a name), else ``name``.

    ``ffprobe`` with only ``AP_FFMPEG`` set is the ``ffprobe`` beside that ffmpeg, when there is one.
    """
    environ = os.environ if environ is None else environ
    given = environ.get(PROGRAMS[name].variable, "").strip()
    if given:
        return given
    if name == "ffprobe":
        ffmpeg = environ.get(PROGRAMS["ffmpeg"].variable, "").strip()
        if ffmpeg and os.sep in ffmpeg:
            beside = Path(ffmpeg).with_name("ffprobe" + Path(ffmpeg).suffix)
            if beside.is_file():
                return str(beside)
    return name


def find_program(name: str, environ: Mapping[str, str] | None = None) -> str | None:
    """The full path of ``name`` (as :func:`program_name` says, then on ``PATH``), or ``None``."""
    return locate(program_name(name, environ), None if environ is None else environ.get("PATH", ""))


def locate(program: str, path: str | None = None) -> str | None:
    """``program`` itself when it is a path to an executable file, else its full path on ``path``
    (default ``$PATH``); ``None`` when there is none."""
    if os.sep in program or (os.altsep and os.altsep in program):
        return program if os.path.isfile(program) and os.access(program, os.X_OK) else None
    return shutil.which(program, path=path)


def missing_message(name: str, program: str | None = None, environ: Mapping[str, str] | None = None) -> str:
    """One line: ``name`` is not installed (where we looked for ``program``, default :func:`program_name`),
    how to install it on each system, and what works without it."""
    about = PROGRAMS[name]
    environ = os.environ if environ is None else environ
    program = program_name(name, environ) if program is None else program
    named_by = f"; {about.variable} names it" if environ.get(about.variable, "").strip() == program else ""
    if os.sep in program or (os.altsep and os.altsep in program):
        where = f"not installed at {program} (no such program{named_by})"
    else:
        where = f"not installed (no program {program!r} on PATH{named_by or f', and {about.variable} is not set'})"
    return (f"{about.title} is {where}; install it: Debian/Ubuntu: {about.debian}; Fedora: {about.fedora}; "
            f"macOS: {about.macos}; conda-forge: {about.conda}; or set {about.variable} to the program. "
            f"{about.without}.")
