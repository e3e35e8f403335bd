"""The options and arguments of the commands, declared without importing typer.

A command names them in its signature (``Annotated[str, Option("--format", ...)]``).
:func:`urdfcli.cli.application.build_app` turns them into typer's for the help screens and
for unusual command lines; :mod:`urdfcli.cli.fast` reads a plain command line
with the same declarations, so that most runs never import typer (a third of
urdfcli's start-up).
"""

from __future__ import annotations

from collections.abc import Callable

TYPE_CHECKING = False  # typing's flag, without typing: a run with a xacro input imports this first
if TYPE_CHECKING:
    from typing import Any


class BadValue(Exception):
    """An option's value the command refuses: typer's BadParameter, without typer."""

    def __init__(self, message: str, option: str):
        super().__init__(message)
        self.option = option


class Option:
    """An option: its names, as typer.Option takes them, and typer.Option's settings."""

    def __init__(self, *names: str, callback: Callable[[Any], Any] | None = None, **settings: Any):
        self.names = names
        self.callback = callback
        self.settings = settings

    def to_typer(self):
        import typer

        callback = self.callback
        if callback is not None:
            def checked(value):
                try:
                    return callback(value)
                except BadValue as error:
                    raise typer.BadParameter(str(error)) from None

            return typer.Option(*self.names, callback=checked, **self.settings)
        return typer.Option(*self.names, **self.settings)


class Argument(Option):
    """A positional argument, as typer.Argument takes it."""

    def __init__(self, **settings: Any):
        super().__init__(**settings)

    def to_typer(self):
        import typer

        return typer.Argument(**self.settings)
