"""Rules on the xacro sources: definitions nothing uses, names nothing defines,
macros that can only be called once, and xacro tags xacro no longer reads.

They judge the files a model's expansion read (``loaded.xacro_sources.files``), each
finding located at the definition or use in its file. Whether a definition is
used elsewhere, or a name defined elsewhere, is looked up in every file the
includes may reach (under any condition) and in the xacro files of the
repository or workspace around the model; a name read or defined by an
expression urdfcli cannot follow (``$(arg ${x})``, ``<xacro:call
macro="${m}"/>``, a property whose name is computed) counts as any name, so
that nothing uncertain is reported.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from ..diagnostics import Diagnostic, Edit, Fix, Location
from ..model.sources import Facts, XacroSources, bound, interface, parameter_place, parameters, used_parameters
from ..read.memo import once
from ..read.xacro_scan import Made, Parameter, Place, XacroFile, free_names, lexed
from . import structure
from .base import ERROR, INFO, UNSAFE, WARNING, Kind, RuleSet, check, joined, names
from .suggestions import close_matches


def _at(file: XacroFile, place: Place) -> Location:
    line, column = file.position(place)
    return Location(file.name, line, column)


def _diagnostic(code: str, message: str, file: XacroFile, place: Place, hint: str | None = None, severity=None) -> Diagnostic:
    return Diagnostic(code, message, _at(file, place), hint=hint, severity=severity)


UNEXPANDED = re.compile(r"(?<!\$)\{(\w+)\}")  # {name}: a xacro expression that lost its $
_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)


def _without_dollar(file: XacroFile, name: str, start: int = 0, end: int | None = None) -> int | None:
    """The offset of ``{name}`` written without its ``$`` between ``start`` and ``end`` of
    ``file``, outside comments (``<torque>{wheel_torque}</torque>``): the name meant, which
    reads nothing, since xacro copies the text as it is."""
    text = _COMMENT.sub(lambda comment: " " * len(comment.group(0)), file.text[start:end])
    return next((start + found.start() for found in UNEXPANDED.finditer(text) if found.group(1) == name), None)


def _written_without_dollar(code: str, what: str, name: str, file: XacroFile, at: int) -> Diagnostic:
    """X102 or X103 where ``{name}`` is written without its ``$``: a typo to mend there, not a leftover to remove."""
    return Diagnostic(
        code, f"{what} is written '{{{name}}}', without its $: xacro copies it as text, and the value never reaches the robot",
        Location(file.name, *file.source.position(at)), hint=f"write ${{{name}}}", severity=WARNING,
    )


def _used(sources: XacroSources, test) -> bool:
    """Whether ``test(facts)`` holds for what the model's files reach, else for the
    whole workspace around it (read only then); true when an include could not be
    followed, since the file it leads to may hold anything."""
    return not sources.complete or test(sources.reached_facts) or test(sources.facts)


@check("X101", "xacro-argument-unused", WARNING, "A `xacro:arg` that nothing reads.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def argument_unused(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Flags a `<xacro:arg>` that no `$(arg NAME)`, `$(eval ...)` or
    `xacro.arg('NAME')` reads: not in the model's files, not in any file their
    includes may reach (under any `xacro:if`), not in any xacro file of the
    repository or workspace around it. An argument read through a computed
    name (`$(arg ${name})`) counts as read, whatever its name.

    ## Why is this bad?
    A user passes `NAME:=VALUE` (on the command line, in a launch file) and
    nothing changes: the argument was renamed, or the code that read it was
    removed, and the launch file still sets it.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:arg name="use_gpu" default="false"/>
      <link name="base_link"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:arg name="use_gpu" default="false"/>
      <link name="base_link"/>
      <xacro:if value="$(arg use_gpu)"><link name="gpu_lidar_link"/></xacro:if>
    </robot>
    ```
    """
    sources = loaded.xacro_sources
    for file in sources.files:
        for definition in file.definitions:
            name = definition.name
            if definition.kind != "argument" or not name or _used(sources, lambda f: f.any_argument or name in f.arguments):
                continue
            yield _diagnostic(
                "X101", f"xacro argument '{name}' is read nowhere: {name}:=VALUE changes nothing", file, definition.place,
                f"read it with $(arg {name}), or remove the <xacro:arg>",
            )


