"""The retargeting tables: capture channels → the head's parameters, each entry with its reason.

A parameter's value is the sum of ``weight × channel`` over its entries
(rotation channels are converted by angle instead, :mod:`engine.capture.retarget`).
``docs/capture-streams.md`` prints these tables; the test suite checks the
geometric claims (jaw, lids, lip corners, head and eye signs) on the default head.

>>> sorted({target for _, target, _, _ in ARKIT_TABLE if target.startswith("eyelid")})
['eyelid_left_close', 'eyelid_right_close']
"""

from __future__ import annotations

Entry = tuple[str, str, float, str]
"""(channel, parameter, weight, reason)."""


def _sides(channel: str, target: str, weight: float, reason: str) -> list[Entry]:
    """The same entry for the subject's left and right (``{side}``/``{Side}`` in the names)."""
    return [(channel.format(Side=s.capitalize()), target.format(side=s), weight, reason) for s in ("left", "right")]


ARKIT_TABLE: list[Entry] = [
    *_sides("eyeBlink{Side}", "eyelid_{side}_close", 1.0, "blink 1 = lid shut; eyelid_*_close 1 shuts the lid"),
    *_sides("eyeWide{Side}", "AU5_{side}", 0.74, "eyeWide is FACS AU5, upper lid raiser; AU5 at 1 is FACS intensity "
           "E, the artist's pose × 1.35 (fit: 0.735)"),
    *_sides("eyeSquint{Side}", "AU7_{side}", 1.0, "eyeSquint is FACS AU7, lid tightener"),
    ("browInnerUp", "AU1_left", 0.6, "browInnerUp is AU1 (inner brow raiser), one shape for both sides; AU1 at 1 "
                                     "is FACS intensity E, the artist's pose × 1.6 with forehead lines (fit: 0.604)"),
    ("browInnerUp", "AU1_right", 0.6, "as above, right side"),
    *_sides("browOuterUp{Side}", "AU2_{side}", 0.79, "outer brow raiser, AU2; at 1 the artist's pose × 1.25 "
           "(fit: 0.786)"),
    *_sides("browDown{Side}", "AU4_{side}", 0.84, "brow lowerer, AU4; at 1 the artist's pose × 1.2 with the "
           "glabellar furrows (fit: 0.84)"),
    *_sides("cheekSquint{Side}", "AU6_{side}", 0.69, "cheek raiser, AU6; at 1 the artist's pose × 1.4 with the "
           "lower lid's bag (fit: 0.688)"),
    *_sides("noseSneer{Side}", "AU9_{side}_nose", 0.59, "nose wrinkler AU9, split into nose and brow; the nose part "
           "is 1.7 × ARKit's sneer (docs/default-head.md)"),
    *_sides("noseSneer{Side}", "AU9_{side}_brow", 1.0, "AU9's pull on the brow"),
    ("jawOpen", "jaw_open", 1.0, "jawOpen 1 = jaw fully dropped; jaw_open 1 is the head's full opening"),
    ("mouthClose", "jaw_open", -1.0, "lips sealed over the open jaw (the reference poses: jawOpen + mouthClose "
                                     "= the rest lip gap); the head's lips follow its jaw, so the jaw gives it back"),
    *_sides("mouthSmile{Side}", "AU12_{side}", 1.0, "lip corner puller, AU12"),
    *_sides("mouthFrown{Side}", "AU15_{side}", 0.8, "lip corner depressor, AU15; at 1 the artist's pose × 1.25 "
           "(fit: 0.798)"),
    *_sides("mouthStretch{Side}", "AU20_{side}", 0.73, "lip stretcher, AU20; at 1 the artist's pose × 1.4 "
           "(fit: 0.726)"),
    *_sides("mouthPress{Side}", "AU24_{side}", 1.0, "lip pressor, AU24"),
    *_sides("mouthLowerDown{Side}", "AU16_{side}", 1.0, "lower lip depressor, AU16"),
    *_sides("mouthUpperUp{Side}", "AU10_{side}", 1.0, "upper lip raiser, AU10 (fit to the reference pose: 0.99)"),
    ("mouthShrugLower", "lower_lip_raise", 1.0, "the lower lip pushed up (fit to the reference pose: 1.05)"),
    ("mouthShrugLower", "AU17", 0.3, "by the chin raiser AU17 (fit: 0.29)"),
    ("mouthShrugUpper", "AU10_middle", 0.8, "the middle of the upper lip rises (fit: 0.83)"),
    ("mouthShrugUpper", "AU17", 0.2, "with the chin pushing up (fit: 0.17)"),
    ("mouthPucker", "lip_protrude", 1.0, "pucker (AU18) pushes the lips forward (fit: 0.99)"),
    ("mouthFunnel", "lip_protrude", 0.5, "funneler (AU22) pushes the lips forward (fit: 0.48)"),
    *_sides("mouthFunnel", "AU16_{side}", 0.5, "and parts them, the lower lip down (fit: 0.50, 0.48)"),
]
"""ARKit / MediaPipe blendshapes (both name the same 52 shapes). Where a blendshape needs more than one
parameter, the weights are a non-negative least-squares fit of those parameters' displacements to the
default head's own ARKit reference pose of that shape (``engine.fitting.reference_poses``), rounded. So are
those of the action units scaled to FACS intensity E (``E_GAIN`` in engine/data/default-head/action_units.py): an AU
at 1 moves more than the artist's pose the ARKit shape is, so the shape at 1 is the AU below 1."""

