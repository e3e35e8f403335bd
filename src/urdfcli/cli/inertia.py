"""`urdfcli inertia`: audit mass properties against physics and geometry, and print the fix."""

from __future__ import annotations

from typing import Annotated

import typer

from .. import report
from ..diagnostics import Severity
from ..model.massprops import TOLERANCE
from ..options import AuditOptions, Options, RuleSet
from ..report.console import Output, write
from .common import (
    ColorOption,
    ConfigOption,
    Exit,
    InputsArgument,
    IsolatedOption,
    PackagePathOption,
    TargetOption,
    choose,
    fail,
    format_option,
    not_a_robot,
    refuse_library,
    report_unreadable,
    session_for,
    split_inputs,
)


def inertia(
    inputs: InputsArgument,
    tolerance: Annotated[
        float,
        typer.Option(
            "--tolerance",
            metavar="FRACTION",
            help="Flag a tensor whose largest element difference from the geometry's exceeds this fraction of the larger "
            "tensor's largest element. The default 0.1 catches swapped or unrotated axes and lets values rounded to two digits pass.",
        ),
    ] = TOLERANCE,
    suggest: Annotated[bool, typer.Option("--suggest", help="Print, for each flagged link, the <inertial> of a uniform body filling its geometry.")] = False,
    xacro: Annotated[bool, typer.Option("--xacro", help="Implies --suggest: name the xacro macro that wrote each flagged <inertial>, and print the call of it that gives the right values.")] = False,
    density: Annotated[float | None, typer.Option("--density", metavar="KG_PER_M3", help="Compute masses from the geometry's volume at this density instead of using the declared masses.")] = None,
    output_format: format_option("text, or json (one object per file; a list of them for several files).") = "text",
    target: TargetOption = None,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    color: ColorOption = "auto",
) -> None:
    """Audit each link's mass, centre of mass and inertia against physics and its geometry.

    Per link: the declared tensor, its principal moments, the tensor the collision shapes (else the visual shapes, or those when the collision shapes are a stand-in under a tenth of their size) imply for the link's mass, and the problems. Then the whole robot at zero joint positions: total mass, centre of mass in the root link's frame, and the inertia about it.

    Exit 0 when nothing is found, 1 on any warning or error, 2 when it cannot run.
    """
    from .. import api
    from ..report.lines import diagnostics_lines

    output_format = choose(output_format, ("text", "json"))
    if not tolerance > 0:
        raise fail("--tolerance must be a positive fraction, such as 0.1")
    if density is not None and not density > 0:
        raise fail("--density must be a positive number of kg/m³")
    if output_format == "json" and (suggest or xacro):
        raise fail("--suggest and --xacro print XML; use them with the text format")
    paths, mappings = split_inputs(inputs)
    options = Options(
        RuleSet.TREE, tuple(mappings.items()), tuple(package_path or ()), config, isolated, targets=tuple(target or ()), libraries=False,
        audit=AuditOptions(tolerance, density, suggest, xacro), format=output_format,
    )
    output = Output.standard(color)
    with session_for(options) as session:
        for path in paths:
            refuse_library(path, session)
        found = api.run(paths, session)
        report_unreadable(output, found.unreadable)
        if not found.results:
            raise SystemExit(Exit.CANNOT_RUN)
        srdf = next((r for r in found.results if r.loaded is not None and r.loaded.semantic is not None), None)
        if srdf is not None:
            raise fail(not_a_robot(srdf.path))
        write(output.err, diagnostics_lines((d for result in found.results for d in result.errors), None))
        report.reporter(options.format)(output, session.files).audit(found.results)
    if found.unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    if any(d.severity is not Severity.INFO for r in found.results for d in [*(r.audit.problems if r.audit else ()), *r.errors]):
        raise SystemExit(Exit.PROBLEMS)  # an info alone (a root link with mass, which KDL ignores) fails nothing
