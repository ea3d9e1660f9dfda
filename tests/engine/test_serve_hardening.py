"""``serve`` against careless and hostile clients (issue 30): the real server in a subprocess, real loopback sockets.

* a served model whose arrays file lies outside the served folders is refused before it is read;
* a client that does not read is not read either, and loses nothing when it reads at last; one whose
  events pile up beyond the bound is disconnected with close code 1008; clients that never read
  neither fill the server's memory nor leave it behind;
* a lone surrogate anywhere in a request is refused with a located error, the connection kept; the
  replies' one encoder cannot fail; two ``Authorization`` headers are a 400, with no traceback;
* ``--host`` takes a bracketed IPv6 literal, and a host it cannot listen on is one error line, exit 2.
"""

from __future__ import annotations

import base64
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import ClientConnection, connect

from engine.live.client import LiveClient, LiveError
from engine.live.connection import (
    INTERNAL_ERROR,
    MAX_OUTBOX_BYTES,
    MESSAGE_OVERHEAD_BYTES,
    OUTBOX_PAUSE_BYTES,
    SLOW_READER_CLOSE_CODE,
    SLOW_READER_REASON,
    encode_message,
)
from engine.live.protocol import MAX_ID_CHARS, MAX_SCHEDULED, RATE_BURST
from engine.paths import default_model_path
from tests.engine.serve_schema_checks import check_server_message, schema_checked  # noqa: F401  (a fixture)
from tests.engine.test_serve import LOCATED, PROJECT_ROOT, Served, run_cli, start_server, stop_server

pytestmark = pytest.mark.usefixtures("schema_checked")

#: How much a client's socket takes in before it stops the server's sends (so the server's own outbox fills).
SMALL_RECEIVE_BUFFER = 8192
#: The most the kernel lets a socket hold unsent (the server's side takes that in before its outbox fills).
KERNEL_SEND_BUFFER = int(Path("/proc/sys/net/ipv4/tcp_wmem").read_text().split()[2])
#: Capabilities requests (replies of about 4 kB each) within one burst of the rate limit.
FILLING_REQUESTS = 1900
CAPABILITIES_REPLY_BYTES = 4000


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    served = start_server(tmp_path_factory.mktemp("serve-hardening"))
    yield served
    stop_server(served)
    assert "Traceback" not in served.stderr() and "internal error" not in served.stderr()


def address(url: str) -> tuple[str, int]:
    host, port = url.removeprefix("ws://").rsplit(":", 1)
    return host.strip("[]"), int(port)


def rss_bytes(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) * 1024
    raise AssertionError("no VmRSS")


def slow_connection(url: str) -> ClientConnection:
    """A WebSocket client whose socket takes in little until it is read, and which itself holds two messages;
    uncompressed, so what the kernel's buffers take in is what the server's outbox held."""
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, SMALL_RECEIVE_BUFFER)
    sock.connect(address(url))
    return connect(url, sock=sock, max_queue=2, open_timeout=30, compression=None)


def read_until_closed(connection: ClientConnection) -> tuple[int, ConnectionClosed]:
    """Read until the server closes the connection: how many messages came first, and the close."""
    received = 0
    while True:
        try:
            connection.recv(timeout=10)            # a TimeoutError fails the test: the server kept it open
        except ConnectionClosed as closed:
            return received, closed
        received += 1


def receive(connection: ClientConnection, checked: bool = True) -> dict:
    """The next message; checked against the schema unless told (a test that reads thousands checks a sample)."""
    message = json.loads(connection.recv(timeout=60))
    if checked:
        check_server_message(message)
    return message


def handshake(url: str, *headers: bytes, after: bytes = b"") -> bytes:
    """The server's answer to a WebSocket handshake with these extra header lines (and ``after`` sent right after
    the request): its status line, empty when it closed the connection without one."""
    host, port = address(url)
    key = base64.b64encode(os.urandom(16))
    request = (b"GET / HTTP/1.1\r\nHost: " + f"{host}:{port}".encode() + b"\r\nUpgrade: websocket\r\n"
               b"Connection: Upgrade\r\nSec-WebSocket-Key: " + key + b"\r\nSec-WebSocket-Version: 13\r\n"
               + b"".join(header + b"\r\n" for header in headers) + b"\r\n" + after)
    return status_line((host, port), request)


def status_line(where: tuple[str, int], request: bytes) -> bytes:
    """The first line the server answers the raw ``request`` with (empty when it closes without one)."""
    with socket.create_connection(where, timeout=30) as sock:
        sock.sendall(request)
        answer = b""
        while b"\r\n" not in answer:
            chunk = sock.recv(4096)
            if not chunk:
                break
            answer += chunk
    return answer.split(b"\r\n", 1)[0]


