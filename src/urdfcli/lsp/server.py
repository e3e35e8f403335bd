"""The Language Server Protocol over standard input and output (pygls): the
protocol's messages in, checks on one checking thread, diagnostics and answers out.

Checks are scheduled, not run per keystroke: a change after a pause starts a
check at once, one that follows another within ``DEBOUNCE_SECONDS`` waits until
the changes pause that long. The file changed last is checked first, then the
other open files whose last check read it; when that file is a library checked
through the models that include it, the open model the user looked at last (or
from which the library was opened) is checked and published before it. A change to what the running check
reads gives that check up (an expansion it waits for is stopped), as does any
change once it has run ``PREEMPT_SECONDS``: a runaway expression in one file holds
up no other.

A file's diagnostics are published only when every open file's check that reads
it was made with the editor's texts as they are now, with the version checked:
an editor never sees a list that is not the diagnostics of a version it sent,
and a list stays shown until the next one is ready.

Requests (hover, definition, completion, symbols, code actions) are answered on
the protocol's thread from the texts' outlines and the last checks' models
(:class:`~urdfcli.lsp.engine.Navigator`), never after a check.
"""

from __future__ import annotations

import asyncio
import ctypes
import gc
import logging
import os
import queue
import sys
import threading
import time
from collections.abc import Mapping
from concurrent.futures import Future
from typing import NamedTuple

import attrs
from lsprotocol import types
from pygls.exceptions import JsonRpcInvalidParams
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol
from pygls.uris import from_fs_path, to_fs_path

from ..diagnostics import Severity
from ..report.escape import escape
from ..report.rules import page
from ..rules import REGISTRY, Remedy
from ..rules.suppression import U001
from ..version import __version__
from .engine import Checked, Checker, Fix, Mark, Navigator
from .places import Place, Point
from .rulepages import rule_links
from .supervisor import OPEN_DOCUMENTS

# Long enough to take in the changes an editor sends together (a paste, a completion,
# an auto-indent), short enough not to be felt: changes further apart than this, as
# keystrokes are, are each checked at once.
DEBOUNCE_SECONDS = 0.03
# A check running longer than this is given up for a change to any file (and run again
# after the files changed since): a runaway expression or a huge model waits its turn.
PREEMPT_SECONDS = 1.0
# How long a code action waits for the checking thread to find an <inertial> fix
# before it answers with what the text alone gives.
FIX_WAIT_SECONDS = 0.08
SUFFIXES = (".urdf", ".xacro")  # .urdf.xacro included
WATCHED = ("**/*.urdf", "**/*.xacro", "**/package.xml", "**/pyproject.toml", "**/urdfcli.toml", "**/.urdfcli.toml")
SEVERITIES = {Severity.ERROR: types.DiagnosticSeverity.Error, Severity.WARNING: types.DiagnosticSeverity.Warning, Severity.INFO: types.DiagnosticSeverity.Information}
DOCUMENT_NOTIFICATIONS = (types.TEXT_DOCUMENT_DID_CHANGE, types.TEXT_DOCUMENT_DID_SAVE, types.TEXT_DOCUMENT_DID_CLOSE)
RELATED_SHOWN = 20  # macro calls listed with one diagnostic
FIX_ALL = "source.fixAll.urdfcli"  # the "fix all safe" action's kind: an editor's fix-all on save asks for source.fixAll

log = logging.getLogger(__name__)


class CheckingThread:
    """One daemon thread running the jobs given to it, in order: the checker's. A
    daemon, so that the server exits at once whatever check runs."""

    def __init__(self) -> None:
        self.jobs: queue.SimpleQueue = queue.SimpleQueue()
        threading.Thread(target=self._serve, name="urdfcli-check", daemon=True).start()

    def submit(self, function, *args) -> Future:
        future: Future = Future()
        self.jobs.put((future, function, args))
        return future

    def _serve(self) -> None:
        while True:
            future, function, args = self.jobs.get()
            if not future.set_running_or_notify_cancel():
                continue
            try:
                future.set_result(function(*args))
            except Exception as error:  # noqa: BLE001 - given to whoever waits for it
                future.set_exception(error)
            del future, function, args  # (a check's texts are not kept until the next job)


