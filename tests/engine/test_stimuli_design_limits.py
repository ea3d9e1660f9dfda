"""Design files at their limits (issue 30): the stimulus cap counted before anything is made, rows looked up in
linear time, integers and nesting tomllib cannot take, and numbers no design means — each one error line
naming the file and the line, never a traceback, a MemoryError or a minute's wait."""

from __future__ import annotations

import sys

import pytest

from engine.stimuli import DesignError, load_design, parse_design
from engine.stimuli.design import MAX_STIMULI
from engine.stimuli.design_toml import MAX_NESTING
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.fuzz_support import no_hang

TEXT = '[factors]\ntext = ["a."]\n'
ADDRESS_SPACE = 1536 * 1024**2
"""What the command may map in the test of the cap: enough to start it (numpy, the engine), far less than
expanding the blocks would take."""
LIMITED = [sys.executable, "-c", f"""
import resource, runpy, sys
resource.setrlimit(resource.RLIMIT_AS, ({ADDRESS_SPACE}, {ADDRESS_SPACE}))
sys.argv[0] = "artificial-person"
runpy.run_module("engine", run_name="__main__")
"""]


def refused(text: str, line: int | None, message: str) -> DesignError:
    with pytest.raises(DesignError) as caught:
        parse_design(text, "d.toml")
    assert caught.value.file == "d.toml" and caught.value.line == line, str(caught.value)
    assert message in caught.value.message, str(caught.value)
    return caught.value


# -- the cap, counted first -----------------------------------------------------------------------------

def test_blocks_are_counted_before_any_is_made_so_a_small_design_of_many_blocks_is_refused_at_once(tmp_path):
    """220 kB: 20,000 blocks of 99,000 stimuli each. Expanding them reached MemoryError; counting them is
    one error line, within an address space far smaller than the expansion needs."""
    levels = ", ".join(str(i) for i in range(1000))
    design = tmp_path / "blocks.toml"
    design.write_text(f"{TEXT}x = [{levels}]\ny = [{', '.join(str(i) for i in range(99))}]\n\n"
                      + "[[blocks]]\n" * 20_000, encoding="utf-8")
    error = assert_user_error(run("stimuli", design, "-o", tmp_path / "out", "--dry-run", command=LIMITED))
    assert error == f"error: {design}:6: blocks: the design makes 1980000000 stimuli, more than {MAX_STIMULI}"


def test_the_cap_holds_for_every_way_of_combining():
    many = ", ".join(str(i) for i in range(50_001))
    refused(f'{TEXT}x = [{many}]\ny = [1, 2]\n', 1, "the design makes 100002 stimuli, more than 100000")
    refused(f'{TEXT}x = [{many}]\n[[blocks]]\n[[blocks]]\nx = [1, 2]\n[[blocks]]\n', 4,
            "the design makes 100004 stimuli")
    rows = '[[rows]]\ntext = "a."\n' * (MAX_STIMULI + 1)
    refused(f'combine = "list"\n{TEXT}{rows}', 4, "the design makes 100001 stimuli")
    assert len(parse_design(f'{TEXT}x = [{many}]\n[[blocks]]\n[[blocks]]\nx = [1]\n').stimuli) == 50_002


# -- rows in linear time ---------------------------------------------------------------------------------

def test_a_design_of_many_rows_finds_its_one_bad_row_in_linear_time_and_names_its_line(tmp_path):
    """3.5 MB: 76,200 levels and as many rows, the last naming no level. Each row's level was looked up in a
    list (67-114 s here); a set takes seconds. The guard is a hang bound, not a timing."""
    count = 76_200
    levels = ", ".join(f'"l{i:06d}"' for i in range(count))
    rows = "".join(f'[[rows]]\ntext = "a."\nx = "l{i:06d}"\n' for i in range(count - 1))
    design = tmp_path / "rows.toml"
    design.write_text(f'combine = "list"\n{TEXT}x = [{levels}]\n{rows}[[rows]]\ntext = "a."\nx = "nosuch"\n',
                      encoding="utf-8")
    assert design.stat().st_size > 3_500_000
    with no_hang(), pytest.raises(DesignError) as caught:
        load_design(design)
    assert str(caught.value) == f"{design}:{4 + 3 * count}: x: 'nosuch' is not a level of 'x'"


def test_rows_and_blocks_match_levels_as_equal_values_and_name_their_own_lines():
    listed = parse_design('combine = "list"\n[factors]\ntext = ["a."]\nintensity = [50]\n'
                          'identity = [{sex = 1, age = 30}]\n[[rows]]\ntext = "a."\nintensity = 50.0\n'
                          'identity = {age = 30, sex = 1.0}\n', "d.toml")
    assert [s.levels["intensity"] for s in listed.stimuli] == [50.0]
    two_rows = 'combine = "list"\n[factors]\ntext = ["a.", "b."]\nintensity = [0, 50]\n' \
               '[[rows]]\ntext = "a."\nintensity = 0\n[[rows]]\ntext = "b."\n'
    refused(two_rows + "intensity = 150\n", 10, "'intensity' level 150: must be a number from 0 to 100")
    refused(two_rows, 8, "a row gives no level for intensity")
    refused(two_rows + "colour = 1\n", 10, "row names 'colour', which is not a factor")
    blocks = '[factors]\ntext = ["a.", "b."]\nintensity = [0, 50]\n[[blocks]]\ntext = ["a."]\n[[blocks]]\n'
    refused(blocks + "intensity = [70]\n", 7, "70 is not a level of 'intensity'")
    refused(blocks + 'text = "a."\n', 7, "factor 'text' must be a list of its levels")


