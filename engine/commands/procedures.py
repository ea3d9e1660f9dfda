"""Expansion procedures (§2.3 ``$proc``): how a command's template is laid out in time.

A procedure receives one line's template (times in ms from the template's
first key, values in parameter units, before any scaling), the span of the
whole command's template and the command's arguments, and returns the keys of
the activation with times measured from the command's ``at``. The translator
then adds ``at`` and scales the values.

Shipped procedures:

* ``periodic`` (the paper's) — the template repeated ``count`` times, each
  repetition stretched to one ``period``; ``count``, ``period``, ``frequency``
  (repetitions per second, i.e. ``period = 1000/frequency``) and ``end`` (the
  action's length from ``at``, ``end = count · period``) overdetermine it, so
  the precedence rules of :func:`periodic_timing` decide.
* ``once`` — the template stretched to ``duration`` ms (as written when the
  command has no ``duration``).
* ``attack-hold-release`` — onset, apex and offset durations, the timing
  model of facial-expression research: each line rises to its peak during
  ``onset``, holds for ``apex`` and returns during ``offset``.

A new procedure is a Python function registered under a name::

    from engine.commands.procedures import register_procedure, stretch

    @register_procedure("twice", arguments=("gap",), required=("gap",))
    def twice(times, values, span, args):
        one = stretch(times, span, 0.0, span[1] - span[0])
        return (np.concatenate([one, one + one[-1] + args["gap"]]),
                np.concatenate([values, values]))

after which library files may say ``$proc = twice``. See ``docs/commands.md``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
import numpy.typing as npt

from engine.commands.command_definition import IMPLICIT_ARGUMENTS, CommandDefinition
from engine.commands.limits import check_key_count
from engine.errors import LibraryError


class ArgumentProblem(ValueError):
    """A command's arguments do not define a valid action (the translator adds file and line)."""


