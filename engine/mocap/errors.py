"""Errors a user can cause with motion-capture input.

All derive from :class:`engine.errors.UserError`, so the command line prints
them as one line, ``error: <file>:<line>: <what>``, and exits with status 2.
"""

from __future__ import annotations

from engine.errors import UserError
from engine.speech.labels import LabelFileError

__all__ = ["LabelFileError", "MarkerFileError", "MocapError", "SessionFileError"]


class MocapError(UserError):
    """A motion-capture operation cannot be done with the data or options given."""


class MarkerFileError(MocapError):
    """A marker file (QTM TSV, C3D, TRC, CSV) is truncated, malformed or of an unknown format."""


class SessionFileError(MocapError):
    """A session file is not one this program wrote, or is damaged or of an unknown version."""
