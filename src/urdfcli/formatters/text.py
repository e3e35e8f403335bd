"""The human format: a coloured tree on stdout, diagnostics and a summary on stderr."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic
from ..document import source_line
from ..escape import escape
from . import call_phrase, plain_line, position

if TYPE_CHECKING:
    from ..loaded import Loaded
    from rich.console import Console

STYLES = {"error": "bold red", "warning": "yellow", "info": "cyan"}


def plain(console: Console) -> bool:
    """Without colour there is nothing for rich to do, and it is slow on many lines."""
    return not console.is_terminal and not console.color_system


def print_tree(console: Console, loaded: Loaded) -> None:
    from .check_urdf import tree_lines  # the kinematic tree's modules: `expand` prints none

    lines = tree_lines(loaded)
    if plain(console):
        console.file.writelines(line + "\n" for line in lines)  # line by line: a deep tree's text is large
        return
    from rich.text import Text  # only to style: plain output never imports rich

    for line in lines:
        text = Text(line)
        if line.startswith("robot name is: "):
            text.stylize("bold", 15)
        elif line.startswith("root Link: "):
            text.stylize("bold green", 11, 11 + len(escape(loaded.root or "")))
        elif "child(" in line:
            text.stylize("green", line.index("):  ") + 4)
        console.print(text, soft_wrap=True, highlight=False)


def print_diagnostic(console: Console, diagnostic: Diagnostic, excerpt: bool = False) -> None:
    """``PATH:LINE:COL: CODE severity: message``, its hint, and (with ``excerpt``) the source line."""
    details = trace_notes(diagnostic) + (["    hint: " + escape(diagnostic.hint)] if diagnostic.hint else []) + (excerpt_lines(diagnostic) if excerpt else [])
    if plain(console):
        console.file.write("".join(line + "\n" for line in [plain_line(diagnostic), *details]))
        return
    from rich.text import Text

    text = Text()
    text.append(escape(position(diagnostic)), style="bold")
    text.append(": ")
    text.append(diagnostic.code, style=STYLES[diagnostic.severity.value])
    text.append(f" {diagnostic.severity.value}: ", style=STYLES[diagnostic.severity.value])
    text.append(escape(diagnostic.message))
    if diagnostic.location.expanded:
        text.append(" (line in the xacro-expanded document)", style="dim")
    console.print(text, soft_wrap=True, highlight=False)
    for line in details:
        console.print(Text(line, style="dim"), soft_wrap=True, highlight=False)


TRACE_LEVELS = 3


def trace_notes(diagnostic: Diagnostic, levels: int = TRACE_LEVELS) -> list[str]:
    """One ``note:`` line per macro call that made the element, innermost first."""
    trace = diagnostic.location.trace
    notes = [escape(f"    note: {call_phrase(call)}") for call in trace[:levels]]
    if len(trace) > levels:
        notes.append(f"    note: ... and {len(trace) - levels} more macro call{'s' if len(trace) - levels > 1 else ''}")
    return notes


def excerpt_lines(diagnostic: Diagnostic, width: int = 160) -> list[str]:
    """The diagnostic's source line, numbered, with a caret under its column."""
    location = diagnostic.location
    if location.expanded or not location.line:
        return []
    text = source_line(location.file, location.line)
    if text is None:
        return []
    text = text.replace("\t", " ").rstrip()
    safe = escape(text)  # the caret moves right by what the escapes before it add
    shown = safe if len(safe) <= width else safe[: width - 3] + "..."
    width = max(4, len(str(location.line)))
    lines = [f"  {location.line:>{width}} | {shown}"]
    caret = len(escape(text[: location.column - 1])) if location.column else None
    if caret is not None and caret <= len(shown):
        lines.append(f"  {'':>{width}} | {' ' * caret}^")
    return lines
