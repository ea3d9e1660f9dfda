"""Each result computed once (issue 35 item 4): counters around the real implementations, not timers.

The mesh of a frame (§2.2's deformation of every vertex) is computed once, by the video that shows it;
the landmarks table, the lip track and a stimulus's motion check take their numbers from the landmarks'
own vertices (:mod:`engine.model.vertex_subset`, the same numbers) or from the positions the video was
drawn from (``encode_video(on_positions=…)``), never by deforming the whole mesh again.
"""

from __future__ import annotations

import csv
import io
import json
import shutil
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from engine.deform.deformer import Deformer
from engine.model.landmarks import landmark_sort_key
from engine.model.vertex_subset import model_at_landmarks, model_at_vertices
from engine.outputs.data_files import landmarks_csv
from engine.outputs.render_helper import ENVIRONMENT
from engine.outputs.speech_files import write_speech_files
from engine.speech import say
from engine.speech.say import speak
from engine.stimuli.design import parse_design
from engine.stimuli.make import make_stimulus
from engine.validation.lips import LOWER, UPPER, lip_track
from tests.engine.recorded_speech import Recorded

VISEME_DESIGN = ('[factors]\ntext = ["Apa."]\nviseme = ["p"]\nviseme_b = ["t"]\nviseme_morph = [40]\n'
                 '[output]\nkinds = ["tracks", "phones"]\nfps = 25\n')


def test_a_viseme_level_builds_the_animation_once_and_as_before(tmp_path, monkeypatch):
    """The continuum's blended table is chosen from the synthesized utterance before the one animation;
    the tracks are the ones the old way (animate with the plain table, then again with the blended one)
    gave, to the byte."""
    from engine.speech.articulation import table_for
    from engine.stimuli.heads import stimulus_head
    from engine.timeline.tracks import tracks_csv_text

    design = parse_design(VISEME_DESIGN, str(tmp_path / "d.toml"))
    stimulus = design.stimuli[0]
    real, built = say.animate, []

    def counted(*args, **kwargs):
        built.append(args[1].text)
        return real(*args, **kwargs)

    monkeypatch.setattr(say, "animate", counted)
    record = make_stimulus(design, stimulus, tmp_path)
    assert built == ["Apa."], built
    monkeypatch.setattr(say, "animate", real)

    model = stimulus_head(design, stimulus.levels)
    plain = say.speak("Apa.", model)
    table = table_for(plain.utterance).with_blended_row("p", "t", 0.4)
    before = say.animate(plain.script, plain.utterance, model, say.load_library(), table)
    written = (tmp_path / record["files"]["tracks"]["name"]).read_text()
    times = [float(line.split(",")[0]) for line in written.splitlines()[1:]]
    assert written == tracks_csv_text(before.timeline.parameters, times, before.timeline.sample(times))



STILL_DESIGN = ('[factors]\ntext = ["Apa."]\nexpression = ["Happy"]\n'
                '[output]\nkinds = ["mp4", "silent-mp4", "png"]\nfps = 25\nsize = "160x120"\n')


def test_a_stimulus_with_both_videos_and_a_still_draws_every_frame_once(tmp_path, monkeypatch):
    """Both MP4s from one drawing, and the still (at the expression's apex, 400 ms: frame 10 at 25 fps) is the
    picture the video drew for that frame — the same bytes the still's own drawing gives."""
    from engine.outputs import render
    from engine.stimuli import make
    from engine.stimuli.heads import stimulus_head

    monkeypatch.setenv("AP_RENDER_PROCESSES", "1")         # one process draws, so this one counts every frame
    design = parse_design(STILL_DESIGN, str(tmp_path / "d.toml"))
    stimulus = design.stimuli[0]
    real, drawn = render.FrameRenderer.render, []

    def counted(self, *args, **kwargs):
        drawn.append(1)
        return real(self, *args, **kwargs)

    monkeypatch.setattr(render.FrameRenderer, "render", counted)
    out = tmp_path / "set"
    out.mkdir()
    record = make_stimulus(design, stimulus, out)
    from engine.outputs.video_probe import read_frames

    frames = read_frames(out / record["files"]["mp4"]["name"])
    assert len(drawn) == len(frames), (len(drawn), len(frames))        # the video's frames, nothing more
    monkeypatch.setattr(render.FrameRenderer, "render", real)
    model = stimulus_head(design, stimulus.levels)
    timeline, _ = make._with_expression(say.speak("Apa.", model), model, stimulus.levels)
    again = tmp_path / "again.png"
    make._still(model, timeline, record["still_ms"], design, again)
    assert (out / record["files"]["png"]["name"]).read_bytes() == again.read_bytes()


needs_festival = pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
needs_ffmpeg = pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="ffmpeg is not installed")


@pytest.fixture
def whole_mesh_deformations(head, monkeypatch):
    """How many times the whole mesh of ``head`` is deformed (a deformer of a vertex subset not counted)."""
    seen: list[int] = []
    original = Deformer.deform

    def counting(self, values):
        if self.n_vertices == head.n_vertices:
            seen.append(1)
        return original(self, values)

    monkeypatch.setattr(Deformer, "deform", counting)
    return seen


def _poses(head, count, seed=3):
    rng = np.random.default_rng(seed)
    return head.values_array()[None] + rng.normal(0.0, 0.3, (count, len(head.parameters)))


