"""Observers trained on photographs of real people judge our pictures and videos (``validate``).

Before a participant sees a stimulus, the toolkit can check that the face reads as a face, the
expression as the intended emotion, the identity as one person (and another person from the
next identity), and the lips as the sounds — for our stimuli and for a lab's recordings of
actors alike. The observers are dlib's face detector, 68-point landmarks and face descriptor,
and a FER2013 emotion classifier (:mod:`engine.validation.observers`; the optional extra
``validate``). ``docs/validation.md`` says what each is trained on, and may be used for.

>>> from engine.validation import validate, write_tables, write_report
>>> summary = validate(["stimuli/"])                      # a stimulus set's folder   # doctest: +SKIP
>>> f"{summary.read} of {summary.scored} emotions read as intended"                  # doctest: +SKIP
'30 of 35 emotions read as intended'
>>> write_tables(summary, "validation.csv")                                          # doctest: +SKIP
>>> write_report(summary, "report.html")                                             # doctest: +SKIP
"""

from engine.validation.intended import Intended, intended_emotion, read_intended, read_set, stimulus_intended
from engine.validation.judge import Verdict, judge_file, judge_pixels
from engine.validation.lips import LipTrack, lip_track, read_landmarks_track
from engine.validation.observers import EMOTIONS, SAME_PERSON, ObserversMissing, observers
from engine.validation.report import report_html, write_report
from engine.validation.run import NothingReadable, validate
from engine.validation.summary import Summary, summarise
from engine.validation.table import COLUMNS, write_tables

__all__ = ["COLUMNS", "EMOTIONS", "SAME_PERSON", "Intended", "LipTrack", "NothingReadable", "ObserversMissing",
           "Summary", "Verdict", "intended_emotion", "judge_file", "judge_pixels", "lip_track", "observers",
           "read_intended", "read_landmarks_track", "read_set", "report_html", "stimulus_intended", "summarise",
           "validate", "write_report", "write_tables"]
