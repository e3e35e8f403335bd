"""The xacro sources behind one model, and what they say across files.

A model's expansion reads some files: its input and the files xacro included.
The source rules (:mod:`urdfcli.rules.xacro`, :mod:`urdfcli.rules.packages`)
report about those files (:attr:`XacroSources.files`). To tell whether a
definition is used, or a name is defined, they look further: at the files the
includes may reach under any condition (``reached``), then at the xacro files
of the repository or workspace around the model (``universe``: another model
may call a library's macro). The wider sets are read only when a rule needs
them, and where a use or a definition cannot be ruled out it counts: a source
finding must be certain.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from functools import cached_property
from typing import NamedTuple

from ..read.memo import once
from ..read.xacro_scan import Parameter, Place, XacroFile, XacroGlobals, free_names, literal_calls


class Facts(NamedTuple):
    """What a set of files reads and defines, by name. An ``any_*`` flag is set when
    a file reads or defines a name computed by an expression: then any name may be."""

    names: frozenset[str]  # names read in ${...}
    arguments: frozenset[str]  # xacro arguments read: $(arg x), $(eval ...), xacro.arg('x')
    any_argument: bool
    calls: frozenset[str]  # macros called (the name after any namespace)
    any_call: bool  # <xacro:call macro="${...}">
    blocks: frozenset[str]  # insert_block names
    globals: frozenset[str]  # properties defined for the whole document, and include namespaces
    any_global: bool
    forwarded: frozenset[str]  # parameters taken from the caller's scope (name:=^)
    free: frozenset[str]  # names a macro body reads that it does not define: its callers' (xacro's scope is the caller's)
    free_blocks: frozenset[str]  # blocks a macro body inserts that are not its own block parameters
    variants: frozenset[tuple[str, str]]  # (macro, parameter as written): a macro of that name uses that parameter
    interfaces: frozenset[tuple[str, str]]  # (parameter list, parameter): a macro taking that list uses that parameter
    unprefixed: frozenset[str] = frozenset()  # elements written without a prefix: among them, macros called without xacro:
    unbound: frozenset[str] = frozenset()  # names read where no macro around binds them (the top level, or free): a document property may be what they read


def chain(file: XacroFile, macro: int | None) -> list[int]:
    """A macro and the macros whose bodies hold its definition, innermost first."""
    found = []
    while macro is not None:
        found.append(macro)
        macro = file.macros[macro].parent
    return found


def parameters(file: XacroFile, macro: int) -> tuple[Parameter, ...]:
    return file.macros[macro].parameters


def used_parameters(file: XacroFile, macro: int) -> frozenset[str]:
    """The parameters (as written: ``*origin`` for a block) a macro's body, nested
    macros included, uses: a name it reads in ``${...}`` (every name, where an
    expression cannot be read), a block it inserts."""
    return once(file, _used_parameters)[macro]


def _used_parameters(file: XacroFile) -> list[frozenset[str]]:
    read: list[set[str]] = [set() for _ in file.macros]
    unreadable: set[int] = set()
    inserted: list[set[str]] = [set() for _ in file.macros]
    for expression in file.expressions:
        names = free_names(expression.text)
        for macro in chain(file, expression.macro):
            if names is None:
                unreadable.add(macro)
            else:
                read[macro].update(n.name for n in names)
    for block in file.blocks:
        for macro in chain(file, block.macro):
            inserted[macro].add(block.name)
    return [
        frozenset(
            p.shown for p in parameters(file, macro)
            if (p.name in inserted[macro] if p.block else macro in unreadable or p.name in read[macro])
        )
        for macro in range(len(file.macros))
    ]


def interface(file: XacroFile, macro: int) -> str:
    """A macro's parameter list, whatever their order and defaults: macros that one
    computed call (``<xacro:call macro="${...}"/>``) may stand for share it."""
    return " ".join(sorted(p.shown for p in parameters(file, macro)))


def bound(file: XacroFile, macro: int | None) -> frozenset[str]:
    """The names a body binds where ``macro`` is: the parameters of the macro and of
    those around it, and the properties defined in their bodies."""
    return once(file, _bound, macro)


def _bound(file: XacroFile, macro: int | None) -> frozenset[str]:
    macros = chain(file, macro)
    names = {p.name for m in macros for p in parameters(file, m) if not p.block}
    names |= {d.name for d in file.definitions if d.kind == "property" and d.macro in macros and d.scope is None}
    return frozenset(names)


def file_facts(file: XacroFile) -> Facts:
    """What one file reads and defines (worked out once per file read)."""
    return once(file, _facts_of)


def _facts_of(file: XacroFile) -> Facts:
    names, free, arguments, globals_, unbound = set(), set(), set(), set(), set()
    any_argument = any_global = False
    for expression in file.expressions:
        read = free_names(expression.text)
        if read is None:
            continue
        names.update(n.name for n in read)
        if expression.macro is not None:
            free.update(n.name for n in read if n.name not in bound(file, expression.macro))
        unbound.update(n.name for n in read if expression.macro is None or n.name not in bound(file, expression.macro))
        if any(n.dotted == "xacro.arg" for n in read):
            given = literal_calls(expression.text, ("xacro.arg",))
            any_argument |= given is None
            arguments.update(given or ())
    for substitution in file.substitutions:
        if substitution.function == "arg":
            if "$" in substitution.argument:
                any_argument = True
            arguments.add(substitution.argument)
        elif substitution.function == "eval":
            read = free_names(substitution.argument)
            given = literal_calls(substitution.argument, ("arg",))
            any_argument |= read is None or given is None
            arguments.update(n.name for n in read or () if n.name != "arg")
            arguments.update(given or ())
    for definition in file.definitions:
        if definition.kind == "property" and (definition.macro is None or definition.scope in ("global", "parent")):
            globals_.add(definition.name)
            any_global |= "$" in definition.name
    for namespace in file.namespaces:
        globals_.add(namespace)
        any_global |= "$" in namespace
    calls = {call.name.rpartition(".")[2] for call in file.calls}
    forwarded = {p.name for m in range(len(file.macros)) for p in parameters(file, m) if p.forward}
    free_blocks = {
        block.name for block in file.blocks
        if block.macro is not None and block.name not in {p.name for m in chain(file, block.macro) for p in parameters(file, m) if p.block}
    }
    used = [(macro, parameter) for macro in range(len(file.macros)) for parameter in used_parameters(file, macro)]
    return Facts(
        frozenset(names), frozenset(arguments), any_argument,
        frozenset(calls), any("$" in c for c in calls),
        frozenset(b.name for b in file.blocks), frozenset(globals_), any_global,
        frozenset(forwarded), frozenset(free), frozenset(free_blocks),
        frozenset((file.macros[m].name, p) for m, p in used), frozenset((interface(file, m), p) for m, p in used),
        frozenset(file.unprefixed), frozenset(unbound),
    )


def merged(facts: Iterable[Facts]) -> Facts:
    facts = list(facts)
    fields = ("names", "arguments", "calls", "blocks", "globals", "forwarded", "free", "free_blocks", "variants", "interfaces", "unprefixed", "unbound")
    union = [frozenset().union(*(getattr(f, field) for f in facts)) for field in fields]
    names, arguments, calls, blocks, globals_, forwarded, free, free_blocks, variants, interfaces, unprefixed, unbound = union
    return Facts(
        names, arguments, any(f.any_argument for f in facts), calls, any(f.any_call for f in facts),
        blocks, globals_, any(f.any_global for f in facts), forwarded, free, free_blocks, variants, interfaces, unprefixed, unbound,
    )


class MacroCall(NamedTuple):
    file: XacroFile
    macro: int | None  # the macro whose body holds the call (None: the top level)
    attributes: dict[str, str]
    place: Place


class XacroSources:
    """The xacro files of one model (``files``, where findings are reported), and,
    read when first asked for, those its includes may reach and those of the
    workspace around it. ``reach()`` gives the former, and whether every include
    on the way could be followed; ``around()`` the latter (the project layer knows
    where to look)."""

    def __init__(
        self,
        files: list[XacroFile],
        reach: Callable[[], tuple[list[XacroFile], bool]],
        around: Callable[[], list[XacroFile]],
        xacro: Callable[[], XacroGlobals | None] = lambda: None,
    ) -> None:
        self.files = files
        self._reach = reach
        self._around = around
        self._xacro = xacro

    @cached_property
    def _reached(self) -> tuple[list[XacroFile], bool]:
        found, complete = self._reach()
        return _unique([*self.files, *found]), complete

    @property
    def reached(self) -> list[XacroFile]:
        """The files of the expansion, and every file its includes may lead to."""
        return self._reached[0]

    @property
    def complete(self) -> bool:
        """Whether every include the model's files may make could be followed to a file
        read here: when not, a name may be defined or used where urdfcli cannot see."""
        return self._reached[1]

    @cached_property
    def universe(self) -> list[XacroFile]:
        """Every file whose definitions or uses may meet those of the model's files."""
        return _unique([*self.reached, *self._around()])

    @cached_property
    def reached_facts(self) -> Facts:
        """What the files the model may read read and define."""
        return merged(file_facts(f) for f in self.reached)

    @cached_property
    def facts(self) -> Facts:
        """What the universe reads and defines."""
        return merged(file_facts(f) for f in self.universe)

    @cached_property
    def xacro(self) -> XacroGlobals | None:
        """The names xacro gives every expression (None when they cannot be known)."""
        return self._xacro()

    def calls(self, name: str) -> list[MacroCall]:
        """Every call of macro ``name`` in the universe."""
        return self._calls.get(name, [])

    @cached_property
    def _calls(self) -> dict[str, list[MacroCall]]:
        found: dict[str, list[MacroCall]] = {}
        for file in self.universe:
            for call in file.calls:
                found.setdefault(call.name.rpartition(".")[2], []).append(MacroCall(file, call.macro, dict(call.attributes), call.place))
        return found

    def given_by_calls(self, file: XacroFile, macro: int, name: str) -> list[tuple[str, XacroFile, Place]] | None:
        """The plain values every call of a macro gives its parameter ``name`` (its
        default where a call gives none), each with the file and place it is written
        in; None when a call gives an expression, or nothing calls the macro."""
        parameter = next((p for p in parameters(file, macro) if p.name == name and not p.block), None)
        calls = self.calls(file.macros[macro].name)
        if parameter is None or not calls:
            return None
        found = []
        for call in calls:
            if name in call.attributes:
                value, where = call.attributes[name], (call.file, call.place._replace(within=name))
            else:
                value, where = parameter.default, (file, parameter_place(file, macro, name))
            if value is None or "$" in value or parameter.forward:
                return None
            found.append((value.strip("'"), *where))
        return found

    def defined_for_calls(self, file: XacroFile, macro: int, name: str, visiting: frozenset = frozenset()) -> bool:
        """Whether every call of a macro, anywhere in the universe, defines ``name``
        where it is made (a parameter or property of the macro that calls it, or of
        those that call that one...); false when nothing calls it."""
        key = (file.name, macro)
        if key in visiting:
            return False
        calls = self.calls(file.macros[macro].name)
        if not calls:
            return False
        for call in calls:
            if call.macro is None:
                return False  # at the top level only the document's properties are there
            if name in bound(call.file, call.macro):
                continue
            if not self.defined_for_calls(call.file, call.macro, name, visiting | {key}):
                return False
        return True


def parameter_place(file: XacroFile, macro: int, name: str) -> Place:
    """Where a parameter is written in its macro's params attribute."""
    place = file.macros[macro].place
    found = re.search(rf"(?<![\w*])\*{{0,2}}{re.escape(name)}(?![\w])", file.macros[macro].params)
    return Place(place.element, "params", found.start() if found else 0)


def _unique(files: list[XacroFile]) -> list[XacroFile]:
    seen, found = set(), []
    for file in files:
        if file.name not in seen:
            seen.add(file.name)
            found.append(file)
    return found


__all__ = [
    "Facts", "MacroCall", "XacroSources", "bound", "chain", "file_facts", "interface", "merged", "parameter_place",
    "parameters", "used_parameters",
]
