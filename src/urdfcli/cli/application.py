"""The typer application: help screens, --version, and the command lines
:mod:`urdfcli.cli.fast` leaves to it. It reads the commands' own declarations
(:mod:`.options`), so both readers of a command line take the same options."""

from __future__ import annotations

import functools
import inspect
import typing
from typing import Annotated

from .. import __version__
from .commands import COMMANDS, command_function
from .options import BadValue, Option


def _version(value: bool) -> None:
    if value:
        import typer

        print(f"urdfcli {__version__}")
        raise typer.Exit()


def build_app(names=COMMANDS):
    """The typer application with the named subcommands registered."""
    import typer

    app = typer.Typer(
        name="urdfcli",
        help="Check, expand, draw and lint URDF and xacro robot descriptions, without ROS.\n\n"
        "Exit codes: 0 no errors, 1 problems found, 2 could not run.",
        no_args_is_help=True,
        add_completion=False,
        pretty_exceptions_enable=False,
        context_settings={"help_option_names": ["-h", "--help"]},
    )

    def _main(version: Annotated[bool, Option("--version", callback=_version, is_eager=True, help="Show the version and exit.")] = False) -> None:
        pass

    app.callback()(_typed(_main, inspect.signature(_main, eval_str=True)))

    for name in names:
        command = command_function(name)
        app.command(name=name, help=reflow(command.__doc__ or ""))(for_typer(command))
    return app


def reflow(doc: str) -> str:
    """The help text with each paragraph on one line, for the help screen to wrap
    (it would keep the docstring's line breaks, and wrap the long lines again)."""
    return "\n\n".join(" ".join(paragraph.split()) for paragraph in inspect.cleandoc(doc).split("\n\n"))


def for_typer(command):
    """``command`` as typer takes it: its options declared with typer's, the ``--color``
    option every command has (it only sets up the consoles) added, and a value the
    command refuses reported as typer reports a bad parameter."""
    import typer

    from .common import ColorOption

    @functools.wraps(command)
    def run(*args, color: str = "auto", **kwargs):
        try:
            return command(*args, **kwargs)
        except BadValue as error:
            raise typer.BadParameter(str(error), param_hint=error.option) from None

    signature = inspect.signature(command, eval_str=True)
    extra = inspect.Parameter("color", inspect.Parameter.KEYWORD_ONLY, default="auto", annotation=ColorOption)
    return _typed(run, signature.replace(parameters=[*signature.parameters.values(), extra]))


def _typed(function, signature: inspect.Signature):
    """``function`` with ``signature``, its options declared with typer's."""
    parameters = [p.replace(annotation=_typer_annotation(p.annotation)) for p in signature.parameters.values()]
    function.__signature__ = signature.replace(parameters=parameters)
    function.__annotations__ = {p.name: p.annotation for p in parameters}
    return function


def _typer_annotation(annotation):
    """``Annotated[T, Option(...)]`` as ``Annotated[T, typer.Option(...)]``."""
    base, *extras = typing.get_args(annotation) if typing.get_origin(annotation) is Annotated else (annotation,)
    if not extras:
        return annotation
    return Annotated[(base, *(e.to_typer() if isinstance(e, Option) else e for e in extras))]


def app_for(argv: list[str]):
    """Only the subcommand named first on the command line, when one is (else all, for help)."""
    first = next((a for a in argv if not a.startswith("-")), None)
    return build_app([first] if first in COMMANDS else COMMANDS)
