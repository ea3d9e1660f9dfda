"""The error a bad photograph or landmark file causes."""

from __future__ import annotations

from engine.errors import UserError


class PhotoFitError(UserError):
    """A photograph or POINTS.json that cannot be used: one line naming the file."""