class Contribution(NamedTuple):
    """What the last check of an open file found, file by file."""

    found: dict[str, list[types.Diagnostic]]
    reads: frozenset[str]
    models: Mapping[tuple, frozenset[str]]  # each model it went through (its absolute path, its arguments) -> the files it read
    library: bool  # checked through models other than the file itself

    def covered_by(self, own: Contribution, file: str) -> bool:
        """Whether ``own``, the check of ``file``, went through every model of this check
        that read ``file``: then it found all that this one finds in it."""
        return bool(self.models) and all(model in own.models for model, reads in self.models.items() if file in reads)


class Running(NamedTuple):
    path: str
    started: float  # the event loop's time
    reads: frozenset[str]  # what its last check read: a change to one of them gives it up


class Protocol(LanguageServerProtocol):
    """pygls's protocol, with an error response for a request whose params do not fit
    its method, notifications about documents never opened ignored (logged), and
    nothing kept of a notification once handled."""

    _ANSWERED = object()

    def structure_message(self, data):
        try:
            return super().structure_message(data)
        except JsonRpcInvalidParams:
            method = escape(str(data.get("method", "")))
            if "id" in data and "method" in data:
                self._send_response(data["id"], error=types.ResponseError(types.ErrorCodes.InvalidParams, f"invalid params for {method}"))
            else:
                log.warning("ignored %s: its params do not fit it", method)
            return self._ANSWERED

    def handle_message(self, message):
        if message is self._ANSWERED:
            return
        if getattr(message, "method", None) in DOCUMENT_NOTIFICATIONS:
            uri = message.params.text_document.uri
            if uri not in self.workspace.text_documents:
                self._server.window_log_message(types.LogMessageParams(types.MessageType.Log, f"ignored {message.method} for {escape(uri)}: not open"))
                return
        super().handle_message(message)
        if getattr(message, "id", None) is None:
            # pygls keeps the future of a notification's handler under a key of its own and
            # never lets go of it: 1 KB for every keystroke, but for this
            for key in [key for key, future in self._request_futures.items() if future.done()]:
                del self._request_futures[key]


def _not_deserialization(record: logging.LogRecord) -> bool:
    """pygls logs a traceback for params that do not fit their method; the server says so
    in one line (and answers the request with an error)."""
    return not str(record.msg).startswith("Unable to deserialize message")


