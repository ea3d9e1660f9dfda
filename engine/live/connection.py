"""One client's connection to the live server: its outbox (sent in order by a writer task) and its rate budget.

Replies and events of a connection leave in the order they were made, each encoded once by
:func:`encode_message` (which cannot fail). What waits in the outbox is bounded in bytes
(``docs/serve.md``, "Safety"; replies and events, each counted with :data:`MESSAGE_OVERHEAD_BYTES`):

* above :data:`OUTBOX_PAUSE_BYTES` the server reads none of the client's requests until the outbox
  is down to :data:`OUTBOX_RESUME_BYTES` (:meth:`Client.room_for_replies`): a client that sends
  without reading is held back by TCP's own flow control and loses nothing;
* above :data:`MAX_OUTBOX_BYTES` (only events can take it there, its requests being unread) the
  client is disconnected at once, what waits for it dropped, with close code
  :data:`SLOW_READER_CLOSE_CODE` and :data:`SLOW_READER_REASON`; ``dropped`` is told, so the
  server ends its performances then and there.

When a client whose outbox held more than :data:`RELEASE_AFTER_BYTES` leaves,
:func:`release_freed_memory` hands the heap pages its messages used back to the system (the C
library keeps freed memory for reuse otherwise).

Each event also goes to the LSL marker outlet when there is one (``markers``), as the same text.

>>> encode_message({"id": "\\ud800", "ok": True})          # a lone surrogate cannot reach the wire as such
b'{"id": "\\xef\\xbf\\xbd", "ok": true}'
"""

from __future__ import annotations

import asyncio
import ctypes
import json
import math
import sys
import time
import traceback
from collections import deque
from collections.abc import Callable
from typing import Any

from websockets.asyncio.server import ServerConnection
from websockets.exceptions import ConnectionClosed

from engine.live.protocol import LONE_SURROGATE, RATE_BURST, RATE_PER_SECOND, RequestId

#: Bytes waiting for one client above which the server stops reading that client's requests ...
OUTBOX_PAUSE_BYTES = 8 * 1024 * 1024
#: ... until they are down to this.
OUTBOX_RESUME_BYTES = 2 * 1024 * 1024
#: Bytes waiting for one client above which it is disconnected (what waits is dropped at once).
MAX_OUTBOX_BYTES = 10 * 1024 * 1024
#: An outbox that held more than this at some moment: its memory is handed back when the client leaves.
RELEASE_AFTER_BYTES = 1024 * 1024
#: What one waiting message costs besides its text (its bytes object and its place in the queue), counted too.
MESSAGE_OVERHEAD_BYTES = 64
#: The close code and reason a client gets when it leaves more than :data:`MAX_OUTBOX_BYTES` unread.
SLOW_READER_CLOSE_CODE = 1008
SLOW_READER_REASON = f"the client does not read its messages (over {MAX_OUTBOX_BYTES // 2**20} MiB waiting)"
INTERNAL_ERROR = "internal error in the server (see its log)"


def release_freed_memory() -> None:
    """Give the heap's free pages back to the system (glibc's ``malloc_trim``; elsewhere nothing is done)."""
    try:
        trim = ctypes.CDLL(None).malloc_trim           # the C library the interpreter runs on
    except (OSError, AttributeError):                   # not glibc
        return
    trim(0)


def encode_message(message: dict[str, Any]) -> bytes:
    """A reply or an event as UTF-8 JSON text. It cannot fail.

    A lone surrogate, which UTF-8 cannot hold (requests carrying one are refused, so only a bug of ours
    could bring one here), becomes U+FFFD. A message JSON cannot write at all (NaN, an object of no JSON
    kind) is a bug of ours: said on stderr, and a reply becomes the internal-error reply with its id, an
    event a ``failed`` event of its request (so a client waiting for the request's end is not left waiting).
    """
    try:
        text = json.dumps(message, ensure_ascii=False, allow_nan=False)
    except (ValueError, TypeError, RecursionError):
        print(f"internal error encoding a message:\n{traceback.format_exc()}", file=sys.stderr, flush=True)
        text = json.dumps(_internal_error(message), ensure_ascii=False)
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError:
        return LONE_SURROGATE.sub("\ufffd", text).encode("utf-8")


