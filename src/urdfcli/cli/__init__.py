"""The command line: one small module per subcommand, joined here."""

from __future__ import annotations

import functools
import importlib
import inspect
import os
import sys
from typing import Annotated

import typer

from .. import __version__
from ..folders import one_run

# Each subcommand: the module defining it and its function. A run imports only the
# module of the command it runs (help lists them all), so no command pays for the others.
COMMANDS = {
    "expand": ("expand", "expand"),
    "check": ("check", "check"),
    "tree": ("tree", "tree"),
    "graph": ("graph", "graph"),
    "inertia": ("inertia", "inertia"),
    "lint": ("lint", "lint"),
    "rules": ("rules", "rules"),
    "rule": ("rules", "rule"),
}


def _version(value: bool) -> None:
    if value:
        print(f"urdfcli {__version__}")
        raise typer.Exit()


def build_app(names=COMMANDS) -> typer.Typer:
    """The application with the named subcommands registered."""
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
    def _main(
        version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version and exit.")] = False,
    ) -> None:
        pass

    for name in names:
        module, function = COMMANDS[name]
        command = getattr(importlib.import_module(f".{module}", __name__), function)
        app.command(name=name, help=reflow(command.__doc__ or ""))(with_color_option(command))
    return app


def reflow(doc: str) -> str:
    """The help text with each paragraph on one line, for the help screen to wrap
    (it would keep the docstring's line breaks, and wrap the long lines again)."""
    return "\n\n".join(" ".join(paragraph.split()) for paragraph in inspect.cleandoc(doc).split("\n\n"))


def with_color_option(command):
    """``command`` with the ``--color`` option every command has (it only sets up the consoles)."""
    from .common import ColorOption

    @functools.wraps(command)
    def run(*args, color: str = "auto", **kwargs):
        return command(*args, **kwargs)

    signature = inspect.signature(command, eval_str=True)
    extra = inspect.Parameter("color", inspect.Parameter.KEYWORD_ONLY, default="auto", annotation=ColorOption)
    run.__signature__ = signature.replace(parameters=[*signature.parameters.values(), extra])
    run.__annotations__ = {**getattr(command, "__annotations__", {}), "color": ColorOption}
    return run


def __getattr__(name: str):
    if name == "app":  # the whole application, for those who import it
        return build_app()
    raise AttributeError(name)


def _app_for(argv: list[str]) -> typer.Typer:
    """Only the subcommand named first on the command line, when one is (else all, for help)."""
    first = next((a for a in argv if not a.startswith("-")), None)
    return build_app([first] if first in COMMANDS else COMMANDS)


def main() -> None:
    """Run the app; a usage error or an internal error is one line, never a bare traceback."""
    try:  # typer vendors click from 0.2x on
        from typer._click.exceptions import ClickException, NoArgsIsHelpError, UsageError
    except ImportError:
        from click.exceptions import ClickException, NoArgsIsHelpError, UsageError

    if os.environ.get("NO_COLOR") and (len(sys.argv) == 1 or {"-h", "--help"} & set(sys.argv)):
        from typer import rich_utils  # the help screen: no bold or dim either

        rich_utils.COLOR_SYSTEM = None
    try:
        with one_run():
            code = _app_for(sys.argv[1:])(prog_name="urdfcli", standalone_mode=False)
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
    except (KeyboardInterrupt, typer.Abort):
        sys.stderr.write("urdfcli: interrupted\n")
        sys.exit(130)
    except BrokenPipeError:
        sys.stderr.close()
        sys.exit(1)
    except Exception as error:  # noqa: BLE001
        if os.environ.get("URDFCLI_DEBUG"):
            raise
        name = " ".join(a for a in sys.argv[1:] if not a.startswith("-"))
        sys.stderr.write(
            f"urdfcli: internal error ({type(error).__name__}: {_one_line(str(error))}) on {name or 'the input'}; "
            "please report this bug with the input file (URDFCLI_DEBUG=1 shows the traceback)\n"
        )
        sys.exit(2)
    sys.exit(code if isinstance(code, int) else 0)


def _one_line(text: str) -> str:
    return " ".join(text.split())
