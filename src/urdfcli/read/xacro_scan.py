"""A xacro file read without expanding it: what it defines, uses and makes, and where.

:func:`scan` reads one file into a :class:`XacroFile`: its macros and their
parameters, its properties and arguments, every ``${...}`` expression and
``$(...)`` substitution (lexed as xacro lexes them, nested ones too), the macro
calls and ``insert_block`` elements, the links, joints and transmissions
written inside macros, the packages it names (``$(find pkg)``,
``package://pkg/``) and the xacro tags written without the ``xacro:`` prefix.
``xacro:if`` and ``xacro:unless`` are not evaluated: what is written under
them counts. A place is kept as (element, attribute, offset) and turned into a
line and column only when a diagnostic needs one (:meth:`XacroFile.position`).

What xacro itself provides (``pi``, ``radians``, ``xacro.load_yaml``...) is read
from the real xacro package, in the worker that runs it (:class:`XacroGlobals`);
a macro's ``params`` are split with xacro's own grammar (:func:`macro_parameters`).
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path
from typing import NamedTuple

from .expanded import display_path
from .positions import Text

XACRO_NAMESPACES = {"http://www.ros.org/wiki/xacro", "http://ros.org/wiki/xacro", "http://wiki.ros.org/xacro"}
# xacro's own elements; any other xacro:NAME element calls macro NAME
DIRECTIVES = {"include", "property", "arg", "macro", "if", "unless", "insert_block", "element", "attribute", "call"}
# elements xacro 1 also read without the prefix (with a deprecation warning); xacro 2 leaves them in the output
OLD_DIRECTIVES = {"include": "filename", "property": "name", "macro": "name", "arg": "name", "insert_block": "name", "if": "value", "unless": "value"}
NAMED = ("link", "joint", "transmission")  # what a robot may hold one of per name

# xacro's lexer (xacro.LEXER): $$ escapes, ${...} up to the first }, $(...) up to the first ), text
_TOKEN = re.compile(r"(?P<escape>\$\$+[{(])|\$\{(?P<expression>[^}]*)\}|\$\((?P<substitution>[^)]*)\)|[^$]+|\$[^{($]+|\$\Z")
_PACKAGE_URI = re.compile(r"package://((?:\$\{[^}]*\}|\$\([^)]*\)|[^/\s\"'<>$])*)")


def lexed(text: str) -> list[tuple[str, int, int, str]]:
    """``text`` as xacro's lexer cuts it: (kind, start, end, inner) for each piece, kind
    "text", "expression" (``${inner}``), "substitution" (``$(inner)``) or "escape"
    (``$${`` and the like); what xacro cannot lex ends in one "invalid" piece."""
    found = []
    at = 0
    while at < len(text):
        token = _TOKEN.match(text, at)
        if token is None:
            found.append(("invalid", at, len(text), text[at:]))
            break
        kind = next((k for k in ("escape", "expression", "substitution") if token.group(k) is not None), "text")
        inner = token.group(kind) if kind in ("expression", "substitution") else token.group()
        found.append((kind, token.start(), token.end(), inner))
        at = token.end()
    return found


TEXT, TAIL = "#text", "#tail"  # a place in an element's text, or in the text after its end tag


class Place(NamedTuple):
    """Where something was written: element ``element`` (in document order, the root
    is 0) itself, or ``offset`` characters into the value of its attribute ``within``,
    its text (TEXT) or the text after it (TAIL)."""

    element: int
    within: str | None = None
    offset: int = 0


class Macro(NamedTuple):
    name: str
    place: Place
    params: str  # the params attribute as written
    parent: int | None  # the macro whose body holds this definition

    @property
    def parameters(self) -> tuple[Parameter, ...]:
        """Its parameters, split as xacro splits them."""
        return macro_parameters(self.params)


class Variable(NamedTuple):
    """A ``xacro:property`` or ``xacro:arg``: a name given a value."""

    kind: str  # "property" or "argument"
    name: str
    place: Place
    value: str | None  # value (property) or default (argument) as written; None for a block property
    macro: int | None  # the macro whose body holds it; None at the file's top level
    scope: str | None = None  # a property's scope attribute


class Expression(NamedTuple):
    """``${text}``, where xacro evaluates it (``macro``: in that macro's body)."""

    text: str
    place: Place  # of the text, after ``${``
    macro: int | None
    in_substitution: bool = False  # inside $(...): evaluated first, for a file name say


class Substitution(NamedTuple):
    """``$(function argument)``."""

    function: str
    argument: str
    place: Place  # of the function's name, after ``$(``
    macro: int | None
    in_expression: bool = False  # inside ${...}, such as load_yaml('$(find pkg)/x.yaml')


class Call(NamedTuple):
    """A macro call: ``<xacro:NAME .../>``, or ``<xacro:call macro="NAME"/>``."""

    name: str  # as written after ``xacro:`` (``ns.name`` through an include's namespace)
    place: Place
    macro: int | None
    attributes: tuple[tuple[str, str], ...]


class Block(NamedTuple):
    """``<xacro:insert_block name=NAME/>``."""

    name: str
    place: Place
    macro: int | None


class Made(NamedTuple):
    """A link, joint or transmission written in a macro's body."""

    tag: str
    name: str  # its name attribute as written
    place: Place  # of the name attribute
    macro: int
    conditions: tuple[str, ...] = ()  # the values of the xacro:if and xacro:unless it is written in, innermost first


class PackageUse(NamedTuple):
    """A package named by ``$(find pkg)`` or ``package://pkg/``; ``package`` as written
    (it may hold ``${...}``); ``path`` what follows it up to a space or a quote
    (``/urdf/arm.xacro``), as written."""

    package: str
    place: Place
    macro: int | None
    path: str = ""


class Old(NamedTuple):
    """A xacro tag written without its prefix (``<include filename=...>``)."""

    tag: str
    place: Place
    value: str = ""  # the attribute that makes it xacro's: the file name, property name or condition


class XacroFile:
    """What one xacro file defines, uses and makes (see the module's documentation).

    ``name`` is the file as diagnostics name it; ``makes`` whether it writes a
    link, a joint or a macro call outside its macro definitions (a model, not a
    library); ``includes``, ``arguments`` and ``properties`` are the plain facts
    the workspace's include search reads."""

    def __init__(self, name: str, source: Text) -> None:
        self.name = name
        self.source = source  # the file's text and its positions
        self.makes = False
        self.uses_xacro = False  # a xacro element, or xacro's namespace declared on the root
        self.xacro_elements: set[str] = set()  # the local names of its xacro elements (macro, property, if...)
        self.includes: list[str] = []
        self.namespaces: list[str] = []  # ns attributes of its includes
        self.including: set[int] = set()  # macros whose bodies include a file: xacro reads that file in their scope
        self.macros: list[Macro] = []
        self.definitions: list[Variable] = []
        self.expressions: list[Expression] = []
        self.substitutions: list[Substitution] = []
        self.calls: list[Call] = []
        self.blocks: list[Block] = []
        self.made: list[Made] = []
        self.packages: list[PackageUse] = []
        self.old: list[Old] = []
        self.unprefixed: set[str] = set()  # names of the elements written without a prefix: a macro's among them is a call xacro 2 never expands
        self.derived: dict = {}  # what the model layer works out from these, once (see urdfcli.read.memo)

    @property
    def arguments(self) -> list[tuple[str, str]]:
        """Each argument with a default, and that default."""
        return [(d.name, d.value) for d in self.definitions if d.kind == "argument" and d.name and d.value is not None]

    @property
    def properties(self) -> list[tuple[str, str]]:
        """Each property with a value written as an attribute, and that value."""
        return [(d.name, d.value) for d in self.definitions if d.kind == "property" and d.name and d.value is not None]

    @property
    def text(self) -> str:
        return self.source.text

    def position(self, place: Place) -> tuple[int | None, int | None]:
        """The line and column (1-based) of a place; the element's when the value
        cannot be followed character by character (an entity, a CDATA section)."""
        spans = self.source.spans
        if place.element >= len(spans):
            return None, None
        start, tag_end, end = spans[place.element]
        at = _value_offset(self.source, start, tag_end, end, place)
        return self.source.position(at if at is not None else start)

    def macros_at(self, offset: int) -> list[int]:
        """The macros whose definitions hold the text at ``offset``, innermost first."""
        spans = self.source.spans
        around = [m for m, macro in enumerate(self.macros) if (span := spans[macro.place.element])[0] < offset < span[2]]
        return sorted(around, key=lambda m: -spans[self.macros[m].place.element][0])

    def within(self, macro: int | None, outer: int) -> bool:
        """Whether the body of macro ``macro`` is (or is inside) that of ``outer``."""
        while macro is not None:
            if macro == outer:
                return True
            macro = self.macros[macro].parent
        return False


def _value_offset(source: Text, start: int, tag_end: int, end: int, place: Place) -> int | None:
    text = source.text
    if place.within is None:
        return start
    if place.within in (TEXT, TAIL):
        base = end if place.within == TAIL else tag_end
        written = text[base:base + place.offset]
        return base + place.offset if "<" not in written and "&" not in written else None
    at = source.attribute(start, place.within)
    if at is None:
        return None
    quote = min((i for i in (text.find('"', at, tag_end), text.find("'", at, tag_end)) if i >= 0), default=-1)
    if quote < 0:
        return at
    written = text[quote + 1:quote + 1 + place.offset]
    return quote + 1 + place.offset if "&" not in written else at


def is_xacro(element) -> bool:
    """Whether an element is one of xacro's (``xacro:`` prefix, or xacro's namespace)."""
    tag = element.tag
    return element.prefix == "xacro" or (tag.startswith("{") and tag[1:].partition("}")[0] in XACRO_NAMESPACES)


def local_name(tag: str) -> str:
    return tag.rpartition("}")[2]


def scan(root, name: str, source: Text) -> XacroFile:
    """What a xacro file defines, uses and makes: ``root`` is its tree (elements only,
    as :func:`urdfcli.read.xml.parse` reads it), ``source`` its text, ``name`` the
    file as diagnostics name it."""
    found = XacroFile(name, source)
    _Scanner(found).run(root)
    return found


class _Scanner:
    def __init__(self, found: XacroFile) -> None:
        self.found = found

    def run(self, root) -> None:
        found = self.found
        found.makes = _makes(root)
        found.uses_xacro = bool(set(root.nsmap.values()) & XACRO_NAMESPACES)
        stack: list[tuple[object, int | None]] = [(root, None)]
        at = -1
        while stack:  # in document order: each element's index is its place
            element, macro = stack.pop()
            at += 1
            inner = self.element(element, at, macro)
            for child in reversed(element):
                stack.append((child, inner))
            if element.text:
                self.value(element.text, Place(at, TEXT), inner)
            if element.tail and element is not root:
                self.value(element.tail, Place(at, TAIL), macro)

    def element(self, element, at: int, macro: int | None) -> int | None:
        """Record what ``element`` is; the macro its children belong to."""
        found = self.found
        local = local_name(element.tag)
        if is_xacro(element):
            found.uses_xacro = True
            found.xacro_elements.add(local)
            if local == "macro":
                found.macros.append(Macro(element.get("name") or "", Place(at, "name"), element.get("params") or "", macro))
                self.attributes(element, at, macro, skip=("name",))  # defaults are read where the macro is called
                return len(found.macros) - 1
            if local in ("property", "arg") and element.get("remove") is None:
                kind = "property" if local == "property" else "argument"
                value = element.get("value", element.get("default")) if kind == "property" else element.get("default")
                found.definitions.append(Variable(kind, element.get("name") or "", Place(at, "name"), value, macro, element.get("scope")))
                self.attributes(element, at, macro, skip=("name",) if kind == "argument" else ())
            elif local == "insert_block":
                found.blocks.append(Block(element.get("name") or "", Place(at, "name"), macro))
            elif local == "include":
                if element.get("filename"):
                    found.includes.append(element.get("filename"))
                    if macro is not None:
                        found.including.add(macro)
                if element.get("ns"):
                    found.namespaces.append(element.get("ns"))
                self.attributes(element, at, macro)
            elif local == "call":
                found.calls.append(Call(element.get("macro") or "", Place(at, "macro"), macro, _plain_attributes(element)))
                self.attributes(element, at, macro)
            elif local not in DIRECTIVES:
                found.calls.append(Call(local, Place(at), macro, _plain_attributes(element)))
                self.attributes(element, at, macro)
            else:
                self.attributes(element, at, macro)
            return macro
        if element.prefix is None:
            found.unprefixed.add(local)
        if element.prefix is None and local in OLD_DIRECTIVES and element.get(OLD_DIRECTIVES[local]) is not None and _directive_place(element, local, macro):
            found.old.append(Old(local, Place(at), element.get(OLD_DIRECTIVES[local])))
        if macro is not None and local in NAMED and element.get("name") is not None and _in_body(element):
            found.made.append(Made(local, element.get("name"), Place(at, "name"), macro, _conditions(element)))
        self.attributes(element, at, macro)
        return macro

    def attributes(self, element, at: int, macro: int | None, skip: tuple[str, ...] = ()) -> None:
        for key, value in element.attrib.items():
            name = _written_name(element, key)
            if name in skip or not value:
                continue
            self.value(value, Place(at, name), macro)

    def value(self, text: str, place: Place, macro: int | None) -> None:
        if "$" not in text and "package://" not in text:
            return
        for match in _PACKAGE_URI.finditer(text):
            self.found.packages.append(PackageUse(match.group(1), place._replace(offset=place.offset + match.start()), macro, _path_after(text, match.end())))
        self.lex(text, place, macro, inside="")

    def lex(self, text: str, place: Place, macro: int | None, inside: str) -> None:
        """Each ``${...}`` and ``$(...)`` of ``text``, as xacro reads them; ``inside``
        tells what holds the text ("": nothing, "$": an expression, "(": a substitution)."""
        found = self.found
        at = 0
        while at < len(text):
            token = _TOKEN.match(text, at)
            if token is None:
                return  # xacro stops here too ("invalid expression")
            where = place._replace(offset=place.offset + token.start() + 2)
            if token.group("expression") is not None:
                inner = token.group("expression")
                found.expressions.append(Expression(inner, where, macro, inside == "("))
                self.lex(inner, where, macro, "$")
            elif token.group("substitution") is not None:
                inner = token.group("substitution")
                function, _, argument = inner.strip().partition(" ")
                found.substitutions.append(Substitution(function, argument.strip(), where, macro, inside == "$"))
                if function == "find" and argument.strip():
                    found.packages.append(PackageUse(argument.strip(), where._replace(offset=where.offset - 2), macro, _path_after(text, token.end())))
                self.lex(inner, where, macro, "(")
            at = token.end()


def _path_after(text: str, at: int) -> str:
    """The path written after a package's name, up to a space or a quote."""
    return re.match(r"[^\s\"']*", text[at:]).group(0)


def _written_name(element, key: str) -> str:
    """An attribute's name as written (``xacro:name`` for xacro's namespace)."""
    if not key.startswith("{"):
        return key
    namespace, _, local = key[1:].partition("}")
    prefix = next((p for p, uri in element.nsmap.items() if uri == namespace and p), None)
    return f"{prefix}:{local}" if prefix else local


def _plain_attributes(element) -> tuple[tuple[str, str], ...]:
    return tuple((key, value) for key, value in element.attrib.items() if not key.startswith("{"))


def _directive_place(element, local: str, macro: int | None) -> bool:
    """Whether an unprefixed element sits where xacro 1 read it as its own: at the top
    level, or in a xacro element's body (not inside a link, a joint or a plugin, where
    an <include> or a <property> may be someone else's); an <insert_block> anywhere in
    a macro's body (Hey5's <joint><insert_block name="origin"/></joint>): it is no one else's."""
    if local == "insert_block" and macro is not None:
        return True
    parent = element.getparent()
    return parent is not None and (parent.getparent() is None or is_xacro(parent))


def _in_body(element) -> bool:
    """Whether an element is written directly in a macro's body (or a condition in it):
    the <joint> of a <transmission> names a joint, it makes none."""
    parent = element.getparent()
    return is_xacro(parent) and local_name(parent.tag) in ("macro", "if", "unless")


def _conditions(element) -> tuple[str, ...]:
    """The conditions of the xacro:if and xacro:unless an element of a macro's body is written in."""
    found = []
    parent = element.getparent()
    while is_xacro(parent) and local_name(parent.tag) in ("if", "unless"):
        found.append(parent.get("value") or "")
        parent = parent.getparent()
    return tuple(found)


# What an SRDF (MoveIt's) writes at its top level: a file that writes one makes a semantic description
_SRDF_ELEMENTS = frozenset(("group", "group_state", "end_effector", "virtual_joint", "passive_joint", "disable_collisions"))


def _makes(root) -> bool:
    """Whether the file writes a link, a joint, an SRDF element or a macro call outside
    its macro definitions (looking into xacro:if and xacro:unless only)."""
    stack = list(root)
    while stack:
        element = stack.pop()
        local = local_name(element.tag)
        if is_xacro(element):
            if local in ("if", "unless"):
                stack.extend(element)
            elif local not in ("include", "property", "arg", "macro"):
                return True
        elif local in ("link", "joint") or local in _SRDF_ELEMENTS:
            return True
    return False


# -- names in expressions ------------------------------------------------------------
class Name(NamedTuple):
    name: str
    offset: int  # in the expression's text
    dotted: str  # the name and the attributes read from it, such as xacro.load_yaml


@functools.lru_cache(maxsize=4096)
def free_names(text: str) -> tuple[Name, ...] | None:
    """The names an expression reads (not those it binds itself, in a comprehension
    or a lambda), in order; None when Python cannot parse it."""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError):
        return None
    lead = len(text) - len(text.lstrip())
    bound = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            bound.add(node.id)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
    lines = text.strip().split("\n")
    starts = [0]
    for line in lines[:-1]:
        starts.append(starts[-1] + len(line) + 1)
    dotted = _dotted(tree)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id not in bound:
            line = lines[node.lineno - 1]
            column = len(line.encode("utf-8")[:node.col_offset].decode("utf-8", errors="ignore"))
            found.append(Name(node.id, lead + starts[node.lineno - 1] + column, dotted.get(id(node), node.id)))
    return tuple(sorted(found, key=lambda n: n.offset))


def _dotted(tree) -> dict[int, str]:
    """For each name read with attributes after it (``a.b.c``), that dotted text."""
    found = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute):
            parts = [node.attr]
            inner = node.value
            while isinstance(inner, ast.Attribute):
                parts.append(inner.attr)
                inner = inner.value
            if isinstance(inner, ast.Name):
                text = ".".join([inner.id, *reversed(parts)])
                if len(text) > len(found.get(id(inner), "")):
                    found[id(inner)] = text
    return found


