"""``urdfcli lsp``'s own process: it runs the server (:mod:`.server`) as its child and
passes the protocol's messages between the client and it, so that what a large file
took can be given back by replacing the child.

Python's allocator keeps each 1 MiB arena as long as one block in it lives. After a
large file's checks, a few blocks that live on (the protocol's next message, a cache's
entry) keep some of the arenas those checks filled: 10-20 % more memory than before
the file was opened, which no collection gives back; a process's end does. So when the
client has closed a file and the server holds far less than its peak did (:data:`LET_GO`),
the supervisor starts a new server, gives it the client's ``initialize`` and the
documents the old one has open, sends it the client's messages from then on, and lets
the old one answer what it was asked, then end (its input closed, as when a client is
gone). The new server checks the open documents again and publishes their diagnostics.

It imports nothing of the server's (pygls, the rules): it stays small. Only Linux tells a
process's peak (``/proc``); elsewhere the server is never replaced.
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import BinaryIO

OPEN_DOCUMENTS = "urdfcli/openDocuments"  # the server's own request: its open documents, as didOpen gives them
LET_GO = 64 * 1024  # KiB: a server whose peak was this much above what it holds now is replaced
SETTLE = (1.0, 3.0, 10.0)  # seconds after the client's last didClose when the server's memory is looked at, until it let go
STARTING = 60.0  # seconds a new server may take to answer initialize
ANSWERING = 5.0  # seconds a server may take to answer the supervisor, and a replaced one the client
OWN = "urdfcli-supervisor-"  # the ids of the supervisor's own requests
# What the supervisor looks for in the client's messages (a request's id, the methods it
# follows); one without any of these is passed on unread
_NOTED = (b'"id"', b"initialize", b"shutdown", b"exit", b"didClose")


def read_message(stream: BinaryIO) -> bytes | None:
    """The body of the next message on ``stream``; None at its end."""
    length = None
    while True:
        line = stream.readline()
        if not line:
            return None
        if line.strip():
            name, _, value = line.partition(b":")
            if name.strip().lower() == b"content-length":
                length = int(value) if value.strip().isdigit() else None
        elif length is not None:
            break  # (headers without a length are skipped)
    body = stream.read(length)
    return body if len(body) == length else None


def framed(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def message(method: str, params, id_: str | None = None) -> bytes:
    """A request (with ``id_``) or a notification."""
    return json.dumps({"jsonrpc": "2.0", **({"id": id_} if id_ is not None else {}), "method": method, "params": params}).encode()


def parsed(body: bytes) -> dict:
    """A message's JSON object; {} for what is none (the server answers it)."""
    try:
        found = json.loads(body)
    except ValueError:  # (UnicodeDecodeError too)
        return {}
    return found if isinstance(found, dict) else {}


