"""One client's connection to the live server: its outbox (sent in order by a writer task) and its rate budget.

Replies and events of a connection leave in the order they were made; a client that leaves
:data:`MAX_OUTBOX` messages unread is disconnected. Each event also goes to the LSL marker
outlet when there is one (``markers``).
"""

from __future__ import annotations

import asyncio
import json
import time
from collections.abc import Callable
from typing import Any

from websockets.asyncio.server import ServerConnection
from websockets.exceptions import ConnectionClosed

from engine.live.protocol import RATE_BURST, RATE_PER_SECOND, RequestId

#: Messages waiting to be sent to one client; a client that reads slower than that is disconnected.
MAX_OUTBOX = 50_000


class Client:
    """One connection: its outbox (sent in order by a writer task), its rate budget, its waiting utterances."""

    def __init__(self, connection: ServerConnection, markers: Callable[[dict[str, Any]], None] | None = None):
        self.connection = connection
        self.markers = markers
        self.outbox: asyncio.Queue[str | None] = asyncio.Queue()
        self.allowance = RATE_BURST
        self.last_check = time.monotonic()
        self.waiting_utterances: set[RequestId] = set()
        self.cancelled: set[RequestId] = set()
        self.closed = False
        self.closing: asyncio.Future[None] | None = None

    def send(self, message: dict[str, Any]) -> None:
        if self.closed:
            return
        if self.markers is not None and "event" in message:
            self.markers(message)
        if self.outbox.qsize() >= MAX_OUTBOX:
            self.closed = True
            self.closing = asyncio.ensure_future(self.connection.close(1008, "the client does not read its messages"))
            return
        self.outbox.put_nowait(json.dumps(message, ensure_ascii=False, allow_nan=False))

    def within_rate(self) -> bool:
        now = time.monotonic()
        self.allowance = min(RATE_BURST, self.allowance + (now - self.last_check) * RATE_PER_SECOND)
        self.last_check = now
        if self.allowance < 1.0:
            return False
        self.allowance -= 1.0
        return True

    async def write(self) -> None:
        while True:
            text = await self.outbox.get()
            if text is None:
                return
            try:
                await self.connection.send(text)
            except ConnectionClosed:
                return
