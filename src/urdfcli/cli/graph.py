"""`urdfcli graph`: the link tree as PDF, SVG, PNG or DOT (a better urdf_to_graphviz)."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from ..options import Options, RuleSet
from ..report.console import Output
from ..report.escape import escape
from ..report.output import OutputError, write_atomic
from .common import ColorOption, ConfigOption, Exit, IsolatedOption, PackagePathOption, fail, session_for, split_inputs

if TYPE_CHECKING:
    from ..model.result import Result

EXTENSIONS = {".pdf": "pdf", ".svg": "svg", ".png": "png", ".gv": "dot", ".dot": "dot"}


class RankDir(str, Enum):
    TB = "TB"
    LR = "LR"


def graph(
    inputs: Annotated[
        list[str],
        typer.Argument(
            metavar="FILE [OUT] [NAME:=VALUE]...",
            help="URDF or xacro file ('-' reads standard input); OUT names the outputs OUT.gv and OUT.pdf "
            "(default: the robot's name); NAME:=VALUE sets a xacro argument.",
            show_default=False,
        ),
    ],
    output: Annotated[Path | None, typer.Option("--output", "-o", metavar="PATH", help="Write one file instead, its format chosen by the extension: .pdf .svg .png .gv .dot.")] = None,
    output_format: Annotated[str | None, typer.Option("--format", "-f", metavar="dot", help="'dot': print the DOT text on standard output, write no file.")] = None,
    compat: Annotated[bool, typer.Option("--compat", help="Exactly urdf_to_graphviz's DOT statements (for scripts that parse them).")] = False,
    limits: Annotated[bool, typer.Option("--limits", help="Add joint limits (range, effort, velocity).")] = False,
    inertial: Annotated[bool, typer.Option("--inertial", help="Add link masses.")] = False,
    rankdir: Annotated[RankDir, typer.Option("--rankdir", case_sensitive=False, metavar="TB|LR", help="Top to bottom, or left to right.")] = RankDir.TB,
    collapse_fixed: Annotated[bool, typer.Option("--collapse-fixed", help="Merge links joined by fixed joints into one box (for large robots).")] = False,
    force: Annotated[bool, typer.Option("--force", help="Draw even when the model has errors (they are still printed, and the exit code is still 1).")] = False,
    timeout: Annotated[float, typer.Option("--timeout", min=1, metavar="SECONDS", help="Give up rendering after this long.")] = 120,
    package_path: PackagePathOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    color: ColorOption = "auto",
) -> None:
    """Draw the link tree, like urdf_to_graphviz: writes OUT.gv and OUT.pdf.

    The default drawing labels each joint with its name and type (and axis),
    coloured by type, with a legend and each joint's origin on its edge.
    Rendering needs the Graphviz program 'dot'. Children follow the order of
    their joints' names.

    The model's errors are those `check` reports (J007 zero axis, J008 mimic
    of a missing joint...) apart from a missing or unreadable mesh, printed on
    stderr. Exit 0; 1 when the model has errors: the graph is drawn all the
    same when urdfdom reads the model (as urdf_to_graphviz would), and
    otherwise only with --force; 2 when the input cannot be read, an output
    cannot be written, or dot is missing or fails (the DOT file is still
    written).
    """
    from ..report.drawing import Style, compat_dot, styled_dot
    from .drawn import load_model, report_errors, start_link

    paths, mappings = split_inputs(inputs)
    if len(paths) > 2:
        raise fail(f"graph takes a file and an optional output name, got {len(paths)} paths")
    if output_format is not None and output_format.lower() != "dot":
        raise typer.BadParameter(f"unknown format {output_format!r}; the only one is dot", param_hint="--format")
    if sum(x is not None for x in (output, output_format, paths[1] if len(paths) == 2 else None)) > 1:
        raise fail("give only one of OUT, --output and --format")
    output_kind = EXTENSIONS.get(output.suffix.lower()) if output is not None else None
    if output is not None and output_kind is None:
        raise fail(f"{output}: unknown extension; use one of {' '.join(EXTENSIONS)}")
    console = Output.standard(color)
    options = Options(RuleSet.CHECK, tuple(mappings.items()), tuple(package_path or ()), config, isolated)
    with session_for(options) as session:
        result = load_model(paths[0], session)
        has_errors = report_errors(result, console, session)
        start = start_link(result, None, console) if force or not stops_drawing(result) else None
    if start is None:
        raise SystemExit(Exit.PROBLEMS)
    robot = result.robot
    dot = compat_dot(robot, start) if compat else styled_dot(robot, start, Style(limits, inertial, rankdir.value, collapse_fixed))
    inputs_read = [paths[0], *result.includes]
    if output_format is not None:
        console.out.file.write(dot)
    elif output is not None and output_kind == "dot":
        write(console, output, dot, inputs_read)
    elif output is not None:
        make_picture(console, dot, output, output_kind, timeout, inputs_read, None)
    else:
        base = paths[1] if len(paths) == 2 else escape(robot.name or "robot").replace("/", "_")  # no control character in a file name
        write(console, Path(f"{base}.gv"), dot, inputs_read)
        make_picture(console, dot, Path(f"{base}.pdf"), "pdf", timeout, inputs_read, Path(f"{base}.gv"))
    if has_errors:  # drawn all the same (what urdfdom does not check), or with --force
        raise SystemExit(Exit.PROBLEMS)


def stops_drawing(result: Result) -> bool:
    """Whether the model cannot be drawn as urdf_to_graphviz draws it: urdfdom rejects it
    (an error check_urdf reports), or no robot was read. Errors urdfdom does not check
    (a negative mass, a link with two parents) are printed, and the drawing made."""
    loaded = result.loaded
    from ..rules import REGISTRY

    return loaded is None or not loaded.modelled or any(REGISTRY[d.code].urdfdom for d in result.errors)


def make_picture(console: Output, dot: str, output: Path, kind: str, timeout: float, inputs: list[str], dot_file: Path | None) -> None:
    """Render and write ``output``; on failure, say so and exit 2, with the DOT
    kept in ``dot_file`` (written now, beside ``output``, when not given)."""
    from ..report.drawing import RenderError, render

    try:
        picture = render(dot, kind, timeout)
    except RenderError as error:
        if dot_file is None:
            dot_file = output.with_suffix(".gv")
            write(console, dot_file, dot, inputs)
        console.err.file.write(f"urdfcli: cannot make {escape(str(output))}: {escape(str(error))}; the graph is in {escape(str(dot_file))}\n")
        raise SystemExit(Exit.CANNOT_RUN) from None
    write(console, output, picture, inputs)


def write(console: Output, path: Path, data: str | bytes, inputs: list[str]) -> None:
    try:
        write_atomic(path, data, inputs)
    except OutputError as error:
        raise fail(str(error)) from None
    console.out.file.write(f"Created file {escape(str(path))}\n")
