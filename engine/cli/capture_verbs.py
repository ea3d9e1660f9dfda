"""The ``capture`` verbs: ``capture animate`` (ARKit / OpenFace / MediaPipe streams onto the head)."""

from __future__ import annotations

from typing import Any


def add_verbs(verbs: Any) -> None:
    """Add ``capture`` and its steps to the CLI's sub-parsers."""
    p = verbs.add_parser("capture", help="face-capture streams (ARKit, OpenFace, MediaPipe) onto the head")
    p.add_subparsers(dest="capture_step", metavar="STEP", required=True)
