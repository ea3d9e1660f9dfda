"""One request of the live protocol, checked: its type, its id, its fields, the limits.

Pure functions, no network: the server calls :func:`parse_request` on every text message and
answers a :class:`RequestError` with ``{"id": ..., "ok": false, "error": str(exc)}``. The
messages are those of ``engine/live/schema/protocol-v1.json`` (``docs/serve.md``).

Errors are one line, ``<message>:LINE: what is wrong`` (the line of the JSON text where the
parser stopped, 1 otherwise), or for the text of a ``say`` the same ``<text>:LINE: column C: …``
the command line gives.

>>> parse_request('{"type": "set", "id": 7, "values": {"jaw_open": 0.5}}')
Request(type='set', id=7, fields={'values': {'jaw_open': 0.5}})
>>> parse_request('{"type": "dance", "id": 1}')   # doctest: +ELLIPSIS
Traceback (most recent call last):
...
engine.live.protocol.RequestError: <message>:1: unknown request type 'dance' (one of: capabilities, command, ...)
>>> parse_request('{"type": ')
Traceback (most recent call last):
...
engine.live.protocol.RequestError: <message>:1: column 10: not JSON: Expecting value
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from typing import Any

from engine.errors import UserError

SCHEMA_VERSION = 1
#: The largest message the server reads as a request (bytes of UTF-8); a longer one is answered with an error.
MAX_MESSAGE_BYTES = 64 * 1024
#: The largest WebSocket frame the server accepts at all: beyond it the connection is closed (code 1009).
MAX_FRAME_BYTES = 1024 * 1024
#: Frames the server holds unread per connection before it stops reading the socket (TCP then holds the client back).
MAX_INCOMING_FRAMES = 4
#: Longest ``say`` text and ``command`` XML, characters.
MAX_TEXT_CHARS = 8000
#: Longest string id.
MAX_ID_CHARS = 128
#: Requests a connection may send per second on average, and in one burst, before they are refused.
RATE_PER_SECOND = 2000.0
RATE_BURST = 2000.0
#: Utterances one connection may have waiting for the synthesizer.
MAX_WAITING_UTTERANCES = 4
#: Clients connected at once; one more gets HTTP 503 in the handshake.
MAX_CLIENTS = 64
#: Sets waiting for their frame, and performances running or waiting, on the head (all clients together).
MAX_SCHEDULED = 10_000
#: Furthest ahead a request may place something (``at``), ms from now.
MAX_AHEAD_MS = 24 * 3600 * 1000.0
#: The message types and the optional/required fields of each (besides ``type`` and ``id``).
REQUEST_FIELDS: dict[str, tuple[frozenset[str], frozenset[str]]] = {
    "capabilities": (frozenset(), frozenset()),
    "command": (frozenset({"xml"}), frozenset({"at"})),
    "load": (frozenset({"model"}), frozenset()),
    "say": (frozenset({"text"}), frozenset({"voice", "at"})),
    "set": (frozenset({"values"}), frozenset({"at"})),
    "state": (frozenset(), frozenset()),
    "stop": (frozenset(), frozenset({"target"})),
}
REQUEST_TYPES = tuple(sorted(REQUEST_FIELDS))
#: The events the server sends (``docs/serve.md``).
EVENT_TYPES = ("applied", "speech_start", "word", "phone", "command_start", "command_apex", "command_end", "finished",
               "failed", "loaded")
#: Longest model name in a ``load`` request.
MAX_MODEL_NAME_CHARS = 1024
MESSAGE_NAME = "<message>"
_VOICE_NAME = re.compile(r"[A-Za-z0-9_]{1,64}\Z")
#: A UTF-16 surrogate on its own (JSON's ``"\\ud800"``): not a character, and no UTF-8 text can hold it.
LONE_SURROGATE = re.compile("[\ud800-\udfff]")

RequestId = str | int | None


class RequestError(UserError):
    """A request the server refuses; ``request_id`` is its id when that could be read (else ``None``)."""

    def __init__(self, message: str, request_id: RequestId = None, file: str | None = MESSAGE_NAME,
                 line: int | None = 1):
        super().__init__(message, file=file, line=line)
        self.request_id = request_id


@dataclass(frozen=True)
class Request:
    """A checked request: ``fields`` holds the type's own fields (``at`` already a float when given)."""

    type: str
    id: RequestId
    fields: dict[str, Any] = field(default_factory=dict)


