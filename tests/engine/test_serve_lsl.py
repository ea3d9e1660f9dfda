"""``serve --lsl``: the events as Lab Streaming Layer markers, received by an inlet here; LSL kept on loopback.

This process's liblsl reads a loopback-only ``lsl_api.cfg`` (``LSLAPICFG``, set before pylsl loads);
the server gets no ``LSLAPICFG`` at all, so it runs on its own default, the same loopback-only
configuration. While it runs, every socket of the server process is read from ``/proc``: each must
be bound and connected to 127.0.0.1 only, except liblsl's data (TCP) and time (UDP) servers, which
liblsl always binds to the wildcard address — those two are named by the outlet's own stream info
and checked to be exactly them.
"""

from __future__ import annotations

import atexit
import ipaddress
import json
import os
import re
import shutil
import tempfile
from pathlib import Path

import pytest

from engine.live.client import LiveClient
from engine.live.lsl import LOOPBACK_CONFIG, STREAM_NAME, lsl_source_id
from tests.engine.serve_schema_checks import check_server_message, schema_checked  # noqa: F401  (a fixture)
from tests.engine.test_serve import (
    check_gaze_cue_log,
    run_cli,
    run_gaze_cue_example,
    start_server,
    stop_server,
)

pytestmark = pytest.mark.usefixtures("schema_checked")

_config_folder = Path(tempfile.mkdtemp(prefix="test-serve-lsl-"))
atexit.register(shutil.rmtree, _config_folder, ignore_errors=True)
(_config_folder / "lsl_api.cfg").write_text(LOOPBACK_CONFIG, encoding="ascii")
os.environ["LSLAPICFG"] = str(_config_folder / "lsl_api.cfg")       # before liblsl loads: it reads it once
pylsl = pytest.importorskip("pylsl")

needs_festival = pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
SOCKET_TABLES = ("tcp", "udp", "tcp6", "udp6", "raw", "raw6")
TCP_LISTEN = "0A"


def process_sockets(pid: int) -> list[tuple[str, str, int, str, int, str]]:
    """(table, local address, local port, remote address, remote port, state) of every inet socket of ``pid``."""
    inodes = set()
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
        except OSError:
            continue
        if target.startswith("socket:["):
            inodes.add(target[len("socket:["):-1])
    found = []
    for table in SOCKET_TABLES:
        for line in Path(f"/proc/{pid}/net/{table}").read_text().splitlines()[1:]:
            fields = line.split()
            if fields[9] in inodes:
                local, remote = (address_and_port(text) for text in (fields[1], fields[2]))
                found.append((table, *local, *remote, fields[3]))
    return found


def address_and_port(text: str) -> tuple[str, int]:
    """``0100007F:1F90`` (the kernel's hex, little-endian words) → ('127.0.0.1', 8080)."""
    address, port = text.split(":")
    raw = bytes.fromhex(address)
    words = b"".join(raw[i:i + 4][::-1] for i in range(0, len(raw), 4))
    return str(ipaddress.ip_address(words)), int(port, 16)


def beyond_loopback(sockets: list[tuple[str, str, int, str, int, str]],
                    wildcard_allowed: set[tuple[str, int]]) -> list[tuple[str, str, int, str, int, str]]:
    """The sockets bound or connected to anything but loopback (a wildcard bind allowed only as listed)."""
    bad = []
    for table, local, local_port, remote, remote_port, state in sockets:
        local_ip, remote_ip = ipaddress.ip_address(local), ipaddress.ip_address(remote)
        local_ok = local_ip.is_loopback or (local_ip.is_unspecified and (table, local_port) in wildcard_allowed)
        remote_ok = remote_ip.is_loopback or (remote_ip.is_unspecified and remote_port == 0)
        if not (local_ok and remote_ok):
            bad.append((table, local, local_port, remote, remote_port, state))
    return bad


