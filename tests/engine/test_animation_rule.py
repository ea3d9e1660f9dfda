"""One animation rule (§2.3; issue 35 item 3): base + the sum of the activations covering a time, clamped to
the range. The offline timeline and the live head both use engine/timeline/rule.py, so the same activations
give the same values frame by frame, whatever they are."""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from engine.commands.command_files import Activation
from engine.commands.interpolation import INTERPOLATIONS
from engine.live.head import LiveHead
from engine.timeline import Timeline
from engine.timeline.rule import AnimationRule
from tests.engine.fuzz_support import EXAMPLES

ENGINE = Path(__file__).parents[2] / "engine"
MOVED = ["head_nod", "jaw_open", "lower_lip_raise", "head_turn"]


@pytest.fixture(scope="module")
def model():
    from engine import load_model

    return load_model()


def activations_strategy():
    def one(parameter, start, gaps, values, kind):
        times = start + np.cumsum([0.0, *gaps])
        return Activation(parameter, times, np.array(values[:len(times)]), kind)

    key_counts = st.integers(2, 5)
    return st.lists(key_counts.flatmap(lambda n: st.builds(
        one, st.sampled_from(MOVED), st.floats(0, 900, allow_nan=False),
        st.lists(st.floats(0, 300, allow_nan=False), min_size=n - 1, max_size=n - 1),
        st.lists(st.floats(-2, 2, allow_nan=False), min_size=n, max_size=n),
        st.sampled_from(INTERPOLATIONS))), max_size=6)


@settings(max_examples=min(EXAMPLES, 200), deadline=None)
@given(activations=activations_strategy(), frame_ms=st.sampled_from([10.0, 16.0, 33.3]))
def test_the_live_head_and_the_timeline_give_the_same_values(model, activations, frame_ms):
    timeline = Timeline(activations, model)
    live = LiveHead(model)
    live.add_commands(0.0, "r", None, activations)
    times = np.arange(0.0, 1700.0, frame_ms)
    offline = timeline.sample(times)
    for k, t in enumerate(times):
        live.advance(float(t))
        np.testing.assert_array_equal(live.current, offline[k])


def test_a_set_moves_the_base_the_activations_add_to(model):
    nod = [Activation("head_nod", np.array([0.0, 100.0]), np.array([0.1, 0.1]))]
    live = LiveHead(model)
    live.add_set(0.0, "s", None, {"head_nod": 0.3})
    live.add_commands(0.0, "c", None, nod)
    live.advance(50.0)
    rule = AnimationRule(model)
    expected = rule.default.copy()
    expected[rule.column["head_nod"]] = 0.4
    np.testing.assert_allclose(live.current, rule.clamp(expected[None, :])[0])


def test_sums_are_clamped_and_both_ends_of_an_activation_count(model):
    rule = AnimationRule(model)
    column = rule.column["jaw_open"]
    big = [Activation("jaw_open", np.array([0.0, 100.0]), np.array([5.0, 5.0])),
           Activation("jaw_open", np.array([100.0, 200.0]), np.array([-0.25, -0.25]))]
    total = rule.base_rows(4)
    rule.add(total, big, rule.columns(big), np.array([-1.0, 0.0, 100.0, 200.0]))
    values = rule.clamp(total)[:, column]
    assert values.tolist() == [rule.default[column], rule.maximum[column], rule.maximum[column],
                               max(rule.default[column] - 0.25, rule.minimum[column])]


def test_the_rule_is_written_once():
    """Only the rule module turns activations into values: neither the timeline nor the live head
    interpolates keys or clamps by itself."""
    for path in (ENGINE / "timeline" / "timeline.py", ENGINE / "live" / "head.py"):
        tree = ast.parse(path.read_text())
        imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)
                    and node.module == "engine.commands.interpolation" for alias in node.names}
        clips = [node for node in ast.walk(tree) if isinstance(node, ast.Attribute) and node.attr == "clip"]
        assert not imported and not clips, path
