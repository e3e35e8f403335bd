"""The human format: a coloured tree on stdout, diagnostics and a summary on stderr."""

from __future__ import annotations

from rich.console import Console
from rich.text import Text

from ..diagnostics import Diagnostic
from ..loaded import Loaded
from . import plain_line, position
from .check_urdf import tree_lines

STYLES = {"error": "bold red", "warning": "yellow", "info": "cyan"}


def print_tree(console: Console, loaded: Loaded) -> None:
    for line in tree_lines(loaded):
        text = Text(line)
        if line.startswith("robot name is: "):
            text.stylize("bold", 15)
        elif line.startswith("root Link: "):
            text.stylize("bold green", 11, 11 + len(loaded.root or ""))
        elif "child(" in line:
            text.stylize("green", line.index("):  ") + 4)
        console.print(text, soft_wrap=True, highlight=False)


def print_diagnostic(console: Console, diagnostic: Diagnostic) -> None:
    if not console.is_terminal and not console.color_system:
        console.print(Text(plain_line(diagnostic)), soft_wrap=True, highlight=False)
    else:
        text = Text()
        text.append(position(diagnostic), style="bold")
        text.append(": ")
        text.append(diagnostic.code, style=STYLES[diagnostic.severity.value])
        text.append(f" {diagnostic.severity.value}: ", style=STYLES[diagnostic.severity.value])
        text.append(diagnostic.message)
        if diagnostic.location.expanded:
            text.append(" (line in the xacro-expanded document)", style="dim")
        console.print(text, soft_wrap=True, highlight=False)
    if diagnostic.hint:
        console.print(Text("    hint: " + diagnostic.hint, style="dim"), soft_wrap=True, highlight=False)
