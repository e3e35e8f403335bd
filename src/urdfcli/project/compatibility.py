"""The compatibility report: for each consumer asked for (``--target``), whether it loads the
model, loads it with changes, or refuses it, and why, from the diagnostics of one model.

A consumer refuses the model when an error of its own rules says so, or when a plain
error (a rule that is no consumer's, such as J003, a revolute joint without ``<limit>``)
is one it does not load anyway (:attr:`urdfcli.model.targets.Consumer.loads_anyway`:
MuJoCo takes that joint, unlimited). A change is a warning of its rules.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..diagnostics import Diagnostic, Severity
from ..model.targets import Consumer, Profile, Verdict
from ..rules import REGISTRY
from ..rules.targets import about_the_model


def refused_by(diagnostic: Diagnostic, consumer: Consumer) -> bool:
    """Whether ``diagnostic`` (severity given) says that ``consumer`` refuses the model."""
    if diagnostic.severity is not Severity.ERROR:
        return False
    if diagnostic.code.startswith(consumer.prefix):
        return True
    rule = REGISTRY.get(diagnostic.code)
    return rule is not None and about_the_model(rule) and diagnostic.code not in consumer.loads_anyway


COUNTED = (Severity.ERROR, Severity.WARNING)


def verdict(diagnostics: Iterable[Diagnostic], chosen: Profile) -> Verdict:
    """What ``chosen``'s consumer does with the model the diagnostics are about."""
    consumer = chosen.consumer
    found = list(diagnostics)
    refusals = [d for d in found if refused_by(d, consumer)]
    changes = [d for d in found if d.code.startswith(consumer.prefix) and d.severity is Severity.WARNING]
    reason = (refusals or changes or [None])[0]
    return Verdict(chosen.text(), consumer.title, bool(refusals), len(changes), reason)


def verdicts(diagnostics: Iterable[Diagnostic], profiles: Iterable[Profile]) -> tuple[Verdict, ...]:
    found = [d for d in diagnostics if d.severity in COUNTED]  # the notes (info) are neither refusals nor changes
    return tuple(verdict(found, chosen) for chosen in profiles)
