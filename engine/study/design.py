"""Study designs: a TOML file in, a checked :class:`StudyDesign` out (docs/study.md).

A study design names the stimulus set (or the design to make it from), the tasks (identification
among the set's emotions plus neutral and "other"; ratings on 1–7 scales), the presentation
conditions (a still at the apex, the video or the live web player), a human comparison table, the
procedure (blocks, counterbalancing, practice, attention checks) and the participant's pages::

    name = "katsyri-2003"
    seed = 2003

    [stimuli]
    design = "faces.toml"                 # make the set first (or: set = "faces/", a set already made)

    [conditions]
    presentation = ["static", "dynamic"]

    [procedure]
    tasks = ["identification", "rating"]
    blocks = "presentation"               # static and dynamic in blocks, their order counterbalanced

Every mistake is one :class:`StudyDesignError` naming the file, the line and the key.

>>> parse_study_design('[stimuli]\\nset = "faces"\\n[procedure]\\ntasks = ["rating"]\\n', "study.toml")
Traceback (most recent call last):
engine.study.design.StudyDesignError: study.toml:2: set: 'faces' holds no manifest.csv: name a stimulus set's \
folder, or give design = "…" to make it first
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from engine.formats.text_files import read_bounded_text
from engine.stimuli.design_toml import DesignError, Locator, read_design_toml

__all__ = ["CANONICAL_EMOTIONS", "Choices", "Pages", "Procedure", "Scale", "StudyDesign", "StudyDesignError",
           "load_study_design", "parse_study_design"]

MAX_DESIGN_BYTES = 1_000_000
MAX_PAGE_BYTES = 200_000
MAX_CHOICES = 20
MAX_SCALES = 10
MAX_SCALE_POINTS = 11
MAX_REPETITIONS = 20
MAX_PRACTICE = 50
MAX_ATTENTION = 50
MAX_MS = 600_000
PRESENTATIONS = ("static", "dynamic")
DYNAMICS = ("video", "live")
TASKS = ("identification", "rating")
BLOCKINGS = ("none", "presentation", "source")
COUNTERBALANCES = ("all", "latin")
HOSTS = ("folder", "jatos", "pavlovia", "cognition")
CANONICAL_EMOTIONS = ("happy", "sad", "surprise", "fear", "angry", "disgust", "contempt")
"""The order choices are offered in when the design does not list them (the set's emotions among these, then
others alphabetically), neutral and "other" last."""
DEFAULT_LABELS = {"happy": "Happiness", "sad": "Sadness", "surprise": "Surprise", "fear": "Fear",
                  "angry": "Anger", "disgust": "Disgust", "contempt": "Contempt", "neutral": "Neutral",
                  "other": "Other"}
_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_-]{0,63}$")
_VALUE = re.compile(r"^[a-z][a-z0-9_]{0,39}$")
_KEY = re.compile(r"^[a-z0-9]$")
_PAGE_FILE = re.compile(r"\.(md|txt|html?)$", re.IGNORECASE)
_TOP = {"name", "title", "seed", "stimuli", "conditions", "human", "identification", "scales", "procedure",
        "pages", "output"}
_KEYS = {
    "stimuli": {"set", "design", "emotion"},
    "conditions": {"presentation", "dynamic"},
    "human": {"table"},
    "identification": {"choices", "neutral", "other", "labels", "keys", "question", "buttons"},
    "procedure": {"tasks", "repetitions", "blocks", "counterbalance", "practice", "attention_checks", "static_ms",
                  "fixation_ms", "gap_ms"},
    "pages": {"consent", "instructions", "practice_end", "debrief", "agree", "decline", "declined"},
    "output": {"hosts", "width"},
}
_SCALE_KEYS = {"name", "question", "min", "max", "anchors", "keys"}
DEFAULT_SCALES = (
    ("intensity", "How intense is the expression?", ("very weak", "very strong")),
    ("naturalness", "How natural does the face look?", ("very unnatural", "very natural")),
)
DEFAULT_PAGES = {
    "consent": "<p>This study is about how people read faces. You will see faces, one at a time, and answer "
               "questions about them. It takes about ten minutes. Your answers are stored without your name.</p>"
               "<p>Do you agree to take part?</p>",
    "instructions": "<p>Each face is shown for a moment. Choose the emotion it shows with the buttons or the keys "
                    "written on them, then answer the questions that follow.</p><p>Answer as quickly and as "
                    "accurately as you can.</p>",
    "practice_end": "<p>That was the practice. The study itself starts now.</p>",
    "debrief": "<p>Thank you for taking part.</p>",
    "declined": "<p>You chose not to take part. Nothing has been recorded. You may close this page.</p>",
}


class StudyDesignError(DesignError):
    """A study design that cannot be built: its file, line and key are named."""


@dataclass(frozen=True)
class Scale:
    """One rating scale: integer points ``low`` … ``high``, the words at its ends, a key for each point."""

    name: str
    question: str
    low: int = 1
    high: int = 7
    anchors: tuple[str, str] = ("", "")
    keys: tuple[str, ...] = ()


@dataclass(frozen=True)
class Choices:
    """The identification task's options (``None``: the set's emotions plus neutral and other, in order)."""

    values: tuple[str, ...] | None = None
    neutral: bool = True
    other: bool = True
    labels: dict[str, str] = field(default_factory=dict)
    keys: tuple[str, ...] = ()
    question: str = "Which emotion does the face show?"
    buttons: bool = True


@dataclass(frozen=True)
class Procedure:
    tasks: tuple[str, ...] = TASKS
    repetitions: int = 1
    blocks: str = "presentation"
    counterbalance: str = "all"
    practice: int = 0
    attention_checks: int = 0
    static_ms: int = 0
    """How long a still stays on the screen (0: until the last question is answered)."""
    fixation_ms: int = 500
    gap_ms: int = 300


@dataclass(frozen=True)
class Pages:
    """The participant's pages as HTML: consent, instructions, the end of practice, debrief, declined."""

    consent: str = DEFAULT_PAGES["consent"]
    instructions: str = DEFAULT_PAGES["instructions"]
    practice_end: str = DEFAULT_PAGES["practice_end"]
    debrief: str = DEFAULT_PAGES["debrief"]
    declined: str = DEFAULT_PAGES["declined"]
    agree: str = "I agree"
    decline: str = "I do not agree"


