"""Warnings for what Festival reads oddly (issue 16 §3): numbers, dates, abbreviations, with where they stand."""

from __future__ import annotations

import pytest

from engine.speech.reading_checks import reading_warnings
from tests.engine.test_festival import needs_festival


@pytest.mark.parametrize("text, token", [
    ("Hinta on 674 500 euroa.", "674 500"),
    ("Tule 12.6. kotiin.", "12.6."),
    ("Syntynyt 12.6.1999 Oulussa.", "12.6.1999"),
    ("Se maksaa 3,5 euroa.", "3,5"),
    ("Hän oli 5. maalissa.", "5."),
    ("Ostin mm. omenoita.", "mm."),
    ("Tapaamme klo 14.", "klo"),
    ("Tämä on esim. hyvä.", "esim."),
])
def test_each_kind_of_token_is_named(text, token):
    warnings = reading_warnings(text, "suo_fi_lj_diphone")
    assert [w.token for w in warnings][:1] == [token]
    warning = warnings[0]
    assert text.splitlines()[warning.line - 1][warning.column - 1:].startswith(token)
    assert "write" in warning.advice


@pytest.mark.parametrize("text", [
    "Pappa ampui pallon.", "Vuonna kaksituhatta kolme.",
    "Hyvää päivää <HeadNod at=\"1.5\" amplitude=\"60\"/> kaikille.",
    "Mm, hyvää.", "Ovi 3 on auki.",
])
def test_plain_text_and_inline_commands_give_no_warning(text):
    assert reading_warnings(text, "suo_fi_lj_diphone") == []


def test_positions_count_the_typed_text_with_its_commands_and_lines():
    text = 'Hei <Happy intensity="50"/> kaikki.\nOstin mm. omenoita.'
    (warning,) = reading_warnings(text)
    assert (warning.line, warning.column, warning.token) == (2, 7, "mm.")
    assert warning.located("story.txt").startswith("story.txt:2: column 7: 'mm.'")


def test_english_voices_are_not_warned_about_finnish_abbreviations():
    assert reading_warnings("Hello mm. world", "kal_diphone") == []
    assert [w.token for w in reading_warnings("It costs 674 500 dollars", "kal_diphone")] == ["674 500"]


@needs_festival
@pytest.mark.slow
def test_say_prints_the_warnings_and_still_speaks(tmp_path):
    from tests.engine.cli_runner import run

    result = run("say", "Ostin mm. 674 500 omenaa.", "--phones", tmp_path / "p.csv")
    assert result.returncode == 0, result.stderr
    lines = result.stderr.splitlines()
    assert any(line.startswith("warning: <text>:1: column 7: 'mm.'") or "column 7: 'mm.'" in line for line in lines)
    assert any("'674 500'" in line for line in lines)
    assert "Traceback" not in result.stderr and (tmp_path / "p.csv").is_file()
