"""Python clients of the live service (``artificial-person serve``): blocking (scripts, PsychoPy) and asyncio.

Requests get ids of their own; :meth:`LiveClient.request` waits for the reply with that id and
keeps every event that arrives meanwhile, so no event is lost; :meth:`LiveClient.events` then
hands them out in the order they came. A refused request raises :class:`LiveError` with the
server's one-line message.

>>> with LiveClient("ws://127.0.0.1:8765") as head:                       # doctest: +SKIP
...     say_id = head.say("Hyvää päivää <HeadNod/> mitä kuuluu?")
...     for event in head.events_until(say_id, "finished"):
...         print(event["event"], event.get("word", ""), event["t"])
...     head.set({"head_turn": 20})
...     head.to_local_monotonic(head.state()["t"])            # the frame clock on this computer's clock

Frame times (``t``, ms) are on the server's frame clock; on the same computer
:meth:`LiveClient.to_local_monotonic` turns them into ``time.monotonic()`` seconds (``docs/serve.md``).

:class:`AsyncLiveClient` has the same methods as coroutines:

>>> async def experiment():                                                # doctest: +SKIP
...     async with await AsyncLiveClient.open("ws://127.0.0.1:8765") as head:
...         await head.set({"head_turn": 0.3})
...         async for event in head.events_until(await head.say("Moi"), "finished"):
...             print(event)
"""

from __future__ import annotations

import asyncio
import itertools
import json
import time
from collections import deque
from collections.abc import AsyncIterator, Iterator
from contextlib import ExitStack
from typing import Any

from websockets.asyncio.client import ClientConnection as AsyncConnection
from websockets.asyncio.client import connect as async_connect
from websockets.exceptions import ConnectionClosed, InvalidHandshake, InvalidStatus
from websockets.sync.client import ClientConnection, connect

from engine.live.protocol import MAX_FRAME_BYTES


class LiveError(Exception):
    """The server refused a request (``str()`` is its message) or sent something that is not the protocol."""


class ConnectionLost(LiveError):
    """The connection broke during a request that is not sent twice (``say``, ``command``, ``stop``)."""


#: Requests a reconnecting client sends again after a lost connection: doing them twice does no harm.
RESENDABLE = frozenset({"state", "capabilities", "set", "load"})


