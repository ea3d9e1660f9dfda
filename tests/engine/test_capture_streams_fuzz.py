"""Fuzzing the capture-stream readers: every input ends with a stream or a ``CaptureFileError`` naming the file.

Seeds are files in each producer's layout (the real Live Link Face take, an
OpenFace and two MediaPipe files written as their APIs write them), mutated by
hypothesis; a stream that reads is also retargeted onto the head, which must
not fail either. ``AP_FUZZ_EXAMPLES`` inputs per reader (default 200; the
release check runs 10,000, ``docs/capture-streams.md``).
"""

from __future__ import annotations

import json
from functools import cache

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from engine.capture.arkit_names import ARKIT_BLENDSHAPES
from engine.capture.live_link_face import parse_live_link_face
from engine.capture.mediapipe_blendshapes import parse_mediapipe
from engine.capture.openface import parse_openface
from engine.capture.retarget import retarget
from engine.capture.stream import CaptureFileError, CaptureStream
from tests.engine.capture_stream_files import LLF_MOUTH, mediapipe_csv, mediapipe_json, openface_text
from tests.engine.fuzz_support import FUZZ, expect_clean, mutated

NAME = "take.fuzz"


@cache
def _head():
    import engine

    return engine.load_model()


def _seed_llf() -> str:
    return "\n".join(LLF_MOUTH.read_text().splitlines()[:8]) + "\n"


def _seed_openface() -> str:
    frames = [{"AU12": 2.5, "pose_Ry": 0.1}, {"success": 0}, {"AU45": 5.0}, {"face_id": 1}]
    return openface_text(frames)


def _seed_mediapipe_json() -> str:
    turned = np.eye(4)
    turned[:3, :3] = [[0.96, 0, 0.28], [0, 1, 0], [-0.28, 0, 0.96]]
    turned[:3, 3] = [1.0, -2.0, -45.0]
    return mediapipe_json([{"jawOpen": 0.4}, {"eyeBlinkLeft": 1.0}, {"mouthSmileLeft": 0.5}],
                          matrices=[turned, np.eye(4), turned])


def _seed_mediapipe_python_json() -> str:
    return mediapipe_json([{"jawOpen": 0.4}, {"eyeBlinkLeft": 1.0}], style="python", matrices=[np.eye(4)] * 2)


def _seed_mediapipe_csv() -> str:
    return mediapipe_csv([{"jawOpen": 0.4}, {"eyeBlinkLeft": 1.0}, {}])


def _check(parse) -> None:
    result = expect_clean(parse, CaptureFileError, NAME)
    if isinstance(result, CaptureStream):
        assert np.all(np.diff(result.times_ms) > 0) and result.times_ms[0] == 0
        mapped = retarget(result, _head())
        assert np.all(np.isfinite(mapped.values))


@FUZZ
@given(mutated(_seed_llf()))
def test_live_link_face_reader_survives_mutations(text):
    _check(lambda: parse_live_link_face(text, NAME))


@FUZZ
@given(mutated(_seed_openface()))
def test_openface_reader_survives_mutations(text):
    _check(lambda: parse_openface(text, NAME))


@FUZZ
@given(mutated(_seed_mediapipe_json()))
def test_mediapipe_json_reader_survives_mutations(text):
    _check(lambda: parse_mediapipe(text, NAME))


@FUZZ
@given(mutated(_seed_mediapipe_python_json()))
def test_mediapipe_python_json_reader_survives_mutations(text):
    _check(lambda: parse_mediapipe(text, NAME))


@FUZZ
@given(mutated(_seed_mediapipe_csv()))
def test_mediapipe_csv_reader_survives_mutations(text):
    _check(lambda: parse_mediapipe(text, NAME, fps=30))


def test_deeply_nested_json_is_refused_not_a_recursion_error():
    _check(lambda: parse_mediapipe("[" * 100_000 + "]" * 100_000, NAME))


_ANY_VALUE = st.one_of(st.none(), st.booleans(), st.integers(-10**30, 10**30), st.floats(allow_nan=True),
                       st.text(max_size=5), st.just([]), st.just({}))
_SCORE = st.one_of(st.floats(0, 1), _ANY_VALUE)
_NAME = st.one_of(st.sampled_from([*ARKIT_BLENDSHAPES, "_neutral"]), st.text(max_size=8), _ANY_VALUE)


@st.composite
def _face(draw):
    names = draw(st.one_of(st.just([*ARKIT_BLENDSHAPES, "_neutral"]), st.lists(_NAME, max_size=60)))
    categories = [{draw(st.sampled_from(["categoryName", "category_name", "name"])): n, "score": draw(_SCORE)}
                  for n in names]
    return draw(st.sampled_from([{"categories": categories}, categories]))


_MATRIX = st.one_of(st.lists(st.one_of(st.floats(-2, 2), _ANY_VALUE), min_size=16, max_size=16)
                    .map(lambda d: {"rows": 4, "columns": 4, "data": d}),
                    st.lists(st.lists(st.floats(allow_nan=True), min_size=4, max_size=4), min_size=4, max_size=4),
                    _ANY_VALUE)
_FRAME = st.fixed_dictionaries({"timestampMs": st.one_of(st.floats(0, 1e4), _ANY_VALUE),
                                "faceBlendshapes": st.one_of(st.lists(_face(), max_size=2), _ANY_VALUE)},
                               optional={"facialTransformationMatrixes": st.lists(_MATRIX, max_size=2)})


@FUZZ
@given(st.one_of(st.lists(_FRAME, max_size=4), st.fixed_dictionaries({"frames": st.lists(_FRAME, max_size=4)}),
                 _ANY_VALUE))
def test_mediapipe_json_reader_survives_hostile_json_documents(document):
    """Well-formed JSON with every field of the wrong type, out of range, missing or doubled."""
    _check(lambda: parse_mediapipe(json.dumps(document), NAME))
