"""Colours for the script editor: inline commands stand out from the words spoken.

``<Happy/>`` (the command name bold, its arguments in a quieter colour); a
lone ``<`` or ``>``, which the interpreter refuses, is underlined in red.

>>> highlighter = InlineCommandHighlighter(editor.document())    # doctest: +SKIP
"""

from __future__ import annotations

import re

from PySide6.QtGui import QColor, QFont, QSyntaxHighlighter, QTextCharFormat

_TAG = re.compile(r"<\s*([A-Za-z_][\w.\-]*)?([^<>]*)>")
_STRAY = re.compile(r"[<>]")


def _format(colour: str, bold: bool = False, error: bool = False) -> QTextCharFormat:
    fmt = QTextCharFormat()
    fmt.setForeground(QColor(colour))
    if bold:
        fmt.setFontWeight(QFont.Weight.Bold)
    if error:
        fmt.setUnderlineStyle(QTextCharFormat.UnderlineStyle.WaveUnderline)
        fmt.setUnderlineColor(QColor("#c0392b"))
    return fmt


class InlineCommandHighlighter(QSyntaxHighlighter):
    TAG = _format("#2f6690")
    NAME = _format("#2f6690", bold=True)
    ARGUMENTS = _format("#7a7f87")
    STRAY = _format("#c0392b", error=True)

    def highlightBlock(self, text: str) -> None:
        covered = [False] * len(text)
        for match in _TAG.finditer(text):
            self.setFormat(match.start(), match.end() - match.start(), self.TAG)
            if match.group(1):
                self.setFormat(match.start(1), len(match.group(1)), self.NAME)
            if match.group(2).strip(" /"):
                self.setFormat(match.start(2), len(match.group(2).rstrip(" /")), self.ARGUMENTS)
            for i in range(match.start(), match.end()):
                covered[i] = True
        for match in _STRAY.finditer(text):
            if not covered[match.start()]:
                self.setFormat(match.start(), 1, self.STRAY)
