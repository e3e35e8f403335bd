"""In-process xacro expansion that remembers where every element was written.

The real ``xacro`` package does the expansion. Before xacro sees a file, every
element is marked with where it was written (file, line, column), as DOM user
data, which minidom hands to each copy of a node through its handler (xacro
copies each macro body it expands); so after expansion each element still says
where it was written. The marks are no part of the document: the output is
exactly what the ``xacro`` tool prints.

This module runs in the bounded worker (:func:`expand_here`, asked for by
:meth:`urdfcli.read.xacro.Expander.expand`): only the worker imports xacro.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import sys
import xml.dom.minicompat
import xml.dom.minidom
import xml.parsers.expat
from array import array
from pathlib import Path
from typing import TYPE_CHECKING

import xacro
import xacro.substitution_args

from ..diagnostics import Call
from . import guard
from .expanded import Expansion, ExpansionError, Origin, Origins, PackageNotFound, display_path
from .names import cut_from, typo_of
from .packages import closest_file
from .positions import Text, decode
from .xml import XmlError, parse

if TYPE_CHECKING:
    from .packages import PackageResolver

ORIGIN = "urdfcli-origin"  # an element's user data: the Origin where it was written
# The same for one of xacro's own tags: it tells where xacro is, but the element xacro
# makes of such a tag (<xacro:element>) is given no origin (the expanded line is shown).
XACRO_TAG_ORIGIN = "urdfcli-xacro-tag-origin"
DEFINED = "urdfcli_defined"  # a xacro symbol table's attribute: where each lazy property was defined
TRACE = "urdfcli-trace"  # an element's user data: the macro calls whose output starts at it (indices), innermost first
XACRO_PREFIX = "xacro:"


class _KeptOnCopies(xml.dom.UserDataHandler):
    """Gives each copy minidom makes of a marked node (xacro copies each macro body it
    expands, and each block it inserts) the node's marks."""

    def handle(self, operation, key, data, src, dst) -> None:
        dst.setUserData(key, data, self)


_KEPT_ON_COPIES = _KeptOnCopies()


class NearbyNodeList(xml.dom.minicompat.NodeList):
    """A list of child nodes (a subclass of minidom's, given to the nodes of the documents
    urdfcli parses for xacro) that looks for a child first where it last found one.
    xacro replaces each macro call by its output with ``insertBefore`` and
    ``removeChild``, which search the siblings from the first: on a model of a thousand
    top-level calls, half of its time. The lists change exactly as minidom's do, so the
    output is byte for byte xacro's (tests/test_differential.py); minidom itself is left
    as it is."""

    __slots__ = ("_last",)

    def _near(self, node) -> int:
        last = getattr(self, "_last", 0)
        for at in (last, last + 1, last - 1, last + 2):
            if 0 <= at < len(self) and self[at] is node:
                break
        else:
            at = list.index(self, node)
        self._last = at
        return at

    def index(self, node, *bounds) -> int:
        return list.index(self, node, *bounds) if bounds else self._near(node)

    def remove(self, node) -> None:
        del self[self._near(node)]


def tagged_dom(data: bytes, file: str) -> xml.dom.minidom.Document:
    """``data`` parsed as xacro parses it (minidom, its only parse here), every element
    marked (user data ORIGIN) with where its ``<`` was written: the text's element
    starts, in document order, are the elements'. Raises XmlError when urdfcli's reader
    refuses the document (not well-formed, entities declared), which then says what is
    wrong where; ExpansionError when only xacro's parser refuses it."""
    try:
        doc = xml.dom.minidom.parseString(data)
    except xml.parsers.expat.ExpatError as error:
        parse(data)  # urdfcli's reader says what is wrong and where, when it refuses the document too
        message = f"xacro cannot read this document: {xml.parsers.expat.ErrorString(error.code)}"  # XML 1.0 5th-edition names that expat refuses
        raise ExpansionError(message, Origin(file, error.lineno, error.offset + 1), file, code="X001") from None
    if doc.doctype is not None:
        parse(data)  # urdfcli's reader refuses what a document type declares or names (entities, an external subset)
    elements = doc.getElementsByTagName("*")
    text = Text(decode(data))
    starts = text.element_starts(len(elements))
    for at, element in enumerate(elements):
        line, column = text.position(starts[at]) if starts is not None else (0, 0)  # unknown then
        key = XACRO_TAG_ORIGIN if element.tagName.startswith(XACRO_PREFIX) else ORIGIN
        element.setUserData(key, Origin(file, line, column or None), _KEPT_ON_COPIES)
        element.childNodes = NearbyNodeList(element.childNodes)
    doc.childNodes = NearbyNodeList(doc.childNodes)
    return doc


