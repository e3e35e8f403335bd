"""An editor for the tests of `urdfcli lsp`: the real server started with
`python -m urdfcli lsp` and driven over stdio by pytest-lsp's client (which also
checks the server's answers against the client's capabilities), with the steps
an editor takes: open, type, save, close, hover, go to definition, complete, fix.

Positions are 0-based lines and characters, as the protocol counts them.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

from lsprotocol import types
from pygls.uris import from_fs_path
from pytest_lsp import LanguageClient, client_capabilities
from pytest_lsp.client import DEFAULT_CLIENT_FEATURES, register_lsp_features
from pygls.protocol import default_converter

TIMEOUT = 60.0  # seconds for one answer: far above any check of these small models


def uri(path: Path) -> str:
    return from_fs_path(str(path))


def position(text: str, needle: str, offset: int = 0) -> types.Position:
    """The position ``offset`` characters into the first ``needle`` of ``text``."""
    at = text.index(needle) + offset
    line = text.count("\n", 0, at)
    return types.Position(line, at - (text.rfind("\n", 0, at) + 1))


class Editor:
    """One server and the documents open in it."""

    def __init__(self, client: LanguageClient, root: Path):
        self.client = client
        self.root = root
        self.texts: dict[Path, str] = {}
        self.versions: dict[Path, int] = {}
        self.published: list[types.PublishDiagnosticsParams] = []
        self.registrations: list[types.Registration] = []
        self.arrived = asyncio.Event()
        self.server: asyncio.subprocess.Process | None = None

    @classmethod
    async def start(cls, root: Path, cache: Path, env: dict[str, str] | None = None, capabilities: str = "visual-studio-code") -> Editor:
        """The server run in ``root``, writing its rule pages under ``cache``."""
        client = LanguageClient(converter_factory=default_converter)
        editor = cls(client, root)

        def published(ls, params: types.PublishDiagnosticsParams) -> None:
            editor.published.append(params)
            editor.arrived.set()

        def register(ls, params: types.RegistrationParams) -> None:
            editor.registrations.extend(params.registrations)

        register_lsp_features(client, {**DEFAULT_CLIENT_FEATURES, types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS: published})
        client.feature(types.CLIENT_REGISTER_CAPABILITY)(register)
        environment = {**os.environ, "XDG_CACHE_HOME": str(cache), **(env or {})}
        await client.start_io(sys.executable, "-m", "urdfcli", "lsp", cwd=str(root), env=environment)
        editor.server = client._server
        await client.initialize_session(
            types.InitializeParams(capabilities=client_capabilities(capabilities), root_uri=uri(root), workspace_folders=[types.WorkspaceFolder(uri(root), root.name)])
        )
        return editor

    async def stop(self) -> None:
        await asyncio.wait_for(self.client.shutdown_session(), TIMEOUT)
        await self.client.stop()

    # -- documents ------------------------------------------------------------------
    def open(self, path: Path, text: str | None = None) -> None:
        self.texts[path] = path.read_text() if text is None else text
        self.versions[path] = 1
        item = types.TextDocumentItem(uri(path), "xml", 1, self.texts[path])
        self.client.text_document_did_open(types.DidOpenTextDocumentParams(item))

    def edit(self, path: Path, old: str, new: str) -> None:
        """Replace the first ``old`` by ``new``, as an editor sends a change: only that range."""
        text = self.texts[path]
        start, end = position(text, old), position(text, old, len(old))
        self.texts[path] = text.replace(old, new, 1)
        self.versions[path] += 1
        change = types.TextDocumentContentChangePartial(types.Range(start, end), new)
        identifier = types.VersionedTextDocumentIdentifier(self.versions[path], uri(path))
        self.client.text_document_did_change(types.DidChangeTextDocumentParams(identifier, [change]))

    def save(self, path: Path) -> None:
        path.write_text(self.texts[path])
        self.client.text_document_did_save(types.DidSaveTextDocumentParams(types.TextDocumentIdentifier(uri(path))))

    def close(self, path: Path) -> None:
        del self.texts[path]
        self.client.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(uri(path))))

    def changed_on_disk(self, *paths: Path) -> None:
        events = [types.FileEvent(uri(p), types.FileChangeType.Changed) for p in paths]
        self.client.workspace_did_change_watched_files(types.DidChangeWatchedFilesParams(events))

    # -- diagnostics ------------------------------------------------------------------
    def mark(self) -> int:
        """Where the diagnostics published from now on start."""
        return len(self.published)

    async def diagnostics(self, path: Path, after: int = 0, timeout: float = TIMEOUT) -> list[types.Diagnostic]:
        """The diagnostics of ``path`` published after ``after``; for an open file, once its
        current text was checked."""
        wanted = uri(path)
        version = self.versions.get(path) if path in self.texts else None
        deadline = asyncio.get_running_loop().time() + timeout
        while True:
            for params in reversed(self.published[after:]):
                if params.uri == wanted and (version is None or (params.version or 0) >= version):
                    return list(params.diagnostics)
            self.arrived.clear()
            left = deadline - asyncio.get_running_loop().time()
            if left <= 0:
                raise TimeoutError(f"no diagnostics for {path.name} (version {version}) within {timeout} s")
            await asyncio.wait_for(self.arrived.wait(), left)

    def latest(self, path: Path) -> list[types.Diagnostic]:
        """The last diagnostics published for ``path`` (none yet: an empty list)."""
        return next((list(p.diagnostics) for p in reversed(self.published) if p.uri == uri(path)), [])

    # -- requests ------------------------------------------------------------------------
    def _at(self, path: Path, needle: str, offset: int) -> tuple[types.TextDocumentIdentifier, types.Position]:
        return types.TextDocumentIdentifier(uri(path)), position(self.texts[path], needle, offset)

    async def hover(self, path: Path, needle: str, offset: int = 1) -> str | None:
        found = await asyncio.wait_for(self.client.text_document_hover_async(types.HoverParams(*self._at(path, needle, offset))), TIMEOUT)
        return found.contents.value if found is not None else None

    async def definition(self, path: Path, needle: str, offset: int = 1) -> list[types.Location]:
        found = await asyncio.wait_for(self.client.text_document_definition_async(types.DefinitionParams(*self._at(path, needle, offset))), TIMEOUT)
        return list(found or [])

    async def completion(self, path: Path, needle: str, offset: int) -> list[types.CompletionItem]:
        found = await asyncio.wait_for(self.client.text_document_completion_async(types.CompletionParams(*self._at(path, needle, offset))), TIMEOUT)
        return list(found.items) if isinstance(found, types.CompletionList) else list(found or [])

    async def code_actions(self, path: Path, diagnostics: list[types.Diagnostic]) -> list[types.CodeAction]:
        whole = types.Range(types.Position(0, 0), types.Position(len(self.texts[path].splitlines()), 0))
        params = types.CodeActionParams(types.TextDocumentIdentifier(uri(path)), whole, types.CodeActionContext(diagnostics))
        return list(await asyncio.wait_for(self.client.text_document_code_action_async(params), TIMEOUT) or [])

    def apply(self, action: types.CodeAction) -> None:
        """Apply a code action's edits to the open documents, as the editor would (sent as changes)."""
        for target, edits in action.edit.changes.items():
            path = next(p for p in self.texts if uri(p) == target)
            for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
                self._replace(path, edit.range, edit.new_text)

    def _replace(self, path: Path, range_: types.Range, new: str) -> None:
        text = self.texts[path]
        lines = text.splitlines(keepends=True)
        start = sum(len(line) for line in lines[: range_.start.line]) + range_.start.character
        end = sum(len(line) for line in lines[: range_.end.line]) + range_.end.character
        self.texts[path] = text[:start] + new + text[end:]
        self.versions[path] += 1
        change = types.TextDocumentContentChangePartial(range_, new)
        identifier = types.VersionedTextDocumentIdentifier(self.versions[path], uri(path))
        self.client.text_document_did_change(types.DidChangeTextDocumentParams(identifier, [change]))


