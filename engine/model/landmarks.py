"""MPEG-4 facial feature points used as landmarks (ISO/IEC 14496-2, Annex C).

Names follow the standard's numbering; "left" and "right" are the face's own
(the subject's) left and right. On the default head, the subject's left is +X.
"""

FEATURE_POINTS = {
    "2.1": "bottom of the chin",
    "2.2": "middle point of the inner upper lip contour",
    "2.3": "middle point of the inner lower lip contour",
    "2.4": "left corner of the inner lip contour",
    "2.5": "right corner of the inner lip contour",
    "2.10": "chin boss",
    "3.1": "centre of the upper inner left eyelid",
    "3.2": "centre of the upper inner right eyelid",
    "3.3": "centre of the lower inner left eyelid",
    "3.4": "centre of the lower inner right eyelid",
    "3.5": "centre of the pupil of the left eye",
    "3.6": "centre of the pupil of the right eye",
    "3.7": "left corner of the left eye",
    "3.8": "left corner of the right eye",
    "3.11": "right corner of the left eye",
    "3.12": "right corner of the right eye",
    "4.1": "right corner of the left eyebrow (inner)",
    "4.2": "left corner of the right eyebrow (inner)",
    "4.3": "uppermost point of the left eyebrow",
    "4.4": "uppermost point of the right eyebrow",
    "4.5": "left corner of the left eyebrow (outer)",
    "4.6": "right corner of the right eyebrow (outer)",
    "8.1": "middle point of the outer upper lip contour",
    "8.2": "middle point of the outer lower lip contour",
    "8.3": "left corner of the outer lip contour",
    "8.4": "right corner of the outer lip contour",
    "8.5": "upper outer lip contour, midway between 8.3 and 8.1",
    "8.6": "upper outer lip contour, midway between 8.4 and 8.1",
    "8.7": "lower outer lip contour, midway between 8.3 and 8.2",
    "8.8": "lower outer lip contour, midway between 8.4 and 8.2",
    "9.1": "left nostril border",
    "9.2": "right nostril border",
    "9.3": "nose tip",
    "9.4": "bottom right edge of the nose",
    "9.5": "bottom left edge of the nose",
    "9.15": "bottom middle edge of the nose (subnasale)",
}


def landmark_sort_key(key: str) -> tuple[tuple[int, ...], str]:
    """Sort MPEG-4 feature point ids numerically (2.2 before 2.10); other ids last, by name.

    >>> sorted(["2.10", "nose", "2.2", "10.1"], key=landmark_sort_key)
    ['2.2', '2.10', '10.1', 'nose']
    """
    try:
        return tuple(int(t) for t in key.split(".")), key
    except ValueError:
        return (10 ** 6,), key
