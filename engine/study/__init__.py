"""Rating studies of stimulus sets: the paper's evaluation (§4) as a product (docs/study.md).

``build_study`` turns a study design (TOML) into a self-contained jsPsych experiment for a folder, a lab
computer, JATOS, Pavlovia and Cognition.run; ``analyse`` reads the participants' CSVs back and sums them
up with the field's measures (recognition rates with their intervals, confusion matrices, Wagner's
unbiased hit rate and chance proportions, ratings, contrasts), beside the ``validate`` verdicts.

>>> from engine.study import build_study
>>> built = build_study("examples/study/katsyri2003.toml", "study/")              # doctest: +SKIP
>>> built.document["study_id"]                                                     # doctest: +SKIP
"""

from engine.study.build import BuiltStudy, build_study
from engine.study.design import StudyDesign, StudyDesignError, load_study_design, parse_study_design

__all__ = ["BuiltStudy", "StudyDesign", "StudyDesignError", "build_study", "load_study_design", "parse_study_design"]
