"""Stimulus sets from design files: every combination of the factors, made reproducibly (docs/stimuli.md).

``load_design`` reads a TOML design, ``make_set`` makes it (in parallel
processes or on a Dask cluster, resumable), ``make_stimulus`` makes one.
"""

from engine.stimuli.design import Design, DesignError, Stimulus, load_design, parse_design
from engine.stimuli.run import SetResult, make_set

__all__ = ["Design", "DesignError", "SetResult", "Stimulus", "load_design", "make_set", "parse_design"]
