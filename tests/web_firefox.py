"""A real headless Firefox (Debian's ``firefox-esr``) for the web tests, driven over WebDriver BiDi with
``websockets`` — the same few calls as :mod:`tests.web_browser`'s Chromium, so a test can take either.

Firefox listens on 127.0.0.1 (``--remote-debugging-port=0``; the port is read back from
``WebDriverBiDiServer.json`` in its profile). Its own traffic is switched off in the profile's
``user.js`` (updates, telemetry, remote settings, safe browsing, captive-portal and connectivity
checks, DNS over HTTPS), and what is left goes to a proxy on 127.0.0.1 port 9, where nothing
listens — only 127.0.0.1 itself is reached directly. Firefox runs in a session of its own with the
parent-death signal, and :meth:`Firefox.close` kills its whole process group whatever happened.
Headless Firefox makes a WebGL context only with an X display to open its GL on (Mesa's llvmpipe
here): without ``DISPLAY`` it is started under ``xvfb-run`` (a virtual display, in the same group).

    with served(site) as base, Firefox() as firefox:
        page = firefox.open(f"{base}/index.html?t=500", (600, 800))
        picture = page.screenshot((600, 800))

``AP_FIREFOX`` names the program; else ``firefox-esr`` or ``firefox`` on the PATH.
"""

from __future__ import annotations

import base64
import contextlib
import io
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from engine.processes import with_parent_death_signal

FIREFOX = os.environ.get("AP_FIREFOX") or shutil.which("firefox-esr") or shutil.which("firefox")
XVFB_RUN = shutil.which("xvfb-run")
STARTUP_SECONDS = 90.0
REPLY_SECONDS = 60.0
#: Preferences that keep Firefox off the network (and quiet) while a test drives it.
PREFERENCES = {
    "app.update.enabled": False, "app.update.auto": False, "app.normandy.enabled": False,
    "browser.shell.checkDefaultBrowser": False, "browser.startup.page": 0, "browser.startup.homepage": "about:blank",
    "browser.newtabpage.enabled": False, "browser.aboutwelcome.enabled": False,
    "browser.safebrowsing.malware.enabled": False, "browser.safebrowsing.phishing.enabled": False,
    "browser.safebrowsing.downloads.enabled": False, "browser.safebrowsing.blockedURIs.enabled": False,
    "browser.region.network.url": "", "browser.region.update.enabled": False,
    "browser.topsites.contile.enabled": False, "browser.urlbar.suggest.quicksuggest.sponsored": False,
    "datareporting.policy.dataSubmissionEnabled": False, "datareporting.healthreport.uploadEnabled": False,
    "toolkit.telemetry.enabled": False, "toolkit.telemetry.unified": False, "toolkit.telemetry.server": "",
    "services.settings.server": "http://127.0.0.1:9/", "extensions.update.enabled": False,
    "extensions.getAddons.cache.enabled": False, "extensions.blocklist.enabled": False,
    "media.gmp-manager.url": "", "media.gmp-gmpopenh264.enabled": False, "media.autoplay.default": 0,
    "media.autoplay.blocking_policy": 0, "media.volume_scale": "0.0",
    "network.captive-portal-service.enabled": False, "network.connectivity-service.enabled": False,
    "network.trr.mode": 5, "network.dns.disablePrefetch": True, "network.prefetch-next": False,
    "network.http.speculative-parallel-limit": 0, "geo.enabled": False,
    "network.proxy.type": 1, "network.proxy.http": "127.0.0.1", "network.proxy.http_port": 9,
    "network.proxy.ssl": "127.0.0.1", "network.proxy.ssl_port": 9, "network.proxy.no_proxies_on": "127.0.0.1",
    "network.proxy.allow_hijacking_localhost": False,
    "webgl.force-enabled": True, "dom.max_script_run_time": 0,
}


