"""The web player frames the head as ``render --view`` does at any size (engine/web/web_camera.py).

The framing written into the animation JSON gives, for every canvas size the player may get, the
camera distance and clipping range of :func:`engine.outputs.camera.camera_pose` at that size — wide
or tall, the limit across or the limit up (to a ten-millionth: the JSON keeps nanometres) — and the
player's JavaScript computes exactly the formula tested here (``_frame`` in engine/web/player/player.js).
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.outputs.camera import VIEWS, camera_pose, framed_points
from engine.web.site import site_camera
from engine.web.web_camera import framed_distance, near_far, web_framing

SIZES = [(600, 800), (640, 480), (1366, 768), (300, 1000), (2000, 200), (1, 1000), (1000, 1), (333, 333)]


@pytest.mark.parametrize("view", sorted(VIEWS))
def test_the_framing_gives_render_s_camera_at_every_size(head, view):
    framing = web_framing(head, view)
    for width, height in SIZES:
        focal, position, _, (near, far) = camera_pose(framed_points(head), VIEWS[view], width, height)
        distance = float(np.linalg.norm(position - focal)) / 1000.0
        assert framed_distance(framing, width, height) == pytest.approx(distance, rel=1e-7), (width, height)
        assert near_far(framing, distance) == pytest.approx((near / 1000.0, far / 1000.0), rel=1e-9)


def test_wide_and_tall_pictures_are_limited_by_different_sides(head):
    """Both branches are taken: up for a wide picture (the same distance at any wider aspect), across for a tall one."""
    framing = web_framing(head)
    wide = [framed_distance(framing, w, 400) for w in (800, 1600, 4000)]
    tall = [framed_distance(framing, 400, h) for h in (1200, 2400)]
    assert wide[0] == wide[1] == wide[2] == framing["distance_up"]
    assert framing["distance_up"] < tall[0] < tall[1]


def test_only_the_points_that_can_limit_the_width_are_kept(head):
    """The side envelope is a few points, and none of the others ever gives a larger distance."""
    framing = web_framing(head)
    sides = np.array(framing["sides"])
    assert 2 <= len(sides) < 100
    assert np.all(np.diff(sides[:, 0]) > 0) and np.all(np.diff(sides[:, 1]) < 0)     # wider, and less in front
    dropped = web_framing(head)
    dropped["sides"] = sides[::2].tolist() if len(sides) > 2 else sides[:1].tolist()
    tall = [(w, 1000) for w in range(1, 400, 7)]
    assert any(framed_distance(dropped, *size) < framed_distance(framing, *size) - 1e-6 for size in tall)


def test_the_site_camera_carries_the_framing(head):
    camera = site_camera(head, (640, 480))
    target, position = np.array(camera["target"]), np.array(camera["position"])
    assert np.linalg.norm(position - target) == pytest.approx(framed_distance(camera["framing"], 640, 480), abs=1e-6)
