"""Each result computed once (issue 35 item 4): counters around the real implementations, not timers."""

from __future__ import annotations

from engine.speech import say
from engine.stimuli.design import parse_design
from engine.stimuli.make import make_stimulus

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
