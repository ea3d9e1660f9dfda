"""A design file's TOML read safely: whatever the text holds ends in one :class:`DesignError` naming the line.

``tomllib`` refuses malformed TOML with a line, but three things a hostile or
careless file can hold escape it: an integer of more digits than Python
converts (4,300: a ``ValueError``), arrays or tables nested a thousand deep
(a ``RecursionError``), and numbers no design means (``inf``, ``nan``,
``1e999``, ``1e308``), which it accepts. :func:`read_design_toml` turns the
first two into errors at the line they are on, and :func:`check_values` checks
every number and every nesting in the design at one place, before anything
reads a value:

* nesting: at most :data:`MAX_NESTING` arrays and tables inside one another
  (a design needs three: ``[factors]``, a factor's list, an identity table);
* numbers: finite and within ±\\ :data:`MAX_NUMBER`; each option and factor
  with a meaning has its own, narrower range (``design.py``).

>>> read_design_toml("x = " + "[" * 40 + "]" * 40, "d.toml")
Traceback (most recent call last):
engine.stimuli.design_toml.DesignError: d.toml:1: arrays and tables nested more than 32 deep
>>> read_design_toml("[output]\\nstill_ms = inf\\n", "d.toml")
Traceback (most recent call last):
engine.stimuli.design_toml.DesignError: d.toml:2: still_ms: inf: a number in a design must be finite and within ±1e+15
"""

from __future__ import annotations

import math
import re
import sys
import tomllib
from pathlib import Path
from typing import Any

from engine.errors import UserError

MAX_NESTING = 32
"""Arrays and tables inside one another (the top-level table counts as none)."""
MAX_NUMBER = 1e15
"""Every number in a design lies within ±10¹⁵ (integers are exact in a float up to 9·10¹⁵)."""


class DesignError(UserError):
    """A design file that cannot be made: its file, line and key are named."""


