"""The Scheme program Festival runs, and the reading of what it prints.

The text is spoken the way Festival's own ``tts`` mode speaks a file: Festival
cuts it into utterances (its end-of-utterance tree: sentence ends, long
pauses), and each utterance is synthesized, its wave saved
(``utterance-N.wav``) and its relations printed before the next one starts.
Time and memory so grow with the length of the text and no faster: a short
story costs the sum of its sentences, not the square of its length.

What the parser reads (every line begins ``AP-``; whatever Festival or the voice
prints itself is skipped)::

    AP-VOICES <tab> name <tab> name …          the installed voices
    AP-BEGIN
    AP-PHONESET <tab> radio                    the voice's phone set
    AP-UTT <tab> 1                             utterance 1 begins (times restart at 0)
    AP-WORD <tab> id <tab> name                its words …
    AP-SEG <tab> end_s <tab> word-id <tab> phone            … and phones
    AP-FEAT <tab> phone <tab> vc vlng vheight vfront vrnd ctype cplace cvox
    AP-UTT <tab> 2
    …
    AP-END

Output without ``AP-UTT`` lines (one utterance, as recorded from earlier
versions) reads as utterance 1.

>>> out = ("AP-BEGIN\\nAP-PHONESET\\tfinnish\\nAP-UTT\\t1\\nAP-WORD\\t_1\\tmoi\\n"
...        "AP-SEG\\t0.030000\\t0\\t#\\nAP-SEG\\t0.100000\\t_1\\tm\\nAP-SEG\\t0.250000\\t_1\\toi\\n"
...        "AP-FEAT\\tm\\t- 0 0 0 0 n l +\\n"
...        "AP-UTT\\t2\\nAP-WORD\\t_1\\tno\\nAP-SEG\\t0.050000\\t_1\\tn\\nAP-SEG\\t0.120000\\t_1\\to\\nAP-END\\n")
>>> parsed = parse_output(out)
>>> [(p.label, p.start_ms, p.end_ms) for p in parsed.phones][-2:]
[('n', 250.0, 300.0), ('o', 300.0, 370.0)]
>>> [w.label for w in parsed.words], parsed.utterance_ends_ms, str(parsed.features["m"])
(['moi', 'no'], [250.0, 370.0], '- 0 0 0 0 n l +')
"""

from __future__ import annotations

from dataclasses import dataclass, field

from engine.speech.phone_features import FEATURE_NAMES, PhoneFeatures
from engine.speech.synthesis import Segment, SynthesisError

WAVE_FILE_PATTERN = "utterance-{}.wav"
"""The wave file of utterance N in Festival's working folder."""


def scheme_string(text: str) -> str:
    """``text`` as a Scheme string literal (backslashes and double quotes escaped)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def synthesis_script(text: str, voice: str) -> str:
    """The Scheme program Festival runs: voice, utterance-by-utterance synthesis, waves, relations on stdout.

    ``text`` must already be prepared (:func:`engine.speech.festival.prepare_text`).
    Word names come last on their line, so they may hold any character.
    """
    features = " ".join(f'(item.feat s "ph_{name}")' for name in FEATURE_NAMES)
    feature_format = " ".join(["%s"] * len(FEATURE_NAMES))
    wave_name = WAVE_FILE_PATTERN.replace("{}", "%d")
    return f"""\
