"""The supervisor of `urdfcli lsp` on its own, with a stand-in server: the client's
messages pass unchanged, a server that let go of much is replaced after a didClose,
the new one is given the client's initialize and the open documents, and the old one
answers what it was asked before it ends. (tests/test_lsp.py drives the real server
through it: the memory test replaces it.)"""

from __future__ import annotations

import json
import os
import sys
import threading
import time

from urdfcli.lsp.supervisor import SETTLE, Supervisor, framed, read_message

# A server that says who it is, opens documents, lists them, answers test/slow after
# 3 s, asks the client to register a capability once initialized, and when a "large"
# document is closed takes 100 MiB and gives it back (its peak far above what it holds then),
# 2 s later for a "slow_large" one.
STAND_IN = r'''
import json, os, sys, threading, time
sys.path.insert(0, sys.argv[1])
from urdfcli.lsp.supervisor import framed, read_message
out, lock, documents = sys.stdout.buffer, threading.Lock(), {}
def send(message):
    with lock:
        out.write(framed(json.dumps({"jsonrpc": "2.0", **message}).encode()))
        out.flush()
def slow(id_):
    time.sleep(3)
    send({"id": id_, "result": {"pid": os.getpid()}})
while (body := read_message(sys.stdin.buffer)) is not None:
    m = json.loads(body)
    method, params = m.get("method"), m.get("params")
    if method == "initialize":
        send({"id": m["id"], "result": {"capabilities": {}, "pid": os.getpid()}})
    elif method == "initialized":
        send({"id": "register", "method": "client/registerCapability", "params": {"registrations": []}})
    elif method == "textDocument/didOpen":
        documents[params["textDocument"]["uri"]] = params["textDocument"]
        send({"method": "test/opened", "params": {"uri": params["textDocument"]["uri"], "pid": os.getpid()}})
    elif method == "textDocument/didClose" and "large" in (uri := documents.pop(params["textDocument"]["uri"])["uri"]):
        taken = bytearray(100 * 1024 * 1024)
        for i in range(0, len(taken), 4096):
            taken[i] = 1
        if "slow" in uri:  # still busy with the close at the supervisor's first look
            threading.Timer(2.0, taken.clear).start()
        del taken
    elif method == "urdfcli/openDocuments":
        send({"id": m["id"], "result": list(documents.values())})
    elif method == "test/slow":
        threading.Thread(target=slow, args=(m["id"],), daemon=True).start()  # (dropped when its input ends)
    elif "id" in m and "method" in m:
        send({"id": m["id"], "result": {"pid": os.getpid()}})
'''


class Pipes:
    """The client's side of a supervisor run on a thread."""

    def __init__(self, tmp_path):
        server = tmp_path / "stand_in.py"
        server.write_text(STAND_IN)
        source = os.path.dirname(os.path.dirname(sys.modules["urdfcli"].__file__))
        to_supervisor, self.writer = os.pipe()
        self.reader, from_supervisor = os.pipe()
        self.to = os.fdopen(self.writer, "wb")
        self.back = os.fdopen(self.reader, "rb")
        self.supervisor = Supervisor([sys.executable, str(server), source], os.fdopen(to_supervisor, "rb"), os.fdopen(from_supervisor, "wb"))
        self.code = None
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self):
        self.code = self.supervisor.run()

    def send(self, **message):
        self.to.write(framed(json.dumps({"jsonrpc": "2.0", **message}).encode()))
        self.to.flush()

    def receive(self, timeout: float = 20) -> dict:
        """The supervisor's next message (TimeoutError: none in time)."""
        read = []
        reader = threading.Thread(target=lambda: read.append(read_message(self.back)), daemon=True)
        reader.start()
        reader.join(timeout)
        if not read:
            raise TimeoutError("nothing from the supervisor")
        return json.loads(read[0])


def document(name: str) -> dict:
    return {"uri": f"file:///{name}", "languageId": "xml", "version": 3, "text": f"<robot name='{name}'/>"}


