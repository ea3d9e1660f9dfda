"""What a model file records of the person a head was made for (``<identity>``; see :mod:`engine.identity`).

The record is the identity parameter values that differ from the defaults
and the version of the shape data they were applied to, so the head can be
made again exactly. :class:`engine.identity.Identity` is the validated kind.
"""

from __future__ import annotations

from collections.abc import Mapping


class IdentityRecord:
    """Identity parameter ``values`` (name → value, defaults left out) and the ``source`` shape data's version."""

    def __init__(self, values: Mapping[str, float] | None = None, source: str = "") -> None:
        self.values: dict[str, float] = {str(k): float(v) for k, v in (values or {}).items()}
        self.source = source

    def __eq__(self, other: object) -> bool:
        return isinstance(other, IdentityRecord) and self.values == other.values

    def __hash__(self) -> int:
        return hash(tuple(self.values.items()))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.values!r})"
