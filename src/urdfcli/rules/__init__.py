"""The rule registry: every diagnostic urdfcli can emit has a code here.

A rule is either *structural* (emitted while the model is read: a missing
attribute, a malformed number, a broken tree) or a *check* (a function over
the loaded model, registered with :func:`check`). Both carry their code,
kebab-case name, default severity, whether they are on by default, their
options and their documentation in one place.

Every rule's documentation has the same four sections (see :data:`SECTIONS`);
:func:`explain` writes them for declared rules, a check's docstring holds them.
"""

from __future__ import annotations

import functools
import importlib
import re
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any, NamedTuple

from ..severity import Severity
from ..suggestions import close_matches

if TYPE_CHECKING:
    from ..loaded import Loaded
    from ..diagnostics import Diagnostic

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
SECTIONS = ("What it does", "Why is this bad?", "Example", "Use instead")


class Option(NamedTuple):
    """A rule option: its name, default value (whose type is the option's type) and meaning."""

    name: str
    default: Any
    doc: str

    @property
    def kind(self) -> str:
        if isinstance(self.default, bool):
            return "boolean"
        if isinstance(self.default, (int, float)):
            return "number"
        if isinstance(self.default, (list, tuple)):
            return "list of strings"
        return "string"

    def validate(self, value: Any) -> Any:
        """The value, converted; raises ValueError saying what was expected."""
        kind = self.kind
        if kind == "boolean" and isinstance(value, bool):
            return value
        if kind == "number" and isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        if kind == "list of strings" and isinstance(value, list) and all(isinstance(v, str) for v in value):
            return tuple(value)
        if kind == "string" and isinstance(value, str):
            return value
        raise ValueError(f"option '{self.name}' must be a {kind}, not {value!r}")


class Rule(NamedTuple):
    code: str
    name: str
    severity: Severity
    summary: str
    doc: str = ""
    urdfdom: bool = False  # check_urdf rejects (prints an error for) this too
    default: bool = True  # on unless selected explicitly
    in_check: bool = True  # reported by `urdfcli check` (else `lint`/`inertia` only)
    options: tuple[Option, ...] = ()
    function: Callable[..., Iterator["Diagnostic"]] | None = None

    @property
    def defaults(self) -> dict[str, Any]:
        return {option.name: option.default for option in self.options}

    def option(self, name: str) -> Option:
        for option in self.options:
            if option.name == name:
                return option
        known = [o.name for o in self.options]
        raise KeyError(f"rule {self.code} ({self.name}) has no option '{name}'" + _did_you_mean(name, known) + (f"; its options are {', '.join(known)}" if known else "; it has no options"))

    def run(self, loaded: "Loaded", options: dict[str, Any] | None = None) -> Iterator["Diagnostic"]:
        """The rule's diagnostics on a loaded model, with options over the defaults."""
        if self.function is None:
            return iter(())
        return self.function(loaded, options) if self.options else self.function(loaded)

    def sections(self) -> dict[str, str]:
        return sections(self.doc)


REGISTRY: dict[str, Rule] = {}


def declare(code: str, name: str, severity: Severity, summary: str, doc: str = "", **kwargs) -> Rule:
    if code in REGISTRY:
        raise ValueError(f"rule {code} declared twice")
    rule = Rule(code, name, severity, summary, cleandoc(doc), **kwargs)
    REGISTRY[code] = rule
    return rule


def check(code: str, name: str, severity: Severity, summary: str, options: tuple[Option, ...] = (), **kwargs):
    """Register a check function; its docstring is the rule's documentation.

    A rule with options gets them as a second argument, a dict holding every
    option (defaults filled in); called with the model alone it uses the defaults.
    """

    if isinstance(options, dict):
        options = tuple(Option(name, default, "") for name, default in options.items())

    def register(function):
        registered = function
        if options:
            defaults = {option.name: option.default for option in options}

            @functools.wraps(function)
            def registered(loaded, values=None):
                return function(loaded, {**defaults, **(values or {})})

        declare(code, name, severity, summary, function.__doc__ or "", function=registered, options=tuple(options), **kwargs)
        return function

    return register


