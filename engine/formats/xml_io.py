"""Safe XML reading shared by every file format the toolkit reads.

Model descriptions and command files are XML that may come from anywhere, so
the parser expands no entities, loads no DTD and never touches the network.
Syntax and schema errors become a :class:`~engine.errors.UserError` (or the
subclass the caller names) carrying the file and line.

>>> from engine.formats.xml_io import parse_xml_text
>>> parse_xml_text("<commands><HeadNod at='1000'/></commands>", "demo.xml").getroot().tag
'commands'
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import cast

from lxml import etree

from engine.errors import UserError

SCHEMA_DIR = Path(__file__).parent / "schemas"


def safe_xml_parser() -> etree.XMLParser:
    """An lxml parser that expands no entities, loads no DTD and never touches the network."""
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           dtd_validation=False, huge_tree=False, remove_blank_text=False)


def parse_xml(path: str | Path, error: type[UserError] = UserError) -> etree._ElementTree:
    """Parse an XML file safely; a syntax error becomes ``error`` with file:line."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise error(f"cannot read file: {exc.strerror or exc}", file=path) from None
    return parse_xml_bytes(data, path, error)


def parse_xml_text(text: str | bytes, name: str | Path = "<text>",
                   error: type[UserError] = UserError) -> etree._ElementTree:
    """Parse XML held in memory; ``name`` is what error messages call it."""
    data = text.encode("utf-8") if isinstance(text, str) else text
    return parse_xml_bytes(data, name, error)


def parse_xml_bytes(data: bytes, name: str | Path, error: type[UserError] = UserError) -> etree._ElementTree:
    try:
        return etree.ElementTree(etree.fromstring(data, safe_xml_parser()))
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if exc.lineno else None
        msg = exc.msg.split(", line ")[0] if exc.msg else "malformed XML"
        raise error(f"malformed XML: {msg}", file=name, line=line) from None
    except ValueError as exc:  # e.g. a str with an encoding declaration
        raise error(f"malformed XML: {exc}", file=name) from None


def source_line(element: etree._Element) -> int | None:
    """The line ``element`` starts on in its file (None for an element built in memory)."""
    # lxml-stubs write ``sourceline = ...  # Optional[int]``, which mypy reads as an ellipsis
    return cast("int | None", element.sourceline)


@cache
def schema(name: str) -> etree.XMLSchema:
    """The XML schema ``engine/formats/schemas/<name>`` (parsed once)."""
    return etree.XMLSchema(etree.parse(str(SCHEMA_DIR / name)))


def validate(doc: etree._ElementTree, schema_name: str, name: str | Path,
             error: type[UserError] = UserError) -> None:
    """Validate ``doc`` against a schema; the first problem becomes ``error`` with file:line."""
    checker = schema(schema_name)
    try:
        valid = checker.validate(doc)
    except etree.LxmlError as exc:
        raise error(f"cannot validate: {exc}", file=name) from None
    if not valid:
        # lxml-stubs declare _ErrorLog without members; a schema's error_log is a _ListErrorLog
        err = checker.error_log.filter_from_errors()[0]  # type: ignore[attr-defined]
        raise error(schema_message(err.message), file=name, line=err.line)


def schema_message(message: str) -> str:
    """lxml's schema message without the XML Schema namespace noise."""
    return message.replace("{http://www.w3.org/2001/XMLSchema}", "xs:")
