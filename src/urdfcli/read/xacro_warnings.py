"""xacro's warnings, each with its fix and, where the words name it, the column of
what it is about.

xacro prints its warnings as text (``xacro.color.warning``); the expansion keeps
each with the element xacro was at (:mod:`urdfcli.read.expansion`). This module
knows what each of xacro 2's warnings means and says how to fix it.
"""

from __future__ import annotations

import re

from ..diagnostics import Applicability, Diagnostic, Edit, Fix, Location, Severity
from .files import SourceFile, SourceFiles
from .xacro_scan import is_xacro, local_name

# xacro's own words (xacro/__init__.py), and the fix for each
_FIXES = (
    (re.compile(r"Using (\w+)\(\) directly is deprecated\. Use (\w+)\.\1\(\) instead\."), "write {1}.{0}(...): xacro keeps the bare {0}() only for old files, with this warning"),
    (re.compile(r"redefining global symbol: (\w+)"), "rename the property: '{0}' is a name xacro gives every expression, and redefining it changes them all"),
    (re.compile(r"([\w:]+): unknown attribute\(s\): (.+)"), "remove {1} from <{0}>, or correct the spelling: xacro ignores it"),
    (re.compile(r"Include tag's filename spec \"(.*)\" matched no files\."), "no file matches {0}: correct the pattern, or remove the <xacro:include>"),
    (re.compile(r"Child elements of a <xacro:include> tag are ignored"), "move the elements out of <xacro:include>: it reads only its filename"),
    (re.compile(r"macro names must not contain prefix 'xacro:': xacro:(\w+)"), 'write name="{0}": a macro is called as <xacro:{0}>, named without the prefix'),
    (re.compile(r"(\w+): default property value can only be defined on local scope"), "remove scope= from property '{0}', or give it value= instead of default="),
    (re.compile(r"(\w+): no parent scope at global scope"), "remove scope=\"parent\" from property '{0}': at the top level it defines nothing"),
    (re.compile(r"inconsistent namespace redefinitions for ([\w:]+)"), "declare {0} with the same namespace in every file of the model"),
)
SAFE = Applicability.SAFE
MODEL_ERROR = "the model reports this with xacro.error(), which xacro prints and goes on from: correct the arguments or the model"
_DEPRECATED_CALL = re.compile(r"Using (\w+)\(\) directly is deprecated")
_START_TAG = re.compile(r"""<[^\s/>]+(?:[^>"']|"[^"]*"|'[^']*')*>""")  # quoted values may hold '>'


def fix(text: str) -> str | None:
    """The fix for one of xacro's warnings (None for words this module does not know)."""
    for pattern, hint in _FIXES:
        found = pattern.search(text)
        if found:
            return hint.format(*found.groups())
    return None


_DEPRECATED = re.compile(r"Using (\w+)\(\) directly is deprecated\. Use (\w+)\.\1\(\) instead\.")
_PREFIXED_MACRO = re.compile(r"macro names must not contain prefix 'xacro:': xacro:(\w+)")
_MACRO_NAME = re.compile(r"""\sname\s*=\s*["']\s*(xacro:)""")


def warning(text: str, location: Location, files: SourceFiles, error: bool = False) -> Diagnostic:
    """X005 for one of xacro's warnings, at the element xacro was at (at the deprecated
    call itself, when the element's start tag holds it), with its fix; for a form xacro
    still reads and has deprecated, the edit that writes it as xacro wants it. An
    ``error`` (the model's own ``xacro.error()``: its arguments are wrong) is an error:
    xacro prints it and still writes a URDF, which the model says is not to be used."""
    if error:
        return Diagnostic("X005", text, location, severity=Severity.ERROR, hint=MODEL_ERROR)
    found = _DEPRECATED_CALL.search(text)
    if found is not None and location.line and location.column:
        location = _at_call(found.group(1), location, files)
    kept = _kept_for_older_xacro(text, location, files)
    if kept is not None:
        return Diagnostic("X005", text, location, hint=kept[0], fix=kept[1])
    return Diagnostic("X005", text, location, hint=_parameter_fix(text, location, files) or fix(text), fix=_rewrite(text, location, files))


_OPPOSITE = {"if": "unless", "unless": "if"}