(format t "\\nAP-VOICES")
(mapcar (lambda (v) (format t "\\t%s" v)) (voice.list))
(format t "\\n")
(set! ap_count 0)
(define (ap_emit utt)
  (set! ap_count (+ ap_count 1))
  (utt.save.wave utt (format nil "{wave_name}" ap_count) 'riff)
  (format t "\\nAP-UTT\\t%d\\n" ap_count)
  (mapcar
    (lambda (w) (format t "AP-WORD\\t%s\\t%s\\n" (item.feat w "id") (item.name w)))
    (utt.relation.items utt 'Word))
  (mapcar
    (lambda (s)
      (format t "AP-SEG\\t%f\\t%s\\t%s\\n"
              (item.feat s "end") (item.feat s "R:SylStructure.parent.parent.id") (item.name s))
      (format t "AP-FEAT\\t%s\\t{feature_format}\\n" (item.name s) {features}))
    (utt.relation.items utt 'Segment))
  utt)
(if (member_string "{voice}" (voice.list))
  (begin
    (voice_{voice})
    (format t "\\nAP-BEGIN\\n")
    (format t "AP-PHONESET\\t%s\\n" (cadr (car (PhoneSet.description '(name)))))
    (set! tts_hooks (list utt.synth ap_emit))
    (tts_text {scheme_string(text)} nil)
    (format t "\\nAP-END\\n"))
  (format t "\\nAP-NOVOICE\\n"))
"""


VOICES_SCRIPT = """\
(format t "\\nAP-VOICES")
(mapcar (lambda (v) (format t "\\t%s" v)) (voice.list))
(format t "\\nAP-END\\n")
"""


def parse_voices(stdout: str) -> list[str]:
    """The voice names on the ``AP-VOICES`` line."""
    for line in stdout.splitlines():
        if line.startswith("AP-VOICES"):
            return [name for name in line.split("\t")[1:] if name]
    raise SynthesisError("Festival did not list its voices (is it a working Festival installation?)")


@dataclass
class FestivalOutput:
    """Phones and words of the whole text (times from its start, ms), and what assembling the audio needs."""

    phones: list[Segment]
    words: list[Segment]
    phoneset: str = ""
    features: dict[str, PhoneFeatures] = field(default_factory=dict)
    utterance_numbers: list[int] = field(default_factory=list)
    """Festival's number of each utterance (its wave is :data:`WAVE_FILE_PATTERN`)."""
    utterance_ends_ms: list[float] = field(default_factory=list)
    """Where each utterance ends, from the start of the text."""


def parse_segments(stdout: str) -> tuple[list[Segment], list[Segment]]:
    """Phones and words of :func:`synthesis_script`'s output (see :func:`parse_output`)."""
    parsed = parse_output(stdout)
    return parsed.phones, parsed.words


def parse_output(stdout: str) -> FestivalOutput:
    """Read the ``AP-`` lines between ``AP-BEGIN`` and ``AP-END``.

    Times: Festival's segment end times (seconds) × 1000, rounded to the
    microsecond, plus the end of the utterances before; each phone starts
    where the one before ends, the first at 0. A phone's ``word`` is the
    name of its word in the SylStructure relation ("" for pauses Festival
    inserts outside any word). Each word spans exactly its phones; a word
    without phones is left out.
    """
    lines = stdout.splitlines()
    try:
        begin = lines.index("AP-BEGIN")
        end = lines.index("AP-END", begin)
    except ValueError:
        raise SynthesisError("Festival's output has no segment list") from None
    out = FestivalOutput([], [])
    reader = _UtteranceReader(out)
    for number, line in enumerate(lines[begin + 1:end], start=begin + 2):
        kind, _, rest = line.partition("\t")
        if not kind.startswith("AP-"):
            continue                                 # the voice's own chatter ("Pause after PSP …")
        if kind == "AP-UTT":
            reader.next_utterance(rest, number)
        elif kind == "AP-WORD":
            reader.word(rest)
        elif kind == "AP-SEG":
            reader.segment(rest, number, line)
        elif kind == "AP-FEAT":
            phone, _, values = rest.partition("\t")
            out.features.setdefault(phone, PhoneFeatures.parse(values))
        elif kind == "AP-PHONESET":
            out.phoneset = rest.strip()
        else:
            raise SynthesisError(f"unexpected line {number} in Festival's output: {line!r}")
    reader.finish()
    if not out.phones:
        raise SynthesisError("Festival produced no phones")
    return out


class _UtteranceReader:
    """Collects one utterance's words and segments, then appends them to the whole text's, shifted."""

    def __init__(self, out: FestivalOutput) -> None:
        self.out = out
        self.number = 1
        self.offset = 0.0
        self.started = False
        self.word_names: dict[str, str] = {}
        self.word_order: list[str] = []
        self.raw: list[tuple[str, float, str]] = []

    def next_utterance(self, text: str, line: int) -> None:
        if self.started:
            self.finish()
        try:
            self.number = int(text.strip())
        except ValueError:
            raise SynthesisError(f"unreadable utterance line {line} in Festival's output") from None
        self.started = True

    def word(self, text: str) -> None:
        word_id, _, name = text.partition("\t")
        self.word_names[word_id] = name
        self.word_order.append(word_id)

    def segment(self, text: str, number: int, line: str) -> None:
        self.started = True
        fields = text.split("\t", 2)
        try:
            end_s = float(fields[0])
            word_id, label = fields[1], fields[2]
        except (ValueError, IndexError):
            raise SynthesisError(f"unreadable segment line {number} in Festival's output: {line!r}") from None
        self.raw.append((label, round(end_s * 1000.0, 3), word_id))

    def finish(self) -> None:
        """Append the utterance read so far (if it has phones) and start a new one."""
        if self.raw:
            self._append()
        self.word_names, self.word_order, self.raw = {}, [], []

    def _append(self) -> None:
        out, offset = self.out, self.offset
        spans: dict[str, list[float]] = {}
        local_start = 0.0
        for label, local_end, word_id in self.raw:
            if local_end < local_start:
                raise SynthesisError(f"Festival's phone {label!r} ends at {local_end} ms, "
                                     f"before it starts ({local_start} ms)")
            start, end = round(offset + local_start, 3), round(offset + local_end, 3)
            word = self.word_names.get(word_id, "")
            out.phones.append(Segment(label, start, end, word))
            if word_id in self.word_names:
                span = spans.setdefault(word_id, [start, end])
                span[1] = end
            local_start = local_end
        out.words += [Segment(self.word_names[w], spans[w][0], spans[w][1]) for w in self.word_order if w in spans]
        self.offset = round(offset + local_start, 3)
        out.utterance_numbers.append(self.number)
        out.utterance_ends_ms.append(self.offset)