@contextlib.asynccontextmanager
async def editing(root: Path, cache: Path, **options):
    """An :class:`Editor` on a server started for the block, and shut down after it."""
    editor = await Editor.start(root, cache, **options)
    try:
        yield editor
    finally:
        await editor.stop()


def server_memory_kib(editor: Editor, field: str = "Pss") -> int:
    """The memory of the server's processes (the supervisor, the server it runs, their
    xacro workers): the sum of their proportional set sizes (a page shared by several
    counted once in all), in KiB. ``Pss_Anon``: their heaps alone, which no other
    process shares (the libraries' pages are shared with every Python process running
    beside the test, and their proportion moves with those)."""
    return sum(pss_kib(pid, field) for pid in process_tree(editor.server.pid))


def process_tree(pid: int) -> list[int]:
    """``pid`` and the processes under it, running now."""
    parents = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                parents[int(entry.name)] = int((entry / "stat").read_text().rsplit(") ", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):  # gone meanwhile
                continue
    tree = [pid]
    for member in tree:
        tree += [child for child, parent in parents.items() if parent == member]
    return tree


def process_alive(pid: int) -> bool:
    """Whether ``pid`` runs (a process ended but not yet waited for does not)."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split(") ")[-1].split()[0] != "Z"
    except (FileNotFoundError, ProcessLookupError):  # gone before the open, or between the open and the read
        return False


def pss_kib(pid: int, field: str = "Pss") -> int:
    try:
        rollup = Path(f"/proc/{pid}/smaps_rollup").read_text()
    except OSError:  # gone meanwhile
        return 0
    return int(next(line.split()[1] for line in rollup.splitlines() if line.startswith(field + ":")))


class Wire:
    """The server driven message by message over its pipes, for what a well-behaved
    client never sends (invalid params, changes to documents never opened, exit
    without shutdown): the raw JSON-RPC exchange, read on a thread of its own."""

    def __init__(self, root: Path, cache: Path, command: tuple[str, ...] = ("-m", "urdfcli", "lsp")):
        environment = {**os.environ, "XDG_CACHE_HOME": str(cache)}
        self.process = subprocess.Popen(
            [sys.executable, *command], cwd=root, env=environment, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self.received: list[dict] = []
        self.next_id = 0
        threading.Thread(target=self._read, daemon=True).start()

    def send(self, message: dict) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode()
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def request(self, method: str, params) -> dict:
        """The response to a request (with its result or its error)."""
        self.next_id += 1
        asked = self.next_id
        self.send({"id": asked, "method": method, "params": params})
        return self.wait(lambda m: m.get("id") == asked and "method" not in m)

    def notify(self, method: str, params) -> None:
        self.send({"method": method, "params": params})

    def wait(self, wanted, timeout: float = TIMEOUT) -> dict:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = next((m for m in list(self.received) if wanted(m)), None)
            if found is not None:
                return found
            time.sleep(0.01)
        raise TimeoutError("no such message")

    def _read(self) -> None:
        output = self.process.stdout
        while header := output.readline():
            length = int(header.split(b":")[1])
            while output.readline() not in (b"\r\n", b""):
                pass
            self.received.append(json.loads(output.read(length)))

    def initialize(self, root: Path) -> None:
        self.request("initialize", {"processId": None, "rootUri": uri(root), "capabilities": {}})
        self.notify("initialized", {})

    def exit_code(self, timeout: float = TIMEOUT) -> int:
        return self.process.wait(timeout)
