"""The baked occlusion (engine/outputs/occlusion.py) is computed once per head, not once per model object:
a file loaded again, or a workbench window's model replaced by the same file, takes the kept values; a
change of what they are computed from (a vertex moved, the jaw's weights, the radius) computes them again."""

from __future__ import annotations

import numpy as np
import pytest

import engine.outputs.occlusion as occlusion
from engine.outputs.occlusion import forget_computed, model_occlusion


@pytest.fixture
def computed(monkeypatch):
    """How many meshes' occlusion was marched (one per pose: rest, jaw half open)."""
    calls: list[int] = []
    original = occlusion._layout_occlusion

    def counting(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(occlusion, "_layout_occlusion", counting)
    forget_computed()
    yield calls
    forget_computed()


def test_another_object_of_the_same_head_takes_the_kept_values(head, computed):
    first = model_occlusion(head)
    assert len(computed) == 2                                  # rest and jaw half open
    again = model_occlusion(head.copy())
    assert len(computed) == 2 and again is first


def test_a_moved_vertex_the_jaw_weights_or_the_radius_compute_them_again(head, computed):
    first = model_occlusion(head)
    moved = head.copy()
    corner = moved.landmarks["8.3"]
    moved.vertices[corner] += [0.0, 0.0, -4.0]                 # the lip's corner pushed into the face
    moved.changed()
    assert len(computed) == 2
    model_occlusion(moved)
    assert len(computed) == 4
    rig = head.copy()
    jaw = rig.regions["jaw_open"]
    jaw.weights[:] = jaw.weights * 0.5                          # the jaw opens half as far
    rig.changed()
    other = model_occlusion(rig)
    assert len(computed) == 6 and not np.array_equal(other, first)
    model_occlusion(head, radius_mm=20.0)
    assert len(computed) == 8


def test_the_kept_values_are_bounded(head, computed, monkeypatch):
    monkeypatch.setattr(occlusion, "_BY_CONTENT_SIZE", 2)
    for k in range(4):
        copy = head.copy()
        copy.vertices[0] += [0.0, 0.0, 0.01 * (k + 1)]
        copy.changed()
        model_occlusion(copy)
    assert len(occlusion._by_content) == 2 and len(computed) == 8
