"""Hair in a model file: the ``<hair>`` element of ``<identity>``, and the names it may hold.

``<hair style="short" colour="brown" beard="stubble" brows="thick" seed="1"/>`` records the
hair a head was given (:mod:`engine.identity.hair`): the scalp ``style`` (``none`` is bald),
the ``beard``, the ``brows``' thickness, the hair ``colour`` (brows and beard share it) and the
``seed`` of the strands' layout. The geometry itself is in the arrays file, as the parts
``eyebrow_left``, ``eyebrow_right``, ``hair``, ``hair_beard`` or ``beard_stubble``; the element says what they are,
so a head can be made again. A name this program does not know is refused with the file and line.

>>> HairChoice.parse(style="short", colour="brown", beard="stubble", brows="thick").describe()
'short brown hair, stubble, thick brows'
>>> HairChoice.parse(style="mohawk")
Traceback (most recent call last):
...
engine.errors.UserError: unknown hair style 'mohawk' (styles: none, short, long, tied)
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from lxml import etree

from engine.errors import ModelFileError, UserError
from engine.formats.xml_io import source_line
from engine.model.identity_record import IdentityRecord

STYLES = ("none", "short", "long", "tied")
BEARDS = ("none", "stubble", "moustache", "beard")
BROWS = ("none", "thin", "medium", "thick")
#: sRGB of each hair colour (the strands vary around it).
COLOURS = {
    "black": (28, 24, 22),
    "dark-brown": (52, 36, 26),
    "brown": (96, 64, 40),
    "blond": (186, 152, 98),
    "red": (140, 62, 30),
    "grey": (168, 166, 162),
    "white": (222, 220, 214),
}
ALIASES = {"dark_brown": "dark-brown", "darkbrown": "dark-brown", "gray": "grey", "blonde": "blond",
           "grey-white": "grey", "ginger": "red", "auburn": "red"}
PIGMENTS = ("black", "dark-brown", "brown", "blond", "red")
SEED = 1                 # the strands' layout: the same for everyone, so a continuum's hair moves smoothly


@dataclass(frozen=True)
class HairChoice:
    """Scalp ``style``, ``beard``, ``brows`` and ``colour`` (``""``: chosen from the person), strand ``seed``."""

    style: str = "none"
    beard: str = "none"
    brows: str = "medium"
    colour: str = ""
    seed: int = SEED

    @staticmethod
    def parse(style: str | None = None, colour: str | None = None, beard: str | None = None,
              brows: str | None = None, seed: int | str | None = None) -> HairChoice:
        """A choice from names as a user writes them (case and ``_`` forgiven), or :class:`IdentityError`."""
        base = HairChoice()
        return HairChoice(
            _named(style, STYLES, "hair style", base.style), _named(beard, BEARDS, "beard", base.beard),
            _named(brows, BROWS, "brows", base.brows),
            _named(colour, tuple(COLOURS), "hair colour", "", ALIASES) if colour else "",
            base.seed if seed is None else _seed(seed))

    def with_colour(self, colour: str) -> HairChoice:
        return replace(self, colour=colour)

    @property
    def has_hair(self) -> bool:
        return self.style != "none" or self.beard != "none" or self.brows != "none"

    def describe(self) -> str:
        scalp = "bald" if self.style == "none" else f"{self.style} {self.colour or 'chosen-colour'} hair"
        beard = "no beard" if self.beard == "none" else self.beard
        brows = "no brows" if self.brows == "none" else f"{self.brows} brows"
        return f"{scalp}, {beard}, {brows}"

    def as_attributes(self) -> dict[str, str]:
        return {"style": self.style, "colour": self.colour, "beard": self.beard, "brows": self.brows,
                "seed": str(self.seed)}


def _named(value: str | None, names: tuple[str, ...], what: str, default: str,
           aliases: dict[str, str] | None = None) -> str:
    if value is None:
        return default
    text = str(value).strip().lower().replace(" ", "-")
    text = (aliases or {}).get(text, text.replace("_", "-"))
    if text not in names:
        shown = str(value) if len(str(value)) <= 30 else f"{str(value)[:30]}…"
        plural = "styles" if what == "hair style" else "colours" if what == "hair colour" else "choices"
        raise UserError(f"unknown {what} '{shown}' ({plural}: {', '.join(names)})")
    return text


def _seed(value: object) -> int:
    try:
        seed = int(str(value).strip())
    except ValueError:
        raise UserError(f"a hair seed must be a whole number 0 … 4294967295, not '{str(value)[:20]}'") from None
    if not 0 <= seed <= 2 ** 32 - 1:
        raise UserError(f"a hair seed must be a whole number 0 … 4294967295, not {seed}")
    return seed


def read_hair(identity: etree._Element, record: IdentityRecord, path: Path) -> IdentityRecord:
    """``record`` with ``.hair`` set from ``<identity>``'s ``<hair>``, if it has one (names checked)."""
    el = identity.find("hair")
    if el is None:
        return record
    try:
        record.hair = HairChoice.parse(el.get("style", "none"), el.get("colour") or None,  # type: ignore[attr-defined]
                                       el.get("beard", "none"), el.get("brows", "none"), el.get("seed") or SEED)
    except UserError as exc:
        raise ModelFileError(f"<hair>: {exc.message}", file=path, line=source_line(el)) from None
    return record


def write_hair(identity: etree._Element, record: IdentityRecord) -> None:
    """A ``<hair>`` in ``<identity>`` when ``record`` carries a hair choice."""
    hair = getattr(record, "hair", None)
    if isinstance(hair, HairChoice):
        etree.SubElement(identity, "hair", {k: v for k, v in hair.as_attributes().items() if v})
