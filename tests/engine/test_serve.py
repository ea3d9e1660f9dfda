"""The live service (issue 21), end to end: the real server in a subprocess, real loopback sockets, real Festival.

Every socket here is on 127.0.0.1: the one test about other addresses checks the refusal, which comes
before anything is bound.
"""

from __future__ import annotations

import asyncio
import json
import os
import re
import select
import shutil
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st
from websockets.exceptions import InvalidStatus

from engine.live.client import AsyncLiveClient, LiveClient, LiveError
from engine.live.protocol import (
    EVENT_TYPES,
    MAX_CLIENTS,
    MAX_FRAME_BYTES,
    MAX_MESSAGE_BYTES,
    REQUEST_TYPES,
    SCHEMA_VERSION,
)
from tests.engine.fuzz_support import FUZZ
from tests.engine.serve_schema_checks import schema_checked  # noqa: F401  (a fixture)

PROJECT_ROOT = Path(__file__).resolve().parents[2]
FRAME_MS = 1000.0 / 60.0
SENTENCE = "Hyvää päivää mitä kuuluu"
needs_festival = pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")
#: A located one-line error: ``<message>:1: …``, ``<text>:1: column 3: …``, ``path/x.lib:12: …``.
LOCATED = re.compile(r"^\S+:\d+: \S")

pytestmark = pytest.mark.usefixtures("schema_checked")


@dataclass
class Served:
    url: str
    process: subprocess.Popen
    stderr_path: Path
    first_line: str = ""

    def stderr(self) -> str:
        return self.stderr_path.read_text(encoding="utf-8", errors="replace")


def start_server(tmp: Path, *options: str, env: dict[str, str] | None = None) -> Served:
    """``artificial-person serve --headless --port 0`` in a subprocess; its first line names the bound address."""
    stderr_path = tmp / "serve-stderr.txt"
    with stderr_path.open("wb") as stderr:
        process = subprocess.Popen([sys.executable, "-m", "engine", "serve", "--headless", "--port", "0", *options],
                                   cwd=PROJECT_ROOT, stdout=subprocess.PIPE, stderr=stderr, env=env)
    assert process.stdout is not None
    ready, _, _ = select.select([process.stdout], [], [], 120)
    line = process.stdout.readline().decode() if ready else ""
    match = re.search(r"ws://127\.0\.0\.1:\d+", line)
    if match is None:
        process.kill()
        process.wait()
        pytest.fail(f"the server did not start: {line!r} {stderr_path.read_text()}")
    return Served(match.group(0), process, stderr_path, line)


def stop_server(served: Served) -> None:
    served.process.terminate()
    try:
        served.process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        served.process.kill()
        served.process.wait()
    assert served.process.stdout is not None
    served.process.stdout.close()


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    served = start_server(tmp_path_factory.mktemp("serve"))
    yield served
    stop_server(served)
    assert "Traceback" not in served.stderr()


@pytest.fixture
def client(server: Served) -> Iterator[LiveClient]:
    with LiveClient(server.url) as head:
        yield head


def events_of(head: LiveClient, request_id: str) -> list[dict]:
    return [e for e in head.events_until(request_id, "finished") if e.get("id") == request_id]


# -- say -------------------------------------------------------------------------------------------------

@needs_festival
def test_say_gives_speech_start_each_word_in_order_and_finished_on_the_frame_clock(client):
    from engine.speech.festival import FestivalSynthesizer

    say_id = client.say(SENTENCE)
    events = events_of(client, say_id)
    kinds = [e["event"] for e in events]
    assert kinds[0] == "speech_start" and kinds[-1] == "finished"
    assert set(kinds) <= {"speech_start", "word", "phone", "finished"}
    start = events[0]
    assert start["sample"] == 0 and start["sample_rate"] > 0
    assert start["t"] == pytest.approx(round(start["t"] / FRAME_MS) * FRAME_MS)     # a frame of the clock
    words = [e for e in events if e["event"] == "word"]
    assert [w["word"] for w in words] == SENTENCE.split()
    assert [w["index"] for w in words] == list(range(len(words)))
    # The same text synthesized here: the server's words start where Festival puts them.
    utterance = FestivalSynthesizer().synthesize(SENTENCE)
    assert [w["onset_ms"] for w in words] == pytest.approx([w.start_ms for w in utterance.words], abs=1e-6)
    rate = start["sample_rate"]
    for word in words:
        assert word["onset_t"] == pytest.approx(start["t"] + word["onset_ms"])
        assert 0 <= word["t"] - word["onset_t"] < FRAME_MS             # the first frame at or after the onset
        assert word["sample"] == round(word["onset_ms"] * rate / 1000)
    times = [e["t"] for e in events]
    assert times == sorted(times)
    phones = [e for e in events if e["event"] == "phone"]
    assert [p["phone"] for p in phones] == [p.label for p in utterance.phones]
    assert events[-1]["t"] - start["t"] >= start["duration_ms"] - FRAME_MS
    assert events[-1]["sample"] == len(utterance.samples)


