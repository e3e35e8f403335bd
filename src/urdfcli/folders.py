"""What a run learns about folders, learnt once: the inputs of a repository share
their ancestors, and each would otherwise look at every one of them again.

Outside :func:`one_run` nothing is remembered, so that a library caller sees
files written since its last call.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Hashable, Iterator
from pathlib import Path

TYPE_CHECKING = False  # typing's flag, without typing: xacro's worker imports this module
if TYPE_CHECKING:
    from typing import TypeVar

    T = TypeVar("T")
_answers: dict[Hashable, object] | None = None


@contextlib.contextmanager
def one_run() -> Iterator[None]:
    """Remember the answers of :func:`remembered` until the end of the block."""
    global _answers
    outer, _answers = _answers, {}
    try:
        yield
    finally:
        _answers = outer


def remembered(key: Hashable, compute: Callable[[], T]) -> T:
    """``compute()``, once per ``key`` within a run."""
    if _answers is None:
        return compute()
    if key not in _answers:
        _answers[key] = compute()
    return _answers[key]  # type: ignore[return-value]


def nearest(start: Path, kind: str, found_in: Callable[[Path], T | None]) -> T | None:
    """``found_in(folder)`` for the nearest folder at or above ``start`` where it is
    not None (None when there is none); each folder asked once per run and ``kind``."""

    def look() -> T | None:
        own = found_in(start)
        if own is None and start.parent != start:
            return nearest(start.parent, kind, found_in)
        return own

    return remembered((kind, start), look)