@check("X102", "xacro-property-unused", INFO, "A `xacro:property` that nothing uses.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def property_unused(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Notes a `<xacro:property>` whose name no `${...}` reads (and, for a block
    property, no `<xacro:insert_block>` inserts) in the model's files, the
    files their includes may reach, or the xacro files of the repository or
    workspace around it. A `${width}` in a macro body whose parameter or own
    property is named `width` reads that, not a document's property. Info: a
    library's property may serve a package outside the workspace.
    A property written `{NAME}`, without its `$` (outside comments), is a
    warning where it is written: the value never reaches the robot, and the
    braces do.

    ## Why is this bad?
    A property nobody reads is a value that looks like it sets something and
    does not: often the old name of one that was renamed, so that a change to
    it is silently lost.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:property name="wheel_width" value="0.04"/>
      <link name="base_link"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:property name="wheel_width" value="0.04"/>
      <link name="base_link">
        <visual><geometry><cylinder radius="0.1" length="${wheel_width}"/></geometry></visual>
      </link>
    </robot>
    ```
    """
    sources = loaded.xacro_sources
    for file in sources.files:
        for definition in file.definitions:
            name = definition.name
            if definition.kind != "property" or not name or "$" in name:
                continue
            # a document's property is read only where no macro parameter or local property of its name hides it
            document_wide = definition.macro is None or definition.scope in ("global", "parent")
            if _used(sources, lambda f: name in (f.unbound if document_wide else f.names) or name in f.blocks or name in f.forwarded):
                continue
            lost = _without_dollar(file, name)
            if lost is not None:
                yield _written_without_dollar("X102", f"property '{name}'", name, file, lost)
                continue
            yield _diagnostic("X102", f"property '{name}' is used nowhere", file, definition.place, f"use it as ${{{name}}}, or remove it")


def _used_elsewhere(facts: Facts, parameter: Parameter, macro: str, shape: str) -> bool:
    """Whether a parameter of macro ``macro`` (with parameter list ``shape``) counts
    as used outside its body, by what ``facts`` read."""
    name = parameter.name
    # a macro that may stand for this one uses it: the parameter is their shared interface
    if (macro, parameter.shown) in facts.variants or (facts.any_call and (shape, parameter.shown) in facts.interfaces):
        return True
    # xacro evaluates a body in its caller's scope: another body may read the name, or insert the block
    return name in facts.free_blocks if parameter.block else name in facts.free or name in facts.forwarded


@check("X103", "macro-parameter-unused", WARNING, "A macro parameter its body never uses.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def parameter_unused(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Flags a parameter of a `<xacro:macro>` that its body (nested macros
    included) never reads as `${NAME}`, and a block parameter (`*NAME`,
    `**NAME`) it never inserts with `<xacro:insert_block name="NAME"/>`.
    A parameter written `{NAME}`, without its `$` (`<torque>{wheel_torque}</torque>`),
    is reported where it is written: xacro copies that text as it is.
    xacro evaluates a macro's body in its caller's scope, so a parameter also
    counts as used when a macro body anywhere in the workspace reads that name
    without defining it, or forwards it (`NAME:=^`). A body that includes a
    file (`<xacro:include>` inside the macro, as the RexROV's `rexrov_base`
    includes its sensors) has xacro read that file in its scope: a name any
    file reads outside its own macros counts as used too.

    Left alone: a parameter that a macro which may stand for this one takes
    and uses. That is another macro of the same name in the workspace (a
    variant: the Robotiq 2F-85's `outer_knuckle` ignores `stroke`, the
    2F-140's names its meshes with it, and one shared caller passes it to
    whichever is included), or, where the workspace calls a macro by a
    computed name (`<xacro:call macro="${platform}"/>`), a macro with the
    same parameter list. The parameter is their shared interface: removing it
    would break the caller, and nothing is wrong with this macro. A block the
    body inserts with `<insert_block>` written without `xacro:` (which xacro 2
    copies unread) is left to X107, which says so once, at that tag.

    ## Why is this bad?
    Every call passes a value that changes nothing: an `xyz` meant for the
    `<origin>`, a `*origin` block never inserted, stack every part at the
    parent's origin, and the model still expands without a word.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="prefix *origin">
        <link name="${prefix}_wheel"/>
        <joint name="${prefix}_wheel_joint" type="continuous">
          <parent link="base_link"/>
          <child link="${prefix}_wheel"/>
        </joint>
      </xacro:macro>
      <link name="base_link"/>
      <xacro:wheel prefix="left"><origin xyz="0 0.2 0"/></xacro:wheel>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="prefix *origin">
        <link name="${prefix}_wheel"/>
        <joint name="${prefix}_wheel_joint" type="continuous">
          <parent link="base_link"/>
          <child link="${prefix}_wheel"/>
          <xacro:insert_block name="origin"/>
        </joint>
      </xacro:macro>
      <link name="base_link"/>
      <xacro:wheel prefix="left"><origin xyz="0 0.2 0"/></xacro:wheel>
    </robot>
    ```
    """
    sources = loaded.xacro_sources
    for file in sources.files:
        unprefixed = _unprefixed_blocks(file)
        for macro, definition in enumerate(file.macros):
            used, shape = used_parameters(file, macro), interface(file, macro)
            includes = any(file.within(inner, macro) for inner in file.including)
            for parameter in parameters(file, macro):
                name = parameter.name
                if parameter.shown in used or _used(sources, lambda f: _used_elsewhere(f, parameter, definition.name, shape)):
                    continue
                if includes and _used(sources, lambda f: name in (f.blocks if parameter.block else f.unbound)):
                    continue  # an included file may read it: xacro reads that file in this body's scope
                if parameter.block and (macro, name) in unprefixed:
                    continue  # an <insert_block> without xacro: names it: X107's to report, once, at that tag
                if parameter.block:
                    message = f"block parameter '*{name}' of macro '{definition.name}' is never inserted: the block each call gives is dropped"
                    hint = f'insert it with <xacro:insert_block name="{name}"/>, or remove *{name} from params'
                elif (lost := _without_dollar(file, name, *file.source.spans[definition.place.element][1:])) is not None:
                    yield _written_without_dollar("X103", f"parameter '{name}' of macro '{definition.name}'", name, file, lost)
                    continue
                else:
                    message = f"parameter '{name}' of macro '{definition.name}' is never used in its body: the value each call gives changes nothing"
                    hint = f"use it as ${{{name}}}, or remove it from params"
                yield _diagnostic("X103", message, file, parameter_place(file, macro, name), hint)


def _unprefixed_blocks(file: XacroFile) -> set[tuple[int, str]]:
    """The (macro, block name) of each ``<insert_block>`` written without ``xacro:``
    in a macro's body (nested macros' bodies count for the macros around them)."""
    spans = file.source.spans
    return {
        (macro, old.value)
        for old in file.old if old.tag == "insert_block" and old.place.element < len(spans)
        for macro in file.macros_at(spans[old.place.element][0])
    }


@check("X104", "macro-unused", INFO, "A macro that nothing calls.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def macro_unused(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Notes a `<xacro:macro>` that no `<xacro:NAME>` (nor `<xacro:call
    macro="NAME">`, nor a `<NAME>` written without the prefix, which X107
    reports where xacro leaves it) calls in the model's files, the files their includes may
    reach, or any xacro file of the repository or workspace around it. Info
    only: a library's macros serve packages this workspace may not hold; the
    macros of one file that nothing calls are one note. A workspace with a
    computed call (`<xacro:call macro="${name}"/>`) draws nothing.

    ## Why is this bad?
    A macro nothing calls is checked by nothing: its mistakes show only the
    day someone calls it. Often it is dead code left after a refactoring.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="bumper" params="parent">
        <link name="bumper_link"/>
      </xacro:macro>
      <link name="base_link"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="bumper" params="parent">
        <link name="bumper_link"/>
        <joint name="bumper_joint" type="fixed"><parent link="${parent}"/><child link="bumper_link"/></joint>
      </xacro:macro>
      <link name="base_link"/>
      <xacro:bumper parent="base_link"/>
    </robot>
    ```
    """
    sources = loaded.xacro_sources
    for file in sources.files:
        uncalled = []
        for definition in file.macros:
            name = definition.name.removeprefix("xacro:")
            if not name or _used(sources, lambda f: f.any_call or name in f.calls or name in f.unprefixed):
                continue  # (a call without xacro:, even in a body xacro never expands, is X107's)
            uncalled.append((name, definition))
        where = "in this file, the files it includes, nor any other file of the workspace" if file.makes else "by any file of the workspace"
        if len(uncalled) == 1:
            name, definition = uncalled[0]
            yield _diagnostic("X104", f"macro '{name}' is called nowhere: not {where}", file, definition.place, "call it, or remove it")
        elif uncalled:  # one note for the file: a library of colours or parts serves packages elsewhere
            yield _diagnostic("X104", f"{len(uncalled)} macros of this file ({names(name for name, _ in uncalled)}) are called nowhere: not {where}", file, uncalled[0][1].place,
                              "call them, or remove them")


