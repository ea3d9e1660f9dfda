"""Articulatory parameters (§3.1.2) as displacement fields, and the lip contact they must respect.

A stage of ``derive_default_head.py``: :func:`articulation` makes
``mouth_widen``, ``lip_protrude``, ``upper_lip_raise`` and ``lower_lip_raise``
from the artist's mouth poses, fitted so that the lips close without passing
through each other (:class:`~lip_contact.LipContact`). Lengths are mm.
"""

from __future__ import annotations

import numpy as np
from head_geometry import smoothstep
from lip_contact import SECTION_SPAN, LipContact

from engine import Parameter

CLOSURE_CLEARANCE = 0.15    # mm left between the lips where they meet (closure, and the other fields' checks)
FOLLOW_DEPTH = 4.5          # mm below the mouth line over which the lower lip follows the upper lip (protrusion)


def _largest(predicate, lo: float, hi: float, steps: int = 25) -> float:
    """The largest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``lo``)."""
    if not predicate(lo):
        raise RuntimeError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if predicate(mid) else (lo, mid)
    return lo


def _smallest(predicate, lo: float, hi: float, steps: int = 14) -> float:
    """The smallest value in [lo, hi] for which ``predicate`` holds (bisection; it must hold at ``hi``)."""
    if predicate(lo):
        return lo
    if not predicate(hi):
        raise RuntimeError("lip contact: no value in the search range clears the lips")
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if predicate(mid) else (mid, hi)
    return hi


def smooth_nodes(values, passes: int = 1):
    """[1 2 1]/4 smoothing of values on nodes x = 0, h, 2h, … (mirrored at 0, flat at the end)."""
    v = np.asarray(values, dtype=float)
    for _ in range(passes):
        p = np.r_[v[1], v, v[-1]]
        v = (p[:-2] + 2 * p[1:-1] + p[2:]) / 4
    return v


def fit_closure(contact: LipContact, region, forward, clearance, nodes: int = 25, iterations: int = 4):
    """The lower-lip closure field: ``region · (0, lift(|x|), forward)``, ``lift`` fitted section by
    section so that the lower lip just meets the upper lip (``clearance`` apart, never crossing)."""
    rest = contact.rest
    xs = np.linspace(0, SECTION_SPAN * contact.half_width(rest), nodes)
    x_abs = np.abs(rest[:, 0])
    up = region[:, None] * np.array([0.0, 1.0, 0.0])

    def field(lift, shift=0.0):
        T = np.zeros((len(rest), 3))
        T[:, 1] = np.interp(x_abs, xs, lift) - shift
        T[:, 2] = forward
        return region[:, None] * T

    lift = np.zeros(nodes)
    for _ in range(iterations):
        P = rest + field(lift)
        extra = [_largest(lambda v, P=P, x=x: contact.section_clear(P + v * up, x + 1e-4, clearance),
                          -6.0, 6.0)
                 for x in xs]
        lift = lift + smooth_nodes(extra)
    # one common downward shift, if needed, so that the sections between the nodes clear as well
    shift = _smallest(lambda s: contact.clear(rest + field(lift, s), clearance), 0.0, 3.0)
    return field(lift, shift), lift


def follow_upper_lip(contact: LipContact, D, closed, depth=FOLLOW_DEPTH, k: int = 3):
    """``D`` with the lower lip near the mouth line moving like the upper lip it touches when closed.

    ``closed`` are the positions with the lips closed (rest + closure field): each lower-lip
    vertex takes the motion of its nearest upper-lip contact vertices there, fully at the
    mouth line and fading out ``depth`` mm below it, so a field that moves both lips keeps
    them in contact the way closure left them."""
    from scipy.spatial import cKDTree

    rest, lower, upper = contact.rest, contact.lower_lip, contact.upper_contact
    dist, idx = cKDTree(closed[upper]).query(closed[lower], k=list(range(1, k + 1)))
    w = 1.0 / np.maximum(dist, 0.3)
    w /= w.sum(axis=1, keepdims=True)
    partner = np.einsum("nk,nkc->nc", w, D[upper][idx])
    b = 1.0 - smoothstep((contact.mouth_line(rest[lower, 0]) - rest[lower, 1]) / depth)
    out = D.copy()
    out[lower] = (1 - b[:, None]) * D[lower] + b[:, None] * partner
    return out


def keep_lips_apart(contact: LipContact, D, clearance, companions, adjacency, lower_side, rounds: int = 20):
    """``D`` with the lower lip lowered wherever ``D`` (alone, and added to each companion field)
    would push it into the upper lip; the lowering spreads over three rings of neighbours."""
    rest = contact.rest
    lowered = np.zeros(len(rest))
    for _ in range(rounds):
        out = D.copy()
        out[:, 1] -= lowered
        owed = np.zeros(len(rest))
        for extra in companions:
            owed = np.maximum(owed, contact.overlap(rest + out + extra, clearance))
        if owed.max() < 1e-3 and all(contact.clear(rest + out + extra, 0.0) for extra in companions):
            return out, float(lowered.max())
        step = owed + 0.02 * (owed > 0)
        for _ in range(3):
            neighbours = adjacency.multiply(step[None, :]).max(axis=1).toarray().ravel()
            step = np.where(lower_side, np.maximum(step, 0.7 * neighbours), 0.0)
        lowered += step
    raise RuntimeError("lip contact: could not keep the lips apart")


