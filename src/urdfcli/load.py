"""The loading core: one pipeline from a path to a checked model.

read bytes -> expand xacro where it is used (in a bounded worker, origins
kept) -> read the model's elements one top-level element at a time (lxml,
nothing external; a large document streamed), tolerantly, keeping no tree ->
build the kinematic graph -> run the checks. Nothing here exits the process.
"""

from __future__ import annotations

import functools
import gc
import re
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import NamedTuple

from .diagnostics import Diagnostic, Location
from . import positions
from .document import SUPPRESSION_MARK, Document
from .loaded import Loaded
from .packages import PackageResolver
from .rules import Rule, load_all, load_check
from .xmlsafe import XmlError, parse_bytes, read_by_expat

XACRO_NAMESPACES = {"http://www.ros.org/wiki/xacro", "http://ros.org/wiki/xacro", "http://wiki.ros.org/xacro"}
STDIN = "-"


class InputError(Exception):
    """The input cannot be read at all (exit 2)."""


class LoadOptions(NamedTuple):
    package_paths: tuple[str, ...] = ()
    mappings: dict[str, str] | None = None  # xacro arguments (name:=value)
    checks: str = "check"  # which rules run: "check", "all", or "none"
    runs: Callable[[Rule], bool] | None = None  # of those, the ones the configuration has on (None: all)


def read_input(path: str) -> bytes:
    if path == STDIN:
        return sys.stdin.buffer.read()
    file = Path(path)
    try:
        if file.is_dir():
            raise InputError(f"{path}: is a directory, not a file")
        return file.read_bytes()
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except PermissionError:
        raise InputError(f"{path}: permission denied") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a directory, not a file") from None
    except OSError as error:
        raise InputError(f"{path}: cannot read: {error.strerror}") from None


_XACRO_ELEMENT = "//*[" + " or ".join(f"namespace-uri() = '{ns}'" for ns in sorted(XACRO_NAMESPACES)) + " or (namespace-uri() != '' and starts-with(name(), 'xacro:'))]"
# ${...} and $(...) where xacro evaluates them: attribute values and text (comments are not text here).
_SUBSTITUTION = "//@*[contains(., '${') or contains(., '$(')] | //text()[contains(., '${') or contains(., '$(')]"
_HAS_XACRO_ELEMENT = f"boolean({_XACRO_ELEMENT})"
_USES_XACRO = f"boolean({_XACRO_ELEMENT} | {_SUBSTITUTION})"
_DECLARES_PREFIX = rb"""xmlns:xacro\s*=\s*["']\Z"""  # just before a namespace (compiled when first met)


def is_xacro(data: bytes) -> bool:
    """Whether a document not named .xacro uses xacro: a xacro element (in xacro's
    namespace, or any element prefixed ``xacro:``), or ``${`` / ``$(`` in an attribute
    or in text outside comments. A namespace declaration alone is not use: xacro's
    output would read the same, at many times the cost. A document that is not
    well-formed is not xacro: reading it says what is wrong. The bytes are searched
    first; the document is parsed only when they cannot tell."""
    try:
        searchable = positions.ascii_compatible(data)  # its markup can be searched as bytes
        if searchable and b"$" not in data and b"xacro" not in data:  # ('$' first: a search for one byte is the fastest)
            return False
        if searchable and b"[CDATA[" not in data:  # comments can be told apart by bytes
            if b"$" not in data or not (_written(data, b"${") or _written(data, b"$(")):
                if not _written(data, b"<xacro:") and all(_binds_prefix(data, at) for at in _namespace_mentions(data)):
                    return False  # each mention of xacro's namespace binds the prefix xacro, which no element uses
                # prefixed xacro: (bound to any namespace), or xacro's namespace under another prefix
                return parse_bytes(data).xpath(_HAS_XACRO_ELEMENT)
        return parse_bytes(data).xpath(_USES_XACRO)
    except XmlError:
        return False


def _written(data: bytes, needle: bytes) -> bool:
    """Whether ``needle`` is written in ``data`` outside comments (generated URDFs
    keep their xacro source in comments)."""
    return next(_outside_comments(data, needle), None) is not None


def _outside_comments(data: bytes, needle: bytes) -> Iterator[int]:
    """The offsets of ``needle`` in ``data`` outside comments."""
    at = data.find(needle)
    while at >= 0:
        opened = data.rfind(b"<!--", 0, at)
        if opened < 0 or data.find(b"-->", opened + 4, at) >= 0:
            yield at
            at = data.find(needle, at + len(needle))
            continue
        closed = data.find(b"-->", at)
        at = data.find(needle, closed + 3) if closed >= 0 else -1


def _namespace_mentions(data: bytes) -> Iterator[int]:
    for namespace in XACRO_NAMESPACES:
        yield from _outside_comments(data, namespace.encode())


def _binds_prefix(data: bytes, at: int) -> bool:
    """Whether the mention of xacro's namespace at ``at`` is the value of ``xmlns:xacro``."""
    if re.search(_DECLARES_PREFIX, data[max(0, at - 64) : at]) is None:
        return False
    end = data.find(data[at - 1 : at], at)  # the closing quote
    return data[at:end].decode("ascii", "replace") in XACRO_NAMESPACES