@needs_festival
def test_say_moves_the_jaw_while_it_speaks_and_state_shows_it(client):
    say_id = client.say(SENTENCE)
    opened = []
    for event in client.events_until(say_id, "finished"):
        if event.get("event") == "word":
            state = client.state()
            opened.append(abs(state["values"]["jaw_open"]))
            assert any(p["id"] == say_id for p in state["playing"])
    assert max(opened) > 0
    assert client.state()["playing"] == []


def test_a_bad_inline_command_is_refused_naming_the_text(client):
    with pytest.raises(LiveError, match=r"^<text>:1: "):
        client.say('Hyvää <HeadNod amplitude="lots"/> päivää')
    assert client.state()["ok"]


# -- set, command, state -----------------------------------------------------------------------------------

def test_set_shows_in_state_from_the_frame_the_reply_names(client):
    before = client.state()
    assert before["values"]["head_turn"] != 0.5
    reply = client.set({"head_turn": 0.5})
    assert reply["t"] > before["t"]
    while True:
        state = client.state()
        if state["t"] >= reply["t"]:
            assert state["values"]["head_turn"] == 0.5
            break
        assert state["values"]["head_turn"] == before["values"]["head_turn"]
    applied = client.next_event()
    assert applied == {"event": "applied", "id": reply["id"], "t": reply["t"], "presented_t": reply["t"]}
    client.set({"head_turn": 0})


def test_set_at_a_later_time_waits_for_that_frame(client):
    now = client.state()["t"]
    reply = client.set({"brow_raise": 0.25}, at=now + 200)
    assert now + 200 <= reply["t"] < now + 200 + FRAME_MS
    assert client.state()["values"]["brow_raise"] != 0.25
    event = client.next_event()
    assert event["event"] == "applied" and event["t"] == reply["t"]
    assert client.state()["values"]["brow_raise"] == 0.25
    client.set({"brow_raise": 0})


def test_a_command_runs_on_the_frame_clock_with_its_events(client):
    reply = client.command('<commands><HeadNod amplitude="60" count="2"/></commands>')
    events = events_of(client, reply["id"])
    kinds = [e["event"] for e in events]
    assert kinds[0] == "command_start" and kinds[-1] == "finished" and "command_end" in kinds
    assert events[0]["command"] == "HeadNod"
    [apex] = [e for e in events if e["event"] == "command_apex"]
    [end] = [e for e in events if e["event"] == "command_end"]
    assert events[0]["onset_t"] < apex["onset_t"] < end["onset_t"]
    assert events[-1]["t"] >= reply["end_t"] > reply["t"]


def test_capabilities_name_the_parameters_types_voices_and_schema(client):
    caps = client.capabilities()
    assert caps["schema_version"] == SCHEMA_VERSION
    assert set(caps["requests"]) == set(REQUEST_TYPES)
    names = {p["name"] for p in caps["parameters"]}
    assert {"jaw_open", "head_turn"} <= names
    assert all(p["min"] <= p["default"] <= p["max"] for p in caps["parameters"])
    if shutil.which("festival"):
        assert "suo_fi_lj_diphone" in caps["voices"]
    assert caps["clock"]["fps"] == 60


