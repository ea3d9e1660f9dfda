"""The files of a built study for each place it runs: a folder (and a lab computer), JATOS, Pavlovia, Cognition.run.

Every layout holds the same experiment (``study.js`` and ``plugin-ap-study.js``, jsPsych 8.3.0, the study's
trials in ``study-data.js``); they differ in the page and in where the files are:

================  =====================================================================================
folder            ``STUDY/index.html`` beside everything (open it, or serve the folder; ``run-lab.py``
                  serves it on a lab computer and saves each participant's CSV in ``data/``)
JATOS             ``hosts/jatos/NAME.jzip``: a JATOS study archive (one folder of study assets, ``NAME/``,
                  and its ``NAME.jas``), imported with JATOS's *Import study*; the page loads ``jatos.js``
Pavlovia          ``hosts/pavlovia/``: the files of the project's repository, ``index.html`` at its root;
                  Pavlovia's jsPsych plugin goes in ``lib/vendors/`` (we do not ship it)
Cognition.run     ``hosts/cognition/task.js`` (pasted as the task's code: our plugins, the trials and the
                  experiment in one script) and ``hosts/cognition/stimuli/`` (uploaded as the task's
                  stimuli: every file flat, named as the script names it)
================  =====================================================================================
"""

from __future__ import annotations

import json
import uuid
from importlib import resources
from pathlib import Path, PurePosixPath
from typing import Any

__all__ = ["JAS_VERSION", "JATOS_INVALID_DIRS", "PAVLOVIA_PLUGIN", "asset_text", "cognition_files", "jas_document",
           "jatos_dir_name", "page", "study_data_js", "vendored_jspsych"]

PAVLOVIA_PLUGIN = "jspsych-7-pavlovia-2022.1.1.js"
"""Pavlovia's jsPsych plugin (MIT, Open Science Tools), which its instructions put in ``lib/vendors/``."""
JAS_VERSION = "3"
JATOS_INVALID_DIRS = ("jatos", "publix", "public", "assets", "study_assets_root", "study_assets")
"""Study asset folder names JATOS refuses (its StudyProperties.INVALID_DIR_NAMES)."""
_NAMESPACE = uuid.UUID("6b1d3c52-7f0e-4f1a-9d61-5a8c3e2b9f40")
Files = dict[str, "bytes | Path"]
"""Path in the layout → its bytes, or the file to copy."""


def asset_text(name: str) -> str:
    return (resources.files("engine.web") / "study" / name).read_text(encoding="utf-8")


def vendored_jspsych() -> Files:
    """jsPsych as the package holds it (``engine/web/vendor/jspsych``, its README left out), under ``jspsych/``."""
    found: Files = {}

    def walk(folder: Any, prefix: str) -> None:
        for entry in sorted(folder.iterdir(), key=lambda e: e.name):
            if entry.is_dir():
                walk(entry, f"{prefix}{entry.name}/")
            elif f"{prefix}{entry.name}" != "jspsych/README.md":
                found[f"{prefix}{entry.name}"] = entry.read_bytes()

    walk(resources.files("engine.web") / "vendor" / "jspsych", "jspsych/")
    return found


def page(document: dict[str, Any], host: str) -> bytes:
    """The experiment's ``index.html`` for ``host`` (the live player, live/player.js, is one ES module with the
    three.js it uses: the page needs no import map)."""
    from html import escape

    scripts = {"jatos": '<script src="jatos.js"></script>\n',
               "pavlovia": f'<script src="lib/vendors/{PAVLOVIA_PLUGIN}"></script>\n'}.get(host, "")
    text = (asset_text("index.html").replace("{{TITLE}}", escape(document["title"]))
            .replace("{{LANG}}", "en").replace("{{HOST_SCRIPTS}}", scripts)
            .replace("{{HOST}}", host))
    return text.encode("utf-8")


def study_data_js(document: dict[str, Any]) -> bytes:
    """``window.AP_STUDY = {…};`` (a classic script, so that the page works from a folder opened as a file)."""
    text = json.dumps(document, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/")
    return f"window.AP_STUDY = {text};\n".encode()


def jatos_dir_name(name: str) -> str:
    return f"{name}-study" if name.lower() in JATOS_INVALID_DIRS else name


def jas_document(document: dict[str, Any]) -> dict[str, Any]:
    """The JATOS study description (``.jas``, version 3) of a study whose assets are ``jatos_dir_name(name)/``.

    Its UUIDs come from the study's name, so a study built again and imported again replaces the one in JATOS
    (JATOS asks first)."""
    name = document["name"]
    title = document["title"].replace("<", "(").replace(">", ")")[:255] or name

    def ident(part: str) -> str:
        return str(uuid.uuid5(_NAMESPACE, f"{name}/{part}"))

    return {"version": JAS_VERSION, "data": {
        "uuid": ident("study"), "title": title,
        "description": f"Artificial Person rating study '{name}' (study_id {document['study_id']})",
        "groupStudy": False, "linearStudy": False, "allowPreview": False, "dirName": jatos_dir_name(name),
        "comments": "Built by artificial-person study; results: Export Results → Data only, then "
                    "artificial-person study-analyse.", "jsonData": None, "endRedirectUrl": None,
        "studyEntryMsg": None,
        "componentList": [{"uuid": ident("component"), "title": "Experiment", "htmlFilePath": "index.html",
                           "reloadable": False, "active": True, "comments": "", "jsonData": None}],
        "batchList": [{"uuid": ident("batch"), "title": "Default", "active": True, "maxActiveMembers": None,
                       "maxTotalMembers": None, "maxTotalWorkers": None,
                       "allowedWorkerTypes": ["Jatos", "PersonalSingle", "PersonalMultiple", "GeneralSingle",
                                              "GeneralMultiple"], "comments": None, "jsonData": None}]}}


def cognition_files(document: dict[str, Any], sources: dict[str, Path]) -> Files:
    """``task.js`` and the flat ``stimuli/``: every file the trials name, renamed to one flat name each."""
    flat = json.loads(json.dumps(document))
    names: dict[str, str] = {}
    for trial in flat["trials"]:
        if trial["media"] == "live":
            continue
        given = trial["file"]
        if given not in names:
            path = PurePosixPath(given)
            names[given] = path.name if path.parts[0] == "stimuli" else f"{path.parts[0]}-{path.name}"
        trial["file"] = names[given]
    if len(set(names.values())) != len(names):
        raise ValueError("two stimulus files have the same flat name")
    script = "\n".join([
        "// Cognition.run task code: an Artificial Person rating study built by `artificial-person study` "
        f"(study '{document['name']}', study_id {document['study_id']}).",
        "// Paste all of this as the task's code; upload every file of the stimuli/ folder beside it as the",
        "// task's stimuli. jsPsych 7 or 8 (the task's setting) runs it; Cognition keeps each trial's data.",
        asset_text("plugin-ap-study.js"),
        'window.AP_HOST = "cognition"; window.AP_BASE = "";',
        study_data_js(flat).decode("utf-8"),
        asset_text("study.js"),
    ])
    files: Files = {"task.js": script.encode("utf-8")}
    for given, flat_name in names.items():
        files[f"stimuli/{flat_name}"] = sources[given]
    return files
