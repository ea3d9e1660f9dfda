"""What the fuzz tests share: their size, a guard against hangs, and the one check they all make.

Every fuzz test runs ``AP_FUZZ_EXAMPLES`` inputs (default 200, so the suite
stays affordable); the release check runs 10,000 per parser
(``AP_FUZZ_EXAMPLES=10000``, ``docs/robustness.md``). Each input must end
normally or with the parser's own documented error naming the file; any other
exception, or an input that takes longer than :data:`HANG_SECONDS`, fails.
"""

from __future__ import annotations

import os
import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from engine.errors import UserError

EXAMPLES = int(os.environ.get("AP_FUZZ_EXAMPLES", "200"))
HANG_SECONDS = 30
"""An input still being parsed after this long counts as a hang (a generous bound, not a timing check)."""

FUZZ = settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=False,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.function_scoped_fixture])


class Hang(Exception):
    """An input took longer than :data:`HANG_SECONDS`."""


@contextmanager
def no_hang(seconds: int = HANG_SECONDS) -> Iterator[None]:
    """Raise :class:`Hang` in the block if it runs longer than ``seconds``."""
    def alarm(signum: int, frame: Any) -> None:
        raise Hang(f"still running after {seconds} s")

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def outcome(call: Callable[[], object], error: type[UserError] = UserError) -> object:
    """What ``call`` returns, or the ``error`` it raises (any other exception, or a hang, propagates)."""
    with no_hang():
        try:
            return call()
        except error as exc:
            return exc


def expect_clean(parse: Callable[[], object], error: type[UserError], name: str) -> object:
    """Run ``parse``: it returns, or raises ``error`` whose message names ``name``; nothing else."""
    result = outcome(parse, error)
    if isinstance(result, error):
        assert result.file is not None and name in result.file, f"the error does not name the file: {result}"
        assert str(result).startswith(name), str(result)
    return result


# -- strategies -------------------------------------------------------------------------------------

#: Numbers as a hostile file writes them: ordinary, huge, tiny, non-finite, malformed.
NUMBER_TEXT = st.one_of(
    st.integers(-10**6, 10**6).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.sampled_from(["1e308", "1e9", "1e-300", "1e999", "nan"]),
    st.sampled_from(["1e308", "-1e308", "1e999", "-1e999", "1e-320", "nan", "inf", "-inf", "1e9", "0",
                     "-0", "0.0000001", "1e-300", "86400000", "86400001", "", " ", "1,5", "0x10", "1_000",
                     "١٢", "--1", "1e", ".", "+.5e-3"]),
)


def mutated(seed_text: str) -> st.SearchStrategy[str]:
    """``seed_text`` with a few characters replaced, inserted or deleted, or cut short."""
    def apply(edits: list[tuple[int, int, str]]) -> str:
        text = seed_text
        for kind, position, insert in edits:
            if not text:
                text = insert
                continue
            i = position % (len(text) + 1)
            if kind == 0:
                text = text[:i] + insert + text[i:]
            elif kind == 1:
                text = text[:i] + text[i + 1:]
            elif kind == 2:
                text = text[:i] + insert + text[i + 1:]
            else:
                text = text[:i]
        return text

    edit = st.tuples(st.integers(0, 3), st.integers(0, 10**6),
                     st.one_of(st.text(max_size=4), NUMBER_TEXT, st.sampled_from(['"', "<", ">", "&", ";", ",",
                                                                                 "\n", "=", "$", "#", "[", "]"])))
    return st.lists(edit, min_size=1, max_size=6).map(apply)