def read_design_toml(text: str, path: Path | str) -> tuple[dict[str, Any], Locator]:
    """The design's TOML as a dict whose numbers and nesting :func:`check_values` has passed, and a
    :class:`Locator` for its keys' lines."""
    path = Path(path)
    where = Locator(text, path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        message = str(exc).split(" (at ")[0] + (f" (column {found.group(2)})" if found else "")
        raise DesignError(f"not a TOML file: {message}", file=path,
                          line=int(found.group(1)) if found else None) from None
    except ValueError:                     # int() of more digits than sys.get_int_max_str_digits() allows
        limit = sys.get_int_max_str_digits()
        raise DesignError(f"an integer of more than {limit} digits (no design needs one)", file=path,
                          line=where.long_integer_line(limit)) from None
    except RecursionError:
        raise DesignError(f"arrays and tables nested more than {MAX_NESTING} deep", file=path,
                          line=where.nesting_line()) from None
    check_values(data, where)
    return data, where


def check_values(data: dict[str, Any], where: Locator) -> None:
    """Refuse nesting deeper than :data:`MAX_NESTING` and any number that is not finite or lies beyond
    ±\\ :data:`MAX_NUMBER`, anywhere in ``data`` (iteratively: a deep value cannot exhaust the stack;
    ``not abs(x) <= MAX_NUMBER`` is true for nan and inf, and compares an integer of any size exactly)."""
    stack: list[tuple[Any, tuple[str | int, ...]]] = [(value, (key,)) for key, value in data.items()]
    while stack:
        value, path = stack.pop()              # path: the keys and array indices down to the value
        if isinstance(value, dict | list):
            if len(path) > MAX_NESTING:
                line = where.nesting_line()
                deep = f"arrays and tables nested more than {MAX_NESTING} deep"
                if line is not None:
                    raise DesignError(deep, file=where.path, line=line)
                raise where.error(_innermost_key(path), deep, where.line_of_path(path))
            items = value.items() if isinstance(value, dict) else enumerate(value)
            stack.extend((v, (*path, k)) for k, v in items)
        elif isinstance(value, int | float) and not isinstance(value, bool) and not abs(value) <= MAX_NUMBER:
            raise where.error(_innermost_key(path), f"{number_text(value)}: a number in a design must be finite "
                                                    f"and within ±{MAX_NUMBER:g}", where.line_of_path(path))


def _innermost_key(path: tuple[str | int, ...]) -> str:
    return next(str(k) for k in reversed(path) if isinstance(k, str))


def number_text(value: float) -> str:
    """A number as an error shows it: ``inf``, ``1e+308``; an integer too long to print by its size."""
    if isinstance(value, int) and abs(value) >= 10**20:
        return f"an integer of about {int(abs(value).bit_length() * math.log10(2)) + 1} digits"
    return repr(value)


class Locator:
    """Finds the line a key is written on, for errors (tomllib gives no positions for values)."""

    def __init__(self, text: str, path: Path):
        self.text = text
        self.lines = text.splitlines()
        self.path = path
        self._headers: dict[str, list[int]] = {}

    def line_of(self, key: str, start: int = 0, stop: int | None = None) -> int | None:
        """The first line (1-based) within lines ``start`` … ``stop`` (0-based, end excluded) that writes
        ``key``: as ``key =``, a table ``[key]`` or a dotted ``key.``, else inside an inline table."""
        lines = self.lines[start:stop]
        pattern = re.compile(rf'^\s*(?:\[+\s*)?"?{re.escape(key)}"?\s*(?:=|\]|\.)')
        for number, line in enumerate(lines, start=start + 1):
            if pattern.match(line):
                return number
        inline = re.compile(rf'[{{,]\s*"?{re.escape(key)}"?\s*=')
        for number, line in enumerate(lines, start=start + 1):
            if inline.search(line):
                return number
        return None

    def line_of_path(self, path: tuple[str | int, ...]) -> int | None:
        """The line of the value at ``path`` (its tables' keys and arrays' indices, outermost first): in the
        n-th ``[[rows]]`` or ``[[blocks]]`` table where it is in one, else of the innermost key found."""
        keys = [k for k in path if isinstance(k, str)]
        if len(path) > 1 and isinstance(path[1], int) and isinstance(path[0], str) and len(keys) > 1:
            return self.line_in_table(path[0], path[1], keys[-1])
        return next((line for key in reversed(dict.fromkeys(keys)) if (line := self.line_of(key)) is not None),
                    None)

    def line_in_table(self, array: str, index: int, key: str | None = None) -> int | None:
        """The line of ``key`` in the ``index``-th ``[[array]]`` table (its header line if ``key`` is None or
        not found there); where the tables are not written as ``[[array]]`` headers, the line of ``key``."""
        if array not in self._headers:
            header = re.compile(rf'^\s*\[\[\s*"?{re.escape(array)}"?\s*\]\]')
            self._headers[array] = [i for i, line in enumerate(self.lines) if header.match(line)]
        headers = self._headers[array]
        if index >= len(headers):
            return self.line_of(key if key is not None else array)
        start = headers[index]
        stop = next((i for i in range(start + 1, len(self.lines)) if self.lines[i].lstrip().startswith("[")),
                    len(self.lines))
        found = self.line_of(key, start + 1, stop) if key is not None else None
        return found if found is not None else start + 1

    def long_integer_line(self, limit: int) -> int | None:
        """The line of the first integer of more than ``limit`` digits (what ``int()`` refuses)."""
        found = re.search(rf"(?<![\w.])[+-]?\d(?:_?\d){{{limit},}}(?![\w.])", self.text)
        return None if found is None else self.text.count("\n", 0, found.start()) + 1

    def nesting_line(self) -> int | None:
        """The line where arrays and tables first nest more than :data:`MAX_NESTING` deep (strings and comments
        skipped; best effort on text that is not valid TOML)."""
        depth, line = 0, 1
        for token in _TOKENS.finditer(self.text):
            mark = token.group()
            if mark in "[{":
                depth += 1
                if depth > MAX_NESTING:
                    return line
            elif mark in "]}":
                depth -= 1
            else:
                line += mark.count("\n")
        return None

    def error(self, key: str, message: str, line: int | None = None) -> DesignError:
        return DesignError(f"{key}: {message}", file=self.path, line=line if line is not None else self.line_of(key))


_TOKENS = re.compile(r'"""(?:[^\\]|\\[\s\S])*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|\'[^\'\n]*\'|#[^\n]*'
                     r'|[\[\]{}]|\n')
