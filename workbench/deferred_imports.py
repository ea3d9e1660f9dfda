"""Start-up time: modules our dependencies import but the workbench does not use run on first use.

pyvista imports ``matplotlib.pyplot`` when it loads, and uses it only inside
a few functions (a colour cycler, matplotlib charts) the workbench never
calls. Executing pyplot costs about 0.3 s, a tenth of the time from launch
to the head on screen (``benchmarks/bench_launch.py``). With
:func:`install` called before pyvista is imported, ``import
matplotlib.pyplot`` gives a module object at once, and pyplot's code runs
the first time anything reads a name from it::

    >>> install()                                   # doctest: +SKIP
    >>> import matplotlib.pyplot as plt             # doctest: +SKIP
    >>> plt.plot                                    # pyplot loads here  # doctest: +SKIP

Unlike :class:`importlib.util.LazyLoader`, whose module loads on *any*
attribute read (on Python 3.11 a second ``import`` statement reads
``__spec__`` and so loads it), this module object carries its own
``__spec__`` and ``__name__`` and loads only when a name it does not have yet
is asked for (a module ``__getattr__``, PEP 562), or its names are listed
(``dir``, ``from … import *``). Other dunder names are answered without
running it: PySide6's import hook asks every newly imported module for
``__wrapped__``. A module that is already imported is left alone, so
calling :func:`install` late changes nothing.
"""

from __future__ import annotations

import importlib.machinery
import sys
import threading

#: Imported by our dependencies, not used by the workbench at start.
DEFERRED = ("matplotlib.pyplot",)

#: Dunder names a module may define that mean "use the module": reading one runs it.
LOADING_DUNDERS = frozenset({"__all__", "__version__"})


class _LoadOnFirstUse:
    """Loader that leaves the module empty until a name is read from it, then runs ``loader``."""

    def __init__(self, loader):
        self.loader = loader
        self.lock = threading.RLock()

    def create_module(self, spec):
        return self.loader.create_module(spec)

    def exec_module(self, module) -> None:
        real = self.loader
        lock = self.lock

        def load() -> None:
            with lock:
                if module.__dict__.get("__getattr__") is deferred_getattr:
                    del module.__dict__["__getattr__"], module.__dict__["__dir__"]
                    module.__loader__ = module.__spec__.loader = real
                    real.exec_module(module)

        def deferred_getattr(name: str):
            # Tools that look modules over ask for dunder names (PySide's import hook asks each newly
            # imported module for ``__wrapped__``): answer those without running the module.
            if name.startswith("__") and name.endswith("__") and name not in LOADING_DUNDERS:
                raise AttributeError(f"module {module.__name__!r} has no attribute {name!r}")
            load()
            return getattr(module, name)

        def deferred_dir():
            load()
            return sorted(module.__dict__)

        module.__getattr__ = deferred_getattr      # the module's own __getattr__ and __dir__ (PEP 562)
        module.__dir__ = deferred_dir


class _DeferringFinder:
    """A ``sys.meta_path`` entry that hands out each name in ``names`` once, with a deferring loader."""

    def __init__(self, names):
        self.names = set(names)

    def find_spec(self, name, path=None, target=None):
        if name not in self.names:
            return None
        self.names.discard(name)               # once: later imports find the module in sys.modules
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is not None and spec.loader is not None and hasattr(spec.loader, "exec_module"):
            spec.loader = _LoadOnFirstUse(spec.loader)
        return spec


_finder = _DeferringFinder(())


def install(names=DEFERRED) -> None:
    """Defer running each module in ``names`` that is not imported yet until it is first used."""
    _finder.names.update(n for n in names if n not in sys.modules)
    if _finder.names and _finder not in sys.meta_path:
        sys.meta_path.insert(0, _finder)
