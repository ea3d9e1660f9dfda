"""The command line on hostile input: one ``error:`` line and status 2, never a traceback, a hang or status 1.

First the cases found by fuzzing, each run as users run it (a fresh
interpreter, :mod:`tests.engine.cli_runner`). Then two fuzz tests: fuzzed
arguments and files through :func:`engine.cli.main` in this process
(``AP_FUZZ_EXAMPLES`` of them), and a smaller number through the real
command in a subprocess (``AP_FUZZ_CLI_EXAMPLES``, default 25), which also
catches what kills a process (a segfault, an abort). Every run must end with
status 0, or 2 and exactly one ``error:`` line; nothing may still be running
after :data:`tests.engine.fuzz_support.HANG_SECONDS`.
"""

from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.cli import main
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error
from tests.engine.fuzz_support import EXAMPLES, FUZZ, HANG_SECONDS, NUMBER_TEXT, mutated, no_hang

NOD = '<commands><HeadNod at="0" amplitude="60" count="2"/></commands>\n'
LONG_NAME = "x" * 300


def write(tmp_path, name: str, text: str):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(("xml", "words"), [
    ('<commands><HeadNod at="1e308" amplitude="60" count="2"/></commands>', "beyond the longest timeline"),
    ('<commands><HeadNod at="0" count="1e9"/></commands>', "more than 1000000"),
    ('<commands><HeadNod at="0" period="1e-300" end="1000"/></commands>', "more than 1000000"),
], ids=["at-1e308", "count-1e9", "tiny-period"])
def test_tracks_of_commands_beyond_the_bounds(tmp_path, xml, words):
    line = assert_user_error(run_in_process("tracks", write(tmp_path, "in.xml", xml), "-o", tmp_path / "out.csv"))
    assert "in.xml:1:" in line and words in line


@pytest.mark.parametrize(("option", "value", "words"), [
    ("--end", "nan", "beyond the longest timeline"),
    ("--end", "1e308", "beyond the longest timeline"),
    ("--fps", "1e308", "at most 1000"),
    ("--fps", "nan", "positive"),
])
def test_tracks_options_beyond_the_bounds(tmp_path, option, value, words):
    line = assert_user_error(run_in_process("tracks", write(tmp_path, "in.xml", NOD), option, value,
                                            "-o", tmp_path / "o.csv"))
    assert option in line and words in line


def test_too_many_frames_is_one_error(tmp_path):
    line = assert_user_error(run_in_process("tracks", write(tmp_path, "in.xml", NOD), "--fps", "1000",
                                            "--end", "86400000", "-o", tmp_path / "o.csv"))
    assert "more than 5000000" in line


@pytest.mark.parametrize("source", ["/dev/zero", "folder", "fifo"])
def test_input_that_is_not_a_regular_file_is_refused_unread(tmp_path, source):
    if source == "folder":
        source = str(tmp_path)
    elif source == "fifo":
        source = str(tmp_path / "pipe.xml")
        os.mkfifo(source)                           # no writer: opening it would block for ever
    line = assert_user_error(run_in_process("translate", source))
    assert "not a regular file" in line and source in line


def test_say_refuses_a_device_as_its_text_file():
    assert "not a regular file" in assert_user_error(run_in_process("say", "--file", "/dev/zero", "-o", "x.wav"))


def test_an_input_file_too_large_is_refused(tmp_path):
    big = tmp_path / "big.xml"
    with big.open("wb") as stream:               # sparse: 200 MB on paper, nothing on the disk
        stream.truncate(200_000_000)
    assert "file too large" in assert_user_error(run_in_process("translate", big))


@pytest.mark.parametrize("text", [
    '<?xml version="1.0"?>\n<!DOCTYPE low-level-commands SYSTEM "http://example.com/low.dtd">\n'
    '<low-level-commands format="artificial-person-low-level-commands" version="1">&acts;</low-level-commands>\n',
    '<!DOCTYPE low-level-commands SYSTEM "low.dtd">\n<low-level-commands format="artificial-person-low-level-'
    'commands" version="1"><activate parameter="jaw_open" source="&s;"><key at="0" value="0"/><key at="10" '
    'value="0.1"/></activate></low-level-commands>\n',
    '<!DOCTYPE commands [<!ENTITY nod SYSTEM "file:///etc/passwd">]>\n<commands>&nod;</commands>\n',
], ids=["external-dtd", "external-dtd-entity-in-attribute", "internal-entity"])
def test_command_files_relying_on_dtd_entities_are_refused_not_emptied(tmp_path, text):
    line = assert_user_error(run_in_process("translate", write(tmp_path, "low.xml", text)))
    assert "low.xml:" in line and ("DTD" in line or "entit" in line)