def articulation(vertices, triangles, is_skin, jaw_share, landmarks, target, adjacency):
    """The articulatory parameters of §3.1.2 as displacement fields fitted to the artist's poses.

    Returns ``(parameters, fields, summary)``: ``fields[name]`` is an (n, 3) mm field for value 1.
    """
    arkit = "faceunits01/targets/faceunits/"
    contact = LipContact(vertices, triangles, is_skin, jaw_share, landmarks)
    lm, P0 = landmarks, vertices
    # Speech moves the lower face only (§3.1.2: jaw, lips and their surroundings): the artist's fields
    # fade out between 10 mm above the nose tip and 5 mm below the lower eyelid, and only skin moves.
    y0, y1 = P0[lm["9.3"], 1] + 10.0, P0[lm["3.3"], 1] - 5.0
    lower_face = (1.0 - smoothstep((P0[:, 1] - y0) / (y1 - y0))) * is_skin

    def pose(*names):
        return sum(target(arkit + n + ".target") for n in names) * lower_face[:, None]

    # lower_lip_raise: the region of the artist's mouthShrugLower (AU17 pushes the lower lip up
    # and forward), carried straight forward until the lower lip's midpoint is under the upper
    # lip's (2.3 under 2.2), and lifted section by section until the lips just meet.
    shrug = np.linalg.norm(target(arkit + "mouthShrugLower.target"), axis=1)
    region = np.clip(shrug / shrug[lm["2.3"]], 0.0, 1.0) * is_skin * ~contact.upper_vertex
    forward = float(P0[lm["2.2"], 2] - P0[lm["2.3"], 2])
    closure, lift = fit_closure(contact, region, forward, CLOSURE_CLEARANCE)
    closed = P0 + closure

    lower_side = is_skin & ~contact.upper_vertex
    companions = [np.zeros_like(P0), closure]        # each field alone, and with the lips closed

    def apart(D):
        return keep_lips_apart(contact, D, CLOSURE_CLEARANCE, companions, adjacency, lower_side)

    # mouth_widen: both mouthStretch, plus the share of both mouthSmile that keeps the corners level
    stretch, smile = pose("mouthStretchLeft", "mouthStretchRight"), pose("mouthSmileLeft", "mouthSmileRight")
    smile_share = float(-(stretch[lm["8.3"], 1] + stretch[lm["8.4"], 1]) / (smile[lm["8.3"], 1] + smile[lm["8.4"], 1]))
    widen, widen_lowered = apart(stretch + smile_share * smile)
    # lip_protrude: mouthPucker; its lower lip follows the upper lip it touches when closed, and is
    # lowered where the artist's pose presses the lips into each other.
    protrude, protrude_lowered = apart(follow_upper_lip(contact, pose("mouthPucker"), closed))
    # upper_lip_raise: mouthUpperUp, both sides
    upper, upper_lowered = apart(pose("mouthUpperUpLeft", "mouthUpperUpRight"))

    fields = {"mouth_widen": widen, "lip_protrude": protrude, "upper_lip_raise": upper,
              "lower_lip_raise": closure}

    def at(D, key):
        return (P0 + D)[lm[key]]

    def gap(D):
        return float(np.linalg.norm(at(D, "2.2") - at(D, "2.3")))

    def corners(D):
        return float(np.linalg.norm(at(D, "8.3") - at(D, "8.4")) - np.linalg.norm(P0[lm["8.3"]] - P0[lm["8.4"]]))

    z81, z82 = (float(protrude[lm[k], 2]) for k in ("8.1", "8.2"))
    y22 = float(upper[lm["2.2"], 1])
    parameters = [
        Parameter("mouth_widen", "translation", parent="head_tilt", field=True, minimum=-0.5, maximum=1.2,
                  description=f"Mouth widening (§3.1.2): lip corners out and back; 1 = the artist's mouthStretch "
                              f"(both sides) + {smile_share:.2f} × mouthSmile (corners level): corners "
                              f"{corners(widen):+.1f} mm apart; − narrows."),
        Parameter("lip_protrude", "translation", parent="head_tilt", field=True, minimum=-0.5, maximum=1.2,
                  description=f"Lip protrusion and rounding (§3.1.2); 1 = the artist's mouthPucker: lips "
                              f"{z81:.1f} / {z82:.1f} mm forward (8.1 / 8.2), corners {corners(protrude):+.1f} mm; "
                              "the lips keep touching as closure left them; − retracts."),
        Parameter("upper_lip_raise", "translation", parent="head_tilt", field=True, minimum=0.0, maximum=1.2,
                  description=f"Upper lip raise (AU10); 1 = the artist's mouthUpperUp, both sides: the upper lip's "
                              f"midpoint {y22:.1f} mm up."),
        Parameter("lower_lip_raise", "translation", parent="jaw_open", field=True, minimum=-0.5, maximum=1.0,
                  description=f"Lower lip raise / lip closure; 1 = the lower lip meets the upper lip (with "
                              f"jaw_open 0: inner lip gap {gap(np.zeros_like(P0)):.1f} → {gap(closure):.1f} mm, "
                              f"lower lip {forward:.1f} mm forward); − drops it back."),
    ]
    summary = {
        "contact": contact, "closure_lift": lift, "forward": forward, "smile_share": smile_share,
        "lowered": {"mouth_widen": widen_lowered, "lip_protrude": protrude_lowered,
                    "upper_lip_raise": upper_lowered},
        "gap": {n: gap(D) for n, D in fields.items()}, "corners": {n: corners(D) for n, D in fields.items()},
    }
    return parameters, fields, summary
