"""The default head's MPEG-4 feature points, found from the geometry and the artist's poses.

A stage of ``derive_default_head.py``. Lengths are mm.
"""

from __future__ import annotations

import numpy as np


def find_landmarks(vertices, part_of, new_index, mirror, source, target, left_eye_centre):
    """MPEG-4 feature points as vertex indices, found from the geometry and the artist poses.

    Subject's left is +X; right-side points are the hm08 mirror images of the left ones.
    """
    skin = part_of["skin"]
    P = vertices
    mid = skin[np.abs(P[skin, 0]) < 1e-6]
    jaw = np.linalg.norm(target("faceunits01/targets/faceunits/jawOpen.target"), axis=1)
    jmax = jaw.max()
    nose_tip = mid[np.argmax(P[mid, 2])]
    lm = {"9.3": nose_tip}
    # Lips on the midline: upper lip = barely moved by jawOpen, lower lip = moved a lot.
    front = mid[(P[mid, 1] < P[nose_tip, 1]) & (P[mid, 1] > P[nose_tip, 1] - 60)]
    front = front[P[front, 2] > P[nose_tip, 2] - 25]
    upper = front[jaw[front] < 0.1 * jmax]
    lower = front[jaw[front] > 0.5 * jmax]
    upper_front = upper[P[upper, 2] > np.percentile(P[front, 2], 40)]
    lm["2.2"] = upper_front[np.argmin(P[upper_front, 1])]                 # lowest point of the upper lip
    lower_front = lower[P[lower, 2] > P[lm["2.2"], 2] - 3]
    lm["2.3"] = lower_front[np.argmax(P[lower_front, 1])]                 # highest point of the lower lip
    # Subnasale: the deepest point of the profile between the nose tip and the lip contact.
    between = mid[(P[mid, 1] < P[nose_tip, 1]) & (P[mid, 1] > P[lm["2.2"], 1]) & (P[mid, 2] > P[lm["2.2"], 2])]
    lm["9.15"] = between[np.argmin(P[between, 2])]
    # Outer lip midpoints: the most protruding points of each lip on the midline.
    upper_lip = upper_front[(P[upper_front, 1] < P[lm["9.15"], 1]) & (P[upper_front, 1] >= P[lm["2.2"], 1])]
    lm["8.1"] = upper_lip[np.argmax(P[upper_lip, 2])]
    lip_lower_front = lower[(P[lower, 1] > P[lm["2.3"], 1] - 15)]
    lm["8.2"] = lip_lower_front[np.argmax(P[lip_lower_front, 2])]
    # Chin: bottom (2.1) is the lowest midline point that moves with the jaw; boss (2.10) the most forward.
    chin = mid[(jaw[mid] > 0.7 * jmax) & (P[mid, 1] < P[lm["8.2"], 1] - 15)]
    lm["2.1"] = chin[np.argmin(P[chin, 1])]
    boss = chin[P[chin, 1] < P[lm["8.2"], 1] - 12]
    lm["2.10"] = boss[np.argmax(P[boss, 2])]
    # Lip corners: the outermost front vertices where upper and lower lip meet (half-moved by jawOpen).
    mouth = skin[(P[skin, 1] < P[lm["9.15"], 1]) & (P[skin, 1] > P[lm["2.10"], 1]) & (P[skin, 0] > 0)
                 & (P[skin, 2] > P[lm["2.2"], 2] - 25)]
    smile = np.linalg.norm(target("faceunits01/targets/faceunits/mouthSmileLeft.target"), axis=1)
    corner_cands = mouth[(np.abs(P[mouth, 1] - (P[lm["2.2"], 1] + P[lm["2.3"], 1]) / 2) < 5)]
    lm["8.3"] = corner_cands[np.argmax(smile[corner_cands])]
    c = P[lm["8.3"]]

    def nearest(cands, point):
        return cands[np.argmin(np.linalg.norm(P[cands] - point, axis=1))]

    upper_side = mouth[jaw[mouth] < 0.15 * jmax]
    lower_side = mouth[jaw[mouth] > 0.45 * jmax]
    for key, lip, mid_key in (("8.5", upper_side, "8.1"), ("8.7", lower_side, "8.2")):
        m = P[lm[mid_key]]
        goal = np.array([c[0] / 2, c[1] + 0.8 * (m[1] - c[1])])       # in the frontal (x, y) plane
        outer_lip = lip[P[lip, 2] > c[2]]                                # on the outer surface
        lm[key] = outer_lip[np.argmin(np.linalg.norm(P[outer_lip, :2] - goal, axis=1))]
    # Inner lip corner (2.4) next to the outer one, a little inside the mouth.
    lm["2.4"] = nearest(mouth[P[mouth, 0] < c[0]], c + np.array([-2.0, 0.0, -2.0]))
    # Eyes.
    eye = part_of["eye_left"]
    lm["3.5"] = eye[np.argmax(P[eye, 2])]
    radius = np.linalg.norm(P[eye] - left_eye_centre, axis=1).mean()
    near_eye = skin[(np.abs(np.linalg.norm(P[skin] - left_eye_centre, axis=1) - radius) < 2.5)
                    & (P[skin, 2] > left_eye_centre[2])]
    right_eye = part_of["eye_right"]
    lm["3.6"] = right_eye[np.argmax(P[right_eye, 2])]
    pupil = P[lm["3.5"]]
    column = near_eye[np.abs(P[near_eye, 0] - pupil[0]) < 3]
    above, below = column[P[column, 1] > pupil[1]], column[P[column, 1] < pupil[1]]
    lm["3.1"] = above[np.argmin(P[above, 1])]
    lm["3.3"] = below[np.argmax(P[below, 1])]
    lm["3.7"] = near_eye[np.argmax(P[near_eye, 0])]     # outer corner of the left eye
    lm["3.11"] = near_eye[np.argmin(P[near_eye, 0])]    # inner corner of the left eye
    # Brows: inner end moves most in browInnerUp, outer end in browOuterUpLeft, top is the highest brow vertex.
    inner = np.linalg.norm(target("faceunits01/targets/faceunits/browInnerUp.target"), axis=1)
    outer = np.linalg.norm(target("faceunits01/targets/faceunits/browOuterUpLeft.target"), axis=1)
    left_skin = skin[P[skin, 0] > 5]
    lm["4.1"] = left_skin[np.argmax(inner[left_skin] * (P[left_skin, 0] < pupil[0]))]
    lm["4.5"] = left_skin[np.argmax(outer[left_skin])]
    raise_ = inner + outer
    column = left_skin[(np.abs(P[left_skin, 0] - pupil[0]) < 3) & (P[left_skin, 1] > pupil[1])]
    lm["4.3"] = column[np.argmax(raise_[column])]          # the brow is where the brow raise moves most
    # Nose wings: the left nostril border moves most in the nostril dilatation unit; 9.5 is the
    # lowest point of the left wing.
    dil = target("mpfb2/targets/expression/units/caucasian/nose-left-dilatation.target.gz")
    dil = np.linalg.norm(dil, axis=1)
    lm["9.1"] = left_skin[np.argmax(dil[left_skin])]
    wing = left_skin[dil[left_skin] > 0.3 * dil.max()]
    lm["9.5"] = wing[np.argmin(P[wing, 1])]
    # Right side: mirror images in the hm08 mesh.
    pairs = {"8.3": "8.4", "8.5": "8.6", "8.7": "8.8", "2.4": "2.5", "3.1": "3.2",
             "3.3": "3.4", "3.7": "3.12", "3.11": "3.8", "4.1": "4.2", "4.3": "4.4", "4.5": "4.6",
             "9.1": "9.2", "9.5": "9.4"}
    for left, right in pairs.items():
        lm[right] = int(new_index[mirror[int(source[lm[left]])]])
        assert lm[right] >= 0, f"mirror of landmark {left} is not in the head"
    return {k: int(v) for k, v in lm.items()}
