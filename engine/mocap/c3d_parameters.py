"""The header and parameter section of a C3D file, read by our own parser.

A C3D file is 512-byte blocks: the header (block 1), the parameter section
(groups such as ``POINT`` and ``ANALOG`` holding typed parameters such as
``POINT:LABELS``) and the frames. Numbers are stored in the processor format
the parameter section names: Intel (little-endian IEEE), DEC (little-endian
integers, VAX floats) or MIPS/SGI (big-endian IEEE).

We parse it ourselves because the readers we measured each fail on some real
files (docs/capture-files.md): a group defined twice, a frame count held in
two 16-bit words, parameters that disagree with the header. The parser keeps
within the section's bytes, merges groups of the same name and stops at the
first record that cannot be right instead of raising whatever it hits.

>>> import struct
>>> header = C3dHeader.from_bytes(bytes([2, 0x50]) + bytes(510), "<")
>>> header.parameter_block
2
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from engine.mocap.errors import MarkerFileError

PROCESSORS = {84: "INTEL", 85: "DEC", 86: "MIPS"}
"""The fourth byte of the parameter section names the processor format."""


def vax_to_ieee(raw: bytes | np.ndarray) -> np.ndarray:
    """DEC (VAX F) floats, 4 bytes each, as float32: swap the 16-bit halves, then divide by 4.

    >>> float(vax_to_ieee(bytes([0x80, 0x40, 0, 0]))[0])   # VAX 1.0
    1.0
    """
    data = np.frombuffer(bytes(raw), dtype=np.uint8).reshape(-1, 4)
    swapped = data[:, [2, 3, 0, 1]].copy().view("<f4").ravel()
    with np.errstate(invalid="ignore"):  # a signalling NaN in a damaged file is just NaN
        return (swapped.astype(np.float64) / 4.0).astype(np.float32)


def decode_floats(raw: bytes, processor: str) -> np.ndarray:
    """Floats of the file's processor format as float64 (NaN bit patterns of any kind become NaN quietly)."""
    if processor == "DEC":
        singles = vax_to_ieee(raw)
    else:
        singles = np.frombuffer(raw, dtype=(">" if processor == "MIPS" else "<") + "f4")
    with np.errstate(invalid="ignore"):
        return singles.astype(np.float64)


def int_order(processor: str) -> str:
    """The byte order of the file's integers for numpy (``<`` or ``>``)."""
    return ">" if processor == "MIPS" else "<"


@dataclass
class C3dHeader:
    """The header block's words (the parameter section may override most of them)."""

    parameter_block: int
    point_count: int
    analog_per_frame: int
    first_frame: int
    last_frame: int
    scale: float
    data_block: int
    rate: float

    @classmethod
    def from_bytes(cls, block: bytes, order: str, processor: str = "INTEL") -> C3dHeader:
        words = np.frombuffer(block[:24], dtype=order + "u2").astype(int)
        floats = decode_floats(block[12:16] + block[20:24], processor)
        return cls(parameter_block=block[0], point_count=int(words[1]), analog_per_frame=int(words[2]),
                   first_frame=int(words[3]), last_frame=int(words[4]), scale=float(floats[0]),
                   data_block=int(words[8]), rate=float(floats[1]))


@dataclass
class C3dParameter:
    """One parameter: its type (-1 text, 1 byte, 2 int16, 4 float), dimensions and raw bytes."""

    kind: int
    dims: tuple[int, ...]
    raw: bytes
    processor: str

    def numbers(self) -> np.ndarray:
        """The values as a flat float array (bytes unsigned, int16 signed)."""
        if self.kind == 1:
            return np.frombuffer(self.raw, dtype=np.uint8).astype(float)
        if self.kind == 2:
            return np.frombuffer(self.raw, dtype=int_order(self.processor) + "i2").astype(float)
        if self.kind == 4:
            return decode_floats(self.raw, self.processor)
        return np.zeros(0)

    def unsigned_words(self) -> np.ndarray:
        """Int16 values read as unsigned (frame counts above 32767 are written that way)."""
        if self.kind == 2:
            return np.frombuffer(self.raw, dtype=int_order(self.processor) + "u2").astype(float)
        return self.numbers()

    def strings(self) -> list[str]:
        """Text values: one string per column of a (length, count, …) array, NULs and blanks stripped."""
        if self.kind != -1:
            return [_number_text(v) for v in self.numbers()]
        text = self.raw.decode("latin-1")
        width = self.dims[0] if self.dims else len(text)
        if width == 0:
            return []
        return [text[k:k + width].replace("\0", " ").strip() for k in range(0, len(text), width)]

    def first_number(self) -> float | None:
        values = self.numbers()
        return float(values[0]) if values.size else None


