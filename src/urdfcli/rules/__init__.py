"""The rule registry: every diagnostic urdfcli can emit has a code here.

A rule is either *structural* (emitted while the model is read: a missing
attribute, a malformed number, a broken tree) or a *check* (a function over
the loaded model, registered with :func:`check`). Both carry their code,
kebab-case name, default severity and documentation in one place.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..diagnostics import Severity

if TYPE_CHECKING:
    from ..loaded import Loaded
    from ..diagnostics import Diagnostic

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO


@dataclass(frozen=True)
class Rule:
    code: str
    name: str
    severity: Severity
    summary: str
    doc: str = ""
    urdfdom: bool = False  # check_urdf rejects (prints an error for) this too
    default: bool = True  # on unless selected explicitly
    in_check: bool = True  # reported by `urdfcli check` (else `lint`/`inertia` only)
    options: dict = field(default_factory=dict)
    function: Callable[["Loaded"], Iterator["Diagnostic"]] | None = None


REGISTRY: dict[str, Rule] = {}


def declare(code: str, name: str, severity: Severity, summary: str, doc: str = "", **kwargs) -> Rule:
    if code in REGISTRY:
        raise ValueError(f"rule {code} declared twice")
    rule = Rule(code, name, severity, summary, doc, **kwargs)
    REGISTRY[code] = rule
    return rule


def check(code: str, name: str, severity: Severity, summary: str, **kwargs):
    """Register a check function; its docstring is the rule's documentation."""

    def register(function):
        declare(code, name, severity, summary, function.__doc__ or "", function=function, **kwargs)
        return function

    return register


def rule(code: str) -> Rule:
    return load_all()[code]


def load_all() -> dict[str, Rule]:
    from . import structure, joints, physics  # noqa: F401  (registration side effects)

    return REGISTRY