class Firefox:
    """One headless Firefox; use as a context manager."""

    def __init__(self) -> None:
        if FIREFOX is None:
            raise RuntimeError("firefox is not installed")
        self.profile = Path(tempfile.mkdtemp(prefix="ap-firefox-"))
        (self.profile / "user.js").write_text(
            "".join(f"user_pref({json.dumps(k)}, {json.dumps(v)});\n" for k, v in PREFERENCES.items()))
        command = [FIREFOX, "--headless", "--no-remote", "--remote-debugging-port=0", "--profile", str(self.profile),
                   "about:blank"]
        if not os.environ.get("DISPLAY") and XVFB_RUN is not None:
            # headless Firefox draws WebGL only with an X display to open its GL on: a virtual one, in its group
            command = [XVFB_RUN, "-a", "-s", "-screen 0 1920x1200x24 -nolisten tcp", *command]
        command = with_parent_death_signal(command)
        home = {"HOME": str(self.profile), "XDG_CONFIG_HOME": str(self.profile / ".config"),
                "XDG_CACHE_HOME": str(self.profile / ".cache"), "MOZ_CRASHREPORTER_DISABLE": "1"}
        self.process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, start_new_session=True, env={**os.environ, **home})
        self.connection: Any = None
        self._stack = contextlib.ExitStack()
        self._next_id = 0
        self.events: list[dict[str, Any]] = []
        try:
            port = self._bidi_port()
            from websockets.sync.client import connect

            self.connection = self._stack.enter_context(
                connect(f"ws://127.0.0.1:{port}/session", max_size=None, open_timeout=REPLY_SECONDS))
            self.call("session.new", {"capabilities": {}})
            self.call("session.subscribe", {"events": ["log.entryAdded", "network.beforeRequestSent"]})
        except BaseException:
            self.close()
            raise

    def __enter__(self) -> Firefox:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _bidi_port(self) -> int:
        written = self.profile / "WebDriverBiDiServer.json"
        deadline = time.monotonic() + STARTUP_SECONDS
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"firefox ended at start with status {self.process.returncode}")
            with contextlib.suppress(OSError, ValueError, KeyError):
                return int(json.loads(written.read_text())["ws_port"])
            time.sleep(0.1)
        raise RuntimeError("firefox did not open its WebDriver BiDi port")

    def call(self, method: str, params: dict[str, Any]) -> dict[str, Any]:
        """Send one BiDi command and wait for its reply (events meanwhile are kept in :attr:`events`)."""
        self._next_id += 1
        self.connection.send(json.dumps({"id": self._next_id, "method": method, "params": params}))
        deadline = time.monotonic() + REPLY_SECONDS
        while True:
            reply = json.loads(self.connection.recv(timeout=max(deadline - time.monotonic(), 0.01)))
            if reply.get("id") == self._next_id:
                if reply.get("type") == "error":
                    raise RuntimeError(f"{method}: {reply.get('error')}: {reply.get('message')}")
                return dict(reply.get("result", {}))
            if reply.get("type") == "event":
                self.events.append(reply)

    def open(self, url: str, size: tuple[int, int]) -> FirefoxPage:
        """A new tab showing ``url`` with a ``size`` viewport (CSS pixels = device pixels)."""
        context = self.call("browsingContext.create", {"type": "tab"})["context"]
        page = FirefoxPage(self, context)
        page.resize(size)
        self.call("browsingContext.navigate", {"context": context, "url": url, "wait": "complete"})
        return page

    def close(self) -> None:
        """End Firefox (its whole process group) and remove its profile, whatever state it is in."""
        if self.connection is not None and self.process.poll() is None:
            with contextlib.suppress(Exception):
                self.connection.send(json.dumps({"id": -1, "method": "browser.close", "params": {}}))
        with contextlib.suppress(Exception):
            self._stack.close()
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.process.wait(timeout=10)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait()
        shutil.rmtree(self.profile, ignore_errors=True)


class FirefoxPage:
    """One tab: evaluate JavaScript, take screenshots, read what it logged and requested (as tests.web_browser.Page)."""

    def __init__(self, browser: Firefox, context: str) -> None:
        self.browser = browser
        self.context = context

    def resize(self, size: tuple[int, int]) -> None:
        self.browser.call("browsingContext.setViewport", {"context": self.context, "devicePixelRatio": 1,
                                                          "viewport": {"width": size[0], "height": size[1]}})

    def evaluate(self, expression: str, await_promise: bool = True) -> Any:
        """The value of ``expression`` (awaited), through JSON."""
        wrapped = f"Promise.resolve(({expression})).then((v) => JSON.stringify(v === undefined ? null : v))"
        reply = self.browser.call("script.evaluate", {"expression": wrapped, "target": {"context": self.context},
                                                      "awaitPromise": True, "resultOwnership": "none"})
        if reply.get("type") == "exception":
            raise RuntimeError(f"{expression}: {reply['exceptionDetails'].get('text')}")
        return json.loads(reply["result"]["value"])

    def wait_for(self, expression: str, seconds: float = 60.0) -> Any:
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
        """The viewport's top-left ``size`` as RGB pixels (height × width × 3)."""
        from PIL import Image

        shot = self.browser.call("browsingContext.captureScreenshot", {
            "context": self.context, "origin": "viewport",
            "clip": {"type": "box", "x": 0, "y": 0, "width": size[0], "height": size[1]}})
        with Image.open(io.BytesIO(base64.b64decode(shot["data"]))) as image:
            return np.asarray(image.convert("RGB"))

    def _mine(self, method: str) -> list[dict[str, Any]]:
        found = []
        for event in self.browser.events:
            params = event.get("params", {})
            context = params.get("source", {}).get("context", params.get("context"))
            if event.get("method") == method and context == self.context:
                found.append(params)
        return found

    def problems(self) -> list[str]:
        """Console errors and uncaught exceptions, as text."""
        return [f"{e.get('type')} {e.get('level')}: {e.get('text')}" for e in self._mine("log.entryAdded")
                if e.get("level") == "error" or e.get("type") == "javascript"]

    def requested(self) -> list[str]:
        """Every URL the page asked for."""
        return [e["request"]["url"] for e in self._mine("network.beforeRequestSent")]