class Arguments(Mapping[str, float]):
    """A command's argument values, remembering which ones the command itself gave."""

    def __init__(self, values: Mapping[str, float], given: set[str], default_order: tuple[str, ...] = ()):
        self._values = dict(values)
        self.given = frozenset(given)
        self.default_order = default_order

    def __getitem__(self, name: str) -> float:
        return self._values[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def is_given(self, name: str) -> bool:
        return name in self.given


ProcedureFunction = Callable[[np.ndarray, np.ndarray, tuple[float, float], Arguments],
                             tuple[npt.ArrayLike, npt.ArrayLike]]
"""``function(times, values, span, args) -> (times, values)``: one line laid out in time."""

_Function = TypeVar("_Function", bound=ProcedureFunction)


@dataclass(frozen=True)
class Procedure:
    name: str
    function: ProcedureFunction
    arguments: tuple[str, ...]
    """The command arguments the procedure reads (a library may declare any of them)."""
    required: tuple[str, ...]
    """Arguments every command using the procedure must declare (mandatory, or optional with a default)."""
    accepts_levels: bool
    """Whether lines may be a single level (``brow_raise = 1``) instead of time,value pairs."""


PROCEDURES: dict[str, Procedure] = {}


def register_procedure(name: str, arguments: tuple[str, ...] = (), required: tuple[str, ...] = (),
                       accepts_levels: bool = False) -> Callable[[_Function], _Function]:
    """Decorator: make ``function(times, values, span, args) -> (times, values)`` available as ``$proc = name``."""

    def decorate(function: _Function) -> _Function:
        PROCEDURES[name] = Procedure(name, function, tuple(arguments), tuple(required), accepts_levels)
        return function

    return decorate


def check_definition(definition: CommandDefinition) -> None:
    """Library-file checks that need the procedure: it exists, its arguments are declared and used."""
    where = definition.where("proc")
    procedure = PROCEDURES.get(definition.procedure)
    if procedure is None:
        raise LibraryError(f"unknown procedure '{definition.procedure}' (known: {', '.join(sorted(PROCEDURES))})",
                           **where)
    declared = set(definition.mandatory) | set(definition.optional) | set(IMPLICIT_ARGUMENTS)
    for name in procedure.required:
        if name not in declared:
            raise LibraryError(f"procedure '{procedure.name}' needs the argument '{name}': declare it in "
                               f"$mandatory, or in $optional with a default", **where)
    for curve in definition.curves:
        if curve.scale is not None and curve.scale not in declared:
            raise LibraryError(f"line '{curve.name}' is scaled by '{curve.scale}', which the command does not "
                               "declare in $mandatory or $optional", file=definition.file, line=curve.line)
        if curve.is_level and not procedure.accepts_levels:
            raise LibraryError(f"line '{curve.name}' gives a single level, which only procedure "
                               f"'attack-hold-release' accepts; give time,value pairs for '{procedure.name}'",
                               file=definition.file, line=curve.line)
    used = set(procedure.arguments) | {c.scale for c in definition.curves if c.scale} | set(IMPLICIT_ARGUMENTS)
    for name in list(definition.mandatory) + list(definition.optional):
        if name not in used:
            directive = "mandatory" if name in definition.mandatory else "optional"
            raise LibraryError(f"argument '{name}' is used neither by procedure '{procedure.name}' "
                               f"(which reads {_listing(procedure.arguments)}) nor by any line",
                               **definition.where(directive))


def expand(definition: CommandDefinition, args: Arguments) -> list[tuple[np.ndarray, np.ndarray]]:
    """Keys (times from ``at``, unscaled values) of every line of a command."""
    procedure = PROCEDURES[definition.procedure]
    span = definition.span()
    out: list[tuple[np.ndarray, np.ndarray]] = []
    for curve in definition.curves:
        times, values = procedure.function(np.array(curve.times, dtype=float),
                                           np.array(curve.values, dtype=float), span, args)
        out.append(merge_repeated_keys(np.asarray(times, float), np.asarray(values, float)))
    return out


# ---------------------------------------------------------------------------
# Helpers for procedures
# ---------------------------------------------------------------------------

def stretch(times: np.ndarray, span: tuple[float, float], start: float, duration: float) -> np.ndarray:
    """Map ``span`` linearly onto ``[start, start + duration]``."""
    t0, t1 = span
    if t1 <= t0:
        return np.full(times.shape, float(start))
    return start + (times - t0) * (duration / (t1 - t0))


def merge_repeated_keys(times: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop a key that repeats the previous one (same time, same value), e.g. where two periods meet.

    Two keys at one time with different values are kept: a jump.
    """
    if times.size < 2:
        return times, values
    same = (np.diff(times) == 0) & (np.diff(values) == 0)
    keep = np.concatenate([[True], ~same])
    return times[keep], values[keep]


def _positive(args: Mapping[str, float], name: str) -> float:
    value = args[name]
    if not value > 0:
        raise ArgumentProblem(f"{name} must be positive (got {value:g})")
    return value


def _non_negative(args: Mapping[str, float], name: str) -> float:
    value = args[name]
    if value < 0:
        raise ArgumentProblem(f"{name} must not be negative (got {value:g})")
    return value


def _listing(names: Sequence[str]) -> str:
    return ", ".join(f"'{n}'" for n in names) if names else "no arguments"


# ---------------------------------------------------------------------------
# periodic (§2.3)
# ---------------------------------------------------------------------------

PERIODIC_ARGUMENTS = ("count", "period", "frequency", "end")
DEFAULT_PRECEDENCE = ("period", "frequency", "count", "end")
"""Order in which library defaults fill in what the command leaves open."""


def periodic_timing(args: Arguments, template_length: float) -> tuple[int, float]:
    """``(count, period)`` of a periodic action from any sufficient subset of its arguments.

    The action is fixed by two of *count*, *period* (or *frequency*, the
    same quantity as ``1000/period``) and *end* (``= count · period``):

    1. Arguments the command gives win over library defaults. Given ones must
       agree with each other (``period`` with ``frequency``; ``count``,
       ``period`` and ``end`` together); disagreement is an error.
    2. What is still open is filled from the library's defaults in the order
       period, frequency, count, end — so ``count="3"`` alone repeats the
       default period three times, and ``end="2000"`` alone repeats the
       default period until 2000 ms after ``at``.
    3. With ``end`` and ``period`` known, ``count`` is ``end/period`` rounded to
       the nearest whole number (at least 1) and the period is then adjusted
       so the action ends exactly at ``end``.
    4. Where neither the command nor the library gives enough, one repetition
       and the template's own length fill in.
    """
    known: dict[str, float] = {}
    for name in PERIODIC_ARGUMENTS:
        if args.is_given(name) and name in args:
            known[name] = _periodic_value(args, name)
    if ("period" in known and "frequency" in known
            and not math.isclose(known["period"], 1000.0 / known["frequency"], rel_tol=1e-9)):
        raise ArgumentProblem(f"period={known['period']:g} and frequency={known['frequency']:g} disagree "
                              f"(frequency={known['frequency']:g} means period={1000.0 / known['frequency']:g})")
    quantities = _quantities(known)
    if len(quantities) == 3 and not math.isclose(quantities["count"] * quantities["period"], quantities["end"],
                                                 rel_tol=1e-9):
        raise ArgumentProblem(f"count={quantities['count']:g}, period={quantities['period']:g} and "
                              f"end={quantities['end']:g} disagree (end must be count × period)")
    for name in DEFAULT_PRECEDENCE:
        if len(quantities) >= 2:
            break
        if name in args and not args.is_given(name):
            trial = dict(known)
            trial[name] = _periodic_value(args, name)
            candidate = _quantities(trial)
            if len(candidate) > len(quantities):
                known, quantities = trial, candidate
    if "count" not in quantities and "period" not in quantities:
        quantities["count"] = 1.0
    if len(quantities) < 2:
        if "count" in quantities:
            quantities["period"] = template_length
        elif "period" in quantities:
            quantities["count"] = 1.0
        else:  # end only
            quantities["count"] = 1.0
    if "period" not in quantities:
        check_key_count(quantities["count"], "count")
        return int(quantities["count"]), quantities["end"] / quantities["count"]
    if "count" not in quantities:
        repetitions = quantities["end"] / quantities["period"]
        check_key_count(repetitions, f"end={quantities['end']:g} at period={quantities['period']:g}")
        count = max(1, round(repetitions))
        return count, quantities["end"] / count
    check_key_count(quantities["count"], "count")
    return int(quantities["count"]), quantities["period"]


def _periodic_value(args: Arguments, name: str) -> float:
    value = _positive(args, name)
    if name == "count" and value != int(value):
        raise ArgumentProblem(f"count must be a whole number (got {value:g})")
    return value


def _quantities(known: dict[str, float]) -> dict[str, float]:
    out: dict[str, float] = {}
    if "count" in known:
        out["count"] = known["count"]
    if "period" in known:
        out["period"] = known["period"]
    elif "frequency" in known:
        out["period"] = 1000.0 / known["frequency"]
    if "end" in known:
        out["end"] = known["end"]
    return out


@register_procedure("periodic", arguments=PERIODIC_ARGUMENTS)
def periodic(times: np.ndarray, values: np.ndarray, span: tuple[float, float],
             args: Arguments) -> tuple[np.ndarray, np.ndarray]:
    """The template repeated ``count`` times, one repetition per ``period`` (§2.3)."""
    count, period = periodic_timing(args, span[1] - span[0])
    check_key_count(count * times.size, f"count={count} repetitions of {times.size} keys")
    one = stretch(times, span, 0.0, period)
    all_times = np.concatenate([one + k * period for k in range(count)])
    return all_times, np.tile(values, count)


# ---------------------------------------------------------------------------
# once
# ---------------------------------------------------------------------------

@register_procedure("once", arguments=("duration",))
def once(times: np.ndarray, values: np.ndarray, span: tuple[float, float],
         args: Arguments) -> tuple[np.ndarray, np.ndarray]:
    """The template once, stretched to ``duration`` (or as written when there is none)."""
    duration = _positive(args, "duration") if "duration" in args else span[1] - span[0]
    return stretch(times, span, 0.0, duration), values


# ---------------------------------------------------------------------------
# attack-hold-release
# ---------------------------------------------------------------------------

@register_procedure("attack-hold-release", arguments=("onset", "apex", "offset"),
                    required=("onset", "apex", "offset"), accepts_levels=True)
def attack_hold_release(times: np.ndarray, values: np.ndarray, span: tuple[float, float],
                        args: Arguments) -> tuple[np.ndarray, np.ndarray]:
    """Onset, apex and offset phases of given durations.

    A level (``brow_raise = 1``) becomes 0 → level over ``onset``, level for
    ``apex``, level → 0 over ``offset``. A time,value line is cut into the
    same three phases at its peak: onset from the first key to the first key
    of largest magnitude, apex from there to the last key of largest
    magnitude, offset to the end; each phase is stretched to its duration.
    """
    onset, apex, offset = (_non_negative(args, n) for n in ("onset", "apex", "offset"))
    if times.size == 0:
        level = values[0]
        return np.array([0.0, onset, onset + apex, onset + apex + offset]), np.array([0.0, level, level, 0.0])
    magnitude = np.abs(values)
    peaks = np.flatnonzero(magnitude == magnitude.max())
    first, last = int(peaks[0]), int(peaks[-1])
    phases = ((0, first, 0.0, onset), (first, last, onset, apex), (last, times.size - 1, onset + apex, offset))
    out_t: list[np.ndarray] = []
    out_v: list[np.ndarray] = []
    for i, j, start, duration in phases:
        segment = times[i:j + 1]
        out_t.append(stretch(segment, (segment[0], segment[-1]), start, duration))
        out_v.append(values[i:j + 1])
    return np.concatenate(out_t), np.concatenate(out_v)