def literal_calls(text: str, functions: tuple[str, ...]) -> list[str] | None:
    """The first arguments of the calls of ``functions`` (dotted names such as
    ``xacro.arg``) in an expression, when each is a string literal; None when one
    is not (or the expression cannot be parsed)."""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError):
        return None
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and _dotted_name(node.func) in functions:
            first = node.args[0] if node.args else None
            if not (isinstance(first, ast.Constant) and isinstance(first.value, str)):
                return None
            found.append(first.value)
    return found


def _dotted_name(node) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = _dotted_name(node.value)
        return f"{inner}.{node.attr}" if inner else None
    return None


# -- what xacro provides -------------------------------------------------------------
class Parameter(NamedTuple):
    name: str  # without the * or ** of a block
    block: bool
    default: str | None  # as written
    forward: bool  # ``name:=^``: taken from the caller's scope

    @property
    def shown(self) -> str:
        """The name as written: ``*origin`` for a block."""
        return ("*" if self.block else "") + self.name

    @property
    def shown_default(self) -> str | None:
        """The default as written: ``0.1``, ``^|0.1`` (the caller's value, else 0.1), ``^``."""
        if self.forward:
            return f"^|{self.default}" if self.default is not None else "^"
        return self.default


# xacro's grammar of a macro's params (xacro/__init__.py, re_macro_arg and parse_macro_arg),
# repeated here so that only the worker imports xacro; tests compare the two.
_DEFAULT = r"""\$\{.*?\}|\$\(.*?\)|(?:'.*?'|\".*?\"|[^\s'\"]+)+|"""
_MACRO_PARAMETER = re.compile(r"^\s*([^\s:=]+?)\s*:?=\s*(\^\|?)?(" + _DEFAULT + r")(?:\s+|$)(.*)", re.DOTALL)  # (params written over lines: the editor reads them as written)