def test_a_server_that_let_go_of_much_is_replaced_after_a_close(tmp_path):
    client = Pipes(tmp_path)
    client.send(id=1, method="initialize", params={"capabilities": {}, "processId": None})
    first = client.receive()["result"]["pid"]
    client.send(method="initialized", params={})
    assert client.receive()["method"] == "client/registerCapability"  # the first server's, passed on
    client.send(id="register", result=None)
    for name in ("kept.urdf", "large.urdf"):
        client.send(method="textDocument/didOpen", params={"textDocument": document(name)})
        assert client.receive()["params"] == {"uri": f"file:///{name}", "pid": first}
    client.send(id=2, method="test/slow", params=None)  # asked of the first server, in flight while it is replaced
    client.send(method="textDocument/didClose", params={"textDocument": {"uri": "file:///large.urdf"}})
    received = [client.receive(), client.receive()]
    # the new server was given the open document (no registration reaches the client)
    assert received[0]["method"] == "test/opened" and received[0]["params"]["uri"] == "file:///kept.urdf"
    second = received[0]["params"]["pid"]
    assert second != first
    # and the old one answered what it was asked, then ended
    assert received[1] == {"jsonrpc": "2.0", "id": 2, "result": {"pid": first}}
    deadline = time.monotonic() + 5
    while os.path.exists(f"/proc/{first}") and time.monotonic() < deadline:
        time.sleep(0.02)
    assert not os.path.exists(f"/proc/{first}")
    client.send(id=3, method="test/other", params=None)
    assert client.receive() == {"jsonrpc": "2.0", "id": 3, "result": {"pid": second}}
    client.to.close()  # the client gone: the supervisor ends with its server
    client.thread.join(10)
    assert client.code is not None and not os.path.exists(f"/proc/{second}")


def test_a_server_still_busy_with_a_close_is_looked_at_again(tmp_path):
    """On a busy machine the server may still hold a closed file's memory at the first look
    (1 s): the supervisor looks again (3 s, 10 s) and replaces it once it has let go."""
    client = Pipes(tmp_path)
    client.send(id=1, method="initialize", params={"capabilities": {}, "processId": None})
    first = client.receive()["result"]["pid"]
    client.send(method="initialized", params={})
    assert client.receive()["method"] == "client/registerCapability"
    client.send(id="register", result=None)
    for name in ("kept.urdf", "slow_large.urdf"):
        client.send(method="textDocument/didOpen", params={"textDocument": document(name)})
        client.receive()
    client.send(method="textDocument/didClose", params={"textDocument": {"uri": "file:///slow_large.urdf"}})
    opened = client.receive(timeout=SETTLE[1] + 5)
    assert opened["method"] == "test/opened" and opened["params"]["uri"] == "file:///kept.urdf" and opened["params"]["pid"] != first
    client.send(id=2, method="shutdown", params=None)
    assert client.receive()["id"] == 2
    client.send(method="exit", params=None)
    client.thread.join(10)
    assert client.code == 0


def test_a_server_that_holds_what_it_took_is_kept(tmp_path):
    client = Pipes(tmp_path)
    client.send(id=1, method="initialize", params={"capabilities": {}, "processId": None})
    first = client.receive()["result"]["pid"]
    client.send(method="textDocument/didOpen", params={"textDocument": document("small.urdf")})
    client.receive()
    client.send(method="textDocument/didClose", params={"textDocument": {"uri": "file:///small.urdf"}})
    time.sleep(SETTLE[-1] + 1)  # every look at its memory made
    client.send(id=2, method="test/other", params=None)
    assert client.receive() == {"jsonrpc": "2.0", "id": 2, "result": {"pid": first}}
    client.send(id=3, method="shutdown", params=None)
    assert client.receive()["id"] == 3
    client.send(method="exit", params=None)
    client.thread.join(10)
    assert client.code == 0
