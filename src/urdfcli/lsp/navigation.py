"""Hover, go to definition and completion in a URDF or xacro source.

Each works on the text being edited, an offset in it, and a :class:`Scope`: the
outlines of the files that share names with it (its own, those it includes, the
models that include it), the links and joints of the expanded models, and how a
filename leads to a file. The text at the cursor is read by
:func:`~urdfcli.lsp.outline.cursor`, so a half-typed tag works too.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import NamedTuple

from ..diagnostics import Location
from ..project.workspace import shown
from ..report.escape import escape
from ..read.xacro_scan import lexed, macro_parameters
from .outline import XACRO_KEYWORDS, Cursor, Definition, Outline, cursor, expression_name, expression_names, substitution

XACRO = "xacro:"
_MACRO_START = re.compile(r"<xacro:macro\b")
_MACRO_END = "</xacro:macro>"
_NAME_ATTRIBUTE = re.compile(r"""\s(name|params)\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_TYPED_TAG = re.compile(r"<xacro:([\w.-]*)$")
_NAME_CHARACTERS = re.compile(r"[\w.-]*")
_TYPED_NAME = re.compile(r"\w*$")
_OPEN_EXPRESSION = re.compile(r"\$\{[^}]*$")
_LONGEST_TAG = 65_536
_ATTRIBUTE = re.compile(r"""\s([\w:.-]+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")


class Scope(NamedTuple):
    outlines: tuple[Outline, ...]  # the file's own first
    links: dict[str, tuple[Location, ...]]  # a link of the expanded models -> where it was written, with its macro calls
    joints: dict[str, tuple[Location, ...]]
    find: Callable[[str], Path | None]  # $(find pkg)
    file_named: Callable[[str], Path | None]  # an include's or a mesh's filename -> the file

    def defined(self, kind: str, name: str) -> list[Definition]:
        return [d for outline in self.outlines for d in outline.named(kind, name)]

    def names(self, kind: str) -> dict[str, Definition]:
        found: dict[str, Definition] = {}
        for outline in self.outlines:
            for definition in outline.definitions:
                if definition.kind == kind:
                    found.setdefault(definition.name, definition)
        return found

    def link_names(self, typed: str = "") -> list[str]:
        """The links' names: of the expanded models and as written; after an expression
        (``${prefix}sh``), the names written in macros that start with it."""
        if "${" in typed:
            written = typed[: typed.rfind("}") + 1]
            return sorted(name for name in self.names("link") if name.startswith(written) and name.isprintable()) if written else []
        return sorted(name for name in set(self.links) | set(self.names("link")) if name.isprintable() and "${" not in name)


class Item(NamedTuple):
    """A completion: its label, its kind, a line about it, and the text it replaces (offsets)."""

    label: str
    kind: str  # "macro", "keyword", "link", "property" or "parameter"
    detail: str
    start: int
    end: int


def code(text: str) -> str:
    """Text from an input as inline Markdown code: escaped, in a fence longer than any of
    its backtick runs (an empty text as ``""``)."""
    text = escape(text) or '""'
    fence = "`" * (max((len(run) for run in re.findall(r"`+", text)), default=0) + 1)
    return f"{fence} {text} {fence}" if fence != "`" else f"`{text}`"


def where(definition: Definition | Location) -> str:
    line = f":{definition.line}" if definition.line else ""
    return code(f"{shown(Path(definition.file))}{line}")


# -- what the cursor is on ----------------------------------------------------------
def _macro_at(text: str, offset: int) -> tuple[str, str] | None:
    """The name and parameters of the ``<xacro:macro>`` whose body holds ``offset``."""
    starts = list(_MACRO_START.finditer(text, 0, offset))
    if not starts or _MACRO_END in text[starts[-1].end() : offset]:
        return None
    tag_end = text.find(">", starts[-1].end())
    attributes = {m.group(1): m.group(2) if m.group(2) is not None else m.group(3) for m in _NAME_ATTRIBUTE.finditer(text, starts[-1].end(), tag_end)}
    return attributes.get("name", ""), attributes.get("params", "")


def _parameter(text: str, offset: int, name: str) -> tuple[str, str, str | None] | None:
    """(macro, parameter, default) when ``name`` is a parameter of the macro around ``offset``."""
    macro = _macro_at(text, offset)
    if macro is None:
        return None
    for parameter in macro_parameters(macro[1]):
        if parameter.name == name:
            return macro[0], parameter.shown, parameter.shown_default
    return None


def _macro_call(at: Cursor) -> str | None:
    """The macro a tag calls (``<xacro:wheel>``), None for xacro's own tags and others."""
    if not at.tag.startswith(XACRO):
        return None
    name = at.tag[len(XACRO):]
    return name if name and name not in XACRO_KEYWORDS else None


def _names_link(at: Cursor) -> bool:
    """Whether an attribute's value names a link: ``<parent link>``, ``<child link>``,
    ``reference``, and a macro call's ``parent`` or ``child``."""
    if at.attribute is None:
        return False
    if at.attribute == "link" and at.tag in ("parent", "child"):
        return True
    return at.attribute == "reference" or (at.tag.startswith(XACRO) and at.attribute in ("parent", "child"))


def _preferred(definitions: list[Definition], macro: str | None) -> list[Definition]:
    """Definitions inside the macro being edited first, then those outside any macro."""
    return [d for d in definitions if d.macro == macro and macro] + [d for d in definitions if d.macro is None] or definitions


def parameter_values(text: str, offset: int, names: bool = True) -> list[str]:
    """The values of the start tag at ``offset`` (or around it: a diagnostic about an
    attribute is placed at the attribute; else the first one after it) that use a parameter
    of the macro whose body holds it, in a ``${...}``: what a call's arguments change. Without
    ``names``, its ``name`` attribute does not count: a ``${prefix}`` that names a link does
    not make what is wrong with the link's limits or shapes."""
    start = text.rfind("<", 0, offset + 1)
    if start < 0 or ">" in text[start:offset]:
        start = text.find("<", offset)
    macro = _macro_at(text, start) if start >= 0 else None
    if macro is None:
        return []
    end = text.find(">", start, start + _LONGEST_TAG)
    tag = text[start : end if end > 0 else start + _LONGEST_TAG]
    parameters = {p.name.lstrip("^") for p in macro_parameters(macro[1])}
    found = []
    for attribute in _ATTRIBUTE.finditer(tag):
        value = attribute.group(2) if attribute.group(2) is not None else attribute.group(3)
        if (names or attribute.group(1) != "name") and parameters & expression_names(value):
            found.append(value)
    return found


def fits_a_name(value: str, known: Iterable[str]) -> bool:
    """Whether a value written with ``${...}`` can make one of the ``known`` names, whatever
    its expressions give: its literal text, in place, matches one (``${prefix}link_2`` and
    ``left_link_2``). When none does, the literal text is what is wrong, not what a call passed."""
    pattern = re.compile("".join(".+" if kind == "expression" else re.escape(value[start:end]) for kind, start, end, _ in lexed(value)), re.DOTALL)
    return any(pattern.fullmatch(name) for name in known)


# -- hover ------------------------------------------------------------------------------
def hover(text: str, offset: int, scope: Scope) -> str | None:
    """Markdown about what the cursor is on: a macro call, ``${name}``, ``$(arg name)``,
    ``$(find pkg)``, a link's name; None for anything else."""
    at = cursor(text, offset)
    if at is None:
        return None
    if at.on_name:
        macro = _macro_call(at)
        return _macro_hover(macro, scope) if macro else None
    if at.attribute is None:
        return None
    inside = offset - at.value_start
    function = substitution(at.value, inside)
    if function is not None:
        return _substitution_hover(*function, scope)
    name = expression_name(at.value, inside)
    if name is not None:
        return _name_hover(text, offset, name, scope)
    if at.value in scope.links or at.value in scope.joints:
        return _link_hover(at.value, scope)
    return None


def _macro_hover(name: str, scope: Scope) -> str | None:
    found = scope.defined("macro", name)
    if not found:
        return None
    macro = found[0]
    shown = [(p.shown, p.shown_default) for p in macro_parameters(macro.detail)]
    parameters = ", ".join(code(p if d is None else f"{p}:={d}") for p, d in shown) or "none"
    return f"**macro** {code(name)}\n\nparameters: {parameters}\n\ndefined at {where(macro)}"


def _substitution_hover(function: str, argument: str, scope: Scope) -> str | None:
    if function == "arg":
        found = scope.defined("arg", argument)
        if not found:
            return f"**argument** {code(argument)}: declared nowhere it can be seen from here"
        default = f", default {code(found[0].detail)}" if found[0].detail else ", no default"
        return f"**argument** {code(argument)}{default}\n\ndeclared at {where(found[0])}"
    if function == "find":
        folder = scope.find(argument)
        return f"**package** {code(argument)}: " + (code(str(folder)) if folder else "not found")
    return None


def _name_hover(text: str, offset: int, name: str, scope: Scope) -> str | None:
    parameter = _parameter(text, offset, name)
    if parameter is not None:
        macro, written, default = parameter
        default_text = f", default {code(default)}" if default is not None else ""
        return f"**parameter** {code(written)} of macro {code(macro)}{default_text}"
    enclosing = _macro_at(text, offset)
    found = _preferred(scope.defined("property", name), enclosing[0] if enclosing else None)
    if not found:
        return None
    first = found[0]
    lines = [f"**property** {code(name)} = {code(first.detail)}", f"defined at {where(first)}"]
    if len(found) > 1:
        lines.append("also defined at " + ", ".join(where(d) for d in found[1:4]))
    return "\n\n".join(lines)


def _link_hover(name: str, scope: Scope) -> str:
    kind, places = ("link", scope.links[name]) if name in scope.links else ("joint", scope.joints[name])
    lines = [f"**{kind}** {code(name)}"]
    if places:
        written = places[0]
        lines.append(f"written at {where(written)}")
        lines += [f"by macro {code(call.macro)} called at {where(call)}" for call in written.trace]
    return "\n\n".join(lines)


# -- go to definition -----------------------------------------------------------------
def definition(text: str, offset: int, scope: Scope) -> list[Location]:
    """Where what the cursor is on was defined: a macro, a property or macro parameter,
    an argument, a package, an included or mesh file, a link or joint."""
    at = cursor(text, offset)
    if at is None:
        return []
    if at.on_name:
        macro = _macro_call(at)
        return [_location(d) for d in scope.defined("macro", macro)] if macro else []
    if at.attribute is None:
        return []
    inside = offset - at.value_start
    function = substitution(at.value, inside)
    if function is not None and function[0] in ("arg", "find"):
        if function[0] == "arg":
            return [_location(d) for d in scope.defined("arg", function[1])]
        folder = scope.find(function[1])
        return [Location(str(folder / "package.xml"))] if folder else []
    name = expression_name(at.value, inside)
    if name is not None:
        return _name_definition(text, offset, name, scope)
    if at.attribute == "filename" or at.value.startswith(("package://", "file://")):
        target = scope.file_named(at.value)
        return [Location(str(target))] if target is not None and target.is_file() else []
    return _link_definition(at.value, scope)


def _location(definition: Definition) -> Location:
    return Location(definition.file, definition.line, definition.column)


def _name_definition(text: str, offset: int, name: str, scope: Scope) -> list[Location]:
    enclosing = _macro_at(text, offset)
    if enclosing is not None and _parameter(text, offset, name) is not None:
        return [_location(d) for d in scope.defined("macro", enclosing[0])][:1]
    return [_location(d) for d in _preferred(scope.defined("property", name), enclosing[0] if enclosing else None)]


def _link_definition(name: str, scope: Scope) -> list[Location]:
    """Where a link or joint is written as the texts are now (``${prefix}base_link`` in a
    macro's body included); else, for one a macro names, the calls of the last check's model."""
    written = [_location(d) for kind in ("link", "joint") for d in scope.defined(kind, name)]
    if written:
        return written
    places = scope.links.get(name) or scope.joints.get(name)
    if places:
        written = places[0]
        calls = [Location(c.file, c.line, c.column) for c in reversed(written.trace)]
        return calls + [Location(written.file, written.line, written.column)]
    return []


# -- completion -------------------------------------------------------------------------
def completion(text: str, offset: int, scope: Scope) -> list[Item]:
    """Macro names after ``<xacro:``, link names in ``parent``/``child``/``reference``
    values, property and parameter names inside ``${``."""
    line_start = text.rfind("\n", 0, offset) + 1
    typed = _TYPED_TAG.search(text, line_start, offset)
    if typed is not None:
        end = _NAME_CHARACTERS.match(text, offset).end()
        return _macro_items(scope, typed.start(1), end)
    at = cursor(text, offset)
    if at is None or at.attribute is None:
        return []
    if _OPEN_EXPRESSION.search(at.value[: offset - at.value_start]):
        start = offset - len(_TYPED_NAME.search(text, at.value_start, offset).group())
        return _name_items(text, offset, scope, start)
    if _names_link(at):
        typed = at.value[: offset - at.value_start]
        return [Item(name, "link", "link", at.value_start, at.value_end) for name in scope.link_names(typed)]
    return []


def _macro_items(scope: Scope, start: int, end: int) -> list[Item]:
    macros = {name: d for name, d in scope.names("macro").items() if name.isprintable()}  # a name no one can type is offered to no one
    items = [Item(name, "macro", escape(f"{name}({d.detail})  {shown(Path(d.file))}:{d.line}"), start, end) for name, d in sorted(macros.items())]
    return items + [Item(keyword, "keyword", "xacro", start, end) for keyword in XACRO_KEYWORDS if keyword not in macros]


def _name_items(text: str, offset: int, scope: Scope, start: int) -> list[Item]:
    macro = _macro_at(text, offset)
    items = [Item(p.name, "parameter", escape(f"parameter of {macro[0]}"), start, offset) for p in macro_parameters(macro[1]) if p.name.isprintable()] if macro else []
    taken = {item.label for item in items}
    properties = scope.names("property")
    return items + [Item(name, "property", escape(d.detail), start, offset) for name, d in sorted(properties.items()) if name not in taken and name.isprintable()]
