"""The rule registry: every diagnostic urdfcli can emit has a code here.

Each rule module holds its rules (see :mod:`.base`); the registry is built from
them once, when this package is imported, and does not change.
"""

from __future__ import annotations

from types import MappingProxyType, ModuleType

from ..diagnostics import Severity
from . import description, drift, inertia, joints, meshes, packages, physics, structure, style, suppression, targets, tree, xacro
from .base import PLACED, SECTIONS, Given, Kind, Option, Remedy, Rule, RuleSet, UnknownRule, cleandoc, example_code, explain, sections
from .suggestions import close_matches

MODULES = (structure, tree, joints, physics, description, meshes, style, inertia, suppression, xacro, drift, packages, *targets.MODULES)


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
    for module in MODULES:
        for found in _rules_of(module):
            if found.code in registry:
                raise ValueError(f"rule {found.code} defined twice")
            registry[found.code] = found
    return dict(sorted(registry.items()))


REGISTRY: MappingProxyType[str, Rule] = MappingProxyType(_registry())


def rule(code: str) -> Rule:
    """The rule ``code`` (KeyError when there is none)."""
    return REGISTRY[code]


def lookup(code_or_name: str) -> Rule:
    """A rule by code (any case) or kebab-case name; UnknownRule says what was meant."""
    key = code_or_name.strip()
    if key.upper() in REGISTRY:
        return REGISTRY[key.upper()]
    for candidate in REGISTRY.values():
        if candidate.name == key.lower():
            return candidate
    known = list(REGISTRY) + [r.name for r in REGISTRY.values()]
    close = close_matches(key, known)
    meant = f" (did you mean '{close[0]}'?)" if close else ""
    raise UnknownRule(f"unknown rule '{code_or_name}'{meant}; `urdfcli rules` lists them")


def severity_of(code: str) -> Severity:
    """The default severity of a rule's diagnostics."""
    return REGISTRY[code].severity


__all__ = [
    "MODULES", "PLACED", "REGISTRY", "SECTIONS", "Given", "Kind", "Option", "Remedy", "Rule", "RuleSet", "UnknownRule", "cleandoc", "example_code", "explain",
    "lookup", "rule", "sections", "severity_of",
]
