"""The command line: one small module per subcommand, joined here, and the one place
that ends the process.

Every command exits 0 when nothing is wrong, 1 when problems are found, 2 when
it cannot run; a usage mistake is one line naming the option, an internal error
one line asking for a bug report (``URDFCLI_DEBUG=1`` shows its traceback).
"""

from __future__ import annotations

import gc
import inspect
import os
import sys
from importlib import import_module

import typer

from ..version import __version__
from .interrupt import CtrlC

# Each command by name: its module and function, imported when the command is built (a run
# builds only the command it runs; the help, all of them).
COMMANDS = {
    "expand": ("expand", "expand"),
    "check": ("check", "check"),
    "tree": ("tree", "tree"),
    "graph": ("graph", "graph"),
    "inertia": ("inertia", "inertia"),
    "lint": ("lint", "lint"),
    "diff": ("diff", "diff"),
    "drift": ("drift", "drift"),
    "rules": ("rules", "rules"),
    "rule": ("rules", "rule"),
    "lsp": ("lsp", "lsp"),
}


def command(name: str):
    """The function of command ``name`` (its module imported now)."""
    module, function = COMMANDS[name]
    return getattr(import_module(f".{module}", __name__), function)


def _version(value: bool) -> None:
    if value:
        print(f"urdfcli {__version__}")
        raise typer.Exit()


def reflow(doc: str) -> str:
    """The help text with each paragraph on one line, for the help screen to wrap
    (it would keep the docstring's line breaks, and wrap the long lines again)."""
    return "\n\n".join(" ".join(paragraph.split()) for paragraph in inspect.cleandoc(doc).split("\n\n"))


def build_app(names: tuple[str, ...] = tuple(COMMANDS)) -> typer.Typer:
    """The command line with these commands (every one by default). typer works out each
    command's options from its signature every time the program runs: a run of one
    command is given that command alone."""
    app = typer.Typer(
        name="urdfcli",
        help="Check, expand, draw and lint URDF and xacro robot descriptions, without ROS.\n\n"
        "Exit codes: 0 no errors, 1 problems found, 2 could not run.",
        no_args_is_help=True,
        add_completion=False,
        pretty_exceptions_enable=False,
        context_settings={"help_option_names": ["-h", "--help"]},
    )

    @app.callback()
    def main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True, help="Show the version and exit.")) -> None:
        pass

    for name in names:
        function = command(name)
        app.command(name=name, help=reflow(function.__doc__ or ""))(function)
    return app


def __getattr__(name: str):
    """``app``: the command line with every command, built when first asked for."""
    if name != "app":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return build_app()


def program_for(argv: list[str]) -> typer.Typer:
    """The command line a run needs: the command it names alone, none for ``--version``
    (which answers before any command), else every command (the help lists them all)."""
    if argv and argv[0] in COMMANDS:
        return build_app((argv[0],))
    return build_app(() if argv[:1] == ["--version"] else tuple(COMMANDS))


def click_exceptions():
    """click's exceptions: typer vendors click from 0.2x on. (Here, not in .common: a Ctrl-C
    while main imports .common, before its handler is set, would end in a traceback.)"""
    try:
        from typer._click import exceptions
    except ImportError:
        from click import exceptions
    return exceptions


def main(argv: list[str] | None = None) -> int:
    """Run a command line; the exit code. Usage and internal errors are one line each."""
    errors = click_exceptions()
    ClickException, NoArgsIsHelpError, UsageError = errors.ClickException, errors.NoArgsIsHelpError, errors.UsageError

    argv = sys.argv[1:] if argv is None else argv
    if os.environ.get("NO_COLOR") and (not argv or {"-h", "--help"} & set(argv)):
        from typer import rich_utils  # the help screen: no bold or dim either

        rich_utils.COLOR_SYSTEM = None
    ctrl_c = CtrlC.install()
    try:
        code = program_for(argv)(args=argv, prog_name="urdfcli", standalone_mode=False)
        if code == INTERRUPTED or ctrl_c.pressed:  # typer's answer to Ctrl-C; or one a library swallowed
            sys.stderr.write("urdfcli: interrupted\n")
            return INTERRUPTED
        return code if isinstance(code, int) else 0
    except SystemExit as done:
        return done.code if isinstance(done.code, int) else 0
    except NoArgsIsHelpError as error:  # the help is printed already
        if error.format_message().strip():
            sys.stderr.write(error.format_message().rstrip("\n") + "\n")
        return error.exit_code
    except UsageError as error:
        command = error.ctx.command_path if error.ctx is not None else "urdfcli"
        sys.stderr.write(f"urdfcli: {_one_line(error.format_message())} (see '{command} -h')\n")
        return error.exit_code
    except ClickException as error:
        sys.stderr.write(f"urdfcli: {_one_line(error.format_message())}\n")
        return error.exit_code
    except (KeyboardInterrupt, typer.Abort):
        sys.stderr.write("urdfcli: interrupted\n")
        return INTERRUPTED
    except BrokenPipeError:
        return 1
    except Exception as error:  # noqa: BLE001
        if ctrl_c.pressed:  # what Ctrl-C caused once a library swallowed it: a -j worker it ended (BrokenProcessPool)
            sys.stderr.write("urdfcli: interrupted\n")
            return INTERRUPTED
        if os.environ.get("URDFCLI_DEBUG"):
            raise
        name = " ".join(a for a in argv if not a.startswith("-"))
        sys.stderr.write(
            f"urdfcli: internal error ({type(error).__name__}: {_one_line(str(error))}) on {name or 'the input'}; "
            "please report this bug with the input file (URDFCLI_DEBUG=1 shows the traceback)\n"
        )
        return 2
    finally:
        ctrl_c.uninstall()


INTERRUPTED = 130  # the shells' exit code for a program stopped by Ctrl-C


def run() -> None:
    """The ``urdfcli`` program."""
    tune_garbage_collector()
    code = main()
    try:
        sys.stdout.flush()
    except (BrokenPipeError, ValueError):  # a reader that stopped early
        code = code or 1
        _quiet_stdout()
    sys.exit(code)


def tune_garbage_collector() -> None:
    """For a program that reads models and ends (not for a library caller): the
    modules imported at start are set aside from the collector's scans, and it
    collects less often. A model is many small objects without cycles, which the
    collector would otherwise walk over and over while they are built: 15 % of
    `check` on 69 published models, 20 % on a model of 100,000 links."""
    gc.freeze()
    gc.set_threshold(100_000, 50, 100)


def _quiet_stdout() -> None:
    """After a broken pipe, point standard output at nothing, so that Python's own
    flush at exit does not print an error."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())


def _one_line(text: str) -> str:
    return " ".join(text.split())
