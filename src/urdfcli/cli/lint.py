"""`urdfcli lint`: every documented rule, with project configuration and suppressions."""

from __future__ import annotations

import contextlib
import time
from pathlib import Path
from typing import Annotated

from ..diagnostics import Severity
from ..formatters import resolve
from ..linter import Job, Linted, run_job
from ..load import STDIN
from ..packages import SKIP_DIRS, PackageError
from ..workspace import Target, assemble, plan
from ..formatters.emit import emit
from .common import LIBRARIES_HELP, ConfigOption, Exit, IsolatedOption, PackagePathOption, configurations, fail, split_inputs, stderr, stdout
from .options import Argument, Option

LINT_FORMATS = ("auto", "text", "concise", "json", "sarif", "github")
MODEL_SUFFIXES = (".urdf", ".urdf.xacro")
PROGRESS_AFTER = 1.0  # seconds: a run this long shows a progress bar on a terminal



def lint(
    inputs: Annotated[
        list[str],
        Argument(
            metavar="PATH... [NAME:=VALUE]...",
            help="Files, or folders to search for *.urdf and *.urdf.xacro ('-' reads standard input); NAME:=VALUE sets a xacro argument.",
            show_default=False,
        ),
    ],
    output_format: Annotated[str, Option("--format", "-f", metavar="FORMAT", help="auto (text, or github under GitHub Actions), text, concise, json, sarif or github.", case_sensitive=False)] = "auto",
    select: Annotated[list[str] | None, Option("--select", metavar="CODES", help="Only these rule codes or prefixes (comma-separated; replaces the configuration's select). ALL selects every rule.", show_default=False)] = None,
    ignore: Annotated[list[str] | None, Option("--ignore", metavar="CODES", help="Also ignore these codes or prefixes.", show_default=False)] = None,
    extend_select: Annotated[list[str] | None, Option("--extend-select", metavar="CODES", help="Also select these codes or prefixes (e.g. S for the style rules).", show_default=False)] = None,
    config: ConfigOption = None,
    isolated: IsolatedOption = False,
    exit_zero: Annotated[bool, Option("--exit-zero", help="Exit 0 even when problems remain (2 still means it could not run).")] = False,
    jobs: Annotated[int, Option("--jobs", "-j", min=0, metavar="N", help="Lint files in N processes (0: one per CPU); the output order does not change.")] = 1,
    package_path: PackagePathOption = None,
) -> None:
    """Lint URDF/xacro files against documented, configurable rules.

    Configuration comes from the tool.urdfcli table of the nearest
    pyproject.toml, or from urdfcli.toml; `urdfcli rules` lists the rules. Exit 0 when nothing remains,
    1 when a warning or error remains, 2 when it cannot run.
    """
    if output_format not in LINT_FORMATS:
        raise fail(f"unknown format {output_format!r}; choose from {', '.join(LINT_FORMATS)}")
    paths, mappings = split_inputs(inputs)
    files = expand_paths(paths)
    config_for = configurations(config, isolated, {"select": select, "ignore": ignore, "extend_select": extend_select})
    extra = tuple(package_path or ())
    try:
        entries = plan(files, config_for, extra)
    except PackageError as error:
        raise fail(str(error)) from None

    def job(target: Target) -> Job:
        return Job.of(target, config_for(target.path), extra, mappings)

    targets = list(dict.fromkeys(t for entry in entries for t in entry.targets))
    done = dict(zip(targets, run([job(t) for t in targets], jobs)))

    def outcome(target: Target) -> Linted | str:
        if target not in done:  # a library no model includes, expanded on its own
            done[target] = run_job(job(target))
        return done[target]

    results, unreadable = assemble(entries, outcome, lambda linted: linted.includes)
    for reason in unreadable:
        stderr.print(f"urdfcli: {reason}", markup=False)
    emit(results, resolve(output_format), stdout, stderr, tree=False)
    if unreadable:
        raise SystemExit(Exit.CANNOT_RUN)
    if not exit_zero and any(d.severity.rank >= Severity.WARNING.rank for r in results for d in r.diagnostics):
        raise SystemExit(Exit.PROBLEMS)


def expand_paths(paths: list[str]) -> list[str]:
    """Files as given; folders searched (sorted) for *.urdf and *.urdf.xacro."""
    files: list[str] = []
    for path in paths:
        folder = Path(path)
        if path != STDIN and folder.is_dir():
            found = models_in(folder)
            if not found:
                raise fail(f"{path}: no *.urdf or *.urdf.xacro file in this folder")
            files.extend(str(f) for f in found)
        else:
            files.append(path)
    return files


def models_in(folder: Path) -> list[Path]:
    """Robot models below a folder, skipping hidden and build folders. Plain *.xacro
    files are macro libraries: they are linted through the models that include them."""
    found = []
    stack = [folder]
    while stack:
        current = stack.pop()
        try:
            entries = sorted(current.iterdir())
        except OSError:
            continue
        for entry in entries:
            if entry.is_dir():
                if not entry.name.startswith(".") and entry.name not in SKIP_DIRS:
                    stack.append(entry)
            elif entry.name.endswith(MODEL_SUFFIXES):
                found.append(entry)
    return sorted(found)


def run(work: list[Job], jobs: int) -> list:
    """Each job's result, in order; in processes when asked, with a progress bar on long runs."""
    parallel = (jobs == 0 or jobs > 1) and len(work) > 1 and not any(job.path == STDIN for job in work)
    if parallel:
        from concurrent.futures import ProcessPoolExecutor  # only parallel runs pay for it

        pool = ProcessPoolExecutor(max_workers=jobs or None)
    else:
        pool = contextlib.nullcontext()
    outcomes = []
    start, progress, task = time.monotonic(), None, None
    with pool:
        for done, outcome in enumerate(pool.map(run_job, work) if parallel else map(run_job, work), 1):
            outcomes.append(outcome)
            if progress is None and stderr.is_terminal and done < len(work) and time.monotonic() - start > PROGRESS_AFTER:
                from rich.progress import Progress

                progress = Progress(console=stderr, transient=True)
                progress.start()
                task = progress.add_task("linting", total=len(work))
            if progress is not None:
                progress.update(task, completed=done)
    if progress is not None:
        progress.stop()
    return outcomes


lint.__doc__ += "\n\n    " + LIBRARIES_HELP
