"""``translate``, ``tracks`` and ``library`` on the command line, as users run them."""

from __future__ import annotations

import csv

import pytest

from engine import load_model
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error

PAPER = '<commands>\n  <HeadNod at="1000" amplitude="60" count="2"/>\n</commands>\n'


@pytest.fixture
def script(tmp_path):
    path = tmp_path / "nod.xml"
    path.write_text(PAPER)
    return path


def test_translate_prints_the_paper_example(script):
    result = run_in_process("translate", script)
    assert result.returncode == 0, result.stderr
    assert '<activate parameter="head_nod" interp="linear" command="HeadNod" line="amplitude"' in result.stdout
    assert result.stdout.count("<key ") == 9
    assert '<key at="1416.5" value="-0.015"/>' in result.stdout


def test_translate_to_a_file_and_tracks_from_both_levels(script, tmp_path):
    low = tmp_path / "low.xml"
    assert run_in_process("translate", script, "-o", low).returncode == 0
    for source in (script, low):
        out = tmp_path / f"{source.stem}.csv"
        result = run_in_process("tracks", source, "--fps", "60", "-o", out)
        assert result.returncode == 0, result.stderr
        with out.open() as fh:
            rows = list(csv.reader(fh))
        assert rows[0][0] == "time_ms" and "head_nod" in rows[0] and len(rows[0]) == 1 + len(load_model().parameters)
        assert len(rows) == 1 + 121
        assert float(rows[-1][0]) == pytest.approx(2000)
    assert (tmp_path / "nod.csv").read_text() == (tmp_path / "low.csv").read_text()


def test_tracks_with_a_user_library_folder(tmp_path):
    folder = tmp_path / "lib"
    folder.mkdir()
    (folder / "smile.lib").write_text("$command = Yes\n$parameter = head_nod\n"
                                      "amplitude = 0,0; 100,0.2; 200,0\n")
    xml = tmp_path / "yes.xml"
    xml.write_text('<commands><Yes at="0"/></commands>')
    out = tmp_path / "yes.csv"
    assert run_in_process("tracks", xml, "-L", folder, "--fps", "10", "-o", out).returncode == 0
    rows = list(csv.reader(out.read_text().splitlines()))
    nod = rows[0].index("head_nod")
    assert [float(r[nod]) for r in rows[1:]] == pytest.approx([0, 0.2, 0])


@pytest.mark.parametrize("content, args, words", [
    ('<commands>\n<HeadNod at="0" cuont="2"/>\n</commands>', (), "x.xml:2: <HeadNod> has no argument 'cuont'"),
    ('<commands>\n<Smile at="0"/>\n</commands>', (), "x.xml:2: unknown command <Smile>"),
    ('<commands>\n<HeadNod/>\n</commands>', (), "x.xml:2: <HeadNod> needs the argument 'at'"),
    ('<commands>\n<HeadNod at="0"\n</commands>', (), "malformed XML"),
    (PAPER, ("--fps", "0"), "must be a positive number"),
    (PAPER, ("-L", "/nonexistent/folder"), "library folder does not exist"),
])
def test_errors_are_one_line_with_status_2(tmp_path, content, args, words):
    xml = tmp_path / "x.xml"
    xml.write_text(content)
    line = assert_user_error(run_in_process("tracks", xml, *args, "-o", tmp_path / "out.csv"))
    assert words in line
    assert not (tmp_path / "out.csv").exists()


def test_a_broken_user_library_file_is_reported_with_its_line(tmp_path, script):
    folder = tmp_path / "lib"
    folder.mkdir()
    (folder / "bad.lib").write_text("$command = Bad\nx = 0,0; 100,1; 50,0\n")
    line = assert_user_error(run_in_process("translate", script, "-L", folder))
    assert "bad.lib:2:" in line and "must increase" in line


def test_wrong_output_extension_and_missing_input(script, tmp_path):
    assert "unknown output extension" in assert_user_error(run_in_process("tracks", script, "-o", tmp_path / "t.txt"))
    assert "no such file" in assert_user_error(run_in_process("translate", tmp_path / "missing.xml"))


def test_library_lists_commands_and_checks_them_against_the_model(tmp_path):
    result = run_in_process("library")
    assert result.returncode == 0, result.stderr
    for name in ("HeadNod", "HeadShake", "HeadTurn", "HeadTilt", "Blink", "Wink", "EyesLook", "BrowRaise",
                 "JawOpen"):
        assert name in result.stdout
    folder = tmp_path / "lib"
    folder.mkdir()
    (folder / "smile.lib").write_text("$command = Smile\n\nlip_corner_pull = 0,0; 100,1\n")
    result = run_in_process("library", "-L", folder)
    assert result.returncode == 2
    assert "smile.lib:3:" in result.stderr and "lip_corner_pull" in result.stderr
    assert "Traceback" not in result.stderr
