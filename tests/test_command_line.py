"""A plain command line is read without typer (urdfcli.cli.fast): the command gets
the values typer would give it, and whatever the fast reading does not take, typer reads."""

from __future__ import annotations

import functools
import inspect

import pytest

from urdfcli.cli import application
from urdfcli.cli.fast import parsed

ROBOT = "robot.urdf"

# Command lines the fast reading takes: every kind of option, each way of writing it.
PLAIN = [
    ["check", ROBOT],
    ["check", ROBOT, "other.urdf.xacro", "-", "arm:=left"],
    ["check", "-f", "json", "--strict", ROBOT],
    ["check", "--format=sarif", ROBOT, "--isolated", "--config", "tool.toml"],
    ["check", "-P", "pkg=dir", "--package-path", "more", "-P", "third", ROBOT],
    ["check", "--color", "never", ROBOT, "--color=always"],
    ["check", "--format", "text", "--format", "json", ROBOT],  # the last one counts
    ["check", "--format=", ROBOT],
    ["tree", ROBOT, "--max-depth", "0", "--from", "base_link", "-f", "json"],
    ["tree", ROBOT, "--no-joints", "--ascii", "-P", "dir", "--isolated", "--config", "a.toml"],
    ["expand", ROBOT, "-o", "out.urdf", "--deps"],
    ["graph", ROBOT, "out", "--rankdir", "lr", "--timeout", "2.5", "--compat", "--limits", "--inertial", "--collapse-fixed", "--force"],
    ["graph", ROBOT, "--rankdir=TB", "-f", "dot"],
    ["inertia", ROBOT, "--tolerance", "0.2", "--density", "1000", "--suggest"],
    ["inertia", ROBOT, "--xacro", "--format", "json", "-P", "dir", "--config", "a.toml", "--isolated"],
    ["lint", ROBOT, "--select", "I,D", "--ignore", "D010", "--extend-select", "S", "--extend-select", "X", "-j", "0", "--exit-zero"],
    ["lint", "urdf/", "--jobs", "2", "--format", "concise", "--config", "a.toml", "--isolated", "-P", "dir"],
    ["graph", ROBOT, "-o", "tree.pdf", "-P", "dir", "--config", "a.toml", "--isolated"],
    ["rules"],
    ["rules", "-f", "json"],
    ["rule", "D002"],
]

# Command lines left to typer: it reads them, or says what is wrong with them.
UNUSUAL = [
    [],
    ["--version"],
    ["check"],  # no input
    ["check", "-h"],
    ["check", ROBOT, "--help"],
    ["nonsense", ROBOT],
    ["check", "--bogus", ROBOT],
    ["check", "-fjson", ROBOT],  # short option and value run together
    ["check", "--strict=yes", ROBOT],
    ["check", "--format", "--strict", ROBOT],  # a value that reads like an option
    ["check", ROBOT, "--format"],  # no value
    ["check", "--", ROBOT],
    ["check", "--color", "purple", ROBOT],
    ["tree", ROBOT, "--max-depth", "-1"],
    ["tree", ROBOT, "--max-depth", "x"],
    ["graph", ROBOT, "--timeout", "0.5"],  # below the minimum
    ["graph", ROBOT, "--rankdir", "BT"],
    ["rules", "extra"],
    ["rule"],
    ["rule", "D002", "D003"],
]


def _options(argv: list[str]) -> set[str]:
    return {a.partition("=")[0] for a in argv if a.startswith("-") and a != "-"}


def typer_reading(argv: list[str], monkeypatch) -> dict:
    """The keyword arguments typer's application gives the command for ``argv``."""
    name = argv[0]
    command = application.command_function(name)
    given: dict = {}

    def spy(**kwargs):
        given.update(kwargs)

    spy.__signature__ = inspect.signature(command, eval_str=True)
    spy.__doc__ = command.__doc__
    monkeypatch.setattr(application, "command_function", lambda _: spy)
    for_typer = application.for_typer

    def recording(function):
        run = for_typer(function)

        @functools.wraps(run)
        def recorder(*args, color="auto", **kwargs):
            given["color"] = color
            return run(*args, color=color, **kwargs)

        return recorder

    monkeypatch.setattr(application, "for_typer", recording)
    application.build_app([name])(args=argv, prog_name="urdfcli", standalone_mode=False)
    return given


@pytest.mark.parametrize("argv", PLAIN, ids=" ".join)
def test_a_plain_command_line_gets_what_typer_gives(argv, monkeypatch):
    found = parsed(argv)
    assert found is not None
    fast = {**found.arguments, "color": found.color}
    assert fast == typer_reading(argv, monkeypatch)
    assert {type(v) for v in fast.values()} == {type(v) for v in typer_reading(argv, monkeypatch).values()}


@pytest.mark.parametrize("argv", UNUSUAL, ids=lambda a: " ".join(a) or "(nothing)")
def test_an_unusual_command_line_is_left_to_typer(argv):
    assert parsed(argv) is None


def test_every_option_is_read_by_some_plain_command_line():
    """The plain command lines above name every option of every command."""
    named = set().union(*(_options(argv) for argv in PLAIN))
    for name in application.COMMANDS:
        for parameter in inspect.signature(application.command_function(name), eval_str=True).parameters.values():
            spec = parameter.annotation.__metadata__[0]
            assert not spec.names or set(spec.names) & named, f"{name} {parameter.name}"
