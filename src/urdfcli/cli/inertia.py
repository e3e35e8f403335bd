"""`urdfcli inertia`: audit mass properties against physics and geometry, and print the fix."""

from __future__ import annotations

import json
import sys
from typing import Annotated

from rich.text import Text

from .. import fixes, massprops
from .. import inertia as audit_module
from ..diagnostics import Severity
from ..escape import escape
from ..formatters.text import print_diagnostic
from ..linter import configured
from ..rules import rule
from .common import ConfigOption, Exit, InputsArgument, IsolatedOption, PackagePathOption, configurations, fail, load_all, stderr, stdout
from .options import BadValue, Option

FORMATS = ("text", "json")


def inertia(
    inputs: InputsArgument,
    tolerance: Annotated[
        float,
        Option(
            "--tolerance",
            metavar="FRACTION",
            help="Flag a tensor whose largest element difference from the geometry's exceeds this fraction of the larger "
            "tensor's largest element. The default 0.1 catches swapped or unrotated axes and lets values rounded to two digits pass.",
        ),
    ] = audit_module.TOLERANCE,
    suggest: Annotated[bool, Option("--suggest", help="Print, for each flagged link, the <inertial> of a uniform body filling its geometry.")] = False,
    xacro: Annotated[bool, Option("--xacro", help="Implies --suggest: name the xacro macro that wrote each flagged <inertial>, and print the call of it that gives the right values.")] = False,
    density: Annotated[float | None, Option("--density", metavar="KG_PER_M3", help="Compute masses from the geometry's volume at this density instead of using the declared masses.")] = None,
    output_format: Annotated[str, Option("--format", "-f", metavar="FORMAT", help="text, or json (one object per file; a list of them for several files).", case_sensitive=False)] = "text",
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
) -> None:
    """Audit each link's mass, centre of mass and inertia against physics and its geometry.

    Per link: the declared tensor, its principal moments, the tensor the collision shapes (else the visual shapes) imply for the link's mass, and the problems. Then the whole robot at zero joint positions: total mass, centre of mass in the root link's frame, and the inertia about it.

    Exit 0 when nothing is found, 1 on any warning or error, 2 when it cannot run.
    """
    output_format = output_format.lower()
    if output_format not in FORMATS:
        raise BadValue(f"unknown format {output_format!r}; choose from {', '.join(FORMATS)}", "--format")
    if not tolerance > 0:
        raise fail("--tolerance must be a positive fraction, such as 0.1")
    if density is not None and not density > 0:
        raise fail("--density must be a positive number of kg/m³")
    if output_format == "json" and (suggest or xacro):
        raise fail("--suggest and --xacro print XML; use them with the text format")
    config_for = configurations(config, isolated)
    results, unreadable = load_all(inputs, package_path, "none", config_for)
    if not results:
        raise SystemExit(Exit.CANNOT_RUN)
    reports = [audit_module.audit(loaded, tolerance, density) if loaded.robot is not None and loaded.robot.at is not None else None for loaded in results]
    reports = [configured_report(r, config_for(r.loaded.path)) if r is not None else None for r in reports]
    for loaded in results:
        for diagnostic in loaded.diagnostics:
            if diagnostic.severity is Severity.ERROR:
                print_diagnostic(stderr, diagnostic)
    if output_format == "json":
        objects = [audit_module.report_json(r) if r else {"robot": None, "links": [], "total": None} for r in reports]
        sys.stdout.write(json.dumps(objects[0] if len(objects) == 1 else objects, indent=2) + "\n")
    else:
        for loaded, report in zip(results, reports):
            if report is not None:
                print_report(report, show_name=len(results) > 1)
                if suggest or xacro:
                    print_suggestions(report, density, xacro)
    problems = sum(len(r.problems) for r in reports if r) + sum(1 for loaded in results for d in loaded.diagnostics if d.severity is Severity.ERROR)
    if output_format == "text":
        stderr.print(f"{len(results)} file{'s' if len(results) != 1 else ''} audited: {problems} problem{'s' if problems != 1 else ''}", markup=False, style="bold")
    if unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    if problems:
        raise SystemExit(Exit.PROBLEMS)