@dataclass(frozen=True)
class StudyDesign:
    path: Path
    name: str
    title: str
    seed: int
    set_folder: Path | None
    """The stimulus set's folder; with ``set_design``, where to make it (None: ``STUDY/set``)."""
    set_design: Path | None
    emotion_factor: str
    presentations: tuple[str, ...]
    dynamic: str
    human_table: Path | None
    choices: Choices
    scales: tuple[Scale, ...]
    procedure: Procedure
    pages: Pages
    hosts: tuple[str, ...]
    width: int | None
    sha256: str = ""

    @property
    def folder(self) -> Path:
        return self.path.parent


def load_study_design(path: str | Path) -> StudyDesign:
    """Read and check a study design file."""
    path = Path(path)
    try:
        text = read_bounded_text(path, limit=MAX_DESIGN_BYTES, error=StudyDesignError, what="study design")
    except OSError as exc:
        raise StudyDesignError(f"cannot read the study design: {exc.strerror or exc}", file=path) from None
    return parse_study_design(text, path)


def parse_study_design(text: str, path: str | Path = "<study>") -> StudyDesign:
    """Check a study design's text (names of files are resolved against its folder)."""
    import hashlib

    path = Path(path)
    try:
        data, where = read_design_toml(text, path)
    except DesignError as exc:
        raise StudyDesignError(exc.message, file=exc.file, line=exc.line) from None
    reader = _Reader(data, where, path.parent)
    for key in data:
        if key not in _TOP:
            raise reader.fail(key, f"unknown key (the keys are {', '.join(sorted(_TOP))})")
    for table, keys in _KEYS.items():
        part = reader.table(table)
        for key in part:
            if key not in keys:
                raise reader.fail(key, f"unknown key in [{table}] (its keys are {', '.join(sorted(keys))})")
    name = reader.string("name", data, default=path.stem if _NAME.match(path.stem) else "study")
    if not _NAME.match(name):
        raise reader.fail("name", "must be 1-64 letters, digits, '-' or '_' (it names files and the study's data)")
    set_folder, set_design, emotion = reader.stimuli()
    presentations, dynamic = reader.conditions()
    procedure = reader.procedure(len(presentations))
    hosts = tuple(reader.strings("hosts", reader.table("output"), HOSTS, default=HOSTS, unique=True))
    if dynamic == "live" and "dynamic" in presentations and "cognition" in hosts:
        if "hosts" in reader.table("output"):
            raise reader.fail("hosts", "cognition cannot show the live player (its page cannot carry the import "
                                       "map the player needs): leave it out, or use dynamic = \"video\"")
        hosts = tuple(h for h in hosts if h != "cognition")
    width = reader.integer("width", reader.table("output"), 100, 4000, default=None)
    return StudyDesign(
        path=path, name=name, title=reader.string("title", data, default="A study of faces"),
        seed=reader.integer("seed", data, 0, 2**32 - 1, default=0) or 0,
        set_folder=set_folder, set_design=set_design, emotion_factor=emotion, presentations=presentations,
        dynamic=dynamic, human_table=reader.file_key("table", reader.table("human")),
        choices=reader.choices(), scales=reader.scales("rating" in procedure.tasks), procedure=procedure,
        pages=reader.pages(), hosts=hosts, width=width,
        sha256=hashlib.sha256(text.encode("utf-8")).hexdigest())


