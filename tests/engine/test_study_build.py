"""``artificial-person study``: the folder each host expects, built from a real set; and every design it refuses.

The layouts are checked against what each host reads: JATOS's importer (one folder of study assets and one
``.jas`` at the archive's root; version 3; a title without HTML; a folder name JATOS takes; a component page
that matches its path pattern and is in the folder — JATOS's ImportExportService, StudyProperties and
ComponentProperties), Pavlovia (``index.html`` at the repository's root, its plugin in ``lib/vendors/``
loaded after jsPsych), Cognition.run (one script for the task's code, every file it names flat among the
stimuli). Bad input ends with one line naming the file and the line, status 2.
"""

from __future__ import annotations

import json
import re
import shutil
import tomllib
import uuid
import zipfile
from pathlib import Path

import pytest

from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.test_study_helpers import STUDY_DESIGN, make_study_inputs

ROOT = Path(__file__).resolve().parents[2]
ASSETS = ROOT / "engine" / "web" / "study"
JATOS_PATH = re.compile(r"^[\w\d_-][\w\d/_-]*\.[\w\d_-]+$")          # ComponentProperties' htmlFilePath pattern
JATOS_ILLEGAL = re.compile(r"[\s\n\r\t\f*?\"\\\0/,`<>|:~!§$%&^°]")     # IOUtils.REGEX_ILLEGAL_IN_FILENAME


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("inputs")
    make_study_inputs(folder)
    return folder


@pytest.fixture(scope="module")
def study(inputs):
    made = run("study", inputs / "study.toml", "-o", inputs / "study")
    assert made.returncode == 0, made.stderr
    assert "study 'tiny'" in made.stdout and "8 trials per participant" in made.stdout
    return inputs / "study"


def _design(folder: Path, text: str) -> Path:
    path = folder / "study.toml"
    path.write_text(text)
    return path


def test_the_folder_holds_the_experiment_and_every_stimulus(study, inputs):
    document = json.loads((study / "study.json").read_text())
    for name in ("index.html", "study.js", "study-data.js", "plugin-ap-study.js", "run-lab.py", "HOSTS.md",
                 "jspsych/dist/index.browser.min.js", "jspsych/css/jspsych.css", "jspsych/LICENSE"):
        assert (study / name).is_file(), name
    assert not (study / "jspsych" / "README.md").exists()
    for trial in document["trials"]:
        assert (study / trial["file"]).is_file(), trial["file"]
    assert (study / "stimuli" / "0001.png").read_bytes() == (inputs / "set" / "0001.png").read_bytes()
    assert {t["stimulus"] for t in document["trials"] if t["source"] == "human"} == {"human-001", "human-002"}
    data = (study / "study-data.js").read_text()
    assert data.startswith("window.AP_STUDY = ") and json.loads(data[len("window.AP_STUDY = "):-2]) == document
    page = (study / "index.html").read_text()
    assert 'window.AP_HOST = "folder"' in page and "{{" not in page and "importmap" not in page
    assert [c["value"] for c in document["choices"]] == ["happy", "sad", "neutral", "other"]
    assert document["procedure"]["orders"] == [["static", "dynamic"], ["dynamic", "static"]]
    assert "<h2>Consent</h2>" in document["pages"]["consent"] and "<b>at any time</b>" in document["pages"]["consent"]


def test_nothing_the_experiment_loads_names_a_server():
    for path in [*ASSETS.glob("*.js"), ASSETS / "index.html"]:
        text = path.read_text()
        assert "http://" not in text and "https://" not in text, path


def test_the_assets_are_package_data():
    patterns = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["engine"]
    shipped = {path for pattern in patterns for path in (ROOT / "engine").glob(pattern) if path.is_file()}
    needed = {path for path in ASSETS.rglob("*") if path.is_file()}
    assert needed and needed <= shipped, sorted(str(p) for p in needed - shipped)


