"""The live animator: the head driven over WebSocket/JSON (``artificial-person serve``, issue 21).

The parts, each usable on its own:

* :mod:`engine.live.protocol` checks one request (pure, no network): the types, their fields, the limits;
* :mod:`engine.live.head` is the headless animator: parameter values, performances (utterances, commands)
  placed on the frame clock, and the events each frame brings;
* :mod:`engine.live.server` runs the frame clock and the WebSocket server (``websockets``, imported there);
  :mod:`engine.live.connection` is one client's outbox (bounded, its one encoder of replies and events),
  :mod:`engine.live.served_models` the folders a ``load`` reads from and the one check that keeps it there;
* :mod:`engine.live.client` is a blocking and an asyncio Python client;
* :mod:`engine.live.lsl` is ``serve --lsl``'s marker outlet (``pylsl``, imported when it opens) and its
  loopback-only liblsl configuration.

The protocol, its clock and its safety rules are in ``docs/serve.md``; the JSON Schema of every
message ships as ``engine/live/schema/protocol-v1.json``. Importing this package imports no
network library.

>>> from engine.live.protocol import SCHEMA_VERSION
>>> SCHEMA_VERSION
1
"""
