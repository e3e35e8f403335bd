"""What a rule is: its code, kebab-case name, default severity, whether it is on
by default, its options and its documentation, in one place.

A rule is either *declared* (:func:`declare`: emitted while the model is read
or expanded, such as a missing attribute or a malformed number) or a *check*
(:func:`check`: a function over the loaded model that yields diagnostics).
Every rule's documentation has the same four sections (see :data:`SECTIONS`);
:func:`explain` writes them for declared rules, a check's docstring holds them.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator
from inspect import cleandoc
from typing import TYPE_CHECKING, Any, NamedTuple

from ..diagnostics import Severity
from .suggestions import close_matches

if TYPE_CHECKING:
    from ..diagnostics import Diagnostic
    from ..model.load import Loaded

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
    always: bool = False  # runs on every model read, whatever the command (the tree's structure)
    inertial_fix: bool = False  # a new <inertial> fixes what it finds (`inertia --suggest` prints one)
    sources: bool = False  # judges the xacro sources (``loaded.sources``), so runs even when no robot was read
    files: bool = False  # judges a file the model names (a mesh), not the model: tree, graph and check_urdf's format leave it out
    target: str | None = None  # a consumer's rule (``mujoco``, or the profile its examples use, ``pinocchio:mimic``): runs only for --target

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

    def run(self, loaded: "Loaded", options: dict[str, Any] | None = None, profile: Any = None) -> Iterator["Diagnostic"]:
        """The rule's diagnostics on a loaded model, with options over the defaults; a
        target rule's for the consumer's ``profile`` (a :class:`urdfcli.model.targets.Profile`)."""
        if self.function is None:
            return iter(())
        if self.target is not None:
            return self.function(loaded, profile)
        return self.function(loaded, options) if self.options else self.function(loaded)

    def sections(self) -> dict[str, str]:
        return sections(self.doc)


def declare(code: str, name: str, severity: Severity, summary: str, doc: str = "", **kwargs) -> Rule:
    """A rule whose diagnostics are made while a model is read or expanded."""
    return Rule(code, name, severity, summary, cleandoc(doc), **kwargs)


def check(code: str, name: str, severity: Severity, summary: str, options: tuple[Option, ...] = (), doc: str | None = None, **kwargs):
    """Make a function over a loaded model a rule (its ``rule`` attribute); its
    docstring is the rule's documentation, unless ``doc`` gives it (made with
    :func:`explain` where rules share their examples).

    A rule with options gets them as a second argument, a dict holding every
    option (defaults filled in); called with the model alone it uses the defaults.
    """

    def register(function):
        registered = function
        if options:
            defaults = {option.name: option.default for option in options}

            @functools.wraps(function)
            def registered(loaded, values=None):
                return function(loaded, {**defaults, **(values or {})})

        text = doc if doc is not None else function.__doc__
        function.rule = Rule(code, name, severity, summary, cleandoc(text or ""), function=registered, options=tuple(options), **kwargs)
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


