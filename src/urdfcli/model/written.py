"""Where a value of the model was written, and the edit that changes it there.

A rule's fix says what to change in the model as read (:class:`~urdfcli.diagnostics.SetAttribute`:
this attribute of that element should be this value; :class:`~urdfcli.diagnostics.InsertChild`).
For a plain URDF the element is in the file. For a xacro model the element's
origin is where its ``<`` was written, through includes and macro bodies, and
the value is followed from there:

- a literal, or the literal part of a value (``package://${pkg}/meshes/arm.STL``
  for the extension), is edited where it is;
- ``${name}`` where ``name`` is a parameter of the macro whose body holds the
  element: at the call that made the element (and on up, when the call passes
  a parameter of its own caller);
- ``${name}`` where ``name`` is a property defined once in the files the model
  reads: in the property's value.

Anything else (an expression, a substitution such as ``$(arg x)``, a property
defined twice or computed, a parameter left to its default) is not edited, and
:class:`Unplaceable` says why and where the value comes from.

An edit of text that makes several values of the model (a literal in a macro
body called three times, a property read in two places) is made only when every
value it changes is one a fix asks to change in the same way: each
:class:`Spot` says which values it affects, and :func:`place_fixes` checks them
against what all the model's fixes ask for.
"""

from __future__ import annotations

import bisect
import os
import re
from collections import defaultdict
from collections.abc import Iterable
from typing import NamedTuple

from ..diagnostics import Call, Change, Diagnostic, Edit, Fix, InsertChild, SetAttribute
from ..read.positions import Text
from ..read.xacro_scan import TAIL, TEXT, XacroFile, free_names, lexed, macro_parameters
from .load import Loaded
from .sources import bound, file_facts

