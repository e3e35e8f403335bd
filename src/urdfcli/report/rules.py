"""The rule registry as documentation: one rule's page, the JSON list, and docs/rules.md."""

from __future__ import annotations

import json
import re

from ..diagnostics import Severity
from ..rules import PLACED, Remedy, Rule, RuleSet
from ..rules.targets import about_the_model
from ..targets import TARGETS
from ..version import __version__

PREFIXES = {
    "X": "Input and xacro",
    "R": "Robot",
    "N": "Names",
    "V": "Values",
    "G": "Geometry",
    "M": "Materials",
    "J": "Joints",
    "T": "Tree",
    "I": "Inertia and mass",
    "D": "Description",
    "F": "Mesh files",
    "P": "Packages",
    "K": "SRDF (MoveIt's semantic description, checked against its URDF)",
    "C": "Targets (with --target NAME: " + ", ".join(f"{c.prefix} {c.title}" for c in TARGETS.values()) + ")",
    "S": "Style (off by default)",
    "U": "Suppression comments",
}


def ordered(rules) -> list[Rule]:
    """Rules grouped as the documentation presents them (input first, style last), by code within a group."""
    order = list(PREFIXES)
    return sorted(rules, key=lambda r: (order.index(r.code[0]) if r.code[0] in order else len(order), r.code))


def in_check(rule: Rule) -> bool:
    """Whether ``urdfcli check`` reports the rule."""
    return RuleSet.CHECK.holds(rule.rule_set)


# What check_urdf does where it does not reject the file (see report.check_urdf.logged)
URDFDOM = {
    **dict.fromkeys(("V001", "V002", "V003", "V004"), "check_urdf rejects it in a joint, and logs it and goes on in a link's visual, collision or inertial"),
    **dict.fromkeys(("V005", "G001", "G002"), "check_urdf logs it, drops the visual, collision or inertial, and goes on (exit 0)"),
    **dict.fromkeys(("N003", "M001", "V007"), "check_urdf logs it and goes on (exit 0)"),
}


def facts(rule: Rule) -> str:
    """One line: severity, on or off by default, and where it is reported."""
    where = "check and lint" if in_check(rule) else "lint"
    parts = [f"severity {rule.severity.value}", "on by default" if rule.default else "off by default (select it)", f"reported by {where}"]
    if rule.target is not None:
        parts[1:2] = [f"runs with --target {rule.consumer}" + (f" (examples: --target {rule.target})" if rule.target != rule.consumer else "")]
    if rule.urdfdom:
        parts.append(URDFDOM.get(rule.code, "check_urdf rejects it too"))
    fix = rule.fixable
    if fix is not None:
        parts.append("fixable with --fix (safe)" if fix.value == "safe" else "fixable with --fix --unsafe-fixes (unsafe)")
    if rule.severity is Severity.ERROR and about_the_model(rule):
        loading = [c.title for c in TARGETS.values() if rule.code in c.loads_anyway]
        parts.append(f"{', '.join(loading)} load{'s' if len(loading) == 1 else ''} the model anyway" if loading else "every --target consumer refuses the model")
    return "; ".join(parts)


def fix_markdown(rule: Rule) -> str:
    """The ``## Fix`` section: what the fix does, how safe it is, and when there is none."""
    fix = rule.fixable
    if fix is None:
        return ""
    safety = "`--fix` applies it." if fix.value == "safe" else "Unsafe: `--fix --unsafe-fixes` applies it, and the editor offers it."
    what = rule.fix_doc or (rule.remedy is Remedy.INERTIAL and "Writes the tensor and centre of mass of a uniform body filling the link's "
                            f"collision geometry (else its visual geometry), its mass kept: `urdfcli inertia --suggest`'s values (unsafe: the dynamics change). {PLACED}") or ""
    return f"## Fix\n\n{what} {safety}"


def options_markdown(rule: Rule) -> str:
    if not rule.options:
        return ""
    lines = ["## Options", ""]
    for option in rule.options:
        lines.append(f"- `{option.name}` ({option.kind}, default `{json.dumps(option.default)}`): {option.doc}")
    lines += ["", f"Set them in `[tool.urdfcli.options.{rule.code}]` of pyproject.toml, or `[options.{rule.code}]` of urdfcli.toml (the rule's name works too)."]
    return "\n".join(lines)


def page(rule: Rule, level: int = 1) -> str:
    """A rule's documentation as Markdown, headed ``CODE name`` at ``level``, its sections one below."""
    sections = "\n\n".join(part for part in (rule.doc, options_markdown(rule), fix_markdown(rule)) if part)
    sections = re.sub(r"^## ", "#" * (level + 1) + " ", sections, flags=re.MULTILINE)
    return f"{'#' * level} {rule.code} {rule.name}\n\n{rule.summary}\n\n*{facts(rule)}*\n\n{sections}\n"


def as_json(rules: list[Rule]) -> str:
    """The registry as ``{"version": 1, "urdfcli": VERSION, "rules": [...]}``: which
    release the codes and defaults belong to travels with them."""
    return json.dumps({"version": 1, "urdfcli": __version__, "rules": [
            {
                "code": r.code,
                "name": r.name,
                "severity": r.severity.value,
                "default": r.default,
                "kind": r.kind.value,
                "in_check": in_check(r),
                "urdfdom": r.urdfdom,
                "target": r.target,
                "fix": r.fixable.value if r.fixable is not None else None,
                "summary": r.summary,
                "options": [{"name": o.name, "type": o.kind, "default": o.default, "doc": o.doc} for o in r.options],
                "doc": r.doc,
            }
            for r in rules
        ]},
        indent=2,
        ensure_ascii=False,
    )


def markdown(rules: list[Rule]) -> str:
    """docs/rules.md: an index table, then every rule's page, grouped by prefix."""
    lines = [
        "# Rules",
        "",
        "Generated by `urdfcli rules --format markdown` from the rule registry; do not edit by hand.",
        "`urdfcli rule CODE` prints one rule. Select and ignore rules by code or prefix (see the README's",
        '"Configuration"); silence one occurrence with `<!-- urdfcli: noqa: CODE -->`.',
        "",
        "| Code | Name | Severity | Default | Fix | Summary |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    rules = ordered(rules)
    for rule in rules:
        summary = rule.summary.replace("|", "\\|")
        fix = rule.fixable.value if rule.fixable is not None else ""
        lines.append(f"| [{rule.code}](#{rule.code.lower()}-{rule.name}) | {rule.name} | {rule.severity.value} | {'on' if rule.default else 'off'} | {fix} | {summary} |")
    prefix = None
    for rule in rules:
        if rule.code[0] != prefix:
            prefix = rule.code[0]
            lines += ["", f"## {PREFIXES.get(prefix, prefix)}"]
        lines += ["", page(rule, level=3).rstrip()]
    return "\n".join(lines) + "\n"
