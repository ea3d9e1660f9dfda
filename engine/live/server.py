"""The live service: a frame clock at 60 Hz and a WebSocket server speaking the JSON protocol.

One asyncio loop runs both. The frame clock is ``time.monotonic()``: frame ``n`` has the time
``t = n · 1000 / fps`` ms and is due at ``epoch + n / fps`` seconds of ``time.monotonic()``;
every frame advances the :class:`~engine.live.head.LiveHead`, and the events of that frame go to
the connections they belong to, stamped with ``t``. When the loop falls behind it goes straight to
the frame now due (no frame time is ever in the future). Festival runs in a worker thread, one
utterance at a time, so frames keep coming while it synthesizes.

Each connection's requests are answered in the order they came, one reply each; events and
replies of a connection leave in the order they were made.

>>> from engine import load_model
>>> server = LiveServer(load_model(), host="127.0.0.1", port=0)
>>> asyncio.run(server.run(ready=print))                  # doctest: +SKIP
serving ws://127.0.0.1:43817 headless 60 Hz
"""

from __future__ import annotations

import asyncio
import hmac
import math
import signal
import sys
import time
import traceback
from collections.abc import Callable, Sequence
from contextlib import suppress
from dataclasses import replace
from http import HTTPStatus
from pathlib import Path
from typing import Any

from websockets.asyncio.server import ServerConnection, serve
from websockets.exceptions import ConnectionClosed
from websockets.http11 import Request as HttpRequest
from websockets.http11 import Response as HttpResponse

from engine.commands import Library, load_library, parse_commands_text, translate
from engine.commands.command_files import Activation, HighLevelCommand
from engine.errors import UserError
from engine.live.connection import Client, release_freed_memory
from engine.live.head import Event, LiveHead
from engine.live.lsl import STREAM_NAME, MarkerOutlet, lsl_source_id
from engine.live.presentation import PresentationStamps, Presenter, Sound, SoundKey, stopped_sounds
from engine.live.protocol import (
    EVENT_TYPES,
    MAX_AHEAD_MS,
    MAX_CLIENTS,
    MAX_FRAME_BYTES,
    MAX_INCOMING_FRAMES,
    MAX_MESSAGE_BYTES,
    MAX_SCHEDULED,
    MAX_TEXT_CHARS,
    MAX_WAITING_UTTERANCES,
    RATE_PER_SECOND,
    REQUEST_TYPES,
    SCHEMA_VERSION,
    Request,
    RequestError,
    RequestId,
    check_values,
    error_reply,
    parse_request,
)
from engine.live.served_models import ServedFolders
from engine.model.model import Model
from engine.speech.synthesis import Synthesizer

FPS = 60.0
TOKEN_HEADER = "Authorization"


