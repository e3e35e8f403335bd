"""The Language Server Protocol over standard input and output (pygls): the
protocol's messages in, :class:`~urdfcli.lsp.engine.Engine` calls on one checking
thread, diagnostics and answers out.

Checks are scheduled, not run per keystroke: a change after a pause starts a
check at once, one that follows another within ``DEBOUNCE_SECONDS`` waits until
the changes pause that long, and the changes made while a check runs are checked
together once it ends, each open file with the editor's latest texts. Requests
(hover, definition, completion, code actions) queue on the same thread, so they
see the session as the last check left it; the protocol itself never waits.
"""

from __future__ import annotations

import asyncio
import gc
import logging
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import attrs
from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import from_fs_path, to_fs_path

from ..diagnostics import Severity
from ..report.escape import escape
from ..report.rules import page
from ..rules import REGISTRY
from ..version import __version__
from .engine import Engine, Mark
from .places import Place, Point
from .rulepages import rule_links

# Long enough to take in the changes an editor sends together (a paste, a completion,
# an auto-indent), short enough not to be felt: changes further apart than this, as
# keystrokes are, are each checked at once.
DEBOUNCE_SECONDS = 0.03
SUFFIXES = (".urdf", ".xacro")  # .urdf.xacro included
WATCHED = ("**/*.urdf", "**/*.xacro", "**/package.xml", "**/pyproject.toml", "**/urdfcli.toml", "**/.urdfcli.toml")
SEVERITIES = {Severity.ERROR: types.DiagnosticSeverity.Error, Severity.WARNING: types.DiagnosticSeverity.Warning, Severity.INFO: types.DiagnosticSeverity.Information}

log = logging.getLogger(__name__)


