"""Fuzzing the reading of a stimulus set's manifest for ``web-export --stimuli`` (hypothesis).

Each example damages a real manifest (from a set made by ``stimuli`` with real Festival) —
characters replaced, inserted, deleted, the text cut short, or whole rows of hostile cells —
and lists the set: it returns the stimuli, or raises :class:`UserError` whose message starts
with the manifest's name; no other exception and no hang. CI runs ``AP_FUZZ_EXAMPLES`` examples
per test (default 200); the release check runs 10000:

    AP_FUZZ_EXAMPLES=10000 .venv/bin/python -m pytest tests/engine/test_web_stimuli_fuzz.py -q
"""

from __future__ import annotations

import shutil

import pytest
from hypothesis import given
from hypothesis import strategies as st

from engine.errors import UserError
from engine.web.stimuli_site import read_set_listing
from tests.engine.cli_runner import made_set
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated

DESIGN = """[factors]
text = ["Pappa ampui pallon.", "Maija meni kotiin."]
[output]
kinds = ["wav", "tracks", "phones"]
fps = 30
"""
CELLS = st.one_of(NUMBER_TEXT, st.text(max_size=12), st.sampled_from(
    ["0001", "0002.wav", "../0001.wav", "/etc/passwd", "0001-tracks.csv", "a;b;c", "1;2", "", '"', "\x00", "x" * 5000,
     "model", "identity", "Pappa;ampui", "30;365.752;737.752"]))


@pytest.fixture(scope="module")
def real_set(tmp_path_factory):
    return made_set(tmp_path_factory.mktemp("fuzz-set"), DESIGN) / "set"


@pytest.fixture(scope="module")
def work(real_set, tmp_path_factory):
    """A copy of the set whose manifest each example overwrites."""
    copy = tmp_path_factory.mktemp("fuzz-work") / "set"
    shutil.copytree(real_set, copy)
    return copy


def _listed_or_refused(folder, text: str) -> None:
    manifest = folder / "manifest.csv"
    manifest.write_text(text, encoding="utf-8", errors="surrogatepass")
    result = expect_clean(lambda: read_set_listing(folder), UserError, str(manifest))
    if not isinstance(result, UserError):
        assert result and all((folder / s.row["file_wav"]).is_file() for s in result)


@pytest.mark.slow
@FUZZ
@given(data=st.data())
def test_a_damaged_manifest_is_listed_or_refused_by_name(real_set, work, data):
    original = (real_set / "manifest.csv").read_text()
    _listed_or_refused(work, data.draw(mutated(original)))


@pytest.mark.slow
@FUZZ
@given(cells=st.lists(st.lists(CELLS, min_size=1, max_size=25), min_size=1, max_size=4), keep_header=st.booleans())
def test_hostile_rows_are_listed_or_refused_by_name(real_set, work, cells, keep_header):
    lines = (real_set / "manifest.csv").read_text().splitlines()
    rows = [",".join(f'"{c}"' if ("," in c or "\n" in c) else c for c in row) for row in cells]
    _listed_or_refused(work, "\n".join(([lines[0]] if keep_header else []) + rows) + "\n")


def test_the_real_manifest_lists_both_stimuli(real_set):
    listing = read_set_listing(real_set)
    assert [s.id for s in listing] == ["0001", "0002"]
    assert [w.label for w in listing[0].manifest_words] == ["Pappa", "ampui", "pallon"]


@pytest.mark.parametrize("name", ["x" * 5000, "a\x00b.wav", "../outside.wav", "/etc/hostname"])
def test_a_file_name_no_folder_can_hold_is_refused_by_the_manifest(real_set, tmp_path, name):
    copy = tmp_path / "set"
    shutil.copytree(real_set, copy)
    manifest = copy / "manifest.csv"
    manifest.write_text(manifest.read_text().replace("0001.wav,", f"{name},", 1))
    with pytest.raises(UserError) as refused:
        read_set_listing(copy)
    assert str(refused.value).startswith(f"{manifest}:2:") and "not in the set's folder" in str(refused.value)
