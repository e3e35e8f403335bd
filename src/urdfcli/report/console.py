"""Where a command writes: standard output and standard error.

Styling (colour, bold, dim) is on for a terminal with ``--color auto``, always
with ``always``, never with ``never`` or when ``NO_COLOR`` is set. What is
written is a line of ``(text, style)`` pieces: :func:`write` prints it styled
through a rich console, or joins the pieces and writes them plain when there is
nothing to style (rich renders line by line, slowly on a tree of 100,000 links).
A :class:`Stream` makes its rich console only when it may be a terminal (or
colour is forced): output to a file or a pipe never needs rich.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable
from functools import cached_property
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from rich.console import Console

COLOR_MODES = ("auto", "always", "never")
Line = list[tuple[str, str]]  # pieces of text, each with a rich style ("" for none)
_TERMINAL_SAYS = ("FORCE_COLOR", "TTY_COMPATIBLE")  # what makes rich take a stream for a terminal, or not


def console(mode: str = "auto", stream: TextIO | None = None, stderr: bool = False) -> Console:
    """A rich console writing to ``stream`` (standard output or error by default)."""
    from rich.console import Console

    never = mode == "never" or (mode == "auto" and os.environ.get("NO_COLOR"))
    return Console(
        file=stream, stderr=stderr, highlight=False, soft_wrap=True,
        color_system=None if never else "auto", force_terminal=True if mode == "always" else None,
    )


class Stream:
    """Standard output or error (or ``stream``) with ``--color`` ``mode``: its file, and
    the rich console that styles it, made the first time it is needed."""

    def __init__(self, mode: str = "auto", stream: TextIO | None = None, stderr: bool = False) -> None:
        self.mode = mode
        self.stream = stream
        self.stderr = stderr

    @property
    def file(self) -> TextIO:
        if self.stream is not None:
            return self.stream
        return sys.stderr if self.stderr else sys.stdout

    @cached_property
    def console(self) -> Console:
        return console(self.mode, self.stream, self.stderr)

    @cached_property
    def _may_be_terminal(self) -> bool:
        """Whether rich may take the stream for a terminal (else it surely does not)."""
        if self.mode == "always" or any(name in os.environ for name in _TERMINAL_SAYS):
            return True
        try:
            return self.file.isatty()
        except (AttributeError, ValueError):
            return False

    @property
    def is_terminal(self) -> bool:
        return self._may_be_terminal and self.console.is_terminal

    @property
    def color_system(self) -> str | None:
        return self.console.color_system if self._may_be_terminal else None

    def print(self, *objects, **options) -> None:
        self.console.print(*objects, **options)


class Output:
    """The two streams of a command: its results, and its diagnostics and progress.
    ``quiet``: only the diagnostics and the summary (no tree, notes or progress)."""

    def __init__(self, out: Stream | Console, err: Stream | Console, quiet: bool = False) -> None:
        self.out = out
        self.err = err
        self.quiet = quiet

    @classmethod
    def standard(cls, mode: str = "auto", quiet: bool = False) -> Output:
        """Standard output and error, styled as ``--color`` says."""
        return cls(Stream(mode), Stream(mode, stderr=True), quiet)


def rich_console(target: Stream | Console) -> Console:
    """The rich console that writes to the stream (made now, if it was not)."""
    return target.console if isinstance(target, Stream) else target


def styled(target: Stream | Console) -> bool:
    """Whether the stream shows styles: a terminal, or colour forced."""
    return target.is_terminal or target.color_system is not None


def write(target: Stream | Console, lines: Iterable[Line]) -> None:
    """Each line, styled when the stream shows styles, else as plain text."""
    if styled(target):
        from rich.text import Text

        for line in lines:
            target.print(Text.assemble(*line), soft_wrap=True, highlight=False)
        return
    target.file.writelines("".join(text for text, _ in line) + "\n" for line in lines)


def plain(text: str, style: str = "") -> Line:
    """A line of one piece."""
    return [(text, style)]


def flush(target: Stream | Console) -> None:
    try:
        target.file.flush()
    except (OSError, ValueError):  # closed, or a reader that stopped early: the exit code says so
        pass


__all__ = ["COLOR_MODES", "Line", "Output", "Stream", "console", "flush", "plain", "rich_console", "styled", "write"]
