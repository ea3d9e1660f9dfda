"""``[output] validate = true``: every stimulus judged as it is made, the verdicts in check.csv, the set's
validation tables and report beside the manifest (docs/stimuli.md, docs/validation.md)."""

from __future__ import annotations

import csv
import json

import pytest

from engine.stimuli import parse_design
from engine.stimuli.design import DesignError
from tests.engine.cli_runner import made_set

DESIGN = """
[factors]
text = ["Pappa ampui pallon."]
expression = ["Happy", "none"]

[output]
kinds = ["mp4", "png", "tracks"]
size = "320x240"
validate = true
"""


def _rows(path):
    with path.open(encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


@pytest.mark.slow
def test_every_stimulus_is_judged_as_it_is_made(tmp_path):
    folder = made_set(tmp_path, DESIGN) / "set"
    checks = {row["id"]: row for row in _rows(folder / "check.csv")}
    assert set(checks) == {"0001", "0002"}
    for row in checks.values():
        assert row["ok"] == "yes" and row["face_found"] == "yes", row
        assert row["validation_status"] == "ok", row
        assert float(row["lip_r"]) > 0.7, row           # the video's lips against the timeline that drew them
        assert int(row["closures_seen"]) == int(row["closures_intended"]) > 0, row
        assert row["frames_face_lost"] == "0"
    assert checks["0001"]["intended_emotion"] == "happy"
    assert checks["0002"]["intended_emotion"] == "neutral"
    assert checks["0001"]["judged_emotion"] in ("angry", "disgust", "fear", "happy", "sad", "surprise", "neutral")
    verdicts = _rows(folder / "validation.csv")
    assert sorted((v["stimulus"], v["kind"]) for v in verdicts) == [("0001", "image"), ("0001", "video"),
                                                                     ("0002", "image"), ("0002", "video")]
    assert {v["file"] for v in verdicts} == {"0001.png", "0001.mp4", "0002.png", "0002.mp4"}
    assert (folder / "validation-confusion.csv").is_file() and (folder / "validation-identities.csv").is_file()
    report = (folder / "validation-report.html").read_text(encoding="utf-8")
    assert "data:image/png;base64," in report
    provenance = json.loads((folder / "provenance.json").read_text())
    assert provenance["validation"]["observers"][0]["role"] == "face detection"
    assert provenance["libraries"]["dlib-bin"]


def test_validate_must_be_true_or_false_and_have_a_picture_to_judge():
    with pytest.raises(DesignError, match=r"d.toml:5: .*validate must be true or false"):
        parse_design('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["png"]\nvalidate = "yes"\n', "d.toml")
    with pytest.raises(DesignError, match=r"validate needs a picture to judge"):
        parse_design('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["wav"]\nvalidate = true\n', "d.toml")
    assert not parse_design('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["png"]\n', "d.toml").output.validate