# -- load: the arrays file a description names ------------------------------------------------------------------

@pytest.fixture(scope="module")
def served_models(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[Served, Path]]:
    root = tmp_path_factory.mktemp("arrays")
    models, outside = root / "models", root / "outside"
    models.mkdir()
    outside.mkdir()
    shipped = default_model_path()
    text = shipped.read_text(encoding="utf-8")
    shutil.copy(shipped.with_name("head.h5"), outside / "head.h5")       # a readable model, were it read
    shutil.copy(shipped.with_name("head.h5"), models / "head.h5")

    def description(name: str, arrays: str) -> None:
        changed = text.replace('arrays="head.h5"', f'arrays="{arrays}"', 1)
        assert changed != text or arrays == "head.h5"
        (models / name).write_text(changed, encoding="utf-8")

    description("beside.xml", "head.h5")
    description("up.xml", "../outside/head.h5")
    description("absolute.xml", str(outside / "head.h5"))
    (models / "linked.h5").symlink_to(outside / "head.h5")
    description("linked.xml", "linked.h5")
    description("shipped.xml", str(shipped.with_name("head.h5")))          # in another served folder: -m's
    served = start_server(root, "--models", str(models))
    yield served, outside
    stop_server(served)
    assert "Traceback" not in served.stderr()


MODEL_LINE = 1 + default_model_path().read_text(encoding="utf-8").split("<model ")[0].count("\n")


@pytest.mark.parametrize("name, arrays", [("up.xml", "../outside/head.h5"), ("absolute.xml", None),
                                          ("linked.xml", "linked.h5")])
def test_a_served_model_whose_arrays_file_lies_outside_the_served_folders_is_refused(served_models, name, arrays):
    served, outside = served_models
    arrays = arrays or str(outside / "head.h5")
    with LiveClient(served.url) as head:
        before = head.state()["model"]
        with pytest.raises(LiveError) as refused:
            head.load(name)
        message = refused.value.args[0]
        assert message == (f"{name}:{MODEL_LINE}: its arrays file {arrays!r} lies outside the folders this server "
                           "was started with")
        assert LOCATED.match(message) and head.state()["model"] == before


def test_a_served_model_whose_arrays_file_lies_in_a_served_folder_loads(served_models):
    served, _ = served_models
    with LiveClient(served.url) as head:
        for name in ("beside.xml", "shipped.xml", "head.xml"):
            assert head.load(name)["model"] == name


# -- clients that do not read -----------------------------------------------------------------------------------

def send_in_bursts(connection: ClientConnection, messages: list[str]) -> threading.Thread:
    """Send ``messages`` from a thread of their own, a burst of the rate limit a second (a send may wait while the
    server reads none of the connection's requests)."""
    def send() -> None:
        for start in range(0, len(messages), FILLING_REQUESTS):
            if start:
                time.sleep(1.0)
            for message in messages[start:start + FILLING_REQUESTS]:
                try:
                    connection.send(message)
                except ConnectionClosed:                   # disconnected: what is left is not sent
                    return

    thread = threading.Thread(target=send, daemon=True)
    thread.start()
    return thread


def filling_requests(count: int) -> list[str]:
    """Capabilities requests whose replies fill the kernel's buffers and the outbox past the pause level."""
    assert count * CAPABILITIES_REPLY_BYTES > KERNEL_SEND_BUFFER + OUTBOX_PAUSE_BYTES + 2 * 2**20
    return [json.dumps({"type": "capabilities", "id": i}) for i in range(count)]


def test_a_client_that_does_not_read_is_not_read_either_and_loses_nothing(server):
    count = 2 * FILLING_REQUESTS
    with slow_connection(server.url) as late, LiveClient(server.url) as watcher:
        sender = send_in_bursts(late, [*filling_requests(count),
                                       json.dumps({"type": "set", "id": "last", "values": {"head_turn": 0.3}})])
        # Once about OUTBOX_PAUSE_BYTES wait for it, the server reads no more of its requests: not the set.
        watched_until = time.monotonic() + 5.0
        while time.monotonic() < watched_until:
            assert watcher.state()["values"]["head_turn"] == 0.0
        replies = [receive(late, checked=i % 100 == 0) for i in range(count)]   # read now: nothing was dropped
        assert [r["id"] for r in replies] == list(range(count)) and all(r["ok"] for r in replies)
        sender.join(60)
        assert not sender.is_alive()
        last = receive(late)
        assert last["id"] == "last" and last["ok"]
        waited_until = time.monotonic() + 60
        while watcher.state()["values"]["head_turn"] != 0.3:                # the set's frame comes
            assert time.monotonic() < waited_until
        watcher.set({"head_turn": 0.0})