def test_the_jatos_archive_is_what_jatos_imports(study, tmp_path):
    with zipfile.ZipFile(study / "hosts" / "jatos" / "tiny.jzip") as archive:
        names = archive.namelist()
        archive.extractall(tmp_path)
    top = {name.split("/")[0] for name in names}
    folders = [p for p in tmp_path.iterdir() if p.is_dir()]
    studies = [p for p in tmp_path.iterdir() if p.suffix == ".jas"]
    assert top == {"tiny", "tiny.jas"} and len(folders) == 1 and len(studies) == 1
    jas = json.loads(studies[0].read_text())
    assert jas["version"] == "3"
    data = jas["data"]
    assert data["dirName"] == folders[0].name and not JATOS_ILLEGAL.search(data["dirName"])
    assert data["title"] and len(data["title"]) <= 255 and "<" not in data["title"]
    ids = [data["uuid"], data["componentList"][0]["uuid"], data["batchList"][0]["uuid"]]
    assert [str(uuid.UUID(x)) for x in ids] == ids and len(set(ids)) == 3
    component = data["componentList"][0]
    assert JATOS_PATH.match(component["htmlFilePath"]) and (folders[0] / component["htmlFilePath"]).is_file()
    page = (folders[0] / "index.html").read_text()
    assert '<script src="jatos.js"></script>' in page and 'window.AP_HOST = "jatos"' in page
    assert not (folders[0] / "run-lab.py").exists()
    document = json.loads((study / "study.json").read_text())
    assert all((folders[0] / trial["file"]).is_file() for trial in document["trials"])
    assert (folders[0] / "study-data.js").read_bytes() == (study / "study-data.js").read_bytes()


def test_the_pavlovia_repository_has_its_page_at_the_root(study):
    repo = study / "hosts" / "pavlovia"
    page = (repo / "index.html").read_text()
    plugin = page.index('src="lib/vendors/jspsych-7-pavlovia-2022.1.1.js"')
    assert page.index('src="jspsych/dist/index.browser.min.js"') < plugin < page.index('src="study.js"')
    assert 'window.AP_HOST = "pavlovia"' in page
    assert (repo / "lib" / "vendors" / "README.md").is_file()
    assert not (repo / "lib" / "vendors" / "jspsych-7-pavlovia-2022.1.1.js").exists()      # Pavlovia's, not ours
    for name in ("study.js", "plugin-ap-study.js", "study-data.js", "jspsych/dist/index.browser.min.js",
                 "stimuli/0002.mp4", "human/human-002-dynamic.mp4"):
        assert (repo / name).read_bytes() == (study / name).read_bytes(), name


def test_the_cognition_task_is_one_script_and_flat_stimuli(study):
    folder = study / "hosts" / "cognition"
    script = (folder / "task.js").read_text()
    assert "var jsPsychApStudyTrial" in script and 'window.AP_HOST = "cognition"' in script
    start = script.index("window.AP_STUDY = ") + len("window.AP_STUDY = ")
    document = json.loads(script[start:script.index(";\n", start)])
    assert document["study_id"] == json.loads((study / "study.json").read_text())["study_id"]
    files = {trial["file"] for trial in document["trials"]}
    assert all("/" not in name for name in files)
    assert files == {p.name for p in (folder / "stimuli").iterdir()}
    assert "http://" not in script and "https://" not in script


def test_building_again_replaces_the_study_and_drops_what_is_gone(study, inputs, tmp_path):
    copy = tmp_path / "study"
    shutil.copytree(study, copy)
    (copy / "stimuli" / "9999.png").write_bytes(b"left from an earlier build")
    made = run("study", inputs / "study.toml", "-o", copy)
    assert made.returncode == 0, made.stderr
    assert not (copy / "stimuli" / "9999.png").exists()
    assert (copy / "study.json").read_bytes() == (study / "study.json").read_bytes()


