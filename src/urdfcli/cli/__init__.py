"""The command line: one small module per subcommand, joined here.

A plain command line (a subcommand, its options and its inputs) is read by
:mod:`.fast` without importing typer; help, --version and anything unusual go
through the typer application (:mod:`.application`), which reads the same declarations
and says what is wrong with a command line. This module imports little: a run
with a xacro input starts xacro's worker before anything else (see :func:`main`).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import sys

from ..folders import one_run
from .options import BadValue


def __getattr__(name: str):
    if name == "app":  # the whole application, for those who import it
        from .application import build_app

        return build_app()
    raise AttributeError(name)


def main() -> None:
    """Run a command line; a usage error or an internal error is one line, never a bare traceback."""
    argv = sys.argv[1:]
    xacro = contextlib.nullcontext()
    if argv[:1] != ["rules"] and any(argument.endswith(".xacro") for argument in argv[1:]):
        from ..expanded import started

        xacro = started(*_first_expansion(argv[1:]))  # xacro's worker expands while this process imports the rest
    try:
        with one_run(), xacro:
            from .fast import parsed  # (after the worker's start: it needs none of it)

            found = parsed(argv)
            code = found.run() if found is not None else _typer_main(argv)
    except BadValue as error:  # as typer says it, for a command line read without typer
        sys.stderr.write(f"urdfcli: Invalid value for {error.option}: {_one_line(str(error))} (see 'urdfcli {argv[0]} -h')\n")
        sys.exit(2)
    except KeyboardInterrupt:
        sys.stderr.write("urdfcli: interrupted\n")
        sys.exit(130)
    except BrokenPipeError:
        sys.stderr.close()
        sys.exit(1)
    except Exception as error:  # noqa: BLE001
        if os.environ.get("URDFCLI_DEBUG"):
            raise
        name = " ".join(a for a in argv if not a.startswith("-"))
        sys.stderr.write(
            f"urdfcli: internal error ({type(error).__name__}: {_one_line(str(error))}) on {name or 'the input'}; "
            "please report this bug with the input file (URDFCLI_DEBUG=1 shows the traceback)\n"
        )
        sys.exit(2)
    sys.exit(code if isinstance(code, int) else 0)


def _first_expansion(arguments: list[str]) -> tuple[str | None, dict[str, str]]:
    """The first xacro input of a command line and its NAME:=VALUE arguments, for the
    worker to expand ahead; no input when package paths are given (they are read
    with the options)."""
    if any(a in ("-P", "--package-path") or a.startswith(("-P", "--package-path=")) for a in arguments):
        return None, {}
    mappings = dict(a.partition(":=")[::2] for a in arguments if ":=" in a)
    return next(a for a in arguments if a.endswith(".xacro")), mappings


def run() -> None:
    """The ``urdfcli`` program: :func:`main`, then an end without Python's finalization.

    Freeing every module and object at exit took 2 to 5 ms of a 55 to 90 ms run on
    a small file. Standard output and error are flushed and the exit handlers (the
    xacro worker's stop) run first; nothing else urdfcli opens outlives its ``with``.
    """
    try:
        main()
        code = 0
    except SystemExit as done:
        if done.code is not None and not isinstance(done.code, int):
            raise  # a message for Python to print as it ends
        code = done.code or 0
    try:
        sys.stdout.flush()
    except (BrokenPipeError, ValueError):  # a reader that stopped early, as main() reports it
        code = code or 1
    with contextlib.suppress(OSError, ValueError):  # main() closes it after a broken pipe
        sys.stderr.flush()
    run_exit_handlers = getattr(atexit, "_run_exitfuncs", None)
    if run_exit_handlers is None:  # not CPython: let the interpreter end as usual
        sys.exit(code)
    run_exit_handlers()
    os._exit(code)


def _typer_main(argv: list[str]):
    """The command line read by typer: help, --version, and what :mod:`.fast` leaves to it."""
    import typer

    from .application import app_for

    try:  # typer vendors click from 0.2x on
        from typer._click.exceptions import ClickException, NoArgsIsHelpError, UsageError
    except ImportError:
        from click.exceptions import ClickException, NoArgsIsHelpError, UsageError

    if os.environ.get("NO_COLOR") and (not argv or {"-h", "--help"} & set(argv)):
        from typer import rich_utils  # the help screen: no bold or dim either

        rich_utils.COLOR_SYSTEM = None
    try:
        return app_for(argv)(args=argv, prog_name="urdfcli", standalone_mode=False)
    except NoArgsIsHelpError as error:  # the help is printed already (rich prints it, the message is empty)
        if error.format_message().strip():
            sys.stderr.write(error.format_message().rstrip("\n") + "\n")
        sys.exit(error.exit_code)
    except UsageError as error:
        command = error.ctx.command_path if error.ctx is not None else "urdfcli"
        sys.stderr.write(f"urdfcli: {_one_line(error.format_message())} (see '{command} -h')\n")
        sys.exit(error.exit_code)
    except ClickException as error:
        sys.stderr.write(f"urdfcli: {_one_line(error.format_message())}\n")
        sys.exit(error.exit_code)
    except typer.Abort:
        raise KeyboardInterrupt from None


def _one_line(text: str) -> str:
    return " ".join(text.split())
