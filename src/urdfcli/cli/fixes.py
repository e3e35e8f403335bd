"""What `lint` and `check` share to fix: the options, the run through :func:`urdfcli.api.fix`,
the files written (or the diff printed) and the line that says what was fixed."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Annotated, NamedTuple

import typer

from ..report.escape import escape
from ..report.lines import plural
from .common import report_unreadable

if TYPE_CHECKING:
    from .. import api
    from ..diagnostics import Diagnostic
    from ..report.console import Output
    from ..session import Session

FixOption = Annotated[
    bool | None,
    typer.Option(
        "--fix/--no-fix",
        help="Apply the safe fixes in place, then report what remains (default: `fix` of the configuration's tool.urdfcli table).",
        show_default=False,
    ),
]
UnsafeFixesOption = Annotated[
    bool | None,
    typer.Option(
        "--unsafe-fixes/--no-unsafe-fixes",
        help="With --fix or --diff, also the fixes that change the robot (a tensor, a scale, a pose, a limit, the expansion, a generated URDF regenerated) "
        "(default: `unsafe-fixes` of the configuration's tool.urdfcli table).",
        show_default=False,
    ),
]
DiffOption = Annotated[
    bool,
    typer.Option(
        "--diff",
        help="Print the unified diff of the fixes (as `patch -p1` applies it; `patch -p1 -d ..` for a file above the working folder, as it says) "
        "and write nothing; exit 1 when there is something to fix.",
    ),
]
AddNoqaOption = Annotated[
    bool,
    typer.Option(
        "--add-noqa",
        help="Write a `urdfcli: noqa` comment, with its codes, on every element that still has a warning or an error; exit 1 when one remains that no comment silences.",
    ),
]


class Fixing(NamedTuple):
    """What the command line asked of the fixes."""

    fix: bool | None
    unsafe: bool | None
    diff: bool
    add_noqa: bool

    @property
    def applies(self) -> bool | None:
        """Whether the safe fixes apply (None: as the configuration says); --diff shows them."""
        return True if self.diff and self.fix is not False else self.fix


class Outcome(NamedTuple):
    fixed: api.Fixed
    changed: dict[str, tuple[bytes, bytes]]  # file -> (before, after), noqa comments included
    noqa: int  # comments written
    remaining: tuple[Diagnostic, ...] | None = None  # with --add-noqa: the warnings and errors no comment silences


def run(paths: list[str], session: Session, asked: Fixing, progress=None) -> Outcome:
    """Check and fix as the session's options say; with --add-noqa, the comments for what
    remains. Nothing is written here."""
    from .. import api  # (the library: imported when the command runs, not for --help)
    from ..project import fixing
    from ..read.document import STDIN
    from ..read.edits import EditError, apply

    if STDIN in paths and (asked.fix or asked.add_noqa) and not asked.diff:
        raise api.UsageError("--fix and --add-noqa cannot write standard input back: use --diff to see the fixes")
    fixed = api.fix(paths, session, progress)
    changed = dict(fixed.changed)
    noqa = 0
    remaining = None
    if asked.add_noqa:
        comments = fixing.noqa_edits((d for r in fixed.run.results for d in r.diagnostics), session.files)
        remaining = list(comments.left)
        for file, found in comments.edits.items():
            before = changed[file][0] if file in changed else session.files.read(file).data
            try:
                after = apply(session.files.read(file).data, [(e.start, e.end, e.text) for e in found])
            except EditError as error:
                fixed.failed.append(f"{file}: {error}")
                remaining += comments.silenced[file]
                continue
            changed[file] = (before, after)
            noqa += len(found)
        remaining = tuple(remaining)
    return Outcome(fixed, changed, noqa, remaining)


def write_files(outcome: Outcome) -> list[str]:
    """Write each changed file (atomically); the files that could not be written, and why."""
    from ..read.edits import write

    failed = []
    for file, (_, after) in outcome.changed.items():
        try:
            write(file, after)
        except OSError as error:
            failed.append(f"{file}: cannot write: {error.strerror}")
    return failed


def print_diff(outcome: Outcome, output: Output) -> None:
    """The unified diff of every change, on standard output; what it would fix, on standard
    error, and, when a file is outside the working folder, the folder its paths are relative to."""
    from ..read.edits import diff_folder, unified_diff

    out = output.out.file
    out.flush()
    binary = getattr(out, "buffer", None)  # the diff is the files' own bytes, whatever their encoding
    folder = diff_folder(outcome.changed)
    for file, (before, after) in outcome.changed.items():
        diff = unified_diff(file, before, after, folder)
        if binary is not None:
            binary.write(diff)
        else:
            out.write(diff.decode("utf-8", "replace"))
    (binary or out).flush()
    fixes = len(outcome.fixed.fixed)
    if outcome.changed:
        what = [_fixes(fixes)] if fixes else []
        what += [plural(outcome.noqa, "noqa comment")] if outcome.noqa else []
        output.err.file.write(f"would apply {' and '.join(what)} in {plural(len(outcome.changed), 'file')}\n")
        if folder != os.curdir:  # ('..' components only: nothing of an input)
            output.err.file.write(f"the paths are relative to {folder}: apply the diff with `patch -p1 -d {folder}`\n")
    elif outcome.fixed.run.results:  # (no file read: the message that says why is all)
        output.err.file.write("nothing to fix\n")


def summary(outcome: Outcome, asked: Fixing) -> str | None:
    """``3 fixed, 2 remaining`` after --fix; ``4 noqa comments written`` after --add-noqa;
    None when no file could be read (the message that says why is all)."""
    results = outcome.fixed.run.results
    if not results:
        return None
    if asked.add_noqa and (outcome.noqa or outcome.remaining):
        left = f", {len(outcome.remaining)} remaining" if outcome.remaining else ""
        return f"{plural(outcome.noqa, 'noqa comment')} written{left}"
    fixed = len(outcome.fixed.fixed)
    if not fixed and not asked.fix:
        return None
    return f"{fixed} fixed, {sum(len(r.diagnostics) for r in results)} remaining"


def report(outcome: Outcome, session: Session, output: Output, asked: Fixing, statistics: bool) -> None:
    """What `check` and `lint` print after fixing: the files that could not be read or fixed;
    then with --diff the diff alone, otherwise the files written, the report (or its
    --statistics) and the summary line, on standard output after a text report and on
    standard error after one a program reads."""
    from .. import report as reports
    from ..options import RuleSet

    found = outcome.fixed.run
    report_unreadable(output, found.unreadable)
    report_failed(output, outcome.fixed.failed)
    if asked.diff:
        print_diff(outcome, output)
        return
    report_failed(output, write_files(outcome))
    options = session.options
    view = "check" if options.rule_set is RuleSet.CHECK else "lint"
    if statistics:
        reports.statistics(found.results, output, view, output_format=options.format)
    else:
        reporter = reports.reporter(options.format)(output, session.files)
        (reporter.check if view == "check" else reporter.lint)(found.results)
    line = summary(outcome, asked)
    if line is not None and not output.quiet:
        (output.out if reports.resolve(options.format) == "text" else output.err).file.write(line + "\n")


def _fixes(count: int) -> str:
    return f"{count} fix{'' if count == 1 else 'es'}"


def report_failed(output: Output, failed: list[str]) -> None:
    for reason in failed:
        output.err.file.write(f"urdfcli: {escape(reason)}\n")
