"""The editor server's work, without the protocol, in two parts that share nothing
mutable:

- :class:`Checker` runs on the server's checking thread: one session for the
  server's lifetime, the editor's unsaved texts given to it, the checks, and the
  quick fixes that need a model's audit. A check is :func:`urdfcli.api.run` on one
  file, as ``urdfcli lint`` runs it (configuration, ``noqa`` comments, a library
  checked through the models that include it), each diagnostic placed in the file
  it points into, and, when a macro call's arguments caused it, at that call too.
  A check can be given up from another thread (:meth:`Checker.give_up`): it stops
  at its next expansion, and an expansion running then is stopped.
- :class:`Navigator` answers hover, definition, completion, document symbols,
  the ``noqa`` fix and the fixes the diagnostics carry on the protocol's thread,
  at once, from the texts' outlines and the models of the last checks, whatever
  check is running.

Paths are absolute.
"""

from __future__ import annotations

import difflib
import functools
import os
import threading
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import NamedTuple

from .. import api
from ..diagnostics import Call, Diagnostic, Location, Severity
from ..project.config import ConfigError
from ..project.workspace import resolve_include
from ..read.document import STDIN
from ..read.packages import PackageResolver
from ..read.expanded import Expansion
from ..read.files import SourceFile, SourceFiles, file_key
from ..read.positions import Text
from ..read.xacro import Expander
from ..model import fixes
from ..model.audit import LinkAudit
from ..model.result import Result
from ..report.escape import escape
from ..options import Options, RuleSet
from ..rules import REGISTRY, Remedy
from ..session import Session
from . import actions, navigation
from .outline import Outline, encoded, outline
from .places import Place, offset, offset_place, token_place

OUTLINES_KEPT = 64  # outlines of files not open (included libraries) kept for navigation
NAME_RULES = frozenset({"N004", "N005", "N006"})  # what they find is the element's own name: a call's ${prefix} can make it
REFERENCE_RULES = frozenset({"J005", "J008", "D006", "D007"})  # what they find is a name the element refers to, missing from the model


class Mark(NamedTuple):
    """A diagnostic placed in the file it points into, with the text to show."""

    diagnostic: Diagnostic
    place: Place
    message: str
    related: tuple[tuple[Place, str], ...] = ()


class Checked(NamedTuple):
    marks: dict[str, list[Mark]]  # file -> its diagnostics
    reads: frozenset[str]  # the files the check read: a change to any calls for it again
    run: api.Run | None  # the models navigation keeps (None: none yet)
    models: Mapping[tuple, frozenset[str]] = {}  # each model this check went through (its absolute path, its arguments) -> the files it read
    library: bool = False  # checked through models other than itself (a file they include)


class Completion(NamedTuple):
    item: navigation.Item
    place: Place  # the text it replaces


class Fix(NamedTuple):
    title: str
    edits: tuple[tuple[Place, str], ...]


class GivenUp(BaseException):
    """A check given up by the server (its texts changed, or another file comes first).
    Not an Exception: nothing on the way up may take it for a problem of the model."""


