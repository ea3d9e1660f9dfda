"""``artificial-person study DESIGN.toml -o STUDY/``: a self-contained jsPsych experiment from a study design.

The set is made first when the design names its design (``engine.stimuli``), read from its manifest
(every file checked against its SHA-256), crossed with the presentation conditions, joined by the human
comparison, and written with jsPsych, our plugins and one page per host (:mod:`engine.study.hosts`). The
live player's site is ``web-export --stimuli``'s (``engine.web.stimuli_site``). Every file is written by
:func:`engine.formats.atomic.atomic_files`, all under one journal.
"""

from __future__ import annotations

import io
import json
import shutil
import zipfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from engine.errors import UserError
from engine.formats.atomic import atomic_files
from engine.study.columns import columns_for
from engine.study.compile import FORMAT, choices_for, study_document
from engine.study.design import StudyDesign, load_study_design
from engine.study.hosts import (
    Files,
    asset_text,
    cognition_files,
    jas_document,
    jatos_dir_name,
    page,
    study_data_js,
    vendored_jspsych,
)
from engine.study.stimuli_list import TrialSpec, human_specs, read_set, set_specs

__all__ = ["STUDY_JSON", "BuiltStudy", "build_study", "check_study_folder"]

STUDY_JSON = "study.json"
_OWN = ("index.html", "study.js", "study-data.js", "plugin-ap-study.js", "run-lab.py", "HOSTS.md", STUDY_JSON)
_OWN_FOLDERS = ("jspsych", "stimuli", "human", "live", "hosts", "data", "set")


@dataclass
class BuiltStudy:
    folder: Path
    document: dict[str, Any]
    set_folder: Path
    files: int
    bytes: int
    made_set: bool


def check_study_folder(out: Path) -> None:
    """Refuse a file, or a folder holding anything but an earlier study (or the set made for one)."""
    if out.exists() and not out.is_dir():
        raise UserError("the study must be a folder, and this is a file", file=out)
    if not out.is_dir():
        return
    entries = [e.name for e in out.iterdir()]
    if not entries or entries == ["set"]:
        return
    marker = out / STUDY_JSON
    try:
        earlier = json.loads(marker.read_text(encoding="utf-8")).get("format") == FORMAT
    except (OSError, ValueError, AttributeError):
        earlier = False
    if not earlier:
        raise UserError("the folder is not empty and holds no earlier study: choose a new or empty folder", file=out)


def build_study(design_path: str | Path, out: str | Path, workers: int | None = None,
                progress: Callable[[str], None] | None = None) -> BuiltStudy:
    """Build the study of ``design_path`` into the folder ``out`` (see the module notes)."""
    say = progress or (lambda _text: None)
    design = load_study_design(design_path)
    out = Path(out)
    check_study_folder(out)
    set_folder, made = _the_set(design, out, workers, say)
    listing = read_set(set_folder)
    specs = set_specs(listing, design.presentations, design.dynamic, design.emotion_factor)
    if design.human_table is not None:
        specs += human_specs(design.human_table, design.presentations)
    choices = choices_for(design, specs)
    pages = {key: getattr(design.pages, key) for key in ("consent", "instructions", "practice_end", "debrief",
                                                        "declined", "agree", "decline")}
    live = design.dynamic == "live" and "dynamic" in design.presentations
    document = study_document(design, specs, choices, listing.manifest_sha256, set_folder.name, pages, live)
    columns, levels = columns_for([s.name for s in design.scales], document["factors"])
    document["columns"], document["level_columns"] = columns, levels
    out.mkdir(parents=True, exist_ok=True)
    if live:
        say("writing the live player's site (live/)")
        _write_live(design, set_folder, out / "live")
    say("writing the experiment")
    files = _layouts(design, document, specs, out)
    total = _write(out, files)
    _remove_stale(out, files)
    return BuiltStudy(out, document, set_folder, len(files), total, made)


