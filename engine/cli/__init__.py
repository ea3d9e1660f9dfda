"""The command line, ``artificial-person <verb>``.

Every verb calls the same engine functions the workbench uses. Mistakes in
the user's input (a bad option, an unknown parameter, a malformed model file)
end with status 2 and one line on stderr, ``error: <file>:<line>: <what>``,
never a traceback.

The verbs live in one module each (``model_verbs``, ``command_verbs``,
``speech_verbs``, ``export_verbs``, ``config_verbs``, ``mocap_verbs``), sharing only
:mod:`engine.cli.common`. Other installed packages add verbs through the
``artificial_person.verbs`` entry point group: the workbench adds
``workbench`` that way, so the engine never imports the GUI. A verb whose optional
part (an extra of the distribution, :mod:`engine.cli.extras`) is not installed ends
with one line naming the ``pip install 'artificial-person[EXTRA]'`` to run, status 2.

>>> from engine.cli import main
>>> main(["info", "--json"])                                   # doctest: +SKIP
"""

from __future__ import annotations

import argparse
import errno
import sys
from importlib import import_module
from importlib.metadata import entry_points

from engine.cli.common import PROG, CliParser, say_error
from engine.cli.extras import check_extras, extra_for_import_error
from engine.errors import UserError

#: The engine's own verb modules, in the order ``--help`` lists them; each has ``add_verbs(verbs)``.
VERB_MODULES = ("model_verbs", "command_verbs", "speech_verbs", "stimuli_verbs", "identity_verbs", "export_verbs",
                "config_verbs", "mocap_verbs", "capture_verbs", "serve_verbs", "photofit_verbs", "web_verbs",
                "validate_verbs", "study_verbs")
#: System errors that a user's own file name causes (too long, a folder where a file belongs):
#: bad input, status 2, like every other mistake in the arguments.
USER_ERRNOS = frozenset({errno.ENAMETOOLONG, errno.EISDIR, errno.ENOTDIR})
#: Entry point group through which other packages add verbs (``add_verbs(verbs)`` callables).
PLUGIN_GROUP = "artificial_person.verbs"


def main(argv: list[str] | None = None) -> int:
    """Run one command; returns the exit status (0 ok, 2 bad input, 1 environment trouble)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        check_extras(args)                 # an optional part the verb needs and lacks: one line, before any work
        return int(args.run(args) or 0)
    except UserError as exc:
        say_error(str(exc))
        return 2
    except ImportError as exc:            # a module of an extra, imported deep in a verb (a bug elsewhere: raised)
        line = extra_for_import_error(exc)
        if line is None:
            raise
        say_error(line)
        return 2
    except SystemExit as exc:  # --help and --version
        return exc.code if isinstance(exc.code, int) else 0
    except KeyboardInterrupt:
        return 130
    except MemoryError:  # a count or size in the input asking for far more than any real file needs
        say_error("out of memory: the input asks for more memory than this machine has (a count, size or "
                  "duration in it may be wrong)")
        return 2
    except BrokenPipeError:  # e.g. `artificial-person info | head`
        sys.stderr.close()
        return 0
    except OSError as exc:  # disk full, permissions: not a bug, so no traceback either
        where = f"{exc.filename}: " if exc.filename else ""
        say_error(f"{where}{exc.strerror or exc}")
        return 2 if exc.errno in USER_ERRNOS else 1


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with one sub-parser per verb (the engine's, then those of plugins)."""
    from engine import __version__

    parser = CliParser(prog=PROG, description="Build, configure and animate the Artificial Person talking head.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB", required=True)
    for plugin in sorted(entry_points(group=PLUGIN_GROUP), key=lambda e: e.name):
        try:
            add_verbs = plugin.load()
        except ImportError:          # a plugin whose package is gone: its verbs are absent, the rest work
            continue
        add_verbs(verbs)
    for name in VERB_MODULES:
        import_module(f"{__name__}.{name}").add_verbs(verbs)
    return parser
