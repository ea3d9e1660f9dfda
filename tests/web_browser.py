"""A real headless Chromium for the web-export tests, driven over the DevTools protocol with ``websockets``.

Everything stays on loopback: the site is served by Python's ``http.server`` on 127.0.0.1
(port 0), Chromium (``AP_CHROMIUM``, else ``chromium`` on the PATH) listens for DevTools on
127.0.0.1 (port 0, read back from
``DevToolsActivePort`` in its profile), and the flags below switch off its own traffic
(updates, sync, safe browsing, …). Chromium is started in a session of its own with the
parent-death signal, and :meth:`Browser.close` kills its whole process group whatever happened.

    with served(site) as base, Browser() as browser:
        page = browser.open(f"{base}/index.html?t=500", (600, 800))
        picture = page.screenshot((600, 800))
"""

from __future__ import annotations

import base64
import contextlib
import functools
import http.server
import io
import json
import os
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from engine.processes import with_parent_death_signal

CHROMIUM = os.environ.get("AP_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
STARTUP_SECONDS = 60.0
REPLY_SECONDS = 60.0
FLAGS = [
    "--headless=new", "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0", "--no-first-run",
    "--no-default-browser-check", "--disable-background-networking", "--disable-component-update",
    "--disable-sync", "--disable-default-apps", "--disable-extensions", "--disable-domain-reliability",
    "--disable-client-side-phishing-detection", "--metrics-recording-only", "--no-pings",
    "--disable-features=Translate,OptimizationHints,MediaRouter,DialMediaRouteProvider,InterestFeedContentSuggestions",
    "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--mute-audio",
    "--autoplay-policy=no-user-gesture-required", "--no-sandbox", "--hide-scrollbars",
]


@contextmanager
def served(folder: Path) -> Iterator[str]:
    """Serve ``folder`` on 127.0.0.1 (a free port) in a thread; yields the base URL."""
    handler = functools.partial(_QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map: ClassVar[dict[str, str]] = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                                                ".js": "text/javascript", ".glb": "model/gltf-binary",
                                                ".wav": "audio/wav"}

    def log_message(self, format: str, *args: Any) -> None:
        pass


class Browser:
    """One headless Chromium; use as a context manager."""

    def __init__(self) -> None:
        if CHROMIUM is None:
            raise RuntimeError("chromium is not installed")
        self.profile = Path(tempfile.mkdtemp(prefix="ap-chromium-"))
        command = with_parent_death_signal([CHROMIUM, *FLAGS, f"--user-data-dir={self.profile}", "about:blank"])
        # HOME and the XDG folders in the profile too: the crash database and caches Chromium keeps outside
        # --user-data-dir go there and are removed with it (its crash handler ends when the browser ends)
        home = {"HOME": str(self.profile), "XDG_CONFIG_HOME": str(self.profile / ".config"),
                "XDG_CACHE_HOME": str(self.profile / ".cache")}
        self.process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, start_new_session=True, env={**os.environ, **home})
        self.connection: Any = None
        self._stack = contextlib.ExitStack()
        try:
            port, path = self._devtools_address()
            from websockets.sync.client import connect

            # connect() must be entered as a context manager (websockets 17.1+)
            self.connection = self._stack.enter_context(
                connect(f"ws://127.0.0.1:{port}{path}", max_size=None, open_timeout=REPLY_SECONDS))
        except BaseException:
            self.close()
            raise
        self._next_id = 0
        self.events: list[dict[str, Any]] = []

    def __enter__(self) -> Browser:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _devtools_address(self) -> tuple[int, str]:
        active = self.profile / "DevToolsActivePort"
        deadline = time.monotonic() + STARTUP_SECONDS
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"chromium ended at start with status {self.process.returncode}")
            lines = active.read_text().split("\n") if active.exists() else []
            if len(lines) >= 2 and lines[0].strip() and lines[1].strip():
                return int(lines[0]), lines[1].strip()
            time.sleep(0.05)
        raise RuntimeError("chromium did not open its DevTools port")

    def call(self, method: str, params: dict[str, Any] | None = None, session: str | None = None) -> dict[str, Any]:
        """Send one DevTools command and wait for its reply (events meanwhile are kept in :attr:`events`)."""
        self._next_id += 1
        message: dict[str, Any] = {"id": self._next_id, "method": method, "params": params or {}}
        if session is not None:
            message["sessionId"] = session
        self.connection.send(json.dumps(message))
        deadline = time.monotonic() + REPLY_SECONDS
        while True:
            reply = json.loads(self.connection.recv(timeout=max(deadline - time.monotonic(), 0.01)))
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return dict(reply.get("result", {}))
            self.events.append(reply)

    def open(self, url: str, size: tuple[int, int]) -> Page:
        """A new tab showing ``url`` at ``size`` (CSS pixels = device pixels), its events recorded from the start."""
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Runtime", "Log", "Network", "Page"):
            self.call(f"{domain}.enable", {}, session)
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": False}, session)
        page = Page(self, session)
        self.call("Page.navigate", {"url": url}, session)
        return page

    def resize(self, page: Page, size: tuple[int, int]) -> None:
        """Make ``page``'s window ``size`` (CSS pixels = device pixels), as a user resizing it would."""
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": False}, page.session)

    def close(self) -> None:
        """End Chromium (its whole process group) and remove its profile, whatever state it is in.

        Chromium is asked to quit first (so it reaps its own helpers), then the group is killed."""
        if self.connection is not None and self.process.poll() is None:
            with contextlib.suppress(Exception):           # a browser that no longer answers
                self.connection.send(json.dumps({"id": -1, "method": "Browser.close"}))
        with contextlib.suppress(Exception):               # a connection Chromium already broke
            self._stack.close()
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.wait(timeout=10)
        with contextlib.suppress(ProcessLookupError):      # helpers left behind, if any
            os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait()
        shutil.rmtree(self.profile, ignore_errors=True)


