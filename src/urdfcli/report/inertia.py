"""The mass-property audit of ``urdfcli inertia`` (worked out in :mod:`urdfcli.model.audit`),
written as text or JSON: per link the declared tensor, its principal moments, the tensor
the geometry implies, and the problems; then the whole robot's total; the suggested
``<inertial>`` elements."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..model import massprops
from ..model.audit import Audit, LinkAudit
from ..model.inertia import declared_tensor
from ..model.load import Loaded
from ..model.massprops import number, tensor_text
from ..rules import REGISTRY
from .console import Line, Output, write
from .escape import escape
from .lines import diagnostic_dict, diagnostics_lines, plural
from .targets import build_dict, inertia_lines

if TYPE_CHECKING:
    from ..model.result import Result


# -- JSON ------------------------------------------------------------------------------
def _vector(values) -> list[float]:
    return [float(v) for v in values]


def _tensor(tensor) -> dict[str, float] | None:
    return None if tensor is None else {k: float(v) for k, v in massprops.as_dict(tensor).items()}


def massless(link, loaded: Loaded) -> str:
    """What a massless link is: a frame (no shape: tool0, the virtual links between the
    joints of a hip; or a shape but no collision, fixed to its parent or the root: a
    footprint drawn as a dot), or a part that declares no mass (one that collides, or
    that moves with a shape: an industrial arm's links without <inertial>)."""
    joint = loaded.parent_joint(link.name)
    if not link.collisions and (not link.visuals or joint is None or joint.type == "fixed"):
        return "massless frame link"
    return "massless: no <inertial>" if link.inertial is None else "massless: mass 0"


def expected_from(entry: LinkAudit, loaded: Loaded) -> str:
    if entry.frame:
        return massless(entry.link, loaded)
    if entry.assessment is None:
        return "no inertia tensor declared"
    return entry.assessment.implied.source


def _principal(tensor) -> tuple[float, float, float]:
    """The principal moments as the rules say them: rounding noise of the solve as 0."""
    return massprops.without_noise(massprops.principal_moments(tensor))


def link_dict(entry: LinkAudit, loaded: Loaded) -> dict:
    link, found = entry.link, entry.assessment
    inertial = link.inertial
    declared = declared_tensor(link)
    where = loaded.document.locate(link.at)
    return {
        "name": link.name,
        "path": where.file,
        "line": where.line,
        "column": where.column,
        "mass": inertial.mass if inertial is not None else None,
        "mass_used": entry.mass,
        "com": _vector(inertial.origin.xyz) if inertial is not None else None,
        "inertia": _tensor(declared),
        "principal": _vector(_principal(declared)) if declared is not None else None,
        "expected": _tensor(found.expected) if found is not None else None,
        "expected_from": expected_from(entry, loaded),
        "problems": [diagnostic_dict(d) for d in entry.problems],
    }


def audit_dict(result: Result) -> dict:
    """``{"robot", "links", "total"}`` of one file (empty when it has no model to audit)."""
    audit = result.audit
    if audit is None:
        return {"robot": None, "links": [], "total": None}
    body = audit.total
    return {
        "robot": audit.loaded.robot.name,
        "links": [link_dict(entry, audit.loaded) for entry in audit.links],
        "total": None if body is None else {"mass": body.mass, "com": _vector(body.com), "inertia": _tensor(body.tensor)},
        **({"targets": [build_dict(built) for built in audit.targets]} if audit.targets else {}),
    }


# -- text ------------------------------------------------------------------------------
def _row(label: str, value: str, style: str = "") -> Line:
    return [(f"    {label:<10} ", "dim"), (value, style)]


def audit_lines(audit: Audit, show_name: bool) -> list[Line]:
    """The per-link table and the total, as styled lines."""
    loaded = audit.loaded
    title: Line = [(f"robot '{escape(loaded.robot.name or '')}'", "bold")]
    if show_name:
        title.append((f"  ({escape(loaded.document.shown)})", "dim"))
    lines = [title]
    for entry in audit.links:
        link, found = entry.link, entry.assessment
        if entry.frame and not entry.problems and not entry.from_density:
            lines.append([(escape(link.name), "bold"), (f"  {massless(link, loaded)}", "dim")])
            continue
        inertial = link.inertial
        header: Line = [(escape(link.name), "bold")]
        if entry.from_density:  # the mass the total counts, and the declared one beside it
            declared = f"declared {number(inertial.mass)}" if inertial is not None and inertial.mass is not None else "none declared"
            header.append((f"  mass {number(entry.mass)} from density ({declared})", ""))
        elif inertial is not None and inertial.mass is not None:
            header.append((f"  mass {number(inertial.mass)}  com {' '.join(map(number, inertial.origin.xyz))}", ""))
        lines.append(header)
        if found is not None:
            expected = found.expected
            lines.append(_row("declared", tensor_text(found.declared, expected)))
            lines.append(_row("principal", " ".join(number(m) for m in _principal(found.declared))))
            if expected is not None:
                style = "yellow" if found.off(audit.tolerance) else "green"
                times = found.times()
                apart = f"declared {times}" if times is not None else f"{found.difference:.1%} apart"
                lines.append(_row("expected", f"{tensor_text(expected, found.declared)}  ({found.implied.source}; {apart})", style))
            else:
                lines.append(_row("expected", f"unknown: {found.implied.source}", "dim"))
        if entry.problems:
            lines.append(_row("problems", ", ".join(f"{d.code} {REGISTRY[d.code].name}" for d in dict.fromkeys(entry.problems)), "yellow"))
    body = audit.total
    if body is not None and body.mass == 0:
        lines.append([("total", "bold"), ("  no link declares a mass: a kinematic model (simulators and dynamics libraries need masses)", "yellow")])
    elif body is not None:
        lines.append([("total", "bold"), (f"  mass {number(body.mass)}  com {' '.join(map(number, body.com))} (in '{escape(loaded.root or '')}' frame, joints at zero)", "")])
        lines.append(_row("inertia", tensor_text(body.tensor) + "  about the centre of mass"))
    for built in audit.targets:
        lines.extend(inertia_lines(built))
    return lines


def problem_count(results: list[Result]) -> int:
    """The audits' problems and the models' errors."""
    return sum(len(r.audit.problems) for r in results if r.audit is not None) + sum(len(r.errors) for r in results)


def write_audit(results: list[Result], output: Output) -> None:
    """Each model's table on standard output and its problems on standard error; then
    how many problems there are."""
    for result in results:
        if result.audit is not None:
            write(output.out, audit_lines(result.audit, show_name=len(results) > 1))
            write(output.err, diagnostics_lines(result.audit.problems, None))
            if result.audit.suggestions:
                write(output.out, [[("", "")], *([(escape(line), "")] for text in result.audit.suggestions for line in text.split("\n"))])
    problems = problem_count(results)
    write(output.err, [[(f"{plural(len(results), 'file')} audited: {plural(problems, 'problem')}", "bold")]])