def test_every_request_sent_and_message_received_here_is_checked_against_the_schema(client):
    from tests.engine.serve_schema_checks import COUNTS, check_request, check_server_message

    before = dict(COUNTS)
    client.state()
    assert COUNTS["requests"] == before["requests"] + 1
    assert COUNTS["received"] == before["received"] + 1
    with pytest.raises(AssertionError, match="breaks the schema"):
        check_server_message({"id": 1, "ok": "yes"})
    with pytest.raises(AssertionError, match="breaks the schema"):
        check_server_message({"event": "danced", "id": 1, "t": 0})
    with pytest.raises(AssertionError, match="breaks the schema"):
        check_request({"type": "state", "id": 1, "extra": True})


def test_the_shipped_schema_lists_every_request_and_event():
    schema = json.loads((PROJECT_ROOT / "engine/live/schema/protocol-v1.json").read_text())
    assert schema["version"] == SCHEMA_VERSION
    assert set(REQUEST_TYPES) <= set(schema["$defs"])
    assert schema["$defs"]["event"]["properties"]["event"]["enum"] == list(EVENT_TYPES)


# -- what a client gets wrong ------------------------------------------------------------------------------

@pytest.mark.parametrize("message, expected", [
    ("nonsense", r"^<message>:1: column 1: not JSON"),
    ("[1, 2]", r"^<message>:1: a request is a JSON object"),
    ('{"type": "dance", "id": 1}', r"unknown request type 'dance'"),
    ('{"type": "state"}', r"has no \"id\""),
    ('{"type": "set", "id": 2, "values": {"jaw": 1}}', r"unknown parameter 'jaw'"),
    ('{"type": "set", "id": 3, "values": {"jaw_open": 1e9}}', r"outside its range"),
    ('{"type": "set", "id": 4, "values": {"jaw_open": NaN}}', r"not JSON"),
    ('{"type": "say", "id": 5, "text": 7}', r"\"text\" must be a string"),
    ('{"type": "state", "id": 6, "extra": true}', r"has no field 'extra'"),
    ('{"type": "command", "id": 7, "xml": "<commands><Nope/></commands>"}', r"^<command>:1: unknown command"),
    ("x" * (MAX_MESSAGE_BYTES + 1), r"longer than 65536 bytes"),
    (b"\x00\x01binary", r"binary messages are not requests"),
    ("[" * 60000, r"not JSON"),
    ('{"type": "set", "id": 8, "values": {"jaw_open": 1' + "0" * 400 + '}}', r"must be a number"),
    ('{"type": "stop", "id": 9, "target": [1]}', r"\"target\" must be a string"),
    ('{"type": "say", "id": 10, "text": "moi", "voice": "../../etc/passwd"}', r"\"voice\" is a Festival voice"),
])
def test_a_bad_message_gets_an_error_reply_and_the_connection_stays_usable(client, message, expected):
    client.send_raw(message)
    reply = client._receive(deadline=time.monotonic() + 30)
    assert reply["ok"] is False
    assert re.search(expected, reply["error"]), reply["error"]
    assert LOCATED.match(reply["error"]), reply["error"]
    assert "\n" not in reply["error"]
    assert client.state()["ok"] is True


# -- safety ---------------------------------------------------------------------------------------------------

def run_cli(*args: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k != "AP_SERVE_TOKEN"}
    return subprocess.run([sys.executable, "-m", "engine", *args], cwd=PROJECT_ROOT, capture_output=True, text=True,
                          timeout=120, check=False, env=env)


@pytest.mark.parametrize("host", ["0.0.0.0", "192.0.2.7", "::", "example.org"])
def test_an_address_beyond_loopback_needs_a_token_and_nothing_is_bound_without_one(host):
    result = run_cli("serve", "--headless", "--host", host, "--port", "0")
    assert result.returncode == 2
    assert result.stderr.startswith(f"error: listening on {host} (not loopback) needs --token")
    assert result.stderr.count("\n") == 1 and result.stdout == ""


@pytest.mark.parametrize("args, expected", [
    (["serve"], "one of the arguments --window --headless is required"),
    (["serve", "--headless", "--window"], "not allowed with argument"),
    (["serve", "--headless", "--fullscreen"], "--fullscreen and --size are for --window"),
    (["serve", "--window", "--size", "0x10"], "width and height must be"),
    (["serve", "--headless", "--port", "70000"], "not a port number"),
])
def test_bad_serve_arguments_are_refused(args, expected):
    result = run_cli(*args)
    assert result.returncode == 2 and expected in result.stderr and "Traceback" not in result.stderr


