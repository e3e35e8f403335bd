"""A plain command line, read without typer.

Importing typer and building its application is a third of urdfcli's start-up.
Most command lines are plain: a subcommand, its options (``--name VALUE``,
``--name=VALUE``, ``-n VALUE``, flags) and its inputs. :func:`parsed` reads
those with the declarations of :mod:`.options`, and gives the command the
values typer would give it. Anything else (help, --version, an unknown option,
a value that does not convert or is out of range, ``--``, short options run
together, a value that starts with ``-``) is left to typer, which reads it the
same way or says what is wrong; a test compares the two readings.
"""

from __future__ import annotations

import typing
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from types import NoneType, UnionType
from typing import Annotated, Any, NamedTuple

from .commands import COMMANDS, command_function
from .options import Argument, Option

_CONVERTERS: dict[type, Callable[[str], Any]] = {str: str, int: int, float: float, Path: Path}


class Parsed(NamedTuple):
    """A command line read: the command's function and its keyword arguments."""

    command: Callable[..., Any]
    arguments: dict[str, Any]
    color: str

    def run(self) -> Any:
        from .common import set_color

        set_color(self.color)
        return self.command(**self.arguments)


class _Parameter(NamedTuple):
    name: str
    spec: Option
    kind: type  # the value's type: str, int, float, Path, bool or an Enum
    many: bool  # a list: repeated option, or every positional input
    default: Any


def parsed(argv: list[str]) -> Parsed | None:
    """The command and the values typer would give it, for a plain command line;
    None for any other, which typer reads instead."""
    from .common import COLOR_MODES, ColorOption

    if not argv or argv[0] not in COMMANDS:
        return None  # no subcommand first: help, --version, or a mistake
    command = command_function(argv[0])
    parameters = _parameters(command)
    if parameters is None:
        return None
    options = [p for p in parameters if not isinstance(p.spec, Argument)]
    options.append(_parameter("color", ColorOption, "auto"))  # every command's; Parsed.run sets it
    read = _read(argv[1:], options)
    if read is None:
        return None
    given, positional = read
    values = _values(options, given)
    if values is None:
        return None
    mode = values.pop("color")
    if mode not in COLOR_MODES or not _assign([p for p in parameters if isinstance(p.spec, Argument)], positional, values):
        return None  # typer says what is wrong
    return Parsed(command, values, mode)


def _read(tokens: list[str], options: list[_Parameter]) -> tuple[dict[str, list[str]], list[str]] | None:
    """The texts given for each option, and the positional inputs."""
    named = {name: p for p in options for name in p.spec.names}
    given: dict[str, list[str]] = {}
    positional: list[str] = []
    rest = iter(tokens)
    for token in rest:
        if token == "-" or not token.startswith("-"):
            positional.append(token)
            continue
        name, equals, value = token.partition("=") if token.startswith("--") else (token, "", "")
        parameter = named.get(name)
        if parameter is None:
            return None  # unknown: typer says so
        if parameter.kind is bool:
            if equals:
                return None
            value = ""
        elif not equals:
            value = next(rest, None)
            if value is None or (value.startswith("-") and value != "-"):
                return None  # missing, or typer's reading of a value like an option
        given.setdefault(parameter.name, []).append(value)
    return given, positional


def _values(options: list[_Parameter], given: dict[str, list[str]]) -> dict[str, Any] | None:
    """Each option's value: converted, the last one given (all, for a list), or its default."""
    values: dict[str, Any] = {}
    for parameter in options:
        texts = given.get(parameter.name)
        if texts is None:
            values[parameter.name] = parameter.default
        elif parameter.kind is bool:
            values[parameter.name] = True
        else:
            converted = [_converted(parameter, text) for text in texts]
            if any(v is None for v in converted):
                return None
            values[parameter.name] = converted if parameter.many else converted[-1]
    return values


def _parameters(command) -> list[_Parameter] | None:
    """The command's parameters, read from its code and annotations (inspect.signature's
    reading, without importing inspect: a tenth of a start)."""
    code = command.__code__
    names = code.co_varnames[: code.co_argcount + code.co_kwonlyargcount]
    positional = names[: code.co_argcount]
    defaults = dict(zip(reversed(positional), reversed(command.__defaults__ or ())))  # the last ones have defaults
    defaults.update(command.__kwdefaults__ or {})
    annotations = typing.get_type_hints(command, include_extras=True)
    found = []
    for name in names:
        made = _parameter(name, annotations.get(name), defaults.get(name))
        if made is None or made.spec.callback is not None:
            return None  # a callback is typer's to run
        found.append(made)
    return found


def _parameter(name: str, annotation, default) -> _Parameter | None:
    """A parameter declared ``Annotated[T, Option(...)]``, T one :func:`parsed` converts."""
    if typing.get_origin(annotation) is not Annotated:
        return None
    base, *extras = typing.get_args(annotation)
    spec = next((e for e in extras if isinstance(e, Option)), None)
    if spec is None:
        return None
    if isinstance(base, UnionType) or typing.get_origin(base) is typing.Union:
        kinds = [k for k in typing.get_args(base) if k is not NoneType]
        if len(kinds) != 1:
            return None
        base = kinds[0]
    many = typing.get_origin(base) is list
    kind = typing.get_args(base)[0] if many else base
    if not (kind in _CONVERTERS or kind is bool or _is_enum(kind)):
        return None
    parameter = _Parameter(name, spec, kind, many, default)
    if default is not None and not many and kind is not bool:  # typer converts a default as it converts a value
        parameter = parameter._replace(default=_converted(parameter, default.value if isinstance(default, Enum) else str(default)))
    return parameter


def _converted(parameter: _Parameter, text: str):
    """The value typer would give for ``text``; None when typer would refuse it."""
    kind = parameter.kind
    if _is_enum(kind):
        if parameter.spec.settings.get("case_sensitive", True):
            return next((m for m in kind if m.value == text), None)
        return next((m for m in kind if m.value.casefold() == text.casefold()), None)
    try:
        value = _CONVERTERS[kind](text)
    except ValueError:
        return None
    low = parameter.spec.settings.get("min")
    if low is not None and value < low:
        return None
    return value


def _is_enum(kind) -> bool:
    return isinstance(kind, type) and issubclass(kind, Enum)


def _assign(arguments: list[_Parameter], positional: list[str], values: dict[str, Any]) -> bool:
    """The positional inputs given to the command's arguments, as typer gives them."""
    if not arguments:
        return not positional
    if len(arguments) > 1:
        return False
    (argument,) = arguments
    if argument.many:
        if not positional:
            return False  # typer says what is missing
        values[argument.name] = positional
        return True
    if len(positional) != 1 or argument.kind is not str:
        return False
    values[argument.name] = positional[0]
    return True
