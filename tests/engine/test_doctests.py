"""The examples in every engine module's docstrings run and give what they show.

Every module of the engine package is found by walking it, so a new module's
examples are tested without being listed anywhere.
"""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import engine

MODULES = sorted(m.name for m in pkgutil.walk_packages(engine.__path__, "engine.")
                 if not m.name.endswith("__main__"))


def test_the_walk_finds_the_engine():
    expected = {"engine.model.model", "engine.deform.deformer", "engine.cli.common", "engine.painting.brush"}
    assert expected <= set(MODULES)


@pytest.mark.parametrize("name", ["engine", *MODULES])
def test_docstring_examples(name):
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(module, name):
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples in {name} failed (output above)"