class LiveClient:
    """A connection to the live service; ``token`` when the server was started with one."""

    def __init__(self, url: str, token: str | None = None, timeout: float = 30.0, reconnect: bool = False):
        self.url = url
        self.timeout = timeout
        self.auto_reconnect = reconnect
        """On a lost connection, connect again (:meth:`reconnect`) and send the request again when that is
        harmless (:data:`RESENDABLE`); other requests raise :class:`ConnectionLost`."""
        self._headers = {"Authorization": f"Bearer {token}"} if token is not None else None
        self._stack = ExitStack()
        self._connection = self._connect()
        self._ids = itertools.count(1)
        self._events: deque[dict[str, Any]] = deque()
        self._clock: dict[str, Any] | None = None

    def _connect(self) -> ClientConnection:
        # connect() is a context manager in every websockets since 14 (and must be used as one since 17.1)
        return self._stack.enter_context(connect(self.url, additional_headers=self._headers,
                                                 open_timeout=self.timeout, max_size=MAX_FRAME_BYTES))

    def reconnect(self, attempts: int = 100, wait: float = 0.1) -> None:
        """Connect again (a restarted server): up to ``attempts`` tries ``wait`` seconds apart. The clock is
        read again, since a new server has a new epoch; events not yet handed out are kept."""
        self._stack.close()
        self._stack = ExitStack()
        for attempt in range(attempts):
            try:
                self._connection = self._connect()
                break
            except (OSError, InvalidStatus, InvalidHandshake):
                if attempt == attempts - 1:
                    raise
                time.sleep(wait)
        self._clock = None

    def __enter__(self) -> LiveClient:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        self._stack.close()

    # -- requests -----------------------------------------------------------------------------

    def request(self, kind: str, **fields: Any) -> dict[str, Any]:
        """Send one request and return its reply (``ok`` true), or raise :class:`LiveError`."""
        try:
            return self._request_once(kind, fields)
        except (ConnectionClosed, OSError):
            if not self.auto_reconnect:
                raise
            self.reconnect()
            if kind in RESENDABLE:
                return self._request_once(kind, fields)
            raise ConnectionLost(f"the connection was lost during '{kind}'; connected again, but the request was "
                                 "not sent again (the server may or may not have done it)") from None

    def _request_once(self, kind: str, fields: dict[str, Any]) -> dict[str, Any]:
        request_id = f"c{next(self._ids)}"
        self.send_raw(json.dumps({"type": kind, "id": request_id, **fields}))
        reply = self.reply_to(request_id)
        if not reply.get("ok"):
            raise LiveError(str(reply.get("error")))
        return reply

    def send_raw(self, text: str | bytes) -> None:
        """Send a message as it is (tests use it for malformed ones)."""
        self._connection.send(text)

    def reply_to(self, request_id: object) -> dict[str, Any]:
        """Wait for the reply that carries ``request_id``; events that come first are kept for :meth:`events`."""
        deadline = time.monotonic() + self.timeout
        while True:
            reply = _sort(self._receive(deadline), request_id, self._events)
            if reply is not None:
                return reply

    def say(self, text: str, voice: str | None = None, at: float | None = None) -> str:
        """Speak ``text`` (inline commands allowed); returns the request id its events carry."""
        fields: dict[str, Any] = {"text": text}
        if voice is not None:
            fields["voice"] = voice
        if at is not None:
            fields["at"] = at
        return str(self.request("say", **fields)["id"])

    def set(self, values: dict[str, float], at: float | None = None) -> dict[str, Any]:
        """New parameter values from the next frame (or the first at ``at``); the reply says that frame's ``t``."""
        return self.request("set", values=values, **({} if at is None else {"at": at}))

    def command(self, xml: str, at: float | None = None) -> dict[str, Any]:
        """High-level commands (``<commands>…</commands>``, §2.3) from the next frame or ``at``."""
        return self.request("command", xml=xml, **({} if at is None else {"at": at}))

    def stop(self, target: str | None = None) -> dict[str, Any]:
        return self.request("stop", **({} if target is None else {"target": target}))

    def load(self, model: str) -> dict[str, Any]:
        """Another model file (an identity), named from a folder the server serves; the head changes next frame."""
        return self.request("load", model=model)

    def state(self) -> dict[str, Any]:
        reply = self.request("state")
        self._clock = reply["clock"]
        return reply

    def capabilities(self) -> dict[str, Any]:
        reply = self.request("capabilities")
        self._clock = reply["clock"]
        return reply

    # -- events -------------------------------------------------------------------------------------

    def next_event(self, timeout: float | None = None) -> dict[str, Any]:
        """The next event (kept ones first), waiting at most ``timeout`` seconds (default: the client's)."""
        if self._events:
            return self._events.popleft()
        deadline = time.monotonic() + (self.timeout if timeout is None else timeout)
        while True:
            message = self._receive(deadline)
            if "event" in message:
                return message
            raise LiveError(f"a reply nobody waits for: {message}")

    def events_until(self, request_id: str, event: str = "finished") -> Iterator[dict[str, Any]]:
        """Every event until (and with) ``event`` of ``request_id`` (events of other requests included)."""
        while True:
            message = self.next_event()
            yield message
            if message.get("id") == request_id and message.get("event") in (event, "failed"):
                return

    def to_local_monotonic(self, t: float) -> float:
        """A frame-clock time as ``time.monotonic()`` seconds of the server's computer (= this one's on loopback)."""
        if self._clock is None:
            self.state()
        assert self._clock is not None
        return float(self._clock["epoch_monotonic_s"]) + t / 1000.0

    def _receive(self, deadline: float) -> dict[str, Any]:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise TimeoutError("no answer from the server in time")
        return _message(self._connection.recv(timeout=remaining))


