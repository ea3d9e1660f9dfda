"""Export configuration (engine.outputs.configuration_export) and its verb ``artificial-person export-config``.

The folder holds the model, the library files whose commands fit it (user
folders after the shipped one, overrides respected) and a README; a failure
writes nothing.
"""

from __future__ import annotations

import numpy as np
import pytest

import engine.outputs.configuration_export as configuration_export
from engine import load_model, save_model
from engine.commands import load_library
from engine.errors import LibraryError, UserError
from engine.outputs.configuration_export import README_NAME, export_configuration
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.synthetic import random_model

MY_JAW = """# A user's own JawOpen: wider.
$command = JawOpen
$mandatory = at
$optional = amplitude=100, onset=100, apex=300, offset=100
jaw_open = 1
$proc = attack-hold-release
"""
ELSEWHERE = """$command = Elsewhere
$mandatory = at
no_such_parameter = 0,0; 100,1
$proc = once
"""


@pytest.fixture
def mine(tmp_path):
    folder = tmp_path / "my-commands"
    folder.mkdir()
    (folder / "WideJaw.lib").write_text(MY_JAW)
    (folder / "Elsewhere.lib").write_text(ELSEWHERE)
    return folder


def test_the_folder_holds_the_model_the_fitting_library_files_and_a_readme(head, mine, tmp_path):
    target = tmp_path / "for-anna"
    summary = export_configuration(head, target, [mine], source="head.xml")
    assert summary.folder == target and summary.model.as_posix() == "model/default-head.xml"
    assert summary.library_args() == ["-L", "library", "-L", "library-user-1"]
    exported = load_model(target / summary.model)
    np.testing.assert_array_equal(exported.vertices, head.vertices)
    assert exported.parameters.names == head.parameters.names
    shipped = sorted(p.name for p in (target / "library").iterdir())
    assert "JawOpen.lib" not in shipped and {"Happy.lib", "HeadNod.lib"} <= set(shipped)   # overridden by mine
    assert sorted(p.name for p in (target / "library-user-1").iterdir()) == ["WideJaw.lib"]
    assert [f.as_posix() for f in summary.library_files if f.parent.name == "library-user-1"] == \
        ["library-user-1/WideJaw.lib"]
    assert len(summary.unfit_commands) == 1 and "Elsewhere.lib" in summary.unfit_commands[0]
    readme = (target / README_NAME).read_text()
    assert "from head.xml" in readme and "-L library -L library-user-1" in readme and "Elsewhere" in readme
    library = load_library([target / "library", target / "library-user-1"], shipped=False)
    assert library["JawOpen"].curves[0].name == "jaw_open" and "library-user-1" in library["JawOpen"].file
    assert all(not p.name.startswith(".") for p in target.rglob("*"))          # no temporary file left


def test_a_model_without_fitting_commands_exports_alone(tmp_path):
    model = random_model(np.random.default_rng(2), n_vertices=12, n_parameters=3, depth=2)
    model.name = "tiny.v2"
    summary = export_configuration(model, tmp_path / "out")
    assert summary.model.as_posix() == "model/tiny.v2.xml" and summary.library_files == []
    assert summary.library_args() == [] and len(summary.unfit_commands) == len(load_library().names())
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [README_NAME, "model"]


def test_the_model_files_take_the_stem_they_are_given(tmp_path):
    """A copy of a model saved as painted.xml still carries the model's name inside: the export is
    named after the file the user knows, and that name is made safe for a file name."""
    model = random_model(np.random.default_rng(3), n_vertices=12, n_parameters=3, depth=2)
    model.name = "default-head"
    summary = export_configuration(model, tmp_path / "out", stem="painted")
    assert summary.model.as_posix() == "model/painted.xml"
    assert sorted(p.name for p in (tmp_path / "out" / "model").iterdir()) == ["painted.h5", "painted.xml"]
    assert load_model(tmp_path / "out" / "model" / "painted.xml").name == "default-head"
    assert "model/painted.xml" in (tmp_path / "out" / README_NAME).read_text()
    assert export_configuration(model, tmp_path / "odd", stem="my head/v2").model.as_posix() == "model/my_head_v2.xml"
    assert export_configuration(model, tmp_path / "none", stem="..").model.as_posix() == "model/model.xml"


def test_a_broken_library_file_stops_the_export_before_anything_is_written(head, tmp_path):
    broken = tmp_path / "broken"
    broken.mkdir()
    (broken / "Bad.lib").write_text("$command = Bad\njaw_open = 1\n$proc = no-such-procedure\n")
    with pytest.raises(LibraryError) as caught:
        export_configuration(head, tmp_path / "out", [broken])
    assert str(caught.value).startswith(f"{broken / 'Bad.lib'}:3:")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("failure", [OSError(28, "No space left on device"), KeyboardInterrupt()])
def test_a_failure_half_way_leaves_the_folder_as_it_was(head, tmp_path, monkeypatch, failure):
    target = tmp_path / "out"
    save_model(head, target / "model" / "default-head.xml")
    (target / README_NAME).write_text("the old readme\n")
    before = {p.relative_to(target): p.read_bytes() for p in target.rglob("*") if p.is_file()}

    def fail(*_):
        raise failure

    monkeypatch.setattr(configuration_export, "_copy", fail)
    with pytest.raises(UserError if isinstance(failure, OSError) else KeyboardInterrupt):
        export_configuration(head, target)
    after = {p.relative_to(target): p.read_bytes() for p in target.rglob("*") if p.is_file()}
    assert after == before
    assert not (target / "library").exists()                      # the folder it made for the copies is gone


def test_a_file_where_the_folder_should_be_is_a_user_error(head, tmp_path):
    (tmp_path / "taken").write_text("a file")
    with pytest.raises(UserError, match="cannot create the folder"):
        export_configuration(head, tmp_path / "taken")


# -- the verb --------------------------------------------------------------------------------------

def test_export_config_verb_writes_the_folder(mine, tmp_path):
    result = run("export-config", "-L", mine, "-o", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert "model/default-head.xml" in result.stdout and "1 commands left out" in result.stdout
    assert (tmp_path / "out" / "library-user-1" / "WideJaw.lib").read_text() == MY_JAW
    assert load_model(tmp_path / "out" / "model" / "default-head.xml").n_vertices > 0


def test_export_config_verb_names_the_files_after_the_model_file_given(tmp_path):
    model = random_model(np.random.default_rng(4), n_vertices=12, n_parameters=3, depth=2)
    model.name = "default-head"                       # a painted copy of the head keeps the head's name
    save_model(model, tmp_path / "painted.xml")
    result = run("export-config", "-m", tmp_path / "painted.xml", "-o", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert "model/painted.xml" in result.stdout
    assert sorted(p.name for p in (tmp_path / "out" / "model").iterdir()) == ["painted.h5", "painted.xml"]


def test_export_config_verb_reports_a_bad_library_file_in_one_line(tmp_path):
    bad = tmp_path / "Bad.lib"
    bad.write_text("$command = Bad\njaw_open = 1\n$proc = no-such-procedure\n")
    line = assert_user_error(run_in_process("export-config", "-L", bad, "-o", tmp_path / "out"))
    assert line.startswith(f"error: {bad}:3:") and "no-such-procedure" in line
    assert not (tmp_path / "out").exists()
    assert assert_user_error(run_in_process("export-config")).startswith("error: ")            # -o is required
