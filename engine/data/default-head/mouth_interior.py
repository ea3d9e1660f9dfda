"""The inside of the mouth a viewer reads: a dark oral cavity, teeth that catch the light, a tongue that rests low.

A stage of ``derive_default_head.py``. MakeHuman's ``hm08`` skin already
closes the mouth with a bag of skin (palate, cheeks, floor) behind the lips;
drawn in the skin's colour and lit like the face, an open mouth read as a
pale or red disc. This stage:

* finds that bag (:func:`oral_cavity`): the skin behind the lip rim, the
  closed edge loop through the upper lip's lowest midline vertex (2.2),
  and how deep each of its vertices lies (along the surface from the rim);
* paints it (:func:`cavity_colors`) from the lip's colour at the rim through
  the red of the inner lip to near black in the throat, and darkens the
  tongue towards its root (:func:`tongue_colors`): the renderer lights every
  surface as if nothing shadowed it, so the depth is painted in;
* bevels the upper teeth (:func:`bevel_teeth`): on the coarse MakeHuman
  dentition the incisal edge joins the front face to a long lingual face
  that faces backwards and down, so the edge's smooth normal pointed down
  and the upper incisors drew dark under the lights from above;
* seats the teeth (:data:`UPPER_TEETH_SHIFT_MM`, :data:`LOWER_TEETH_SHIFT_MM`):
  the upper incisors 2 mm lower (about 3 mm of incisor below the relaxed
  upper lip, as in a young adult; it was 0.8 mm) and the lower ones behind
  them (the MakeHuman bite was edge to edge);
* lowers the tongue (:func:`lower_tongue`): MakeHuman's tongue rests with its
  tip between the incisors and its back up against the palate, so it filled
  every open mouth; it now lies behind the lower incisors and
  ``tongue_raise`` lifts its tip to the back of the upper ones.

Lengths are mm, angles degrees, colours sRGB bytes.

>>> import numpy as np
>>> cavity_colors(np.array([0.0, 3.0, 40.0]))[[0, 2]].tolist()
[[227, 180, 156], [30, 12, 14]]
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np
from head_geometry import kabsch

from engine.deform.transforms import apply, rotation_about_axis
from engine.identity.mouth_bag import edge_loop, oral_cavity  # noqa: F401  (the derivation's names, one implementation)

UPPER_TEETH_SHIFT_MM = (0.0, -2.0, -0.6)
LOWER_TEETH_SHIFT_MM = (0.0, -0.3, -2.2)
BEVEL_MM = 1.2                 # length left to the lingual face at the upper incisal edge
TONGUE_DOWN_DEGREES = 10.0     # the tongue's rest turned down about its root
TONGUE_FLATTEN = 0.7           # its height above its lowest point, scaled
# (depth behind the lip rim along the surface in mm, colour): lip, inner lip, mucosa in shadow, throat
CAVITY_STOPS = [(0.0, "#e3b49c"), (3.0, "#b4646a"), (10.0, "#5c2228"), (22.0, "#1e0c0e")]
TONGUE_TIP, TONGUE_ROOT = "#c25a5f", "#3a1216"
TONGUE_SHADE_MM = (8.0, 40.0)  # the tongue darkens from this far behind the lower incisors, over this length


def rgb(colour: str) -> np.ndarray:
    return np.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)], dtype=float)


def cavity_colors(depth: np.ndarray) -> np.ndarray:
    """sRGB bytes for the mouth bag's vertices at these depths behind the lip rim."""
    at = [d for d, _ in CAVITY_STOPS]
    colours = np.array([rgb(c) for _, c in CAVITY_STOPS])
    return np.rint(np.column_stack([np.interp(depth, at, colours[:, i]) for i in range(3)])).astype(np.uint8)


def tongue_colors(tongue_z: np.ndarray, incisors_z: float) -> np.ndarray:
    """sRGB bytes for the tongue: its colour at the tip, darker towards the root (``z`` in mm, +Z forward)."""
    start, length = TONGUE_SHADE_MM
    k = np.clip((incisors_z - start - tongue_z) / length, 0, 1)[:, None]
    return np.rint((1 - k) * rgb(TONGUE_TIP) + k * rgb(TONGUE_ROOT)).astype(np.uint8)


