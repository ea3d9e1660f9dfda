"""``serve --lsl``: every event also pushed to a Lab Streaming Layer marker outlet (``pylsl``).

The outlet: name :data:`STREAM_NAME`, type ``Markers``, one ``string`` channel, irregular rate,
source id ``artificial-person@HOST:PORT`` (the WebSocket address, so a recorder that loses the
stream finds it again when the server restarts on that address). Each marker is the event's JSON,
exactly as the clients get it, stamped with the LSL clock at the event's frame time ``t``:

    lsl_timestamp = epoch_monotonic_s + t / 1000 + (lsl_clock − time.monotonic())

where the last term is measured once when the outlet opens (on Linux both clocks are
``CLOCK_MONOTONIC`` and it is 0 to within a microsecond). The marker is pushed when the frame is
processed, after its moment; its timestamp is the frame's moment, not the push's.

liblsl finds streams by multicast and broadcast on the local network unless configured otherwise.
``serve --lsl`` therefore points liblsl at :data:`LOOPBACK_CONFIG` (written to a private temporary
file, named by ``LSLAPICFG``) unless the user gives their own (``--lsl-config FILE``, or
``LSLAPICFG`` already set): discovery on this computer only (``ResolveScope = machine``, the
responder on 127.0.0.1, 127.0.0.1 the only known peer), IPv6 off. liblsl binds the outlet's data
(TCP) and time (UDP) servers to the wildcard address whatever the configuration says; a firewall
keeps them from other computers (``docs/serve.md``).

>>> print(LOOPBACK_CONFIG.splitlines()[7])
ResolveScope = machine
>>> lsl_source_id("127.0.0.1", 8765)
'artificial-person@127.0.0.1:8765'
"""

from __future__ import annotations

import atexit
import importlib
import json
import os
import shutil
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

from engine.errors import UserError

STREAM_NAME = "ArtificialPerson"
STREAM_TYPE = "Markers"
CONFIG_VARIABLE = "LSLAPICFG"

LOOPBACK_CONFIG = """\
[log]
level = -2

[ports]
IPv6 = disable

[multicast]
ResolveScope = machine
ListenAddress = 127.0.0.1
MachineAddresses = {127.0.0.1}
AddressesOverride = {127.0.0.1}
TTLOverride = 0
Interfaces = {127.0.0.1}

[lab]
KnownPeers = {127.0.0.1}
SessionID = default
"""
"""liblsl's ``lsl_api.cfg`` that keeps discovery on this computer (see liblsl's api_config.cpp)."""


def lsl_source_id(host: str, port: int) -> str:
    """The outlet's source id: the WebSocket address it belongs to."""
    return f"artificial-person@{host}:{port}"


def use_lsl_config(config: str | Path | None) -> Path:
    """Point liblsl at ``config``, or at the loopback-only one when neither it nor ``LSLAPICFG`` is given.

    Call before the first use of liblsl in the process (it reads its configuration once).
    """
    if config is not None:
        path = Path(config)
        if not path.is_file():
            raise UserError("no such LSL configuration file (lsl_api.cfg)", file=path)
        os.environ[CONFIG_VARIABLE] = str(path.resolve())
        return path
    given = os.environ.get(CONFIG_VARIABLE)
    if given:
        return Path(given)
    folder = Path(tempfile.mkdtemp(prefix="artificial-person-lsl-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    path = folder / "lsl_api.cfg"
    path.write_text(LOOPBACK_CONFIG, encoding="ascii")
    os.environ[CONFIG_VARIABLE] = str(path)
    return path


def import_pylsl() -> Any:
    """``pylsl``, or a :class:`UserError` saying how to install it."""
    try:
        pylsl = importlib.import_module("pylsl")       # by name: pylsl ships no type information
    except ImportError:
        raise UserError("--lsl needs pylsl: pip install 'artificial-person[lsl]' (or pip install pylsl)") from None
    except RuntimeError as exc:                        # pylsl raises this when it cannot load liblsl
        raise UserError(f"--lsl: pylsl cannot load liblsl: {exc}") from None
    return pylsl


class MarkerOutlet:
    """The marker stream of one server; :meth:`push` sends an event stamped at its frame time."""

    def __init__(self, source_id: str, epoch_monotonic_s: float):
        pylsl = import_pylsl()
        info = pylsl.StreamInfo(STREAM_NAME, STREAM_TYPE, 1, pylsl.IRREGULAR_RATE, pylsl.cf_string, source_id)
        description = info.desc()
        description.append_child_value("clock", "lsl_timestamp = epoch_monotonic_s + t/1000 + lsl_minus_monotonic_s")
        self.epoch_monotonic_s = float(epoch_monotonic_s)
        self.lsl_minus_monotonic_s = clock_offset(pylsl.local_clock)
        description.append_child_value("epoch_monotonic_s", repr(self.epoch_monotonic_s))
        description.append_child_value("lsl_minus_monotonic_s", repr(self.lsl_minus_monotonic_s))
        self.outlet = pylsl.StreamOutlet(info)
        self.pushed = 0

    def timestamp(self, t_ms: float) -> float:
        """The LSL clock's reading at the frame time ``t_ms``."""
        return self.epoch_monotonic_s + t_ms / 1000.0 + self.lsl_minus_monotonic_s

    def push(self, event: dict[str, Any], text: str | None = None) -> None:
        """``event`` as a marker at its frame's moment; ``text``: its JSON as its client got it (default: made here)."""
        if text is None:
            text = json.dumps(event, ensure_ascii=False, allow_nan=False)
        self.outlet.push_sample([text], self.timestamp(float(event["t"])))
        self.pushed += 1


def clock_offset(lsl_clock: Any, probes: int = 9) -> float:
    """``lsl_clock() − time.monotonic()``: the median of ``probes`` readings, each between two monotonic ones."""
    readings = []
    for _ in range(probes):
        before = time.monotonic()
        lsl_now = float(lsl_clock())
        after = time.monotonic()
        readings.append(lsl_now - (before + after) / 2.0)
    return statistics.median(readings)