@functools.lru_cache(maxsize=1024)
def macro_parameters(params: str) -> tuple[Parameter, ...]:
    """A macro's ``params`` split as xacro splits them."""
    found = []
    rest = params
    while rest and rest.strip():
        match = _MACRO_PARAMETER.match(rest)
        if match:
            param, forward, default, rest = match.groups()
            found.append(Parameter(param.lstrip("*"), param.startswith("*"), default or None, bool(forward)))
        else:  # no default
            param, *more = rest.lstrip().split(None, 1)
            rest = more[0] if more else ""
            found.append(Parameter(param.lstrip("*"), param.startswith("*"), None, False))
    return tuple(found)


class XacroGlobals(NamedTuple):
    """The names xacro puts in every expression's scope (pi, radians, load_yaml, xacro,
    python, math...), and each namespace's members; read from xacro in the worker
    (:meth:`urdfcli.read.xacro.Expander.global_names`)."""

    names: frozenset[str]
    members: dict[str, frozenset[str]]


def shown(path: Path | str) -> str:
    """A path as diagnostics name files: relative to the working directory when below it."""
    return display_path(str(path))


_GENERATED = re.compile(rb"autogenerated\s+by\s+xacro\s+from\s+([^\s|]+)")


def header_source(head: bytes) -> str | None:
    """The PATH of xacro's ``autogenerated by xacro from PATH`` in a file's first bytes:
    a URDF xacro generated (a model's output, compared with its source by drift)."""
    match = _GENERATED.search(head)
    return match.group(1).decode("utf-8", "replace").removesuffix("-->") if match else None


ARGUMENT = re.compile(r"\$\(\s*arg\s+([^\s()]+)\s*\)")
"""``$(arg NAME)``, NAME its group."""

COMPUTED = re.compile(r"\$\{[^}]*\}|\$\([^)]*\)")
"""A ``${...}`` expression or a ``$(...)`` substitution: what a file name computes."""