def _made_by_macros(origins) -> dict[tuple[int, int, int], list[int]]:
    """For each place of the sources (file index, line, column) that macro calls made
    elements from, the call chains (trace indices) of those elements."""
    places = origins.places
    found: dict = {}
    for at in range(0, len(places), 4):
        trace = places[at + 3]
        if trace:  # trace 0 is no call at all
            found.setdefault((places[at], places[at + 1], places[at + 2]), []).append(trace)
    return found


def _call_site(origins, call: int) -> str:
    file, line, column, _ = origins.calls[call]
    return f"{file}:{line}:{column}" if line else file


def _differing(origins, first: int, second: int) -> tuple[str, str]:
    """The two call sites that tell two call chains apart (the outermost that differ)."""
    a, b = origins.traces[first], origins.traces[second]
    for one, other in zip(reversed(a), reversed(b)):
        if one != other:
            return _call_site(origins, one), _call_site(origins, other)
    return _call_site(origins, a[0]), _call_site(origins, b[0])


@check("X105", "macro-name-fixed", ERROR, "A macro that names a link, joint or transmission the same whatever its parameters.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def macro_name_fixed(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Looks at each `<link>`, `<joint>` and `<transmission>` written in a macro's
    body with a fixed name (no `${...}`, no `$(...)`) and counts the calls of
    the macro that made one in the expanded model: two calls or more make two
    elements of one name, an error, which names two of the calls; one call is
    info, since the macro can then be used only once per robot (as vendors
    write a robot's macro, on purpose). One diagnostic per macro, at its first
    fixed name, names them all: the error those made twice, else the info
    every fixed name.

    Left alone: a name built from a parameter or a property
    (`${prefix}wheel`), and a fixed name written in an `xacro:if` or
    `xacro:unless` whose condition reads a parameter of the macro or a
    property of its body (`<xacro:if value="${attach_to == 'world'}">`):
    whether a call makes it depends on what the call passes. The
    duplicate-name rules (N004, N005) judge what they expand to.

    ## Why is this bad?
    The second call of the macro defines the link or joint again: check_urdf
    and every tool built on urdfdom reject the model ("link defined twice"),
    and a transmission named twice drives one joint only.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="side">
        <link name="wheel_link"/>
      </xacro:macro>
      <xacro:wheel side="left"/>
      <xacro:wheel side="right"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="side">
        <link name="${side}_wheel_link"/>
      </xacro:macro>
      <xacro:wheel side="left"/>
      <xacro:wheel side="right"/>
    </robot>
    ```
    """
    origins = loaded.document.origins
    if origins is None:
        return
    files = {name: index for index, name in enumerate(origins.files)}
    made = None
    for file in loaded.xacro_sources.files:
        fixed: dict[int, list] = {}  # macro index: (element, the call chains that made it), as written
        for element in file.made:
            if "$" in element.name or file.name not in files or _conditional_on_parameters(file, element):
                continue
            made = made if made is not None else _made_by_macros(origins)
            line, column = file.position(Place(element.place.element))
            traces = list(dict.fromkeys(made.get((files[file.name], line, column), [])))
            if traces:
                fixed.setdefault(element.macro, []).append((element, traces))
        for macro, elements in fixed.items():
            yield _fixed_names(origins, file, file.macros[macro], elements)


def _conditional_on_parameters(file: XacroFile, element: Made) -> bool:
    """Whether a condition around an element reads a name its macro binds (a parameter,
    or a property of its body): whether a call makes the element depends on the call.
    A condition that cannot be read counts as one that does."""
    bound_here = bound(file, element.macro)
    for condition in element.conditions:
        for kind, _, _, inner in lexed(condition):
            read = free_names(inner) if kind == "expression" else ()
            if read is None or any(name.name in bound_here for name in read):
                return True
    return False


def _fixed_names(origins, file: XacroFile, definition, elements: list) -> Diagnostic:
    """X105 for one macro: an error naming the elements its calls made twice, else info naming
    every fixed name (one note for the macro: a vendor's robot macro writes dozens, on purpose)."""
    twice = [(element, traces) for element, traces in elements if len(traces) > 1]
    named = [element for element, _ in twice or elements]
    first = named[0]
    # a macro without parameters (ros2_control_demos' r6bot_description) has none to build names from
    macro, whatever = definition.name, ("whatever its parameters" if definition.parameters else "and takes no parameters")
    build = "build the name{} from a parameter" if definition.parameters else "give it a parameter and build the name{} from it"
    if len(named) == 1:
        what = f"macro '{macro}' names {first.tag} '{first.name}' {whatever}"
        hint = f'{build.format("")}, such as name="${{prefix}}{first.name}"'
    else:
        kinds = joined(dict.fromkeys(f"{element.tag}s" for element in named))
        what = f"macro '{macro}' names {len(named)} {kinds} ({names(element.name for element in named)}) {whatever}"
        hint = f'{build.format("s")}, such as name="${{prefix}}{first.name}"'
    if not twice:
        return _diagnostic("X105", f"{what}: it can be called once per robot", file, first.place, hint, severity=INFO)
    traces = twice[0][1]
    count = len({trace for _, traces in twice for trace in traces})
    one, other = _differing(origins, traces[0], traces[1])
    calls = f"{count} calls" if count > 2 else "two calls"
    made_twice = f"{first.tag} '{first.name}' twice" if len(named) == 1 else "each of them twice"
    return _diagnostic("X105", f"{what}: its {calls} (at {one} and {other}) make {made_twice}", file, first.place, hint)


@check("X106", "xacro-name-undefined", WARNING, "A name in a macro body that nothing defines.", kind=Kind.SOURCES)
def name_undefined(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Reads every `${...}` in every macro body of the model's files, called or
    not, and flags a name that is none of: a parameter of the macro (or of a
    macro around it), a property defined in its body, a property or include
    namespace defined for the whole document in any file the model may read or
    any xacro file of the workspace, a name xacro provides (`pi`, `radians`,
    `xacro.load_yaml`, math functions, read from xacro itself). A name defined
    only where the macro is called counts as defined when every call, in the
    whole workspace, defines it (a parameter of the calling macro, say). Names
    a comprehension or lambda binds, and expressions Python cannot parse, are
    left alone. The warning is at the name's line and column, with the closest
    name the macro can see (its parameters and properties, xacro's names, the
    properties of the files the model may read, not those of another robot of
    the workspace). It is a warning, not an error: the model loads as long as
    its expansion never evaluates the name (a macro it does not call, a branch
    its call does not take); where the expansion does evaluate it, xacro's own
    error (X003) says so at that line. A name a `<property>` written without
    `xacro:` declares is left to X107, which says so once, at that tag.

    ## Why is this bad?
    xacro evaluates a macro's body only when it is called: a misspelt name in
    a library passes every check until a model calls the macro, then the
    expansion fails (or, for a macro nobody calls yet, the day someone does).

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="prefix radius">
        <link name="${prefix}_wheel">
          <visual><geometry><cylinder radius="${raduis}" length="0.05"/></geometry></visual>
        </link>
      </xacro:macro>
      <link name="base_link"/>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:macro name="wheel" params="prefix radius">
        <link name="${prefix}_wheel">
          <visual><geometry><cylinder radius="${radius}" length="0.05"/></geometry></visual>
        </link>
      </xacro:macro>
      <link name="base_link"/>
    </robot>
    ```
    """
    sources = loaded.xacro_sources
    failed = {(d.path, d.line) for d in loaded.diagnostics if d.code == structure.X003.code}
    # a property written without xacro: is X107's to report, once, at its tag
    unprefixed = {old.value for file in sources.files for old in file.old if old.tag == "property"}
    for file in sources.files:
        for expression in file.expressions:
            if expression.macro is None:
                continue
            for name in free_names(expression.text) or ():
                known = bound(file, expression.macro)
                if name.name in known or name.name in unprefixed:
                    continue
                if sources.xacro is None:
                    return  # without xacro's own names, any name may be one of them
                builtins = sources.xacro.names
                if name.name in builtins:
                    continue
                if _used(sources, lambda f: f.any_global or name.name in f.globals):
                    continue
                if sources.defined_for_calls(file, expression.macro, name.name):
                    continue
                place = expression.place._replace(offset=expression.place.offset + name.offset)
                location = _at(file, place)
                if (location.file, location.line) in failed:
                    continue  # xacro's own error (X003) says it there
                macro = file.macros[expression.macro].name
                called = "nor by every call of it" if sources.calls(macro) else "nor for the whole document (nothing calls the macro)"
                # what the macro can see: not the properties of another robot of the workspace
                scope = sorted(known | sources.reached_facts.globals | builtins)
                close = close_matches(name.name, scope)
                hint = f"did you mean '{close[0]}'?" if close else f"add it to the params of macro '{macro}', or define it with <xacro:property>"
                yield Diagnostic("X106", f"name '{name.name}' is defined neither in macro '{macro}' {called}", location, hint=hint)


@check("X107", "xacro-tag-unprefixed", WARNING, "A xacro tag written without `xacro:`, which xacro leaves in the output unread.", kind=Kind.SOURCES, rule_set=RuleSet.LINT, fix=UNSAFE, fix_doc="Writes the `xacro:` prefix on the start and end tags, and declares the prefix on the root when it is not "
       "(unsafe: xacro then reads the tag, and the expansion changes).")
def tag_unprefixed(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Flags `<include filename=...>`, `<property name=...>`, `<macro name=...>`,
    `<arg name=...>`, `<insert_block name=...>`, `<if value=...>` and
    `<unless value=...>` written without the `xacro:` prefix, at the top
    level of a xacro file or in a xacro element's body (not inside a link or a
    plugin, where such tags may be someone else's); and a call of one of the
    model's macros written without it (`<RefLink ref="link1"/>` for a macro
    `RefLink`), where the expansion still holds it as URDF markup (not inside
    another format's block).

    ## Why is this bad?
    xacro 1 read these with a deprecation warning; xacro 2 (ROS 2, and the
    `xacro` on PyPI) does not read them at all: the `<include>` is copied into
    the URDF, which every consumer ignores, and the file it names is never
    included; the macro is never called, so what it makes (a link's friction,
    its colour in Gazebo) is missing.

    ## Example
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <include filename="arm.xacro"/>
      <xacro:property name="size" value="0.1"/>
      <link name="base_link"><visual><geometry><box size="${size} ${size} ${size}"/></geometry></visual></link>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:include filename="arm.xacro"/>
      <xacro:property name="size" value="0.1"/>
      <link name="base_link"><visual><geometry><box size="${size} ${size} ${size}"/></geometry></visual></link>
    </robot>
    ```
    """
    for file in loaded.xacro_sources.files:
        for old in file.old:
            yield _diagnostic(
                "X107", f"<{old.tag}> without the xacro: prefix is not read by xacro: it is copied into the URDF and does nothing",
                file, old.place, f"write <xacro:{old.tag} ...> (with xmlns:xacro=\"http://www.ros.org/wiki/xacro\" on <robot>)",
            )._replace(fix=_prefixed(file, old))
    for call in unprefixed_calls(loaded):
        yield loaded.diagnostic(
            "X107", f"<{call.name}> calls macro '{call.name}' without the xacro: prefix: xacro copies it into the URDF and never calls the macro",
            call.at, f"write <xacro:{call.name} .../>",
        )


@check("X108", "xacro-named-urdf", INFO, "A file named `.urdf` that is written in xacro, which URDF readers given the file read unexpanded.", kind=Kind.SOURCES, rule_set=RuleSet.LINT)
def xacro_named_urdf(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    Notes a model whose file is named `.urdf` but uses xacro: a xacro element, or
    `${...}` / `$(...)` in an attribute or text (a `xmlns:xacro` declaration alone is
    not use). urdfcli expands it, as it does a `.xacro` file, and checks the expansion.
    Info: the file is right when every reader expands it first (a launch file that runs
    xacro on it). A file whose only xacro is `<xacro:property>` and `<xacro:arg>` elements
    that nothing reads is left to X102 and X101: readers skip the elements, and load what
    xacro makes.

    ## Why is this bad?
    A reader given the file itself does not expand it: `check_urdf`, PyBullet,
    MuJoCo, Gazebo, a launch file that passes the file's text to
    robot_state_publisher. They read `$(arg namespace)base_link` as a link's name,
    and `<xacro:...>` elements as unknown markup; what they load is not what
    urdfcli checked (and what `--target` predicts).

    ## Example
    A file `robot.urdf` (TurtleBot3's ROS 2 `.urdf` files read `$(arg namespace)` the same way):
    ```xml
    <robot name="r">
      <link name="base_link">
        <visual><geometry><mesh filename="$(find my_robot)/meshes/base.stl"/></geometry></visual>
      </link>
    </robot>
    ```

    ## Use instead
    A URDF every reader reads as written; or the same text in `robot.urdf.xacro`, its
    readers given its expansion (`xacro robot.urdf.xacro`, or `urdfcli expand`).
    ```xml
    <robot name="r">
      <link name="base_link">
        <visual><geometry><mesh filename="package://my_robot/meshes/base.stl"/></geometry></visual>
      </link>
    </robot>
    ```
    """
    document = loaded.document
    if not document.is_xacro or document.file is None or not document.file.name.endswith(".urdf") or not loaded.xacro_sources.files:
        return
    if _definitions_only(loaded.xacro_sources.files[0]):
        return  # readers skip the unknown elements and load what xacro makes: X102 and X101 say what nothing reads
    name = document.file.name
    # gz_ros2_control's demos are named test_cart.xacro.urdf: the xacro name is test_cart.urdf.xacro
    meant = name.removesuffix(".xacro.urdf") + ".urdf.xacro" if name.endswith(".xacro.urdf") else f"{name}.xacro"
    yield _diagnostic(
        "X108", f"{name} is written in xacro: a URDF reader given the file itself (check_urdf, PyBullet, MuJoCo, Gazebo) reads its xacro markup unexpanded",
        loaded.xacro_sources.files[0], Place(0), f"name it {meant}, and give readers its expansion (urdfcli expand {name})",
    )


def _definitions_only(file) -> bool:
    """Whether a file's xacro is only properties and arguments, which no ``${...}`` or
    ``$(...)`` reads: its expansion is its own text without them."""
    return not file.expressions and not file.substitutions and file.xacro_elements <= {"property", "arg"}


def unprefixed_calls(loaded) -> list:
    """The elements of the expansion (markup URDF does not define) named as a macro of the
    model's files: calls written without ``xacro:``, which xacro 2 copies unexpanded.
    Worked out once per model (X107, X104 and D010 ask)."""
    return once(loaded, _unprefixed_calls)


def _unprefixed_calls(loaded) -> list:
    sources, robot = loaded.xacro_sources, loaded.robot
    if sources is None or robot is None:
        return []
    macros = {macro.name.removeprefix("xacro:") for file in sources.reached for macro in file.macros}
    return [unknown for unknown in robot.unknown if not unknown.attribute and unknown.name in macros]


def _prefixed(file: XacroFile, old) -> Fix:
    """The edits that write ``xacro:`` on an unprefixed tag (and declare the prefix on the root)."""
    title = f"write <xacro:{old.tag}>"
    spans = file.source.spans
    if old.place.element >= len(spans):
        return Fix(title, UNSAFE, reason="the file's elements cannot be followed")
    text = file.source.text
    start, tag_end, end = spans[old.place.element]
    edits = [Edit(file.name, start + 1, start + 1, "xacro:")]
    if end > tag_end:  # an end tag of its own
        closing = text.rfind("</", tag_end, end)
        edits.append(Edit(file.name, closing + 2, closing + 2, "xacro:"))
    root_start, root_end, _ = spans[0]
    if not re.search(r"\sxmlns:xacro\s*=", text[root_start:root_end]):
        at = root_end - 2 if text[root_end - 2:root_end] == "/>" else root_end - 1
        at = len(text[:at].rstrip())
        edits.append(Edit(file.name, at, at, ' xmlns:xacro="http://www.ros.org/wiki/xacro"'))
    return Fix(title, UNSAFE, edits=tuple(edits))


__all__ = [
    "argument_unused", "macro_name_fixed", "macro_unused", "name_undefined", "parameter_unused", "property_unused", "tag_unprefixed", "unprefixed_calls", "xacro_named_urdf",
]
