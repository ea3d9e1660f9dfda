"""What the photo-fit wizard's pages share: the photographs, the points placed on them and the fit.

>>> session = PhotoFitSession(None)
>>> sorted(session.photos), session.fit is None
([], True)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import engine
    from engine.photofit import PhotoFit

TITLE = "New head from photographs"
VIEWS = ("front", "side")


@dataclass
class PhotoFitSession:
    """``current`` is the document's model: its landmarks are the first guesses when it has the default head's."""

    current: engine.Model | None
    photos: dict[str, np.ndarray] = field(default_factory=dict)
    paths: dict[str, Path] = field(default_factory=dict)
    points: dict[str, dict[str, tuple[float, float]]] = field(default_factory=dict)
    fit: PhotoFit | None = None
    find_points: bool = True                   # the front photograph's points found by dlib (else a first guess)

    def landmark_head(self) -> engine.Model:
        """The head whose landmarks are placed: the current one if it has every landmark the default head has."""
        from ..identity_panel.heads import default_head

        default = default_head()
        current = self.current
        if current is not None and set(default.landmarks) <= set(current.landmarks):
            return current
        return default
