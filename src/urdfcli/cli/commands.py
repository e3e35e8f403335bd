"""The subcommands, each named with the module that defines it and its function.

A run imports only the module of the command it runs (help lists them all), so no
command pays for the others. Both readers of a command line take them from here:
typer's application (:mod:`urdfcli.cli`) and the plain reader (:mod:`.fast`).
"""

from __future__ import annotations

import importlib

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


def command_function(name: str):
    """The function of the subcommand ``name`` (its module imported now)."""
    module, function = COMMANDS[name]
    return getattr(importlib.import_module(f".{module}", __package__), function)