class UrdfServer(LanguageServer):
    """The server's state: the checker and its thread, what each open file's check
    found in each file, and the checks waiting to run."""

    def __init__(self, package_paths: tuple[str, ...] = ()) -> None:
        super().__init__("urdfcli", __version__, protocol_cls=Protocol, text_document_sync_kind=types.TextDocumentSyncKind.Incremental)
        self.checker = Checker(package_paths)
        self.navigator = Navigator(package_paths, self.checker.session.files)
        self.thread = CheckingThread()
        self.contributions: dict[str, Contribution] = {}  # open file -> what its last check found
        self.dirty: dict[str, float] = {}  # open file -> when a check of it was asked for (the latest first)
        self.pending: set[str] = set()  # files to publish once every check reading them is current
        self.checked: set[str] = set()  # open files checked since their list was last published: published even if unchanged
        self.shown: dict[str, tuple[int | None, list[types.Diagnostic]]] = {}  # file -> its last published version and list
        self.uris: dict[str, str] = {}  # open file -> its URI as the client sent it
        self.looked: dict[str, float] = {}  # open file -> when the user last did something in it, or in a file opened from it
        self.opened_from: dict[str, str] = {}  # open file -> the file the user was in when opening it
        self.running: Running | None = None
        self.timer: asyncio.TimerHandle | None = None
        self.last_change = 0.0  # the event loop's time of the last change
        self.task: asyncio.Task | None = None
        self.shut_down = False
        self.exit_code = 1  # the protocol's: 0 only for an exit after a shutdown
        self.links = rule_links()
        self.memory = Memory()

    def report_server_error(self, error: Exception, source) -> None:
        """Logged, never shown in a pop-up: a request gets its error response anyway."""
        log.error("%s: %s", type(error).__name__, error)

    # -- the editor's files ---------------------------------------------------------
    def open_files(self) -> dict[str, str]:
        """The texts of the open URDF and xacro files, by absolute path."""
        found = {}
        for uri, document in list(self.workspace.text_documents.items()):
            path = checkable(uri)
            if path is not None:
                found[path] = document.source
        return found

    def versions(self) -> dict[str, int | None]:
        return {path: document.version for uri, document in list(self.workspace.text_documents.items()) if (path := checkable(uri))}

    def dependents(self, path: str) -> set[str]:
        """The open files whose last check read ``path``, and ``path`` itself."""
        return {path} | {file for file, found in self.contributions.items() if path in found.reads}

    def look(self, path: str) -> None:
        """The user does something in ``path`` (opens, edits, saves it, asks about it); in a
        library, in the file it was opened from too (the model it was opened from)."""
        now = time.monotonic()
        self.looked[path] = now
        found = self.contributions.get(path)
        if path in self.opened_from and found is not None and found.library:
            self.looked[self.opened_from[path]] = now

    def watched_model(self, changed: str | None, paths: set[str]) -> str | None:
        """Of the models among ``paths``, the one the user looked at last, when ``changed``
        is a library checked through models: its check runs, and is published, before
        the library's own through them all."""
        found = self.contributions.get(changed) if changed is not None else None
        if found is None or not found.library:
            return None
        models = [path for path in paths if path != changed and path in self.contributions and not self.contributions[path].library]
        return max(models, key=lambda path: self.looked.get(path, 0.0), default=None)

    def navigate(self) -> Navigator:
        self.navigator.sync(self.open_files())
        return self.navigator

    # -- checks ------------------------------------------------------------------------
    def schedule(self, changed: str | None, paths: set[str]) -> None:
        """Check ``paths`` (``changed`` first), giving up a running check that they outdate."""
        loop = asyncio.get_running_loop()
        now = loop.time()
        for path in paths:
            self.dirty[path] = now
        if changed in self.dirty:
            self.dirty[changed] = now + 1e-6  # the file the user works on comes first
        watched = self.watched_model(changed, paths)
        if watched is not None:
            self.dirty[watched] = now + 2e-6  # but before a library, the model the user looks at
        running = self.running
        if running is not None and (changed in running.reads or changed == running.path or now - running.started > PREEMPT_SECONDS):
            self.checker.give_up()
        after_a_pause = now - self.last_change >= DEBOUNCE_SECONDS
        self.last_change = now
        if self.task is not None and not self.task.done():
            return  # taken when the running check ends
        if self.timer is not None:
            self.timer.cancel()
        self.timer = loop.call_later(0 if after_a_pause else DEBOUNCE_SECONDS, self._start)

    def _start(self) -> None:
        self.timer = None
        self.task = asyncio.ensure_future(self._check_waiting())

    async def _check_waiting(self) -> None:
        loop = asyncio.get_running_loop()
        while self.dirty:
            path = max(self.dirty, key=self.dirty.__getitem__)
            asked = self.dirty[path]
            texts, versions = self.open_files(), self.versions()
            if path not in texts:
                del self.dirty[path]
                continue
            before = self.contributions.get(path)
            self.running = Running(path, loop.time(), before.reads if before else frozenset())
            self.checker.begin()  # here, not on the checking thread: a give-up that comes before the check starts counts
            try:
                checked = await asyncio.wrap_future(self.thread.submit(self.checker.check, path, texts))
            except Exception:  # noqa: BLE001 - logged; the server goes on
                log.exception("checking %s", escape(path))
                self.dirty.pop(path, None)
                continue
            finally:
                self.running = None
            if checked is None:
                continue  # given up: checked again, after what changed
            now = self.versions()
            if any(now.get(file) != versions.get(file) for file in checked.reads):
                self.dirty.setdefault(path, asked)  # checked with texts changed since: again
                continue
            if self.dirty.get(path) == asked:
                del self.dirty[path]
            self.keep(path, checked, texts)
        # The collector runs seldom while a model is read (the command line's setting: a
        # fifth of a check's time otherwise); the garbage of the checks goes now, while idle.
        self.thread.submit(self.memory.give_back)
        self.navigator.sync(self.open_files())  # what it holds of texts changed or closed goes too

    def keep(self, path: str, checked: Checked, texts: dict[str, str]) -> None:
        """Keep what the check of ``path`` found, and publish what is ready."""
        before = self.contributions.get(path)
        found = {file: [self.diagnostic(m) for m in marks] for file, marks in checked.marks.items()}
        self.contributions[path] = Contribution(found, checked.reads, checked.models, checked.library)
        self.pending |= {path, *found, *(before.found if before else ())}
        self.checked.add(path)
        self.publish_ready()
        # after publishing: the models it lets go of are freed then (a large model's take 15 ms)
        self.navigator.keep(path, checked.run, texts)

    def publish_ready(self) -> None:
        """Publish each pending file whose every contributing check is current: when
        its list or version changed, and an open file just checked in any case.

        An open file's own check that went through every model of another check that
        read the file found all that one finds in it: that one is not waited for."""
        busy = set(self.dirty) | ({self.running.path} if self.running else set())
        versions = self.versions()
        for file in sorted(self.pending):
            own = self.contributions.get(file) if file not in busy else None
            waited = [
                checked
                for checked, found in self.contributions.items()
                if checked in busy and (file in found.found or file in found.reads)
                and not (own is not None and found.covered_by(own, file))
            ]
            if waited or file in busy:
                continue
            self.pending.discard(file)
            diagnostics = merged(found.found.get(file, ()) for checked, found in self.contributions.items() if checked not in busy)
            shown = (versions.get(file), diagnostics)
            if self.shown.get(file) == shown and file not in self.checked:
                continue
            self.checked.discard(file)
            self.shown[file] = shown
            if not diagnostics and file not in versions:
                del self.shown[file]  # closed, and nothing left to show
            uri = self.uris.get(file) or from_fs_path(file)
            self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics, version=versions.get(file)))

    def close(self, path: str) -> None:
        found = self.contributions.pop(path, None)
        self.dirty.pop(path, None)
        self.uris.pop(path, None)
        self.looked.pop(path, None)
        self.opened_from = {file: opener for file, opener in self.opened_from.items() if path not in (file, opener)}
        self.pending |= {path, *(found.found if found else ())}
        self.navigator.sync(self.open_files())
        self.navigator.keep(path, None)
        self.thread.submit(self.checker.sync, self.open_files())  # its file on disk stands for it again
        self.publish_ready()
        self.thread.submit(self.memory.give_back)

    # -- protocol values -----------------------------------------------------------------
    def diagnostic(self, mark: Mark) -> types.Diagnostic:
        found = mark.diagnostic
        link = self.links.get(found.code)
        related = [types.DiagnosticRelatedInformation(self.location(place), message) for place, message in mark.related]
        return types.Diagnostic(
            range=self.range(mark.place),
            message=mark.message,
            severity=SEVERITIES[found.severity or Severity.ERROR],
            code=found.code or None,
            code_description=types.CodeDescription(href=link) if link else None,
            source="urdfcli",
            related_information=related or None,
            tags=[types.DiagnosticTag.Unnecessary] if found.code == U001.code else None,
            data={"subjects": list(found.subjects)},
        )

    def range(self, place: Place) -> types.Range:
        return types.Range(self.position(place.start), self.position(place.end))

    def position(self, point: Point) -> types.Position:
        counted = self.workspace.position_codec.position_to_client_units([point.text], types.Position(0, point.character))
        return types.Position(point.line, counted.character)

    def location(self, place: Place) -> types.Location:
        return types.Location(self.uris.get(place.file) or from_fs_path(place.file), self.range(place))

    def cursor(self, uri: str, position: types.Position) -> tuple[str, int, int] | None:
        """The file, 0-based line and character (in code points) of a request's position;
        None for a document not open (logged) or not a URDF or xacro file."""
        path = checkable(uri)
        if path is None:
            return None
        document = self.workspace.text_documents.get(uri)
        if document is None:
            self.window_log_message(types.LogMessageParams(types.MessageType.Log, f"no answer for {escape(uri)}: not open"))
            return None
        self.look(path)
        at = document.position_from_client_units(position)
        return path, at.line, at.character

    def workspace_edit(self, fix: Fix) -> types.WorkspaceEdit:
        changes: dict[str, list[types.TextEdit]] = {}
        for place, text in fix.edits:
            changes.setdefault(self.uris.get(place.file) or from_fs_path(place.file), []).append(types.TextEdit(self.range(place), text))
        return types.WorkspaceEdit(changes=changes)

    def diagnostics_at(self, path: str, position: types.Position) -> list[types.Diagnostic]:
        shown = self.shown.get(path)
        return [d for d in (shown[1] if shown else ()) if _within(position, d.range)]