def test_a_client_whose_events_pile_up_unread_is_disconnected_with_close_code_1008(tmp_path):
    served = start_server(tmp_path)
    long_id = "x" * (MAX_ID_CHARS - 8)
    blinks = "<commands>" + "<Blink/>\n" * 100 + "</commands>"        # 100 commands: start, apex, end each
    commands, sets = 10, MAX_SCHEDULED - 10
    # What comes in the flood's frame (applied events; each command's start, apex and end, and a finished) on top
    # of the outbox filled to the pause level is well over the bound.
    t = 20_016.666666666668
    applied = len(encode_message({"event": "applied", "id": f"{long_id}s1234", "t": t, "presented_t": t}))
    command = len(encode_message({"event": "command_start", "id": f"{long_id}c1", "t": t, "onset_t": t,
                                  "command": "Blink", "source": "<command>:55", "index": 55, "presented_t": t}))
    flood = sets * (applied + MESSAGE_OVERHEAD_BYTES) + commands * 301 * (command + MESSAGE_OVERHEAD_BYTES)
    assert flood + OUTBOX_PAUSE_BYTES > 1.15 * MAX_OUTBOX_BYTES
    try:
        with slow_connection(served.url) as flooded, LiveClient(served.url) as watcher:
            due = watcher.state()["t"] + 30_000.0              # well after the requests below have been read
            for i in range(commands):
                flooded.send(json.dumps({"type": "command", "id": f"{long_id}c{i}", "xml": blinks, "at": due}))
                assert receive(flooded)["ok"]
            # From here on it reads nothing: the sets' replies, then enough replies to fill its outbox to the pause
            # level, then at `due` the flood.
            time.sleep(1.0)                                    # a whole burst of the rate limit
            sender = send_in_bursts(flooded, [json.dumps({"type": "set", "id": f"{long_id}s{i}", "at": due,
                                                          "values": {"jaw_open": 0.1}}) for i in range(sets)]
                                    + filling_requests(2 * FILLING_REQUESTS))
            waited_until = time.monotonic() + 120               # the due frame comes: disconnected then
            while any(p["id"].startswith(long_id) for p in watcher.state()["playing"]):
                assert time.monotonic() < waited_until, "the client whose events pile up is still connected"
                time.sleep(0.1)
            received, closed = read_until_closed(flooded)
            assert closed.rcvd is not None and closed.rcvd.code == SLOW_READER_CLOSE_CODE
            assert closed.rcvd.reason == SLOW_READER_REASON
            assert received < sets + 2 * FILLING_REQUESTS       # what waited was dropped
            sender.join(60)
            watcher.set({"jaw_open": 0.0})
    finally:
        stop_server(served)
    assert "Traceback" not in served.stderr()


def send_until_refused(url: str, requests: int) -> socket.socket:
    """A raw WebSocket client that sends ``requests`` capabilities requests (paced within the rate limit) and never
    reads; it stops early when the server has stopped reading it (its socket takes no more for 5 s)."""
    host, port = address(url)
    sock = socket.create_connection((host, port), timeout=30)
    key = base64.b64encode(os.urandom(16))
    sock.sendall(b"GET / HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: "
                 + key + b"\r\nSec-WebSocket-Version: 13\r\n\r\n")
    answer = b""
    while b"\r\n\r\n" not in answer:
        answer += sock.recv(1)
    assert answer.startswith(b"HTTP/1.1 101"), answer
    sock.settimeout(5.0)
    started = time.monotonic()
    for i in range(requests):
        payload = json.dumps({"type": "capabilities", "id": i}).encode()
        mask = os.urandom(4)
        frame = bytes([0x81, 0x80 | len(payload)]) + mask + bytes(b ^ mask[k % 4] for k, b in enumerate(payload))
        try:
            sock.sendall(frame)
        except OSError:                                                # not read any more
            break
        ahead = (i + 1) / (0.9 * RATE_BURST) - (time.monotonic() - started)
        if ahead > 0:
            time.sleep(ahead)                                          # pacing, not a measurement
    return sock


