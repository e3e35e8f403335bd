"""What a rule is: its code, kebab-case name, default severity, whether it is on
by default, its kind, the rule set it belongs to, its options and its
documentation, in one place.

A rule's :class:`Kind` says what it reads, and so when it runs. A rule said
while a model is read or expanded (a missing attribute, a malformed number) is
*declared* (:func:`declare`); any other is a *check* (:func:`check`): a function
``rule(loaded, given)`` over the loaded model that yields diagnostics, ``given``
holding its options and, for a target rule, the consumer's profile.
Every rule's documentation has the same four sections (see :data:`SECTIONS`);
:func:`explain` writes them for declared rules, a check's docstring holds them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping
from enum import Enum
from inspect import cleandoc
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, NamedTuple

from ..diagnostics import Applicability, Severity, joined  # noqa: F401 - the rules list names with it
from .suggestions import close_matches

if TYPE_CHECKING:
    from ..diagnostics import Diagnostic
    from ..model.load import Loaded
    from ..model.targets import Profile

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
SAFE, UNSAFE = Applicability.SAFE, Applicability.UNSAFE
SECTIONS = ("What it does", "Why is this bad?", "Example", "Use instead")
# what every fix that changes a value of the model says of where it writes it (see urdfcli.model.written)
PLACED = ("The value is written where it was written, through includes and macro bodies; one computed by an expression, "
          "or given by a xacro argument or by a macro parameter whose calls cannot all be edited alike, is left alone, "
          "and the diagnostic says where it comes from.")


class RuleSet(Enum):
    """Which rules a run runs, each set holding the one before it: the rules on the
    tree's structure (``tree``, ``graph``, ``inertia``), those of ``check``, or every
    rule (``lint``)."""

    TREE = "tree"
    CHECK = "check"
    LINT = "lint"

    def holds(self, other: RuleSet) -> bool:
        """Whether this set holds every rule of ``other``."""
        return _RANK[other] <= _RANK[self]


_RANK = {RuleSet.TREE: 0, RuleSet.CHECK: 1, RuleSet.LINT: 2}


class Kind(Enum):
    """What a rule reads, which decides when it runs."""

    READING = "reading"  # said while the input is read or expanded (declared: no function)
    SUPPRESSIONS = "suppressions"  # said of the suppression comments, once every other rule has run
    LOADING = "loading"  # said by a consumer's own loader (``check --load``)
    TREE = "tree"  # the links and joints as a tree: runs in every command, whatever the selection
    MODEL = "model"  # the robot model
    MASS = "mass"  # the mass properties: `inertia` audits them, and a new <inertial> fixes what they find
    FILES = "files"  # a file the model names (a mesh), not the model: tree, graph and check_urdf's format leave it out
    SOURCES = "sources"  # the xacro files as written: runs even when no robot was read
    SEMANTIC = "semantic"  # an SRDF (MoveIt's) against the URDF of its robot: runs on an SRDF, never on a robot
    TARGET = "target"  # what a consumer makes of the model: runs for the targets asked for

    @property
    def declared(self) -> bool:
        """Whether rules of this kind are said by reading, suppressions or a load, not by a function."""
        return self in (Kind.READING, Kind.SUPPRESSIONS, Kind.LOADING)


class Remedy(Enum):
    """What fixes what a rule finds, where urdfcli can offer it."""

    NONE = "none"
    INERTIAL = "inertial"  # a new <inertial>: a uniform body filling the link's geometry (``inertia --suggest``)


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


NO_OPTIONS: Mapping[str, Any] = MappingProxyType({})


class Given(NamedTuple):
    """What a check is run with besides the model: its options (every one, the defaults
    filled in) and, for a target rule, the consumer's profile."""

    options: Mapping[str, Any] = NO_OPTIONS
    profile: Profile | None = None


Function = Callable[["Loaded", Given], Iterator["Diagnostic"]]


