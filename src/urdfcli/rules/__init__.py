"""The rule registry: every diagnostic urdfcli can emit has a code here.

Each rule module holds its rules (see :mod:`.base`); the registry is built from
them once, the first time it is asked for (not when this package is imported:
a program that only asks for ``--help`` imports no rule), and does not change.
"""

from __future__ import annotations

from functools import cache
from importlib import import_module
from types import MappingProxyType, ModuleType

from ..diagnostics import Severity
from .base import PLACED, SECTIONS, Given, Kind, Option, Remedy, Rule, RuleSet, UnknownRule, cleandoc, example_code, explain, sections
from .suggestions import close_matches

MODULES = ("structure", "tree", "joints", "physics", "description", "meshes", "style", "inertia", "suppression", "xacro", "drift", "packages", "srdf", "targets")
"""The rule modules, by name (``targets`` is a package of them: its ``MODULES``)."""


def _rules_of(module: ModuleType) -> list[Rule]:
    """The rules a module defines: declared ones, and check functions' ``rule``."""
    found = []
    for value in vars(module).values():
        if isinstance(value, Rule):
            found.append(value)
        elif callable(value) and isinstance(getattr(value, "rule", None), Rule) and value.__module__ == module.__name__:
            found.append(value.rule)
    return found


def _registry() -> dict[str, Rule]:
    registry: dict[str, Rule] = {}
    modules = [import_module(f".{name}", __name__) for name in MODULES]
    for module in [m for found in modules for m in getattr(found, "MODULES", (found,))]:
        for found in _rules_of(module):
            if found.code in registry:
                raise ValueError(f"rule {found.code} defined twice")
            registry[found.code] = found
    return dict(sorted(registry.items()))


def __getattr__(name: str):
    """``REGISTRY``, built the first time it is asked for, then kept as the module's constant."""
    if name != "REGISTRY":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return registry()


def registry() -> MappingProxyType[str, Rule]:
    """Every rule by code (the rule modules imported the first time it is asked for)."""
    found = globals().get("REGISTRY")
    if found is None:
        found = globals()["REGISTRY"] = MappingProxyType(_registry())
    return found


@cache
def checks(rule_set: RuleSet) -> tuple[Rule, ...]:
    """The check rules (those with a function) a run of ``rule_set`` runs, by code: worked
    out once a process, not for each model."""
    return tuple(rule for rule in registry().values() if rule.function is not None and rule_set.holds(rule.rule_set))


def rule(code: str) -> Rule:
    """The rule ``code`` (KeyError when there is none)."""
    return registry()[code]


def lookup(code_or_name: str) -> Rule:
    """A rule by code (any case) or kebab-case name; UnknownRule says what was meant."""
    key = code_or_name.strip()
    rules = registry()
    if key.upper() in rules:
        return rules[key.upper()]
    for candidate in rules.values():
        if candidate.name == key.lower():
            return candidate
    known = list(rules) + [r.name for r in rules.values()]
    close = close_matches(key, known)
    meant = f" (did you mean '{close[0]}'?)" if close else ""
    raise UnknownRule(f"unknown rule '{code_or_name}'{meant}; `urdfcli rules` lists them")


def severity_of(code: str) -> Severity:
    """The default severity of a rule's diagnostics."""
    return registry()[code].severity


__all__ = [
    "MODULES", "PLACED", "REGISTRY", "SECTIONS", "Given", "Kind", "Option", "Remedy", "Rule", "RuleSet", "UnknownRule", "checks", "cleandoc", "example_code",
    "explain", "lookup", "registry", "rule", "sections", "severity_of",
]
