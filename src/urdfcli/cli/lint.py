"""`urdfcli lint`: every documented rule, with project configuration and suppressions."""

from __future__ import annotations

import time
from typing import Annotated

import typer

from ..diagnostics import Severity
from ..options import Options, RuleSet
from ..report.console import Output, rich_console
from ..report.escape import escape
from . import fixes
from .common import (
    LIBRARIES_HELP,
    ColorOption,
    ConfigOption,
    Exit,
    IsolatedOption,
    QuietOption,
    SrdfsOption,
    GitDeletionsOption,
    PackagePathOption,
    NoInfoOption,
    StatisticsOption,
    TargetOption,
    UrdfOption,
    changed_inputs,
    nothing_to_check,
    choose,
    format_option,
    session_for,
)
from .interrupt import CtrlC
from .fixes import AddNoqaOption, DiffOption, FixOption, UnsafeFixesOption

FORMATS = ("auto", "text", "concise", "json", "sarif", "github")
PROGRESS_AFTER = 1.0  # seconds: a run this long shows a progress bar on a terminal


def lint(
    ctx: typer.Context,
    inputs: Annotated[
        list[str] | None,
        typer.Argument(
            metavar="PATH... [NAME:=VALUE]...",
            help="Files, or folders to search for *.urdf and *.urdf.xacro ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
            show_default=False,
        ),
    ] = None,
    output_format: format_option("auto (text, or github under GitHub Actions), text, concise, json, sarif or github.") = "auto",
    select: Annotated[list[str] | None, typer.Option("--select", metavar="CODES", help="Only these rule codes or prefixes (comma-separated; replaces the configuration's select). ALL selects every rule.", show_default=False)] = None,
    ignore: Annotated[list[str] | None, typer.Option("--ignore", metavar="CODES", help="Also ignore these codes or prefixes.", show_default=False)] = None,
    extend_select: Annotated[list[str] | None, typer.Option("--extend-select", metavar="CODES", help="Also select these codes or prefixes (e.g. S for the style rules).", show_default=False)] = None,
    target: TargetOption = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    exit_zero: Annotated[bool, typer.Option("--exit-zero", help="Exit 0 even when problems remain (2 still means it could not run).")] = False,
    exit_non_zero_on_fix: Annotated[bool, typer.Option("--exit-non-zero-on-fix", help="Exit 1 when --fix changed a file, even when nothing remains (a pre-commit hook).")] = False,
    jobs: Annotated[int, typer.Option("--jobs", "-j", min=0, metavar="N", help="Lint files in N processes (0: one per CPU); the output order does not change.")] = 1,
    package_path: PackagePathOption = None,
    urdf: UrdfOption = None,
    srdfs: SrdfsOption = False,
    git_deletions: GitDeletionsOption = False,
    fix: FixOption = None,
    unsafe_fixes: UnsafeFixesOption = None,
    diff: DiffOption = False,
    add_noqa: AddNoqaOption = False,
    quiet: QuietOption = False,
    no_info: NoInfoOption = None,
    statistics: StatisticsOption = False,
    color: ColorOption = "auto",
) -> None:
    """Lint URDF/xacro files against documented, configurable rules.

    Configuration comes from the tool.urdfcli table of the nearest
    pyproject.toml, or from urdfcli.toml; `urdfcli rules` lists the rules. Exit 0 when nothing remains,
    1 when a warning or error remains, 2 when it cannot run.

    With --fix, the safe fixes are written first (with --unsafe-fixes, all of them), and what
    remains sets the exit status; --diff prints them, writes nothing, and exits 1 when there is
    something to fix.
    """
    paths, mappings, deleted = changed_inputs(ctx, inputs, git_deletions)
    output_format = choose(output_format, FORMATS)
    if nothing_to_check(paths, deleted, output_format):
        return
    from .. import api  # (the library: imported when the command runs, not for --help)

    asked = fixes.Fixing(fix, unsafe_fixes, diff, add_noqa)
    options = Options(
        RuleSet.LINT, tuple(mappings.items()), tuple(package_path or ()), config, isolated, tuple(select or ()), tuple(ignore or ()),
        tuple(extend_select or ()), tuple(target or ()), jobs=jobs, format=output_format, fix=asked.applies, unsafe_fixes=unsafe_fixes,
        urdf=urdf, srdfs=srdfs, deleted=deleted, show_info=None if no_info is None else not no_info,
    )
    output = Output.standard(color, quiet)
    with session_for(options) as session:
        files = api.find_models(paths, session)
        with Progress(output) as progress:
            outcome = fixes.run(files, session, asked, progress=progress.update)
        found = outcome.fixed.run
        fixes.report(outcome, session, output, asked, statistics)
    if found.unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    if diff:
        raise SystemExit(Exit.PROBLEMS if outcome.changed and not exit_zero else Exit.OK)
    if exit_non_zero_on_fix and outcome.changed:
        raise SystemExit(Exit.PROBLEMS)
    remaining = outcome.remaining if add_noqa else [d for r in found.results for d in r.diagnostics]  # (--add-noqa: what no comment silences)
    if not exit_zero and any(d.severity.rank >= Severity.WARNING.rank for d in remaining):
        raise SystemExit(Exit.PROBLEMS)


class Progress:
    """A progress bar on standard error, drawn by rich once a run has taken more than
    PROGRESS_AFTER seconds, and only when standard error is a terminal: files done
    out of all, and the file being read, in the terminal's own colour. It is
    removed (the cursor shown again) before the report, however the run ends."""

    def __init__(self, output: Output) -> None:
        self.console = output.err
        self.quiet = output.quiet
        self.start = time.monotonic()
        self.bar = None
        self.task = None

    def update(self, done: int, total: int, current: str = "") -> None:
        CtrlC.stop_if_pressed()
        if self.bar is None:
            if self.quiet or not self.console.is_terminal or done >= total or time.monotonic() - self.start < PROGRESS_AFTER:
                return
            from rich.progress import BarColumn, MofNCompleteColumn, Progress as Bar, TextColumn

            self.bar = Bar(
                TextColumn("linting"), BarColumn(bar_width=24, style="dim", complete_style="default", finished_style="default"),
                MofNCompleteColumn(), TextColumn("{task.fields[current]}", style="dim"),
                console=rich_console(self.console), transient=True,
            )
            self.bar.start()
            self.task = self.bar.add_task("linting", total=total, current="")
        width = max(10, rich_console(self.console).width - 50)
        shown = current if len(current) <= width else "..." + current[-(width - 3):]
        self.bar.update(self.task, completed=done, total=total, current=escape(shown))

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc) -> None:
        if self.bar is not None:
            self.bar.stop()


lint.__doc__ += "\n\n    " + LIBRARIES_HELP