def test_a_folder_of_other_files_is_refused(inputs, tmp_path):
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "notes.txt").write_text("mine")
    line = assert_user_error(run_in_process("study", inputs / "study.toml", "-o", tmp_path / "out"))
    assert line == f"error: {tmp_path / 'out'}: the folder is not empty and holds no earlier study: choose a new " \
                   "or empty folder"


def _in(inputs: Path, tmp_path: Path, text: str) -> str:
    for name in ("set", "actors"):
        (tmp_path / name).symlink_to(inputs / name)
    for name in ("actors.csv", "consent.md"):
        shutil.copyfile(inputs / name, tmp_path / name)
    return assert_user_error(run_in_process("study", _design(tmp_path, text), "-o", tmp_path / "out"))


@pytest.mark.parametrize("changes", [
    (("seed = 2003", "seed = -1"), ":3: seed: must be a whole number from 0 to 4294967295"),
    (("seed = 2003", "seed = 2003\ncolour = 1"), ":4: colour: unknown key"),
    (("[procedure]", "[procedure]\nblocks = \"mood\""), ":12: blocks: must be one of none, presentation, source"),
    (("practice = 1", "practice = 1.5"), ":12: practice: must be a whole number from 0 to 50"),
    (("set = \"set\"", "set = \"nowhere\""), ":6: set: 'nowhere' holds no manifest.csv"),
    (("table = \"actors.csv\"", "table = \"actors.tsv\""), ":9: table: 'actors.tsv' is not a file"),
    (("consent = \"consent.md\"", "consent = \"gone.md\""), ":18: consent: 'gone.md' is not a file"),
    (("name = \"tiny\"", "name = \"my study\""), ":1: name: must be 1-64 letters"),
    (("[procedure]", "[identification]\nkeys = [\"1\", \"1\"]\n[procedure]"), ":12: keys: lists the same entry twice"),
    (("[procedure]", "[identification]\nchoices = [\"happy\", \"sad\"]\n[procedure]"),
     "stimuli show neutral, which [identification] choices does not offer"),
    (("[procedure]", "[[scales]]\nname = \"arousal\"\nmin = 1\nmax = 40\n[procedure]"),
     ":14: max: a scale has 2 to 11 points"),
    (("gap_ms = 100", "gap_ms = 100\ntasks = [\"identification\"]"), ("[pages]", "[[scales]]\nname = \"x\"\n[pages]"),
     "scales: scales are given but procedure.tasks has no \"rating\""),
    (("seed = 2003", "seed = 2003\n[output]\nhosts = [\"cognition\"]\n[conditions]\ndynamic = \"live\""),
     "hosts: cognition cannot show the live player"),
    (("seed = 2003", "seed = 2003 ="), ":3: not a TOML file"),
])
def test_a_design_that_cannot_be_built_is_one_line(inputs, tmp_path, changes):
    *edits, expected = changes
    text = STUDY_DESIGN
    for old, new in edits:
        assert old in text
        text = text.replace(old, new)
    line = _in(inputs, tmp_path, text)
    assert line.startswith(f"error: {tmp_path / 'study.toml'}") and expected in line, line
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("table, expected", [
    ("file,emotion\nactors/astronaut-happy.png,joyful?\n", ":2: emotion 'joyful?'"),
    ("file,mood\nactors/astronaut-happy.png,happy\n", ":1: the human table needs a 'emotion' column"),
    ("file,emotion\nactors/none.png,happy\n", ":2: 'actors/none.png' is not a file"),
    ("file,emotion,presentation\nactors/astronaut-happy.png,happy,dynamic\n", ":2: a dynamic stimulus must be a video"),
    ("file,emotion\nconsent.md,happy\n", ":2: 'consent.md': a picture"),
    ("file,emotion,id\nactors/astronaut-happy.png,happy,a\nactors/astronaut-happy.png,sad,a\n",
     ":3: a is listed twice as static"),
])
def test_a_bad_human_table_is_one_line_naming_its_line(inputs, tmp_path, table, expected):
    for name in ("set", "actors"):
        (tmp_path / name).symlink_to(inputs / name)
    shutil.copyfile(inputs / "consent.md", tmp_path / "consent.md")
    (tmp_path / "actors.csv").write_text(table)
    line = assert_user_error(run_in_process("study", _design(tmp_path, STUDY_DESIGN), "-o", tmp_path / "out"))
    assert line.startswith(f"error: {tmp_path / 'actors.csv'}") and expected in line, line


