"""The user command interpreter (§2): text with inline high-level commands.

    Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä kuuluu?

The text is spoken; every ``<Command …/>`` in it is a high-level command for
the translator (§2.3), taken out of the text before synthesis. Anchoring:

* a command **without** ``at`` starts when the **next word** starts (here: when
  "mitä" starts); a command after the last word starts when the last word ends;
* a command **with** ``at`` starts at that time, in ms from the start of the
  utterance's audio, wherever it stands in the text;
* words are matched to the synthesizer's words by their letters, so a number
  Festival reads as several words ("2" → "kaksi") still anchors correctly at
  the first of them.

Errors (a malformed tag, an argument that is not a number) name the text's
file and line, and the column in the message.

>>> script = parse_script('Hyvää päivää <HeadNod amplitude="60" count="2"/> mitä kuuluu?')
>>> script.text, script.words, script.commands[0].word_index
('Hyvää päivää mitä kuuluu?', ['Hyvää', 'päivää', 'mitä', 'kuuluu'], 2)
"""

from __future__ import annotations

import difflib
import re
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass, replace

from engine.commands.command_files import HighLevelCommand, parse_commands_text
from engine.errors import CommandError
from engine.script.timed_labels import TimedLabel

_TAG = re.compile(r"<[^<>]*>")
_WELL_FORMED = re.compile(r"<\s*[A-Za-z_][A-Za-z0-9_.\-]*(\s+[^<>]*?)?/\s*>$", re.S)
_WORD = re.compile(r"[^\W_]+(?:['’\-][^\W_]+)*", re.UNICODE)


@dataclass
class InlineCommand:
    command: HighLevelCommand
    word_index: int
    """Index in :attr:`Script.words` of the word the command precedes (== len(words) at the end)."""


@dataclass
class Script:
    text: str
    """The text to speak, commands removed."""
    words: list[str]
    commands: list[InlineCommand]
    name: str = "<text>"


def parse_script(source: str, name: str = "<text>") -> Script:
    """Split text with inline commands into the text to speak and the commands."""
    pieces: list[str] = []
    words: list[str] = []
    commands: list[InlineCommand] = []
    position = 0
    lines = _LineCounter(source)
    for match in _TAG.finditer(source):
        before = source[position:match.start()]
        _check_no_stray_brackets(source, position, match.start(), name)
        pieces.append(before + " ")
        words += _WORD.findall(before)
        line, column = lines.at(match.start())
        commands.append(InlineCommand(_command(match.group(0), line, column, name), len(words)))
        position = match.end()
    _check_no_stray_brackets(source, position, len(source), name)
    pieces.append(source[position:])
    words += _WORD.findall(source[position:])
    text = re.sub(r"[ \t]+", " ", "".join(pieces)).strip()
    text = re.sub(r" +([,.!?;:])", r"\1", text)
    return Script(text, words, commands, name)


def anchored_commands(script: Script, spoken_words: Sequence[TimedLabel]) -> list[HighLevelCommand]:
    """The script's commands with ``at`` filled in from the synthesizer's word timings.

    ``spoken_words`` are segments with ``label``, ``start_ms``, ``end_ms`` (the
    synthesizer's words, in order).
    """
    starts = word_start_times(script.words, spoken_words)
    end = spoken_words[-1].end_ms if spoken_words else 0.0
    out: list[HighLevelCommand] = []
    for inline in script.commands:
        command = inline.command
        if "at" not in command.arguments:
            at = starts[inline.word_index] if inline.word_index < len(starts) else end
            command = replace(command, arguments={"at": float(at), **command.arguments})
        out.append(command)
    return out


def word_start_times(words: list[str], spoken_words: Sequence[TimedLabel]) -> list[float]:
    """Start time of each written word, matched to the spoken words by their letters.

    The match runs block by block (:data:`MATCH_BLOCK` written words against
    the spoken words from where the block before ended), so a long story costs
    in proportion to its length; a text of one block is matched as a whole.
    """
    if not spoken_words:
        return [0.0] * len(words)
    written = [_letters(w) for w in words]
    spoken = [_letters(w.label) for w in spoken_words]
    starts: list[float] = []
    next_spoken = 0
    for first in range(0, len(written), MATCH_BLOCK):
        block = written[first:first + MATCH_BLOCK]
        last = first + MATCH_BLOCK >= len(written)
        window_end = len(spoken) if last else min(len(spoken), next_spoken + 4 * MATCH_BLOCK)
        offset = min(next_spoken, len(spoken))
        match_of: dict[int, int] = {}
        matcher = difflib.SequenceMatcher(a=block, b=spoken[offset:window_end], autojunk=False)
        for found in matcher.get_matching_blocks():
            for k in range(found.size):
                match_of[found.a + k] = offset + found.b + k
        for i in range(len(block)):
            j = match_of.get(i)
            if j is None:                    # e.g. "2" spoken as "kaksi": the next unmatched spoken word
                j = min(next_spoken, len(spoken_words) - 1)
            starts.append(float(spoken_words[j].start_ms))
            next_spoken = max(next_spoken, j + 1)
    return starts


MATCH_BLOCK = 256
"""Written words matched at a time by :func:`word_start_times` (a number spoken as several words,
inline commands between them: a spoken window four times as long is searched)."""


def _letters(word: str) -> str:
    return "".join(c for c in unicodedata.normalize("NFC", word.lower()) if c.isalnum())


def _command(tag: str, line: int, column: int, name: str) -> HighLevelCommand:
    if not _WELL_FORMED.match(tag):
        raise CommandError(f"column {column}: '{_short(tag)}' is not an inline command; write "
                           "<Name argument=\"value\" …/> (self-closing)", file=name, line=line)
    try:
        [command] = parse_commands_text(f"<commands>{tag}</commands>", name)
    except CommandError as exc:
        raise CommandError(f"column {column}: {exc.message}", file=name, line=line) from None
    if not isinstance(command, HighLevelCommand):   # the schema refuses an <activate/> without keys first
        raise CommandError(f"column {column}: <activate> cannot stand inline in a script", file=name, line=line)
    return replace(command, file=name, line=line, column=column)


def _check_no_stray_brackets(source: str, start: int, end: int, name: str) -> None:
    for i in range(start, end):
        if source[i] in "<>":
            line, column = _line_column(source, i)
            raise CommandError(f"column {column}: a '{source[i]}' that does not belong to an inline command "
                               "<Name …/>", file=name, line=line)


class _LineCounter:
    """Line and column of rising offsets in one text, counting each stretch of it once (linear time)."""

    def __init__(self, source: str):
        self.source = source
        self.offset = 0
        self.line = 1
        self.line_start = 0

    def at(self, offset: int) -> tuple[int, int]:
        newlines = self.source.count("\n", self.offset, offset)
        if newlines:
            self.line += newlines
            self.line_start = self.source.rfind("\n", self.offset, offset) + 1
        self.offset = offset
        return self.line, offset - self.line_start + 1


def _line_column(source: str, offset: int) -> tuple[int, int]:
    line = source.count("\n", 0, offset) + 1
    column = offset - (source.rfind("\n", 0, offset) + 1) + 1
    return line, column


def _short(text: str) -> str:
    return text if len(text) <= 40 else text[:37] + "…"