@pytest.mark.parametrize("where", ["input", "output"])
def test_an_over_long_file_name_is_status_2(tmp_path, where):
    if where == "input":
        result = run_in_process("translate", tmp_path / f"{LONG_NAME}.xml")
    else:
        result = run_in_process("tracks", write(tmp_path, "in.xml", NOD), "-o", tmp_path / f"{LONG_NAME}.csv")
    assert "too long" in assert_user_error(result)


# -- fuzzing the whole command line -----------------------------------------------------------------

VERB_ARGUMENTS = st.one_of(
    st.tuples(st.just("translate"), st.just([])),
    st.tuples(st.just("tracks"), st.lists(st.sampled_from(["--fps", "--end"]).flatmap(
        lambda option: NUMBER_TEXT.map(lambda value: [option, value])), max_size=2).map(
        lambda pairs: [x for pair in pairs for x in pair])),
    st.tuples(st.just("library"), st.just([])),
    st.tuples(st.sampled_from(["translate", "tracks", "info", "pose", "nonsense"]),
              st.lists(st.one_of(st.sampled_from(["--fps", "--end", "-m", "-L", "--set", "--json", "-o", "--",
                                                  "--size", "jaw_open=1e999", "-"]), NUMBER_TEXT,
                                 st.text(alphabet=st.characters(blacklist_categories=["Cs"],
                                                                blacklist_characters="\x00"), max_size=8)),
                       max_size=4)),
)
FILE_TEXT = st.one_of(
    mutated(NOD),
    mutated("$command = Fuzz\n$mandatory = at\n$proc = once\njaw_open = 0,0; 100,0.5\n"),
    st.lists(st.tuples(st.sampled_from(["HeadNod", "Blink", "Happy", "Nope"]),
                       st.sampled_from(["at", "count", "period", "end", "amplitude", "duration"]), NUMBER_TEXT),
             max_size=3).map(lambda cs: "<commands>" + "".join(f'<{c} {k}="{v}"/>' for c, k, v in cs)
                             + "</commands>"),
    st.text(max_size=100),
)


def _arguments(tmp_path, verb: str, extra: list[str], text: str) -> list[str]:
    if verb == "library":
        return ["library", "-L", str(write(tmp_path, "fuzz.lib", text)), *extra]
    source = str(write(tmp_path, "fuzz.xml", text))
    if verb == "tracks":
        return ["tracks", source, *extra, "-o", str(tmp_path / "out.csv")]
    if verb == "pose":
        return ["pose", *extra, "-o", str(tmp_path / "out.npz")]
    return [verb, source, *extra]


def _check_one_error_line(status: int, stderr: str) -> None:
    assert "Traceback" not in stderr, stderr
    assert status in (0, 2), (status, stderr)
    if status == 2:
        lines = stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: "), stderr


@FUZZ
@given(VERB_ARGUMENTS, FILE_TEXT)
def test_fuzzed_command_lines_in_process(tmp_path_factory, verb_arguments, text):
    verb, extra = verb_arguments
    argv = _arguments(tmp_path_factory.mktemp("cli"), verb, extra, text)
    stdout, stderr = io.StringIO(), io.StringIO()
    with no_hang(), contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        status = main(argv)
    if verb == "library" and status == 2 and stderr.getvalue().count("error:") > 1:
        return                                      # `library` lists every problem it finds, one per line
    _check_one_error_line(status, stderr.getvalue())


SUBPROCESS_EXAMPLES = int(os.environ.get("AP_FUZZ_CLI_EXAMPLES", str(min(25, EXAMPLES))))


@settings(FUZZ, max_examples=SUBPROCESS_EXAMPLES)
@given(VERB_ARGUMENTS, FILE_TEXT)
def test_fuzzed_command_lines_through_the_real_command(tmp_path_factory, verb_arguments, text):
    verb, extra = verb_arguments
    argv = _arguments(tmp_path_factory.mktemp("cli"), verb, extra, text)
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    result = subprocess.run([sys.executable, "-m", "engine", *argv], capture_output=True, text=True, env=env,
                            timeout=HANG_SECONDS * 2, check=False)
    assert result.returncode >= 0, f"killed by signal {-result.returncode}: {argv}"
    if verb == "library" and result.returncode == 2 and result.stderr.count("error:") > 1:
        return
    _check_one_error_line(result.returncode, result.stderr)
