"""A validation run: the files to judge, what each was meant to show, the verdicts, the summary.

:func:`validate` takes pictures and videos, a folder of them, or a stimulus set's folder (its
``manifest.csv`` says what each stimulus was meant to show), judges every file on this core and
sums up. A file that cannot be judged gets a row with a plain status and the run goes on;
:class:`NothingReadable` (status 2 on the command line) only when no file could be read.

>>> from engine.validation import validate, write_tables, write_report
>>> summary = validate(["happy.png", "take.mp4"])                         # doctest: +SKIP
>>> summary = validate(["stimuli/"])                                      # doctest: +SKIP
>>> write_tables(summary, "validation.csv"); write_report(summary, "report.html")   # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from engine.errors import UserError
from engine.validation.intended import Intended, SetFile, read_intended, read_set
from engine.validation.judge import Verdict, safe_judge
from engine.validation.lips import LipTrack, lip_track, read_landmarks_track
from engine.validation.observers import observers
from engine.validation.summary import Summary, summarise

RunProgress = Callable[[int, int, str], None]
"""Called with (files done, files in all, the file now judged)."""


class NothingReadable(UserError):
    """Not one of the files given could be read as a picture or a video."""


def validate(inputs: Sequence[str | Path], intended: str | Path | None = None, detector: str = "auto",
             progress: RunProgress | None = None) -> Summary:
    """Judge every file of ``inputs`` (files, folders, or one stimulus set's folder) and sum up.

    ``intended``: the ``--intended`` table for files we did not make (it overrides a manifest)."""
    files = collect(inputs)
    table = read_intended(intended) if intended is not None else {}
    eyes = observers()
    verdicts: list[Verdict] = []
    for n, item in enumerate(files):
        if progress is not None:
            progress(n, len(files), str(item.path))
        meant = table.get(item.path.resolve()) or _by_name(table, item.path) or item.intended
        verdicts.append(safe_judge(item.path, meant, _lips(meant, item.path), detector, eyes))
    if progress is not None:
        progress(len(files), len(files), "")
    if verdicts and all(v.kind == "?" for v in verdicts):
        first = verdicts[0]
        raise NothingReadable(f"no file could be read as a picture or a video ({first.status})", file=first.file)
    return summarise(verdicts)


def collect(inputs: Sequence[str | Path]) -> list[SetFile]:
    """The files to judge: each file given; a stimulus set's stills and videos; a folder's files."""
    if not inputs:
        raise UserError("give the pictures or videos to judge, or a stimulus set's folder")
    out: list[SetFile] = []
    for given in inputs:
        path = Path(given)
        if path.is_dir():
            if (path / "manifest.csv").is_file():
                out.extend(read_set(path))
            else:
                inside = sorted(p for p in path.iterdir() if p.is_file() and not p.name.startswith("."))
                if not inside:
                    raise UserError("the folder holds no files to judge", file=path)
                out.extend(SetFile(p, "", Intended()) for p in inside)
        else:
            out.append(SetFile(path, "", Intended()))
    return out


def _by_name(table: dict[Path, Intended], path: Path) -> Intended | None:
    matches = [meant for where, meant in table.items() if where.name == path.name]
    return matches[0] if len(matches) == 1 else None


def _lips(meant: Intended, path: Path) -> LipTrack | None:
    """The engine's intended lip gap for a video: its landmarks table, or its tracks on the
    default head (a set made on another head names no landmarks table: its lips are not compared)."""
    if meant.landmarks is not None:
        return read_landmarks_track(meant.landmarks)
    if meant.tracks is not None and meant.identity == "default head" and path.suffix.lower() == ".mp4":
        from engine.formats.model_files import load_model
        from engine.timeline.tracks import read_tracks_csv

        head = load_model()
        tracks = read_tracks_csv(meant.tracks, head)
        return lip_track(head, tracks.times, tracks.sample(tracks.times))
    return None
