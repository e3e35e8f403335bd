"""Where a command writes: standard output and standard error, each a rich console.

Styling (colour, bold, dim) is on for a terminal with ``--color auto``, always
with ``always``, never with ``never`` or when ``NO_COLOR`` is set. What is
written is a line of ``(text, style)`` pieces: :func:`write` prints it styled,
or joins the pieces and writes them plain when there is nothing to style (rich
renders line by line, slowly on a tree of 100,000 links).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import TextIO

from rich.console import Console
from rich.text import Text

COLOR_MODES = ("auto", "always", "never")
Line = list[tuple[str, str]]  # pieces of text, each with a rich style ("" for none)


def console(mode: str = "auto", stream: TextIO | None = None, stderr: bool = False) -> Console:
    """A console writing to ``stream`` (standard output or error by default)."""
    never = mode == "never" or (mode == "auto" and os.environ.get("NO_COLOR"))
    return Console(
        file=stream, stderr=stderr, highlight=False, soft_wrap=True,
        color_system=None if never else "auto", force_terminal=True if mode == "always" else None,
    )


class Output:
    """The two consoles of a command: its results, and its diagnostics and progress.
    ``quiet``: only the diagnostics and the summary (no tree, notes or progress)."""

    def __init__(self, out: Console, err: Console, quiet: bool = False) -> None:
        self.out = out
        self.err = err
        self.quiet = quiet

    @classmethod
    def standard(cls, mode: str = "auto", quiet: bool = False) -> Output:
        """Standard output and error, styled as ``--color`` says."""
        return cls(console(mode), console(mode, stderr=True), quiet)


def styled(target: Console) -> bool:
    """Whether the console shows styles: a terminal, or colour forced."""
    return target.is_terminal or target.color_system is not None


def write(target: Console, lines: Iterable[Line]) -> None:
    """Each line, styled when the console shows styles, else as plain text."""
    if styled(target):
        for line in lines:
            target.print(Text.assemble(*line), soft_wrap=True, highlight=False)
        return
    target.file.writelines("".join(text for text, _ in line) + "\n" for line in lines)


def plain(text: str, style: str = "") -> Line:
    """A line of one piece."""
    return [(text, style)]


def flush(target: Console) -> None:
    try:
        target.file.flush()
    except (OSError, ValueError):  # closed, or a reader that stopped early: the exit code says so
        pass


__all__ = ["COLOR_MODES", "Line", "Output", "console", "flush", "plain", "styled", "write"]