# -- what tomllib cannot take -----------------------------------------------------------------------------

@pytest.mark.parametrize("text, line, message", [
    (f"{TEXT}x = [{'1' * 5000}]\n", 3, "an integer of more than 4300 digits"),
    (f"{TEXT}[output]\nfps = -{'9' * 4301}\n", 4, "an integer of more than 4300 digits"),
    (f"seed = 1_{'2_' * 4400}3\n{TEXT}", 1, "an integer of more than 4300 digits"),
    (f"{TEXT}\nx = {'[' * 1200}{']' * 1200}\n", 4, f"arrays and tables nested more than {MAX_NESTING} deep"),
    (f"{TEXT}x = [{'{a = ' * 700}1{'}' * 700}]\n", 3, "nested more than"),
    (f"{TEXT}x = [\n  # a comment ]]]] [[[[\n  \"[[[[\",\n  {'[' * 40}{']' * 40}]\n", 6, "nested more than"),
    (f"{TEXT}x = [1]\n[output]\nq{'.a' * 100} = 1\n", 5, "nested more than"),
    (f"{TEXT}x = [0x{'f' * 5000}]\n", 3, "x: an integer of about 6021 digits: a number in a design must be finite"),
    (f"combine = 0x{'f' * 5000}\n{TEXT}", 1, "combine: an integer of about"),
])
def test_integers_and_nesting_tomllib_cannot_take_are_one_error_at_their_line(text, line, message):
    refused(text, line, message)


def test_the_command_says_so_in_one_line(tmp_path):
    design = tmp_path / "deep.toml"
    design.write_text(f"{TEXT}x = {'[' * 2000}{']' * 2000}\n", encoding="utf-8")
    assert assert_user_error(run_in_process("stimuli", design, "-o", tmp_path / "out")) == \
        f"error: {design}:3: arrays and tables nested more than {MAX_NESTING} deep"
    design.write_text(f"{TEXT}x = [{'7' * 10_000}]\n", encoding="utf-8")
    assert assert_user_error(run_in_process("stimuli", design, "-o", tmp_path / "out")) == \
        f"error: {design}:3: an integer of more than 4300 digits (no design needs one)"
    assert not (tmp_path / "out").exists()


# -- numbers: finite and bounded, everywhere ---------------------------------------------------------------

@pytest.mark.parametrize("text, line, message", [
    (f"{TEXT}[output]\nstill_ms = inf\n", 4, "still_ms: inf: a number in a design must be finite and within ±1e+15"),
    (f"{TEXT}[output]\nstill_ms = nan\n", 4, "still_ms: nan: a number in a design must be finite"),
    (f"{TEXT}[output]\nstill_ms = -inf\n", 4, "still_ms: -inf: a number"),
    (f"{TEXT}[output]\nstill_ms = 1e308\n", 4, "still_ms: 1e+308: a number"),
    (f"{TEXT}[output]\nstill_ms = 1e999\n", 4, "still_ms: inf: a number"),
    (f"{TEXT}[output]\nstill_ms = 86400001\n", 4, "still_ms must be a time in ms from the start of the clip, 0 to "
                                                  "86400000 (24 hours)"),
    (f"{TEXT}[output]\nstill_ms = -1\n", 4, "still_ms must be a time in ms"),
    (f"{TEXT}[output]\nfps = nan\n", 4, "fps: nan: a number"),
    (f"{TEXT}[output]\nfps = 1e300\n", 4, "fps: 1e+300: a number"),
    (f"{TEXT}[output]\nfps = 241\n", 4, "fps must be a number from 1 to 240"),
    (f"{TEXT}av_offset_ms = [0, inf]\n", 3, "av_offset_ms: inf: a number"),
    (f"{TEXT}snr_db = [nan]\n", 3, "snr_db: nan: a number"),
    (f"{TEXT}intensity = [1e999]\n", 3, "intensity: inf: a number"),
    (f"{TEXT}trial = [1, nan]\n", 3, "trial: nan: a number"),
    (f"{TEXT}trial = [1e16]\n", 3, "trial: 1e+16: a number"),
    (f"{TEXT}trial = [-10_000_000_000_000_000]\n", 3, "trial: -10000000000000000: a number"),
    (f"{TEXT}identity = [{{sex = 1, age = inf}}]\n", 3, "age: inf: a number"),
    (f'combine = "list"\n{TEXT}x = [1]\n[[rows]]\ntext = "a."\nx = nan\n', 7, "x: nan: a number"),
    (f"seed = 1e308\n{TEXT}", 1, "seed: 1e+308: a number"),
])
def test_every_number_of_a_design_is_finite_and_bounded(text, line, message):
    refused(text, line, message)


def test_numbers_within_the_bounds_are_kept():
    design = parse_design(f"{TEXT}trial = [1e15, -1_000_000_000_000_000, 0.5]\n[output]\nstill_ms = 86400000\n"
                          "fps = 240\n", "d.toml")
    assert design.output.still_ms == 86_400_000.0 and design.output.fps == 240.0
    assert [s.levels["trial"] for s in design.stimuli] == [1e15, -10**15, 0.5]
