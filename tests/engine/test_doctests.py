"""The examples in the engine's docstrings run and give what they show."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "engine.errors", "engine.formats.xml_io", "engine.commands.interpolation", "engine.commands.library_format",
    "engine.commands.library", "engine.commands.command_files", "engine.commands.translator",
    "engine.timeline.timeline", "engine.script.inline_commands", "engine.speech.articulation", "engine.speech.coarticulation",
    "engine.speech.prosody", "engine.model.landmarks",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
    assert result.attempted > 0
