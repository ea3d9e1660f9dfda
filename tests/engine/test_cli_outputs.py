"""Where verbs write, and how they name a number they refuse (issue 30).

``-o`` must name a file: ``identity -o /dev/null`` wrote ``/dev/null.xml`` and
``/dev/null.h5``, a folder became ``folder.xml`` beside it, and a named pipe
was replaced by a file. A value of 401 digits (``float`` makes it ``inf``) was
refused with a message that did not say what was wrong, or printed all 401
digits, or (as a whole number) was an ``OverflowError``.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import pytest

from engine.cli import common, main
from engine.identity import Identity, IdentityError
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error

DIGITS = "9" * 401


def one_error(capsys, *args) -> str:
    """Run the verb in this process: status 2 and exactly one ``error:`` line; returns it."""
    status = main([str(a) for a in args])
    err = capsys.readouterr().err
    assert status == 2, err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


# -- -o names a file -----------------------------------------------------------------------------------------

def test_identity_to_dev_null_is_refused_and_writes_nothing_beside_it():
    beside = [Path("/dev/null.xml"), Path("/dev/null.h5")]
    there = [p.exists() for p in beside]
    try:
        line = assert_user_error(run_in_process("identity", "--set", "age=40", "-o", os.devnull))
        assert line == "error: /dev/null: the model must be a file, not a device or a pipe", line
        assert [p.exists() for p in beside] == there
    finally:                        # the command before the fix wrote these: leave /dev as it was
        for path, was in zip(beside, there, strict=True):
            if path.exists() and not was:
                path.unlink()


def test_a_folder_as_a_model_output_is_refused(tmp_path, capsys):
    folder = tmp_path / "people"
    folder.mkdir()
    assert "must be a file, not a folder" in one_error(capsys, "identity", "-o", folder)
    assert not (tmp_path / "people.xml").exists()
    assert "must be a file name, not a folder" in one_error(capsys, "identity", "-o", f"{tmp_path}/anna/")


@pytest.mark.parametrize("verb", [
    ("identity", "-o"),
    ("pose", "-o"),
    ("mocap", "import", "missing.tsv", "-o"),
    ("fit-photos", "--front", "missing.jpg", "--landmarks", "missing.json", "-o"),
])
def test_a_named_pipe_as_output_is_refused_before_any_work(tmp_path, capsys, verb):
    suffix = {"identity": ".xml", "pose": ".npz", "mocap": ".h5", "fit-photos": ".xml"}[verb[0]]
    pipe = tmp_path / f"out{suffix}"
    os.mkfifo(pipe)
    line = one_error(capsys, *verb, pipe)
    assert line.startswith(f"error: {pipe}: the ") and line.endswith(" must be a file, not a device or a pipe"), line
    assert not pipe.is_file()                                     # still the pipe, not replaced by a file


def test_a_regular_file_or_a_new_name_is_a_good_output(tmp_path):
    existing = tmp_path / "old.csv"
    existing.write_text("x")
    assert common.output_file(existing) == existing
    assert common.output_file(tmp_path / "new" / "file.csv") == tmp_path / "new" / "file.csv"


# -- numbers of 401 digits -----------------------------------------------------------------------------------

def test_an_identity_value_of_401_digits_says_what_is_wrong(tmp_path, capsys):
    line = one_error(capsys, "identity", "--set", f"age={DIGITS}", "-o", tmp_path / "p.xml")
    assert "age: the value must be a finite number, not '9999" in line and "(401 characters)" in line, line
    assert DIGITS not in line


@pytest.mark.parametrize("value", [10**401, DIGITS, float("inf"), float("nan")])
def test_an_identity_of_a_value_no_float_holds_is_an_identity_error(value):
    with pytest.raises(IdentityError, match=r"identity parameter 'age' must be a finite number, not "):
        Identity({"age": value})


@pytest.mark.parametrize(("args", "words"), [
    (("render", "--set", f"jaw_open={DIGITS}", "-o", "x.png"), "jaw_open: the value must be a finite number"),
    (("tracks", "x.xml", "--fps", "1e999", "-o", "x.csv"), "'1e999' must be a finite positive number"),
    (("tracks", "x.xml", "--fps", DIGITS, "-o", "x.csv"), "(401 characters) must be a finite positive number"),
    (("mocap", "import", "x.tsv", "--max-gap", "1e999", "-o", "x.h5"), "must be a finite number, 0 or more"),
    (("mocap", "apply", "a.h5", "--range=-1e999,1e999", "-o", "x.xml"), "MIN and MAX must be finite numbers"),
])
def test_an_option_of_a_value_no_float_holds_says_so_briefly(tmp_path, capsys, args, words):
    line = one_error(capsys, *args)
    assert words in line and DIGITS not in line and len(line) < 200, line


def test_a_whole_number_of_too_many_digits_says_so():
    with pytest.raises(argparse.ArgumentTypeError, match=r"\(5000 characters\) is not a whole number \(it has "
                                                         r"more digits"):
        common.positive_int("9" * 5000)
    with pytest.raises(argparse.ArgumentTypeError, match=r"^x: the value must be a finite number, not 'nan'$"):
        common.setting("x=nan")
