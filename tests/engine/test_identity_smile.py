"""A smile on a new face shows no mouth lining at its corners (issue 18 §2).

Carried over as they were, AU12's fields pulled the lip corners of fuller
lips away from the lining behind them, and the lining showed through as red
spots beside the corners (``docs/images/identity/gallery.png`` of session 7).
Measured here with the real renderer: the lining (the mouth bag more than
1 mm behind the lip rim) painted pure green, the front picture of the
library's Happy (AU6 0.8 and AU12 1 on both sides), and the green pixels
counted outside the lip opening (the lip rim's edge loop, projected, widened
by 2 px).
"""

from __future__ import annotations

import pytest
from scipy import ndimage

import engine
from engine.identity import Identity, make_identity_head
from engine.identity.mouth_bag import edge_loop, polygon_graph
from engine.identity.rest_fit import _mouth_bag
from engine.outputs.render import render_model
from tests.engine.test_mouth_and_eyes import inside, project

SIZE = (400, 500)
SMILE = {"AU6_left": 0.8, "AU6_right": 0.8, "AU12_left": 1.0, "AU12_right": 1.0}
ONLY = {"african": 0.0, "asian": 0.0, "caucasian": 0.0}
FACES = {
    "default": None,
    "man-25-african": {**ONLY, "sex": 1.0, "age": 25, "african": 1.0},
    "woman-25-african": {**ONLY, "sex": 0.0, "age": 25, "african": 1.0},
    "woman-28-asian": {**ONLY, "sex": 0.0, "age": 28, "asian": 1.0},
}
MOST_GREEN = 3               # pixels of lining outside the opening a smile may show (antialiased edges)


def lining_pixels_outside_the_opening(head) -> int:
    """Green (lining) pixels of the front picture of the smile outside the widened lip opening."""
    bag, depth = _mouth_bag(engine.load_model())
    painted = head.copy()
    colors = painted.vertex_colors.copy()
    colors[bag[depth > 1.0]] = (0, 255, 0)
    painted.vertex_colors = colors
    image = render_model(painted, SMILE, view="front", size=SIZE).astype(int)
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    green = (g > r + 40) & (g > b + 40)
    rim = project(head, head.deform(SMILE)[lip_rim(engine.load_model())], size=SIZE)   # same mesh
    opening = ndimage.binary_dilation(inside(rim, SIZE), iterations=2)
    return int((green & ~opening).sum())


def lip_rim(head) -> list[int]:
    """The lip rim: the skin's edge loop through the upper lip's inner midpoint (2.2), in order (as
    ``engine.identity.mouth_bag.oral_cavity`` walks it)."""
    skin = head.vertex_part == head.parts.index("skin")
    polygons = [p for p in head.polygons() if skin[p].all()]
    start = head.landmarks["2.2"]
    graph = polygon_graph(polygons, head.n_vertices)
    graph = (graph + graph.T).tocsr()
    sideways = [int(v) for v in graph[start].indices if head.vertices[v, 0] > head.vertices[start, 0]]
    return edge_loop(polygons, start, sideways[0])


@pytest.mark.parametrize("face", list(FACES))
def test_a_smile_shows_no_lining_beside_the_corners(face):
    values = FACES[face]
    head = engine.load_model() if values is None else make_identity_head(Identity(values))
    count = lining_pixels_outside_the_opening(head)
    assert count <= MOST_GREEN, f"{count} pixels of mouth lining show outside the lips in a smile"