def parse_request(text: str | bytes) -> Request:
    """The request in one message, or :class:`RequestError` saying what is wrong with it."""
    if isinstance(text, bytes):
        raise RequestError("binary messages are not requests: send JSON text")
    if len(text) > MAX_MESSAGE_BYTES or len(text.encode("utf-8", "surrogatepass")) > MAX_MESSAGE_BYTES:
        raise RequestError(f"the message is longer than {MAX_MESSAGE_BYTES} bytes")
    try:
        data = json.loads(text, parse_constant=_no_constant)
    except json.JSONDecodeError as exc:
        raise RequestError(f"column {exc.colno}: not JSON: {exc.msg}", line=exc.lineno) from None
    except (ValueError, RecursionError) as exc:
        raise RequestError(f"not JSON: {exc}") from None
    if not isinstance(data, dict):
        raise RequestError(f"a request is a JSON object, not {_kind(data)}")
    request_id = check_id(data.get("id"), "id") if "id" in data else None
    refuse_lone_surrogates(data, request_id)
    if "id" not in data:
        raise RequestError("the request has no \"id\" (a string or an integer the reply will carry)")
    kind = data.get("type")
    if not isinstance(kind, str):
        raise RequestError("the request has no \"type\" string", request_id)
    if kind not in REQUEST_FIELDS:
        raise RequestError(f"unknown request type {_shown(kind)} (one of: {', '.join(REQUEST_TYPES)})", request_id)
    required, optional = REQUEST_FIELDS[kind]
    given = set(data) - {"type", "id"}
    missing = sorted(required - given)
    if missing:
        raise RequestError(f"'{kind}' needs \"{missing[0]}\"", request_id)
    unknown = sorted(given - required - optional)
    if unknown:
        allowed = ", ".join(sorted(required | optional)) or "none"
        raise RequestError(f"'{kind}' has no field {_shown(unknown[0])} (its fields: {allowed})", request_id)
    fields = {name: data[name] for name in given}
    if "at" in fields:
        fields["at"] = _time(fields["at"], request_id)
    if kind in ("say", "command"):
        key = "text" if kind == "say" else "xml"
        fields[key] = _text(fields[key], key, request_id)
    if kind == "say" and "voice" in fields:
        voice = fields["voice"]
        if not isinstance(voice, str) or not _VOICE_NAME.match(voice):
            raise RequestError("\"voice\" is a Festival voice name (letters, digits and _, at most 64)", request_id)
    if kind == "set":
        fields["values"] = _values(fields["values"], request_id)
    if kind == "load":
        fields["model"] = model_name(fields["model"], request_id)
    if kind == "stop" and "target" in fields:
        fields["target"] = check_id(fields["target"], "target", request_id)
    return Request(kind, request_id, fields)


def check_id(value: object, what: str, request_id: RequestId = None) -> str | int:
    """An id: a string of at most :data:`MAX_ID_CHARS` characters or an integer that fits in 53 bits."""
    if isinstance(value, str) and len(value) <= MAX_ID_CHARS:
        if LONE_SURROGATE.search(value):
            raise RequestError(f"\"{what}\" {_lone_surrogate(value)}", request_id)
        return value
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) < 2**53:
        return value
    raise RequestError(f"\"{what}\" must be a string (at most {MAX_ID_CHARS} characters) or an integer, "
                       f"not {_kind(value)}", request_id)


def refuse_lone_surrogates(data: dict[str, Any], request_id: RequestId) -> None:
    """Refuse a request with a lone surrogate in any string, field name or nested value (the reply names the field).

    Such a string is valid JSON (``"\\ud800"``) but no text: it cannot be written as UTF-8, so nothing
    downstream (the XML parser, Festival, the reply echoing it) could take it.

    >>> refuse_lone_surrogates({"type": "say", "id": 1, "text": "moi \\ud800"}, 1)   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    engine.live.protocol.RequestError: <message>:1: "text" holds a lone UTF-16 surrogate (U+D800), ...
    """
    for name, value in data.items():
        if LONE_SURROGATE.search(name):
            raise RequestError(f"a field name {_lone_surrogate(name)}", request_id)
        pending = [value]
        while pending:                                   # json.loads has bounded the depth already
            item = pending.pop()
            if isinstance(item, str):
                if LONE_SURROGATE.search(item):
                    raise RequestError(f"\"{name}\" {_lone_surrogate(item)}", request_id)
            elif isinstance(item, dict):
                pending.extend(item.keys())
                pending.extend(item.values())
            elif isinstance(item, list):
                pending.extend(item)


