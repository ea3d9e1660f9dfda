"""The videos' encoding a lab chooses (issue 36): an x264 preset and CRF, or lossless for analysis; through
write_video, ``say`` and a design's ``[output]``, recorded in the set's provenance and manifest. The frames'
timing and the audio do not depend on it."""

from __future__ import annotations

import csv
import json
import subprocess

import numpy as np
import pytest

from engine.errors import UserError
from engine.outputs.render import FrameRenderer
from engine.outputs.video_encoding import Encoding, encoding_from
from engine.outputs.video_probe import probe, read_frames
from engine.outputs.video_writer import write_video
from engine.stimuli import DesignError, parse_design
from tests.engine.cli_runner import assert_user_error, run
from tests.engine.test_festival import needs_festival

FPS = 25.0
SIZE = (96, 72)


def moving(count: int = 6) -> tuple[np.ndarray, np.ndarray]:
    times = np.arange(count) * (1000.0 / FPS)
    return times, np.column_stack([np.linspace(0.0, 0.8, count), np.linspace(-0.3, 0.3, count)])


def video_stream(path) -> dict:
    out = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_streams", "-print_format",
                          "json", str(path)], capture_output=True, text=True, check=True).stdout
    return json.loads(out)["streams"][0]


def test_a_lossless_video_holds_every_pixel_the_renderer_drew(head, tmp_path):
    times, values = moving()
    out = tmp_path / "lossless.mp4"
    write_video(out, head, times, values, ["jaw_open", "head_turn"], FPS, size=SIZE, encoding="lossless")
    stream = video_stream(out)
    assert stream["codec_name"] == "h264" and stream["pix_fmt"] in ("gbrp", "rgb24"), stream
    decoded = read_frames(out)
    deformer = head.deformer()
    names = head.parameters.names
    with FrameRenderer(head, size=SIZE) as renderer:        # the look's anti-aliasing, as the video has it
        for n, row in enumerate(values):
            pose = head.values_array().copy()
            pose[names.index("jaw_open")], pose[names.index("head_turn")] = row
            np.testing.assert_array_equal(decoded[n], renderer.render(deformer.deform(pose)))


def test_the_crf_trades_size_for_quality_and_keeps_the_frames_and_their_times(head, tmp_path):
    times, values = moving(12)
    sizes, errors = {}, {}
    reference = read_frames(_written(head, tmp_path, times, values, "lossless"))
    for crf in (10, 40):
        path = _written(head, tmp_path, times, values, {"crf": crf, "preset": "medium"})
        info = probe(path)
        assert info.frames == 12 and info.fps == pytest.approx(FPS)
        sizes[crf] = path.stat().st_size
        errors[crf] = float(np.abs(read_frames(path).astype(int) - reference).mean())
    assert sizes[40] < sizes[10] / 2 and errors[40] > errors[10]


def _written(head, folder, times, values, encoding):
    out = folder / f"{encoding_from(encoding).name.replace('/', '-')}.mp4"
    write_video(out, head, times, values, ["jaw_open", "head_turn"], FPS, size=SIZE, encoding=encoding)
    return out


@pytest.mark.parametrize("value, message", [
    ({"crf": 52}, "crf must be a number from 0 to 51"),
    ({"crf": True}, "crf must be a number from 0 to 51"),
    ({"crf": float("nan")}, "crf must be a number from 0 to 51"),
    ({"preset": "warp"}, "preset must be one of ultrafast"),
    ({"lossless": "yes"}, "lossless must be true or false"),
    ({"lossless": True, "crf": 0}, "crf has no meaning in a lossless video"),
    ({"speed": 1}, "unknown setting 'speed'"),
    (3, "must be \"lossless\", a preset"),
])
def test_a_bad_encoding_is_refused_saying_why(value, message):
    with pytest.raises(UserError, match=message):
        encoding_from(value)


def test_the_default_is_the_encoding_every_video_had():
    assert Encoding().ffmpeg_args()[:6] == ["-c:v", "libx264", "-preset", "veryfast", "-crf", "20"]
    assert encoding_from(None) == encoding_from("default") == encoding_from({}) == Encoding()
    assert encoding_from("slow") == Encoding(preset="slow")


def test_a_design_names_its_encoding_and_a_bad_one_names_its_line(tmp_path):
    base = '[factors]\ntext = ["Moi."]\n[output]\nkinds = ["mp4"]\n'
    assert parse_design(base, "d.toml").output.encoding == Encoding()
    assert parse_design(base + 'encoding = "lossless"\n', "d.toml").output.encoding.lossless
    chosen = parse_design(base + '[output.encoding]\npreset = "slow"\ncrf = 23\n', "d.toml").output.encoding
    assert chosen == Encoding("slow", 23.0)
    with pytest.raises(DesignError, match=r"d\.toml:7: encoding: crf must be a number from 0 to 51"):
        parse_design(base + '[output.encoding]\npreset = "slow"\ncrf = 99\n', "d.toml")


def test_say_refuses_a_bad_crf_in_one_line():
    assert "--crf" in assert_user_error(run("say", "Moi.", "--crf", "80", "-o", "x.mp4"))
    assert "lossless" in assert_user_error(run("say", "Moi.", "--crf", "10", "--lossless", "-o", "x.mp4"))


@needs_festival
def test_say_writes_a_lossless_video(tmp_path):
    out = tmp_path / "moi.mp4"
    said = run("say", "Moi.", "--lossless", "--size", "96x72", "--quiet", "-o", out)
    assert said.returncode == 0, said.stderr
    assert video_stream(out)["pix_fmt"] in ("gbrp", "rgb24")
    assert probe(out).audio_codec == "aac"


@needs_festival
def test_a_set_records_its_encoding_in_provenance_and_manifest(tmp_path):
    (tmp_path / "d.toml").write_text('[factors]\ntext = ["Moi."]\n[output]\nkinds = ["mp4", "wav"]\n'
                                     'size = "96x72"\n[output.encoding]\npreset = "faster"\ncrf = 26\n')
    made = run("stimuli", tmp_path / "d.toml", "-o", tmp_path / "set", "--workers", "1")
    assert made.returncode == 0, made.stderr
    provenance = json.loads((tmp_path / "set" / "provenance.json").read_text())
    assert provenance["encoding"] == {"preset": "faster", "crf": 26.0, "lossless": False}
    with (tmp_path / "set" / "manifest.csv").open() as stream:
        assert [row["encoding"] for row in csv.DictReader(stream)] == ["faster/crf26"]
