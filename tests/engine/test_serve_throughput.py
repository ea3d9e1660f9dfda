"""Full size (issue 21): two clients each sending 1,000 messages a second for 10 s, every reply in order.

Each client paces its sending by its own clock (message ``i`` at ``start + i / 1000`` s, sent in
groups of 10 every 10 ms) while a reader thread takes the replies and events off the same
connection, so nothing piles up in the client. The messages are a mix of ``state``, ``set`` (now
and at a later frame) and ``command``. Checked: every reply, in the order sent, all accepted; the
``state`` times never going back; an ``applied`` event for every ``set``, in order; the server's
stderr free of tracebacks. The latencies (send → reply) are printed for ``docs/serve.md``, never
asserted. About 12 s on the shared 2-core machine, so it stays in ``./bootstrap test``.
"""

from __future__ import annotations

import json
import statistics
import threading
import time

import pytest

from engine.live.client import LiveClient
from tests.engine.serve_schema_checks import check_server_message
from tests.engine.test_serve import start_server, stop_server

RATE = 1000                     # messages a second, per client
SECONDS = 10
COUNT = RATE * SECONDS
GROUP = 10                      # sent together, every GROUP / RATE seconds


def message(i: int) -> dict:
    kind = i % 5
    if kind in (0, 2):
        return {"type": "state", "id": i}
    if kind == 1:
        return {"type": "set", "id": i, "values": {"head_tilt": (i % 7) / 20}}
    if kind == 3:
        return {"type": "set", "id": i, "values": {"brow_raise": (i % 3) / 10}, "at": 0}
    return {"type": "command", "id": i, "xml": "<commands><Blink/></commands>"} if i % 50 == 4 else \
        {"type": "state", "id": i}


class Driver:
    """One client: a sender pacing :data:`RATE` messages a second, a reader taking every message back."""

    def __init__(self, url: str):
        self.head = LiveClient(url, timeout=120)
        self.sent_at: dict[int, float] = {}
        self.replies: list[dict] = []
        self.events: list[dict] = []
        self.received_at: dict[int, float] = {}
        self.failure: BaseException | None = None

    def send(self) -> None:
        start = time.monotonic()
        for first in range(0, COUNT, GROUP):
            due = start + first / RATE
            wait = due - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            for i in range(first, first + GROUP):
                self.sent_at[i] = time.monotonic()
                self.head.send_raw(json.dumps(message(i)))

    def read(self) -> None:
        try:
            connection = self.head._connection
            wanted = {"applied": sum(message(i)["type"] == "set" for i in range(COUNT)),
                      "finished": sum(message(i)["type"] == "command" for i in range(COUNT))}
            seen = dict.fromkeys(wanted, 0)
            while len(self.replies) < COUNT or seen != wanted:      # until the last command has finished too
                received = json.loads(connection.recv(timeout=120))
                if "event" in received:
                    self.events.append(received)
                    if received["event"] in seen:
                        seen[received["event"]] += 1
                else:
                    self.received_at[received["id"]] = time.monotonic()
                    self.replies.append(received)
        except BaseException as exc:            # handed to the test's thread
            self.failure = exc


@pytest.mark.slow
def test_two_clients_at_a_thousand_messages_a_second_for_ten_seconds_get_every_reply_in_order(tmp_path):
    served = start_server(tmp_path)
    try:
        drivers = [Driver(served.url), Driver(served.url)]
        threads = [threading.Thread(target=d.read) for d in drivers] + \
                  [threading.Thread(target=d.send) for d in drivers]
        started = time.monotonic()
        for thread in threads:
            thread.start()
        for thread in threads[2:]:
            thread.join()
        sending = time.monotonic() - started
        for thread in threads[:2]:
            thread.join()
        elapsed = time.monotonic() - started
        for driver in drivers:
            driver.head.close()
    finally:
        stop_server(served)
    assert "Traceback" not in served.stderr()
    latencies = []
    for driver in drivers:
        assert driver.failure is None, driver.failure
        assert [r["id"] for r in driver.replies] == list(range(COUNT))
        refused = [r for r in driver.replies if not r["ok"]]
        assert not refused, refused[:3]
        state_times = [r["t"] for r in driver.replies if "frame" in r]
        assert state_times == sorted(state_times)
        sets = [i for i in range(COUNT) if message(i)["type"] == "set"]
        assert [e["id"] for e in driver.events if e["event"] == "applied"] == sets
        latencies += [(driver.received_at[i] - driver.sent_at[i]) * 1000 for i in range(COUNT)]
    for driver in drivers:                                  # checked here, not in the reader: it keeps up
        for received in driver.replies + driver.events:
            check_server_message(received)
    latencies.sort()
    print(f"\n{2 * COUNT} messages from 2 clients sent in {sending:.1f} s, all answered in {elapsed:.1f} s "
          f"({2 * COUNT / elapsed:.0f}/s); "
          f"send → reply p50 {statistics.median(latencies):.1f} ms, "
          f"p95 {latencies[int(0.95 * len(latencies))]:.1f} ms, max {latencies[-1]:.1f} ms")
