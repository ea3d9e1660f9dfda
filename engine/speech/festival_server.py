"""Festival on another computer: synthesis through a Festival server (``festival --server``).

Festival's server mode reads Scheme expressions from a TCP connection (port 1314 by default;
it forks one Festival per client) and answers each with messages of three bytes and a body:
``LP\\n`` + the printed value of the expression, ``WV\\n`` + a wave file, each body ended by the
key ``ft_StUfF_key`` (an occurrence of the key inside a body is sent with an ``X`` before its
last letter), ``ER\\n`` for an error and ``OK\\n`` once the expression is done.

:class:`FestivalServerSynthesizer` sends the very script the local :class:`FestivalSynthesizer`
runs (:func:`engine.speech.festival_script.synthesis_script`, the same text preparation and the
same parsing of what it prints), inside one ``begin`` whose prelude turns what the script prints
on standard output into the expression's value and what it saves as ``utterance-N.wav`` into
``WV`` messages. The phones, words and waves are therefore Festival's own, as with a local
Festival of the same version and voices, and lip-sync is identical.

>>> festival_address("speech-lab.example.org:1314")
('speech-lab.example.org', 1314)
>>> festival_address("[::1]:1314")
('::1', 1314)
>>> festival_address("localhost")
Traceback (most recent call last):
...
engine.speech.synthesis.SynthesisError: --festival 'localhost' is not HOST:PORT (e.g. 127.0.0.1:1314)
>>> unstuffed(b"a ft_StUfF_keXy b")
b'a ft_StUfF_key b'
"""

from __future__ import annotations

import re
import socket
import time
from collections.abc import Callable

from engine.speech.festival import FestivalSynthesizer, SynthesisCancelled
from engine.speech.festival_script import WAVE_FILE_PATTERN
from engine.speech.synthesis import SynthesisError, Utterance

__all__ = ["DEFAULT_PORT", "FestivalServerSynthesizer", "festival_address", "festival_synthesizer", "unstuffed"]

DEFAULT_PORT = 1314
"""Festival's own default ``server_port``."""

FILE_STUFF_KEY = b"ft_StUfF_key"
"""Festival's end-of-body key (``festival/src/arch/festival/server.cc``, and its C client)."""

_STUFFED_KEY = FILE_STUFF_KEY[:-1] + b"X" + FILE_STUFF_KEY[-1:]
MAX_REPLY_BYTES = 256 * 1024 * 1024
"""The most a server's answer to one text may hold (waves and output together); more is refused."""
_POLL_SECONDS = 0.1
_CONNECT_SECONDS = 10.0

# What the script prints with (format t …) is collected instead and returned as the value of the whole
# expression; what it saves with utt.save.wave is sent to the client, one WV message per utterance, in order.
_PRELUDE = """\
(set! ap_parts nil)
(set! ap_real_format format)
(set! format
  (lambda args
    (if (eq? (car args) t)
      (begin (set! ap_parts (cons (apply ap_real_format (cons nil (cdr args))) ap_parts)) nil)
      (apply ap_real_format args))))
(Parameter.set 'Wavefiletype 'riff)
(set! utt.save.wave (lambda (utt name type) (utt.send.wave.client utt)))
"""
_RESULT = "(apply string-append (reverse ap_parts))"


def festival_address(text: str) -> tuple[str, int]:
    """``HOST:PORT`` (``[IPv6]:PORT`` for an IPv6 address) → (host, port); :class:`SynthesisError` otherwise."""
    match = re.fullmatch(r"\[([0-9A-Fa-f:.]+)\]:(\d{1,5})|([A-Za-z0-9][A-Za-z0-9.-]*):(\d{1,5})", text.strip())
    port = int(match.group(2) or match.group(4)) if match else 0
    if match is None or not 1 <= port <= 65535:
        raise SynthesisError(f"--festival {text!r} is not HOST:PORT (e.g. 127.0.0.1:{DEFAULT_PORT})")
    return (match.group(1) or match.group(3)), port


def festival_synthesizer(address: str | None) -> FestivalSynthesizer:
    """The synthesizer a ``--festival`` option asks for: a local Festival when it is not given."""
    if address is None:
        return FestivalSynthesizer()
    return FestivalServerSynthesizer(*festival_address(address))


def unstuffed(body: bytes) -> bytes:
    """A message body as Festival meant it: the stuffed key (``ft_StUfF_keXy``) back to the key."""
    return body.replace(_STUFFED_KEY, FILE_STUFF_KEY)


