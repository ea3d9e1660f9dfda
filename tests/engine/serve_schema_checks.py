"""Every live message the serve tests send through the client, and every one they receive, checked against the schema.

The schema is the shipped ``engine/live/schema/protocol-v1.json``. The check sits where the
client turns requests into text and text into messages (its module's ``json``), so it covers
both clients and every test, whatever it asks; messages a test sends malformed on purpose go
through ``send_raw`` with text it made itself and are not checked (their replies are).

Use in a test module::

    from tests.engine.serve_schema_checks import schema_checked  # noqa: F401  (the fixture)
    pytestmark = pytest.mark.usefixtures("schema_checked")
"""

from __future__ import annotations

import importlib.resources
import json
from typing import Any

import jsonschema
import pytest

SCHEMA = json.loads((importlib.resources.files("engine.live") / "schema/protocol-v1.json").read_text("utf-8"))
MESSAGE = jsonschema.Draft202012Validator(SCHEMA)
REQUEST = jsonschema.Draft202012Validator({**SCHEMA, "oneOf": [{"$ref": "#/$defs/request"}]})
SERVER_MESSAGE = jsonschema.Draft202012Validator(
    {**SCHEMA, "oneOf": [{"$ref": "#/$defs/reply"}, {"$ref": "#/$defs/event"}]})
COUNTS = {"requests": 0, "received": 0}


def check_request(request: dict[str, Any]) -> None:
    """A request as the schema describes it (AssertionError naming what is wrong)."""
    errors = sorted(REQUEST.iter_errors(request), key=str)
    assert not errors, f"request {request!r} breaks the schema: {errors[0].message}"
    COUNTS["requests"] += 1


def check_server_message(message: dict[str, Any]) -> None:
    """A reply or an event as the schema describes it."""
    errors = sorted(SERVER_MESSAGE.iter_errors(message), key=str)
    assert not errors, f"the server sent {message!r}, which breaks the schema: {errors[0].message}"
    COUNTS["received"] += 1


class CheckedJson:
    """``json`` for the client module: ``dumps`` checks a request, ``loads`` a reply or an event."""

    JSONDecodeError = json.JSONDecodeError

    @staticmethod
    def dumps(value: Any, **options: Any) -> str:
        if isinstance(value, dict) and "type" in value:
            check_request(value)
        return json.dumps(value, **options)

    @staticmethod
    def loads(text: str | bytes, **options: Any) -> Any:
        value = json.loads(text, **options)
        if isinstance(value, dict):
            check_server_message(value)
        return value


@pytest.fixture
def schema_checked(monkeypatch: pytest.MonkeyPatch) -> dict[str, int]:
    import engine.live.client

    monkeypatch.setattr(engine.live.client, "json", CheckedJson)
    return COUNTS
