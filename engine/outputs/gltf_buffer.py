"""The binary buffer of a glTF file: arrays packed one bufferView each, with their accessors.

>>> import numpy as np
>>> buffer = GltfBuffer()
>>> buffer.add(np.zeros((3, 3), np.float32), None), buffer.accessors[0]["type"], len(buffer.data())
(0, 'VEC3', 36)
"""

from __future__ import annotations

import numpy as np

#: glTF component types (the accessor's ``componentType``).
_FLOAT, _UBYTE, _USHORT, _UINT = 5126, 5121, 5123, 5125


class GltfBuffer:
    """The binary buffer, one bufferView per array, each aligned to 4 bytes."""

    def __init__(self) -> None:
        self.chunks: list[bytes] = []
        self.length = 0
        self.views: list[dict[str, int]] = []
        self.accessors: list[dict[str, object]] = []

    def add(self, array: np.ndarray, target: int | None, bounds: bool = True, kind: str | None = None) -> int:
        array = np.ascontiguousarray(array)
        data = array.astype(array.dtype.newbyteorder("<"), copy=False).tobytes()
        view = {"buffer": 0, "byteOffset": self.length, "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self.views.append(view)
        pad = -len(data) % 4
        self.chunks.append(data + b"\0" * pad)
        self.length += len(data) + pad
        component = {np.dtype(np.float32): _FLOAT, np.dtype(np.uint8): _UBYTE, np.dtype(np.uint16): _USHORT,
                     np.dtype(np.uint32): _UINT}[array.dtype]
        accessor: dict[str, object] = {
            "bufferView": len(self.views) - 1, "componentType": component, "count": int(array.shape[0]),
            "type": kind or ("SCALAR" if array.ndim == 1 else f"VEC{array.shape[1]}")}
        if bounds and len(array):
            flat = array.reshape(len(array), -1)
            # float32 values written as Python floats: the JSON numbers round-trip to the same float32
            accessor["min"] = [_json_number(v) for v in flat.min(axis=0)]
            accessor["max"] = [_json_number(v) for v in flat.max(axis=0)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def add_bytes(self, data: bytes) -> int:
        """A bufferView of raw bytes with no accessor (an embedded image); returns the view's index."""
        self.views.append({"buffer": 0, "byteOffset": self.length, "byteLength": len(data)})
        pad = -len(data) % 4
        self.chunks.append(data + b"\0" * pad)
        self.length += len(data) + pad
        return len(self.views) - 1

    def data(self) -> bytes:
        return b"".join(self.chunks)


def _json_number(v: np.integer | np.floating) -> int | float:
    return int(v) if isinstance(v, np.integer) else float(v)