def test_the_address_reader_reads_the_kernels_hex():
    assert address_and_port("0100007F:1F90") == ("127.0.0.1", 8080)
    assert address_and_port("00000000000000000000000001000000:0050") == ("::1", 80)
    sample = [("tcp", "10.0.0.5", 5000, "127.0.0.1", 80, "01"), ("udp", "0.0.0.0", 16572, "0.0.0.0", 0, "07"),
              ("tcp", "127.0.0.1", 1, "192.0.2.1", 9, "01"), ("tcp", "127.0.0.1", 2, "0.0.0.0", 0, TCP_LISTEN)]
    assert beyond_loopback(sample, {("udp", 16572)}) == [sample[0], sample[2]]
    assert beyond_loopback(sample, set()) == sample[:3]


@needs_festival
def test_an_inlet_receives_every_event_in_order_stamped_at_its_frame_and_lsl_stays_on_loopback(tmp_path):
    server_env = {k: v for k, v in os.environ.items() if k not in ("LSLAPICFG", "AP_SERVE_TOKEN")}
    served = start_server(tmp_path, "--lsl", env=server_env)
    try:
        port = int(served.url.rsplit(":", 1)[1])
        source_id = lsl_source_id("127.0.0.1", port)
        assert served.first_line.strip().endswith(f", LSL markers {STREAM_NAME} {source_id}")
        [info] = pylsl.resolve_byprop("source_id", source_id, minimum=1, timeout=30)
        assert (info.name(), info.type(), info.channel_format()) == (STREAM_NAME, "Markers", pylsl.cf_string)
        inlet = pylsl.StreamInlet(info)
        inlet.open_stream(timeout=30)
        xml = inlet.info(timeout=30).as_xml()
        data_port, service_port = (int(re.search(f"<{tag}>(\\d+)</{tag}>", xml).group(1))
                                   for tag in ("v4data_port", "v4service_port"))
        with LiveClient(served.url) as head:
            clock = head.state()["clock"]
        rows = run_gaze_cue_example(served.url, tmp_path / "log.csv")
        sockets = process_sockets(served.process.pid)
        markers = []
        while len(markers) < len(rows):
            sample, timestamp = inlet.pull_sample(timeout=30)
            assert sample is not None, f"only {len(markers)} of {len(rows)} markers arrived"
            markers.append((json.loads(sample[0]), timestamp))
    finally:
        stop_server(served)
    assert "Traceback" not in served.stderr()
    check_gaze_cue_log(rows)
    for marker, _ in markers:                               # each marker an event of the protocol's schema
        check_server_message(marker)
    assert [(m["event"], m["t"], m.get("word", "")) for m, _ in markers] == \
        [(r["event"], float(r["t"]), r["word"]) for r in rows]
    for marker, timestamp in markers:                       # the LSL clock at the frame: monotonic + ~0 on Linux
        assert timestamp == pytest.approx(clock["epoch_monotonic_s"] + marker["t"] / 1000, abs=1e-3)
    assert any(s[0] == "tcp" and s[2] == data_port and s[5] == TCP_LISTEN for s in sockets)
    assert beyond_loopback(sockets, {("tcp", data_port), ("udp", service_port)}) == []


def test_without_lsl_every_socket_of_the_server_is_on_loopback(tmp_path):
    served = start_server(tmp_path)
    try:
        with LiveClient(served.url) as head:
            head.state()
            sockets = process_sockets(served.process.pid)
    finally:
        stop_server(served)
    assert sockets and beyond_loopback(sockets, set()) == []


@pytest.mark.parametrize("args, expected", [
    (["--lsl-config", "lsl_api.cfg"], "--lsl-config needs --lsl"),
    (["--lsl", "--lsl-config", "no/such/lsl_api.cfg"], "no/such/lsl_api.cfg: no such LSL configuration file"),
])
def test_a_bad_lsl_option_is_refused_in_one_line(args, expected):
    result = run_cli("serve", "--headless", "--port", "0", *args)
    assert result.returncode == 2 and result.stdout == "" and result.stderr.count("\n") == 1
    assert expected in result.stderr
