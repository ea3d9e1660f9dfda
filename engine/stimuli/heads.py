"""Each stimulus's head: the model file its ``model`` level names, or the head of its ``identity``.

A worker makes each head once (the identity's rig carried over, docs/identity.md) and keeps it for
the stimuli after; ``web-export --stimuli`` makes the same heads again from the design, one site
holding every head of the set (:class:`engine.stimuli.set_heads.DesignHeads`).

>>> from engine.stimuli.design import parse_design
>>> design = parse_design('[factors]\\ntext = ["Moi."]\\nidentity = [{sex = 1.0}]\\n[output]\\nkinds = ["wav"]\\n',
...                       "d.toml")
>>> head_key(design.stimuli[0].levels)
'{"identity": {"sex": 1.0}}'
>>> stimulus_head(design, design.stimuli[0].levels).identity.values["sex"]         # doctest: +SKIP
1.0
"""

from __future__ import annotations

import functools
import json
from typing import TYPE_CHECKING, Any

from engine.formats.model_files import load_model
from engine.model.model import Model
from engine.stimuli.design import Design

if TYPE_CHECKING:
    from engine.identity.hair_style import HairChoice

#: The factors that choose a stimulus's head.
HEAD_FACTORS = ("model", "identity", "identity_b", "identity_morph")


def stimulus_head(design: Design, levels: dict[str, Any]) -> Model:
    """The stimulus's head: its ``model`` file, or the head of its ``identity`` (at ``identity_morph`` % of the
    way to ``identity_b``), made on the ``model`` (default: the default head), with the hair its level asks
    for or, for a random person, the hair drawn with it."""
    base = str(design.extra_files[levels["model"]]) if "model" in levels else ""
    if "identity" not in levels and "identity_b" not in levels:
        return _model(base)
    ends = [_identity_values(design, levels.get(key, {})) for key in ("identity", "identity_b")]
    share = float(levels.get("identity_morph", 0.0)) / 100.0
    return _identity_head(base, ends[0], ends[1], share, _hair(levels.get("identity")))


def _hair(level: Any) -> HairChoice | None:
    """The hair of an identity level: what it asks for, else a random person's hair drawn with it (as
    ``identity --random`` gives it), else none. A continuum keeps its first person's hair at every step."""
    from engine.identity.hair_style import hair_from_level
    from engine.identity.population import is_random_level, level_identity
    from engine.identity.population_hair import drawn_hair

    asked = hair_from_level(level)
    if asked is None and is_random_level(level):
        return drawn_hair(level_identity(level))
    return asked


def head_key(levels: dict[str, Any]) -> str:
    """The levels that choose the head, as one string: stimuli with the same key have the same head."""
    return json.dumps({f: levels[f] for f in HEAD_FACTORS if f in levels}, sort_keys=True)


def _identity_values(design: Design, level: Any) -> tuple[tuple[str, float], ...]:
    """An identity level as sorted (name, value) pairs: a table, a random person, or the identity of a model file."""
    from engine.identity.population import is_random_level, level_identity

    if is_random_level(level):                 # {random = 1, seed = 8, population = 1}: drawn again, the same
        return tuple(sorted(level_identity(level).values.items()))
    if isinstance(level, str):
        record = _model(str(design.extra_files[level])).identity
        return tuple(sorted(record.values.items())) if record is not None else ()
    from engine.identity.hair_style import without_hair_keys

    return tuple(sorted((str(k), float(v)) for k, v in without_hair_keys(dict(level)).items()))


@functools.lru_cache(maxsize=16)
def _identity_head(base: str, a: tuple[tuple[str, float], ...], b: tuple[tuple[str, float], ...],
                   share: float, hair: HairChoice | None = None) -> Model:
    """An identity's head per worker process, made once (engine.identity: the rig carried over)."""
    from engine.identity import Identity, make_identity_head, morph

    identity = morph(Identity(dict(a)), Identity(dict(b)), share) if b or share else Identity(dict(a))
    return make_identity_head(identity, _model(base) if base else None, hair=hair)


@functools.lru_cache(maxsize=8)
def _model(path: str) -> Model:
    """A model per worker process, loaded once (the default head for ``""``)."""
    return load_model(path or None)


__all__ = ["HEAD_FACTORS", "head_key", "stimulus_head"]