class UrdfServer(LanguageServer):
    """The server's state: the engine and its thread, what each open file's check
    found in each file, and the checks waiting to run."""

    def __init__(self, package_paths: tuple[str, ...] = ()) -> None:
        super().__init__("urdfcli", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Incremental)
        self.engine = Engine(package_paths)
        self.checking = ThreadPoolExecutor(max_workers=1, thread_name_prefix="urdfcli-check")
        self.found: dict[str, dict[str, list[types.Diagnostic]]] = {}  # open file -> file -> what its check found there
        self.reads: dict[str, frozenset[str]] = {}  # open file -> the files its check read
        self.waiting: set[str] = set()
        self.stale: set[str] = set()  # open files whose check is to run again: what they found is not shown
        self.timer: asyncio.TimerHandle | None = None
        self.last_change = 0.0  # the event loop's time of the last change
        self.running: asyncio.Task | None = None
        self.links = rule_links()

    # -- the editor's files ---------------------------------------------------------
    def open_files(self) -> dict[str, str]:
        """The texts of the open URDF and xacro files, by absolute path."""
        found = {}
        for uri, document in list(self.workspace.text_documents.items()):
            path = checkable(uri)
            if path is not None:
                found[path] = document.source
        return found

    def dependents(self, path: str) -> set[str]:
        """The open files whose last check read ``path``, and ``path`` itself."""
        return {path} | {file for file, reads in self.reads.items() if path in reads}

    async def on_engine(self, function, *args):
        """``function(*args)`` on the checking thread, after what is queued there."""
        return await asyncio.get_running_loop().run_in_executor(self.checking, function, *args)

    # -- checks ------------------------------------------------------------------------
    def schedule(self, paths: set[str]) -> None:
        self.waiting |= paths
        loop = asyncio.get_running_loop()
        after_a_pause = loop.time() - self.last_change >= DEBOUNCE_SECONDS
        self.last_change = loop.time()
        if self.running is not None and not self.running.done():
            return  # taken when the running check ends
        if self.timer is not None:
            self.timer.cancel()
        self.timer = loop.call_later(0 if after_a_pause else DEBOUNCE_SECONDS, self._start)

    def _start(self) -> None:
        self.timer = None
        self.running = asyncio.ensure_future(self._check_waiting())

    async def _check_waiting(self) -> None:
        while self.waiting:
            paths, self.waiting = self.waiting, set()
            self.stale = paths & set(self.open_files())
            for path in sorted(self.stale):
                texts, versions = self.open_files(), self.versions()  # the latest, and which they are
                try:
                    checked = await self.on_engine(self.engine.check, path, texts)
                except Exception:  # noqa: BLE001 - logged; the server goes on
                    log.exception("checking %s", escape(path))
                    continue
                finally:
                    self.stale.discard(path)
                if path in self.open_files():  # not closed while it was checked
                    self.reads[path] = checked.reads
                    self.publish(path, {file: [self.diagnostic(m) for m in marks] for file, marks in checked.marks.items()}, versions)
                    self.checking.submit(self.engine.outline, path)  # after publishing: kept for navigation while the text is half-typed
        # The collector runs seldom while a model is read (the command line's setting: a
        # fifth of a check's time otherwise); the garbage of the checks goes now, while idle.
        self.checking.submit(gc.collect)

    def versions(self) -> dict[str, int | None]:
        return {path: document.version for uri, document in list(self.workspace.text_documents.items()) if (path := checkable(uri))}

    def publish(self, path: str, found: dict[str, list[types.Diagnostic]], versions: dict[str, int | None]) -> None:
        """Keep what the check of ``path`` found, and publish ``path`` (its version checked)
        and every other file whose diagnostics changed."""
        before = self.found.pop(path, {})
        if found:
            self.found[path] = found
        for file in sorted(set(before) | set(found)):
            if file == path or before.get(file) != found.get(file):
                self.publish_file(file, versions.get(file))

    def publish_file(self, file: str, version: int | None = None) -> None:
        """All the open files' checks found in ``file``, each diagnostic once, with the
        macro calls of every model that made it."""
        merged: dict[tuple, types.Diagnostic] = {}
        for checked, found in self.found.items():
            if checked in self.stale or checked in self.waiting:
                continue  # to be checked again with the latest texts
            for diagnostic in found.get(file, ()):
                start = diagnostic.range.start
                key = (diagnostic.code, start.line, start.character, diagnostic.message)
                if key not in merged:
                    merged[key] = attrs.evolve(diagnostic, related_information=list(diagnostic.related_information or []) or None)
                    continue
                known = merged[key].related_information or []
                more = [r for r in diagnostic.related_information or () if r not in known]
                if more:
                    merged[key].related_information = known + more
        params = types.PublishDiagnosticsParams(uri=from_fs_path(file), diagnostics=list(merged.values()), version=version)
        self.text_document_publish_diagnostics(params)

    # -- protocol values -----------------------------------------------------------------
    def diagnostic(self, mark: Mark) -> types.Diagnostic:
        found = mark.diagnostic
        link = self.links.get(found.code)
        related = [types.DiagnosticRelatedInformation(types.Location(from_fs_path(p.file), self.range(p)), message) for p, message in mark.related]
        return types.Diagnostic(
            range=self.range(mark.place),
            message=mark.message,
            severity=SEVERITIES[found.severity or Severity.ERROR],
            code=found.code or None,
            code_description=types.CodeDescription(href=link) if link else None,
            source="urdfcli",
            related_information=related or None,
            tags=[types.DiagnosticTag.Unnecessary] if found.code == "U001" else None,
            data={"subjects": list(found.subjects)},
        )

    def range(self, place: Place) -> types.Range:
        return types.Range(self.position(place.start), self.position(place.end))

    def position(self, point: Point) -> types.Position:
        counted = self.workspace.position_codec.position_to_client_units([point.text], types.Position(0, point.character))
        return types.Position(point.line, counted.character)

    def location(self, place: Place) -> types.Location:
        return types.Location(from_fs_path(place.file), self.range(place))

    def cursor(self, uri: str, position: types.Position) -> tuple[str, int, int] | None:
        """The file, 0-based line and character (in code points) of a request's position."""
        path = checkable(uri)
        if path is None:
            return None
        document = self.workspace.get_text_document(uri)
        at = document.position_from_client_units(position)
        return path, at.line, at.character

    def diagnostics_at(self, path: str, position: types.Position) -> list[types.Diagnostic]:
        found = [d for contribution in self.found.values() for d in contribution.get(path, ())]
        return [d for d in found if _within(position, d.range)]


def _within(position: types.Position, range_: types.Range) -> bool:
    at = (position.line, position.character)
    return (range_.start.line, range_.start.character) <= at <= (range_.end.line, range_.end.character)


def checkable(uri: str) -> str | None:
    """The absolute path of a URDF or xacro file's URI; None for anything else."""
    path = to_fs_path(uri) if uri.startswith("file:") else None
    return os.path.abspath(path) if path and path.endswith(SUFFIXES) else None


