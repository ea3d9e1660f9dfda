"""Head pose from MediaPipe's facial transformation matrix (``output_facial_transformation_matrixes=True``).

The matrix takes MediaPipe's canonical face (+X the subject's left, +Y up, +Z
out of the face: the head frame of :mod:`engine.capture.stream`) into its
metric camera space (camera at the origin looking down −Z, +Y up, +X to the
image's right). For a face looking into the camera it is the identity, so
its rotation is the head's rotation in the head frame. That rotation is split
as the default head's tree turns: ``R = R_y(turn) · R_x(nod) · R_z(tilt)``
(the nod is a child of the turn, the tilt of the nod). A mirrored (selfie)
image reverses turn and tilt, as MediaPipe says it swaps Left and Right.

Serialised, a matrix is ``{"rows": 4, "columns": 4, "data": [16 numbers]}``
(the JavaScript API; ``data`` column-major as MediaPipe's ``MatrixData``
packs it by default) or a list of 4 rows of 4 (the Python API's numpy array
through ``tolist()``). A flat ``data`` whose bottom row is not ``0 0 0 1``
but whose last column is, is read row-major.

>>> import numpy as np
>>> turn = 0.3                                                # towards the subject's left
>>> rows = [[np.cos(turn), 0, np.sin(turn), 0], [0, 1, 0, 0], [-np.sin(turn), 0, np.cos(turn), -40], [0, 0, 0, 1]]
>>> (np.round(head_angles(matrix_rows(rows, "m")), 6) + 0.0).tolist()    # + 0.0: no -0.0
[0.3, 0.0, 0.0]
"""

from __future__ import annotations

from typing import Any

import numpy as np

from engine.capture.stream import CaptureFileError

ANGLE_CHANNELS = ("head_turn_rad", "head_nod_rad", "head_tilt_rad")


def matrix_rows(value: Any, where: str, source: str = "", line: int | None = None) -> np.ndarray:
    """A serialised 4×4 matrix as a row-major (4, 4) array, or a :class:`CaptureFileError`."""
    if isinstance(value, dict):
        data = value.get("data")
        if value.get("rows", 4) != 4 or value.get("columns", 4) != 4 or not _numbers(data, 16):
            raise CaptureFileError(f"{where}: a transformation matrix is not 4×4 numbers", file=source, line=line)
        flat = np.array(data, dtype=float)
        column_major = flat.reshape(4, 4).T
        row_major = flat.reshape(4, 4)
        if np.allclose(column_major[3], [0, 0, 0, 1]) or not np.allclose(row_major[3], [0, 0, 0, 1]):
            matrix = column_major
        else:
            matrix = row_major
    elif isinstance(value, list) and len(value) == 4 and all(_numbers(row, 4) for row in value):
        matrix = np.array(value, dtype=float)
    else:
        raise CaptureFileError(f"{where}: a transformation matrix is neither {{\"data\": [16]}} nor 4 rows of 4",
                               file=source, line=line)
    if not np.all(np.isfinite(matrix)):
        raise CaptureFileError(f"{where}: a transformation matrix holds a non-finite number", file=source, line=line)
    rotation = matrix[:3, :3]
    scale = np.linalg.norm(rotation, axis=0)
    if np.any(scale < 1e-9) or abs(np.linalg.det(rotation / scale)) < 0.5:
        raise CaptureFileError(f"{where}: the transformation matrix is not a rotation (and scale)",
                               file=source, line=line)
    return matrix


def head_angles(matrix: np.ndarray) -> np.ndarray:
    """(turn, nod, tilt) in radians of the matrix's rotation, split as ``R_y · R_x · R_z``."""
    u, _, vt = np.linalg.svd(matrix[:3, :3])
    rotation = u @ vt                                   # the nearest rotation, scale removed
    nod = np.arcsin(np.clip(-rotation[1, 2], -1.0, 1.0))
    turn = np.arctan2(rotation[0, 2], rotation[2, 2])
    tilt = np.arctan2(rotation[1, 0], rotation[1, 1])
    return np.array([turn, nod, tilt])


def _numbers(values: Any, count: int) -> bool:
    return (isinstance(values, list) and len(values) == count
            and all(isinstance(v, int | float) and not isinstance(v, bool) and abs(v) < 1e300 for v in values))