def _internal_error(message: dict[str, Any]) -> dict[str, Any]:
    """What is sent instead of a message that cannot be encoded: only its id and time are kept, when they can be."""
    request_id = message.get("id")
    if not isinstance(request_id, int | str) or isinstance(request_id, bool):
        request_id = None
    if "event" not in message:
        return {"id": request_id, "ok": False, "error": INTERNAL_ERROR}
    t = message.get("t")
    if not isinstance(t, int | float) or isinstance(t, bool) or not math.isfinite(t):
        t = 0.0
    return {"event": "failed", "id": request_id, "t": t, "presented_t": t, "error": INTERNAL_ERROR}


class Client:
    """One connection: its outbox (sent in order by a writer task), its rate budget, its waiting utterances."""

    def __init__(self, connection: ServerConnection,
                 markers: Callable[[dict[str, Any], str], None] | None = None,
                 dropped: Callable[[Client], None] | None = None):
        self.connection = connection
        self.markers = markers
        self.dropped = dropped
        self.outbox: deque[bytes] = deque()
        #: Bytes in :attr:`outbox`, each message counted with :data:`MESSAGE_OVERHEAD_BYTES`.
        self.outbox_bytes = 0
        #: The most :attr:`outbox_bytes` has been.
        self.peak_outbox_bytes = 0
        self._more = asyncio.Event()                 # something to send, or the writer is to end
        self._room = asyncio.Event()                 # the outbox is low enough to read the next request
        self._room.set()
        self._ending = False
        self.allowance = RATE_BURST
        self.last_check = time.monotonic()
        self.waiting_utterances: set[RequestId] = set()
        self.cancelled: set[RequestId] = set()
        self.closed = False
        self.closing: asyncio.Future[None] | None = None

    def send(self, message: dict[str, Any]) -> None:
        if self.closed:
            return
        data = encode_message(message)
        if self.markers is not None and "event" in message:
            self.markers(message, data.decode("utf-8"))
        self.outbox_bytes += len(data) + MESSAGE_OVERHEAD_BYTES
        self.peak_outbox_bytes = max(self.peak_outbox_bytes, self.outbox_bytes)
        if self.outbox_bytes > MAX_OUTBOX_BYTES:
            self.disconnect_slow_reader()
            return
        self.outbox.append(data)
        self._more.set()
        if self.outbox_bytes > OUTBOX_PAUSE_BYTES:
            self._room.clear()

    async def room_for_replies(self) -> None:
        """Wait while the outbox is over :data:`OUTBOX_PAUSE_BYTES`, until it is down to :data:`OUTBOX_RESUME_BYTES`
        (or the connection is gone): the caller reads the client's next request only then."""
        await self._room.wait()

    def disconnect_slow_reader(self) -> None:
        """Drop what waits and close the connection with :data:`SLOW_READER_CLOSE_CODE`; tell ``dropped``."""
        self.closed = True
        self.discard_outbox()
        self.closing = asyncio.ensure_future(self.connection.close(SLOW_READER_CLOSE_CODE, SLOW_READER_REASON))
        if self.dropped is not None:
            self.dropped(self)

    def discard_outbox(self) -> None:
        """Forget every message still waiting (the connection is gone or being closed); the reader may go on."""
        self.outbox.clear()
        self.outbox_bytes = 0
        self._room.set()

    @property
    def held_much(self) -> bool:
        """Its outbox held more than :data:`RELEASE_AFTER_BYTES` at some moment."""
        return self.peak_outbox_bytes > RELEASE_AFTER_BYTES

    def end_writer(self) -> None:
        """Make :meth:`write` return once the outbox is empty."""
        self._ending = True
        self._more.set()

    def within_rate(self) -> bool:
        now = time.monotonic()
        self.allowance = min(RATE_BURST, self.allowance + (now - self.last_check) * RATE_PER_SECOND)
        self.last_check = now
        if self.allowance < 1.0:
            return False
        self.allowance -= 1.0
        return True

    async def write(self) -> None:
        """Send the outbox's messages in order until :meth:`end_writer` (or the connection closes)."""
        while True:
            if not self.outbox:
                if self._ending:
                    return
                self._more.clear()
                await self._more.wait()
                continue
            data = self.outbox.popleft()
            self.outbox_bytes -= len(data) + MESSAGE_OVERHEAD_BYTES
            if self.outbox_bytes <= OUTBOX_RESUME_BYTES:
                self._room.set()
            try:
                await self.connection.send(data, text=True)
            except ConnectionClosed:                    # gone: nothing more is queued for it
                self.closed = True
                self.discard_outbox()
                return
