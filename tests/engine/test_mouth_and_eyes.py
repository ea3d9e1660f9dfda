"""The mouth a lip-reader looks at (issue 18 §1): a dark cavity, upper incisors that catch the light, a low tongue.

Measured on the real default head with the real renderer: the front picture
(400 × 500) at the middle of Finnish ``a`` (the shipped articulation table's
targets), the pixels inside the projected inner-lip contour (landmarks 2.4,
2.2, 2.5, 2.3 and the lip rim between them). Figures: docs/default-head.md.
"""

from __future__ import annotations

import numpy as np
import pytest

from engine.outputs.camera import VIEW_ANGLE, VIEWS, camera_pose, framed_points
from engine.outputs.part_layout import PartLayout
from engine.outputs.render import render_model
from engine.speech.articulation import load_articulation

SIZE = (400, 500)
DARK_LUMA = 70              # a pixel of the cavity: Rec. 601 luma below this
BRIGHT_LUMA, GREY_SPREAD = 140, 45   # a pixel of a tooth: light and nearly grey
MIN_DARK, MIN_BRIGHT = 0.45, 0.10    # fractions of the lip opening


def phone_values(phone: str) -> dict[str, float]:
    """A phone's targets in the shipped Finnish table: the middle of the phone spoken alone."""
    table = load_articulation()
    return {name: table.target(phone, name) for name in table.parameters}


def project(model, points: np.ndarray, view: str = "front", size=SIZE) -> np.ndarray:
    """Pixel (column, row) of model points in the renderer's picture (its camera, engine.outputs.camera)."""
    width, height = size
    focal, position, up, _ = camera_pose(framed_points(model), VIEWS[view], width, height)
    back = (position - focal) / np.linalg.norm(position - focal)
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    upward = np.cross(back, right)
    d = np.asarray(points, float) - position
    scale = height / 2 / (-(d @ back) * np.tan(np.radians(VIEW_ANGLE) / 2))
    return np.column_stack([width / 2 + (d @ right) * scale, height / 2 - (d @ upward) * scale])


