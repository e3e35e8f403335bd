"""What every real load shares: the :class:`Outcome` of a consumer on one file, the
:class:`Loader` each consumer's ``load`` module declares, and the consumer's own messages
read back (:class:`Said`), each with the line or the names it gives.

The loaders themselves are in :mod:`urdfcli.targets` (``targets/NAME/load.py``), the
registry and the child process in :mod:`urdfcli.project.consumers`.
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import re
import tempfile
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import Any, NamedTuple

Packages = Mapping[str, str]  # a package's name -> its folder, as urdfcli resolved them


class Outcome(NamedTuple):
    """What a consumer did with one file. ``crashed`` is the signal that killed it."""

    accepted: bool
    error: str = ""  # why it refused the model, in its own words, whole
    printed: str = ""  # what it wrote to its standard output and error
    built: dict[str, Any] = {}  # what it built: bodies, joints (each loader says which fields)
    crashed: int | None = None


class Said(NamedTuple):
    """One message of the consumer: ``error`` or ``warning``, its text whole, and where it
    points: a line of the file it was given, else the names of links or joints it quotes."""

    severity: str
    text: str
    line: int | None = None
    names: tuple[str, ...] = ()


class Loader(NamedTuple):
    """How a consumer is run on a model. A Python consumer gives ``built`` (run in a child
    process on one file: what it built, or it raises); a program gives ``load`` (every
    file at once). ``missing`` says in one line why it cannot run here (None: it can)."""

    name: str
    missing: Callable[[], str | None]
    said: Callable[[Outcome, str], list[Said]]  # its messages on the file at that path
    built: Callable[[str, frozenset[str], Packages], dict] | None = None
    load: Callable[[Sequence[str], frozenset[str], Packages], list[Outcome]] | None = None


def python_package(module: str, install: str) -> Callable[[], str | None]:
    """``missing`` for a consumer that is a Python package: whether it can be imported (without importing it)."""

    def missing() -> str | None:
        return None if importlib.util.find_spec(module) is not None else f"its Python package is not installed: pip install {install}"

    return missing


def finite(value: float) -> float | None:
    """A number as JSON keeps it: None for an infinite or NaN one."""
    import math

    return float(value) if math.isfinite(value) else None


@contextlib.contextmanager
def package_folders(packages: Packages) -> Iterator[str]:
    """A folder holding one entry per package, named as the package and leading to its
    folder: where a consumer that looks ``package://NAME/`` up as ``NAME/`` under one
    search path finds every package urdfcli resolved."""
    with tempfile.TemporaryDirectory(prefix="urdfcli-packages-") as folder:
        for name, path in packages.items():
            if name and "/" not in name and name not in (".", ".."):
                os.symlink(path, os.path.join(folder, name))
        yield folder


QUOTED = re.compile(r"""['"\[]([^'"\[\]\s]+)['"\]]""")


def lines_of(text: str, severity: str, path: str | None = None) -> list[Said]:
    """Each non-empty line of ``text`` as a message of ``severity``, with the line of
    ``path`` it names (``PATH:LINE:``) and the quoted names in it."""
    found = []
    for line in text.splitlines():
        line = line.strip()
        if line:
            found.append(Said(severity, line, line_in(line, path), quoted(line)))
    return found


def quoted(text: str) -> tuple[str, ...]:
    """The names a message quotes: 'link1', "link1" or [link1]."""
    return tuple(QUOTED.findall(text))


def refusal(text: str, path: str | None = None) -> Said:
    """A consumer's error, whole, as one message."""
    text = " ".join(line.strip() for line in text.splitlines() if line.strip())
    return Said("error", text, line_in(text, path), quoted(text))


def line_in(text: str, path: str | None) -> int | None:
    """The line of ``path`` a message names as ``PATH:LINE``."""
    if path is None:
        return None
    match = re.search(re.escape(path) + r":(\d+)\b", text)
    return int(match.group(1)) if match else None


def without_colours(text: str) -> str:
    return re.sub(r"\x1b\[[0-9;]*m", "", text)
