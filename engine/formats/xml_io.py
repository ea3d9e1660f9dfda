"""Safe XML reading shared by every file format the toolkit reads.

Model descriptions and command files are XML that may come from anywhere, so
the parser expands no entities, loads no DTD and never touches the network.
A document that declares entities or names an external DTD is refused with a
clear error rather than read with the entity references left empty (none of
our formats uses them). Files are read whole with a bound
(:mod:`engine.formats.text_files`). Syntax and schema errors become a :class:`~engine.errors.UserError` (or the
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
from engine.formats.text_files import read_bounded_bytes

SCHEMA_DIR = Path(__file__).parent / "schemas"


def safe_xml_parser() -> etree.XMLParser:
    """An lxml parser that expands no entities, loads no DTD and never touches the network."""
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           dtd_validation=False, huge_tree=False, remove_blank_text=False)


def parse_xml(path: str | Path, error: type[UserError] = UserError) -> etree._ElementTree:
    """Parse an XML file safely; a syntax error becomes ``error`` with file:line."""
    return parse_xml_bytes(read_bounded_bytes(path, error=error), Path(path), error)


def parse_xml_text(text: str | bytes, name: str | Path = "<text>",
                   error: type[UserError] = UserError) -> etree._ElementTree:
    """Parse XML held in memory; ``name`` is what error messages call it."""
    data = text.encode("utf-8") if isinstance(text, str) else text
    return parse_xml_bytes(data, name, error)


def parse_xml_bytes(data: bytes, name: str | Path, error: type[UserError] = UserError) -> etree._ElementTree:
    """Parse XML bytes safely; ``name`` is what error messages call the document."""
    try:
        doc = etree.ElementTree(etree.fromstring(data, safe_xml_parser()))
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if exc.lineno else None
        msg = exc.msg.split(", line ")[0] if exc.msg else "malformed XML"
        raise error(f"malformed XML: {msg}", file=name, line=line) from None
    except ValueError as exc:  # e.g. a str with an encoding declaration
        raise error(f"malformed XML: {exc}", file=name) from None
    start = data.find(b"<!DOCTYPE")
    refuse_entities(doc, name, error, data[:start].count(b"\n") + 1 if start >= 0 else None)
    return doc


def refuse_entities(doc: etree._ElementTree, name: str | Path, error: type[UserError] = UserError,
                    doctype_line: int | None = None) -> None:
    """Refuse a document whose DTD is external or declares entities, or that holds an entity reference.

    Entities are never expanded (that is how XML reads files off the disk or
    the network), and an undeclared one in an attribute reads as an empty
    string: a file relying on them would be read wrongly in silence.

    >>> refuse_entities(parse_xml_text("<commands/>"), "ok.xml")
    >>> parse_xml_text('<!DOCTYPE commands SYSTEM "cmds.dtd"><commands/>', "ext.xml")
    Traceback (most recent call last):
    engine.errors.UserError: ext.xml:1: the file names an external DTD ('cmds.dtd'); entities and DTDs are not \
read (write the content out in the file)
    """
    info = doc.docinfo
    root = doc.getroot()
    line = source_line(root)
    # lxml-stubs leave out DocInfo.system_url and DTD.iterentities, which lxml has had since 2.x and 3.x
    external = info.system_url or info.public_id  # type: ignore[attr-defined]
    if external:
        raise error(f"the file names an external DTD ('{external}'); entities and DTDs are not read "
                    "(write the content out in the file)", file=name, line=doctype_line)
    dtd = info.internalDTD
    declared = list(dtd.iterentities()) if dtd is not None else []  # type: ignore[attr-defined]
    if declared:
        raise error("the file declares entities in its DTD; entities are not expanded "
                    "(write the content out in the file)", file=name, line=doctype_line)
    for reference in root.iter(etree.Entity):
        raise error(f"entity reference {reference.text} is not expanded (write the content out in the file)",
                    file=name, line=source_line(reference) or line)


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