def test_a_vertex_subset_moves_exactly_as_the_whole_mesh_there(head):
    ids = sorted(head.landmarks, key=landmark_sort_key)
    vertices = [head.landmarks[i] for i in ids]
    whole, part = head.deformer(), model_at_landmarks(head, ids).deformer()
    for row in _poses(head, 12):
        np.testing.assert_array_equal(part.deform(row), whole.deform(row)[vertices])
    twice = model_at_vertices(head, [vertices[0], vertices[0]])     # a vertex listed twice, twice
    row = _poses(head, 1)[0]
    np.testing.assert_array_equal(twice.deformer().deform(row), whole.deform(row)[[vertices[0]] * 2])


def test_the_landmarks_table_deforms_no_whole_mesh_and_shows_its_positions(head, whole_mesh_deformations):
    values = _poses(head, 5)
    table = list(csv.reader(io.StringIO(landmarks_csv(head, np.arange(5) * 40.0, values))))
    assert whole_mesh_deformations == []
    ids = sorted(head.landmarks, key=landmark_sort_key)
    expected = head.deformer().deform(values[3])[[head.landmarks[i] for i in ids]]
    np.testing.assert_allclose(np.array(table[4][2:], dtype=float).reshape(-1, 3), expected, atol=5e-4)


def test_the_lip_track_deforms_no_whole_mesh(head, whole_mesh_deformations):
    values = _poses(head, 4)
    track = lip_track(head, np.arange(4) * 40.0, values)
    assert whole_mesh_deformations == []
    moved = head.deformer().deform(values[2])
    assert track.gaps[2] == pytest.approx(float(np.linalg.norm(moved[head.landmarks[UPPER]]
                                                              - moved[head.landmarks[LOWER]])), abs=1e-12)


@needs_ffmpeg
def test_say_with_a_video_and_landmarks_deforms_each_frame_once(head, tmp_path, monkeypatch,
                                                                 whole_mesh_deformations):
    monkeypatch.setenv(ENVIRONMENT, "1")          # one process draws every frame, so all are counted here
    speech = speak("moi", head, synthesizer=Recorded())
    frames = len(speech.frame_times(25))
    write_speech_files(speech, head, {"mp4": tmp_path / "alone.mp4"}, fps=25, size=(64, 48))
    alone = len(whole_mesh_deformations)          # the frames, and the head's baked occlusion the first time
    whole_mesh_deformations.clear()
    write_speech_files(speech, head, {"mp4": tmp_path / "s.mp4", "landmarks": tmp_path / "l.csv",
                                      "tracks": tmp_path / "t.csv"}, fps=25, size=(64, 48))
    assert len(whole_mesh_deformations) == frames <= alone     # once per frame; the table adds none
    rows = (tmp_path / "l.csv").read_text().splitlines()
    assert len(rows) == frames + 1


@needs_festival
def test_a_stimulus_checks_its_video_motion_without_deforming_a_frame_again(head, tmp_path, monkeypatch,
                                                                            whole_mesh_deformations):
    from engine.outputs.video_probe import probe

    monkeypatch.setenv(ENVIRONMENT, "1")
    design = parse_design('[factors]\ntext = ["Pappa on pappa."]\n[output]\nkinds = ["mp4"]\nsize = "64x48"\n',
                          str(tmp_path / "d.toml"))
    record = make_stimulus(design, design.stimuli[0], tmp_path)
    assert "measured_video_lag_frames" in record["check"]          # the motion check ran …
    assert record["check"]["video_ok"] is True
    assert len(whole_mesh_deformations) == probe(tmp_path / "0001.mp4").frames   # … on the video's own meshes


HELPER_RUN = textwrap.dedent("""
    import json, os, sys
    import numpy as np
    os.environ["AP_RENDER_PROCESSES"] = "2"
    import engine
    from engine.deform.deformer import Deformer
    from engine.outputs.render import render_model
    from engine.outputs.video_writer import check_video, encode_video
    from engine.stimuli.make import MotionMeter, vertex_motion

    head = engine.load_model()
    frames = 70
    times = np.arange(frames) * (1000 / 30)
    values = np.column_stack([0.4 * (1 + np.sin(times / 150)) / 2, 0.2 * np.sin(times / 400)])
    request = check_video(sys.argv[1], head, times, values, ["jaw_open", "head_turn"], 30, size=(64, 48))
    render_model(head, size=(64, 48))      # the baked occlusion computed (and kept) before the count
    drawn_here = []
    original = Deformer.deform
    def counting(self, row):
        drawn_here.append(1)
        return original(self, row)
    Deformer.deform = counting
    meter = MotionMeter(frames)
    encode_video(request, sys.argv[1], on_positions=meter)
    Deformer.deform = original
    expected = vertex_motion(head, request.values)
    print(json.dumps({"seen": meter.seen, "here": len(drawn_here),
                      "equal": bool(np.array_equal(meter.motion, expected))}))
""")


@needs_ffmpeg
def test_the_helper_process_hands_over_the_positions_it_drew_from(tmp_path):
    """With two drawing processes, the frames the helper drew come with their meshes, byte for byte."""
    done = subprocess.run([sys.executable, "-c", HELPER_RUN, str(tmp_path / "v.mp4")], capture_output=True,
                          text=True, timeout=600, check=True)
    seen = json.loads(done.stdout.strip().splitlines()[-1])
    assert seen["seen"] == 70 and seen["equal"] is True
    assert seen["here"] == 35                      # the other 35 frames were deformed in the helper, once