def _lone_surrogate(text: str) -> str:
    found = LONE_SURROGATE.search(text)
    assert found is not None
    return (f"holds a lone UTF-16 surrogate (U+{ord(found.group()):04X}), which is no character: "
            "escape a character outside the BMP as a pair, \\ud83d\\ude00")


def model_name(value: object, request_id: RequestId = None) -> str:
    """A model file named relative to the served folders: ``face.xml``, ``people/anna.xml``; never a way out.

    >>> model_name("people/anna.xml")
    'people/anna.xml'
    >>> model_name("../etc/x.xml")   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    engine.live.protocol.RequestError: <message>:1: "model" is a model file (.xml) named from a served folder: ...
    """
    refusal = ("\"model\" is a model file (.xml) named from a served folder: a relative path with / between "
               "folders, no '..', at most 1024 characters")
    if not isinstance(value, str) or not 0 < len(value) <= MAX_MODEL_NAME_CHARS or not value.endswith(".xml"):
        raise RequestError(refusal, request_id)
    parts = value.split("/")
    if value.startswith("/") or "\\" in value or any(part in ("", ".", "..") for part in parts) \
            or any(ord(c) < 32 or c == ":" for c in value):
        raise RequestError(refusal, request_id)
    return value


def check_values(values: dict[str, float], ranges: dict[str, tuple[float, float]],
                 request_id: RequestId = None) -> None:
    """Every name a parameter of the model, every value inside its range."""
    for name, value in values.items():
        if name not in ranges:
            raise RequestError(f"unknown parameter {_shown(name)}", request_id)
        low, high = ranges[name]
        if not low <= value <= high:
            raise RequestError(f"{name} = {value:g} is outside its range {low:g} … {high:g}", request_id)


def error_reply(exc: RequestError) -> dict[str, Any]:
    """The reply that refuses a request."""
    return {"id": exc.request_id, "ok": False, "error": " ".join(str(exc).split())}


def _values(values: object, request_id: RequestId) -> dict[str, float]:
    if not isinstance(values, dict) or not values:
        raise RequestError("\"values\" must be an object of parameter name → number, with at least one", request_id)
    checked: dict[str, float] = {}
    for name, value in values.items():
        if not _is_number(value):
            raise RequestError(f"the value of {_shown(name)} must be a number, not {_kind(value)}", request_id)
        checked[name] = float(value)
    return checked


def _time(value: object, request_id: RequestId) -> float:
    if not _is_number(value):
        raise RequestError(f"\"at\" must be a time in ms on the server's clock, not {_kind(value)}", request_id)
    return float(value)  # type: ignore[arg-type]


def _text(value: object, what: str, request_id: RequestId) -> str:
    if not isinstance(value, str):
        raise RequestError(f"\"{what}\" must be a string, not {_kind(value)}", request_id)
    if len(value) > MAX_TEXT_CHARS:
        raise RequestError(f"\"{what}\" is longer than {MAX_TEXT_CHARS} characters", request_id)
    return value


def _is_number(value: object) -> bool:
    return (isinstance(value, int | float) and not isinstance(value, bool)
            and abs(value) < 1e300 and math.isfinite(value))


def _no_constant(name: str) -> None:
    raise ValueError(f"{name} is not a JSON number")


def _kind(value: object) -> str:
    names = {dict: "an object", list: "an array", str: "a string", bool: "true/false", type(None): "null",
             int: "a number", float: "a number"}
    return names.get(type(value), type(value).__name__)


def _shown(text: str) -> str:
    text = " ".join(text.split())
    return repr(text if len(text) <= 40 else text[:40] + "…")
