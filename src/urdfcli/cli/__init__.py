"""The command line: one small module per subcommand, joined here."""

from __future__ import annotations

import os
import sys
from typing import Annotated

import typer

from .. import __version__
from .check import check
from .expand import expand
from .graph import graph
from .inertia import inertia
from .lint import lint
from .rules import rule, rules
from .tree import tree

app = typer.Typer(
    name="urdfcli",
    help="Check, expand, draw and lint URDF and xacro robot descriptions, without ROS.\n\n"
    "Exit codes: 0 no errors, 1 problems found, 2 could not run.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def _version(value: bool) -> None:
    if value:
        print(f"urdfcli {__version__}")
        raise typer.Exit()


@app.callback()
def _main(
    version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version and exit.")] = False,
) -> None:
    pass


app.command(name="expand")(expand)
app.command(name="check")(check)
app.command(name="tree")(tree)
app.command(name="graph")(graph)
app.command(name="inertia")(inertia)
app.command(name="lint")(lint)
app.command(name="rules")(rules)
app.command(name="rule")(rule)


def _planned(name: str, summary: str):
    def command(args: Annotated[list[str] | None, typer.Argument(hidden=True)] = None) -> None:
        from .common import fail

        raise fail(f"'{name}' is not available in this version yet")

    command.__doc__ = f"{summary} (not available yet)"
    return command


# Subcommands still to come; each entry goes when its module is registered above.
PLANNED = {
}
for _name, _summary in PLANNED.items():
    app.command(name=_name, context_settings={"allow_extra_args": True, "ignore_unknown_options": True})(_planned(_name, _summary))


def main() -> None:
    """Run the app; a usage error or an internal error is one line, never a bare traceback."""
    try:  # typer vendors click from 0.2x on
        from typer._click.exceptions import ClickException, UsageError
    except ImportError:
        from click.exceptions import ClickException, UsageError

    try:
        code = app(prog_name="urdfcli", standalone_mode=False)
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