def _the_set(design: StudyDesign, out: Path, workers: int | None, say: Callable[[str], None]) -> tuple[Path, bool]:
    if design.set_design is None:
        assert design.set_folder is not None
        return design.set_folder, False
    from engine.stimuli.design import load_design
    from engine.stimuli.run import make_set

    set_design = load_design(design.set_design)
    kinds = set(set_design.output.kinds)
    needed = {"static": {"png"}, "dynamic": {"tracks", "wav"} if design.dynamic == "live" else {"mp4"}}
    for presentation in design.presentations:
        missing = needed[presentation] - kinds - ({"mp4"} if "silent-mp4" in kinds else set())
        if missing:
            raise UserError(f"the {presentation} condition needs {', '.join(sorted(missing))} among the set's "
                            "[output] kinds", file=set_design.path, line=None)
    folder = design.set_folder or out / "set"
    resume = (folder / "manifest.csv").exists() or (folder / ".records").is_dir()
    if resume:
        from engine.stimuli.manifest import PROVENANCE

        try:
            made_from = json.loads((folder / PROVENANCE).read_text(encoding="utf-8"))["design"]["sha256"]
        except (OSError, ValueError, KeyError, TypeError):
            made_from = None
        if made_from is not None and made_from != set_design.sha256:
            raise UserError("this set was made from another design (its provenance.json names another SHA-256): "
                            "remove it, or name another set folder", file=folder)
    say(f"making the stimulus set {folder} from {design.set_design}")
    result = make_set(set_design, folder, workers=workers, resume=resume)
    if result.failed:
        raise UserError(f"stimuli {', '.join(result.failed)} miss their specification (see check.csv)",
                        file=folder / "check.csv")
    return folder, result.made > 0


def _write_live(design: StudyDesign, set_folder: Path, site: Path) -> None:
    from engine.web.stimuli_site import write_stimuli_site

    if design.set_design is not None:
        from engine.stimuli.design import load_design
        from engine.stimuli.set_heads import DesignHeads

        write_stimuli_site(None, set_folder, site, heads=DesignHeads(load_design(design.set_design), set_folder))
    else:
        from engine.formats.model_files import load_model

        write_stimuli_site(load_model(None), set_folder, site)


def _layouts(design: StudyDesign, document: dict[str, Any], specs: list[TrialSpec], out: Path) -> Files:
    sources: dict[str, Path] = {s.file: s.source_path for s in specs if s.source_path is not None}
    shared: Files = {"study-data.js": study_data_js(document), "study.js": asset_text("study.js").encode("utf-8"),
                     "plugin-ap-study.js": asset_text("plugin-ap-study.js").encode("utf-8"),
                     **vendored_jspsych(), **sources}
    live = _live_files(out / "live") if document["live"] else {}
    files: Files = {"index.html": page(document, "folder"), **shared,
                    STUDY_JSON: (json.dumps(document, indent=1, ensure_ascii=False) + "\n").encode("utf-8"),
                    "run-lab.py": asset_text("run-lab.py").encode("utf-8"),
                    "HOSTS.md": _hosts_text(document, design.hosts).encode("utf-8")}
    if "jatos" in design.hosts:
        files[f"hosts/jatos/{design.name}.jzip"] = _jzip(document, {"index.html": page(document, "jatos"), **shared,
                                                                    **live})
    if "pavlovia" in design.hosts:
        for name, content in {"index.html": page(document, "pavlovia"), **shared, **live}.items():
            files[f"hosts/pavlovia/{name}"] = content
        files["hosts/pavlovia/lib/vendors/README.md"] = _pavlovia_vendors().encode("utf-8")
    if "cognition" in design.hosts:
        for name, content in cognition_files(document, sources).items():
            files[f"hosts/cognition/{name}"] = content
    return files


def _live_files(site: Path) -> Files:
    return {f"live/{p.relative_to(site).as_posix()}": p for p in sorted(site.rglob("*"))
            if p.is_file() and not p.name.startswith(".")}


def _jzip(document: dict[str, Any], files: Files) -> bytes:
    """A JATOS study archive: the study assets in one folder and the ``.jas`` beside it (what JATOS imports)."""
    folder = jatos_dir_name(document["name"])
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(f"{folder}/", b"")
        for name, content in sorted(files.items()):
            data = content if isinstance(content, bytes) else content.read_bytes()
            archive.writestr(f"{folder}/{name}", data, zipfile.ZIP_STORED if name.endswith((".mp4", ".webm", ".png",
                                                                                            ".jpg", ".jpeg"))
                             else zipfile.ZIP_DEFLATED)
        archive.writestr(f"{document['name']}.jas", json.dumps(jas_document(document), indent=2))
    return buffer.getvalue()


