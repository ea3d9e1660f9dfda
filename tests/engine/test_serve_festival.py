"""``--festival HOST:PORT``: synthesis through a real ``festival --server`` started here, on 127.0.0.1 only.

Festival's server accepts clients whose host matches ``server_access_list``, by default
``("127.0.0.1" "localhost\\.localdomain" "localhost")`` (festival.scm): the test's own connections only.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import time
from collections.abc import Iterator

import numpy as np
import pytest

from engine.processes import with_parent_death_signal
from engine.speech.festival import FestivalSynthesizer
from engine.speech.festival_server import FestivalServerSynthesizer
from engine.speech.synthesis import SynthesisError
from tests.engine.serve_schema_checks import schema_checked  # noqa: F401  (a fixture)
from tests.engine.test_serve import (
    check_gaze_cue_log,
    run_cli,
    run_gaze_cue_example,
    start_server,
    stop_server,
)

pytestmark = [pytest.mark.usefixtures("schema_checked"),
              pytest.mark.skipif(shutil.which("festival") is None, reason="Festival is not installed")]

#: Several utterances, quotes, a backslash and Latin-1 letters: every path of the script's output.
TEXT = 'Hyvää päivää! Mitä "kuuluu" \\ tänään? Toinen lause tässä.'


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@pytest.fixture(scope="module")
def festival_port(tmp_path_factory: pytest.TempPathFactory) -> Iterator[int]:
    """A real ``festival --server`` on 127.0.0.1 (its port found free just before), ended with its clients."""
    port = free_port()
    log = tmp_path_factory.mktemp("festival-server") / "festival-server.log"
    with log.open("wb") as out:
        process = subprocess.Popen(with_parent_death_signal(["festival", f"(set! server_port {port})", "--server"]),
                                   stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                                   start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                socket.create_connection(("127.0.0.1", port), timeout=1).close()
                break
            except OSError:
                if process.poll() is not None or time.monotonic() > deadline:
                    pytest.fail(f"festival --server did not start: {log.read_text(errors='replace')}")
                time.sleep(0.1)
        yield port
    finally:
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=30)


def test_the_server_gives_the_same_utterance_as_a_local_festival(festival_port):
    local = FestivalSynthesizer().synthesize(TEXT)
    served = FestivalServerSynthesizer("127.0.0.1", festival_port).synthesize(TEXT)
    assert [w.label for w in served.words] == ["Hyvää", "päivää", "Mitä", "kuuluu", "\\", "tänään", "Toinen",
                                               "lause", "tässä"]
    assert served.words == local.words and served.phones == local.phones
    assert served.sample_rate == local.sample_rate and np.array_equal(served.samples, local.samples)
    assert served.phoneset == local.phoneset and served.phone_features == local.phone_features


def test_the_server_lists_its_voices_and_names_a_missing_one(festival_port):
    synthesizer = FestivalServerSynthesizer("127.0.0.1", festival_port)
    assert synthesizer.voices() == FestivalSynthesizer().voices()
    with pytest.raises(SynthesisError, match="voice no_such_voice is not installed"):
        synthesizer.synthesize("moi", voice="no_such_voice")


def test_a_closed_port_is_refused_naming_the_address():
    port = free_port()
    with pytest.raises(SynthesisError, match=f"cannot reach the Festival server at 127.0.0.1:{port}"):
        FestivalServerSynthesizer("127.0.0.1", port).synthesize("moi")


def test_serve_with_the_festival_server_gives_the_events_of_a_local_festival(festival_port, tmp_path):
    logs = {}
    for name, options in (("local", ()), ("server", ("--festival", f"127.0.0.1:{festival_port}"))):
        (tmp_path / name).mkdir()
        served = start_server(tmp_path / name, *options)
        try:
            logs[name] = run_gaze_cue_example(served.url, tmp_path / f"{name}.csv")
        finally:
            stop_server(served)
        assert "Traceback" not in served.stderr()
        check_gaze_cue_log(logs[name])

    def words(rows: list[dict[str, str]]) -> list[tuple[str, float, int]]:
        start = next(float(r["t"]) for r in rows if r["event"] == "speech_start")
        return [(r["word"], float(r["onset_t"]) - start, int(r["sample"])) for r in rows if r["event"] == "word"]

    local, remote = words(logs["local"]), words(logs["server"])
    assert [w for w, _, _ in remote] == [w for w, _, _ in local]
    for (_, local_ms, local_sample), (_, remote_ms, remote_sample) in zip(local, remote, strict=True):
        assert abs(remote_ms - local_ms) < 1.0 and remote_sample == local_sample


def test_say_through_the_festival_server_writes_the_local_wave(festival_port, tmp_path):
    local, remote = tmp_path / "local.wav", tmp_path / "remote.wav"
    assert run_cli("say", "Hyvää huomenta.", "-o", str(local)).returncode == 0
    result = run_cli("say", "Hyvää huomenta.", "--festival", f"127.0.0.1:{festival_port}", "-o", str(remote))
    assert result.returncode == 0, result.stderr
    assert remote.read_bytes() == local.read_bytes()


@pytest.mark.parametrize("address, expected", [
    ("localhost", "--festival 'localhost' is not HOST:PORT"),
    ("127.0.0.1:0", "--festival '127.0.0.1:0' is not HOST:PORT"),
    ("127.0.0.1:99999", "--festival '127.0.0.1:99999' is not HOST:PORT"),
    ("bad host:1314", "--festival 'bad host:1314' is not HOST:PORT"),
    ("closed", "cannot reach the Festival server at 127.0.0.1:"),
])
def test_serve_refuses_a_bad_or_unreachable_festival_in_one_line(address, expected):
    if address == "closed":
        address = f"127.0.0.1:{free_port()}"
    result = run_cli("serve", "--headless", "--port", "0", "--festival", address)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.startswith("error: ") and expected in result.stderr and result.stderr.count("\n") == 1


def test_say_refuses_an_unreachable_festival_in_one_line(tmp_path):
    result = run_cli("say", "moi", "--festival", f"127.0.0.1:{free_port()}", "-o", str(tmp_path / "moi.wav"))
    assert result.returncode == 2 and result.stderr.count("\n") == 1
    assert "cannot reach the Festival server at 127.0.0.1:" in result.stderr


def test_a_cancelled_synthesis_on_the_server_ends_at_once(festival_port):
    from engine.speech.festival import SynthesisCancelled

    asked = []

    def cancelled() -> bool:
        asked.append(True)
        return True

    synthesizer = FestivalServerSynthesizer("127.0.0.1", festival_port, cancelled=cancelled)
    with pytest.raises(SynthesisCancelled):
        synthesizer.synthesize(TEXT * 20)
    assert asked
    assert FestivalServerSynthesizer("127.0.0.1", festival_port).synthesize("Moi.").words    # the server serves on


def test_say_refuses_a_festival_server_beside_a_recording(tmp_path):
    take, labels = tmp_path / "take.wav", tmp_path / "take.TextGrid"
    result = run_cli("say", "--audio", str(take), "--labels", str(labels), "--festival", "127.0.0.1:1314",
                     "-o", str(tmp_path / "out.wav"))
    assert result.returncode == 2 and result.stderr.count("\n") == 1
    assert "--festival applies to synthesis" in result.stderr
