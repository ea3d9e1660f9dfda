"""The ``load`` request: another model file (an identity) from the folders the server was started with, nothing else.

The served folder here is a temporary ``models/`` holding a copy of the shipped head with other
defaults (``anna.xml``), one with a bad attribute on a known line (``broken.xml``) and a symbolic
link to a model outside the folder (``escape.xml``); the shipped head's own folder is served as
-m's folder (the default model).
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from engine.live.client import LiveClient, LiveError
from engine.paths import default_model_path
from tests.engine.serve_schema_checks import REQUEST, schema_checked  # noqa: F401  (a fixture)
from tests.engine.test_serve import LOCATED, Served, run_cli, start_server, stop_server

BROKEN_LINE_TEXT = '<parameter name="head_nod" type="rotation" min="-0.6"'

pytestmark = pytest.mark.usefixtures("schema_checked")


@pytest.fixture(scope="module")
def models(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("load")
    folder = root / "models"
    (folder / "people").mkdir(parents=True)
    shipped = default_model_path()
    text = shipped.read_text(encoding="utf-8")
    anna = re.sub(r'(<parameter name="head_turn" type="rotation" min="-1.0" max="1.0" default=")0.0"', r'\g<1>0.2"',
                  text, count=1)
    assert anna != text
    (folder / "people" / "anna.xml").write_text(anna, encoding="utf-8")
    (folder / "people" / "head.h5").symlink_to(shipped.with_name("head.h5"))
    assert BROKEN_LINE_TEXT in text
    (folder / "broken.xml").write_text(text.replace(BROKEN_LINE_TEXT, BROKEN_LINE_TEXT.replace("-0.6", "oops")),
                                       encoding="utf-8")
    (folder / "escape.xml").symlink_to(shipped)
    (root / "outside.xml").write_text(text, encoding="utf-8")
    return folder


@pytest.fixture(scope="module")
def server(models: Path, tmp_path_factory: pytest.TempPathFactory) -> Iterator[Served]:
    served = start_server(tmp_path_factory.mktemp("serve-load"), "--models", str(models))
    yield served
    stop_server(served)
    assert "Traceback" not in served.stderr()


def test_a_model_from_a_served_folder_replaces_the_head_from_the_frame_the_reply_names(server):
    with LiveClient(server.url) as head:
        assert head.state()["values"]["head_turn"] == 0.0
        far = head.command("<commands><HeadNod/></commands>", at=head.state()["t"] + 60_000)
        reply = head.load("people/anna.xml")
        assert reply["ok"] and reply["model"] == "people/anna.xml" and reply["parameter_count"] > 10
        events = [head.next_event(), head.next_event()]
        stopped = next(e for e in events if e["id"] == far["id"])
        loaded = next(e for e in events if e["id"] == reply["id"])
        assert stopped["event"] == "finished" and stopped["stopped"] is True     # what ran on the old head ended
        assert loaded == {"event": "loaded", "id": reply["id"], "t": reply["t"], "model": "people/anna.xml",
                          "presented_t": reply["t"]}
        state = head.state()
        assert state["model"] == "people/anna.xml" and state["values"]["head_turn"] == pytest.approx(0.2)
        caps = head.capabilities()
        assert caps["model"] == "people/anna.xml"
        assert next(p for p in caps["parameters"] if p["name"] == "head_turn")["default"] == pytest.approx(0.2)
        back = head.load("head.xml")                 # -m's folder: the shipped head
        assert back["ok"] and head.state()["values"]["head_turn"] == 0.0


def test_a_bad_model_file_is_refused_with_its_name_and_line_and_the_head_is_kept(server):
    line = 1 + default_model_path().read_text(encoding="utf-8").split(BROKEN_LINE_TEXT)[0].count("\n")
    with LiveClient(server.url) as head:
        before = head.state()["model"]
        with pytest.raises(LiveError) as refused:
            head.load("broken.xml")
        message = refused.value.args[0]
        assert message.startswith(f"broken.xml:{line}: ") and "'oops'" in message and "\n" not in message
        assert "/" not in message.split(":")[0]                                    # no server path given away
        assert head.state()["model"] == before


@pytest.mark.parametrize("name, expected", [
    ("../outside.xml", r"^<message>:1: \"model\" is a model file \(\.xml\) named from a served folder"),
    ("/etc/passwd.xml", r"^<message>:1: \"model\" is a model file"),
    ("people/../../outside.xml", r"^<message>:1: \"model\" is a model file"),
    ("escape.xml", r"^<message>:1: no model file 'escape.xml' in the folders this server was started with"),
    ("missing.xml", r"^<message>:1: no model file 'missing.xml'"),
    ("people", r"^<message>:1: \"model\" is a model file"),
    (7, r"^<message>:1: \"model\" is a model file"),
])
def test_nothing_outside_the_served_folders_is_read(server, name, expected):
    with LiveClient(server.url) as head:
        request = {"type": "load", "id": "outside", "model": name}
        schema_allows = REQUEST.is_valid(request)
        if not schema_allows:                                  # the schema refuses it too: sent as raw text
            head.send_raw(json.dumps(request))
            reply = head.reply_to("outside")
            assert reply["ok"] is False
            error = reply["error"]
        else:
            with pytest.raises(LiveError) as refused:
                head.load(name)
            error = refused.value.args[0]
        assert schema_allows == (name in ("escape.xml", "missing.xml"))
        assert re.search(expected, error), error
        assert LOCATED.match(error)
        assert head.state()["ok"]


def test_a_models_option_that_names_no_folder_is_refused_in_one_line(tmp_path):
    result = run_cli("serve", "--headless", "--port", "0", "--models", str(tmp_path / "nothing"))
    assert result.returncode == 2 and result.stderr.count("\n") == 1
    assert result.stderr.startswith(f"error: {tmp_path / 'nothing'}: --models names no folder")