@dataclass
class C3dParameters:
    """The parameter section: ``"GROUP:NAME"`` → :class:`C3dParameter`; ``notes`` say what was repaired."""

    processor: str
    values: dict[str, C3dParameter] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def get(self, key: str) -> C3dParameter | None:
        return self.values.get(key.upper())

    def number(self, key: str) -> float | None:
        param = self.get(key)
        return None if param is None else param.first_number()


def read_parameters(data: bytes, path: Path) -> tuple[C3dHeader, C3dParameters]:
    """Parse the header and parameter section of a whole C3D file's bytes."""
    if len(data) < 512 or data[1] != 0x50:
        raise MarkerFileError("not a C3D file: the first block does not start with the C3D key (80)", file=path)
    start = (data[0] - 1) * 512
    if data[0] < 2 or start + 4 > len(data):
        raise MarkerFileError(f"not a readable C3D file: the parameter section is said to start in block "
                              f"{data[0]}, outside the file", file=path)
    processor = PROCESSORS.get(data[start + 3])
    if processor is None:
        raise MarkerFileError(f"not a readable C3D file: unknown processor type {data[start + 3]} "
                              "(84 Intel, 85 DEC, 86 MIPS)", file=path)
    order = int_order(processor)
    header = C3dHeader.from_bytes(data[:512], order, processor)
    end = _section_end(data, start, header)
    params = C3dParameters(processor)
    _parse_records(data, start + 4, end, order, params)
    return header, params


def _section_end(data: bytes, start: int, header: C3dHeader) -> int:
    """Where the parameter section ends: at the data (some writers count its blocks short), else by its count."""
    data_start = (header.data_block - 1) * 512
    if start < data_start <= len(data):
        return data_start
    return min(len(data), start + 512 * data[start + 2]) if data[start + 2] else len(data)


def _parse_records(data: bytes, pos: int, end: int, order: str, params: C3dParameters) -> None:
    groups: dict[int, str] = {}
    pending: list[tuple[int, str, C3dParameter]] = []
    while pos + 4 <= end:
        name_length = abs(_signed(data[pos]))
        group_id = _signed(data[pos + 1])
        if name_length == 0:
            break
        name = data[pos + 2:pos + 2 + name_length].decode("latin-1").strip().upper()
        link = pos + 2 + name_length
        if link + 2 > end:
            params.notes.append("the parameter section ends inside a record")
            break
        offset = int(np.frombuffer(data[link:link + 2], dtype=order + "i2")[0])
        body = link + 2
        if group_id < 0:
            if -group_id in groups and groups[-group_id] != name:
                params.notes.append(f"group number {-group_id} defined twice ({groups[-group_id]}, {name})")
            groups.setdefault(-group_id, name)
        elif group_id > 0:
            param = _parameter(data, body, end, params.processor)
            if param is None:
                params.notes.append(f"parameter {name} runs past the parameter section")
                break
            pending.append((group_id, name, param))
        if offset == 0:
            break
        if offset < 0 or body - 2 + offset <= pos:
            params.notes.append(f"the record after {name} is linked backwards; stopped there")
            break
        pos = link + offset
    repeated = []
    for group_id, name, param in pending:
        key = f"{groups.get(group_id, f'GROUP{group_id}')}:{name}"
        if key in params.values:
            repeated.append(key)
            continue
        params.values[key] = param
    if repeated:
        names = list(dict.fromkeys(repeated))
        params.notes.append(f"{len(names)} parameter(s) defined more than once ({', '.join(names[:3])}"
                            f"{', …' if len(names) > 3 else ''}); the first definition kept")


def _parameter(data: bytes, pos: int, end: int, processor: str) -> C3dParameter | None:
    if pos + 2 > end:
        return None
    kind = _signed(data[pos])
    n_dims = data[pos + 1]
    dims = tuple(data[pos + 2:pos + 2 + n_dims])
    size = abs(kind) * int(np.prod(dims, dtype=np.int64)) if kind in (-1, 1, 2, 4) else 0
    start = pos + 2 + n_dims
    if start + size > end:
        return None
    return C3dParameter(kind, dims, data[start:start + size], processor)


def _number_text(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else str(value)


def _signed(byte: int) -> int:
    return byte - 256 if byte > 127 else byte
