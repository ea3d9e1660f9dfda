"""The HDF5 probe's helper (engine/formats/hdf5_probe_helper.py): one interpreter that forks the readers
where this process cannot fork, reused from file to file, replaced when it dies, gone when we are."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from engine import ModelFileError, load_model, save_model
from engine.formats import hdf5_probe, hdf5_probe_helper
from tests.engine.test_mesh_child import _alive
from tests.engine.test_model_files import small_model


@pytest.fixture
def no_forking_here(monkeypatch):
    monkeypatch.setattr(hdf5_probe, "_one_thread", lambda: False)


def test_one_helper_reads_file_after_file_and_a_dead_one_is_replaced(tmp_path, no_forking_here):
    written = save_model(small_model(), tmp_path / "m.xml")
    assert load_model(written).n_vertices == 6
    first = hdf5_probe_helper.helper_pid()
    assert first is not None and first != os.getpid()
    assert load_model(written).n_vertices == 6
    assert hdf5_probe_helper.helper_pid() == first, "the helper is reused, not started again"
    os.kill(first, signal.SIGKILL)
    while _alive(first):
        time.sleep(0.01)
    assert load_model(written).n_vertices == 6
    assert hdf5_probe_helper.helper_pid() not in (None, first)


def test_a_helper_that_ends_without_answering_leaves_the_file_to_a_fresh_interpreter(tmp_path, no_forking_here,
                                                                                    monkeypatch):
    written = save_model(small_model(), tmp_path / "m.xml")
    hdf5_probe_helper._stop()
    mute = [sys.executable, "-c", "import sys; sys.stdin.readline()"]     # reads the request, then ends
    monkeypatch.setattr(hdf5_probe_helper, "_start", lambda: subprocess.Popen(
        mute, stdin=subprocess.PIPE, stdout=subprocess.PIPE, bufsize=0))
    spawned: list[Path] = []
    real = hdf5_probe.probe_spawned
    monkeypatch.setattr(hdf5_probe, "probe_spawned",
                        lambda path, *rest: (spawned.append(path), real(path, *rest)))
    assert load_model(written).n_vertices == 6
    assert spawned == [written.with_suffix(".h5")]
    assert hdf5_probe_helper.helper_pid() is None, "the mute helper was ended"


def test_threads_probing_at_once_each_get_their_own_answer(tmp_path, no_forking_here, monkeypatch):
    good = save_model(small_model(), tmp_path / "good.xml")
    bad = save_model(small_model(), tmp_path / "bad.xml")
    data = bytearray(bad.with_suffix(".h5").read_bytes())
    data[data.find(b"\x02\x00\x00\x00\x00\x00\x00\x00mm\x00")] = 0xC1     # a byte the library hangs on
    bad.with_suffix(".h5").write_bytes(bytes(data))
    monkeypatch.setenv("AP_HDF5_PROBE_SECONDS", "2")
    outcomes: dict[str, list[str]] = {"good": [], "bad": []}

    def load(name: str, path: Path) -> None:
        for _ in range(3):
            try:
                load_model(path)
                outcomes[name].append("loaded")
            except ModelFileError as exc:
                outcomes[name].append(str(exc))

    threads = [threading.Thread(target=load, args=item) for item in (("good", good), ("bad", bad))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert outcomes["good"] == ["loaded"] * 3
    assert len(outcomes["bad"]) == 3 and all("did not finish" in o and "bad.h5" in o for o in outcomes["bad"])


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="reads the process tree from /proc")
def test_the_helper_leaves_when_its_program_is_killed(tmp_path):
    written = save_model(small_model(), tmp_path / "m.xml")
    script = ("from pathlib import Path; import engine; from engine.formats import hdf5_probe, hdf5_probe_helper; "
              "hdf5_probe._one_thread = lambda: False; "
              f"engine.load_model(Path({str(written)!r})); print(hdf5_probe_helper.helper_pid(), flush=True); "
              "import time; time.sleep(600)")
    program = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        assert program.stdout is not None
        helper = int(program.stdout.readline())
        assert _alive(helper)
        os.kill(program.pid, signal.SIGKILL)
        program.wait()
        for _ in range(300):
            if not _alive(helper):
                break
            time.sleep(0.1)
        assert not _alive(helper), "the helper outlived the program it served"
    finally:
        if program.poll() is None:
            program.kill()
            program.wait()


def test_a_request_the_helper_cannot_read_is_answered_and_it_goes_on(tmp_path):
    written = save_model(small_model(), tmp_path / "m.xml")
    helper = subprocess.Popen([sys.executable, "-I", hdf5_probe.__file__, "--serve"], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True)
    good = json.dumps({"path": str(written.with_suffix(".h5")), "budget": 1000000, "filters": [1, 2, 3, 4],
                       "seconds": 10}) + "\n"
    out, _ = helper.communicate('{"path": 3}\nnot json\n' + good, timeout=60)
    answers = out.splitlines()
    assert len(answers) == 3 and '"error"' in answers[0] and '"error"' in answers[1]
    assert answers[2] == '{"status": 0, "message": ""}'
    assert helper.returncode == 0
