"""Fuzzing what ``validate`` reads besides pictures: the ``--intended`` table, a set's manifest, and
the engine's landmarks table. Each is read, or refused with a UserError naming the file.

Size: ``AP_FUZZ_EXAMPLES`` (``tests/engine/fuzz_support.py``).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from engine.errors import UserError
from engine.validation.intended import read_intended, read_set
from engine.validation.lips import read_landmarks_track
from tests.engine.fuzz_support import FUZZ, NUMBER_TEXT, expect_clean, mutated

INTENDED = "file,emotion,identity,landmarks\na.png,happy,anna,\nb.mp4,Sad,anna,b-landmarks.csv\nc.jpg,,bo,\n"
MANIFEST = ("id,text,expression,intensity,expression_b,morph,identity,file_png,file_mp4,file_tracks\n"
            "0001,Moi.,Happy,50,,,sex=1,0001.png,0001.mp4,0001-tracks.csv\n"
            "0002,Moi.,Fear,100,Surprise,70,,0002.png,,\n")
LANDMARKS = ("frame,time_ms,2.2_x,2.2_y,2.2_z,2.3_x,2.3_y,2.3_z\n0,0,0,-40,60,0,-42.6,60\n"
             "1,33.3,0,-40,60,0,-50,60\n")
CELLS = st.one_of(NUMBER_TEXT, st.sampled_from(["happy", "Anger", "Contempt", "joy", "", '"', '"a,b"', "x" * 200000,
                                                 "\x00", "\r", "../../etc/passwd", "/dev/zero"]))


def _table(header: list[str]) -> st.SearchStrategy[str]:
    rows = st.lists(st.lists(CELLS, min_size=0, max_size=len(header) + 2).map(",".join), max_size=6)
    return rows.map(lambda r: "\n".join([",".join(header), *r]) + "\n")


def _texts(seed: str, header: list[str]) -> st.SearchStrategy[str]:
    return st.one_of(mutated(seed), _table(header), st.text(max_size=300))


@FUZZ
@given(_texts(INTENDED, ["file", "emotion", "identity", "landmarks"]))
def test_intended_tables_are_read_or_refused_with_the_file_named(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("intended") / "intended.csv"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    expect_clean(lambda: read_intended(path), UserError, str(path))


@FUZZ
@given(_texts(MANIFEST, ["id", "expression", "intensity", "expression_b", "morph", "file_png", "file_mp4"]))
def test_manifests_are_read_or_refused_with_the_file_named(tmp_path_factory, text):
    folder = tmp_path_factory.mktemp("set")
    (folder / "manifest.csv").write_text(text, encoding="utf-8", errors="surrogatepass")
    expect_clean(lambda: read_set(folder), UserError, str(folder / "manifest.csv"))


@FUZZ
@given(_texts(LANDMARKS, ["frame", "time_ms", "2.2_x", "2.2_y", "2.2_z", "2.3_x", "2.3_y", "2.3_z"]))
def test_landmarks_tables_are_read_or_refused_with_the_file_named(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("landmarks") / "landmarks.csv"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    track = expect_clean(lambda: read_landmarks_track(path), UserError, str(path))
    if not isinstance(track, UserError):
        assert len(track.times) == len(track.gaps) > 0
