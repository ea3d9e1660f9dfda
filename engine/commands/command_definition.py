"""A high-level command as the library defines it (§2.3): its arguments and the curves of its lines.

:class:`CommandDefinition` is what a library file says about one command
(:mod:`engine.commands.library_format` reads it), the expansion procedures
(:mod:`engine.commands.procedures`) lay it out in time and the translator
turns it into activations. Times are ms, values parameter units.

>>> nod = CommandDefinition("HeadNod", ("at",), {"count": 1.0}, "linear", "periodic",
...                         (Curve("amplitude", (0.0, 500.0, 1000.0), (0.0, 0.15, 0.0), 8),), "HeadNod.lib", 1)
>>> nod.span(), nod.arguments()["count"], nod.arguments()["at"]
((0.0, 1000.0), 1.0, None)
"""

from __future__ import annotations

from dataclasses import dataclass, field

AMPLITUDE = "amplitude"
"""The paper's name for a command's percentage scale, and for its single line."""

START = "at"
"""The argument giving a command's start time in ms."""

IMPLICIT_ARGUMENTS = {START: 0.0, AMPLITUDE: 100.0}
"""Every command accepts these, with these defaults, unless its file says otherwise."""


@dataclass(frozen=True)
class Curve:
    """One line of a library file: the activation template of one parameter.

    ``name`` is as written (``amplitude`` or a model parameter); ``scale`` names
    the command argument that multiplies its values, if any. ``times`` are ms
    (strictly increasing), ``values`` parameter units. A single value with no
    time (``brow_raise = 1``) is a *level*, which only ``attack-hold-release``
    accepts; it is stored as ``times == ()``.
    """

    name: str
    times: tuple[float, ...]
    values: tuple[float, ...]
    line: int
    scale: str | None = None

    @property
    def is_level(self) -> bool:
        return not self.times


@dataclass(frozen=True)
class CommandDefinition:
    """One high-level command as a library file defines it (§2.3)."""

    name: str
    mandatory: tuple[str, ...]
    optional: dict[str, float]
    interpolation: str
    procedure: str
    curves: tuple[Curve, ...]
    file: str
    line: int
    parameter: str | None = None
    description: str = ""
    lines: dict[str, int] = field(default_factory=dict)
    """Line number of each directive, for messages."""

    def arguments(self) -> dict[str, float | None]:
        """Every argument the command accepts → its default (``None`` when mandatory)."""
        args: dict[str, float | None] = dict(IMPLICIT_ARGUMENTS)
        args.update(self.optional)
        for name in self.mandatory:
            args[name] = None
        return args

    def span(self) -> tuple[float, float]:
        """First and last key time over all curves (levels have no times)."""
        timed = [c for c in self.curves if c.times]
        if not timed:
            return 0.0, 0.0
        return min(c.times[0] for c in timed), max(c.times[-1] for c in timed)

    def where(self, directive: str | None = None) -> dict:
        """``file=`` and ``line=`` keywords for an error about this command or one directive."""
        return {"file": self.file, "line": self.line if directive is None else self.lines.get(directive, self.line)}
