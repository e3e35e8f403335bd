"""What a consumer builds from a model, for people: ``tree --target`` marks each link
with what the consumer makes of it, ``inertia --target`` lists the masses and
tensors it will use. The build itself is :mod:`urdfcli.model.targets`."""

from __future__ import annotations

from ..model.massprops import number
from ..model.targets import Build
from .console import Line
from .escape import escape
from .tree import plural


def link_notes(built: Build) -> dict[str, str]:
    """Each link the consumer does not keep as a body of its own -> what happens to it."""
    notes = dict(built.dropped)
    for body in built.bodies:
        for link in body.links[1:]:
            notes[link] = f"fused into {body.top}"
    return {link: _dropped(note) for link, note in notes.items()}


def _dropped(note: str) -> str:
    return note if note.startswith(("fused", "the root")) else f"dropped: {note}"


def joint_notes(built: Build) -> dict[str, str]:
    return {joint: f"becomes {what}" for joint, what in built.changed.items()}


def summary(built: Build) -> str:
    """``MuJoCo: 7 bodies (3 links fused or dropped), fixed base, 6 DOF``."""
    left = sum(len(body.links) - 1 for body in built.bodies) + len(built.dropped)
    fused = f" ({plural(left, 'link')} fused or dropped)" if left else ""
    return f"{built.profile.name} ({built.profile.text()}): {len(built.bodies)} {'body' if len(built.bodies) == 1 else 'bodies'}{fused}, {built.base} base, {built.dof} DOF"


def _moments(moments) -> str:
    return " ".join(number(m) for m in moments) if moments is not None else "unknown"


def inertia_lines(built: Build) -> list[Line]:
    """The masses and principal moments the consumer will use, body by body, and the total mass."""
    lines: list[Line] = [[(f"{built.profile.name} ({built.profile.text()}) uses", "bold")]]
    for body in built.bodies:
        fused = f" + {', '.join(escape(n) for n in body.links[1:])}" if len(body.links) > 1 else ""
        mass = number(body.mass) if body.mass is not None else "unknown"
        lines.append([
            (f"    {escape(body.top)}{fused}", "bold"),
            (f"  mass {mass}  moments {_moments(body.moments)}", ""),
            (f"  ({body.source})", "dim"),
        ])
    for link, why in built.dropped.items():
        lines.append([(f"    {escape(link)}", "bold"), (f"  {_dropped(why)}", "yellow")])
    masses = [b.mass for b in built.bodies]
    total = number(sum(m for m in masses if m is not None)) + (" and the bodies of unknown mass" if None in masses else "")
    lines.append([("    total", "bold"), (f"  mass {total}, {built.base} base, {built.dof} DOF", "")])
    return lines


def build_dict(built: Build) -> dict:
    return {
        "target": built.profile.text(),
        "base": built.base,
        "dof": built.dof,
        "bodies": [
            {"links": list(b.links), "joint": b.joint.name if b.joint is not None else None, "mass": b.mass,
             "moments": list(b.moments) if b.moments is not None else None, "source": b.source}
            for b in built.bodies
        ],
        "dropped": built.dropped,
        "changed": built.changed,
        "total_mass": sum(b.mass for b in built.bodies if b.mass is not None),
    }


def compatibility_lines(result) -> list[Line]:
    """The compatibility table of one model (``check --target``): one row per consumer, its
    verdict and the first reason with its place."""
    verdicts = result.compatibility
    if not verdicts:
        return []
    width = max(len(_consumer(v)) for v in verdicts)
    said = max(len(v.outcome) for v in verdicts)
    lines: list[Line] = [[(f"Compatibility of {escape(result.shown)} (urdfcli's prediction):", "bold")]]
    for verdict in verdicts:
        style = "red" if verdict.refuses else "yellow" if verdict.changes else "green"
        outcome = f"{verdict.outcome:<{said}}" if verdict.reason is not None else verdict.outcome
        row: Line = [(f"  {escape(_consumer(verdict)):<{width}}  ", "bold"), (outcome, style)]
        if verdict.reason is not None:
            row.append((f"  {escape(_place(verdict.reason))}: {verdict.reason.code} {escape(verdict.reason.message)}", "dim"))
        lines.append(row)
    return lines


def _consumer(verdict) -> str:
    """``MuJoCo``, or ``Pinocchio (pinocchio:mimic)`` for a variant."""
    return f"{verdict.title} ({verdict.profile})" if ":" in verdict.profile else verdict.title


def _place(diagnostic) -> str:
    location = diagnostic.location
    return f"{location.file}:{location.line}" if location.line else location.file


def compatibility_dicts(result) -> list[dict]:
    """The compatibility table as JSON: each consumer's verdict and its first reason."""
    return [
        {"target": v.profile, "consumer": v.title, "verdict": "refuses" if v.refuses else "loads with changes" if v.changes else "loads",
         "changes": v.changes,
         "reason": None if v.reason is None else {"code": v.reason.code, "message": v.reason.message, "path": v.reason.location.file,
                                                  "line": v.reason.location.line, "column": v.reason.location.column}}
        for v in result.compatibility
    ]


def registry_markdown() -> str:
    """The section of docs/targets.md made from the registry: the targets, their variants and the
    versions they follow, and which plain errors each consumer loads the model with all the same."""
    from ..rules import REGISTRY
    from ..rules.targets import about_the_model
    from ..targets import ALL, TARGETS

    consumers = list(TARGETS.values())
    lines = ["| target | consumer | rules | follows | variants |", "|---|---|---|---|---|"]
    for consumer in consumers:
        variants = "; ".join(f"`{consumer.name}:{v.name}`: `{v.means}`" for v in consumer.variants) or "-"
        lines.append(f"| `{consumer.name}` | {consumer.title} | {consumer.prefix}xx | {consumer.follows} | {variants} |")
    lines += ["", f"`--target {ALL}` (or `targets = [\"{ALL}\"]`) is every consumer in its default profile.", "",
              "Plain errors (rules that are no consumer's) and the consumers that load the model all the same "
              "(L: loads it; -: refuses it), measured on one case each in tests/target_cases.py:", "",
              "| rule | " + " | ".join(c.title for c in consumers) + " |", "|---|" + "---|" * len(consumers)]
    for code, rule in REGISTRY.items():
        if rule.severity.value == "error" and about_the_model(rule):
            lines.append(f"| {code} {rule.name} | " + " | ".join("L" if code in c.loads_anyway else "-" for c in consumers) + " |")
    return "\n".join(lines) + "\n"