class LiveServer:
    """The head of ``model`` served on ``host:port`` (port 0: any free port): headless, or shown by ``presenter``
    (a window, :mod:`engine.live.presentation`; the frame clock then runs at its refresh rate)."""

    def __init__(self, model: Model, host: str = "127.0.0.1", port: int = 8765, token: str | None = None,
                 library: Library | None = None, synthesizer: Synthesizer | None = None, fps: float = FPS,
                 lsl: bool = False, model_folders: Sequence[str | Path] = (), model_name: str = "",
                 model_reader: Callable[[str], Model] | None = None, presenter: Presenter | None = None):
        self.model = model
        self.presenter = presenter
        self._stamps = PresentationStamps()
        self._loop: asyncio.AbstractEventLoop | None = None
        if model_reader is None:
            from engine.formats.model_files import load_model

            model_reader = load_model
        #: Reads a model file for ``load``; any failure it reports as a :class:`UserError` reaches the client.
        self.model_reader = model_reader
        self.model_name = model_name
        #: The folders a ``load`` request may name a model file in (resolved; nothing outside them is read).
        self.served = ServedFolders(model_folders)
        self._loading: asyncio.Lock | None = None
        self._announcements: list[tuple[Client, Event]] = []
        self.lsl = lsl
        self.markers: MarkerOutlet | None = None
        self.host = host
        self.port = port
        self.token = token
        self.library = load_library() if library is None else library
        if synthesizer is None:
            from engine.speech.festival import FestivalSynthesizer

            synthesizer = FestivalSynthesizer()
        self.synthesizer = synthesizer
        self.fps = float(presenter.fps if presenter is not None else fps)
        self.head = LiveHead(model)
        self.epoch = time.monotonic()
        self.epoch_unix = time.time()
        self.frame = 0
        self._synthesis_lock: asyncio.Lock | None = None
        self._voices: list[str] | None = None
        self._stopping: asyncio.Event | None = None
        self._tasks: set[asyncio.Future[None]] = set()
        self._clients: set[Client] = set()

    # -- running -----------------------------------------------------------------------

    async def run(self, ready: Callable[[str], None] | None = None) -> None:
        """Serve until SIGINT/SIGTERM (or :meth:`close`); ``ready`` gets the line naming the bound address."""
        self._synthesis_lock = asyncio.Lock()
        self._loading = asyncio.Lock()
        self._stopping = asyncio.Event()
        self._loop = asyncio.get_running_loop()
        await asyncio.to_thread(self.voices)                   # Festival asked once, before any client waits
        loop = asyncio.get_running_loop()
        for signum in (signal.SIGINT, signal.SIGTERM):
            with suppress(NotImplementedError, RuntimeError):
                loop.add_signal_handler(signum, self._stopping.set)
        try:
            listening = await serve(self._serve_client, self.host, self.port, max_size=MAX_FRAME_BYTES,
                                    max_queue=MAX_INCOMING_FRAMES, process_request=self._check_handshake,
                                    origins=[None], server_header=None, ping_interval=20, ping_timeout=20)
        except OSError as exc:                   # a name that does not resolve, an address not ours, a port taken
            raise UserError(f"cannot listen on {self.host} port {self.port}: {exc.strerror or exc}") from None
        async with listening as server:
            host, port = server.sockets[0].getsockname()[:2]
            shown = f"[{host}]" if ":" in host else host
            self.epoch = time.monotonic()
            self.epoch_unix = time.time()
            line = f"serving ws://{shown}:{port} {self.mode} {self.fps:g} Hz"
            if self.lsl:
                source_id = lsl_source_id(shown, port)
                self.markers = MarkerOutlet(source_id, self.epoch)
                line += f", LSL markers {STREAM_NAME} {source_id}"
            if ready is not None:
                ready(line)
            clock = asyncio.ensure_future(self._frame_loop())
            await self._stopping.wait()
            clock.cancel()
            with suppress(asyncio.CancelledError):
                await clock

    def close(self) -> None:
        """End :meth:`run` (from the server's own thread; from another, :meth:`close_soon`)."""
        if self._stopping is not None:
            self._stopping.set()

    def close_soon(self) -> None:
        """End :meth:`run`, called from any thread (a window being closed)."""
        loop = self._loop
        if loop is not None and not loop.is_closed():
            with suppress(RuntimeError):                       # the loop has just ended
                loop.call_soon_threadsafe(self.close)

    @property
    def mode(self) -> str:
        return "headless" if self.presenter is None else "window"

    def presented(self, frame: int, swap_s: float, audio: dict[SoundKey, float | None]) -> None:
        """Frame ``frame`` was on the screen at ``swap_s`` (``time.monotonic()``), and the sounds in ``audio``
        started reaching the output at the moment given (or are silent: ``None``). Any thread may call it."""
        loop = self._loop
        if loop is not None and not loop.is_closed():
            with suppress(RuntimeError):
                loop.call_soon_threadsafe(self._on_presented, frame, swap_s, audio)

    def _on_presented(self, frame: int, swap_s: float, audio: dict[SoundKey, float | None]) -> None:
        def ms(seconds: float) -> float:
            return round((seconds - self.epoch) * 1000.0, 3)

        self._deliver(self._stamps.presented(frame, ms(swap_s), {key: None if at is None else ms(at)
                                                                   for key, at in audio.items()}))

    def frame_time(self, frame: int) -> float:
        """Frame ``frame``'s time, ms on the frame clock."""
        return frame * 1000.0 / self.fps

    def next_frame_time(self, at: float | None = None) -> float:
        """The time of the first frame still to come that is at or after ``at``."""
        first = self.frame + 1
        if at is not None:
            first = max(first, math.ceil(at * self.fps / 1000.0 - 1e-9))
        return self.frame_time(first)

    async def _frame_loop(self) -> None:
        while True:
            due = self.epoch + (self.frame + 1) / self.fps
            wait = due - time.monotonic()
            if wait > 0:
                await asyncio.sleep(wait)
            now_frame = math.floor((time.monotonic() - self.epoch) * self.fps + 1e-9)
            self.frame = max(self.frame + 1, now_frame)
            try:
                t = self.frame_time(self.frame)
                announced, self._announcements = self._announcements, []
                events = [(owner, {**event, "t": t}) for owner, event in announced] + self.head.advance(t)
                if self.presenter is None:
                    self._deliver(events)
                else:                                     # they leave when the frame is on the screen
                    self._stamps.hold(self.frame, events)
                    self.presenter.show(self.frame, t, self.model, self.head.current)
            except Exception:                             # a bug of ours: said, and the clock keeps going
                print(f"internal error in frame {self.frame}:\n{traceback.format_exc()}", file=sys.stderr, flush=True)
                self._deliver(self.head.stop())

    def _push_marker(self, event: dict[str, Any], text: str) -> None:
        assert self.markers is not None
        try:
            self.markers.push(event, text)
        except Exception:                                 # a bug of ours or liblsl's: said, the clients served on
            print(f"internal error pushing an LSL marker:\n{traceback.format_exc()}", file=sys.stderr, flush=True)

    def _deliver(self, events: list[tuple[object, Event]]) -> None:
        """Send each event to its client; one that no frame shows (a stop's ``finished``) has presented_t = t."""
        if self.presenter is not None:
            for key in stopped_sounds(events):
                self.presenter.silence(key)
        for owner, event in events:
            if isinstance(owner, Client):
                owner.send(event if "presented_t" in event else {**event, "presented_t": event["t"]})

    # -- connections ---------------------------------------------------------------------

    async def _check_handshake(self, connection: ServerConnection, request: HttpRequest) -> HttpResponse | None:
        """The handshake's refusals: too many clients (503), a missing, wrong or doubled token (401, 400).

        A client that sent bytes after its handshake request that are no WebSocket frame has had its stream
        ended by websockets already, which (17.x) then fails on an assertion, with a traceback in the log, when
        it sends the response: such a connection is closed without one.
        """
        if connection.protocol.eof_sent:
            connection.transport.abort()
            await connection.wait_closed()                # closed: websockets sends nothing more
            return None
        return self._check_token(connection, request)

    def _check_token(self, connection: ServerConnection, request: HttpRequest) -> HttpResponse | None:
        if len(self._clients) >= MAX_CLIENTS:
            return connection.respond(HTTPStatus.SERVICE_UNAVAILABLE, f"at most {MAX_CLIENTS} clients at a time\n")
        if self.token is None:
            return None
        given_all = request.headers.get_all(TOKEN_HEADER)
        if len(given_all) > 1:                            # which one counts would be a guess: neither does
            return connection.respond(HTTPStatus.BAD_REQUEST, f"one {TOKEN_HEADER} header, not {len(given_all)}\n")
        given = given_all[0] if given_all else ""
        expected = f"Bearer {self.token}"
        if hmac.compare_digest(given.encode("utf-8", "replace"), expected.encode("utf-8")):
            return None
        return connection.respond(HTTPStatus.UNAUTHORIZED, "a token is required: Authorization: Bearer TOKEN\n")

    async def _serve_client(self, connection: ServerConnection) -> None:
        client = Client(connection, self._push_marker if self.markers is not None else None, self._forget)
        self._clients.add(client)
        writer = asyncio.ensure_future(client.write())
        try:
            async for message in connection:
                client.send(await self._answer(client, message))
                await client.room_for_replies()                 # one that does not read is not read either
        except ConnectionClosed:
            pass
        finally:
            client.closed = True
            self._clients.discard(client)
            self._forget(client)
            client.discard_outbox()                             # its memory goes with it
            client.end_writer()
            with suppress(asyncio.CancelledError, ConnectionClosed):
                await writer
            if client.held_much:
                release_freed_memory()                          # and back to the system, not only to the heap

    def _forget(self, client: Client) -> None:
        """A client gone, or being disconnected: its performances end, its sets and utterances do not happen."""
        client.cancelled.update(client.waiting_utterances)
        self._deliver(self.head.forget(client))                # to no one: the client is gone (sounds end)

    async def _answer(self, client: Client, message: str | bytes) -> dict[str, Any]:
        request_id: RequestId = None
        try:
            over_rate = not client.within_rate()
            try:
                request = parse_request(message)
            except RequestError as exc:
                if over_rate:                           # the same refusal, whatever else is wrong
                    exc = RequestError(f"too many requests: at most {RATE_PER_SECOND:g} a second", exc.request_id)
                raise exc from None
            if over_rate:
                raise RequestError(f"too many requests: at most {RATE_PER_SECOND:g} a second", request.id)
            request_id = request.id
            if request.type == "load":
                return await self._load(client, request)
            return self._handle(client, request)
        except RequestError as exc:
            return error_reply(exc)
        except UserError as exc:                        # from the engine: located in the text, XML or library
            where = {"file": None, "line": None} if exc.file is not None else {}
            return error_reply(RequestError(str(exc), request_id, **where))
        except Exception:                               # a bug of ours: said on stderr, the client told
            print(f"internal error answering a request:\n{traceback.format_exc()}", file=sys.stderr, flush=True)
            return {"id": request_id, "ok": False, "error": "internal error in the server (see its log)"}

    def _handle(self, client: Client, request: Request) -> dict[str, Any]:
        fields = request.fields
        reply: dict[str, Any] = {"id": request.id, "ok": True}
        if request.type in ("set", "say", "command") and (len(self.head.pending_sets) >= MAX_SCHEDULED
                                                         or len(self.head.performances) >= MAX_SCHEDULED):
            raise RequestError(f"{MAX_SCHEDULED} changes or performances are already waiting on the head; "
                               "stop some first", request.id)
        if request.type == "set":
            check_values(fields["values"], self.head.ranges, request.id)
            at = self._start(fields.get("at"), request.id)
            self.head.add_set(at, request.id, client, fields["values"])
            reply["t"] = at
        elif request.type == "say":
            self._accept_say(client, request, reply)
        elif request.type == "command":
            activations = self._commands(fields["xml"])
            at = self._start(fields.get("at"), request.id)
            performance = self.head.add_commands(at, request.id, client, activations)
            reply.update(t=at, end_t=performance.end_t)
        elif request.type == "stop":
            target = fields.get("target")
            if target is None:
                client.cancelled.update(client.waiting_utterances)
            elif target in client.waiting_utterances:
                client.cancelled.add(target)
            self._deliver(self.head.stop(target))
        elif request.type == "state":
            reply.update(self.state())
        elif request.type == "capabilities":
            reply.update(self.capabilities())
        return reply

    def _start(self, at: float | None, request_id: RequestId) -> float:
        if at is not None and at > self.head.t + MAX_AHEAD_MS:
            raise RequestError("\"at\" is more than 24 hours ahead", request_id)
        return self.next_frame_time(at)

    def _commands(self, xml: str) -> list[Activation]:
        commands = [replace(c, arguments={"at": 0.0, **c.arguments}) if isinstance(c, HighLevelCommand) else c
                    for c in parse_commands_text(xml, "<command>")]       # no "at": at the request's start
        activations = translate(commands, self.library, self.model)
        from engine.timeline.timeline import Timeline

        Timeline(activations, self.model)                       # the same checks as every timeline
        return activations

    # -- say -------------------------------------------------------------------------------

    def _accept_say(self, client: Client, request: Request, reply: dict[str, Any]) -> None:
        from engine.script.inline_commands import parse_script
        from engine.speech.festival import prepare_text
        from engine.speech.say import check_commands

        if len(client.waiting_utterances) >= MAX_WAITING_UTTERANCES:
            raise RequestError(f"{MAX_WAITING_UTTERANCES} utterances are already waiting for the synthesizer",
                               request.id)
        if request.id in client.waiting_utterances:
            raise RequestError("an utterance with this id is still waiting for the synthesizer", request.id)
        text = request.fields["text"]
        script = parse_script(text, "<text>")
        if not script.text.strip():
            raise RequestError("there is no text to speak (only commands?)", request.id, file="<text>", line=1)
        prepare_text(text, "<text>")
        check_commands(script, self.library, self.model)
        at = self._start(request.fields.get("at"), request.id)
        client.waiting_utterances.add(request.id)
        task = asyncio.ensure_future(self._say(client, request, at))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    async def _say(self, client: Client, request: Request, at: float) -> None:
        from engine.speech.festival import SynthesisCancelled
        from engine.speech.say import speak

        assert self._synthesis_lock is not None
        try:
            async with self._synthesis_lock:
                if request.id in client.cancelled or client.closed:
                    return
                if hasattr(self.synthesizer, "cancelled"):       # Festival is stopped when its client is gone
                    self.synthesizer.cancelled = lambda: client.closed or request.id in client.cancelled
                model = self.model
                speech = await asyncio.to_thread(speak, request.fields["text"], model, self.synthesizer,
                                                 request.fields.get("voice"), self.library)
        except SynthesisCancelled:
            if not client.closed:
                client.cancelled.discard(request.id)
                client.send({"event": "finished", "id": request.id, "t": self.head.t, "stopped": True})
            return
        except UserError as exc:
            client.send({"event": "failed", "id": request.id, "t": self.head.t, "error": " ".join(str(exc).split())})
            return
        except Exception:
            print(f"internal error in say:\n{traceback.format_exc()}", file=sys.stderr, flush=True)
            client.send({"event": "failed", "id": request.id, "t": self.head.t,
                         "error": "internal error in the server (see its log)"})
            return
        finally:
            client.waiting_utterances.discard(request.id)
        if request.id in client.cancelled:
            client.cancelled.discard(request.id)
            client.send({"event": "finished", "id": request.id, "t": self.head.t, "stopped": True})
            return
        if client.closed:
            return
        if model is not self.model:
            client.send({"event": "failed", "id": request.id, "t": self.head.t,
                         "error": "another model was loaded while Festival synthesized this utterance; say it again"})
            return
        performance = self.head.add_speech(self.next_frame_time(at), request.id, client, speech)
        if self.presenter is not None:
            self.presenter.play(Sound((id(client), request.id), speech.utterance.samples,
                                      speech.utterance.sample_rate, performance.start_t))

    # -- load ----------------------------------------------------------------------------------

    async def _load(self, client: Client, request: Request) -> dict[str, Any]:
        """Read another model file from a served folder; it replaces the head from the next frame."""
        name = request.fields["model"]
        path = self.served.model_path(name, request.id)
        assert self._loading is not None
        async with self._loading:
            try:
                model = await asyncio.to_thread(self._read_served_model, path)
            except UserError as exc:
                shown = name if exc.file is None or Path(exc.file).resolve() == path else Path(exc.file).name
                raise RequestError(exc.message, request.id, file=shown, line=exc.line) from None
            self._deliver(self.head.stop())                     # every performance ends; pending sets are dropped
            for other in self._clients:
                other.cancelled.update(other.waiting_utterances)
            head = LiveHead(model)
            head.t = self.head.t
            self.model, self.head, self.model_name = model, head, name
            self._announcements.append((client, {"event": "loaded", "id": request.id, "model": name}))
            return {"id": request.id, "ok": True, "t": self.next_frame_time(), "model": name,
                    "parameter_count": len(head.names)}

    def _read_served_model(self, path: Path) -> Model:
        """The model at ``path``, once every file it names is known to lie in the served folders (in a worker)."""
        self.served.check_named_files(path)
        return self.model_reader(str(path))

    # -- state and capabilities ------------------------------------------------------------------

    def clock(self) -> dict[str, Any]:
        """The frame clock: frame n is at t = n·1000/fps ms = epoch_monotonic_s + t/1000 on ``time.monotonic()``."""
        return {"fps": self.fps, "epoch_monotonic_s": self.epoch, "epoch_unix_s": self.epoch_unix}

    def state(self) -> dict[str, Any]:
        return {"t": self.head.t, "frame": self.frame, "model": self.model_name, "values": self.head.values,
                "playing": self.head.playing(),
                "clock": self.clock()}

    def capabilities(self) -> dict[str, Any]:
        tree = self.model.parameters
        parameters = [{"name": name, "min": tree[name].minimum, "max": tree[name].maximum,
                       "default": tree[name].default} for name in self.head.names]
        return {"schema_version": SCHEMA_VERSION, "mode": self.mode, "model": self.model_name,
                "requests": list(REQUEST_TYPES),
                "events": list(EVENT_TYPES), "parameters": parameters, "voices": self.voices(),
                "commands": sorted(self.library.names()), "clock": self.clock(),
                "limits": {"message_bytes": MAX_MESSAGE_BYTES, "frame_bytes": MAX_FRAME_BYTES,
                           "text_chars": MAX_TEXT_CHARS, "requests_per_second": RATE_PER_SECOND,
                           "waiting_utterances": MAX_WAITING_UTTERANCES, "clients": MAX_CLIENTS,
                           "scheduled": MAX_SCHEDULED}}

    def voices(self) -> list[str]:
        if self._voices is None:
            lister = getattr(self.synthesizer, "voices", None)
            try:
                self._voices = list(lister()) if callable(lister) else []
            except UserError:
                self._voices = []
        return list(self._voices)