class _Expander(Expander):
    """The session's expander, stopping before each expansion of a check given up, and
    expanding a model again only when a file it read changed: a library's check and the
    check of an open model that includes it (or a second keystroke elsewhere) share one
    expansion. One expansion is kept per model, argument set and package settings."""

    def __init__(self, giving_up: threading.Event, files: SourceFiles) -> None:
        super().__init__()
        self.giving_up = giving_up
        self.files = files
        self.kept: dict[tuple, tuple[bytes, dict[str, bytes | None], Expansion]] = {}  # key -> (data, each file read: its bytes, the expansion)

    def expand(self, data: bytes, file: str | None, mappings: dict[str, str], resolver: PackageResolver, given: dict[str, bytes] | None = None) -> Expansion:
        if self.giving_up.is_set():
            raise GivenUp
        given = given or {}
        # (a model is named relative to the working folder by a library's check, absolute by its own)
        settings = tuple(file_key(setting) if isinstance(setting, os.PathLike) else setting for setting in resolver.settings())
        key = (file and file_key(file), tuple(sorted(mappings.items())), settings)
        kept = self.kept.get(key)
        if kept is not None and kept[0] == data and all(self._bytes(f, given) == read for f, read in kept[1].items()):
            return kept[2]
        expansion = super().expand(data, file, mappings, resolver, given)
        if not self.giving_up.is_set():  # (what an expansion stopped for it made is not kept)
            self.kept[key] = (data, {f: self._bytes(f, given) for f in map(file_key, expansion.includes)}, expansion)
        return expansion

    def _bytes(self, file: str, given: dict[str, bytes]) -> bytes | None:
        """The file's bytes as an expansion now reads them (None: it cannot be read)."""
        if file in given:
            return given[file]
        found = self.files.get(file)
        return found.data if found is not None else None

    def forget(self, file: str | None = None) -> None:
        """Let go of the expansions of ``file`` (a file closed), or of every one (a change on disk)."""
        self.kept = {key: kept for key, kept in self.kept.items() if file is not None and key[0] != file}