class FestivalServerSynthesizer(FestivalSynthesizer):
    """:class:`FestivalSynthesizer` whose Festival is a ``festival --server`` at ``host:port``.

    Everything but the running of Festival is inherited: the voice check, the text preparation,
    the script, the parsing of phones and words, the joining of the utterances' waves.
    ``timeout`` bounds every exchange with the server; ``cancelled`` is asked every 0.1 s while it
    synthesizes (then the connection is closed, which ends the server's Festival for it).
    """

    def __init__(self, host: str, port: int = DEFAULT_PORT, timeout: float = 600,
                 cancelled: Callable[[], bool] | None = None):
        super().__init__(festival="festival", timeout=timeout, cancelled=cancelled)
        self.host = host
        self.port = int(port)

    @property
    def address(self) -> str:
        return f"[{self.host}]:{self.port}" if ":" in self.host else f"{self.host}:{self.port}"

    def executable(self) -> str:
        return f"the Festival server at {self.address}"

    def synthesize(self, text: str, voice: str | None = None) -> Utterance:
        """As a local Festival's; an error that is not about the text names the server."""
        try:
            return super().synthesize(text, voice)
        except SynthesisCancelled:
            raise
        except SynthesisError as exc:
            raise self._naming_the_server(exc) from None

    def voices(self) -> list[str]:
        try:
            return super().voices()
        except SynthesisError as exc:
            raise self._naming_the_server(exc) from None

    def _naming_the_server(self, error: SynthesisError) -> SynthesisError:
        if error.file == "<text>" or self.address in str(error):      # about the text, or already says where
            return error
        return SynthesisError(f"{error} (the Festival server at {self.address})")

    def _run(self, script: str, want_waves: bool = False) -> tuple[str, str, dict[str, bytes]]:
        """Send ``script`` to the server: (what it printed, "", its waves by the local file names)."""
        expression = f"(begin\n{_PRELUDE}{script}{_RESULT})\n"
        started = time.perf_counter()
        try:
            connection = socket.create_connection((self.host, self.port), timeout=min(self.timeout, _CONNECT_SECONDS))
        except OSError as exc:
            raise SynthesisError(f"cannot reach the Festival server at {self.address}: {exc.strerror or exc}"
                                 ) from None
        with connection:
            try:
                connection.sendall(expression.encode("latin-1"))
                value, waves = _ServerReply(connection, self).read()
            except OSError as exc:
                raise SynthesisError(f"the Festival server at {self.address} failed: {exc.strerror or exc}"
                                     ) from None
        self.last_run_seconds = time.perf_counter() - started
        named = {WAVE_FILE_PATTERN.format(number): wave for number, wave in enumerate(waves, start=1)}
        return value, "", (named if want_waves else {})


class _ServerReply:
    """Reads one expression's messages (LP, WV …, then OK or ER) from the connection."""

    def __init__(self, connection: socket.socket, synthesizer: FestivalServerSynthesizer):
        self.connection = connection
        self.synthesizer = synthesizer
        self.buffer = bytearray()
        self.received = 0
        self.deadline = time.monotonic() + synthesizer.timeout
        connection.settimeout(_POLL_SECONDS)

    def read(self) -> tuple[str, list[bytes]]:
        value: bytes | None = None
        waves: list[bytes] = []
        while True:
            kind = self._take_until(b"\n")
            if kind == b"OK":
                break
            if kind == b"ER":
                raise SynthesisError(f"the Festival server at {self.synthesizer.address} could not run the script "
                                     "(an error in Festival: its log says which)")
            if kind == b"WV":
                waves.append(unstuffed(self._take_until(FILE_STUFF_KEY)))
            elif kind == b"LP":
                value = unstuffed(self._take_until(FILE_STUFF_KEY))
            else:
                raise SynthesisError(f"{self.synthesizer.address} does not speak Festival's server protocol "
                                     f"(it sent {kind[:20]!r})")
        if value is None:
            raise SynthesisError(f"the Festival server at {self.synthesizer.address} returned nothing")
        return printed_string(value.decode("latin-1")), waves

    def _take_until(self, end: bytes) -> bytes:
        searched = 0                                   # the buffer before this is known not to hold ``end``
        while True:
            found = self.buffer.find(end, searched)
            if found >= 0:
                taken = bytes(self.buffer[:found])
                del self.buffer[:found + len(end)]
                return taken
            searched = max(0, len(self.buffer) - len(end) + 1)
            self.buffer += self._receive()

    def _receive(self) -> bytes:
        synthesizer = self.synthesizer
        while True:
            if synthesizer.cancelled is not None and synthesizer.cancelled():
                raise SynthesisCancelled("speech synthesis was cancelled")
            if time.monotonic() >= self.deadline:
                raise SynthesisError(f"the Festival server at {synthesizer.address} did not finish within "
                                     f"{synthesizer.timeout:g} s (a very long text? split it, or allow more time)")
            try:
                data = self.connection.recv(1 << 16)
            except TimeoutError:
                continue
            if not data:
                raise SynthesisError(f"the Festival server at {synthesizer.address} closed the connection")
            self.received += len(data)
            if self.received > MAX_REPLY_BYTES:
                raise SynthesisError(f"the Festival server at {synthesizer.address} sent more than "
                                     f"{MAX_REPLY_BYTES // (1024 * 1024)} MiB for one text")
            return data


def printed_string(printed: str) -> str:
    r"""The string Festival printed as a Scheme literal (``"a \"b\""\n``) → its text (``a "b"``).

    >>> printed_string('"tab\there \\"quoted\\" back\\\\slash"\n')
    'tab\there "quoted" back\\slash'
    """
    printed = printed.strip("\n")
    if len(printed) < 2 or not (printed.startswith('"') and printed.endswith('"')):
        raise SynthesisError(f"the Festival server returned {printed[:60]!r} where its output was expected")
    return re.sub(r"\\(.)", r"\1", printed[1:-1], flags=re.DOTALL)