def test_a_client_without_the_token_is_refused(tmp_path):
    served = start_server(tmp_path, "--token", "s3cret-token")
    try:
        for token in (None, "wrong"):
            with pytest.raises(InvalidStatus, match="401"):
                LiveClient(served.url, token=token)
        with LiveClient(served.url, token="s3cret-token") as head:
            assert head.state()["ok"]
    finally:
        stop_server(served)
    assert "Traceback" not in served.stderr()


@needs_festival
def test_a_client_gone_mid_utterance_leaves_the_server_ready(server):
    with LiveClient(server.url) as first:
        say_id = first.say(SENTENCE + " ja sitten vielä pitkä lause lisää")
        while first.next_event()["event"] != "word":
            pass
        [playing] = first.state()["playing"]
    with LiveClient(server.url) as second:
        state = second.state()
        while state["playing"] and state["t"] < playing["end_t"]:     # the close may take a frame to be seen
            state = second.state()
        assert state["playing"] == [] and state["t"] < playing["end_t"]   # ended by the disconnect, not by itself
        say_id = second.say("Moi")
        assert events_of(second, say_id)[-1]["event"] == "finished"


# -- fuzzing -------------------------------------------------------------------------------------------------------

JSON_LEAF = st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=30)
JSON_VALUE = st.recursive(JSON_LEAF, lambda inner: st.lists(inner, max_size=4)
                          | st.dictionaries(st.text(max_size=10), inner, max_size=4), max_leaves=12)
FIELD_NAMES = st.sampled_from(["text", "values", "xml", "at", "voice", "target", "id", "type", "x", "model"])
MODEL_NAMES = st.sampled_from(["head.xml", "../head.xml", "/etc/passwd", "head.h5", "missing.xml", "a/../head.xml",
                               "default-head/head.xml", "..\\head.xml", "C:head.xml", "head.xml\x00.xml"])
PARAMETERS = st.sampled_from(["jaw_open", "head_turn", "head_nod", "brow_raise", "nope", ""])
FIELD_VALUES = (JSON_VALUE
                | st.dictionaries(PARAMETERS, st.floats(-1e4, 1e4) | JSON_LEAF, max_size=3)
                | st.sampled_from(["<commands><HeadNod/></commands>", "<commands><Blink at='-5'/></commands>",
                                   "<commands>", "moi <Blink/>", "<HeadNod amplitude='1e999'/> moi"])
                | MODEL_NAMES)
REQUESTS = st.fixed_dictionaries(
    {"type": st.sampled_from([*REQUEST_TYPES, "Say", "", "x" * 200]), "id": st.integers() | st.text(max_size=140)},
    optional={"f": st.dictionaries(FIELD_NAMES, FIELD_VALUES, max_size=3)})
WORDS = st.lists(st.sampled_from(["moi", "hyvää", "päivää", "<Blink/>", "<HeadNod amplitude='60'/>", "2", "!", "<x"]),
                 min_size=1, max_size=4).map(" ".join)
WELL_FORMED = st.one_of(
    st.fixed_dictionaries({"type": st.just("set"), "id": st.integers(0, 9),
                           "values": st.dictionaries(PARAMETERS, st.floats(-2, 2), min_size=1, max_size=3)},
                          optional={"at": st.floats(-1e3, 1e5)}),
    st.fixed_dictionaries({"type": st.just("say"), "id": st.text(max_size=3), "text": WORDS},
                          optional={"voice": st.sampled_from(["suo_fi_lj_diphone", "kal_diphone", "no_such"])}),
    st.fixed_dictionaries({"type": st.just("command"), "id": st.integers(0, 9),
                           "xml": st.sampled_from(["<commands><HeadNod/></commands>", "<commands/>",
                                                   "<commands><Blink at='100'/><Smile/></commands>"])}),
    st.fixed_dictionaries({"type": st.sampled_from(["stop", "state", "capabilities"]), "id": st.integers(0, 9)},
                          optional={"target": st.integers(0, 9)}),
    st.fixed_dictionaries({"type": st.just("load"), "id": st.integers(0, 9),
                           "model": MODEL_NAMES | st.text(max_size=40).map(lambda name: name + ".xml")}),
).map(json.dumps)
MESSAGES = (WELL_FORMED
            | REQUESTS.map(lambda r: json.dumps({**{k: v for k, v in r.items() if k != "f"}, **r.get("f", {})}))
            | JSON_VALUE.map(json.dumps) | st.text(max_size=200) | st.binary(max_size=100))


