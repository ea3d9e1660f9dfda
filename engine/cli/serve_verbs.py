"""The ``serve`` verb: the head as a live service over WebSocket/JSON (``docs/serve.md``).

Safe by default: it listens on 127.0.0.1; any address that is not loopback needs a token
(``--token`` or the environment variable ``AP_SERVE_TOKEN``), and a client without it is refused.
``--window`` shows the head in a window of its own (the workbench package's
:mod:`workbench.live_window`, found through the entry point group
``artificial_person.windows``: the engine imports no Qt), at the display's refresh rate, with
sound; ``--headless`` renders nothing. ``--festival HOST:PORT`` synthesizes with a Festival
server (``festival --server``) instead of a local Festival; ``--lsl`` pushes every event to a Lab
Streaming Layer marker outlet too, liblsl kept to this computer unless told otherwise.

>>> listen_host("[::1]")                    # an IPv6 literal, bare or in brackets as in a URL
'::1'
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

from engine.cli.common import add_library_option, add_model_option, size
from engine.errors import UserError

TOKEN_VARIABLE = "AP_SERVE_TOKEN"
#: Entry point group through which a package offers the window of ``serve --window``: ``serve(make_server,
#: fullscreen, size, ready)``, ``make_server(presenter)`` making the server (``engine.live.presentation``).
WINDOW_GROUP = "artificial_person.windows"
LOOPBACK_NAMES = ("localhost",)


def add_verbs(verbs: Any) -> None:
    p = verbs.add_parser("serve", help="the live animator over WebSocket/JSON, in a window of its own or headless")
    add_model_option(p)
    add_library_option(p)
    p.add_argument("--host", type=listen_host, default="127.0.0.1", metavar="H",
                   help="address to listen on: a host name, an IPv4 address or an IPv6 address, bare or in brackets "
                        "(::1 or [::1]) (default 127.0.0.1; any but loopback needs --token)")
    p.add_argument("--port", type=port_number, default=8765, metavar="P", help="port (default 8765; 0: any free one)")
    shown = p.add_mutually_exclusive_group(required=True)
    shown.add_argument("--window", action="store_true",
                       help="show the head in a window of its own at the display's refresh rate, with sound; "
                            "events are stamped with the moment their frame was on the screen")
    shown.add_argument("--headless", action="store_true",
                       help="render nothing: parameter values and events only, on a 60 Hz frame clock")
    p.add_argument("--fullscreen", action="store_true", help="with --window: full screen, no cursor (F11 toggles)")
    p.add_argument("--size", type=size, default=(600, 800), metavar="WxH",
                   help="with --window: the window's size in pixels (default 600x800)")
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

    if args.headless and (args.fullscreen or args.size != (600, 800)):
        raise UserError("--fullscreen and --size are for --window, not --headless")
    if args.window and not any(os.environ.get(name) for name in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")):
        raise UserError("--window needs a display, and DISPLAY is not set: run it on the computer's screen (or "
                        "under xvfb-run), or use --headless")
    window = find_window() if args.window else None
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

    def make_server(presenter: Any = None) -> LiveServer:
        return LiveServer(model, host=args.host, port=args.port, token=token, library=library,
                          synthesizer=synthesizer, lsl=args.lsl, model_folders=folders,
                          model_name=Path(args.model).name if args.model else "head.xml",
                          model_reader=load_model_argument, presenter=presenter)

    def ready(line: str) -> None:
        print(line, flush=True)

    if window is not None:
        window(make_server, args.fullscreen, args.size, ready)
    else:
        asyncio.run(make_server().run(ready=ready))
    return 0


def find_window() -> Any:
    """The ``serve`` function of the installed window package, or a :class:`UserError` saying what is missing."""
    from importlib.metadata import entry_points

    found = [entry for entry in entry_points(group=WINDOW_GROUP) if entry.name == "serve"]
    if not found:
        raise UserError("--window needs the workbench package (PySide6) installed; use --headless without it")
    try:
        return found[0].load()
    except ImportError as exc:
        raise UserError(f"--window cannot open a window here: {exc}; use --headless") from None


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


def listen_host(text: str) -> str:
    """``--host``: a host name, an IPv4 address, or an IPv6 address bare or in brackets (``[::1]``, as in a URL); the
    brackets are dropped. What cannot be one (unbalanced or misplaced brackets, a port, nothing) is refused here;
    a name that does not resolve, or an address that is not this computer's, when the server binds (exit 2 both)."""
    host = text.strip()
    bracketed = host.startswith("[") and host.endswith("]")
    if bracketed:
        host = host[1:-1]
    try:
        is_ipv6 = ipaddress.ip_address(host).version == 6
    except ValueError:
        is_ipv6 = False
    if bracketed and not is_ipv6:
        raise argparse.ArgumentTypeError(f"'{text}' is not an address: brackets hold an IPv6 address, as in [::1]")
    if not host or "[" in host or "]" in host or (":" in host and not is_ipv6) or any(c.isspace() for c in host):
        raise argparse.ArgumentTypeError(f"'{text}' is not a host name or an address (an IPv6 address may be put in "
                                         "brackets, [::1]; the port goes in --port)")
    return host


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
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def port_number(text: str) -> int:
    """A TCP port, 0 … 65535."""
    if not text.strip().isdigit() or not 0 <= int(text) <= 65535:
        raise argparse.ArgumentTypeError(f"'{text}' is not a port number (0 … 65535)")
    return int(text)