def test_clients_that_never_read_do_not_fill_the_servers_memory_and_it_is_given_back(tmp_path):
    served = start_server(tmp_path)
    mib = 2**20
    try:
        with LiveClient(served.url) as warm:                           # the replies' code paths, once
            for _ in range(50):
                warm.capabilities()
                warm.state()
        before = rss_bytes(served.process.pid)
        sockets: list[socket.socket] = []
        senders = [threading.Thread(target=lambda: sockets.append(send_until_refused(served.url, 5400)))
                   for _ in range(4)]                                  # ~22 MB of replies each, unread
        for sender in senders:
            sender.start()
        for sender in senders:
            sender.join()
        during = rss_bytes(served.process.pid)
        for sock in sockets:
            sock.close()
        for _ in range(600):                                           # the server sees the closes a moment later
            with LiveClient(served.url) as head:
                assert head.state()["ok"]
            after = rss_bytes(served.process.pid)
            if after - before < 16 * mib:
                break
            time.sleep(0.1)
    finally:
        stop_server(served)
    bound = 4 * (OUTBOX_PAUSE_BYTES + CAPABILITIES_REPLY_BYTES) * 1.25 + 16 * mib    # the outboxes, and some slack
    assert during - before < bound, f"{(during - before) / mib:.0f} MiB more while 4 clients did not read"
    assert after - before < 16 * mib, f"{(after - before) / mib:.0f} MiB kept after they left"
    assert "Traceback" not in served.stderr()


# -- lone surrogates, the replies' encoder, the handshake ------------------------------------------------------------

SURROGATE = "\ud800"


@pytest.mark.parametrize("request_fields, reply_id, field", [
    ({"type": "state", "id": SURROGATE}, None, "id"),
    ({"type": "state", "id": "a" + SURROGATE + "b"}, None, "id"),
    ({"type": "command", "id": 1, "xml": f"<commands><HeadNod/>{SURROGATE}</commands>"}, 1, "xml"),
    ({"type": "command", "id": 2, "xml": f"<commands><HeadNod amplitude='{SURROGATE}'/></commands>"}, 2, "xml"),
    ({"type": "say", "id": 3, "text": f"moi {SURROGATE}"}, 3, "text"),
    ({"type": "set", "id": 4, "values": {"\udc00": 1}}, 4, "values"),
    ({"type": "stop", "id": 5, "target": SURROGATE}, 5, "target"),
    ({"type": "load", "id": 6, "model": f"a{SURROGATE}.xml"}, 6, "model"),
    ({"type": SURROGATE, "id": 7}, 7, "type"),
    ({"type": "set", "id": 8, "values": {"jaw_open": 0.1}, "at": [SURROGATE]}, 8, "at"),
])
def test_a_lone_surrogate_anywhere_in_a_request_is_refused_and_the_connection_kept(server, request_fields,
                                                                                   reply_id, field):
    with LiveClient(server.url) as head:
        text = json.dumps(request_fields)                            # ASCII: the surrogate as the escape \ud800
        assert "\\ud800" in text or "\\udc00" in text
        head.send_raw(text)
        reply = head._receive(deadline=time.monotonic() + 30)
        assert reply["id"] == reply_id and reply["ok"] is False
        assert reply["error"].startswith(f'<message>:1: "{field}" holds a lone UTF-16 surrogate (U+D'), reply["error"]
        assert head.state()["ok"]


def test_a_field_name_with_a_lone_surrogate_is_refused(server):
    with LiveClient(server.url) as head:
        head.send_raw(json.dumps({"type": "state", "id": 9, SURROGATE: 1}))
        reply = head._receive(deadline=time.monotonic() + 30)
        assert reply["id"] == 9 and reply["error"].startswith("<message>:1: a field name holds a lone UTF-16 surrogate")
        assert head.state()["ok"]


def test_the_encoder_of_replies_cannot_fail():
    assert json.loads(encode_message({"id": SURROGATE, "ok": True})) == {"id": "\ufffd", "ok": True}
    assert encode_message({"id": "päivää", "ok": True}).decode("utf-8") == '{"id": "päivää", "ok": true}'
    for unwritable in (float("nan"), object(), {1j: 1}):
        assert json.loads(encode_message({"id": 7, "ok": True, "t": unwritable})) == {
            "id": 7, "ok": False, "error": INTERNAL_ERROR}
    failed = json.loads(encode_message({"event": "word", "id": "w", "t": 50.0, "word": float("nan")}))
    assert failed == {"event": "failed", "id": "w", "t": 50.0, "presented_t": 50.0, "error": INTERNAL_ERROR}
    check_server_message(failed)
    assert json.loads(encode_message({"event": "word", "id": [1], "t": float("inf")}))["t"] == 0.0