def _write(out: Path, files: Files) -> int:
    targets = {name: _target(out, name) for name in files}
    total = 0
    with atomic_files(targets.values()) as temporary:
        for name, target in targets.items():
            content = files[name]
            if isinstance(content, bytes):
                temporary[target].write_bytes(content)
                total += len(content)
            else:
                shutil.copyfile(content, temporary[target])
                total += content.stat().st_size
    return total


def _target(out: Path, name: str) -> Path:
    folder = out
    for part in Path(name).parts[:-1]:
        folder = folder / part
        if folder.is_symlink():
            raise UserError("is a symbolic link: the study's folders must be its own (remove the link)", file=folder)
        if not folder.exists():
            folder.mkdir()
        elif not folder.is_dir():
            raise UserError("is a file where the study needs a folder", file=folder)
    return folder / Path(name).name


def _remove_stale(out: Path, files: Files) -> None:
    """Files an earlier build of this study left that this one does not write (a stimulus dropped, a host)."""
    for folder in ("stimuli", "human", "hosts"):
        top = out / folder
        if not top.is_dir() or top.is_symlink():
            continue
        for path in sorted(top.rglob("*"), reverse=True):
            relative = path.relative_to(out).as_posix()
            if path.is_file() and not path.name.startswith(".") and relative not in files:
                path.unlink()
            elif path.is_dir() and not any(path.iterdir()):
                path.rmdir()


def _pavlovia_vendors() -> str:
    from engine.study.hosts import PAVLOVIA_PLUGIN

    return (f"# lib/vendors/\n\nPut Pavlovia's jsPsych plugin here as `{PAVLOVIA_PLUGIN}` (MIT licence, Open "
            "Science Tools; the file Pavlovia's jsPsych instructions link to). index.html loads it from here; "
            "without it the study says so and does not start. The toolkit does not ship it: it is Pavlovia's, "
            "and it talks to Pavlovia's server.\n")


def _hosts_text(document: dict[str, Any], hosts: tuple[str, ...]) -> str:
    name = document["name"]
    parts = [f"# Running the study '{name}' (study_id {document['study_id']})\n",
             "Every way of running it below runs the same experiment and writes the same CSV, one row per "
             "trial; give the CSVs to `artificial-person study-analyse`.\n",
             "## From this folder\n",
             "* Open `index.html` in a browser (double-click): it asks for the participant's number; at the end "
             "the browser downloads `" + name + "_PARTICIPANT.csv`." +
             (" (The live player needs the folder served: use run-lab.py.)" if document["live"] else ""),
             "* On a lab computer: `python3 run-lab.py` (Python 3.8+, nothing else) serves this folder on "
             "127.0.0.1 and opens the study; each participant's data are written to `data/`. "
             "`--participant N` skips the question; `--no-browser` only serves.",
             "* Any web server: the folder is plain files; `index.html?participant=N` names the participant.\n"]
    if "jatos" in hosts:
        parts += ["## JATOS\n",
                  f"Import `hosts/jatos/{name}.jzip` (JATOS: *Import study*). It holds the study assets "
                  f"(`{jatos_dir_name(name)}/`, whose component page is `index.html`, loading JATOS's `jatos.js`) "
                  "and the study's `.jas`. The data of each run are its result data (*Results → Export results → "
                  "Data only*: a text file of every run's CSV, which study-analyse reads as it is) and a result file "
                  f"`{name}_PARTICIPANT.csv`. The participant is `?participant=` of the study link, else JATOS's "
                  "study result id.\n"]
    if "pavlovia" in hosts:
        parts += ["## Pavlovia\n",
                  "Push the files of `hosts/pavlovia/` as the project's repository (index.html at its root), put "
                  "Pavlovia's jsPsych plugin in `lib/vendors/` (see the README there) and set the project to "
                  "*running* with CSV results. Pavlovia saves each session's CSV in the project's `data/` folder. "
                  "The participant is `?participant=` of the link, else a random code.\n"]
    if "cognition" in hosts:
        parts += ["## Cognition.run\n",
                  "Make a new task (jsPsych 7 or 8), paste `hosts/cognition/task.js` as its code and upload every "
                  "file of `hosts/cognition/stimuli/` as its stimuli (the script names them without a folder). "
                  "Cognition keeps every trial's data; download its CSV and give it to study-analyse (the rows "
                  "that are not trials are passed over).\n"]
    return "\n".join(parts)
