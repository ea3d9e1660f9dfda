"""Syntax colours for §2.3 library files.

=====================  ==================================================
what                   example
=====================  ==================================================
directive              ``$command``, ``$optional``, ``$parameter`` …
command name           ``HeadNod`` after ``$command =``
argument names         ``count`` in ``$optional = count=1``
line (parameter) name  ``AU12_left`` in ``AU12_left * left = 1``
scale argument         ``left`` in ``AU12_left * left = 1``
number                 ``0.15``, ``-0.025``, ``1e-3``
comment                ``# from here to the end of the line``
=====================  ==================================================

Unknown directives are shown in the error colour; the checker underlines
them too.
"""

from __future__ import annotations

import re

from PySide6.QtGui import QColor, QFont, QSyntaxHighlighter, QTextCharFormat, QTextDocument

from engine.commands.library_format import DIRECTIVES

_NAME = r"[A-Za-z_][A-Za-z0-9_.\-]*"
_DIRECTIVE = re.compile(rf"^\s*\$({_NAME})")
_COMMAND = re.compile(rf"^\s*\$command\s*=\s*({_NAME})")
_ARGUMENT_LIST = re.compile(r"^\s*\$(optional|mandatory)\s*=")
_LINE = re.compile(rf"^\s*({_NAME})(?:\s*\*\s*({_NAME}))?\s*=")
_NUMBER = re.compile(r"(?<![A-Za-z_0-9.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_ARGUMENT = re.compile(rf"({_NAME})\s*(?==)")
_BARE_NAME = re.compile(rf"(?<![A-Za-z_0-9.]){_NAME}")


def _format(colour: str, bold: bool = False, italic: bool = False) -> QTextCharFormat:
    fmt = QTextCharFormat()
    fmt.setForeground(QColor(colour))
    if bold:
        fmt.setFontWeight(QFont.Weight.Bold)
    fmt.setFontItalic(italic)
    return fmt


FORMATS = {
    "directive": _format("#7a3e9d", bold=True),
    "unknown": _format("#c0392b", bold=True),
    "command": _format("#1a5fb4", bold=True),
    "argument": _format("#986801"),
    "parameter": _format("#26734d", bold=True),
    "scale": _format("#986801", italic=True),
    "number": _format("#b5462a"),
    "comment": _format("#7f8c8d", italic=True),
}


class LibraryHighlighter(QSyntaxHighlighter):
    """Colours a :class:`QTextDocument` holding a library file, line by line.

    A line continuing a value (curve data such as ``833,-0.025; 1000,0`` or an
    ``$optional`` list broken over lines) is coloured as such: the block state
    remembers whether the previous statement was an argument list.
    """

    ARGUMENTS_STATE = 1

    def __init__(self, document: QTextDocument):
        super().__init__(document)

    def highlightBlock(self, text: str) -> None:
        code, hash_mark, _ = text.partition("#")
        if hash_mark:
            self.setFormat(len(code), len(text) - len(code), FORMATS["comment"])
        state = self.previousBlockState() if self.previousBlockState() > 0 else 0
        directive = _DIRECTIVE.match(code)
        line = _LINE.match(code) if directive is None else None
        if directive is not None:
            name = directive.group(1)
            known = name in DIRECTIVES
            self.setFormat(directive.start(1) - 1, len(name) + 1, FORMATS["directive" if known else "unknown"])
            command = _COMMAND.match(code)
            if command is not None:
                self.setFormat(command.start(1), len(command.group(1)), FORMATS["command"])
            state = self.ARGUMENTS_STATE if _ARGUMENT_LIST.match(code) else 0
            if state:
                self._arguments(code, code.index("=") + 1)
            elif name == "parameter":
                self._names(code, code.index("=") + 1 if "=" in code else len(code), "parameter")
        elif line is not None and not code.lstrip()[:1].isdigit():
            self.setFormat(line.start(1), len(line.group(1)), FORMATS["parameter"])
            if line.group(2):
                self.setFormat(line.start(2), len(line.group(2)), FORMATS["scale"])
            state = 0
            self._numbers(code, line.end())
        elif state == self.ARGUMENTS_STATE:
            self._arguments(code, 0)
        else:
            self._numbers(code, 0)
        self.setCurrentBlockState(state)

    def _arguments(self, code: str, start: int) -> None:
        for match in _ARGUMENT.finditer(code, start):
            self.setFormat(match.start(1), len(match.group(1)), FORMATS["argument"])
        for match in _BARE_NAME.finditer(code, start):
            if not code[match.end():].lstrip().startswith("="):
                self.setFormat(match.start(), len(match.group(0)), FORMATS["argument"])
        self._numbers(code, start)

    def _names(self, code: str, start: int, kind: str) -> None:
        for match in _BARE_NAME.finditer(code, start):
            self.setFormat(match.start(), len(match.group(0)), FORMATS[kind])

    def _numbers(self, code: str, start: int) -> None:
        for match in _NUMBER.finditer(code, start):
            self.setFormat(match.start(), len(match.group(0)), FORMATS["number"])