@pytest.fixture(scope="module")
def token_server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    served = start_server(tmp_path_factory.mktemp("serve-token"), "--token", "s3cret")
    yield served
    stop_server(served)
    assert "Traceback" not in served.stderr() and "failed" not in served.stderr()


@pytest.mark.parametrize("headers, status", [
    ([b"Authorization: Bearer s3cret"], b"101"),
    ([b"Authorization: Bearer s3cret", b"Authorization: Bearer s3cret"], b"400"),
    ([b"Authorization: Bearer wrong", b"Authorization: Bearer s3cret"], b"400"),
    ([b"Authorization: Bearer s3cret", b"authorization: Bearer other"], b"400"),
    ([b"Authorization: Bearer \xff\xfe"], b"401"),
    ([], b"401"),
    ([b"Authorization: Bearer s3cret", b"Origin: http://a.example", b"Origin: http://b.example"], b"400"),
])
def test_the_handshake_refuses_ambiguous_authorization_without_a_traceback(token_server, headers, status):
    status_line = handshake(token_server.url, *headers)
    assert status_line.split(b" ")[1] == status, status_line
    assert "Traceback" not in token_server.stderr()


@pytest.mark.parametrize("after", [b"\r\n", b"GET / HTTP/1.1\r\n\r\n", b"\x81\x80"])
def test_bytes_sent_after_the_handshake_request_end_it_without_a_traceback(token_server, after):
    for _ in range(20):                                  # websockets' failure here depended on timing
        status_line = handshake(token_server.url, b"Authorization: Bearer s3cret", after=after)
        assert status_line in (b"", b"HTTP/1.1 101 Switching Protocols"), status_line
    with LiveClient(token_server.url, token="s3cret") as head:
        assert head.state()["ok"]
    assert "Traceback" not in token_server.stderr()


# -- --host ------------------------------------------------------------------------------------------------------------

def ipv6_loopback() -> bool:
    try:
        with socket.socket(socket.AF_INET6, socket.SOCK_STREAM) as sock:
            sock.bind(("::1", 0))
        return True
    except OSError:
        return False


@pytest.mark.skipif(not ipv6_loopback(), reason="no IPv6 loopback here")
@pytest.mark.parametrize("host", ["[::1]", "::1"])
def test_serve_listens_on_an_ipv6_literal_bare_or_in_brackets(tmp_path, host):
    stderr_path = tmp_path / "stderr.txt"
    with stderr_path.open("wb") as stderr:
        process = subprocess.Popen([sys.executable, "-m", "engine", "serve", "--headless", "--host", host,
                                    "--port", "0"], cwd=PROJECT_ROOT, stdout=subprocess.PIPE, stderr=stderr)
    try:
        assert process.stdout is not None
        line = process.stdout.readline().decode()
        match = re.match(r"serving (ws://\[::1\]:\d+) headless", line)
        assert match, (line, stderr_path.read_text())
        with LiveClient(match.group(1)) as head:
            assert head.state()["ok"]
    finally:
        process.terminate()
        process.wait(timeout=60)
        assert process.stdout is not None
        process.stdout.close()
    assert "Traceback" not in stderr_path.read_text()


@pytest.mark.parametrize("host, expected", [
    ("[::1", "argument --host: '[::1' is not a host name or an address"),
    ("::1]", "argument --host: '::1]' is not a host name or an address"),
    ("[127.0.0.1]", "argument --host: '[127.0.0.1]' is not an address: brackets hold an IPv6 address"),
    ("[]", "argument --host: '[]' is not an address"),
    ("127.0.0.1:8765", "the port goes in --port"),
    ("", "argument --host: '' is not a host name or an address"),
    ("a b", "is not a host name or an address"),
    ("no-such-host.invalid", "cannot listen on no-such-host.invalid port 0: "),
    ("192.0.2.7", "cannot listen on 192.0.2.7 port 0: "),
])
def test_a_host_it_cannot_listen_on_is_one_error_line_and_exit_2(host, expected):
    result = run_cli("serve", "--headless", "--host", host, "--port", "0", "--token", "s3cret")
    assert result.returncode == 2, result
    assert result.stderr.startswith("error: ") and expected in result.stderr, result.stderr
    assert result.stderr.count("\n") == 1 and result.stdout == ""


def test_a_port_already_taken_is_one_error_line_and_exit_2(server):
    port = server.url.rsplit(":", 1)[1]
    result = run_cli("serve", "--headless", "--port", port)
    assert result.returncode == 2 and result.stderr.count("\n") == 1, result
    assert result.stderr.startswith(f"error: cannot listen on 127.0.0.1 port {port}: "), result.stderr
