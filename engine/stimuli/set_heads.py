"""The heads of a stimulus set, made again from the design it was made from (``web-export --stimuli``).

>>> heads = DesignHeads(load_design("identities.toml"), "set")                 # doctest: +SKIP
>>> key, model = heads("0002")                                                 # doctest: +SKIP
"""

from __future__ import annotations

import json
from pathlib import Path

from engine.errors import UserError
from engine.model.model import Model
from engine.stimuli.design import Design
from engine.stimuli.heads import head_key, stimulus_head
from engine.stimuli.manifest import PROVENANCE


class DesignHeads:
    """The heads of a set's stimuli, made again from the design the set was made from.

    ``heads(stimulus_id)`` is ``(key, model)``; stimuli with one key share one head. The design must
    be the one in the set's ``provenance.json`` (its SHA-256), else :class:`UserError` naming it.
    """

    def __init__(self, design: Design, set_folder: str | Path) -> None:
        self.design = design
        self._levels = {stimulus.id: stimulus.levels for stimulus in design.stimuli}
        _check_made_from(design, Path(set_folder))

    def __call__(self, stimulus_id: str) -> tuple[str, Model]:
        levels = self._levels.get(stimulus_id)
        if levels is None:
            raise UserError(f"the design has no stimulus {stimulus_id!r}: is it the design the set was made from?",
                            file=self.design.path)
        return head_key(levels), stimulus_head(self.design, levels)


def _check_made_from(design: Design, set_folder: Path) -> None:
    record = set_folder / PROVENANCE
    try:
        made_from = json.loads(record.read_text(encoding="utf-8"))["design"]["sha256"]
    except (OSError, ValueError, KeyError, TypeError):
        return                            # no record to check against: the stimulus ids are checked instead
    if made_from != design.sha256:
        raise UserError(f"not the design this set was made from ({record} names a design with SHA-256 "
                        f"{str(made_from)[:12]}…, this one is {design.sha256[:12]}…)", file=design.path)


__all__ = ["DesignHeads"]