class Memory:
    """Gives the memory a check freed back to the system: the garbage collected, then
    glibc's allocator trimmed (it keeps what a large file's check freed otherwise,
    hundreds of MiB after a 50 MB model, though nothing uses it).

    Python's attribute cache is emptied first: it holds on to the attribute names
    looked up last, strings a check made, each a few bytes that keep a whole MiB
    arena of Python's allocator in use. It fills again at the next lookups.

    ``malloc_trim`` is looked up once, here: a look-up makes ctypes objects that live
    on, and made after a large file's check they would stay in its arenas too."""

    def __init__(self) -> None:
        try:
            self._trim = ctypes.CDLL("libc.so.6").malloc_trim
        except (OSError, AttributeError):  # not glibc: its allocator decides
            self._trim = None

    def give_back(self) -> None:
        sys._clear_type_cache()
        gc.collect()
        if self._trim is not None:
            self._trim(0)


def merged(contributions) -> list[types.Diagnostic]:
    """The diagnostics of one file from every check: each once, with the macro calls of
    every model that made it; those of one rule starting on one line as one, counted."""
    by_line: dict[tuple, list[types.Diagnostic]] = {}
    for found in contributions:
        for diagnostic in found:
            by_line.setdefault((diagnostic.code, diagnostic.range.start.line), []).append(diagnostic)
    result = []
    for same in by_line.values():
        messages = list(dict.fromkeys(d.message for d in same))
        first = same[0]
        related: list[types.DiagnosticRelatedInformation] = []
        for r in (r for d in same for r in d.related_information or ()):
            if r not in related and len(related) < RELATED_SHOWN:
                related.append(r)
        message = first.message
        if len(messages) > 1:
            head, hint, rest = message.partition("\nhint: ")
            message = f"{head}\n(and {len(messages) - 1} more like it on this line){hint}{rest}"
        subjects = list(dict.fromkeys(s for d in same for s in (d.data or {}).get("subjects", ())))
        result.append(attrs.evolve(first, message=message, related_information=related or None, data={"subjects": subjects}))
    return result