def inner_lip_contour(model, positions: np.ndarray, points: int = 48) -> np.ndarray:
    """The lip opening in the front picture: two half-ellipses through the inner lip corners (2.4, 2.5),
    the upper lip's lowest midline point (2.2, the top) and the lower lip's highest (2.3, the bottom)."""
    lm = model.landmarks
    left, top, right, bottom = project(model, positions[[lm[k] for k in ("2.4", "2.2", "2.5", "2.3")]])
    centre = (left + right) / 2
    half_width = abs(right[0] - left[0]) / 2
    t = np.linspace(0, np.pi, points // 2, endpoint=False)
    upper = np.column_stack([centre[0] + half_width * np.cos(t), centre[1] - (centre[1] - top[1]) * np.sin(t)])
    lower = np.column_stack([centre[0] - half_width * np.cos(t), centre[1] + (bottom[1] - centre[1]) * np.sin(t)])
    return np.concatenate([upper, lower])


def inside(polygon: np.ndarray, size=SIZE) -> np.ndarray:
    """(height, width) mask of the pixel centres inside a polygon (even-odd rule)."""
    width, height = size
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    mask = np.zeros((height, width), bool)
    for (x0, y0), (x1, y1) in zip(polygon, np.roll(polygon, -1, axis=0), strict=True):
        crosses = (y0 > ys) != (y1 > ys)
        x_at = x0 + (ys - y0) * (x1 - x0) / np.where(y1 != y0, y1 - y0, 1)
        mask ^= crosses & (xs < x_at)
    return mask


def mouth_pixels(model, values) -> tuple[float, float, int]:
    """(dark fraction, bright near-white fraction, pixel count) inside the inner-lip contour, front view."""
    positions = model.deform(values)
    image = render_model(model, values, view="front", size=SIZE).astype(float)
    mask = inside(inner_lip_contour(model, positions))
    pixels = image[mask]
    luma = pixels @ [0.299, 0.587, 0.114]
    spread = pixels.max(axis=1) - pixels.min(axis=1)
    return float(np.mean(luma < DARK_LUMA)), float(np.mean((luma > BRIGHT_LUMA) & (spread < GREY_SPREAD))), len(pixels)


def test_the_open_mouth_at_a_shows_a_dark_cavity_and_teeth(head):
    dark, bright, count = mouth_pixels(head, phone_values("a"))
    print(f"a, front {SIZE}: {count} px inside the lips, dark {dark:.1%}, bright near-white {bright:.1%}")
    assert count > 300, "the lips open at a"
    assert dark > MIN_DARK, f"the cavity behind the teeth reads dark ({dark:.1%})"
    assert bright > MIN_BRIGHT, f"the teeth read as teeth ({bright:.1%})"


def test_without_the_cavity_the_measure_fails(head):
    """The same measure on the head with its mouth bag painted the skin's colour again: no cavity."""
    plain = head.copy()
    if plain.texture is not None:                  # the skin image keeps the bag's dark: drawn without it
        plain.texture.face_image[:] = -1
    skin_colour = np.array([int(head.part_colors["skin"][i:i + 2], 16) for i in (1, 3, 5)], dtype=np.uint8)
    bag = mouth_bag(head)
    plain.vertex_colors = head.vertex_colors.copy()
    plain.vertex_colors[bag] = skin_colour
    plain.vertex_colors[head.part_vertices("tongue")] = [0xc2, 0x5a, 0x5f]
    dark, _bright, _count = mouth_pixels(plain, phone_values("a"))
    assert dark < MIN_DARK, f"a skin-coloured mouth would not pass ({dark:.1%})"


def test_without_the_teeth_the_measure_fails(head):
    values = phone_values("a")
    gone = head.copy()
    teeth = np.concatenate([head.part_vertices("teeth_upper"), head.part_vertices("teeth_lower")])
    gone.vertices[teeth] = head.vertices[head.landmarks["2.3"]] - [0.0, 0.0, 30.0]   # collapsed: nothing drawn
    gone.changed()
    _dark, bright, _count = mouth_pixels(gone, values)
    assert bright < MIN_BRIGHT, f"without teeth the opening must not pass ({bright:.1%})"


def mouth_bag(head) -> np.ndarray:
    """The skin vertices painted as the oral cavity: darker than any skin outside it."""
    skin = head.part_vertices("skin")
    luma = head.vertex_colors[skin].astype(float) @ [0.299, 0.587, 0.114]
    mouth = (head.vertices[head.landmarks["2.2"]] + head.vertices[head.landmarks["2.3"]]) / 2
    near = np.linalg.norm(head.vertices[skin] - mouth, axis=1) < 60      # not the painted brows
    return skin[(luma < 90) & near]


def test_the_cavity_is_inside_the_mouth_and_rides_with_the_jaw(head):
    bag = mouth_bag(head)
    P, lm = head.vertices, head.landmarks
    assert len(bag) > 200
    # behind the lips and between the cheeks, above the chin, below the nose
    assert P[bag, 2].max() < P[lm["2.3"], 2]
    assert P[bag, 1].min() > P[lm["2.1"], 1] and P[bag, 1].max() < P[lm["9.15"], 1] + 25
    # its floor goes down with the jaw, its roof (the palate) stays
    jaw = head.regions["jaw_open"].dense(head.n_vertices)[bag]
    floor, roof = bag[P[bag, 1] < P[lm["2.3"], 1] - 10], bag[P[bag, 1] > P[lm["2.2"], 1] + 10]
    assert np.median(jaw[np.isin(bag, floor)]) > 0.5 and np.median(jaw[np.isin(bag, roof)]) < 0.2


def incisal_edge_normals(head, part: str, values=None) -> np.ndarray:
    """Smooth normals (as the renderer computes them) at the incisal edge of a tooth strip's front."""
    layout = PartLayout(head)
    k = layout.parts.index(part)
    start, stop = layout.slices[k]
    used = layout.used(k)
    _points, normals = layout.points_and_normals(head.deform(values))
    P = head.vertices[used]
    front = P[:, 2] > P[:, 2].max() - 8                  # the incisors
    edge = front & (P[:, 1] < P[front, 1].min() + 0.6)   # their lowest row
    return normals[start:stop][edge]


@pytest.mark.parametrize("phone", ["a", "e", "i"])
def test_upper_incisors_face_the_viewer(head, phone):
    """The upper incisal edge is lit like the front of the teeth (its normal forward), not turned down into shadow."""
    normals = incisal_edge_normals(head, "teeth_upper", phone_values(phone))
    assert len(normals) >= 3
    assert normals[:, 2].min() > 0.7, normals.round(2).tolist()


@pytest.mark.parametrize("phone", ["a", "e", "i"])
def test_upper_incisors_show_below_the_upper_lip(head, phone):
    """At a, e, i the upper incisal edge (front) is below the upper lip's lowest point (2.2) by ≥ 1.5 mm."""
    P = head.deform(phone_values(phone))
    teeth = head.part_vertices("teeth_upper")
    front = teeth[np.abs(head.vertices[teeth, 0]) < 8]
    assert P[head.landmarks["2.2"], 1] - P[front, 1].min() >= 1.5


def tongue_front(head, P) -> np.ndarray:
    tongue = head.part_vertices("tongue")
    return tongue[head.vertices[tongue, 2] > head.vertices[tongue, 2].max() - 15]


@pytest.mark.parametrize("phone", ["a", "@", "o", "e"])
def test_the_tongue_rests_low_at_open_vowels(head, phone):
    """The front of the tongue lies below the lower incisal edge: it does not fill the lip opening."""
    P = head.deform(phone_values(phone))
    lower = head.part_vertices("teeth_lower")
    lower_edge = P[lower[head.vertices[lower, 2] > head.vertices[lower, 2].max() - 4], 1].max()
    assert P[tongue_front(head, P), 1].max() < lower_edge


@pytest.mark.parametrize("phone", ["l", "t", "d", "n"])
def test_the_tongue_tip_rises_to_the_upper_teeth_for_l_t_d_n(head, phone):
    values = phone_values(phone)
    assert values["tongue_raise"] > 0.5, "the table lifts the tongue for the tongue-tip consonants"
    P = head.deform(values)
    upper = head.part_vertices("teeth_upper")
    upper_edge = P[upper[np.abs(head.vertices[upper, 0]) < 8], 1].min()
    tip = P[tongue_front(head, P), 1].max()
    assert tip > upper_edge + 3, "the tip is up behind the upper incisors"
    rest_tip = head.deform(phone_values("a"))[tongue_front(head, P), 1].max()
    assert tip - rest_tip > 8


def test_the_raised_tongue_stays_behind_the_teeth(head):
    """At tongue_raise 1 the tongue's front stays behind the upper incisors' back (lingual) surface."""
    P = head.deform({"jaw_open": 0.14, "tongue_raise": 1.0})
    upper = head.part_vertices("teeth_upper")
    mid = upper[np.abs(head.vertices[upper, 0]) < 6]
    assert P[tongue_front(head, P), 2].max() < P[mid, 2].min()


# -- the eyelashes -------------------------------------------------------------------

LID_POSES = {
    "AU5": {"AU5_left": 1.0, "AU5_right": 1.0},
    "AU6": {"AU6_left": 1.0, "AU6_right": 1.0},
    "AU7": {"AU7_left": 1.0, "AU7_right": 1.0},
    "AU41": {"eyelid_left_close": 0.4, "eyelid_right_close": 0.4},
    "blink": {"eyelid_left_close": 1.0, "eyelid_right_close": 1.0},
    "AU6+AU7+AU12": {"AU6_left": 1.0, "AU6_right": 1.0, "AU7_left": 1.0, "AU7_right": 1.0,
                     "AU12_left": 1.0, "AU12_right": 1.0},
}


def lashes_and_lid_skin(head, side: str) -> tuple[np.ndarray, np.ndarray]:
    """The lash vertices of one eye, and for each the nearest skin vertex at rest (on its lid)."""
    lashes = head.part_vertices(f"eyelashes_{side}")
    skin = head.part_vertices("skin")
    P = head.vertices
    nearest = skin[np.argmin(np.linalg.norm(P[lashes][:, None] - P[skin][None], axis=2), axis=1)]
    return lashes, nearest


def skin_normals(head, positions) -> np.ndarray:
    """Per-vertex outward skin normals as the renderer computes them (zero off the skin)."""
    layout = PartLayout(head)
    k = layout.parts.index("skin")
    start, stop = layout.slices[k]
    _points, normals = layout.points_and_normals(positions)
    out = np.zeros((head.n_vertices, 3))
    out[layout.used(k)] = normals[start:stop]
    return out


@pytest.mark.parametrize("side", ["left", "right"])
def test_lashes_are_thin_fringes_on_the_lids(head, side):
    """Every lash vertex is within 3 mm of its lid's skin, and none lies under the skin (no shards in it)."""
    lashes, nearest = lashes_and_lid_skin(head, side)
    P = head.vertices
    offset = P[lashes] - P[nearest]
    assert np.linalg.norm(offset, axis=1).max() < 3.0
    depth = np.einsum("ij,ij->i", offset, skin_normals(head, P)[nearest])
    # (measured along the nearest skin vertex's normal, which at the sharp lid margin points down:
    # a lash beside it reads up to 0.25 mm "under"; MakeHuman's lower cards went 0.86 mm into the skin)
    assert depth.min() > -0.3, f"{np.sum(depth < -0.3)} lash vertices under the skin (down to {depth.min():.2f} mm)"


@pytest.mark.parametrize("pose", sorted(LID_POSES))
def test_lashes_move_with_the_lids(head, pose):
    """In every lid pose each lash vertex keeps its distance to the lid skin nearest to it (within 0.5 mm)."""
    P0, P1 = head.vertices, head.deform(LID_POSES[pose])
    for side in ("left", "right"):
        lashes, nearest = lashes_and_lid_skin(head, side)
        before = np.linalg.norm(P0[lashes] - P0[nearest], axis=1)
        after = np.linalg.norm(P1[lashes] - P1[nearest], axis=1)
        assert np.abs(after - before).max() < 0.5, f"{side}: up to {np.abs(after - before).max():.2f} mm"


@pytest.mark.parametrize("pose", ["rest", "AU5", "AU7", "AU6+AU7+AU12"])
def test_the_upper_lash_stays_above_the_lid_margin(head, pose):
    """Over the pupil the upper lashes never hang below the upper lid margin (3.1 / 3.2): they do not cross the iris."""
    P = head.deform(LID_POSES.get(pose, {}))
    for side, margin in (("left", "3.1"), ("right", "3.2")):
        lashes = head.part_vertices(f"eyelashes_{side}")
        pupil_x = head.vertices[head.landmarks["3.5" if side == "left" else "3.6"], 0]
        over_pupil = lashes[(np.abs(head.vertices[lashes, 0] - pupil_x) < 3)
                            & (head.vertices[lashes, 1] > head.vertices[head.landmarks["3.5"], 1])]
        assert len(over_pupil) > 0
        assert P[over_pupil, 1].min() > P[head.landmarks[margin], 1] - 0.2