def explain(what: str, why: str, example: str, use_instead: str) -> str:
    """A rule's documentation in the four sections; examples are XML."""
    example, use_instead = cleandoc(example), cleandoc(use_instead)
    return (
        f"## What it does\n{cleandoc(what)}\n\n## Why is this bad?\n{cleandoc(why)}\n\n"
        f"## Example\n```xml\n{example}\n```\n\n## Use instead\n```xml\n{use_instead}\n```"
    )


def cleandoc(text: str) -> str:
    """A docstring as inspect.cleandoc reads it: the first line's leading blanks and
    the other lines' common indentation removed, blank lines at either end dropped.
    Rules are declared at every start, and inspect (with what it imports) costs a
    tenth of one; a test compares the two readings."""
    first, *rest = text.expandtabs().split("\n")
    margin = min((len(line) - len(line.lstrip()) for line in rest if line.strip()), default=0)
    lines = [first.lstrip(), *(line[margin:] for line in rest)]
    while lines and not lines[-1]:
        lines.pop()
    while lines and not lines[0]:
        lines.pop(0)
    return "\n".join(lines)


_HEADING = re.compile(r"^## (.+?)\s*$", re.MULTILINE)


def sections(doc: str) -> dict[str, str]:
    """``## Heading`` sections of a rule's documentation, heading -> body."""
    found: dict[str, str] = {}
    matches = list(_HEADING.finditer(doc))
    for match, following in zip(matches, matches[1:] + [None]):
        end = following.start() if following else len(doc)
        found[match.group(1)] = doc[match.end():end].strip()
    return found


def example_code(body: str) -> str | None:
    """The first fenced code block of a section, or None."""
    match = re.search(r"```[a-z]*\n(.*?)\n```", body, re.DOTALL)
    return match.group(1) if match else None


class UnknownRule(KeyError):
    def __str__(self) -> str:
        return self.args[0]


def _did_you_mean(word: str, known) -> str:
    close = close_matches(word, known)
    return f" (did you mean '{close[0]}'?)" if close else ""


def rule(code: str) -> Rule:
    """The rule ``code``. The model reports while it is read, before any rule module
    is loaded: the structural rules are tried first (a xacro error imports no model),
    then `check`'s own modules, so that it imports no other."""
    for modules in (STRUCTURAL_MODULES, CHECK_MODULES):
        if code not in REGISTRY:
            _load(modules)
    return REGISTRY[code] if code in REGISTRY else load_all()[code]


def lookup(code_or_name: str) -> Rule:
    """A rule by code (any case) or kebab-case name; UnknownRule says what was meant."""
    registry = load_all()
    key = code_or_name.strip()
    if key.upper() in registry:
        return registry[key.upper()]
    for candidate in registry.values():
        if candidate.name == key.lower():
            return candidate
    known = list(registry) + [r.name for r in registry.values()]
    raise UnknownRule(f"unknown rule '{code_or_name}'" + _did_you_mean(key, known) + "; `urdfcli rules` lists them")


# The modules that define rules, and those among them that hold every rule `check` runs
# (a test keeps the two in step): `check` imports no other rule module.
MODULES = ("structure", "joints", "physics", "description", "style", "inertia", "suppression")
CHECK_MODULES = ("structure", "joints", "physics")
STRUCTURAL_MODULES = ("structure",)  # every rule reported while a model is read or expanded


def load_all() -> dict[str, Rule]:
    return _load(MODULES)


def load_check() -> dict[str, Rule]:
    """At least every rule `check` runs (all rules when something asked for them already)."""
    return _load(CHECK_MODULES)


def _load(names: tuple[str, ...]) -> dict[str, Rule]:
    for name in names:
        importlib.import_module(f"{__name__}.{name}")  # registers its rules
    return REGISTRY