class Checker:
    """The checks, on one thread: every method but :meth:`give_up` runs there."""

    def __init__(self, package_paths: tuple[str, ...] = ()) -> None:
        self.session = Session(Options(RuleSet.LINT, package_paths=package_paths))  # an editor shows every rule the configuration selects
        self.giving_up = threading.Event()
        self.session.expander = _Expander(self.giving_up, self.session.files)
        self.texts: dict[str, str] = {}  # the editor's texts given to the session
        self.runs: dict[str, api.Run] = {}  # each open file's last check that read models

    # -- the editor's texts ---------------------------------------------------------
    def sync(self, texts: dict[str, str]) -> None:
        """Let the editor's texts stand for their files; a file no longer open is read from disk again."""
        for path in [p for p in self.texts if p not in texts]:
            self.session.files.take_back(path)
            self.session.expander.forget(path)
            del self.texts[path]
            self.runs.pop(path, None)
        for path, text in texts.items():
            if self.texts.get(path) != text:
                self.session.files.give(path, encoded(text))
                self.texts[path] = text

    def forget(self) -> None:
        """Something changed on disk (a checkout, a new package or configuration file)."""
        self.session.forget()
        self.session.expander.forget()

    def close(self) -> None:
        self.session.close()

    def warm(self) -> None:
        """Start the xacro worker now, while the server has one thread, rather than at the first check."""
        self.session.expander.expand(b'<robot name="warm" xmlns:xacro="http://www.ros.org/wiki/xacro"/>', None, {}, PackageResolver())

    def begin(self) -> None:
        """From the thread that gives checks up: a check is about to be asked for."""
        self.giving_up.clear()

    def give_up(self) -> None:
        """From another thread: stop the running check (it raises GivenUp) and the expansion it waits for."""
        self.giving_up.set()
        self.session.expander.worker.interrupt()

    # -- checking -------------------------------------------------------------------
    def check(self, path: str, texts: dict[str, str]) -> Checked | None:
        """Check one open file with the editor's texts standing for their files; None
        when :meth:`give_up` was called since :meth:`begin`."""
        if self.giving_up.is_set():
            return None  # given up before it began
        by_target = {os.path.realpath(path): path for path in texts}  # (a file opened at its symlink in a built workspace's install/)
        self.sync({**texts, **{real: texts[path] for real, path in by_target.items() if real not in texts}})  # $(find) reads src/'s
        try:
            run = api.run([path], self.session)
        except GivenUp:
            return None
        except api.UsageError as error:
            self.runs.pop(path, None)
            return Checked({path: [self._problem(path, f"urdfcli cannot check this file: {error}")]}, frozenset({path}), None)
        except Exception as error:  # noqa: BLE001 - a bug of urdfcli's must not stop the server
            self.runs.pop(path, None)
            message = f"urdfcli internal error ({type(error).__name__}: {error}); please report this bug with the file"
            return Checked({path: [self._problem(path, message)]}, frozenset({path}), None)
        if self.giving_up.is_set():  # what an expansion stopped for it found is not the model's
            return None
        if path not in self.runs or any(m.robot is not None for m in run.models):
            self.runs[path] = run  # navigation keeps the models of the last check that read any
        marks: dict[str, list[Mark]] = {path: []}
        opened = _opened_as(texts, by_target)
        known = functools.cache(lambda: frozenset(n for m in run.models if m.robot is not None for n in (*m.robot.links, *m.robot.joints)))
        for diagnostic, note in _labelled(run.results):
            mark = self.mark(diagnostic, note)
            file = opened(mark.place.file)
            marks.setdefault(file, []).append(mark)
            for call in self._calls_that_caused(mark, known):
                if opened(call.place.file) in texts and opened(call.place.file) != file:
                    marks.setdefault(opened(call.place.file), []).append(call)
        for reason in [*map(str, run.unreadable), *(n for r in run.results if r.library for n in r.library.notes)]:
            marks[path].append(self._problem(path, reason, Severity.INFO))
        models = {(_absolute(m.path), m.arguments): frozenset(_files([m])) for m in run.models}  # (a library's check names models relative, their own absolute)
        library = any(_absolute(m.path) != path for m in run.models)
        return Checked(marks, frozenset({path, *_files(run.models)}), self.runs.get(path), models, library)

    def mark(self, diagnostic: Diagnostic, note: str = "") -> Mark:
        location = diagnostic.location
        file = _absolute(location.file)
        message = escape(diagnostic.message) + note
        line = location.line
        if location.expanded:  # no place in the sources: said in the message
            message += f" (line {line} of the xacro expansion)" if line else ""
            line = None
        if diagnostic.hint:
            message += "\nhint: " + escape(diagnostic.hint)
        related = tuple((self.place(_absolute(c.file), c.line, c.column), f"in macro '{escape(c.macro)}' called here") for c in location.trace)
        return Mark(diagnostic, self.place(file, line, location.column if line else None), message, related)

    def _calls_that_caused(self, mark: Mark, known: Callable[[], frozenset[str]]) -> list[Mark]:
        """The same diagnostic at each macro call whose arguments made the element it is
        about: the innermost call when the element uses its macro's parameters (in its
        ``name`` only for the rules about names; for a name it refers to that the model
        lacks, only when the name's literal text fits one of ``known()``, the model's
        names: else the body's text is what is wrong), the call around that one when the
        inner call passes its own macro's parameters on, and so on. The element's own
        place is the related information."""
        location = mark.diagnostic.location
        if location.expanded or not location.line or not location.trace:
            return []
        found: list[Mark] = []
        written = (_absolute(location.file), location.line, location.column)
        maker = location.trace[0].macro  # the macro whose body wrote the element, whichever call is marked
        names, refers = mark.diagnostic.code in NAME_RULES, mark.diagnostic.code in REFERENCE_RULES
        for call in location.trace:
            values = self._parameter_values(*written, names)
            if not values or (refers and not any(navigation.fits_a_name(value, known()) for value in values)):
                break
            names, refers = True, False  # (a call's every attribute is an argument)
            found.append(self._at_call(mark, call, maker))
            written = (_absolute(call.file), call.line, call.column)
        return found

    def _parameter_values(self, file: str, line: int | None, column: int | None, names: bool) -> list[str]:
        source = self.session.files.get(file)
        if source is None or not line or source.line(line) is None:
            return []
        return navigation.parameter_values(source.text, offset(source, line - 1, (column or 1) - 1), names)

    def _at_call(self, mark: Mark, call: Call, maker: str) -> Mark:
        """``mark`` at a call that caused it, its message saying where macro ``maker`` wrote it."""
        macro = escape(maker)
        written = f"{Path(mark.place.file).name}:{mark.place.start.line + 1}"
        message = f"{mark.message} (in macro '{macro}', {escape(written)})"
        return Mark(mark.diagnostic, self.place(_absolute(call.file), call.line, call.column), message, ((mark.place, f"written here in macro '{macro}'"),))

    def _problem(self, path: str, message: str, severity: Severity = Severity.ERROR) -> Mark:
        """What is not a rule's diagnostic (an unusable configuration, a library's note), at the file's top."""
        return Mark(Diagnostic("", message, Location(path), severity=severity), self.place(path, None, None), escape(message))

    def place(self, file: str, line: int | None, column: int | None) -> Place:
        return token_place(file, self.session.files.get(file), line, column)

    # -- quick fixes that need the model ---------------------------------------------
    def inertial_fixes(self, path: str, code: str, subjects: Iterable[str]) -> list[Fix]:
        """The ``<inertial>`` fixes of one diagnostic in ``path`` (its code, the links it is about)."""
        rule = REGISTRY.get(code)
        if rule is None or rule.remedy is not Remedy.INERTIAL:
            return []
        return [fix for link in subjects if (fix := self._inertial_fix(path, code, link)) is not None]

    def _inertial_fix(self, path: str, code: str, name: str) -> Fix | None:
        """The ``<inertial>`` ``urdfcli inertia --suggest`` gives for a link, in place of the
        one written; for one a macro call wrote, the call that gives those values. From
        the first model whose audit finds ``code`` on that link."""
        for model in _models_reading(self.runs, path):
            audit = api.audit(model.loaded, api.configured(self.session)(model.path)) if model.loaded is not None else None
            entry = next((e for e in audit.links if e.link.name == name), None) if audit is not None else None
            if entry is not None and entry.link.inertial is not None and any(d.code == code for d in entry.problems):
                return self._replacement(model, entry)
        return None

    def _replacement(self, model: Result, entry: LinkAudit) -> Fix | None:
        link = entry.link
        loaded = model.loaded
        suggested = fixes.suggestion(loaded, entry)
        if "<inertial>" not in suggested:
            return None  # the geometry cannot tell
        use = fixes.macro_use(loaded, link)
        if use is not None and use.called_at is not None:
            file, _, line = use.called_at.rpartition(":")
            call = fixes.matching_call(loaded, link, use, self.session.expander)
            if call is not None:
                title = f"Call {use.name} with the values the geometry of link '{link.name}' gives"
            else:
                title = f"Replace the call of {use.name} by the <inertial> of a uniform body filling the geometry of link '{link.name}'"
            return self._replace(_absolute(file), int(line), f"<xacro:{use.name}", call or suggested, title)
        where = loaded.document.locate(link.inertial.at)
        if where.trace or not where.line or where.expanded:
            return None  # written in a macro's body for every call: no one edit fixes this link alone
        return self._replace(_absolute(where.file), where.line, "<inertial", suggested, f"Replace the <inertial> of link '{link.name}' by a uniform body filling its geometry")

    def _replace(self, file: str, line: int, tag: str, replacement: str, title: str) -> Fix | None:
        source = self.session.files.get(file)
        text = source.line(line) if source is not None else None
        column = text.find(tag) + 1 if text is not None and tag in text else None
        edit = actions.replace_element(source, line, column, replacement) if column else None
        if edit is None:
            return None
        return Fix(escape(title), ((offset_place(file, source, edit.start, edit.end), edit.text),))