def test_a_set_changed_since_it_was_made_is_refused(inputs, tmp_path):
    shutil.copytree(inputs / "set", tmp_path / "set")
    (tmp_path / "actors").symlink_to(inputs / "actors")
    for name in ("actors.csv", "consent.md"):
        shutil.copyfile(inputs / name, tmp_path / name)
    (tmp_path / "set" / "0002.png").write_bytes((inputs / "set" / "0001.png").read_bytes())
    line = assert_user_error(run_in_process("study", _design(tmp_path, STUDY_DESIGN), "-o", tmp_path / "out"))
    assert line == f"error: {tmp_path / 'set' / 'manifest.csv'}:3: stimulus 0002: 0002.png has changed since the " \
                   "set was made (its SHA-256 is not the manifest's)"


def test_a_set_without_the_files_a_condition_needs_is_refused(inputs, tmp_path):
    shutil.copytree(inputs / "set", tmp_path / "set")
    manifest = tmp_path / "set" / "manifest.csv"
    rows = manifest.read_text().splitlines()
    header = rows[0].split(",")
    keep = [i for i, name in enumerate(header) if name not in ("file_mp4", "sha256_mp4")]
    manifest.write_text("\n".join(",".join(r.split(",")[i] for i in keep) for r in rows) + "\n")
    text = STUDY_DESIGN.replace("[human]\ntable = \"actors.csv\"\n", "").replace("consent = \"consent.md\"", "")
    line = assert_user_error(run_in_process("study", _design(tmp_path, text), "-o", tmp_path / "out"))
    assert line == f"error: {manifest}:1: the dynamic condition needs each stimulus's video: make the set with " \
                   "\"mp4\" among [output] kinds (or dynamic = \"live\" with tracks and wav)"


@pytest.mark.slow
def test_a_study_of_a_set_design_makes_the_set_first(tmp_path):
    (tmp_path / "faces.toml").write_text('[factors]\ntext = ["Moi."]\nexpression = ["Happy", "none"]\n'
                                         '[output]\nkinds = ["png"]\nsize = "160x120"\n')
    design = _design(tmp_path, '[stimuli]\ndesign = "faces.toml"\n[conditions]\npresentation = ["static"]\n'
                               '[procedure]\ntasks = ["identification"]\n')
    made = run("study", design, "-o", tmp_path / "study", "--workers", "1")
    assert made.returncode == 0, made.stderr
    assert (tmp_path / "study" / "set" / "manifest.csv").is_file() and "the set made in" in made.stdout
    document = json.loads((tmp_path / "study" / "study.json").read_text())
    assert [t["intended"] for t in document["trials"]] == ["happy", "neutral"] and document["scales"] == []
    again = run("study", design, "-o", tmp_path / "study", "--workers", "1")            # the set is kept
    assert again.returncode == 0 and "the set made in" not in again.stdout
    (tmp_path / "faces.toml").write_text("name = \"other\"\n" + (tmp_path / "faces.toml").read_text())
    line = assert_user_error(run_in_process("study", design, "-o", tmp_path / "study"))
    assert "this set was made from another design" in line
    design.write_text(design.read_text().replace('["static"]', '["static", "dynamic"]'))
    line = assert_user_error(run_in_process("study", design, "-o", tmp_path / "elsewhere"))
    assert line == f"error: {tmp_path / 'faces.toml'}: the dynamic condition needs mp4 among the set's [output] kinds"
