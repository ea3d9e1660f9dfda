#!/usr/bin/env python3
"""Run this study on a lab computer: serve its folder on this computer only, save each participant's data here.

    python3 run-lab.py                    # opens the study in the default browser
    python3 run-lab.py --participant 12   # … for participant 12 (else the first page asks)
    python3 run-lab.py --no-browser       # only serve: open the address it prints

The study is served on 127.0.0.1 (nothing outside this computer can reach it); each participant's data
arrive at the end of the session and are written to data/STUDY_PARTICIPANT.csv beside this file (a
second session of the same participant is saved as …-2.csv, never over the first). Needs only Python 3.8
or later: no toolkit, no network. Stop it with Ctrl-C.
"""

from __future__ import annotations

import argparse
import http.server
import json
import os
import re
import sys
import tempfile
import typing
import urllib.parse
import webbrowser

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
LIMIT = 50 * 1024 * 1024


def study_name() -> str:
    try:
        with open(os.path.join(HERE, "study.json"), encoding="utf-8") as stream:
            return str(json.load(stream)["name"])
    except (OSError, ValueError, KeyError):
        return "study"


def safe(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text)[:64] or "participant"


def save(participant: str, body: bytes) -> str:
    """Write the data to a new file in data/ (never over another), atomically; returns its name."""
    os.makedirs(DATA, exist_ok=True)
    stem = f"{safe(study_name())}_{safe(participant)}"
    handle, temporary = tempfile.mkstemp(prefix=f".{stem}.", suffix=".tmp", dir=DATA)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(body)
            stream.flush()
            os.fsync(stream.fileno())
        number = 1
        while True:
            name = f"{stem}.csv" if number == 1 else f"{stem}-{number}.csv"
            try:
                os.link(temporary, os.path.join(DATA, name))     # fails if the name is taken: nothing overwritten
                break
            except FileExistsError:
                number += 1
    finally:
        os.unlink(temporary)
    return f"data/{name}"


class Handler(http.server.SimpleHTTPRequestHandler):
    def __init__(self, *args: typing.Any, **kwargs: typing.Any) -> None:
        self.extensions_map = {**self.extensions_map, ".js": "text/javascript", ".glb": "model/gltf-binary",
                               ".wav": "audio/wav", ".mp4": "video/mp4", ".json": "application/json"}
        super().__init__(*args, directory=HERE, **kwargs)       # handles the request

    def log_message(self, format: str, *args: typing.Any) -> None:
        pass

    def do_POST(self) -> None:
        url = urllib.parse.urlsplit(self.path)
        if url.path != "/save":
            self._answer(404, {"error": "not found"})
            return
        participant = urllib.parse.parse_qs(url.query).get("participant", [""])[0]
        length = int(self.headers.get("Content-Length") or 0)
        if not participant or not 0 < length <= LIMIT:
            self._answer(400, {"error": "a participant and at most 50 MB of data are needed"})
            return
        body = self.rfile.read(length)
        try:
            name = save(participant, body)
        except OSError as exc:
            self._answer(500, {"error": f"cannot save: {exc.strerror or exc}"})
            return
        print(f"saved {name}", flush=True)
        self._answer(200, {"file": name})

    def _answer(self, status: int, document: dict[str, str]) -> None:
        data = json.dumps(document).encode("utf-8")
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--port", type=int, default=8000, help="the port (0: any free one; default 8000)")
    parser.add_argument("--participant", help="the participant's number or code")
    parser.add_argument("--no-browser", action="store_true", help="do not open a browser")
    args = parser.parse_args()
    server = http.server.ThreadingHTTPServer(("127.0.0.1", args.port), Handler)
    query = {"lab": "1"}
    if args.participant:
        query["participant"] = args.participant
    address = f"http://127.0.0.1:{server.server_address[1]}/index.html?{urllib.parse.urlencode(query)}"
    print(f"serving the study at {address} (Ctrl-C stops)", flush=True)
    if not args.no_browser:
        webbrowser.open(address)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