class Navigator:
    """Hover, definition, completion, symbols and the ``noqa`` fix, on the protocol's
    thread: from the editor's texts (and the files on disk), their outlines, and the
    models of the last checks handed over by :meth:`keep`."""

    def __init__(self, package_paths: tuple[str, ...] = (), files: SourceFiles | None = None) -> None:
        # its configurations and package look-ups (it never expands); ``files`` the checks' (one object per buffer)
        self.session = Session(Options(RuleSet.LINT, package_paths=package_paths), files)
        self.texts: dict[str, str] = {}
        self.runs: dict[str, api.Run] = {}  # each open file's last check that read models
        self._outlines: dict[str, tuple[SourceFile, Outline]] = {}  # file -> (its source, its last well-formed outline)
        self._places: dict[int, tuple] = {}  # id(run) -> (run, its links' and joints' places)
        self.checked_texts: dict[str, str] = {}  # open file -> its text as the last check of it read it
        self._run_texts: dict[str, dict[str, str]] = {}  # open file -> the texts its run in ``runs`` was made with
        self._moves: dict[str, tuple[str, str, list]] = {}  # file -> (text checked, text now, their diff)

    def sync(self, texts: dict[str, str]) -> None:
        for path in [p for p in self.texts if p not in texts]:
            self.session.files.take_back(path)
            del self.texts[path]
            self.runs.pop(path, None)
            self._run_texts.pop(path, None)
            self._outlines.pop(path, None)
            self.checked_texts.pop(path, None)
            self._moves.pop(path, None)
        if len(self._outlines) > len(texts) + OUTLINES_KEPT:  # of files not open: read again when needed
            for path in [p for p in self._outlines if p not in texts]:
                del self._outlines[path]
        for path, text in texts.items():
            if self.texts.get(path) is not text:
                self.session.files.give(path, encoded(text))
                self.texts[path] = text

    def keep(self, path: str, run: api.Run | None, texts: dict[str, str] | None = None) -> None:
        """The models of the last check of ``path`` (None: it read none, the earlier ones
        stay), and the texts it was made with."""
        if run is not None:
            self.runs[path] = run
            self._run_texts[path] = dict(texts or {})
        for file, text in (texts or {}).items():
            self.checked_texts[file] = text
        live = {id(r) for r in self.runs.values()}
        self._places = {key: value for key, value in self._places.items() if key in live}

    def forget(self) -> None:
        self.session.forget()  # (a file on disk is read again anyway when it changes)

    # -- requests -------------------------------------------------------------------
    def hover(self, path: str, line: int, character: int) -> str | None:
        source, at = self._at(path, line, character)
        return navigation.hover(source.text, at, self.scope(path))

    def definition(self, path: str, line: int, character: int) -> list[Place]:
        source, at = self._at(path, line, character)
        return [self.place(_absolute(found.file), found.line, found.column) for found in navigation.definition(source.text, at, self.scope(path))]

    def completion(self, path: str, line: int, character: int) -> list[Completion]:
        source, at = self._at(path, line, character)
        return [Completion(item, offset_place(path, source, item.start, item.end)) for item in navigation.completion(source.text, at, self.scope(path))]

    def symbols(self, path: str) -> list[tuple[str, str, str, Place]]:
        """(kind, name, detail, place) of what the file defines, in its order."""
        found = self.outline(path)
        return [(d.kind, d.name, d.detail, self.place(path, d.line, d.column)) for d in found.definitions] if found else []

    def noqa(self, path: str, code: str, line: int) -> Fix | None:
        """The ``noqa`` comment that silences one diagnostic of ``path`` (its 0-based line)."""
        source = self.session.files.get(path)
        edit = actions.noqa(source, line + 1, code) if source is not None and code in REGISTRY else None
        if edit is None:
            return None
        return Fix(f"Silence {code} on this element (noqa comment)", ((offset_place(path, source, edit.start, edit.end), edit.text),))

    def own_fixes(self, path: str, code: str, line: int) -> list[Fix]:
        """The fixes the diagnostics of ``code`` at ``line`` (0-based) of ``path`` carry, as
        `lint --fix` writes them: only while the texts they edit are those checked."""
        found = []
        for fix in actions.own_fixes(self._diagnostics(path), path, code, line):
            edits = actions.fix_edits(fix, self.session.files) if self._unchanged(path, fix) else None
            if edits is not None:
                found.append(Fix(escape(actions.fix_title(fix)), edits))
        return found

    def fix_all(self, path: str) -> Fix | None:
        """Every safe fix of the last check of ``path`` (what `urdfcli lint --fix` applies
        first), as one change of the files; None when there is none, or the texts changed."""
        chosen = [fix for fix in actions.fix_all(self._diagnostics(path), path) if self._unchanged(path, fix)]
        edits = [edit for fix in chosen for edit in actions.fix_edits(fix, self.session.files) or ()]
        return Fix("Fix all safe urdfcli problems", tuple(edits)) if edits else None

    def _diagnostics(self, path: str) -> list[Diagnostic]:
        run = self.runs.get(path)
        return [d for result in run.results for d in result.diagnostics] if run is not None else []

    def _unchanged(self, path: str, fix) -> bool:
        """Whether every file ``fix`` edits has the text the check of ``path`` that found it read
        (a file not open: as on disk)."""
        made_with = self._run_texts.get(path, {})
        return all(self.texts.get(file) == made_with.get(file) for file in {os.path.abspath(e.file) for e in fix.edits})

    def place(self, file: str, line: int | None, column: int | None) -> Place:
        return token_place(file, self.session.files.get(file), line, column)

    def _at(self, path: str, line: int, character: int) -> tuple[Text, int]:
        """The text of ``path`` as the editor has it now, and the offset of a position in it."""
        source = self.session.files.get(path) or Text("")
        return source, offset(source, line, character)

    def scope(self, path: str) -> navigation.Scope:
        """What names the file shares: its outline, then those of the files it includes
        (statically, and as its last check read them), then the models that include it."""
        models = _models_reading(self.runs, path)
        files = list(dict.fromkeys([path, *_files(models)]))
        outlines: list[Outline] = []
        for file in files:  # grows as includes are found
            found = self.outline(file)
            if found is None:
                continue
            outlines.append(found)
            for include in found.includes:
                target = self._file_named(file, include.value)
                if target is not None and str(target) not in files:
                    files.append(str(target))
        links, joints = (_Moved(found, self.line_now) for found in self._named_places(models))
        resolver = self._resolver(path)
        return navigation.Scope(tuple(outlines), links, joints, resolver.find, lambda value: self._file_named(path, value))

    def _named_places(self, models: list[Result]) -> tuple[dict, dict]:
        links: dict[str, tuple[Location, ...]] = {}
        joints: dict[str, tuple[Location, ...]] = {}
        for model in models:
            known = self._places.get(id(model))
            if known is None or known[0] is not model:
                known = self._places[id(model)] = (model, *_named_places([model]))
            for name, places in known[1].items():
                links.setdefault(name, places)
            for name, places in known[2].items():
                joints.setdefault(name, places)
        return links, joints

    def line_now(self, file: str, line: int | None) -> int | None:
        """Where a line of ``file`` as the last check read it is in the editor's text now
        (edits since move it); the line itself when the text is the same or not open."""
        file = _absolute(file)
        checked, now = self.checked_texts.get(file), self.texts.get(file)
        if line is None or checked is None or now is None or checked is now or checked == now:
            return line
        known = self._moves.get(file)
        if known is None or known[0] is not checked or known[1] is not now:
            opcodes = difflib.SequenceMatcher(None, checked.splitlines(), now.splitlines(), autojunk=False).get_opcodes()
            known = self._moves[file] = (checked, now, opcodes)
        for tag, old_start, old_end, new_start, new_end in known[2]:
            if old_start < line <= old_end:  # 1-based line in this block
                return new_start + (line - old_start) if tag == "equal" else new_start + 1
        return line

    def outline(self, file: str) -> Outline | None:
        """The file's outline; while its text is not well-formed, the last one that was."""
        source = self.session.files.get(file)
        if source is None:
            return None
        known = self._outlines.get(file)
        if known is not None and known[0] is source:
            return known[1]
        found = outline(file, source)
        if found is None:
            return known[1] if known else None
        self._outlines[file] = (source, found)
        return found

    def _resolver(self, file: str) -> PackageResolver:
        try:
            extra = self.session.configs.for_input(file).package_paths
        except ConfigError:
            extra = ()
        try:
            return self.session.resolver(extra, Path(file))
        except ValueError:  # a package path that is no folder: checking says so
            return PackageResolver((), Path(file), index=self.session.packages)

    def _file_named(self, file: str, value: str) -> Path | None:
        """The file an include's filename or a mesh's URI in ``file`` leads to."""
        resolver = self._resolver(file)
        if value.startswith(("package://", "file://")):
            return resolver.resolve_uri(value, Path(file).parent)
        found = self.outline(file)
        if found is None:
            return None
        include = resolve_include(value, found.declared, resolver.find, source_of=resolver.source_of)
        return Path(include.value) if include.kind == "path" else None


