"""The 52 ARKit face blendshapes, in Apple's order and camelCase spelling.

Live Link Face capitalises the first letter (``EyeBlinkLeft``); MediaPipe's
Face Landmarker uses these names as they are and adds ``_neutral``. Left and
Right are the subject's sides (Apple's ``ARFaceAnchor.BlendShapeLocation`` and
MediaPipe's ``FaceLandmarkerResult`` both say so).

>>> len(ARKIT_BLENDSHAPES), ARKIT_BLENDSHAPES[0], ARKIT_BLENDSHAPES[-1]
(52, 'eyeBlinkLeft', 'tongueOut')
>>> canonical_blendshape("EyeBlinkLeft"), canonical_blendshape("nope")
('eyeBlinkLeft', None)
"""

from __future__ import annotations

ARKIT_BLENDSHAPES: tuple[str, ...] = (
    "eyeBlinkLeft", "eyeLookDownLeft", "eyeLookInLeft", "eyeLookOutLeft", "eyeLookUpLeft", "eyeSquintLeft",
    "eyeWideLeft", "eyeBlinkRight", "eyeLookDownRight", "eyeLookInRight", "eyeLookOutRight", "eyeLookUpRight",
    "eyeSquintRight", "eyeWideRight", "jawForward", "jawRight", "jawLeft", "jawOpen", "mouthClose",
    "mouthFunnel", "mouthPucker", "mouthRight", "mouthLeft", "mouthSmileLeft", "mouthSmileRight",
    "mouthFrownLeft", "mouthFrownRight", "mouthDimpleLeft", "mouthDimpleRight", "mouthStretchLeft",
    "mouthStretchRight", "mouthRollLower", "mouthRollUpper", "mouthShrugLower", "mouthShrugUpper",
    "mouthPressLeft", "mouthPressRight", "mouthLowerDownLeft", "mouthLowerDownRight", "mouthUpperUpLeft",
    "mouthUpperUpRight", "browDownLeft", "browDownRight", "browInnerUp", "browOuterUpLeft", "browOuterUpRight",
    "cheekPuff", "cheekSquintLeft", "cheekSquintRight", "noseSneerLeft", "noseSneerRight", "tongueOut",
)
_BY_LOWER = {name.lower(): name for name in ARKIT_BLENDSHAPES}


def canonical_blendshape(name: str) -> str | None:
    """The camelCase name of blendshape ``name`` in any capitalisation, or None."""
    return _BY_LOWER.get(name.lower())