class AsyncLiveClient:
    """The asyncio client: :meth:`open` connects; the methods of :class:`LiveClient`, as coroutines."""

    def __init__(self, connection: AsyncConnection, timeout: float = 30.0):
        self._connection = connection
        self.timeout = timeout
        self._ids = itertools.count(1)
        self._events: deque[dict[str, Any]] = deque()
        self._clock: dict[str, Any] | None = None

    @classmethod
    async def open(cls, url: str, token: str | None = None, timeout: float = 30.0) -> AsyncLiveClient:
        headers = {"Authorization": f"Bearer {token}"} if token is not None else None
        connection = await async_connect(url, additional_headers=headers, open_timeout=timeout,
                                         max_size=MAX_FRAME_BYTES)
        return cls(connection, timeout)

    async def __aenter__(self) -> AsyncLiveClient:
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.close()

    async def close(self) -> None:
        await self._connection.close()

    async def request(self, kind: str, **fields: Any) -> dict[str, Any]:
        request_id = f"a{next(self._ids)}"
        await self.send_raw(json.dumps({"type": kind, "id": request_id, **fields}))
        reply = await self.reply_to(request_id)
        if not reply.get("ok"):
            raise LiveError(str(reply.get("error")))
        if "clock" in reply:
            self._clock = reply["clock"]
        return reply

    async def send_raw(self, text: str | bytes) -> None:
        await self._connection.send(text)

    async def reply_to(self, request_id: object) -> dict[str, Any]:
        while True:
            reply = _sort(await self._receive(), request_id, self._events)
            if reply is not None:
                return reply

    async def say(self, text: str, voice: str | None = None, at: float | None = None) -> str:
        fields: dict[str, Any] = {"text": text}
        if voice is not None:
            fields["voice"] = voice
        if at is not None:
            fields["at"] = at
        return str((await self.request("say", **fields))["id"])

    async def set(self, values: dict[str, float], at: float | None = None) -> dict[str, Any]:
        return await self.request("set", values=values, **({} if at is None else {"at": at}))

    async def command(self, xml: str, at: float | None = None) -> dict[str, Any]:
        return await self.request("command", xml=xml, **({} if at is None else {"at": at}))

    async def stop(self, target: str | None = None) -> dict[str, Any]:
        return await self.request("stop", **({} if target is None else {"target": target}))

    async def load(self, model: str) -> dict[str, Any]:
        return await self.request("load", model=model)

    async def state(self) -> dict[str, Any]:
        return await self.request("state")

    async def capabilities(self) -> dict[str, Any]:
        return await self.request("capabilities")

    async def next_event(self) -> dict[str, Any]:
        if self._events:
            return self._events.popleft()
        message = await self._receive()
        if "event" in message:
            return message
        raise LiveError(f"a reply nobody waits for: {message}")

    async def events_until(self, request_id: str, event: str = "finished") -> AsyncIterator[dict[str, Any]]:
        while True:
            message = await self.next_event()
            yield message
            if message.get("id") == request_id and message.get("event") in (event, "failed"):
                return

    async def to_local_monotonic(self, t: float) -> float:
        if self._clock is None:
            await self.state()
        assert self._clock is not None
        return float(self._clock["epoch_monotonic_s"]) + t / 1000.0

    async def _receive(self) -> dict[str, Any]:
        async with asyncio.timeout(self.timeout):
            return _message(await self._connection.recv())


def _message(text: str | bytes) -> dict[str, Any]:
    message = json.loads(text)
    if not isinstance(message, dict):
        raise LiveError(f"not a protocol message: {text!r}")
    return message


def _sort(message: dict[str, Any], request_id: object, events: deque[dict[str, Any]]) -> dict[str, Any] | None:
    """``message`` if it is the reply to ``request_id``; an event is kept in ``events`` (None); else an error."""
    if "event" in message:
        events.append(message)
        return None
    if message.get("id") == request_id:
        return message
    raise LiveError(f"a reply to another request came first: {message}")