class _Moved(Mapping):
    """Places of links or joints as the last check found them, each line moved to where
    the editor's text has it now."""

    def __init__(self, places: dict[str, tuple[Location, ...]], line_now) -> None:
        self.places, self.line_now = places, line_now

    def __getitem__(self, name: str) -> tuple[Location, ...]:
        return tuple(self._moved(location) for location in self.places[name])

    def __iter__(self):
        return iter(self.places)

    def __len__(self) -> int:
        return len(self.places)

    def _moved(self, location: Location) -> Location:
        trace = tuple(call._replace(line=self.line_now(call.file, call.line)) for call in location.trace)
        return location._replace(line=self.line_now(location.file, location.line), trace=trace)


def _models_reading(runs: dict[str, api.Run], path: str) -> list[Result]:
    """The models that the last checks of the open files expanded and that read
    ``path`` (each once, the latest check's), those of its own check first."""
    ordered = [runs[path]] if path in runs else []
    ordered += [run for file, run in runs.items() if file != path]
    found: dict[str, Result] = {}
    for run in ordered:
        for model in run.models:
            if path in _files([model]):
                found.setdefault(model.label, model)
    return list(found.values())


def _opened_as(texts: Mapping[str, str], by_target: Mapping[str, str]):
    """The path under which the editor opened a file (``by_target``: each open file's real
    path -> the path opened): a built workspace's ``install/`` holds symlinks into ``src/``,
    where diagnostics are placed; a buffer opened at the link gets them."""
    seen: dict[str, str] = {}

    def opened(file: str) -> str:
        if file in texts:
            return file
        if file not in seen:
            seen[file] = by_target.get(os.path.realpath(file), file)
        return seen[file]

    return opened