@needs_festival
def test_fuzzed_messages_are_all_answered_without_a_traceback(tmp_path):
    served = start_server(tmp_path)
    tried = {"messages": 0, "refused": 0}
    try:
        with LiveClient(served.url) as head:
            @FUZZ
            @given(message=MESSAGES)
            def answer(message):
                if isinstance(message, str) and '"say"' in message:
                    head.send_raw(json.dumps({"type": "stop", "id": "fuzz-stop"}))   # keep Festival's queue short
                    head.reply_to("fuzz-stop")
                head.send_raw(message)
                tried["messages"] += 1
                while True:
                    reply = head._receive(deadline=time.monotonic() + 60)
                    if "event" not in reply:
                        break
                assert isinstance(reply["ok"], bool)
                if not reply["ok"]:
                    tried["refused"] += 1
                    assert isinstance(reply["error"], str) and LOCATED.match(reply["error"]), reply["error"]

            answer()
            head.stop()
            assert head.state()["ok"]
    finally:
        stop_server(served)
    print(f"fuzz: {tried['messages']} messages, {tried['refused']} refused")
    assert served.process.returncode in (0, -15)
    assert "Traceback" not in served.stderr()
    assert "internal error" not in served.stderr()


def test_a_browser_page_is_refused(server):
    from websockets.sync.client import connect

    with pytest.raises(InvalidStatus, match="403"), connect(server.url, origin="http://example.org"):
        pass


@needs_festival
def test_stop_ends_an_utterance_at_once(client):
    say_id = client.say(SENTENCE + " ja sitten vielä pitkä lause lisää")
    while client.next_event()["event"] != "speech_start":
        pass
    client.stop(say_id)
    finished = [e for e in client.events_until(say_id, "finished") if e.get("id") == say_id][-1]
    assert finished["event"] == "finished" and finished["stopped"] is True
    assert client.state()["playing"] == []


@needs_festival
def test_the_asyncio_client_says_and_sets(server):
    async def run():
        async with await AsyncLiveClient.open(server.url) as head:
            reply = await head.set({"jaw_open": 0.2})
            applied = await head.next_event()
            assert applied["event"] == "applied" and applied["t"] == reply["t"]
            say_id = await head.say("Moi")
            kinds = [e["event"] async for e in head.events_until(say_id, "finished") if e.get("id") == say_id]
            await head.set({"jaw_open": 0})
            return kinds, await head.to_local_monotonic(0.0)

    kinds, epoch = asyncio.run(run())
    assert kinds[0] == "speech_start" and "word" in kinds and kinds[-1] == "finished"
    assert epoch <= time.monotonic()                                   # the server's clock is this computer's


