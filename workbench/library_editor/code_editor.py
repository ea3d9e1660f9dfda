"""A plain-text editor for library files: line numbers, §2.3 colours, problems underlined at their line.

Problems are drawn as extra selections — a red wavy underline
(``QTextCharFormat.SpellCheckUnderline``) under the line's text and a pale red
band across it — with the message as the line's tooltip and a red dot in the
line-number gutter.
"""

from __future__ import annotations

from PySide6.QtCore import QRect, QSize, Qt
from PySide6.QtGui import QColor, QFontDatabase, QPainter, QTextCharFormat, QTextCursor, QTextFormat
from PySide6.QtWidgets import QPlainTextEdit, QTextEdit, QToolTip, QWidget

from .highlighter import LibraryHighlighter

ERROR_COLOUR = QColor("#d0021b")
ERROR_BAND = QColor(255, 0, 0, 28)


class _LineNumbers(QWidget):
    def __init__(self, editor: CodeEditor):
        super().__init__(editor)
        self.editor = editor

    def sizeHint(self) -> QSize:
        return QSize(self.editor.gutter_width(), 0)

    def paintEvent(self, event) -> None:
        self.editor.paint_gutter(event)


class CodeEditor(QPlainTextEdit):
    """The text of one library file. :meth:`set_problems` marks lines; :meth:`error_lines` reads them back."""

    def __init__(self, parent: QWidget | None = None):
        super().__init__(parent)
        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        self.setFont(font)
        self.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        self.setTabStopDistance(4 * self.fontMetrics().horizontalAdvance(" "))
        self.highlighter = LibraryHighlighter(self.document())
        self.problems: dict[int, str] = {}
        self._gutter = _LineNumbers(self)
        self.blockCountChanged.connect(self._update_gutter_width)
        self.updateRequest.connect(self._update_gutter)
        self._update_gutter_width()

    # -- problems -----------------------------------------------------------
    def set_problems(self, problems: dict[int, str]) -> None:
        """Underline each line (1-based) → message; an empty dict clears every mark."""
        count = self.document().blockCount()
        self.problems = {min(max(1, line), count): message for line, message in problems.items()}
        selections = []
        for line in sorted(self.problems):
            block = self.document().findBlockByNumber(line - 1)
            band = QTextEdit.ExtraSelection()
            band.format.setBackground(ERROR_BAND)
            band.format.setProperty(QTextFormat.Property.FullWidthSelection, True)
            band.cursor = QTextCursor(block)
            selections.append(band)
            text = block.text()
            start = len(text) - len(text.lstrip())
            end = len(text.split("#", 1)[0].rstrip()) or len(text)
            if end > start:
                wavy = QTextEdit.ExtraSelection()
                wavy.format.setUnderlineStyle(QTextCharFormat.UnderlineStyle.SpellCheckUnderline)
                wavy.format.setUnderlineColor(ERROR_COLOUR)
                cursor = QTextCursor(block)
                cursor.setPosition(block.position() + start)
                cursor.setPosition(block.position() + end, QTextCursor.MoveMode.KeepAnchor)
                wavy.cursor = cursor
                selections.append(wavy)
        self.setExtraSelections(selections)
        self._gutter.update()

    def error_lines(self) -> list[int]:
        """The 1-based lines underlined now, read from the editor's extra selections."""
        lines = set()
        for selection in self.extraSelections():
            if selection.format.underlineStyle() == QTextCharFormat.UnderlineStyle.SpellCheckUnderline:
                lines.add(selection.cursor.block().blockNumber() + 1)
        return sorted(lines)

    def go_to_line(self, line: int) -> None:
        block = self.document().findBlockByNumber(max(0, line - 1))
        self.setTextCursor(QTextCursor(block))
        self.centerCursor()
        self.setFocus()

    # -- Qt overrides ---------------------------------------------------------
    def event(self, event) -> bool:
        if event.type() == event.Type.ToolTip:
            cursor = self.cursorForPosition(self.viewport().mapFrom(self, event.pos()))
            message = self.problems.get(cursor.blockNumber() + 1)
            if message:
                QToolTip.showText(event.globalPos(), message, self)
            else:
                QToolTip.hideText()
            return True
        return super().event(event)

    def resizeEvent(self, event) -> None:
        super().resizeEvent(event)
        rect = self.contentsRect()
        self._gutter.setGeometry(QRect(rect.left(), rect.top(), self.gutter_width(), rect.height()))

    # -- gutter ---------------------------------------------------------------
    def gutter_width(self) -> int:
        digits = len(str(max(1, self.blockCount())))
        return 14 + self.fontMetrics().horizontalAdvance("9") * max(2, digits)

    def paint_gutter(self, event) -> None:
        painter = QPainter(self._gutter)
        painter.fillRect(event.rect(), self.palette().color(self.palette().ColorRole.AlternateBase))
        block = self.firstVisibleBlock()
        top = round(self.blockBoundingGeometry(block).translated(self.contentOffset()).top())
        height = self.fontMetrics().height()
        width = self._gutter.width()
        while block.isValid() and top <= event.rect().bottom():
            bottom = top + round(self.blockBoundingRect(block).height())
            if block.isVisible() and bottom >= event.rect().top():
                number = block.blockNumber() + 1
                if number in self.problems:
                    painter.setBrush(ERROR_COLOUR)
                    painter.setPen(Qt.PenStyle.NoPen)
                    painter.drawEllipse(3, top + height // 2 - 3, 6, 6)
                painter.setPen(ERROR_COLOUR if number in self.problems else QColor("#8a8a8a"))
                painter.drawText(0, top, width - 4, height, Qt.AlignmentFlag.AlignRight, str(number))
            block = block.next()
            top = bottom

    def _update_gutter_width(self, *_args) -> None:
        self.setViewportMargins(self.gutter_width(), 0, 0, 0)

    def _update_gutter(self, rect, dy) -> None:
        if dy:
            self._gutter.scroll(0, dy)
        else:
            self._gutter.update(0, rect.y(), self._gutter.width(), rect.height())