def live_processes(group: int) -> list[int]:
    """The processes of a process group that still run (not zombies waiting for a parent to reap them)."""
    alive = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        with contextlib.suppress(OSError, ValueError, IndexError):
            fields = stat.read_text().rsplit(")", 1)[1].split()
            if int(fields[2]) == group and fields[0] != "Z":
                alive.append(int(stat.parent.name))
    return alive


class Page:
    """One tab: evaluate JavaScript, take screenshots, read what it logged and requested."""

    def __init__(self, browser: Browser, session: str) -> None:
        self.browser = browser
        self.session = session

    def resize(self, size: tuple[int, int]) -> None:
        self.browser.resize(self, size)

    def evaluate(self, expression: str, await_promise: bool = True) -> Any:
        result = self.browser.call("Runtime.evaluate", {"expression": expression, "awaitPromise": await_promise,
                                                        "returnByValue": True}, self.session)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def wait_for(self, expression: str, seconds: float = 60.0) -> Any:
        """Evaluate ``expression`` until it is truthy (a generous limit: the machine may be busy)."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(0.05)
        raise TimeoutError(f"{expression} stayed false for {seconds:g} s; problems: {self.problems()}")

    def ready(self) -> None:
        """Wait until the player has loaded and drawn two frames since."""
        self.wait_for("typeof window.ArtificialPerson === 'object'")
        self.evaluate("ArtificialPerson.whenReady().then(() => ArtificialPerson.nextFrame())"
                      ".then(() => ArtificialPerson.nextFrame())")

    def screenshot(self, size: tuple[int, int]) -> np.ndarray:
        """The page's top-left ``size`` as RGB pixels (height × width × 3)."""
        from PIL import Image

        shot = self.browser.call("Page.captureScreenshot", {
            "format": "png", "clip": {"x": 0, "y": 0, "width": size[0], "height": size[1], "scale": 1}}, self.session)
        with Image.open(io.BytesIO(base64.b64decode(shot["data"]))) as image:
            return np.asarray(image.convert("RGB"))

    def mine(self, method: str) -> list[dict[str, Any]]:
        return [e["params"] for e in self.browser.events if e.get("method") == method
                and e.get("sessionId") == self.session]

    def problems(self) -> list[str]:
        """Console errors, uncaught exceptions and error log entries, as text."""
        found = [f"console.{e['type']}: {[a.get('value', a.get('description')) for a in e['args']]}"
                 for e in self.mine("Runtime.consoleAPICalled") if e["type"] in ("error", "assert")]
        found += [f"exception: {e['exceptionDetails'].get('exception', {}).get('description', e['exceptionDetails'])}"
                  for e in self.mine("Runtime.exceptionThrown")]
        found += [f"log {e['entry']['source']}: {e['entry']['text']} {e['entry'].get('url', '')}"
                  for e in self.mine("Log.entryAdded") if e["entry"]["level"] == "error"]
        return found

    def requested(self) -> list[str]:
        """Every URL the page asked for."""
        return [e["request"]["url"] for e in self.mine("Network.requestWillBeSent")]


def outside(urls: list[str], base: str, local: Callable[[str], bool] | None = None) -> list[str]:
    """The URLs not under ``base`` (``data:`` URLs and the page's own ``blob:`` URLs — the glTF loader's embedded
    images — which travel nowhere, count as inside)."""
    inside = (base + "/", "data:", f"blob:{base}/")
    return [u for u in urls if not (u.startswith(inside) or (local is not None and local(u)))]