ARKIT_LOST = {
    "jawForward": "the head has no jaw thrust", "jawLeft": "the head has no sideways jaw",
    "jawRight": "the head has no sideways jaw",
    "mouthLeft": "the head has no sideways mouth", "mouthRight": "the head has no sideways mouth",
    "mouthDimpleLeft": "dimpler AU14 is not on the head", "mouthDimpleRight": "dimpler AU14 is not on the head",
    "mouthRollLower": "lip suck AU28 is not on the head", "mouthRollUpper": "lip suck AU28 is not on the head",
    "cheekPuff": "the head has no cheek puffer (AU34)", "tongueOut": "the head's tongue does not protrude",
}
"""Blendshapes with no parameter, and why (warned about when a take uses them)."""

EYE_LOOK_RAD = {"turn": 0.607, "raise": 0.556}
"""Radians of eye turn (and raise) for an eyeLook shape at 1: the slope of Live Link Face's own eye
angles against ``eyeLookOut − eyeLookIn`` (and ``eyeLookUp − eyeLookDown``) over a 4030-frame range-of-motion
take (correlation −0.999), used where a stream has no angles (MediaPipe)."""

OPENFACE_TABLE: list[Entry] = [
    ("AU01", "AU1_left", 0.2, "intensity 0–5 (FACS A–E) → 0–1, as the library's A–E levels"),
    ("AU01", "AU1_right", 0.2, "OpenFace scores both sides together"),
    *_sides("AU02", "AU2_{side}", 0.2, "outer brow raiser"),
    *_sides("AU04", "AU4_{side}", 0.2, "brow lowerer"),
    *_sides("AU05", "AU5_{side}", 0.2, "upper lid raiser"),
    *_sides("AU06", "AU6_{side}", 0.2, "cheek raiser"),
    *_sides("AU07", "AU7_{side}", 0.2, "lid tightener"),
    *_sides("AU09", "AU9_{side}_nose", 0.2, "nose wrinkler (nose part)"),
    *_sides("AU09", "AU9_{side}_brow", 0.2, "nose wrinkler (brow part)"),
    *_sides("AU10", "AU10_{side}", 0.2, "upper lip raiser"),
    ("AU10", "AU10_middle", 0.2, "upper lip raiser (middle)"),
    *_sides("AU12", "AU12_{side}", 0.2, "lip corner puller"),
    *_sides("AU15", "AU15_{side}", 0.2, "lip corner depressor"),
    ("AU17", "AU17", 0.2, "chin raiser"),
    *_sides("AU20", "AU20_{side}", 0.2, "lip stretcher"),
    ("AU23", "AU23", 0.2, "lip tightener"),
    ("AU25", "jaw_open", 0.02, "lips part: E (5) → jaw_open 0.1, the opening that parts the lips"),
    ("AU26", "jaw_open", 0.07, "jaw drop: E (5) → jaw_open 0.35, as the library's Surprise"),
    ("AU45", "eyelid_left_close", 0.2, "blink: E (5) → the lid shut"),
    ("AU45", "eyelid_right_close", 0.2, "blink, right eye"),
]
"""OpenFace 2 ``AUxx_r`` intensities."""

OPENFACE_LOST = {"AU14": "dimpler AU14 is not on the head"}

ROTATION_TARGETS = {
    "head_turn_rad": "head_turn", "head_nod_rad": "head_nod", "head_tilt_rad": "head_tilt",
    "eye_left_turn_rad": "eye_left_turn", "eye_left_raise_rad": "eye_left_raise",
    "eye_right_turn_rad": "eye_right_turn", "eye_right_raise_rad": "eye_right_raise",
}
"""Rotation channels → the rotation parameter that carries them (value = angle / degrees-per-unit,
signed by the parameter's axis)."""