class _Reader:
    """The design's values, checked one key at a time; every failure names the key's line."""

    def __init__(self, data: dict[str, Any], where: Locator, folder: Path):
        self.data = data
        self.where = where
        self.folder = folder

    def fail(self, key: str, message: str, line: int | None = None) -> StudyDesignError:
        error = self.where.error(key, message, line)
        return StudyDesignError(error.message, file=error.file, line=error.line)

    def table(self, name: str) -> dict[str, Any]:
        value = self.data.get(name, {})
        if not isinstance(value, dict):
            raise self.fail(name, f"must be a table ([{name}])")
        return value

    def string(self, key: str, table: dict[str, Any], default: str = "", limit: int = 2000) -> str:
        value = table.get(key, default)
        if not isinstance(value, str):
            raise self.fail(key, "must be a string")
        if len(value) > limit:
            raise self.fail(key, f"at most {limit} characters")
        return value

    def boolean(self, key: str, table: dict[str, Any], default: bool) -> bool:
        value = table.get(key, default)
        if not isinstance(value, bool):
            raise self.fail(key, "must be true or false")
        return value

    def integer(self, key: str, table: dict[str, Any], low: int, high: int, default: int | None) -> int | None:
        value = table.get(key, default)
        if value is None:
            return None
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
            raise self.fail(key, f"must be a whole number from {low} to {high}")
        return value

    def strings(self, key: str, table: dict[str, Any], allowed: tuple[str, ...] | None, default: tuple[str, ...],
                unique: bool = False, limit: int = 100) -> list[str]:
        value = table.get(key, list(default))
        if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
            raise self.fail(key, "must be a list of strings" + (f", some of {', '.join(allowed)}" if allowed else ""))
        if len(value) > limit:
            raise self.fail(key, f"at most {limit} entries")
        if allowed is not None:
            for v in value:
                if v not in allowed:
                    raise self.fail(key, f"{v[:40]!r} is not one of {', '.join(allowed)}")
        if unique and len(set(value)) != len(value):
            raise self.fail(key, "lists the same entry twice")
        return list(value)

    def choice(self, key: str, table: dict[str, Any], allowed: tuple[str, ...], default: str) -> str:
        value = table.get(key, default)
        if value not in allowed:
            raise self.fail(key, f"must be one of {', '.join(allowed)}")
        return str(value)

    def file_key(self, key: str, table: dict[str, Any], folder_ok: bool = False) -> Path | None:
        """A file (or folder) named relative to the design; it must exist."""
        if key not in table:
            return None
        name = self.string(key, table, limit=1000)
        if not name.strip() or "\x00" in name:
            raise self.fail(key, "must name a file")
        found = self.folder / name
        try:
            ok = found.is_dir() if folder_ok else found.is_file()
        except (OSError, ValueError):
            ok = False
        if not ok:
            raise self.fail(key, f"{name[:200]!r} is not {'a folder' if folder_ok else 'a file'} (names are "
                                 "relative to the study design)")
        return found

    def stimuli(self) -> tuple[Path | None, Path | None, str]:
        table = self.table("stimuli")
        design = self.file_key("design", table)
        folder: Path | None = None
        if "set" in table:
            name = self.string("set", table, limit=1000)
            if not name.strip() or "\x00" in name:
                raise self.fail("set", "must name a folder")
            folder = self.folder / name
            if design is None:
                try:
                    listed = (folder / "manifest.csv").is_file()
                except (OSError, ValueError):
                    listed = False
                if not listed:
                    raise self.fail("set", f"{name[:200]!r} holds no manifest.csv: name a stimulus set's folder, "
                                           "or give design = \"…\" to make it first")
        if design is None and folder is None:
            raise self.fail("stimuli", "say which stimuli: set = \"SETDIR\" (a set made by 'stimuli') or design = "
                                       "\"DESIGN.toml\" (made first)", line=self.where.line_of("stimuli") or 1)
        emotion = self.string("emotion", table, default="expression", limit=64)
        if not re.match(r"^[A-Za-z_][A-Za-z0-9_]*$", emotion):
            raise self.fail("emotion", "must name a factor of the set (the column holding each stimulus's emotion)")
        return folder, design, emotion

    def conditions(self) -> tuple[tuple[str, ...], str]:
        table = self.table("conditions")
        presentations = self.strings("presentation", table, PRESENTATIONS, PRESENTATIONS, unique=True)
        return tuple(presentations), self.choice("dynamic", table, DYNAMICS, "video")

    def procedure(self, presentations: int) -> Procedure:
        table = self.table("procedure")
        tasks = tuple(self.strings("tasks", table, TASKS, TASKS, unique=True))
        default_blocks = "presentation" if presentations > 1 else "none"
        return Procedure(
            tasks=tasks, repetitions=self.integer("repetitions", table, 1, MAX_REPETITIONS, 1) or 1,
            blocks=self.choice("blocks", table, BLOCKINGS, default_blocks),
            counterbalance=self.choice("counterbalance", table, COUNTERBALANCES, "all"),
            practice=self.integer("practice", table, 0, MAX_PRACTICE, 0) or 0,
            attention_checks=self.integer("attention_checks", table, 0, MAX_ATTENTION, 0) or 0,
            static_ms=self.integer("static_ms", table, 0, MAX_MS, 0) or 0,
            fixation_ms=self.integer("fixation_ms", table, 0, 10_000, 500) or 0,
            gap_ms=self.integer("gap_ms", table, 0, 10_000, 300) or 0)

    def choices(self) -> Choices:
        table = self.table("identification")
        values: tuple[str, ...] | None = None
        if "choices" in table:
            values = tuple(self.strings("choices", table, None, (), unique=True, limit=MAX_CHOICES))
            for value in values:
                if not _VALUE.match(value):
                    raise self.fail("choices", f"{value[:40]!r}: a choice is a lower-case name (letters, digits, "
                                               "'_'), such as happy; give its words in labels")
        labels = table.get("labels", {})
        if not isinstance(labels, dict) or not all(isinstance(k, str) and isinstance(v, str) and 0 < len(v) <= 60
                                                   for k, v in labels.items()):
            raise self.fail("labels", "must be a table of choice = \"its words\" (1-60 characters each)")
        keys = tuple(self.strings("keys", table, None, (), unique=True, limit=MAX_CHOICES)) if "keys" in table else ()
        for key in keys:
            if not _KEY.match(key):
                raise self.fail("keys", f"{key[:20]!r}: a key is one lower-case letter or digit")
        return Choices(values=values, neutral=self.boolean("neutral", table, True),
                       other=self.boolean("other", table, True), labels=dict(labels), keys=keys,
                       question=self.string("question", table, Choices.question, limit=500),
                       buttons=self.boolean("buttons", table, True))

    def scales(self, wanted: bool) -> tuple[Scale, ...]:
        given = self.data.get("scales")
        if given is None:
            if not wanted:
                return ()
            return tuple(Scale(name, question, 1, 7, anchors, tuple(str(k) for k in range(1, 8)))
                         for name, question, anchors in DEFAULT_SCALES)
        if not isinstance(given, list) or not given or not all(isinstance(s, dict) for s in given):
            raise self.fail("scales", "must be [[scales]] tables")
        if len(given) > MAX_SCALES:
            raise self.fail("scales", f"at most {MAX_SCALES} scales")
        if not wanted:
            raise self.fail("scales", "scales are given but procedure.tasks has no \"rating\"")
        scales = []
        for index, table in enumerate(given):
            scales.append(self._scale(index, table))
        if len({s.name for s in scales}) != len(scales):
            raise self.fail("scales", "two scales have the same name")
        return tuple(scales)

    def _scale(self, index: int, table: dict[str, Any]) -> Scale:
        def fail(key: str, message: str) -> StudyDesignError:
            return self.fail(key, message, self.where.line_in_table("scales", index, key))

        for key in table:
            if key not in _SCALE_KEYS:
                raise fail(key, f"unknown key in [[scales]] (its keys are {', '.join(sorted(_SCALE_KEYS))})")
        name = table.get("name")
        if not isinstance(name, str) or not _VALUE.match(name):
            raise fail("name", "each scale needs a name: lower-case letters, digits, '_' (it names its column)")
        question = table.get("question", f"{name.capitalize()}?")
        if not isinstance(question, str) or len(question) > 500:
            raise fail("question", "must be a string of at most 500 characters")
        low, high = table.get("min", 1), table.get("max", 7)
        for key, value in (("min", low), ("max", high)):
            if isinstance(value, bool) or not isinstance(value, int) or not -100 <= value <= 100:
                raise fail(key, "must be a whole number from -100 to 100")
        if not 2 <= high - low + 1 <= MAX_SCALE_POINTS:
            raise fail("max", f"a scale has 2 to {MAX_SCALE_POINTS} points (min {low}, max {high})")
        anchors = table.get("anchors", ["", ""])
        if not (isinstance(anchors, list) and len(anchors) == 2 and all(isinstance(a, str) and len(a) <= 60
                                                                        for a in anchors)):
            raise fail("anchors", "must be two strings: the words at the low and the high end")
        if "keys" in table:
            keys = table["keys"]
            if not (isinstance(keys, list) and len(keys) == high - low + 1 and all(isinstance(k, str) and _KEY.match(k)
                                                                                  for k in keys)
                    and len(set(keys)) == len(keys)):
                raise fail("keys", f"must list {high - low + 1} different keys (one letter or digit each), one a point")
        elif low >= 0 and high <= 9:
            keys = [str(v) for v in range(low, high + 1)]
        else:
            keys = []
        return Scale(name, question, low, high, (anchors[0], anchors[1]), tuple(keys))

    def pages(self) -> Pages:
        table = self.table("pages")
        texts = {}
        for key in ("consent", "instructions", "practice_end", "debrief", "declined"):
            if key in table:
                texts[key] = self._page(key, table)
        labels = {key: self.string(key, table, getattr(Pages, key), limit=60) for key in ("agree", "decline")}
        return Pages(**texts, **labels)

    def _page(self, key: str, table: dict[str, Any]) -> str:
        value = self.string(key, table, limit=MAX_PAGE_BYTES)
        if "\n" not in value and _PAGE_FILE.search(value.strip()):
            path = self.file_key(key, table)
            assert path is not None
            text = read_bounded_text(path, limit=MAX_PAGE_BYTES, error=StudyDesignError, what="page")
            if path.suffix.lower() in (".html", ".htm"):
                return text
            return text_to_html(text)
        return text_to_html(value)


