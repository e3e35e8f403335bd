"""Standard output and error, through rich only when rich has something to style.

Importing rich and building a console costs about 20 ms, as long as the rest of a
small file's check. When the stream is not a terminal (and no variable asks for
colour), rich would write the text unchanged: a :class:`Stream` then writes it
itself, and makes the rich console on first need otherwise.
"""

from __future__ import annotations

import os
import sys


_RICH_VARIABLES = ("FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE")  # each may make rich style a stream that is no terminal


class Stream:
    """What the commands use of a rich ``Console``: ``print``, ``file``, ``is_terminal``,
    ``color_system``; anything else goes to the console (made on first use)."""

    def __init__(self, **options):
        """``options`` are those of rich's ``Console``."""
        self.configure(**options)

    def configure(self, **options) -> None:
        """Set the console options anew (the console is made again on next use)."""
        self._options = options
        self._stderr = bool(options.get("stderr"))
        self._console = None

    @property
    def file(self):
        return sys.stderr if self._stderr else sys.stdout  # looked up each time, as rich does

    @property
    def console(self):
        if self._console is None:
            from rich.console import Console

            self._console = Console(**self._options)
        return self._console

    def _plain(self) -> bool:
        """Whether rich would see no terminal (so no colour), told without rich.

        A forced terminal, or any variable rich reads to decide, leaves the decision to rich."""
        if self._console is not None or self._options.get("force_terminal") is not None:
            return False
        if any(name in os.environ for name in _RICH_VARIABLES):
            return False
        isatty = getattr(self.file, "isatty", None)
        try:
            return isatty is not None and not isatty()
        except ValueError:  # a closed stream
            return False

    @property
    def is_terminal(self) -> bool:
        return False if self._plain() else self.console.is_terminal

    @property
    def color_system(self):
        return None if self._plain() else self.console.color_system

    def print(self, *objects, sep: str = " ", end: str = "\n", markup: bool | None = None, **options) -> None:
        """``Console.print``; plain text without markup is written as it is."""
        if markup is False and self._plain() and all(isinstance(o, str) for o in objects):
            self.file.write(sep.join(objects) + end)
            return
        self.console.print(*objects, sep=sep, end=end, markup=markup, **options)

    def __getattr__(self, name: str):
        return getattr(self.console, name)