def test_two_clients_sending_fast_get_every_reply_in_order(server):
    count = 2000
    results: dict[str, list] = {}

    def drive(name: str) -> None:
        with LiveClient(server.url) as head:
            for i in range(count):
                message = {"type": "set", "id": i, "values": {"head_tilt": (i % 10) / 20}} if i % 2 else \
                    {"type": "state", "id": i}
                head.send_raw(json.dumps(message))
                if i % 100 == 99:
                    time.sleep(0.1)                                    # about 1000 messages a second
            replies = []
            while len(replies) < count:
                message = head._receive(deadline=time.monotonic() + 60)
                if "event" not in message:
                    replies.append(message)
            results[name] = replies
            head.set({"head_tilt": 0})

    threads = [threading.Thread(target=drive, args=(name,)) for name in ("a", "b")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for replies in results.values():
        assert [r["id"] for r in replies] == list(range(count))
        assert all(r["ok"] for r in replies), [r for r in replies if not r["ok"]][:3]
        state_times = [r["t"] for r in replies if "frame" in r]
        assert state_times == sorted(state_times)


def test_importing_the_engine_and_the_live_protocol_loads_no_network_library():
    code = ("import sys, engine, engine.cli, engine.live, engine.live.protocol, engine.live.head;"
            "import engine.cli.serve_verbs; engine.cli.build_parser();"
            "print(sorted(m for m in sys.modules if m.startswith('websockets')))")
    result = subprocess.run([sys.executable, "-c", code], cwd=PROJECT_ROOT, capture_output=True, text=True,
                            timeout=120, check=True)
    assert result.stdout.strip() == "[]"


@needs_festival
def test_an_inline_command_starts_with_the_next_word_on_the_frame_clock(client):
    say_id = client.say("Hyvää päivää <HeadNod amplitude='60'/> mitä kuuluu")
    events = events_of(client, say_id)
    words = {e["word"]: e for e in events if e["event"] == "word"}
    [start] = [e for e in events if e["event"] == "command_start"]
    [apex] = [e for e in events if e["event"] == "command_apex"]
    [end] = [e for e in events if e["event"] == "command_end"]
    assert start["command"] == "HeadNod" and start["source"] == "<text>:1"
    assert start["onset_t"] == pytest.approx(words["mitä"]["onset_t"])
    assert start["t"] == words["mitä"]["t"]
    assert start["onset_t"] < apex["onset_t"] < end["onset_t"] <= events[-1]["t"]
    assert 0 <= apex["t"] - apex["onset_t"] < FRAME_MS


def test_a_frame_over_the_hard_limit_closes_only_that_connection(server):
    from websockets.exceptions import ConnectionClosed

    with LiveClient(server.url) as head:
        head.send_raw("x" * (MAX_FRAME_BYTES + 1))
        with pytest.raises(ConnectionClosed) as closed:
            head.state()
        assert closed.value.rcvd is not None and closed.value.rcvd.code == 1009
    with LiveClient(server.url) as head:
        assert head.state()["ok"]


def open_clients(url: str, count: int, into: list) -> None:
    for _ in range(count):
        into.append(LiveClient(url))  # noqa: PERF401  (each kept even when a later one is refused)


def test_more_clients_than_the_limit_are_refused_and_the_server_recovers(server):
    clients: list[LiveClient] = []
    try:
        with pytest.raises(InvalidStatus, match="503"):
            open_clients(server.url, MAX_CLIENTS + 1, clients)
        assert len(clients) <= MAX_CLIENTS
    finally:
        for head in clients:
            head.close()
    for _ in range(1000):                            # the server sees the closes a moment later
        try:
            with LiveClient(server.url) as head:
                assert head.state()["ok"]
            break
        except InvalidStatus:
            continue
    else:
        pytest.fail("the server stayed full after every client left")


def test_a_reconnecting_client_carries_on_after_the_server_is_killed_and_restarted(tmp_path):
    from engine.live.client import ConnectionLost

    runs = [tmp_path / name for name in ("first", "second", "third")]
    for run in runs:
        run.mkdir()
    servers = [start_server(runs[0])]
    port = servers[0].url.rsplit(":", 1)[1]

    def kill_and_restart() -> None:
        servers[-1].process.kill()
        stop_server(servers[-1])
        servers.append(start_server(runs[len(servers)], "--port", port))

    try:
        with LiveClient(servers[0].url, reconnect=True) as head:
            head.set({"jaw_open": 0.3})
            epoch = head.state()["clock"]["epoch_monotonic_s"]
            kill_and_restart()
            state = head.state()                                   # sent again on the new connection
            assert state["clock"]["epoch_monotonic_s"] > epoch and state["values"]["jaw_open"] == 0.0
            assert head.set({"jaw_open": 0.3})["ok"]
            kill_and_restart()
            with pytest.raises(ConnectionLost, match="'command'"):
                head.command("<commands><Blink/></commands>")
            assert head.state()["ok"]
    finally:
        for served in servers:
            stop_server(served)
    assert not any("Traceback" in served.stderr() for served in servers)


def run_gaze_cue_example(url: str, log: Path) -> list[dict[str, str]]:
    """``docs/examples/psychopy_gaze_cue.py`` run against the server at ``url``: the rows of its log."""
    import csv
    import io

    subprocess.run([sys.executable, "docs/examples/psychopy_gaze_cue.py", "--url", url, "--log", str(log)],
                   cwd=PROJECT_ROOT, check=True, timeout=300, capture_output=True)
    return list(csv.DictReader(io.StringIO(log.read_text(encoding="utf-8"))))


def check_gaze_cue_log(rows: list[dict[str, str]]) -> None:
    """The example's log agrees with the frames and the audio that were presented."""
    say = [r for r in rows if r["request"] == "say"]
    assert say[0]["event"] == "speech_start" and say[-1]["event"] == "finished"
    assert [r["word"] for r in say if r["event"] == "word"] == ["Katso", "tänne", "ja", "sitten", "vasemmalle"]
    # sample 0 is due at speech_start's onset (its frame t is later when the clock skipped a frame under load)
    start_t, rate = float(say[0]["onset_t"]), int(say[0]["sample_rate"])
    for row in rows:
        t = float(row["t"])
        assert t == pytest.approx(round(t / FRAME_MS) * FRAME_MS)                    # a frame of the clock
        # the first frame at its onset (a set's onset is the example's own sum: ±1e-9 ms of float rounding)
        assert -1e-9 <= t - float(row["onset_t"]) < FRAME_MS
        assert float(row["received_monotonic_s"]) >= float(row["frame_monotonic_s"])  # never heard before shown
        assert float(row["presented_t"]) >= t                                         # presented at or after it
        assert float(row["received_monotonic_s"]) >= float(row["presented_monotonic_s"])
        if row["request"] == "say" and row["sample"]:                                 # the audio clock agrees
            assert float(row["onset_t"]) - start_t == pytest.approx(int(row["sample"]) * 1000 / rate, abs=0.05)
    [nod] = [r for r in say if r["event"] == "command_start"]
    [tanne] = [r for r in say if r["word"] == "tänne" and r["event"] == "word"]
    assert nod["command"] == "HeadNod" and nod["t"] == tanne["t"]                    # nods at the word after it
    left, ahead = (next(r for r in rows if r["request"] == name) for name in ("look_left", "look_ahead"))
    assert float(left["onset_t"]) == float(say[-1]["t"]) + 500
    assert float(ahead["t"]) - float(left["t"]) == pytest.approx(500, abs=FRAME_MS)


@needs_festival
def test_the_gaze_cue_example_logs_event_times_that_agree_with_the_frames_and_the_audio(server, tmp_path):
    check_gaze_cue_log(run_gaze_cue_example(server.url, tmp_path / "log.csv"))


def test_what_waits_on_the_head_is_bounded_and_stop_clears_it(client):
    from engine.live.protocol import MAX_SCHEDULED

    far = client.state()["t"] + 3_600_000
    for batch in range(MAX_SCHEDULED // 1000):
        for i in range(1000):
            client.send_raw(json.dumps({"type": "set", "id": f"w{batch}-{i}", "values": {"jaw_open": 0.1},
                                        "at": far + i}))
        for i in range(1000):
            assert client.reply_to(f"w{batch}-{i}")["ok"]
        time.sleep(0.5)                                   # within the rate limit (2000 a second)
    with pytest.raises(LiveError, match="already waiting on the head"):
        client.set({"jaw_open": 0.1}, at=far)
    client.stop()
    assert client.set({"jaw_open": 0.0})["ok"]


@needs_festival
def test_stopping_an_utterance_still_in_synthesis_ends_it_and_the_next_one_is_spoken(client):
    long_id = client.say(" ".join(["Tämä on pitkä lause, jota ei koskaan kuulla."] * 30))
    client.stop(long_id)
    [ended] = [e for e in client.events_until(long_id, "finished") if e.get("id") == long_id]
    assert ended["event"] == "finished" and ended["stopped"] is True
    say_id = client.say("Moi")
    kinds = [e["event"] for e in events_of(client, say_id)]
    assert kinds[0] == "speech_start" and kinds[-1] == "finished"


def test_a_client_over_the_rate_limit_is_refused_per_request_and_served_again_later(client):
    count = 6000                                          # three seconds' worth, sent as fast as the socket takes
    for i in range(count):
        client.send_raw(json.dumps({"type": "state", "id": i}))
    replies = [client.reply_to(i) for i in range(count)]
    refused = [r for r in replies if not r["ok"]]
    assert refused and all(r["error"] == "<message>:1: too many requests: at most 2000 a second" for r in refused)
    assert replies[0]["ok"]
    time.sleep(1.0)                                       # the allowance refills
    assert client.state()["ok"]
