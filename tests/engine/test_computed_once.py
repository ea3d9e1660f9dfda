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

