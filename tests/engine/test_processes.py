"""Children end with us (engine/processes.py): the parent-death signal, tested with a child that never writes.

A child writing to a pipe dies of SIGPIPE soon after its parent; one that
computes silently (Festival on one long utterance, ffmpeg waiting on a file)
would run on for minutes as an orphan without the signal.
"""

from __future__ import annotations

import signal
import subprocess
import sys

import pytest

from tests.engine.test_long_speech import alive, children_named, wait_for

PARENT = """
import signal, subprocess, sys, time
from engine.processes import with_parent_death_signal
# Ctrl-C ends it as it ends any Python program, even where the suite was started in the background
# (a shell starts background jobs with SIGINT ignored, and Python keeps an ignored SIGINT ignored)
signal.signal(signal.SIGINT, signal.default_int_handler)
subprocess.Popen(with_parent_death_signal(["sleep", "1000"]), stdin=subprocess.DEVNULL,
                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
print("started", flush=True)
time.sleep(1000)
"""


@pytest.mark.parametrize("how", [signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
def test_a_silent_child_dies_with_its_parent(how):
    parent = subprocess.Popen([sys.executable, "-c", PARENT], stdout=subprocess.PIPE, text=True)
    try:
        assert parent.stdout is not None and parent.stdout.readline().strip() == "started"
        children = wait_for(lambda: children_named(parent.pid, "sleep"))
        assert children
        parent.send_signal(how)
        parent.wait(30)
        assert wait_for(lambda: not any(alive(pid) for pid in children), 10), "the child outlived its parent"
    finally:
        if parent.poll() is None:
            parent.kill()
            parent.wait()
