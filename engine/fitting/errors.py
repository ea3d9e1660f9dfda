"""The error of fitting, and the suggestion its messages make for a misspelt name.

>>> suggest_name("jawOpn", ["jawOpen", "mouthClose"])
" (did you mean 'jawOpen'?)"
"""

from __future__ import annotations

import difflib
from collections.abc import Sequence

from engine.errors import UserError


class FittingError(UserError):
    """A pose, region or option that cannot be fitted."""


def suggest_name(name: str, known: Sequence[str]) -> str:
    """`` (did you mean 'X'?)`` with the closest of ``known``, else `` (known: …)``: the end of a message."""
    close = difflib.get_close_matches(name, list(known), n=1)
    return f" (did you mean '{close[0]}'?)" if close else f" (known: {', '.join(known)})"
