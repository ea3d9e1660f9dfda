"""The Festival-server client against hostile servers: whatever comes back, a located one-line error or a result.

A real TCP listener on 127.0.0.1 (a thread here) answers each connection with bytes hypothesis makes
from the pieces of Festival's protocol (``LP``/``WV``/``ER``/``OK``, the key and its stuffed form,
printed Scheme strings with ``AP-`` lines, RIFF headers) and plain noise, then closes. Every run of
:class:`FestivalServerSynthesizer` must return an utterance or raise :class:`SynthesisError` whose
message names the server; no other exception, no hang (``AP_FUZZ_EXAMPLES``, default 200; the
release check runs 10,000: ``docs/serve.md``).
"""

from __future__ import annotations

import socket
import struct
import threading
from collections.abc import Iterator

import pytest
from hypothesis import given
from hypothesis import strategies as st

from engine.speech.festival_server import FILE_STUFF_KEY, FestivalServerSynthesizer
from engine.speech.synthesis import SynthesisError
from tests.engine.fuzz_support import FUZZ, outcome

KEY = FILE_STUFF_KEY
STUFFED = KEY[:-1] + b"X" + KEY[-1:]
AP_OUTPUT = ('"\nAP-VOICES\tsuo_fi_lj_diphone\nAP-BEGIN\nAP-PHONESET\tfinnish\nAP-UTT\t1\n'
             'AP-WORD\t_1\tmoi\nAP-SEG\t0.030000\t0\t#\nAP-SEG\t0.100000\t_1\tm\n'
             'AP-SEG\t0.250000\t_1\toi\nAP-END\n"\n').encode("latin-1")
"""What Festival prints for the script: a Scheme string with real tabs and line breaks inside."""


def riff(samples: int, rate: int) -> bytes:
    data = b"\x00\x01" * max(0, samples)
    return (b"RIFF" + struct.pack("<I", 36 + len(data)) + b"WAVEfmt " + struct.pack("<IHHIIHH", 16, 1, 1, rate,
            rate * 2, 2, 16) + b"data" + struct.pack("<I", len(data)) + data)


VALID = b"WV\n" + riff(5512, 22050) + KEY + b"LP\n" + AP_OUTPUT + KEY + b"OK\n"
"""A whole reply as Festival sends it for one utterance of "moi"."""

PIECES = st.one_of(
    st.just(VALID),
    st.sampled_from([b"LP\n", b"WV\n", b"ER\n", b"OK\n", KEY, STUFFED, AP_OUTPUT, b'"unterminated', b"nil\n",
                     b'"\\"', b"AP-END", b"\n", b"LP\n" + AP_OUTPUT + KEY + b"OK\n"]),
    st.builds(riff, st.integers(-2, 600), st.sampled_from([0, 1, 8000, 16000, 22050, 2**31 - 1])),
    st.binary(max_size=64),
    st.text(max_size=40).map(lambda text: text.encode("utf-8")),
)
REPLIES = st.lists(PIECES, max_size=12).map(b"".join)


class HostileServer:
    """Listens on 127.0.0.1; each connection gets :attr:`reply`, then the connection is closed."""

    def __init__(self) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.reply = b""
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        while True:
            try:
                connection, _ = self.listener.accept()
            except OSError:
                return
            with connection:
                connection.settimeout(5)
                try:
                    connection.recv(1 << 20)
                    connection.sendall(self.reply)
                except OSError:
                    pass

    def close(self) -> None:
        self.listener.close()


@pytest.fixture(scope="module")
def hostile() -> Iterator[HostileServer]:
    server = HostileServer()
    yield server
    server.close()


def test_a_plain_festival_reply_read_from_the_socket_gives_the_utterance(hostile):
    hostile.reply = VALID
    utterance = FestivalServerSynthesizer("127.0.0.1", hostile.port, timeout=10).synthesize("moi")
    assert [w.label for w in utterance.words] == ["moi"] and utterance.sample_rate == 22050
    assert len(utterance.samples) == round(250 * 22050 / 1000)


def test_a_server_that_is_not_festival_is_refused_naming_it(hostile):
    hostile.reply = b"HTTP/1.1 400 Bad Request\r\n\r\n"
    with pytest.raises(SynthesisError, match=f"127.0.0.1:{hostile.port} does not speak Festival's server protocol"):
        FestivalServerSynthesizer("127.0.0.1", hostile.port, timeout=10).synthesize("moi")


def test_fuzzed_server_replies_give_a_result_or_an_error_naming_the_server(hostile):
    tried = {"replies": 0, "refused": 0, "spoken": 0}
    address = f"127.0.0.1:{hostile.port}"

    @FUZZ
    @given(reply=REPLIES)
    def answer(reply: bytes) -> None:
        hostile.reply = reply
        tried["replies"] += 1
        synthesizer = FestivalServerSynthesizer("127.0.0.1", hostile.port, timeout=10)
        result = outcome(lambda: synthesizer.synthesize("moi"), SynthesisError)
        if isinstance(result, SynthesisError):
            tried["refused"] += 1
            assert address in str(result) and "\n" not in str(result).strip(), str(result)
        else:
            tried["spoken"] += 1

    answer()
    print(f"festival-server fuzz: {tried}")
    assert tried["refused"] > 0