def text_to_html(text: str) -> str:
    """A researcher's plain text as HTML: paragraphs at blank lines, ``# `` headings, ``**bold**``, ``*italic*``,
    lines starting ``- `` as a list; everything else escaped.

    >>> text_to_html("# Consent\\n\\nYou may stop **at any time**.\\n- no names\\n- no pictures")
    '<h2>Consent</h2>\\n<p>You may stop <b>at any time</b>.</p>\\n<ul><li>no names</li><li>no pictures</li></ul>'
    """
    out: list[str] = []
    for block in re.split(r"\n\s*\n", text.strip()):
        paragraph: list[str] = []
        items: list[str] = []
        for line in (line.strip() for line in block.strip().splitlines()):
            if not line:
                continue
            if line.startswith("#"):
                _flush(out, paragraph, items)
                level = min(len(line) - len(line.lstrip("#")) + 1, 4)
                out.append(f"<h{level}>{_inline(line.lstrip('#').strip())}</h{level}>")
            elif line.startswith(("- ", "* ")):
                _flush(out, paragraph, [])
                items.append(_inline(line[2:].strip()))
            else:
                _flush(out, [], items)
                paragraph.append(_inline(line))
        _flush(out, paragraph, items)
    return "\n".join(out)


def _flush(out: list[str], paragraph: list[str], items: list[str]) -> None:
    """Put the paragraph and the list gathered so far into ``out`` (and empty them)."""
    if paragraph:
        out.append(f"<p>{' '.join(paragraph)}</p>")
        paragraph.clear()
    if items:
        out.append("<ul>" + "".join(f"<li>{item}</li>" for item in items) + "</ul>")
        items.clear()


def _inline(text: str) -> str:
    escaped = html.escape(text, quote=False)
    escaped = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", escaped)
    return re.sub(r"(?<![*\w])\*(?!\s)(.+?)(?<!\s)\*(?![*\w])", r"<i>\1</i>", escaped)
