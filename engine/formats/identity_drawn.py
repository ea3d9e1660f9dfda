"""How a random person was drawn, in a model file: ``<identity>``'s optional ``<drawn>`` element.

``<drawn population="1" seed="7" given="sex=female;age=20-40"/>`` says which population model
(:mod:`engine.identity.population`) drew the identity's values, with which seed, and what was
asked besides; the values themselves are the ``<value>`` elements, so the head is made again
from them alone. The schema checks the version and the seed (whole numbers, the seed 0 …
2³²−1); the reader checks ``given``'s form.
"""

from __future__ import annotations

import re
from pathlib import Path

from lxml import etree

from engine.errors import ModelFileError
from engine.formats.xml_io import source_line
from engine.model.identity_record import IdentityRecord

_GIVEN = re.compile(r"[A-Za-z][A-Za-z0-9._-]*=[^;=]+")


class DrawnIdentityRecord(IdentityRecord):
    """An identity record of a person drawn at random: ``drawn`` holds the ``population`` model's version,
    the ``seed`` and what was ``given``, as strings."""

    def __init__(self, values: dict[str, float], source: str, drawn: dict[str, str]) -> None:
        super().__init__(values, source)
        self.drawn: dict[str, str] | None = drawn


def read_drawn(identity: etree._Element, record: IdentityRecord, path: Path) -> IdentityRecord:
    """``record``, as a :class:`DrawnIdentityRecord` where ``<identity>`` has a ``<drawn>``."""
    drawn = identity.find("drawn")
    if drawn is None:
        return record
    given = drawn.get("given", "")
    if given and not all(_GIVEN.fullmatch(item) for item in given.split(";")):
        raise ModelFileError("the drawn identity's 'given' must be NAME=VALUE items separated by ';'",
                             file=path, line=source_line(drawn))
    return DrawnIdentityRecord(record.values, record.source, {
        "population": str(int(drawn.get("population", ""))), "seed": str(int(drawn.get("seed", ""))),
        "given": given})


def write_drawn(identity: etree._Element, record: IdentityRecord) -> None:
    """A ``<drawn>`` in ``<identity>`` when ``record`` was drawn at random (its ``drawn`` is set)."""
    drawn = getattr(record, "drawn", None)
    if not drawn:
        return
    el = etree.SubElement(identity, "drawn", population=str(int(drawn["population"])), seed=str(int(drawn["seed"])))
    if drawn.get("given"):
        el.set("given", str(drawn["given"]))
