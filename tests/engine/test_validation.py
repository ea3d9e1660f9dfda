"""``validate``: the real observers (dlib, FER2013) on real photographs, our renders and videos.

The photograph is scikit-image's astronaut (Eileen Collins, NASA: public domain), a smiling face.
Every test runs the models themselves: no observer is faked.
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from engine.validation import EMOTIONS, Intended, judge_file, judge_pixels, summarise, validate, write_tables
from engine.validation.observers import observers
from tests.engine.cli_in_process import run_in_process
from tests.engine.cli_runner import assert_user_error, made_set, run

skimage_data = pytest.importorskip("skimage.data")


@pytest.fixture(scope="module")
def astronaut() -> np.ndarray:
    return skimage_data.astronaut()


@pytest.fixture(scope="module")
def default_render(head) -> np.ndarray:
    from engine.outputs.render import FrameRenderer

    renderer = FrameRenderer(head, size=(480, 360), view="front")
    try:
        return renderer.render(head.deform({}))
    finally:
        renderer.close()


def _png(folder: Path, name: str, pixels: np.ndarray) -> Path:
    path = folder / name
    Image.fromarray(pixels).save(path)
    return path


def test_the_astronaut_is_one_smiling_face(astronaut):
    verdict = judge_pixels(astronaut, "astronaut", Intended(emotion="happy"))
    assert verdict.status == "ok" and verdict.faces == 1
    assert verdict.judged == "happy" and verdict.intended_probability > 0.9
    assert verdict.descriptor.shape == (128,)
    assert abs(verdict.emotions.sum() - 1) < 1e-3 and len(verdict.emotions) == len(EMOTIONS)


def test_the_default_head_is_found_as_one_face_with_its_eyes_open(default_render):
    verdict = judge_pixels(default_render, "head")
    assert verdict.status == "ok" and verdict.faces == 1
    assert verdict.eye_opening > 0.2                  # open eyes: the eye aspect ratio of a person is ~0.3
    assert verdict.lip_aperture < 0.1                 # lips at rest, nearly closed


def test_two_faces_and_no_face_are_plain_statuses(astronaut):
    two = judge_pixels(np.concatenate([astronaut, astronaut[:, ::-1]], axis=1), "two")
    assert two.faces == 2 and two.status.startswith("2 faces")
    assert two.judged == "happy"                      # the most certain face is still judged
    ramp = np.tile(np.linspace(0, 255, 320, dtype=np.uint8)[None, :, None], (240, 1, 3))
    none = judge_pixels(ramp, "ramp", detector="hog")
    assert none.status == "no face" and none.judged is None


def test_the_same_person_is_near_and_another_is_far(astronaut, default_render):
    same = judge_pixels(astronaut[:, ::-1].copy(), "mirrored", Intended(identity="eileen"))
    original = judge_pixels(astronaut, "astronaut", Intended(identity="eileen"))
    head = judge_pixels(default_render, "head", Intended(identity="head"))
    summary = summarise([original, same, head])
    assert original.identity_own < 0.6 and same.identity_own < 0.6
    distances = dict(zip(summary.identities, summary.identity_distances[summary.identities.index("eileen")],
                         strict=True))
    assert distances["head"] > 0.6                    # a mannequin is not Eileen Collins


def _huge_png(path: Path, width: int = 30000, height: int = 30000) -> Path:
    """A valid PNG header declaring width × height, with a few bytes of data: reading its size is
    cheap, decoding it would take 2.7 GB."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"\0" * 64))
                     + chunk(b"IEND", b""))
    return path


@pytest.mark.slow
def test_bad_files_get_a_row_each_and_the_run_goes_on(tmp_path, astronaut):
    good = _png(tmp_path, "astronaut.png", astronaut)
    text = tmp_path / "notes.txt"
    text.write_text("not a picture\n")
    huge = _huge_png(tmp_path / "huge.png")
    empty = tmp_path / "empty.jpg"
    empty.write_bytes(b"")
    cut = tmp_path / "cut.jpg"
    Image.fromarray(astronaut).save(tmp_path / "whole.jpg")
    cut.write_bytes((tmp_path / "whole.jpg").read_bytes()[:2000])
    done = run("validate", good, text, huge, empty, cut, tmp_path / "missing.png", "-o", tmp_path / "v.csv")
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    rows = {Path(r.split(",")[0]).name: r for r in (tmp_path / "v.csv").read_text().splitlines()[1:]}
    assert ",ok," in rows["astronaut.png"]
    assert "not a picture or a video" in rows["notes.txt"]
    assert "900,000,000 pixels is more than the" in rows["huge.png"]
    assert "an empty file" in rows["empty.jpg"]
    assert "cannot read the picture" in rows["cut.jpg"]
    assert "no such file" in rows["missing.png"]


def test_nothing_readable_is_one_error_line_and_status_2(tmp_path):
    text = tmp_path / "notes.txt"
    text.write_text("not a picture\n")
    line = assert_user_error(run_in_process("validate", text, tmp_path / "missing.png", "-o", tmp_path / "v.csv"))
    assert "no file could be read" in line and "notes.txt" in line
    assert not (tmp_path / "v.csv").exists()