def configured_report(report: audit_module.Report, config) -> audit_module.Report:
    """The report with the findings the configuration and noqa comments leave (severities as configured)."""
    loaded = report.loaded
    kept = configured(loaded, loaded.path, config, diagnostics=list(report.problems))
    by_key = {(d.code, d.location, d.message): d for d in kept if d.code not in ("U001", "U002")}

    def keep(found) -> tuple:
        return tuple(by_key[key] for d in found if (key := (d.code, d.location, d.message)) in by_key)

    links = tuple(entry._replace(problems=keep(entry.problems)) for entry in report.links)
    return report._replace(links=links, problems=keep(report.problems))


def _row(label: str, value: str, style: str = "") -> Text:
    return Text.assemble((f"    {label:<10} ", "dim"), (value, style))


def print_report(report: audit_module.Report, show_name: bool) -> None:
    """The per-link table and the total on stdout; the problems with locations on stderr."""
    lines = list(report_lines(report, show_name))
    if stdout.is_terminal:
        for line in lines:
            stdout.print(line, soft_wrap=True)
    else:  # plain text, written at once: rich's per-line rendering is slow on 100,000 links
        sys.stdout.write("".join(line.plain + "\n" for line in lines))
        sys.stdout.flush()
    for diagnostic in report.problems:
        print_diagnostic(stderr, diagnostic)


def report_lines(report: audit_module.Report, show_name: bool):
    """The report as styled lines."""
    number = audit_module.number
    loaded = report.loaded
    title = Text.assemble((f"robot '{escape(loaded.robot.name or '')}'", "bold"))
    if show_name:
        title.append(f"  ({escape(loaded.document.shown)})", style="dim")
    yield title
    for entry in report.links:
        link, found = entry.link, entry.assessment
        if entry.frame and not entry.problems and not entry.from_density:
            yield Text.assemble((escape(link.name), "bold"), ("  massless frame link", "dim"))
            continue
        inertial = link.inertial
        header = Text.assemble((escape(link.name), "bold"))
        if entry.from_density:  # the mass the total counts, and the declared one beside it
            declared = f"declared {number(inertial.mass)}" if inertial is not None and inertial.mass is not None else "none declared"
            header.append(f"  mass {number(entry.mass)} from density ({declared})")
        elif inertial is not None and inertial.mass is not None:
            header.append(f"  mass {number(inertial.mass)}  com {' '.join(map(number, inertial.origin.xyz))}")
        yield header
        if found is not None:
            expected = found.expected
            yield _row("declared", audit_module.tensor_text(found.declared, expected))
            yield _row("principal", " ".join(number(m) for m in massprops.principal_moments(found.declared)))
            if expected is not None:
                style = "yellow" if found.off(report.tolerance) else "green"
                yield _row("expected", f"{audit_module.tensor_text(expected, found.declared)}  ({found.implied.source}; {found.difference:.1%} apart)", style)
            else:
                yield _row("expected", f"unknown: {found.implied.source}", "dim")
        if entry.problems:
            yield _row("problems", ", ".join(f"{d.code} {rule(d.code).name}" for d in entry.problems), "yellow")
    body = report.total
    if body is not None:
        yield Text.assemble(("total", "bold"), f"  mass {number(body.mass)}  com {' '.join(map(number, body.com))} (in '{escape(loaded.root or '')}' frame, joints at zero)")
        yield _row("inertia", audit_module.tensor_text(body.tensor) + "  about the centre of mass")


def print_suggestions(report: audit_module.Report, density: float | None, xacro: bool) -> None:
    flagged = audit_module.flagged(report)
    if not flagged:
        return
    stdout.print()
    for entry in flagged:
        loaded = report.loaded
        use = fixes.macro_use(loaded, entry.link) if xacro else None
        if use is not None:
            called = f", called at {use.called_at} as {use.call}" if use.call else ""
            stdout.print(f"<!-- link '{escape(entry.link.name)}': its <inertial> comes from xacro macro '{use.name}' ({use.defined_at}){called} -->", markup=False, soft_wrap=True)
            call = fixes.matching_call(loaded, entry.link, use) if density is None else None
            if call is not None:
                stdout.print(f"<!-- the call that gives the geometry's values: -->\n{call}", markup=False, soft_wrap=True)
                continue
            stdout.print(f"<!-- no call of '{use.name}' gives the geometry's values: replace the call with -->", markup=False, soft_wrap=True)
        stdout.print(fixes.suggestion(loaded, entry, density), markup=False, soft_wrap=True)
