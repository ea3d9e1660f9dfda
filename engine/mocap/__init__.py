"""Motion capture (§3.1): import marker files, derive articulatory parameters by multistage PCA.

Import (this package's readers) turns a marker file — Qualisys QTM TSV, C3D,
TRC or plain CSV — into a :class:`~engine.mocap.session.Session`: markers
named by MPEG-4 feature point ids, lengths in mm, short gaps filled, head
motion removed, optional phone labels. ``docs/mocap.md`` describes the
formats, the mapping file and the session file.

>>> from engine.mocap.importer import import_marker_file          # doctest: +SKIP
>>> session = import_marker_file("take1.tsv", max_gap_ms=100)     # doctest: +SKIP
"""

from engine.mocap.errors import LabelFileError, MarkerFileError, MocapError, SessionFileError
from engine.mocap.session import Session, load_session, save_session

__all__ = [
           "LabelFileError",
           "MarkerFileError",
           "MocapError",
           "Session",
           "SessionFileError",
           "load_session",
           "save_session",
]
