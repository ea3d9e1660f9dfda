"""Every Festival voice speaks (issue 16 §3): targets from phone features, the English table, kal_diphone.

The paper's voices are Finnish (§2.1); any Festival voice describes its phones
by the same features, so articulation targets come from them wherever a
hand-made table has no row.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from engine.errors import LibraryError
from engine.speech.articulation import load_articulation, shipped_tables, table_for
from engine.speech.phone_features import FEATURE_NAMES, PhoneFeatures, derived_cells
from engine.speech.synthesis import Segment, Utterance
from tests.engine.test_festival import needs_festival


@pytest.fixture(scope="module")
def festival():
    from engine.speech.festival import FestivalSynthesizer

    return FestivalSynthesizer()

RADIO_PHONES = Path("/usr/share/festival/radio_phones.scm")
FINNISH_PHONES = Path("/usr/share/festival/voices/finnish/suopuhe.common/finnish_phones.scm")
ENGLISH = Path(__file__).parents[2] / "engine" / "library" / "articulation" / "english.phones"


def phone_set(path: Path) -> dict[str, PhoneFeatures]:
    """The members of a Festival phone set file: ``(name vc vlng vheight vfront vrnd ctype cplace cvox)``."""
    members = {}
    for match in re.finditer(r"^\s*\(([^\s()]+)((?:\s+[-+0-9a-z]){8,})\s*\)", path.read_text(encoding="latin-1"),
                             re.MULTILINE):
        if match.group(1) not in FEATURE_NAMES:                     # the feature declarations themselves
            members[match.group(1)] = PhoneFeatures.parse(match.group(2))
    return members


def needs(path: Path):
    return pytest.mark.skipif(not path.is_file(), reason=f"{path} is not installed")


# ---------------------------------------------------------------------------
# Targets from features
# ---------------------------------------------------------------------------

@needs(FINNISH_PHONES)
def test_derived_finnish_rows_agree_with_the_hand_made_table():
    """The derivation, applied to Suopuhe's own phone features, gives the hand-made Finnish targets back:
    vowels within 0.05 in every parameter, consonant rows the same cells."""
    table = load_articulation()
    features = phone_set(FINNISH_PHONES)
    vowels = [p for p in "aeiouy@7" if p in features]
    assert len(vowels) == 8
    for phone in vowels:
        derived = table.with_derived_rows({f"x{phone}": features[phone]})
        for parameter in table.parameters:
            assert derived.target(f"x{phone}", parameter) == pytest.approx(table.target(phone, parameter), abs=0.05), \
                (phone, parameter)
    for phone in ("p", "b", "m", "f", "v", "t", "s", "n", "l", "k", "N", "j"):
        cells = derived_cells(features[phone], table.parameters)
        hand = table.row(phone)
        derived = table.with_derived_rows({"x": features[phone]}).row("x")
        assert [t.enforced for t in derived] == [t.enforced for t in hand], phone
        assert [t.value for t in derived] == pytest.approx([t.value for t in hand], abs=1e-9), (phone, cells)


def test_features_of_pauses_vowels_and_syllabic_consonants():
    assert PhoneFeatures.parse("- 0 0 0 0 0 0 -").is_pause                        # pau
    assert PhoneFeatures.parse("0 0 0 0 0 0 0 0").is_pause                        # Suopuhe #
    em = PhoneFeatures.parse("+ s 0 0 0 n l +")                                   # English syllabic m
    assert not em.is_vowel and not em.is_pause
    assert derived_cells(em, ["jaw_open", "lower_lip_raise"]) == ["0!/2", "1!/2"]
    assert derived_cells(PhoneFeatures.parse("+ l 1 3 + 0 0 0"), ["lip_protrude", "mouth_widen"]) == ["1", "0"]
    assert derived_cells(PhoneFeatures.parse("+ s 1 1 - 0 0 0"), ["eyebrow_raise"]) == ["-"]   # not an articulator


def test_a_table_lacking_a_phone_gets_its_row_from_the_features_and_the_hand_made_row_wins():
    table = load_articulation()
    utterance = Utterance("x", "v", np.zeros(10, np.float32), 1000, [Segment("pau", 0, 5), Segment("a", 5, 10)],
                          [], phoneset="finnish",
                          phone_features={"pau": PhoneFeatures.parse("- 0 0 0 0 0 0 -"),
                                          "a": PhoneFeatures.parse("+ s 1 1 - 0 0 0")})   # lies: a is open
    chosen = table_for(utterance)
    assert chosen.target("a", "jaw_open") == table.target("a", "jaw_open")      # the hand-made row
    assert chosen.target("pau", "jaw_open") == 0 and chosen.derived == {"pau"}


def test_a_phone_set_without_a_table_is_all_derived_and_an_unknown_phone_is_named():
    features = {"pau": PhoneFeatures.parse("- 0 0 0 0 0 0 -"), "A": PhoneFeatures.parse("+ s 3 3 - 0 0 0"),
                "P": PhoneFeatures.parse("- 0 0 0 0 s l -")}
    utterance = Utterance("x", "v", np.zeros(10, np.float32), 1000, [], [], phoneset="klingon",
                          phone_features=features)
    table = table_for(utterance)
    assert table.target("A", "jaw_open") == pytest.approx(0.4) and table.row("P")[0].enforced
    with pytest.raises(LibraryError, match="no row for phone 'Q'"):
        table.row("Q")
    bare = Utterance("x", "v", np.zeros(10, np.float32), 1000, [], [], phoneset="finnish")
    with pytest.raises(LibraryError, match="no row for phone 'pau'"):
        table_for(bare).row("pau")


# ---------------------------------------------------------------------------
# The English table
# ---------------------------------------------------------------------------

def test_the_english_table_is_shipped_for_the_radio_phone_set():
    assert shipped_tables()["radio"] == ENGLISH.resolve() or shipped_tables()["radio"] == ENGLISH
    assert load_articulation(ENGLISH).phoneset == "radio"


@needs(RADIO_PHONES)
def test_the_english_table_has_every_radio_phone_and_agrees_with_its_features():
    table = load_articulation(ENGLISH)
    members = phone_set(RADIO_PHONES)
    assert len(members) >= 50
    assert set(members) <= set(table.rows), set(members) - set(table.rows)
    jaw, spread, rounding = (table.parameters.index(p) for p in ("jaw_open", "mouth_widen", "lip_protrude"))
    for phone, features in members.items():
        row = table.row(phone)
        if features.is_pause:
            assert all(t.value == 0 for t in row), phone
        elif features.is_vowel:
            height = {"1": (0.1, 0.2), "2": (0.19, 0.32), "3": (0.35, 0.45)}[features.vheight]
            assert height[0] <= row[jaw].value <= height[1], phone
            if features.vrnd == "+" and features.vlng != "d":
                assert row[rounding].value >= 0.4 and row[spread].value == 0, phone
            if features.vrnd == "-" and features.vfront == "1":
                assert row[spread].value >= 0.4 and row[rounding].value == 0, phone
        elif features.cplace == "l" and features.ctype in ("s", "n"):
            assert row[jaw].enforced and row[jaw].value == 0, phone                 # bilabials close


# ---------------------------------------------------------------------------
# Speaking English with Festival (kal_diphone, installed by ./bootstrap)
# ---------------------------------------------------------------------------

@needs_festival
@pytest.mark.slow
def test_kal_diphone_speaks_bilabials_close_and_open_vowels_open(festival, head):
    from engine.speech.say import speak

    if "kal_diphone" not in festival.voices():
        pytest.fail("kal_diphone (festvox-kallpc16k) is not installed: ./bootstrap installs it")
    speech = speak("My father bought a map, and Bob ate a pie.", head, synthesizer=festival, voice="kal_diphone")
    utterance = speech.utterance
    assert utterance.phoneset == "radio"
    assert {"m", "p", "b", "aa", "ae"} <= {p.label for p in utterance.phones}
    for phone in utterance.phones:
        values = speech.timeline.values_at(phone.mid_ms)
        if phone.label in ("m", "p", "b"):
            assert values["jaw_open"] == pytest.approx(0, abs=1e-9) and values["lower_lip_raise"] == pytest.approx(1)
        if phone.label in ("aa", "ae"):
            assert values["jaw_open"] > 0.3, phone


@needs_festival
@pytest.mark.slow
def test_say_with_an_english_voice_from_the_command_line(festival, tmp_path):
    from tests.engine.cli_runner import run

    if "kal_diphone" not in festival.voices():
        pytest.fail("kal_diphone (festvox-kallpc16k) is not installed: ./bootstrap installs it")
    phones = tmp_path / "phones.csv"
    result = run("say", "Hello world.", "--voice", "kal_diphone", "--phones", phones)
    assert result.returncode == 0, result.stderr
    assert "pau" in phones.read_text() and "Traceback" not in result.stderr