def memory_kib(pid: int, field: str) -> int | None:
    """A field of ``/proc/PID/status`` in KiB (``VmRSS``: now, ``VmHWM``: its peak)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return None
    return next((int(line.split()[1]) for line in status.splitlines() if line.startswith(field + ":")), None)


class Server:
    """One server process, and where it stands: the first or a replacement, retired or not."""

    def __init__(self, command: list[str], replacement: bool) -> None:
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.replacement = replacement  # its registrations are the first server's: the client has them
        self.retired = False  # replaced: only its answers to the client's requests go on
        self.asked: set = set()  # the ids of the client's requests it has not answered yet
        self.relay: threading.Thread | None = None  # its messages to the client
        self._writing = threading.Lock()

    def send(self, body: bytes) -> None:
        with self._writing:
            try:
                self.process.stdin.write(framed(body))
                self.process.stdin.flush()
            except (BrokenPipeError, ValueError):  # it ended (its reader says so) or its input was closed
                pass

    def close(self) -> None:
        """Close its input: it ends, as a server whose client is gone."""
        with self._writing:
            try:
                self.process.stdin.close()
            except BrokenPipeError:
                pass

    def let_go(self) -> bool:
        """Whether its peak was :data:`LET_GO` above what it holds now."""
        peak, now = memory_kib(self.process.pid, "VmHWM"), memory_kib(self.process.pid, "VmRSS")
        return peak is not None and now is not None and peak - now >= LET_GO


class Supervisor:
    """The client's messages to the current server, the servers' to the client."""

    def __init__(self, command: list[str], client_in: BinaryIO, client_out: BinaryIO) -> None:
        self.command = command
        self.client_in, self.client_out = client_in, client_out
        self.routing = threading.Lock()  # held while a client's message goes to ``server``, and while it is replaced
        self.replacing = threading.Lock()
        self._writing = threading.Lock()  # one message at a time to the client
        self.initialize: dict | None = None  # the client's initialize params
        self.initialized = False
        self.shut_down = False
        self.client_gone = False
        self._ids = itertools.count()
        self._waiting: dict[str, list] = {}  # own request id -> [its answer's Event, the answer]
        self._timer: threading.Timer | None = None
        self.server = self._start(replacement=False)

    def run(self) -> int:
        """Until the client's ``exit``, or its end; the exit code is the server's."""
        while (body := read_message(self.client_in)) is not None:
            found = parsed(body) if any(noted in body for noted in _NOTED) else {}
            method = found.get("method")
            if method == "initialize":
                self.initialize = found.get("params")
            self.initialized |= method == "initialized"
            self.shut_down |= method == "shutdown"
            with self.routing:
                if method is not None and "id" in found:
                    self.server.asked.add(_key(found["id"]))
                self.server.send(body)
            if method == "textDocument/didClose":
                self._settle()
            if method == "exit":
                break
        self.client_gone = True
        with self.routing:
            server = self.server
        server.close()
        code = server.process.wait()
        server.relay.join()
        return code

    # -- the servers -------------------------------------------------------------------
    def _start(self, replacement: bool) -> Server:
        server = Server(self.command, replacement)
        server.relay = threading.Thread(target=self._relay, args=(server,), name="urdfcli-relay", daemon=True)
        server.relay.start()
        return server

    def _relay(self, server: Server) -> None:
        """The server's messages to the client: not the answers to the supervisor's own
        requests; a replacement's registrations answered here; once retired, its
        answers to the client's requests alone (a newer server speaks for the documents).
        The supervisor ends with the current server."""
        while (body := read_message(server.process.stdout)) is not None:
            if OWN.encode() in body and self._answered(body):
                continue
            answer = server.asked and (b'"result"' in body or b'"error"' in body)
            found = parsed(body) if answer or server.retired else {}
            if "id" in found and "method" not in found:
                server.asked.discard(_key(found["id"]))
            elif server.retired:
                continue
            if server.replacement and b"client/registerCapability" in body:
                found = parsed(body)
                if found.get("method") == "client/registerCapability":
                    server.send(json.dumps({"jsonrpc": "2.0", "id": found.get("id"), "result": None}).encode())
                    continue
            self._to_client(body)
        code = server.process.wait()
        if server is self.server and not self.client_gone:  # it ended by itself (its client's process gone)
            os._exit(code)

    def _to_client(self, body: bytes) -> None:
        with self._writing:
            try:
                self.client_out.write(framed(body))
                self.client_out.flush()
            except (BrokenPipeError, ValueError):  # the client is gone: its end is read next
                pass

    def _answered(self, body: bytes) -> bool:
        found = parsed(body)
        waiting = self._waiting.get(found.get("id")) if "method" not in found and isinstance(found.get("id"), str) else None
        if waiting is None:
            return False
        waiting[1] = found
        waiting[0].set()
        return True

    def _ask(self, server: Server, method: str, params, timeout: float) -> dict | None:
        """A server's answer to a request of the supervisor's (None: none in time)."""
        key = f"{OWN}{next(self._ids)}"
        waiting = self._waiting[key] = [threading.Event(), None]
        server.send(message(method, params, key))
        waiting[0].wait(timeout)
        del self._waiting[key]
        return waiting[1]

    # -- replacing the server ----------------------------------------------------------
    def _settle(self, after: int = 0) -> None:
        """Look at the server's memory at each of :data:`SETTLE` after the last didClose,
        until it has let go (a busy machine's server may still be finishing the close at
        the first look)."""
        if self._timer is not None:
            self._timer.cancel()
        if after >= len(SETTLE):
            return
        self._timer = threading.Timer(SETTLE[after] - (SETTLE[after - 1] if after else 0.0), self._replace_if_let_go, (after,))
        self._timer.daemon = True
        self._timer.start()

    def _replace_if_let_go(self, after: int = 0) -> None:
        if not self.replacing.acquire(blocking=False):
            return
        try:
            old = self.server
            if self.initialize is None or self.shut_down or self.client_gone:
                return
            if old.let_go():
                self._replace(old)
            else:
                self._settle(after + 1)
        finally:
            self.replacing.release()

    def _replace(self, old: Server) -> None:
        new = self._start(replacement=True)
        started = self._ask(new, "initialize", self.initialize, STARTING)
        with self.routing:
            documents = self._ask(old, OPEN_DOCUMENTS, None, ANSWERING) if started and "result" in started else None
            if documents is None or not isinstance(documents.get("result"), list) or self.shut_down or self.client_gone:
                new.retired = True  # (what it says goes nowhere)
                new.process.kill()
                return
            old.retired = True
            self.server = new
            if self.initialized:
                new.send(message("initialized", {}))
            for document in documents["result"]:
                new.send(message("textDocument/didOpen", {"textDocument": document}))
        deadline = time.monotonic() + ANSWERING  # it answers what the client asked it, then ends
        while old.asked and time.monotonic() < deadline:
            time.sleep(0.01)
        old.close()


def _key(id_) -> str:
    """A request's id as a key: 1 and "1" are two ids."""
    return json.dumps(id_)


def supervise(package_paths: tuple[str, ...] = ()) -> int:
    """Run the server (``urdfcli lsp --in-process``) under a supervisor on standard input
    and output; the exit code is the server's."""
    # -P: the working folder (the user's workspace) is not put first on the module path,
    # where a folder of it named urdfcli would be imported in place of urdfcli
    command = [sys.executable, "-P", "-m", "urdfcli", "lsp", "--in-process", *(f"--package-path={path}" for path in package_paths)]
    return Supervisor(command, sys.stdin.buffer, sys.stdout.buffer).run()