def _error(code: str, message: str, location: Location, hint: str | None = None) -> Diagnostic:
    return Diagnostic.of(code, message, location, None, hint)


def load_document(
    path: str,
    options: LoadOptions,
    data: bytes | None = None,
    force_xacro: bool = False,
    resolver: PackageResolver | None = None,
) -> tuple[Document, list[Diagnostic]]:
    """Read, parse and (for xacro) expand one input. Raises InputError."""
    data = read_input(path) if data is None else data
    file = None if path == STDIN else Path(path)
    shown = "<stdin>" if file is None else path
    if file is None:
        positions.register(shown, data)  # excerpts and columns, as for a file
    named_xacro = force_xacro or path.endswith(".xacro")
    if not (named_xacro or is_xacro(data)):
        return Document(path, data, file), []  # read by model.read
    error = _not_well_formed(data) if named_xacro else None  # (is_xacro parsed the others)
    if error is not None:
        return Document(path, None, file), [_error(error.code, error.message, Location(shown, error.line, error.column))]
    from . import expanded  # xacro itself is imported where it runs: the bounded worker

    resolver = resolver or PackageResolver(options.package_paths, file)
    try:
        result = expanded.expand(data, str(file) if file else None, options.mappings or {}, resolver)
    except expanded.ExpansionError as error:
        location = expanded.located(error.origin, error.file or shown)
        return Document(path, None, file, is_xacro=True, includes=list(error.includes)), [_error(error.code, error.message, location)]
    document = Document(path, result.text.encode("utf-8"), file, True, result.text, result.includes, result.origins)
    warnings = [_error("X005", text, expanded.located(origin, shown)) for text, origin in result.warnings]
    return document, warnings


def _answered_ahead() -> bool:
    """Whether xacro's worker has answered the expansion sent ahead already. The
    model's modules are imported while it works, else once a document is there
    to read: an expansion that failed is reported without them."""
    expanded = sys.modules.get(f"{__package__}.expanded")  # (imported by a run with a xacro input)
    return expanded is not None and expanded.answered_ahead()


def _not_well_formed(data: bytes) -> XmlError | None:
    """Why ``data`` is not a well-formed document, or None when it is."""
    if read_by_expat(data) is not None:
        return None
    try:
        parse_bytes(data)
    except XmlError as error:
        return error
    return None


def _collector_paused(function):
    """Run ``function`` with the cyclic garbage collector paused: a large model is
    millions of small objects without cycles, which it would scan over and over
    while they are built (a quarter of the time on 100,000 links). What it built
    is then set aside from the collector's scans (``gc.freeze``): the first full
    collection after it would otherwise walk the whole model once more, a second
    on 100,000 links. The model is freed all the same, by reference counting."""

    @functools.wraps(function)
    def paused(*args, **kwargs):
        enabled = gc.isenabled()
        gc.disable()
        try:
            return function(*args, **kwargs)
        finally:
            gc.freeze()
            if enabled:
                gc.enable()

    return paused


@_collector_paused
def load(path: str, options: LoadOptions = LoadOptions(), data: bytes | None = None) -> Loaded:
    if not _answered_ahead():
        from . import kinematics, model  # noqa: F401  (while xacro's worker works; see _answered_ahead)
    resolver = PackageResolver(options.package_paths, None if path == STDIN else Path(path))
    document, diagnostics = load_document(path, options, data, resolver=resolver)
    loaded = Loaded(document, diagnostics=diagnostics, resolver=resolver)
    if not document.readable:
        return loaded
    from .kinematics import tree_diagnostics  # the model's modules: only for a document to read
    from .model import read

    try:
        robot, found = read(document, vocabulary=options.checks == "all")
    except Exception as failure:  # noqa: BLE001  (a stream may reach odd markup before the error after it)
        error = failure if isinstance(failure, XmlError) else _not_well_formed(document.data)
        if error is None:
            raise
        document.data, document.readable = None, False
        loaded.diagnostics.append(_error(error.code, error.message, Location(document.shown, error.line, error.column)))
        return loaded
    if not document.is_xacro and document.file is not None:
        document.may_suppress = positions.may_contain(document.data, SUPPRESSION_MARK)
    document.data = None
    loaded.diagnostics += found
    loaded.robot = robot
    if robot.at is None:
        return loaded
    loaded.diagnostics += tree_diagnostics(robot, document)
    if options.checks != "none":
        for spec in (load_check() if options.checks == "check" else load_all()).values():
            if spec.function is not None and (options.checks == "all" or spec.in_check) and (options.runs is None or options.runs(spec)):
                loaded.diagnostics.extend(spec.function(loaded))
    loaded.diagnostics.sort(key=Diagnostic.sort_key)
    return loaded


__all__ = ["InputError", "LoadOptions", "Loaded", "load", "load_document", "read_input"]
