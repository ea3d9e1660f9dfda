"""Starting points for a new library command, one per expansion procedure; the empty editor's example.

>>> print(template_text("once", "Twitch", "brow_raise"))        # doctest: +NORMALIZE_WHITESPACE
# Twitch: brow_raise rises and falls back once, over duration ms.
$command = Twitch
$description = brow_raise up and back down
$mandatory = at
$optional = amplitude=100, duration=400
$interp = cosine
brow_raise = 0,0; 150,1; 400,0
$proc = once
"""

from __future__ import annotations

import re

TEMPLATES: dict[str, tuple[str, str]] = {
    "attack-hold-release": (
        "Expression (onset, apex, offset)",
        "# {name}: {parameter} rises over onset ms, holds for apex ms and falls over offset ms.\n"
        "$command = {name}\n"
        "$description = {parameter} raised and held, like an expression\n"
        "$mandatory = at\n"
        "$optional = amplitude=100, onset=300, apex=1000, offset=500\n"
        "$interp = cosine\n"
        "{parameter} = 1\n"
        "$proc = attack-hold-release\n"),
    "periodic": (
        "Repeated gesture (count, period)",
        "# {name}: {parameter} swings count times, one swing per period ms (like HeadNod, §2.3).\n"
        "$command = {name}\n"
        "$description = {parameter} swung back and forth\n"
        "$mandatory = at\n"
        "$optional = amplitude=100, count=2, period=500\n"
        "$interp = cosine\n"
        "{parameter} = 0,0; 250,0.5; 500,0\n"
        "$proc = periodic\n"),
    "once": (
        "One movement (duration)",
        "# {name}: {parameter} rises and falls back once, over duration ms.\n"
        "$command = {name}\n"
        "$description = {parameter} up and back down\n"
        "$mandatory = at\n"
        "$optional = amplitude=100, duration=400\n"
        "$interp = cosine\n"
        "{parameter} = 0,0; 150,1; 400,0\n"
        "$proc = once\n"),
}

COMMAND_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


def template_text(kind: str, name: str, parameter: str) -> str:
    """The text of a new library file defining command ``name`` that drives ``parameter``."""
    if kind not in TEMPLATES:
        raise ValueError(f"unknown template '{kind}' (known: {', '.join(TEMPLATES)})")
    return TEMPLATES[kind][1].format(name=name, parameter=parameter)


def example_text(parameters: list[str]) -> str:
    """What the empty library editor shows, greyed, until something is typed: an example and where templates are.

    The example drives the model's first parameter, so it would be valid as written.
    """
    parameter = parameters[0] if parameters else "parameter_name"
    return ("Type a library file (§2.3) here, for example:\n\n"
            + template_text("periodic", "MyGesture", parameter)
            + "\nor start from a template: New on the toolbar.")
