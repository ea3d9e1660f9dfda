"""The identity package's error."""

from __future__ import annotations

from engine.errors import UserError


class IdentityError(UserError):
    """An identity that cannot be made: an unknown parameter, a value out of range, a bad identity file."""
