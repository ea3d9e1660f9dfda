"""Reading marker files: format detection and the dispatch to the reader of each format.

Every reader returns a :class:`~engine.mocap.recording.Recording`: the
file's own marker labels, positions in millimetres with NaN wherever the file
has no sample (QTM's ``0 0 0`` triplets, C3D's negative residuals, empty or
NaN cells in TRC and CSV), and the frame rate as the file states it. Naming,
gap filling and head alignment come later (``engine.mocap.importer``).

>>> from engine.mocap.readers import read_marker_file
>>> rec = read_marker_file("take1.tsv")                 # doctest: +SKIP
>>> rec.positions.shape, rec.rate_hz                    # doctest: +SKIP
((600, 32, 3), 60.0)
"""

from __future__ import annotations

from pathlib import Path

from engine.mocap.c3d_file import read_c3d
from engine.mocap.csv_table import CsvLayout, read_csv
from engine.mocap.errors import MarkerFileError
from engine.mocap.qtm_tsv import read_qtm_tsv
from engine.mocap.recording import Recording
from engine.mocap.trc import read_trc

FORMATS = ("tsv", "c3d", "trc", "csv")
FORMAT_NAMES = {"tsv": "Qualisys QTM TSV", "c3d": "C3D", "trc": "TRC", "csv": "CSV"}


def detect_format(path: str | Path) -> str:
    """The format of a marker file from its content, else its extension: ``tsv``, ``c3d``, ``trc`` or ``csv``."""
    path = Path(path)
    head = _head_bytes(path)
    if len(head) >= 512 and head[1] == 0x50 and not 32 <= head[0] < 127:  # C3D: block pointer, then key 80
        return "c3d"
    text = head.decode("latin-1").lstrip("\ufeff\xef\xbb\xbf")
    first = text.split("\n", 1)[0].strip()
    key = first.split("\t", 1)[0].split(" ", 1)[0].split(",", 1)[0].upper()   # a TRC saved comma-separated too
    if key == "PATHFILETYPE":
        return "trc"
    if key in ("NO_OF_FRAMES", "FILE_VERSION", "NO_OF_CAMERAS", "NO_OF_MARKERS"):
        return "tsv"
    suffix = path.suffix.lower().lstrip(".")
    if suffix in FORMATS:
        return suffix
    if suffix == "txt" and "," in first:
        return "csv"
    raise MarkerFileError("unknown marker file format: not QTM TSV, C3D, TRC or CSV "
                          "(give --format tsv|c3d|trc|csv if it is one of them)", file=path, line=1)


def read_marker_file(path: str | Path, format: str = "auto", csv_layout: CsvLayout | None = None) -> Recording:
    """Read a marker file of any supported format (``format="auto"`` detects it).

    ``csv_layout`` (a :class:`engine.mocap.csv_table.CsvLayout`) says how a
    CSV file's columns map onto markers and time; other formats ignore it.
    """
    path = Path(path)
    if not path.exists():
        raise MarkerFileError("no such file", file=path)
    if path.is_dir():
        raise MarkerFileError("is a folder, not a marker file", file=path)
    if not path.is_file():
        raise MarkerFileError("is not a regular file (a device or a pipe?), not a marker file", file=path)
    fmt = detect_format(path) if format == "auto" else format
    if fmt == "tsv":
        return read_qtm_tsv(path)
    if fmt == "trc":
        return read_trc(path)
    if fmt == "c3d":
        return read_c3d(path)
    if fmt == "csv":
        return read_csv(path, csv_layout)
    raise MarkerFileError(f"unknown format '{fmt}' (use auto, {', '.join(FORMATS)})", file=path)


def _head_bytes(path: Path, n: int = 4096) -> bytes:
    try:
        with open(path, "rb") as fh:
            return fh.read(n)
    except OSError as exc:
        raise MarkerFileError(f"cannot read: {exc.strerror or exc}", file=path) from None
