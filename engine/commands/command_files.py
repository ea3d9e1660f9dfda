"""Command files in XML: high-level commands in, low-level activations out (§2.3).

High level::

    <commands>
      <HeadNod at="1000" amplitude="60" count="2"/>
      <Blink at="1800"/>
      <activate parameter="jaw_open" interp="cosine">     <!-- a low-level command, passed through -->
        <key at="0" value="0"/><key at="300" value="0.4"/><key at="600" value="0"/>
      </activate>
    </commands>

Low level — the paper prints ``<HeadNod at="1000" amplitude="0" at="1166.5" …>``
with repeated attributes, which XML forbids; the same information (parameter,
ordered time/value keys, interpolation) is carried as::

    <low-level-commands format="artificial-person-low-level-commands" version="1">
      <activate parameter="head_nod" interp="linear" command="HeadNod" line="amplitude" source="in.xml:2">
        <key at="1000" value="0"/>
        <key at="1166.5" value="0.09"/>
        …
      </activate>
    </low-level-commands>

Both are validated against ``engine/formats/schemas/commands.xsd``; parsing is safe
against hostile XML, and every error names the file and line.

>>> from engine.commands.command_files import parse_commands_text
>>> parse_commands_text('<commands><HeadNod at="1000" count="2"/></commands>')[0]
HighLevelCommand(name='HeadNod', arguments={'at': 1000.0, 'count': 2.0}, file='<text>', line=1)
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import cast

import numpy as np
from lxml import etree

from engine.commands.limits import LimitProblem, check_time, check_value
from engine.errors import CommandError
from engine.formats.atomic import atomic_write_text
from engine.formats.xml_io import parse_xml, parse_xml_text, source_line, validate

SCHEMA_NAME = "commands.xsd"
LOW_LEVEL_ROOT = "low-level-commands"
LOW_LEVEL_FORMAT = "artificial-person-low-level-commands"
LOW_LEVEL_VERSION = 1
HIGH_LEVEL_ROOT = "commands"
_WHOLE_NUMBER = re.compile(r"[0-9]{1,18}")     # ASCII digits, few enough for int() to take
ACTIVATE = "activate"


@dataclass
class HighLevelCommand:
    """One high-level command as written: its name, numeric arguments, and where it stands."""

    name: str
    arguments: dict[str, float]
    file: str = "<text>"
    line: int | None = None
    column: int | None = field(default=None, repr=False)
    """Set for an inline command in a script: where on its line the tag starts."""

    def where(self) -> dict:
        return {"file": self.file, "line": self.line}

    def error(self, message: str) -> CommandError:
        """A :class:`CommandError` about this command, at its file, line and (inline) column."""
        prefix = f"column {self.column}: " if self.column is not None else ""
        return CommandError(prefix + message, **self.where())


@dataclass
class Activation:
    """A low-level command: one parameter's time course as keys (ms, parameter units).

    Outside its first and last key an activation contributes nothing; keys
    may share a time (a jump), never go back in time.
    """

    parameter: str
    times: np.ndarray
    values: np.ndarray
    interpolation: str = "linear"
    command: str | None = None
    """The high-level command it was translated from, if any."""
    line: str | None = None
    """The library line it comes from (``amplitude``, ``eye_left_turn`` …), if any."""
    source: str | None = None
    """``file:line`` of the command it came from, for messages and for the reader of the file."""
    file: str | None = field(default=None, compare=False)
    line_number: int | None = field(default=None, compare=False)
    """Where this activation itself was read from (low-level files)."""

    def __post_init__(self) -> None:
        self.times = np.asarray(self.times, dtype=float)
        self.values = np.asarray(self.values, dtype=float)

    @property
    def start(self) -> float:
        return float(self.times[0])

    @property
    def end(self) -> float:
        return float(self.times[-1])

    def where(self) -> dict:
        if self.file is not None:
            return {"file": self.file, "line": self.line_number}
        if self.source:
            file, _, line = self.source.rpartition(":")
            if _WHOLE_NUMBER.fullmatch(line):       # not str.isdigit: '²' is a digit that int() refuses
                return {"file": file, "line": int(line)}
            return {"file": self.source, "line": None}
        return {"file": None, "line": None}


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

def read_commands(path: str | Path) -> list[HighLevelCommand | Activation]:
    """Every command in a high- or low-level command file, in document order."""
    return _commands(parse_xml(path, CommandError), str(path))


def parse_commands_text(text: str | bytes, name: str = "<text>") -> list[HighLevelCommand | Activation]:
    """Like :func:`read_commands` for XML held in a string (``name`` appears in messages)."""
    return _commands(parse_xml_text(text, name, CommandError), name)


def _commands(doc: etree._ElementTree, name: str) -> list[HighLevelCommand | Activation]:
    root = doc.getroot()
    if root.tag not in (HIGH_LEVEL_ROOT, LOW_LEVEL_ROOT):
        raise CommandError(f"not a command file: the root element is <{root.tag}>, expected <{HIGH_LEVEL_ROOT}> "
                           f"or <{LOW_LEVEL_ROOT}>", file=name, line=source_line(root))
    version = root.get("version")
    if version is not None and _newer_version(version):
        shown = version if len(version) <= 20 else version[:20] + "…"
        raise CommandError(f"command file format version {shown} is newer than this program reads "
                           f"({LOW_LEVEL_VERSION})", file=name, line=source_line(root))
    validate(doc, SCHEMA_NAME, name, CommandError)
    out: list[HighLevelCommand | Activation] = []
    for element in root:
        if not isinstance(element.tag, str):
            continue                       # comments and processing instructions
        if element.tag == ACTIVATE:
            out.append(_activation(element, name))
        else:
            out.append(_high_level(element, name))
    return out


def _newer_version(version: str) -> bool:
    """Whether a format version (ASCII digits, any number of them) is newer than the one this program reads."""
    digits = version.strip().lstrip("0")
    return digits.isascii() and digits.isdigit() and (len(digits) > 18 or int(digits) > LOW_LEVEL_VERSION)


def _high_level(element: etree._Element, name: str) -> HighLevelCommand:
    if len([c for c in element if isinstance(c.tag, str)]) or (element.text or "").strip():
        raise CommandError(f"<{element.tag}> holds content; a high-level command has only attributes",
                           file=name, line=source_line(element))
    arguments: dict[str, float] = {}
    attributes = cast(Mapping[str, str], element.attrib)     # lxml-stubs say str | bytes; Python 3 lxml gives str
    for key, text in attributes.items():
        if "}" in key:
            raise CommandError(f"<{element.tag}>: attribute '{key}' has a namespace; command arguments have none",
                               file=name, line=source_line(element))
        arguments[key] = _number(text, f"<{element.tag}> argument {key}", name, source_line(element))
    return HighLevelCommand(element.tag, arguments, name, source_line(element))


def _activation(element: etree._Element, name: str) -> Activation:
    times: list[float] = []
    values: list[float] = []
    for key in element:
        if not isinstance(key.tag, str):
            continue
        t = _number(key.get("at"), "key time 'at'", name, source_line(key))
        v = _number(key.get("value"), "key 'value'", name, source_line(key))
        try:
            check_time(t, "key time 'at'")
            check_value(v, "key 'value'")
        except LimitProblem as exc:
            raise CommandError(str(exc), file=name, line=source_line(key)) from None
        if times and t < times[-1]:
            raise CommandError(f"key times must not decrease: at={t:g} comes after at={times[-1]:g}",
                               file=name, line=source_line(key))
        times.append(t)
        values.append(v)
    parameter = element.get("parameter")
    if parameter is None:              # the schema requires it; this guards against a mistake
        raise CommandError(f"<{element.tag}> has no 'parameter' attribute", file=name, line=source_line(element))
    return Activation(parameter, np.array(times), np.array(values),
                      element.get("interp", "linear"), element.get("command"), element.get("line"),
                      element.get("source"), file=name, line_number=source_line(element))


def _number(text: str | None, what: str, file: str, line: int | None) -> float:
    try:
        value = float(text or "")     # None (a missing attribute) fails as "" does
    except (TypeError, ValueError):
        raise CommandError(f"{what} is not a number: '{text}'", file=file, line=line) from None
    if not math.isfinite(value):
        raise CommandError(f"{what} must be a finite number, not '{text}'", file=file, line=line)
    return value


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------

def low_level_xml(activations: list[Activation]) -> str:
    """The low-level command file for ``activations`` as text."""
    root = etree.Element(LOW_LEVEL_ROOT, format=LOW_LEVEL_FORMAT, version=str(LOW_LEVEL_VERSION))
    root.text = "\n  "
    for i, act in enumerate(activations):
        el = etree.SubElement(root, ACTIVATE, parameter=act.parameter, interp=act.interpolation)
        for attribute in ("command", "line", "source"):
            if getattr(act, attribute):
                el.set(attribute, str(getattr(act, attribute)))
        el.text = "\n    "
        for k, (t, v) in enumerate(zip(act.times, act.values, strict=True)):
            key = etree.SubElement(el, "key", at=format_number(t), value=format_number(v))
            key.tail = "\n    " if k < len(act.times) - 1 else "\n  "
        el.tail = "\n  " if i < len(activations) - 1 else "\n"
    if not activations:
        root.text = "\n"
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8").decode("utf-8") + "\n"


def write_low_level(activations: list[Activation], path: str | Path) -> None:
    """Write a low-level command file atomically."""
    atomic_write_text(path, low_level_xml(activations))


def format_number(x: float) -> str:
    """Shortest text for a time or value, to 12 significant digits: ``1166.5``, ``0.09``, ``-0.015``."""
    text = f"{float(x):.12g}"
    return "0" if text == "-0" else text
