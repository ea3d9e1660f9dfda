"""The ``serve`` verb: the head as a live service over WebSocket/JSON (``docs/serve.md``).

Safe by default: it listens on 127.0.0.1; any address that is not loopback needs a token
(``--token`` or the environment variable ``AP_SERVE_TOKEN``), and a client without it is refused.
This version is headless only (``--headless``); ``--festival HOST:PORT`` synthesizes with a Festival
server (``festival --server``) instead of a local Festival; ``--lsl`` pushes every event to a Lab
Streaming Layer marker outlet too, liblsl kept to this computer unless told otherwise.

>>> check_listen_address("127.0.0.1", None)
>>> check_listen_address("0.0.0.0", None)   # doctest: +ELLIPSIS
Traceback (most recent call last):
...
engine.errors.UserError: listening on 0.0.0.0 (not loopback) needs --token TOKEN: ...
"""

from __future__ import annotations

import argparse
import ipaddress
import os
from pathlib import Path
from typing import Any

from engine.cli.common import add_library_option, add_model_option
from engine.errors import UserError

TOKEN_VARIABLE = "AP_SERVE_TOKEN"
LOOPBACK_NAMES = ("localhost",)


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("serve", help="the live animator over WebSocket/JSON (headless in this version)")
    add_model_option(p)
    add_library_option(p)
    p.add_argument("--host", default="127.0.0.1", metavar="H",
                   help="address to listen on (default 127.0.0.1; any other needs --token)")
    p.add_argument("--port", type=port_number, default=8765, metavar="P", help="port (default 8765; 0: any free one)")
    p.add_argument("--headless", action="store_true",
                   help="render nothing: parameter values and events only, on a 60 Hz frame clock (required "
                        "in this version)")
    p.add_argument("--festival", default=None, metavar="HOST:PORT",
                   help="synthesize with the Festival server (festival --server) at HOST:PORT instead of a local "
                        "Festival; the same phones, words and waves")
    p.add_argument("--lsl", action="store_true",
                   help="push every event to a Lab Streaming Layer marker outlet too (ArtificialPerson, type Markers); "
                        "liblsl discovery stays on this computer unless --lsl-config or $LSLAPICFG names another "
                        "lsl_api.cfg")
    p.add_argument("--lsl-config", default=None, metavar="FILE",
                   help="liblsl configuration (lsl_api.cfg) for --lsl instead of the loopback-only default")
    p.add_argument("--models", dest="model_folders", action="append", default=[], metavar="DIR",
                   help="a folder whose model files (.xml) a client may load (may be repeated; -m's folder and the "
                        "-L folders are served too)")
    p.add_argument("--token", default=None, metavar="TOKEN",
                   help=f"clients must send 'Authorization: Bearer TOKEN' (default: ${TOKEN_VARIABLE}, if set)")
    p.set_defaults(run=run_serve)


def run_serve(args: argparse.Namespace) -> int:
    """Check the options, load the model, serve until interrupted."""
    import asyncio

    from engine.cli.common import load_model_argument
    from engine.commands import load_library

    if not args.headless:
        raise UserError("serve needs --headless in this version (the window mode is to come: docs/serve.md)")
    token = args.token if args.token is not None else os.environ.get(TOKEN_VARIABLE) or None
    if token is not None and (not token.strip() or any(ord(c) < 33 or ord(c) > 126 for c in token)):
        raise UserError("--token must be printable ASCII without spaces")
    check_listen_address(args.host, token)
    synthesizer = None
    if args.festival is not None:
        from engine.speech.festival_server import festival_synthesizer

        synthesizer = festival_synthesizer(args.festival)
        synthesizer.voices()                                  # an unreachable server is refused before serving
    if args.lsl_config is not None and not args.lsl:
        raise UserError("--lsl-config needs --lsl")
    if args.lsl:
        from engine.live.lsl import import_pylsl, use_lsl_config

        use_lsl_config(args.lsl_config)                      # before liblsl is loaded: it reads it once
        import_pylsl()
    folders = served_model_folders(args.model, args.library, args.model_folders)
    model = load_model_argument(args.model)
    library = load_library(args.library)
    from engine.live.server import LiveServer

    server = LiveServer(model, host=args.host, port=args.port, token=token, library=library,
                        synthesizer=synthesizer, lsl=args.lsl, model_folders=folders,
                        model_name=Path(args.model).name if args.model else "head.xml",
                        model_reader=load_model_argument)
    asyncio.run(server.run(ready=lambda line: print(line, flush=True)))
    return 0


def served_model_folders(model: str | None, libraries: list[str], extra: list[str]) -> list[Path]:
    """The folders a ``load`` request may read model files from: -m's (or the shipped head's), -L's, --models."""
    from engine.paths import default_model_path

    folders = [Path(model).parent if model else default_model_path().parent]
    folders += [Path(library) if Path(library).is_dir() else Path(library).parent for library in libraries]
    for folder in extra:
        if not Path(folder).is_dir():
            raise UserError("--models names no folder", file=folder)
        folders.append(Path(folder))
    return folders


def check_listen_address(host: str, token: str | None) -> None:
    """Refuse to listen beyond this computer without a token."""
    if token is None and not is_loopback(host):
        raise UserError(f"listening on {host} (not loopback) needs --token TOKEN: any computer that reaches it "
                        "could drive the head")


def is_loopback(host: str) -> bool:
    """127.0.0.0/8, ::1 and 'localhost' are loopback; every other name or address counts as not."""
    if host.lower() in LOOPBACK_NAMES:
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def port_number(text: str) -> int:
    """A TCP port, 0 … 65535."""
    if not text.strip().isdigit() or not 0 <= int(text) <= 65535:
        raise argparse.ArgumentTypeError(f"'{text}' is not a port number (0 … 65535)")
    return int(text)