def asked(kind: str, only: list[str]) -> bool:
    """Whether a code action of ``kind`` is asked for by a request's ``only`` kinds (none: every kind)."""
    return not only or any(kind == wanted or kind.startswith(wanted + ".") for wanted in only)


def _within(position: types.Position, range_: types.Range) -> bool:
    at = (position.line, position.character)
    return (range_.start.line, range_.start.character) <= at <= (range_.end.line, range_.end.character)


def checkable(uri: str) -> str | None:
    """The absolute path of a URDF or xacro file's URI; None for anything else."""
    path = to_fs_path(uri) if uri.startswith("file:") else None
    return os.path.abspath(path) if path and path.endswith(SUFFIXES) else None


def rule_hover(diagnostics: list[types.Diagnostic]) -> list[str]:
    """Each diagnostic's message, then each rule's page once."""
    parts = [f"**{d.code or 'urdfcli'}**: {d.message}" for d in diagnostics]
    codes = dict.fromkeys(str(d.code) for d in diagnostics if d.code)
    return parts + [page(REGISTRY[code], level=3) for code in codes if code in REGISTRY]


# -- the handlers ------------------------------------------------------------------------------
def build(package_paths: tuple[str, ...] = ()) -> UrdfServer:
    server = UrdfServer(package_paths)

    @server.feature(types.INITIALIZED)
    async def initialized(ls: UrdfServer, params: types.InitializedParams) -> None:
        watching = ls.client_capabilities.workspace and ls.client_capabilities.workspace.did_change_watched_files
        if watching and watching.dynamic_registration:
            options = types.DidChangeWatchedFilesRegistrationOptions([types.FileSystemWatcher(glob) for glob in WATCHED])
            registration = types.Registration("urdfcli-files", types.WORKSPACE_DID_CHANGE_WATCHED_FILES, options)
            await ls.client_register_capability_async(types.RegistrationParams([registration]))

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: UrdfServer, params: types.DidOpenTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is not None:
            ls.uris[path] = params.text_document.uri
            opener = max((file for file in ls.looked if file != path), key=ls.looked.__getitem__, default=None)
            if opener is not None:
                ls.opened_from[path] = opener
            ls.look(path)
            ls.thread.submit(ls.checker.forget)  # the disk may have changed while it was closed
            ls.navigator.forget()
            ls.schedule(path, ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: UrdfServer, params: types.DidChangeTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is not None:
            ls.look(path)
            ls.schedule(path, ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(ls: UrdfServer, params: types.DidSaveTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is not None:
            ls.look(path)
            ls.thread.submit(ls.checker.forget)
            ls.navigator.forget()
            ls.schedule(path, ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: UrdfServer, params: types.DidCloseTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is None:
            return
        readers = ls.dependents(path) - {path}
        ls.close(path)
        ls.schedule(None, readers)

    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def changed_on_disk(ls: UrdfServer, params: types.DidChangeWatchedFilesParams) -> None:
        ls.thread.submit(ls.checker.forget)
        ls.navigator.forget()
        ls.schedule(None, set(ls.open_files()))

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    def hover(ls: UrdfServer, params: types.HoverParams) -> types.Hover | None:
        at = ls.cursor(params.text_document.uri, params.position)
        if at is None:
            return None
        parts = rule_hover(ls.diagnostics_at(at[0], params.position))
        found = ls.navigate().hover(*at)
        parts += [found] if found else []
        return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, "\n\n---\n\n".join(parts))) if parts else None

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    def definition(ls: UrdfServer, params: types.DefinitionParams) -> list[types.Location] | None:
        at = ls.cursor(params.text_document.uri, params.position)
        if at is None:
            return None
        return [ls.location(place) for place in ls.navigate().definition(*at)] or None

    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=[":", '"', "'", "{"]))
    def completion(ls: UrdfServer, params: types.CompletionParams) -> types.CompletionList | None:
        at = ls.cursor(params.text_document.uri, params.position)
        if at is None:
            return None
        items = [
            types.CompletionItem(
                label=c.item.label,
                kind=COMPLETION_KINDS[c.item.kind],
                detail=c.item.detail,
                text_edit=types.TextEdit(ls.range(c.place), c.item.label),
            )
            for c in ls.navigate().completion(*at)
        ]
        return types.CompletionList(is_incomplete=False, items=items)

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def symbols(ls: UrdfServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol] | None:
        path = checkable(params.text_document.uri)
        if path is None or params.text_document.uri not in ls.workspace.text_documents:
            return None
        ls.look(path)
        return [
            types.DocumentSymbol(escape(name) or '""', SYMBOL_KINDS[kind], ls.range(place), ls.range(place), detail=escape(f"{kind} {detail}".strip()))
            for kind, name, detail, place in ls.navigate().symbols(path)
        ]

    @server.feature(types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix, FIX_ALL]))
    async def code_action(ls: UrdfServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
        path = checkable(params.text_document.uri)
        if path is None or params.text_document.uri not in ls.workspace.text_documents:
            return None
        ls.look(path)
        only = [str(getattr(kind, "value", kind)) for kind in params.context.only or ()]
        found = []
        for diagnostic in params.context.diagnostics if asked(types.CodeActionKind.QuickFix, only) else ():
            if diagnostic.source != "urdfcli" or not diagnostic.code:
                continue
            code = str(diagnostic.code)
            subjects = (diagnostic.data or {}).get("subjects", []) if isinstance(diagnostic.data, dict) else []
            noqa = ls.navigate().noqa(path, code, diagnostic.range.start.line)
            fixes = [*ls.navigator.own_fixes(path, code, diagnostic.range.start.line), *([noqa] if noqa is not None else [])]
            if subjects and REGISTRY.get(code) is not None and REGISTRY[code].remedy is Remedy.INERTIAL:
                # the audit needs the checking thread: while a check runs, waited for a moment, else left out
                job = ls.thread.submit(ls.checker.inertial_fixes, path, code, subjects)
                busy = ls.running is not None or bool(ls.dirty)
                try:
                    fixes += await asyncio.wait_for(asyncio.shield(asyncio.wrap_future(job)), FIX_WAIT_SECONDS if busy else None)
                except asyncio.TimeoutError:
                    job.cancel()
            found += [types.CodeAction(fix.title, kind=types.CodeActionKind.QuickFix, diagnostics=[diagnostic], edit=ls.workspace_edit(fix)) for fix in fixes]
        every = ls.navigate().fix_all(path) if asked(FIX_ALL, only) else None
        if every is not None:
            found.append(types.CodeAction(every.title, kind=FIX_ALL, edit=ls.workspace_edit(every)))
        return found or None

    @server.feature(types.SHUTDOWN)
    def shutdown(ls: UrdfServer, params: None) -> None:
        ls.shut_down = True
        ls.checker.give_up()

    @server.feature(types.EXIT)
    def exit_(ls: UrdfServer, params: None) -> None:
        ls.exit_code = 0 if ls.shut_down else 1

    @server.feature(OPEN_DOCUMENTS)
    def open_documents(ls: UrdfServer, params) -> list[dict]:
        """The supervisor's: the documents open, as the client's didOpen gives them, the
        one the user looked at last at the end (a server that replaces this one checks it first)."""
        documents = sorted(ls.workspace.text_documents.values(), key=lambda d: ls.looked.get(checkable(d.uri) or "", 0.0))
        return [{"uri": d.uri, "languageId": d.language_id or "", "version": d.version or 0, "text": d.source} for d in documents]

    return server


COMPLETION_KINDS = {
    "macro": types.CompletionItemKind.Function,
    "keyword": types.CompletionItemKind.Keyword,
    "link": types.CompletionItemKind.Reference,
    "property": types.CompletionItemKind.Constant,
    "parameter": types.CompletionItemKind.Variable,
}
SYMBOL_KINDS = {
    "macro": types.SymbolKind.Function,
    "property": types.SymbolKind.Constant,
    "arg": types.SymbolKind.Variable,
    "link": types.SymbolKind.Struct,
    "joint": types.SymbolKind.Interface,
}


def make_converters(protocol: LanguageServerProtocol) -> None:
    """The protocol's converters for every message the server handles, made now rather than
    when the first such message arrives: made while a large file is open (its first
    ``didClose``), they would keep arenas of Python's allocator that its checks filled in
    use once it is closed."""
    for method in {*protocol.fm.builtin_features, *protocol.fm.features, types.CANCEL_REQUEST}:
        message = types.METHOD_TO_TYPES.get(method, (None,))[0]
        if message is not None:
            protocol.fm.converter.get_structure_hook(message)


def serve(package_paths: tuple[str, ...] = ()) -> int:
    """Run the server on standard input and output until the client ends it (or is
    gone); ``package_paths`` are ``-P`` options. The exit code, as the protocol says:
    0 after ``shutdown`` then ``exit``, else 1. Raises PackageError for a ``-P`` that
    is not NAME=DIR or a folder."""
    server = build(package_paths)
    logging.getLogger("pygls.protocol.json_rpc").addFilter(_not_deserialization)
    protocol_out = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    # Whatever else would write to standard output (a library, the forked xacro worker)
    # goes to standard error, never into the protocol's stream.
    os.dup2(sys.stderr.fileno(), sys.stdout.fileno())
    sys.stdout = sys.stderr
    # What lives as long as the server (the protocol's types and converters, the rules) is
    # set aside from the collector's scans, here and in the xacro worker forked from it:
    # a collection after each check then takes about a millisecond, not 40.
    make_converters(server.protocol)
    gc.collect()
    gc.freeze()
    server.checker.warm()
    try:
        server.start_io(sys.stdin.buffer, protocol_out)
    finally:
        # the running check is given up (its expansion stopped); the checking thread is a
        # daemon, so nothing waits for it
        server.checker.give_up()
    return server.exit_code