class Rule(NamedTuple):
    code: str
    name: str
    severity: Severity
    summary: str
    doc: str = ""
    kind: Kind = Kind.READING
    rule_set: RuleSet = RuleSet.CHECK  # the smallest rule set that reports it
    default: bool = True  # on unless selected explicitly
    urdfdom: bool = False  # check_urdf rejects (prints an error for) this too
    remedy: Remedy = Remedy.NONE
    options: tuple[Option, ...] = ()
    function: Function | None = None
    target: str | None = None  # a target rule's consumer (``mujoco``), or the profile its examples use (``pinocchio:mimic``)
    fix: Applicability | None = None  # how safe its fix is, where its diagnostics carry one
    fix_doc: str = ""  # what the fix does, and when there is none

    @property
    def fixable(self) -> Applicability | None:
        """How safe the rule's fix is (None: it has none)."""
        return self.fix

    @property
    def consumer(self) -> str | None:
        """The consumer a target rule is about (None for the other rules)."""
        return self.target.split(":")[0] if self.target else None

    @property
    def defaults(self) -> dict[str, Any]:
        return {option.name: option.default for option in self.options}

    def option(self, name: str) -> Option:
        for option in self.options:
            if option.name == name:
                return option
        known = [o.name for o in self.options]
        raise KeyError(f"rule {self.code} ({self.name}) has no option '{name}'" + _did_you_mean(name, known) + (f"; its options are {', '.join(known)}" if known else "; it has no options"))

    def given(self, options: Mapping[str, Any] | None = None, profile: Profile | None = None) -> Given:
        """What the rule is run with: ``options`` over its defaults, and a target rule's profile."""
        return Given(MappingProxyType({**self.defaults, **(options or {})}) if self.options else NO_OPTIONS, profile)

    def run(self, loaded: Loaded, given: Given) -> Iterator[Diagnostic]:
        """The rule's diagnostics on a loaded model (none for a declared rule)."""
        return self.function(loaded, given) if self.function is not None else iter(())

    def sections(self) -> dict[str, str]:
        return sections(self.doc)


def declare(code: str, name: str, severity: Severity, summary: str, doc: str = "", kind: Kind = Kind.READING, **kwargs) -> Rule:
    """A rule said while a model is read or expanded (or of its suppressions, or by a consumer's load)."""
    if not kind.declared:
        raise ValueError(f"{code}: a declared rule is said by reading, suppressions or a load, not {kind}")
    return Rule(code, name, severity, summary, cleandoc(doc), kind, **kwargs)


def check(
    code: str, name: str, severity: Severity, summary: str, kind: Kind = Kind.MODEL, rule_set: RuleSet = RuleSet.CHECK,
    options: tuple[Option, ...] = (), doc: str | None = None, target: str | None = None, **kwargs,
):
    """Make a function ``rule(loaded, given)`` a rule (its ``rule`` attribute); its
    docstring is the rule's documentation, unless ``doc`` gives it (made with
    :func:`explain` where rules share their examples). A target rule names its
    consumer (``target``); a rule on the tree's structure belongs to every rule set."""
    if kind.declared or (kind is Kind.TARGET) != (target is not None):
        raise ValueError(f"{code}: a check of kind {kind} {'needs' if kind is Kind.TARGET else 'takes no'} target")
    if kind is Kind.TREE:
        rule_set = RuleSet.TREE

    def register(function: Function):
        text = doc if doc is not None else function.__doc__
        function.rule = Rule(code, name, severity, summary, cleandoc(text or ""), kind, rule_set, options=tuple(options), function=function, target=target, **kwargs)
        return function

    return register


def explain(what: str, why: str, example: str, use_instead: str) -> str:
    """A rule's documentation in the four sections; examples are XML."""
    example, use_instead = cleandoc(example), cleandoc(use_instead)
    return (
        f"## What it does\n{cleandoc(what)}\n\n## Why is this bad?\n{cleandoc(why)}\n\n"
        f"## Example\n```xml\n{example}\n```\n\n## Use instead\n```xml\n{use_instead}\n```"
    )


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


def names(items, most: int = 3) -> str:
    """``'a', 'b', 'c' and 2 more``: what one diagnostic about several elements names."""
    items = list(items)
    shown = ", ".join(f"'{item}'" for item in items[:most])
    return shown + (f" and {len(items) - most} more" if len(items) > most else "")