def test_a_bad_intended_table_names_its_file_and_line(tmp_path, astronaut):
    good = _png(tmp_path, "a.png", astronaut)
    table = tmp_path / "intended.csv"
    table.write_text("file,emotion\na.png,happy\na.png,joyful-ish\n")
    line = assert_user_error(run_in_process("validate", good, "--intended", table, "-o", tmp_path / "v.csv"))
    assert f"{table}:3:" in line and "joyful-ish" in line
    table.write_text("picture,feeling\na.png,happy\n")
    line = assert_user_error(run_in_process("validate", good, "--intended", table, "-o", tmp_path / "v.csv"))
    assert f"{table}:1:" in line


def test_without_the_extra_the_verb_says_what_to_install(tmp_path, astronaut):
    good = _png(tmp_path, "a.png", astronaut)
    hide = ("import sys; sys.modules['dlib'] = None; from engine.cli import main; "
            "sys.exit(main(sys.argv[1:]))")
    import sys
    done = run("validate", good, "-o", tmp_path / "v.csv", command=[sys.executable, "-c", hide])
    line = assert_user_error(done)
    assert "pip install 'artificial-person[validate]'" in line


@pytest.mark.slow
def test_a_speaking_video_shows_the_lips_the_engine_meant(tmp_path):
    """Festival speaks; the pixels' lip aperture follows the engine's lip gap, and every bilabial closes."""
    video, landmarks = tmp_path / "say.mp4", tmp_path / "say-landmarks.csv"
    said = run("say", "Pappa ampui pallon, mamma meni mökille.", "--size", "480x360", "-o", video,
               "--landmarks", landmarks, "--quiet")
    assert said.returncode == 0, said.stderr
    table = tmp_path / "intended.csv"
    table.write_text(f"file,emotion,landmarks\n{video.name},neutral,{landmarks.name}\n")
    summary = validate([video], intended=table)
    verdict = summary.verdicts[0]
    assert verdict.kind == "video" and verdict.frames_lost == 0, verdict.status
    assert verdict.lips.r >= 0.9, verdict.lips
    assert verdict.lips.closures_intended >= 4
    assert verdict.lips.closures_seen == verdict.lips.closures_intended
    times, _aperture, gaps = verdict.aperture_trace
    assert len(times) == verdict.frames and gaps is not None


@pytest.mark.slow
def test_a_cut_video_is_judged_as_far_as_it_goes(tmp_path):
    video = tmp_path / "say.mp4"
    assert run("say", "Pappa ampui pallon.", "--size", "320x240", "-o", video, "--quiet").returncode == 0
    data = video.read_bytes()
    cut = tmp_path / "cut.mp4"
    cut.write_bytes(data[: len(data) // 2])
    verdict = judge_file(cut)
    assert "Traceback" not in verdict.status
    assert verdict.kind in ("video", "?")
    if verdict.kind == "video":                      # the index is at the front: the first frames decode
        assert verdict.frames > 0 and verdict.status != "ok"


DESIGN = """
[factors]
text = ["Pappa ampui pallon."]
expression = ["Happy", "Sad"]

[output]
kinds = ["mp4", "png", "tracks"]
size = "480x360"
fps = 30
"""


@pytest.mark.slow
def test_a_stimulus_set_is_judged_from_its_manifest_with_a_report(tmp_path):
    folder = made_set(tmp_path, DESIGN) / "set"
    out = tmp_path / "validation.csv"
    done = run("validate", folder, "--report", tmp_path / "report.html", "-o", out)
    assert done.returncode == 0, done.stderr
    assert "emotion read as intended:" in done.stdout
    lines = out.read_text().splitlines()
    header = lines[0].split(",")
    rows = [dict(zip(header, line.split(","), strict=True)) for line in lines[1:]]
    assert len(rows) == 4                              # a still and a video of each stimulus
    assert {r["intended_emotion"] for r in rows} == {"happy", "sad"}
    assert {r["kind"] for r in rows} == {"image", "video"}
    assert all(r["status"] == "ok" for r in rows), rows
    videos = [r for r in rows if r["kind"] == "video"]
    # tracks on the default head: the lips are compared (r 0.82 and 0.84 when written; the expressions
    # change the lips' shape, and the face is 160 pixels high)
    assert all(float(r["lip_r"]) > 0.7 for r in videos), videos
    assert (tmp_path / "validation-confusion.csv").read_text().startswith("intended,angry")
    report = (tmp_path / "report.html").read_text()
    assert report.count("data:image/png;base64,") >= 2           # confusion matrix and lip traces
    assert "http://" not in report and "https://" not in report  # opens offline: nothing outside the file


def test_the_tables_are_written_together(tmp_path, astronaut):
    verdict = judge_pixels(astronaut, "astronaut.png", Intended(emotion="happy", identity="eileen"))
    written = write_tables(summarise([verdict]), tmp_path / "v.csv")
    assert [p.name for p in written] == ["v.csv", "v-confusion.csv", "v-identities.csv"]
    assert "astronaut.png" in (tmp_path / "v.csv").read_text()
    confusion = (tmp_path / "v-confusion.csv").read_text().splitlines()
    assert confusion[1].startswith("happy,0,0,0,1,")


def test_the_observers_are_loaded_once_per_process():
    assert observers() is observers()