def rule_hover(diagnostic: types.Diagnostic) -> str:
    rule = REGISTRY.get(str(diagnostic.code)) if diagnostic.code else None
    text = f"**{diagnostic.code or 'urdfcli'}**: {diagnostic.message}"
    return f"{text}\n\n---\n\n{page(rule, level=3)}" if rule is not None else text


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
            ls.checking.submit(ls.engine.forget)  # the disk may have changed while it was closed
            ls.schedule(ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: UrdfServer, params: types.DidChangeTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is not None:
            ls.schedule(ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(ls: UrdfServer, params: types.DidSaveTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is not None:
            ls.checking.submit(ls.engine.forget)
            ls.schedule(ls.dependents(path))

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: UrdfServer, params: types.DidCloseTextDocumentParams) -> None:
        path = checkable(params.text_document.uri)
        if path is None:
            return
        ls.reads.pop(path, None)
        ls.publish(path, {}, {})
        ls.checking.submit(ls.engine.sync, ls.open_files())  # its file on disk stands for it again
        ls.schedule(ls.dependents(path) - {path})

    @server.feature(types.WORKSPACE_DID_CHANGE_WATCHED_FILES)
    def changed_on_disk(ls: UrdfServer, params: types.DidChangeWatchedFilesParams) -> None:
        ls.checking.submit(ls.engine.forget)
        ls.schedule(set(ls.open_files()))

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    async def hover(ls: UrdfServer, params: types.HoverParams) -> types.Hover | None:
        at = ls.cursor(params.text_document.uri, params.position)
        if at is None:
            return None
        parts = [rule_hover(d) for d in ls.diagnostics_at(at[0], params.position)]
        found = await ls.on_engine(ls.engine.hover, *at, ls.open_files())
        parts += [found] if found else []
        return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, "\n\n---\n\n".join(parts))) if parts else None

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    async def definition(ls: UrdfServer, params: types.DefinitionParams) -> list[types.Location] | None:
        at = ls.cursor(params.text_document.uri, params.position)
        if at is None:
            return None
        return [ls.location(place) for place in await ls.on_engine(ls.engine.definition, *at, ls.open_files())] or None

    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=[":", '"', "'", "{"]))
    async def completion(ls: UrdfServer, params: types.CompletionParams) -> types.CompletionList | None:
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
            for c in await ls.on_engine(ls.engine.completion, *at, ls.open_files())
        ]
        return types.CompletionList(is_incomplete=False, items=items)

    @server.feature(types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix]))
    async def code_action(ls: UrdfServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
        path = checkable(params.text_document.uri)
        if path is None:
            return None
        found = []
        for diagnostic in params.context.diagnostics:
            if diagnostic.source != "urdfcli" or not diagnostic.code:
                continue
            subjects = (diagnostic.data or {}).get("subjects", []) if isinstance(diagnostic.data, dict) else []
            for fix in await ls.on_engine(ls.engine.fixes, path, str(diagnostic.code), diagnostic.range.start.line, subjects):
                changes: dict[str, list[types.TextEdit]] = {}
                for place, text in fix.edits:
                    changes.setdefault(from_fs_path(place.file), []).append(types.TextEdit(ls.range(place), text))
                found.append(types.CodeAction(fix.title, kind=types.CodeActionKind.QuickFix, diagnostics=[diagnostic], edit=types.WorkspaceEdit(changes=changes)))
        return found or None

    @server.feature(types.SHUTDOWN)
    def shutdown(ls: UrdfServer, params: None) -> None:
        ls.checking.submit(ls.engine.close)

    return server


COMPLETION_KINDS = {
    "macro": types.CompletionItemKind.Function,
    "keyword": types.CompletionItemKind.Keyword,
    "link": types.CompletionItemKind.Reference,
    "property": types.CompletionItemKind.Constant,
    "parameter": types.CompletionItemKind.Variable,
}


def serve(package_paths: tuple[str, ...] = ()) -> None:
    """Run the server on standard input and output until the client ends it; ``package_paths``
    are ``-P`` options. Raises PackageError for one that is not NAME=DIR or a folder."""
    server = build(package_paths)
    protocol_out = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    # Whatever else would write to standard output (a library, the forked xacro worker)
    # goes to standard error, never into the protocol's stream.
    os.dup2(sys.stderr.fileno(), sys.stdout.fileno())
    sys.stdout = sys.stderr
    # What lives as long as the server (the protocol's types and converters, the rules) is
    # set aside from the collector's scans, here and in the xacro worker forked from it:
    # a collection after each check then takes about a millisecond, not 40.
    gc.collect()
    gc.freeze()
    server.engine.warm()
    try:
        server.start_io(sys.stdin.buffer, protocol_out)
    finally:
        server.checking.shutdown(wait=False, cancel_futures=True)
        server.engine.close()