class _Session:
    """Patches xacro's module functions for one expansion, and undoes it."""

    TRACKED = ("eval_all", "grab_property", "grab_macro", "process_include")
    TOUCHED = ("check_attrs", "reqd_attrs")

    def __init__(self, resolver: PackageResolver, given: dict[str, bytes]):
        self.resolver = resolver
        self.found: dict[str, Path] = {}  # each package $(find) gave: its folder
        self.given = given  # texts that stand for files (absolute path -> bytes)
        self.stack: list[object] = []
        self.touched: object | None = None
        self.saved: dict[tuple[object, str], object] = {}  # (module or class, name) -> the original
        self.resolving: list[tuple] = []  # the places of the lazy properties being evaluated, innermost last
        self.calling: list[object] = []  # the macro calls being expanded, outermost first
        self.calls: list[Call] = []  # each macro call site once, by its index in TRACE attributes
        self.call_index: dict[Call, int] = {}
        self.warnings: list[tuple[str, Origin | None, bool]] = []  # (words, where, whether the model's xacro.error())
        self.documents: list[xml.dom.minidom.Document] = []  # each file included, as parsed

    # -- where is xacro now --------------------------------------------------
    def origin_of(self, node) -> Origin | None:
        while node is not None and getattr(node, "nodeType", None) == xml.dom.Node.ELEMENT_NODE:
            origin = node.getUserData(ORIGIN) or node.getUserData(XACRO_TAG_ORIGIN)
            if origin is not None:
                return origin
            node = node.parentNode
        return None

    def locate(self, error: BaseException) -> None:
        """Mark an error with where xacro is, unless a deeper frame already did."""
        if not hasattr(error, "urdfcli_origin"):
            error.urdfcli_origin = self.current_origin()

    def place(self) -> tuple:
        """What tells where xacro is now: the node it is at, the tag whose attributes
        it reads, and the macro calls it is inside (worked out into an Origin only when
        one is asked for)."""
        return (self.stack[-1] if self.stack else None, self.touched, tuple(self.calling))

    def current_origin(self) -> Origin | None:
        """Where xacro is now, with the macro calls it is inside, innermost first.
        While it evaluates a lazy property, that is where the property was defined:
        xacro evaluates it where it is first used, but what goes wrong or warns
        there is written in the definition."""
        top, touched, calling = self.resolving[-1] if self.resolving else self.place()
        if touched is not None and top is not None and getattr(touched, "parentNode", None) is top:
            origin = self.origin_of(touched)
        else:
            origin = self.origin_of(top)
        if origin is None:
            return None
        trace = tuple(self.calls[i] for i in reversed([self.call_of(node) for node in calling]) if i is not None)
        if trace and (trace[0].file, trace[0].line, trace[0].column) == (origin.file, origin.line, origin.column):
            trace = trace[1:]  # xacro is at the call itself (its parameters)
        return Origin(origin.file, origin.line, origin.column, trace) if trace else origin

    def call_of(self, node) -> int | None:
        """The index of a macro call node's call site (None when unknown)."""
        origin = self.origin_of(node)
        if origin is None:
            return None
        call = Call(origin.file, origin.line or None, origin.column, node.tagName[len(XACRO_PREFIX):])
        index = self.call_index.get(call)
        if index is None:
            index = self.call_index[call] = len(self.calls)
            self.calls.append(call)
        return index

    def stamp(self, node, body) -> None:
        """Mark the top elements a macro call made with its call site; their
        descendants inherit it (see _collect_origins)."""
        index = self.call_of(node)
        if index is None:
            return
        child = body.firstChild
        while child is not None:
            if child.nodeType == xml.dom.Node.ELEMENT_NODE:
                child.setUserData(TRACE, (child.getUserData(TRACE) or ()) + (index,), _KEPT_ON_COPIES)
            child = child.nextSibling

    # -- patches ---------------------------------------------------------------
    def track(self, original, calls: bool = False):
        """``original`` wrapped to keep where xacro is; with ``calls`` (``handle_macro_call``),
        also the macro calls it is inside. xacro asks that of every element; one not in
        xacro's namespace is no call, and xacro answers so at once."""

        def tracked(node, *args, **kwargs):
            if calls and not node.tagName.startswith(XACRO_PREFIX):
                return original(node, *args, **kwargs)
            self.stack.append(node)
            if calls:
                self.calling.append(node)
            try:
                return original(node, *args, **kwargs)
            except Exception as error:
                self.locate(error)
                raise
            finally:
                self.stack.pop()
                if calls:
                    self.calling.pop()

        return tracked

    def define(self, original):
        """Keep the place of each property xacro will evaluate lazily, in its table."""

        def _setitem(table, key, value, unevaluated):
            original(table, key, value, unevaluated)
            if key in table.unevaluated:
                table.__dict__.setdefault(DEFINED, {})[key] = self.place()

        return _setitem

    def resolve(self, original):
        """While xacro evaluates a lazy property, it is at the property's definition."""

        def _resolve_(table, key):
            if key not in table.unevaluated:
                return original(table, key)
            self.resolving.append(table.__dict__.get(DEFINED, {}).get(key) or self.place())
            try:
                return original(table, key)
            except Exception as error:
                self.locate(error)
                raise
            finally:
                self.resolving.pop()

        return _resolve_

    def replace_node(self, node, by, content_only=False):
        """xacro puts a macro's output in place of its call here: stamp it first."""
        if content_only and by is not None and self.calling and node is self.calling[-1]:
            self.stamp(node, by)
        return self.saved[xacro, "replace_node"](node, by, content_only)

    def touch(self, original):
        def touched(tag, *args, **kwargs):
            self.touched = tag
            return original(tag, *args, **kwargs)

        return touched

    def parse(self, inp, filename=None):
        if inp is not None:
            return self.saved[xacro, "parse"](inp, filename)
        path = os.path.join(xacro.root_dir, filename)
        if os.path.abspath(path) in {os.path.abspath(f) for f in xacro.filestack[:-1] if f}:
            chain = " -> ".join(display_path(f) for f in [*xacro.filestack[:-1], filename] if f)
            xacro.filestack.pop()
            raise xacro.XacroException(f"include cycle: {chain}")
        path = self.resolver.source_of(path)  # a file of the workspace's install space: its source, which the user edits
        try:
            data = self.given.get(os.path.abspath(path)) or Path(path).read_bytes()
        except OSError as error:
            uri = _package_uri(filename)  # shown as written: the path xacro made of it reads 'package:/' nowhere in the file
            failure = xacro.XacroException(f"cannot include {uri or display_path(path)}: {error.strerror}", exc=error)
            failure.urdfcli_hint = _package_uri_hint(uri) if uri else self.empty_in_path(filename) or self.installed_elsewhere(path)
            xacro.filestack.pop()
            raise failure from None
        if not data.lstrip(b"\xef\xbb\xbf \t\r\n").startswith(b"<"):  # never show a line of a non-XML file
            xacro.filestack.pop()
            raise xacro.XacroException(f"cannot include {display_path(path)}: it is not an XML file")
        try:
            self.documents.append(tagged_dom(data, display_path(path)))
            return self.documents[-1]
        except XmlError as error:
            xacro.filestack.pop()
            raise ExpansionError(
                f"XML syntax error in included file: {error.message}",
                Origin(display_path(path), error.line or 0, error.column),
                display_path(path),
                code="X001",
            ) from None

    def find(self, package: str) -> str:
        folder = self.resolver.find(package)
        if folder is None:
            raise PackageNotFound(package)
        self.found[package] = folder
        return str(folder)

    def empty_in_path(self, filename: str) -> str | None:
        """For an include whose file name a substitution left out: which one was empty
        (``arms/${arm}/${dof}dof/...`` with ``dof`` empty reads ``arms/gen3/dof/...``), and,
        when an argument of that name is empty, to give it; None when none was, or when
        which one was cannot be told (two substitutions side by side)."""
        include = self.stack[-1] if self.stack else None
        written = include.getAttribute("filename") if include is not None else ""
        pieces = _SUBSTITUTION.split(written)
        if len(pieces) < 2:
            return None
        pattern = "".join(re.escape(piece) if at % 2 == 0 else "(.*?)" for at, piece in enumerate(pieces)) + r"\Z"
        lazy, greedy = re.search(pattern, filename), re.search(pattern.replace("(.*?)", "(.*)"), filename)
        if lazy is None or greedy is None:
            return None
        empty = [at for at in range(1, lazy.re.groups + 1) if lazy.group(at) == "" and greedy.group(at) == ""]
        if not empty:
            return None
        token = pieces[2 * empty[0] - 1]
        name = _SUBSTITUTION_NAME.fullmatch(token)
        arguments = xacro.substitution_args_context.get("arg") or {}
        if name is not None and arguments.get(name.group(1) or name.group(2)) == "":
            argument = name.group(1) or name.group(2)
            return f"{token} is empty here, which leaves it out of the path: xacro argument '{argument}' is empty; pass {argument}:=VALUE"
        return f"{token} is empty here, which leaves it out of the path: give it a value"

    def unprefixed_property(self, doc: xml.dom.minidom.Document, error: BaseException) -> str | None:
        """For a name no expression knows that a ``<property>`` written without ``xacro:`` gives
        (xacro 1 read it; xacro 2 copies it unread): where that tag is, and to write the prefix."""
        while error is not None and not isinstance(error, NameError):
            error = getattr(error, "exc", None)
        name = getattr(error, "name", None)
        if name is None:
            return None
        for document in (doc, *self.documents):
            for element in document.getElementsByTagName("property"):
                if element.getAttribute("name") == name:
                    origin = element.getUserData(ORIGIN)
                    where = f" ({origin.file}:{origin.line})" if origin is not None and origin.line else ""
                    return f'<property name="{name}">{where} is written without xacro:, which xacro 2 copies unread: write <xacro:property>'
        return None

    def reported(self) -> tuple[tuple[str, Origin | None], ...]:
        """What the model said with ``xacro.error()`` so far: before an expansion that then
        stops, often why (Shadow's hand: a hand type its version does not fit, then the
        include of that type's file fails)."""
        return tuple((text, origin) for text, origin, error in self.warnings if error)

    def macro_defined_below(self, doc: xml.dom.minidom.Document, message: str, call: Origin | None) -> str | None:
        """For a call of a macro xacro does not know yet, that its own file defines further
        down (xacro.py before ROS Jade gathered a file's macros first; xacro 2 reads in
        order): where the definition is, and to move it above the call."""
        found = _UNKNOWN_MACRO.search(message)
        if found is None or call is None or not call.line:
            return None
        for document in (doc, *self.documents):
            for element in document.getElementsByTagName("xacro:macro"):
                origin = element.getUserData(XACRO_TAG_ORIGIN)
                if element.getAttribute("name").removeprefix("xacro:") == found.group(1) and origin is not None and origin.file == call.file and (origin.line or 0) > call.line:
                    return f"macro '{found.group(1)}' is defined below this call, at line {origin.line}: xacro reads a file from top to bottom; move the definition above its first call"
        return None

    def installed_elsewhere(self, path: str) -> str | None:
        """For ``$(find NAME)/x/file`` that the sources of NAME, in the input's repository or
        workspace, lack: where they have that file, and how to check against the folders
        the package installs it to (ros2_control_demos installs ``description/ros2_control``
        to ``share/NAME/ros2_control``); None when they have no file of that name."""
        absolute = Path(os.path.abspath(path))
        for name, folder in self.found.items():
            if absolute.is_relative_to(folder) and self.resolver.workspace_of(folder) is not None:
                found = closest_file(folder, absolute.relative_to(folder).parts)
                if found is not None:
                    return (
                        f"package '{name}' installs its files to other folders than its sources, which have it at "
                        f"{display_path(str(found))}: build the workspace (colcon build) and check again, or give its "
                        f"installed share folder with -P {name}=DIR"
                    )
        return None

    def patch(self, owner: object, name: str, replacement) -> None:
        self.saved[owner, name] = getattr(owner, name)
        setattr(owner, name, replacement)

    def __enter__(self):
        for name in self.TRACKED:
            self.patch(xacro, name, self.track(getattr(xacro, name)))
        self.patch(xacro, "handle_macro_call", self.track(xacro.handle_macro_call, calls=True))
        for name in self.TOUCHED:
            self.patch(xacro, name, self.touch(getattr(xacro, name)))
        self.patch(xacro, "parse", self.parse)
        self.patch(xacro, "replace_node", self.replace_node)
        self.patch(xacro, "safe_eval", guard.safe_eval)
        self.patch(xacro.Table, "_setitem", self.define(xacro.Table._setitem))
        self.patch(xacro.Table, "_resolve_", self.resolve(xacro.Table._resolve_))
        guard.restrict(xacro._global_symbols)
        self.patch(xacro.substitution_args, "_eval_find", self.find)
        xacro.all_includes = []
        # The wrappers above add about three frames to the four of each level of xacro's
        # recursion: with the limit raised in proportion, a chain of macros nests as deep
        # as under the xacro tool, and a runaway recursion still ends at about its depth.
        self.limit = sys.getrecursionlimit()
        sys.setrecursionlimit(self.limit * 9 // 5)
        return self

    def __exit__(self, *exc):
        sys.setrecursionlimit(self.limit)
        for (owner, name), original in self.saved.items():
            setattr(owner, name, original)
        xacro.filestack = None
        xacro.macrostack = None
        return False


def _untraced(origin: Origin | None) -> Origin | None:
    """The origin without its macro calls (a runaway recursion's are the same call, hundreds of times)."""
    return Origin(origin.file, origin.line, origin.column) if origin is not None else None



def _collect_origins(doc: xml.dom.minidom.Document, calls: list[Call]) -> Origins:
    """The marks of the expanded document's elements, in document order, iteratively.

    An element's trace is its own stamps (innermost first) then its parent's."""
    files: dict[str, int] = {}
    traces: dict[tuple[int, ...], int] = {(): 0}
    places = array("i")
    element = xml.dom.Node.ELEMENT_NODE
    stack: list[tuple[object, tuple[int, ...]]] = [(doc.documentElement, ())]
    while stack:
        node, trace = stack.pop()
        stamps = node.getUserData(TRACE)
        if stamps is not None:
            trace = stamps + trace
        origin = node.getUserData(ORIGIN)
        if origin is None:
            places.extend((-1, 0, 0, 0))
        else:
            places.extend((files.setdefault(origin.file, len(files)), origin.line, origin.column or 0, traces.setdefault(trace, len(traces))))
        for child in reversed(node.childNodes):
            if child.nodeType == element:
                stack.append((child, trace))
    return Origins(list(files), [(c.file, c.line, c.column, c.macro) for c in calls], list(traces), places)


def _where_raised(error: BaseException) -> Origin | None:
    """Where an error was raised: the innermost place marked on it or on the errors
    it wraps (xacro wraps an error in each expression it evaluates, ``.exc``)."""
    origin = None
    while error is not None:
        origin = getattr(error, "urdfcli_origin", origin)
        error = getattr(error, "exc", None)
    return origin


def _missing_package(error: BaseException | None) -> PackageNotFound | None:
    """The package look-up that failed under ``error``, however deep xacro wrapped it
    (an expression in an expression: ``load_yaml('$(find pkg)/x.yaml')`` in a property)."""
    while error is not None:
        if isinstance(error, PackageNotFound):
            return error
        error = getattr(error, "exc", None) or error.__cause__ or error.__context__
    return None


_SUBSTITUTION = re.compile(r"(\$\{[^}]*\}|\$\([^)]*\))")  # ${expression} or $(command ...), as xacro writes them in text
_SUBSTITUTION_NAME = re.compile(r"\$\{\s*(\w+)\s*\}|\$\(arg\s+(\w+)\s*\)")  # ${name} or $(arg name)


def _package_uri(filename: str) -> str | None:
    """The ``package://`` URI an ``<xacro:include>`` names, which xacro reads as a path beside the
    including file (it joins the URI to that file's folder); None for any other name."""
    parent = xacro.filestack[-2] if len(xacro.filestack) > 1 else None
    folder = os.path.dirname(parent) if parent else "."
    written = filename[len(folder) + 1:] if filename.startswith(folder + os.sep) else filename
    return written if written.startswith("package://") else None


def _package_uri_hint(uri: str) -> str:
    """What to write for an ``<xacro:include>`` of a ``package://`` URI."""
    package, _, rest = uri[len("package://"):].partition("/")
    return f"xacro reads no package:// URI in <xacro:include>: write $(find {package})/{rest}"


def _included(resolver: PackageResolver) -> tuple[str, ...]:
    """The files xacro included, each once; a file of the workspace's install space as its source."""
    return tuple(dict.fromkeys(resolver.source_of(file) for file in xacro.all_includes))


def _short(error: BaseException) -> str:
    inner = getattr(error, "exc", None)
    if isinstance(inner, OSError) and error.args and error.args[0] is not None:  # (None: load_yaml's, said by str() below)
        return str(error.args[0])
    missing = _missing_package(error)
    if missing is not None:
        return f"package '{missing.args[0]}' not found"
    text = " ".join(str(error).split())
    if isinstance(inner, MemoryError):
        return f"out of memory {text}"
    if isinstance(inner, NameError) and "when evaluating expression" in text:
        return text.replace(" when evaluating", ", when evaluating")
    return text or type(error).__name__


class _Stderr(io.StringIO):
    """xacro's standard error: each ``warning:`` line kept with where xacro was when it began,
    and each ``error:`` line, which only a model's ``xacro.error()`` prints while xacro
    expands (xacro prints it and goes on; its own errors are raised)."""

    def __init__(self, session: _Session):
        super().__init__()
        self.session = session
        self.line: list[str] = []
        self.origin: Origin | None = None

    def write(self, text: str) -> int:
        for piece in text.splitlines(keepends=True):
            if not self.line:
                self.origin = self.session.current_origin()
            self.line.append(piece)
            if piece.endswith("\n"):
                line = "".join(self.line)
                self.line = []
                for label in ("warning: ", "error: "):
                    if line.startswith(label):
                        self.session.warnings.append((line[len(label):].strip(), self.origin, label == "error: "))
        return len(text)


def global_names() -> tuple[list[str], dict[str, list[str]]]:
    """The names xacro gives every expression, as an expansion here sees them (after
    :func:`guard.restrict`), and the members of those that are namespaces."""
    table = xacro._global_symbols
    guard.restrict(table)
    return sorted(table), {name: sorted(value) for name, value in table.items() if isinstance(value, dict)}


_UNDEFINED_ARGUMENT = re.compile(r"\bUndefined substitution argument (\w+)")  # xacro's words for $(arg NAME) without a value


def _missing_argument(message: str) -> tuple[str | None, str | None]:
    """For xacro's error on ``$(arg NAME)`` without a value: NAME, an argument the model
    needs from its caller, or (None, a hint) when NAME is a misspelling of an argument
    declared before it (``prefx`` for ``prefix``): a mistake to fix, not a value to give."""
    found = _UNDEFINED_ARGUMENT.search(message)
    if found is None:
        return None, None
    name = found.group(1)
    declared = xacro.substitution_args_context.get("arg") or {}
    meant = typo_of(name, declared)
    if meant is None:
        return name, None
    return None, f"did you mean $(arg {meant})? No <xacro:arg> declares '{name}'"


_UNKNOWN_MACRO = re.compile(r"^unknown macro name: (?:xacro:)?([\w.-]+)")  # xacro's words for a call of a macro it has not read


_INVALID_PARAMETER = re.compile(r'^Invalid parameter "([^"]+)"')  # xacro's words for a call giving a parameter its macro lacks


def _parameter_hint(error: Exception, message: str) -> str | None:
    """For xacro's error on a macro call giving a parameter the macro does not declare: the
    parameter meant (``rpy_ee`` for ``rpy``: the name with a part added, or misspelt), else the
    macro's parameters; None for any other error."""
    found = _INVALID_PARAMETER.match(message)
    macros = getattr(error, "macros", None)
    if found is None or not macros or macros[0].body is None:
        return None
    given, macro = found.group(1), macros[0]
    params = [name for name in macro.params if not name.startswith("*")]  # a block (*name) is given as content, not as an attribute
    name = macro.body.getAttribute("name").removeprefix("xacro:")
    meant = next((param for param in params if cut_from(param, given)), None) or typo_of(given, params)
    if meant is not None:
        return f"macro '{name}' has no parameter '{given}': did you mean '{meant}'?"
    return f"macro '{name}' has no parameter '{given}'; its parameters: {', '.join(params) or '(none)'}"


def expand_here(data: bytes, file: str | None, mappings: dict[str, str], resolver: PackageResolver, given: dict[str, bytes]) -> Expansion:
    """:meth:`urdfcli.read.xacro.Expander.expand`, here in this process and unbounded."""
    shown = display_path(file) if file else "<stdin>"
    try:
        doc = tagged_dom(data, shown)
    except XmlError as error:
        raise ExpansionError(error.message, Origin(shown, error.line, error.column), shown, code=error.code) from None
    session = _Session(resolver, given)
    with session, contextlib.redirect_stderr(_Stderr(session)):
        xacro.init_stacks(file)
        try:
            xacro.process_doc(doc, mappings=dict(mappings))
        except ExpansionError as error:
            error.includes = _included(resolver)
            error.reported = session.reported()
            raise
        except RecursionError as error:
            names = [m.body.getAttribute("name") for m in (xacro.macrostack or [])[-3:]]
            what = f" in macro '{names[-1]}'" if names else ""
            raise ExpansionError(
                f"runaway recursion{what}: a macro or include that expands itself without end",
                _untraced(getattr(error, "urdfcli_origin", None)),
                shown,
            ) from None
        except Exception as error:
            code = "X004" if _missing_package(error) is not None else "X003"
            message = _short(error)
            if code == "X004":
                message += f" {resolver.where()}"
            origin = _where_raised(error)
            current_file = xacro.filestack[-1] if xacro.filestack else file
            current_file = resolver.source_of(current_file) if current_file else current_file
            missing, hint = _missing_argument(message) if code == "X003" else (None, None)
            raise ExpansionError(
                message, origin, display_path(current_file) if current_file else shown, code,
                _included(resolver), missing, hint or getattr(error, "urdfcli_hint", None) or _parameter_hint(error, message) or session.unprefixed_property(doc, error)
                or session.macro_defined_below(doc, message, origin), session.reported(),
            ) from None
        finally:
            includes = list(_included(resolver))
        if file is not None:
            banner = [
                " %s " % ("=" * 83),
                " |    This document was autogenerated by xacro from %-30s | "
                % re.sub(r"-+", "-", str(file)),
                " |    EDITING THIS FILE BY HAND IS NOT RECOMMENDED  %-30s | " % "",
                " %s " % ("=" * 83),
            ]
            first = doc.firstChild
            for text in banner:
                doc.insertBefore(xml.dom.minidom.Comment(text), first)
    origins = _collect_origins(doc, session.calls)
    text = doc.toprettyxml(indent="  ")
    return Expansion(text, origins, includes, session.warnings)
