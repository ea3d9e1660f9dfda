"""Articulatory parameters (§3.1.2) as displacement fields, and the lip contact they must respect.

A stage of ``derive_default_head.py``: :func:`articulation` makes
``mouth_widen``, ``lip_protrude``, ``upper_lip_raise`` and ``lower_lip_raise``
from the artist's mouth poses, fitted so that the lips close without passing
through each other (:class:`engine.identity.lip_contact.LipContact`, which fits
them again on every identity's face). Lengths are mm.
"""

from __future__ import annotations

import numpy as np
from head_geometry import smoothstep

from engine import Parameter
from engine.identity.lip_contact import LipContact, fit_closure, follow_upper_lip, keep_lips_apart

CLOSURE_CLEARANCE = 0.15    # mm left between the lips where they meet (closure, and the other fields' checks)


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