_NAME = re.compile(r"<([^\s/>]+)")
_START_TAG = re.compile(r"""<[^\s/>!?](?:[^>"'/]|/(?!>)|"[^"]*"|'[^']*')*/?>""")  # quoted values may hold '>'
_VALUE = re.compile(r"""\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_TOKEN = re.compile(r"""(?:\$\{[^}]*\}|\$\([^)]*\)|\S)+""")  # a whitespace-separated part, ${...} whole
_IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
_NEGATED = re.compile(r"-\s*([A-Za-z_]\w*)")
_NUMBER = re.compile(r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?")
_BLANKS = str.maketrans("\t\n\r", "   ")
CHILD = "<child>"  # the key of an InsertChild among attribute names

Value = tuple[int, str]  # (element of the model, attribute): one value a fix may change


class Unplaceable(Exception):
    """No edit can make the change: the reason, naming where the value comes from."""


class Spot(NamedTuple):
    """One edit, and the values of the model it changes."""

    edit: Edit
    affected: frozenset[Value]


class _Site(NamedTuple):
    """A source element that a value of the model was written in."""

    file: str
    source: Text
    scan: XacroFile | None  # None for a plain URDF
    element: int  # its index in the file, in document order
    start: int  # the offset of its ``<``
    trace: tuple[Call, ...]  # the macro calls that made the value, innermost first
    instances: tuple[int, ...]  # the model's elements this one made (through this trace)


def _key(change: Change) -> Value:
    return (change.at, change.attribute) if isinstance(change, SetAttribute) else (change.at, CHILD)


def escape_attribute(text: str, quote: str = '"') -> str:
    """``text`` as an XML attribute value between ``quote``\\ s."""
    text = text.replace("&", "&amp;").replace("<", "&lt;")
    return text.replace(quote, "&quot;" if quote == '"' else "&apos;")


def _same_number(written: str, read: str) -> bool:
    """Whether a literal and the value read from it are one number, written two ways."""
    try:
        return float(written) == float(read)
    except ValueError:
        return False


def _common(old: str, new: str) -> tuple[int, int]:
    """The length of the common start and of the common end of two texts (not overlapping)."""
    most = min(len(old), len(new))
    start = 0
    while start < most and old[start] == new[start]:
        start += 1
    end = 0
    while end < most - start and old[len(old) - 1 - end] == new[len(new) - 1 - end]:
        end += 1
    return start, end


class Placer:
    """Turns the changes of one model's fixes into edits of its sources."""

    def __init__(self, loaded: Loaded) -> None:
        self.loaded = loaded
        self.document = loaded.document
        self.model = self.document.model_source
        sources = loaded.xacro_sources
        self.scans = {_absolute(f.name): f for f in sources.reached} if sources is not None and self.document.is_xacro else {}
        self._instances: dict | None = None
        self._files: dict[str, int] = {}

    # -- the element a value of the model was written in ----------------------------
    def site(self, at: int) -> _Site:
        model = self.model
        if model is None or model.start(at) is None:
            raise Unplaceable("the model's text is not at hand")
        origins = self.document.origins
        if origins is None:  # a plain URDF: the element is in the file
            return _Site(self.document.shown, model, None, at, model.start(at), (), (at,))
        origin = origins[at] if at < len(origins) else None
        if origin is None or not origin.line or not origin.column:
            raise Unplaceable("where xacro made this element is not known")
        scan = self.scans.get(_absolute(origin.file))
        if scan is None:
            raise Unplaceable(f"{origin.file} is not a file urdfcli read as xacro")
        start = scan.source.offset(origin.line, origin.column)
        element = _index(scan.source, start)
        if element is None or _tag(scan.source, start) != _tag(model, model.start(at)):
            raise Unplaceable(f"the element at {origin.file}:{origin.line} is not written as it is read (made by xacro)")
        return _Site(origin.file, scan.source, scan, element, start, origin.trace, tuple(self.instances(origin.file, element)))

    def instances(self, file: str, element: int, through: tuple[Call, ...] = ()) -> list[int]:
        """The model's elements made from element ``element`` of ``file``; with
        ``through``, only those its macro calls made."""
        origins = self.document.origins
        scan = self.scans[_absolute(file)]
        line, column = scan.source.position(scan.source.spans[element][0])
        if self._instances is None:
            found: dict = defaultdict(list)
            places = origins.places
            for at in range(0, len(places), 4):
                found[(places[at], places[at + 1], places[at + 2])].append(at // 4)
            self._instances = found
            self._files = {_absolute(name): index for index, name in enumerate(origins.files)}
        if _absolute(file) not in self._files:
            return []
        made = self._instances.get((self._files[_absolute(file)], line, column), [])
        if not through:
            return made
        calls = {i for i, c in enumerate(origins.calls) if any((c[0], c[1], c[2]) == (t.file, t.line, t.column) for t in through)}
        return [at for at in made if calls & set(origins.traces[origins.places[at * 4 + 3]])]

    def where(self, site: _Site, offset: int | None = None) -> str:
        start = site.start if offset is None else offset
        return f"{site.file}:{site.source.position(start)[0]}"

    def same_for_every_argument_set(self, at: int, attribute: str) -> None:
        """Raises Unplaceable when value ``attribute`` of element ``at`` comes from a xacro
        argument (or an environment variable): directly, through the parameters of the
        macro calls that made it, or through a property. A value worked out from it
        and written as a literal would fit this argument set only."""
        site = self.site(at)
        if site.scan is None:
            return  # a plain URDF: every value is written as it is
        raw = self._written(site, attribute)
        if raw is not None:
            self._given_by_arguments(site, raw, f'{attribute}="{raw}" at {self.where(site)}', 0)

    def _written(self, site: _Site, attribute: str) -> str | None:
        text = site.source.text
        name = site.source.attribute(site.start, attribute)
        value = _VALUE.match(text, name + len(attribute)) if name is not None else None
        if value is None:
            return None
        return value.group(1) if value.group(1) is not None else value.group(2)

    def _given_by_arguments(self, site: _Site, raw: str, what: str, depth: int) -> None:
        for kind, _, _, inner in lexed(raw):
            if kind == "substitution" and inner.split()[:1] in (["arg"], ["env"], ["optenv"]):
                raise Unplaceable(f"the new values would be worked out from {what}, which $({inner}) gives: they would fit this argument set only")
            if kind != "expression" or depth > 8:
                continue
            macros = site.scan.macros_at(site.start)
            for name in dict.fromkeys(n.name for n in free_names(inner) or ()):
                declared = [(m, p) for m in macros for p in macro_parameters(site.scan.macros[m].params) if p.name == name and not p.block]
                if not declared:
                    for file in self.scans.values():
                        for definition in file.definitions:
                            if definition.kind == "property" and definition.name == name and definition.value:
                                self._given_by_arguments(site, definition.value, what, depth + 1)
                    continue
                macro, parameter = declared[0]
                called = site.trace[0] if site.trace else None
                if macro != macros[0] or called is None or called.macro.rpartition(".")[2] != site.scan.macros[macro].name.removeprefix("xacro:"):
                    continue  # (the call that gives it is not known)
                try:
                    call_site = self._call_site(site, what)
                except Unplaceable:
                    continue
                passed = self._written(call_site, name)
                if passed is not None:
                    self._given_by_arguments(call_site, passed, what, depth + 1)
                elif parameter.default is not None:
                    self._given_by_arguments(site, parameter.default, what, depth + 1)

    # -- a change ---------------------------------------------------------------------
    def place(self, change: Change) -> list[Spot]:
        """The edits that make ``change``; raises Unplaceable."""
        site = self.site(change.at)
        if isinstance(change, InsertChild):
            return [self._insert_child(site, change)]
        old = self.model.value(change.at, change.attribute)
        old = old.translate(_BLANKS) if old is not None else None  # as XML reads it
        if old == change.value:
            return []
        affected = frozenset((at, change.attribute) for at in site.instances)
        return self._attribute(site, change.attribute, old, change.value, affected)

    def _insert_child(self, site: _Site, change: InsertChild) -> Spot:
        span = site.source.span(site.element)
        if span is None:
            raise Unplaceable(f"the element at {self.where(site)} cannot be read")
        start, tag_end, end = span
        text = site.source.text
        if text[tag_end - 2:tag_end] == "/>":
            raise Unplaceable(f"<{_tag(site.source, start)}> at {self.where(site)} has no children to write it among")
        own = _indentation(text, start)
        child = site.source.start(site.element + 1)
        inner = _indentation(text, child) if child is not None and child < end and "\n" in text[tag_end:child] else own + "  "
        return Spot(Edit(site.file, tag_end, tag_end, "\n" + inner + change.markup), frozenset((at, CHILD) for at in site.instances))

    def _attribute(self, site: _Site, attribute: str, old: str | None, new: str, affected: frozenset[Value]) -> list[Spot]:
        text = site.source.text
        start = site.start
        tag = _START_TAG.match(text, start)
        if tag is None:
            raise Unplaceable(f"the element at {self.where(site)} cannot be read")
        tag_end = tag.end()
        name = site.source.attribute(start, attribute)
        if name is None:
            if old is not None:
                raise Unplaceable(f"attribute {attribute} of the element at {self.where(site)} is not written there")
            close = tag_end - 2 if text[tag_end - 2:tag_end] == "/>" else tag_end - 1
            at = len(text[:close].rstrip())
            return [Spot(Edit(site.file, at, at, f' {attribute}="{escape_attribute(new)}"'), affected)]
        value = _VALUE.match(text, name + len(attribute))
        if value is None or old is None:
            raise Unplaceable(f"attribute {attribute} at {self.where(site)} cannot be read")
        group = 1 if value.group(1) is not None else 2
        quote = text[value.start(group) - 1]
        return self._text(site, value.start(group), value.group(group), old, new, quote, affected)

    def _text(self, site: _Site, base: int, raw: str, old: str, new: str, quote: str, affected: frozenset[Value]) -> list[Spot]:
        """The edits of ``raw`` (written at ``base``) that turn the value ``old`` it makes into ``new``."""
        if "&" in raw:
            raise Unplaceable(f"the value at {self.where(site, base)} is written with an XML entity")
        pieces = lexed(raw)
        computed = [p for p in pieces if p[0] != "text"]
        if not computed:
            if raw.translate(_BLANKS) != old:  # (XML reads a tab or a new line in a value as a space)
                if not _same_number(raw, old):
                    raise Unplaceable(f"the value at {self.where(site, base)} is not read as written")
                # xacro read the number through ${...} and wrote it its own way (0.000096 as 9.6e-05): the number is written anew
                begin = len(raw) - len(raw.lstrip())
                return [Spot(Edit(site.file, base + begin, base + len(raw.rstrip()), escape_attribute(new, quote)), affected)]
            start, end = _common(old, new)
            return [Spot(Edit(site.file, base + start, base + len(raw) - end, escape_attribute(new[start:len(new) - end], quote)), affected)]
        head, tail = raw[:computed[0][1]], raw[computed[-1][2]:]
        start, end = _common(old, new)
        if old.startswith(head) and old.endswith(tail) and len(old) >= len(head) + len(tail):
            # (a change touching no literal character, such as a sign put before ${swing}, is the expression's)
            if len(old) - end <= len(head) and start < len(head):  # the change is in the literal text before the first ${...}
                return [Spot(Edit(site.file, base + start, base + len(old) - end, escape_attribute(new[start:len(new) - end], quote)), affected)]
            if start >= len(old) - len(tail) and end < len(tail):  # in the literal text after the last one
                begin = base + len(raw) - (len(old) - start)
                return [Spot(Edit(site.file, begin, base + len(raw) - end, escape_attribute(new[start:len(new) - end], quote)), affected)]
            if len(computed) == 1 and computed[0][0] == "expression" and start >= len(head) and end >= len(tail):
                given = (old[len(head):len(old) - len(tail)], new[len(head):len(new) - len(tail)])
                return self._expression(site, base + computed[0][1] + 2, computed[0][3], *given)
        old_parts, new_parts, written = old.split(), new.split(), list(_TOKEN.finditer(raw))
        if len(written) > 1 and len(written) == len(old_parts) == len(new_parts):
            spots = []
            for part, before, after in zip(written, old_parts, new_parts):
                if before != after:
                    spots += self._text(site, base + part.start(), part.group(), before, after, quote, affected)
            return spots
        first = next((p for p in computed if p[0] != "text"), computed[0])
        shown = f"${{{first[3]}}}" if first[0] == "expression" else f"$({first[3]})" if first[0] == "substitution" else raw
        raise Unplaceable(f"the value is computed by {shown} at {self.where(site, base)}")

    # -- a ${name} ------------------------------------------------------------------
    def _expression(self, site: _Site, at: int, inner: str, old: str, new: str) -> list[Spot]:
        name = inner.strip()
        negated = _NEGATED.fullmatch(name)
        if negated and _NUMBER.fullmatch(old) and _NUMBER.fullmatch(new):
            # ${-name} (a lower bound beside ${name}): the number written for name is the negated one
            return self._expression(site, at, negated.group(1), _negated(old), _negated(new))
        if not _IDENTIFIER.fullmatch(name) or site.scan is None:
            raise Unplaceable(f"the value is computed by ${{{inner}}} at {self.where(site, at)}")
        scan = site.scan
        macros = scan.macros_at(scan.source.spans[site.element][0])
        for depth, macro in enumerate(macros):
            parameter = next((p for p in macro_parameters(scan.macros[macro].params) if p.name == name and not p.block), None)
            if parameter is None:
                continue
            return self._parameter(site, at, macro, depth, parameter, old, new)
        return self._property(site, at, name, macros, old, new)

    def _parameter(self, site: _Site, at: int, macro: int, depth: int, parameter, old: str, new: str) -> list[Spot]:
        scan = site.scan
        name, macro_name = parameter.name, scan.macros[macro].name.removeprefix("xacro:")
        if depth or parameter.forward or not site.trace or site.trace[0].macro.rpartition(".")[2] != macro_name:
            raise Unplaceable(f"the value is parameter '{name}' of macro '{macro_name}' ({self.where(site, at)}), whose call is not known")
        sources = self.loaded.xacro_sources
        if sources is None or not sources.complete or name in sources.reached_facts.free:
            # a macro body that reads a name it does not define reads its caller's: this one's too, maybe
            raise Unplaceable(f"the value is parameter '{name}' of macro '{macro_name}', which another macro's body may read too")
        call = site.trace[0]
        call_site = self._call_site(site, f"the value is parameter '{name}' of macro '{macro_name}'")
        call_scan, start = call_site.scan, call_site.start
        if call_scan.source.attribute(start, name) is None:
            raise Unplaceable(f"the value is the default of parameter '{name}' of macro '{macro_name}' ({self.where(site, at)}), which the call at {call.file}:{call.line} leaves")
        affected = set()
        for read in self._reads(scan, name, lambda expression: scan.within(expression.macro, macro), f"parameter '{name}' of macro '{macro_name}'"):
            affected.update((i, read[1]) for i in self.instances(scan.name, read[0], (call,)))
        return self._attribute(call_site, name, old, new, frozenset(affected))

    def _call_site(self, site: _Site, what: str) -> _Site:
        """The innermost macro call that made ``site``'s element, as a site of its own; raises
        Unplaceable (``what``: the value the reason is about)."""
        call = site.trace[0]
        call_scan = self.scans.get(_absolute(call.file))
        if call_scan is None or not call.line or not call.column:
            raise Unplaceable(f"{what}, called where urdfcli cannot edit")
        element = _index(call_scan.source, call_scan.source.offset(call.line, call.column))
        if element is None:
            raise Unplaceable(f"the call of macro '{call.macro.rpartition('.')[2]}' at {call.file}:{call.line} cannot be read")
        return _Site(call.file, call_scan.source, call_scan, element, call_scan.source.spans[element][0], site.trace[1:], ())

    def _property(self, site: _Site, at: int, name: str, macros: list[int], old: str, new: str) -> list[Spot]:
        definitions = [
            (file, d) for file in self.scans.values() for d in file.definitions
            if d.kind == "property" and d.name == name and (d.macro is None or d.scope in ("global", "parent") or (file is site.scan and d.macro in macros))
        ]
        what = f"property '{name}'"
        if not definitions:
            raise Unplaceable(f"the value is ${{{name}}} at {self.where(site, at)}, defined where urdfcli cannot follow")
        if len(definitions) > 1:
            places = ", ".join(f"{f.name}:{f.position(d.place)[0]}" for f, d in definitions[:3])
            raise Unplaceable(f"the value is {what}, defined {len(definitions)} times ({places})")
        file, definition = definitions[0]
        element = definition.place.element
        start = file.source.spans[element][0]
        written = "value" if file.source.attribute(start, "value") is not None else "default"
        if definition.value is None or "$" in definition.value:
            raise Unplaceable(f"the value is {what}, computed by {definition.value!r} at {file.name}:{file.position(definition.place)[0]}")
        own = self._model_files()
        local = definition.macro is not None and definition.scope is None
        affected = set()
        for scan in self.scans.values():

            def reads_it(expression, scan=scan) -> bool:
                if local:
                    return scan is file and scan.within(expression.macro, definition.macro)
                return name not in bound(scan, expression.macro)

            for read in self._reads(scan, name, reads_it, what):
                if _absolute(scan.name) not in own:
                    raise Unplaceable(f"{what} ({file.name}:{file.position(definition.place)[0]}) is also read in {scan.name}, outside this model")
                affected.update((i, read[1]) for i in self.instances(scan.name, read[0]))
        for scan in self._universe():
            defines = any(d.kind == "property" and d.name == name and d.macro is None for d in scan.definitions)
            if _absolute(scan.name) not in self.scans and name in _names_read(scan) and not defines:  # (one that defines it reads its own)
                raise Unplaceable(f"{what} ({file.name}:{file.position(definition.place)[0]}) may also be read in {scan.name}, outside this model")
        property_site = _Site(file.name, file.source, file, element, start, (), ())
        return self._attribute(property_site, written, old, new, frozenset(affected))

    def _reads(self, scan: XacroFile, name: str, counts, what: str) -> Iterable[tuple[int, str]]:
        """(element, attribute) of each ``${...}`` of ``scan`` that reads ``name`` where
        ``counts(expression)``; raises Unplaceable for one urdfcli cannot follow to
        the model (in a xacro element, in text, in a substitution)."""
        word = re.compile(rf"(?<![\w.]){re.escape(name)}(?!\w)")
        for expression in scan.expressions:
            if not counts(expression):
                continue
            names = free_names(expression.text)
            if (names is None and not word.search(expression.text)) or (names is not None and all(n.name != name for n in names)):
                continue
            place = expression.place
            where = f"{scan.name}:{scan.position(place)[0]}"
            if names is None or expression.in_substitution:
                raise Unplaceable(f"the value is {what}, also read by ${{{expression.text}}} at {where}")
            if place.within in (TEXT, TAIL) or _is_xacro_tag(scan.source, place.element):
                raise Unplaceable(f"the value is {what}, also read at {where}, where it does not go into the model as such")
            yield place.element, place.within
        for substitution in scan.substitutions:
            if substitution.function == "eval" and counts(substitution) and word.search(substitution.argument):
                raise Unplaceable(f"the value is {what}, also read by $(eval ...) at {scan.name}:{scan.position(substitution.place)[0]}")

    def _model_files(self) -> set[str]:
        sources = self.loaded.xacro_sources
        return {_absolute(f.name) for f in sources.files} if sources is not None else set()

    def _universe(self) -> list[XacroFile]:
        sources = self.loaded.xacro_sources
        return sources.universe if sources is not None else []


def _absolute(name: str) -> str:
    """A file's name as the lookups here keep it: absolute (standard input as it is)."""
    return name if name.startswith("<") else os.path.abspath(name)


def _negated(number: str) -> str:
    """``-150`` for ``150`` and ``150`` for ``-150``, written as it was otherwise."""
    return number[1:] if number.startswith("-") else "-" + number


def _index(source: Text, start: int | None) -> int | None:
    """The index (document order) of the element whose ``<`` is at ``start``."""
    if start is None or not source.spans:
        return None
    starts = source.starts
    found = bisect.bisect_left(starts, start)
    return found if found < len(starts) and starts[found] == start and found < len(source.spans) else None


def _tag(source: Text, start: int) -> str | None:
    found = _NAME.match(source.text, start)
    return found.group(1) if found else None


def _indentation(text: str, offset: int) -> str:
    line_start = text.rfind("\n", 0, offset) + 1
    before = text[line_start:offset]
    return before if not before.strip() else before[: len(before) - len(before.lstrip())]


def _is_xacro_tag(source: Text, element: int) -> bool:
    tag = _tag(source, source.spans[element][0]) or ""
    return tag.startswith("xacro:")


def _names_read(scan: XacroFile) -> set[str]:
    return set(file_facts(scan).names)


# -- a model's fixes --------------------------------------------------------------------
def place_fixes(loaded: Loaded, diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    """The diagnostics with each fix's changes placed in the sources: as edits, or
    with the reason they cannot be. An edit that would change a value of the model
    no fix asks to change (a literal in a macro body whose other calls need no
    change) is not made."""
    pending = [d for d in diagnostics if d.fix is not None and d.fix.changes]
    if not pending:
        return diagnostics
    placer = Placer(loaded)
    placed: dict[int, list[tuple[Change, list[Spot]]] | str] = {}
    wanted: dict[Edit, set[Value]] = defaultdict(set)
    for number, diagnostic in enumerate(diagnostics):
        fix = diagnostic.fix
        if fix is None or not fix.changes:
            continue
        try:
            for at, attribute in fix.inputs:
                placer.same_for_every_argument_set(at, attribute)
            spots = [(change, placer.place(change)) for change in fix.changes]
        except Unplaceable as why:
            placed[number] = str(why)
            continue
        except (IndexError, KeyError, ValueError) as error:  # a text that is not what the model was read from
            placed[number] = f"the sources cannot be followed here ({type(error).__name__})"
            continue
        placed[number] = spots
        for change, found in spots:
            for spot in found:
                wanted[spot.edit].add(_key(change))
    out = []
    for number, diagnostic in enumerate(diagnostics):
        outcome = placed.get(number)
        if outcome is None:
            out.append(diagnostic)
            continue
        fix = diagnostic.fix
        if isinstance(outcome, str):
            out.append(diagnostic.with_fix(fix._replace(changes=(), reason=outcome)))
            continue
        edits, reason = [], None
        for _, spots in outcome:
            for spot in spots:
                others = spot.affected - wanted[spot.edit]
                if others:
                    line = placer_line(loaded, spot.edit)
                    reason = f"editing {line} would also change {len(others)} other value{'s' if len(others) > 1 else ''} of the model, which need{'s' if len(others) == 1 else ''} no such change"
                    break
                edits.append(spot.edit)
            if reason:
                break
        if not reason and not edits:
            reason = "the model already has these values"
        out.append(diagnostic.with_fix(fix._replace(changes=(), edits=() if reason else tuple(dict.fromkeys(edits)), reason=reason)))
    return out


def placer_line(loaded: Loaded, edit: Edit) -> str:
    """``FILE:LINE`` of an edit."""
    source = loaded.document.files.get(edit.file)
    return f"{edit.file}:{source.position(edit.start)[0]}" if source is not None else edit.file


__all__ = ["CHILD", "Placer", "Spot", "Unplaceable", "escape_attribute", "place_fixes"]