def _absolute(file: str) -> str:
    return file if file == STDIN else os.path.abspath(file)


def _files(models: Iterable[Result]) -> list[str]:
    """The models and every file their expansions read."""
    return list(dict.fromkeys(_absolute(f) for model in models for f in (model.path, *model.includes)))


def _named_places(models: Iterable[Result]) -> tuple[dict[str, tuple[Location, ...]], dict[str, tuple[Location, ...]]]:
    """Each link and joint of the expanded models, where it was written (with its macro calls)."""
    links: dict[str, tuple[Location, ...]] = {}
    joints: dict[str, tuple[Location, ...]] = {}
    for model in models:
        robot, document = model.robot, model.loaded.document
        if robot is None:
            continue
        for named, found in ((robot.links, links), (robot.joints, joints)):
            for name, part in named.items():
                location = document.locate(part.at)
                found.setdefault(name, (location._replace(file=_absolute(location.file)),))
    return links, joints


def _labelled(results: list[Result]) -> list[tuple[Diagnostic, str]]:
    """Each diagnostic once; for a model checked with several argument sets, one that
    only some of them give says which."""
    if len(results) == 1:
        return [(d, "") for d in results[0].diagnostics]
    given: dict[tuple, tuple[Diagnostic, list[str]]] = {}
    for result in results:
        arguments = " ".join(f"{k}:={v}" for k, v in result.arguments)
        for diagnostic in result.diagnostics:
            key = (diagnostic.code, diagnostic.location, diagnostic.message)
            given.setdefault(key, (diagnostic, []))[1].append(arguments)
    return [(d, "" if len(args) == len(results) else f" (with {'; '.join(escape(a) for a in args)})") for d, args in given.values()]