def lower_tongue(vertices, tongue, root, axis) -> np.ndarray:
    """Turn the tongue down about its root (``axis`` turns the tip up) and flatten its back, in place.

    Returns the linear part (3 × 3) of that change, for carrying the artist's poses over.
    """
    turn = rotation_about_axis(np.asarray(axis, float), np.asarray(root, float), -TONGUE_DOWN_DEGREES)
    turned = apply(turn, vertices[tongue])
    floor = turned[:, 1].min()
    turned[:, 1] = floor + (turned[:, 1] - floor) * TONGUE_FLATTEN
    vertices[tongue] = turned
    return np.diag([1.0, TONGUE_FLATTEN, 1.0]) @ np.asarray(turn)[:3, :3].T     # apply() multiplies rows


def carried_displacement(made, displacement, reshaped, linear) -> np.ndarray:
    """An artist pose of a part made on MakeHuman's shape (``made`` + ``displacement``), carried over to
    the part ``reshaped``: the pose's rigid motion of the part (least squares) moves the new shape, and
    what the pose does beyond that motion (the tongue's own bending) is mapped by the reshape's
    ``linear`` part. The jaw's pose thus turns the new teeth and tongue about the same hinge."""
    centre, moved = made.mean(axis=0), made + displacement
    centre_moved = moved.mean(axis=0)
    turn = kabsch(made - centre, moved - centre_moved)
    own = moved - ((made - centre) @ turn.T + centre_moved)
    return (reshaped - centre) @ turn.T + centre_moved - reshaped + own @ np.asarray(linear).T


def bevel_teeth(vertices, polygons, teeth) -> np.ndarray:
    """Shorten the lingual face at the incisal edge to :data:`BEVEL_MM`, in place; returns the lingual row.

    The edge's smooth normal then follows the front face (forward), not the
    sum of the front and a long backward-facing lingual face (down).
    """
    lingual, edge = incisal_rows(vertices, polygons, teeth)
    direction = vertices[lingual] - vertices[edge]
    vertices[lingual] = vertices[edge] + BEVEL_MM * direction / np.linalg.norm(direction, axis=1)[:, None]
    return lingual


def incisal_rows(vertices, polygons, teeth) -> tuple[np.ndarray, np.ndarray]:
    """(lingual row, the incisal-edge vertex beside each) of a MakeHuman tooth strip.

    The strip is a grid of quads four vertices deep (gum, middle, incisal
    edge, lingual) along the arch; its boundary loop has four corners, and of
    its two long sides the lingual row is the one nearer the arch's centre.
    """
    teeth_set = {int(v) for v in teeth}
    strip = [[int(v) for v in p] for p in polygons if int(p[0]) in teeth_set]
    count, neighbours = defaultdict(int), defaultdict(set)
    for p in strip:
        for i in range(len(p)):
            a, b = p[i], p[(i + 1) % len(p)]
            count[min(a, b), max(a, b)] += 1
            neighbours[a].add(b)
            neighbours[b].add(a)
    on_boundary = {v for (a, b), k in count.items() if k == 1 for v in (a, b)}
    corners = sorted(v for v in on_boundary if len(neighbours[v]) == 2)
    loop, previous = [corners[0]], -1
    while True:
        v = loop[-1]
        ahead = [u for u in sorted(neighbours[v]) if u != previous and count[min(u, v), max(u, v)] == 1]
        if ahead[0] == loop[0]:
            break
        previous = v
        loop.append(ahead[0])
    cuts = [i for i, v in enumerate(loop) if v in corners] + [len(loop)]
    sides = [(loop + loop[:1])[cuts[i]:cuts[i + 1] + 1] for i in range(4)]
    long_sides = sorted(sides, key=len)[2:]
    centre = vertices[list(teeth_set)].mean(axis=0)
    lingual = np.array(min(long_sides, key=lambda side: float(
        np.mean(np.linalg.norm((vertices[side] - centre)[:, [0, 2]], axis=1)))))
    lingual_set = set(lingual.tolist())
    edge = []
    for v in lingual:
        inward = [u for u in neighbours[v] if u not in lingual_set]
        edge.append(inward[0])
    return lingual, np.array(edge)