def _kept_for_older_xacro(text: str, location: Location, files: SourceFiles) -> tuple[str, Fix] | None:
    """The hint, and the fix without an edit, of a deprecated call the file keeps on purpose: it is
    written in an ``xacro:if`` (or ``xacro:unless``) whose twin on the same condition
    writes the new form, so that an xacro without it (ROS Noetic's before 1.14.10 has no
    ``xacro.load_yaml``) still reads the file (xArm's ``use_xacro_load_yaml``). Rewriting
    the call would make both branches the new form; the condition is what to set."""
    deprecated = _DEPRECATED.search(text)
    source = files.get(location.file) if deprecated is not None and location.line and location.column else None
    if source is None or source.tree is None:
        return None
    name, namespace = deprecated.groups()
    condition = _condition_around(source, source.offset(location.line, location.column))
    if condition is None:
        return None
    kind, value = local_name(condition.tag), (condition.get("value") or "").strip()
    new_form = re.compile(rf"(?<![\w.]){re.escape(namespace)}\.{re.escape(name)}\s*\(")
    for twin in condition.itersiblings(preceding=True) if kind == "unless" else condition.itersiblings():
        if (is_xacro(twin) and local_name(twin.tag) == _OPPOSITE[kind] and (twin.get("value") or "").strip() == value
                and any(new_form.search(written) for element in twin.iter() for written in (*element.attrib.values(), element.text or ""))):
            hint = (f"the file keeps {name}() for an xacro without {namespace}.{name}(), which it writes where {value} "
                    f"is true: make {value} true where xacro has it")
            return hint, Fix(f"write {namespace}.{name}()", SAFE, reason=f"{name}() is kept on purpose for an xacro without {namespace}.{name}()")
    return None


def _condition_around(source: SourceFile, at: int | None):
    """The ``xacro:if`` or ``xacro:unless`` nearest around the element whose start tag holds ``at``."""
    if at is None:
        return None
    holding = None
    for element in source.elements:
        start = source.start_of(element)
        if start is None or start > at:
            break
        holding = element
    while holding is not None and not (is_xacro(holding) and local_name(holding.tag) in _OPPOSITE):
        holding = holding.getparent()
    return holding


_REDEFINED = re.compile(r"redefining global symbol: (\w+)")
_CALLED = re.compile(r"<xacro:([\w.]+)")


def _parameter_fix(text: str, location: Location, files: SourceFiles) -> str | None:
    """The fix of a global symbol a macro's parameter redefines (xacro was at the call):
    the name is hidden in that macro's body only, and it is no property."""
    redefined = _REDEFINED.search(text)
    source = files.get(location.file) if redefined is not None and location.line and location.column else None
    at = source.offset(location.line, location.column) if source is not None else None
    called = _CALLED.match(source.text, at) if at is not None else None
    if called is None or called.group(1) in ("property", "arg", "call"):
        return None
    name, macro = redefined.group(1), called.group(1).rpartition(".")[2]
    return f"rename parameter '{name}' of macro '{macro}', and where calls pass it: in the macro's body it hides the '{name}' xacro gives every expression"


def _rewrite(text: str, location: Location, files: SourceFiles) -> Fix | None:
    """The edit of a deprecated form: ``load_yaml(`` written ``xacro.load_yaml(``, a macro
    named ``xacro:NAME`` named ``NAME``; None for the other warnings."""
    deprecated, prefixed = _DEPRECATED.search(text), _PREFIXED_MACRO.search(text)
    if deprecated is None and prefixed is None:
        return None
    source = files.get(location.file) if location.line and location.column else None
    at = source.offset(location.line, location.column) if source is not None else None
    if deprecated is not None:
        name, namespace = deprecated.groups()
        title = f"write {namespace}.{name}()"
        if at is None or not re.match(rf"{re.escape(name)}\s*\(", source.text[at:]):
            return Fix(title, SAFE, reason="the call is not where xacro was (in the text of an element, or a property's value)")
        return Fix(title, SAFE, edits=(Edit(location.file, at, at, f"{namespace}."),))
    title = f'write name="{prefixed.group(1)}"'
    tag = _START_TAG.match(source.text, at) if at is not None else None
    written = _MACRO_NAME.search(tag.group()) if tag is not None else None
    if written is None:
        return Fix(title, SAFE, reason="the macro's name is not written where xacro read it")
    start = at + written.start(1)
    return Fix(title, SAFE, edits=(Edit(location.file, start, start + len("xacro:"), ""),))


def _at_call(name: str, location: Location, files: SourceFiles) -> Location:
    source = files.get(location.file)
    start = source.offset(location.line, location.column) if source is not None else None
    if start is None:
        return location
    tag = _START_TAG.match(source.text, start)
    call = re.compile(rf"(?<![\w.]){re.escape(name)}\s*\(").search(source.text, start, tag.end()) if tag else None
    if call is None:
        return location
    line, column = source.position(call.start())
    return location._replace(line=line, column=column)
