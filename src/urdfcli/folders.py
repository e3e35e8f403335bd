"""What a run learns about folders, learnt once: the inputs of a repository share
their ancestors, and each would otherwise look at every one of them again.

Outside :func:`one_run` nothing is remembered, so that a library caller sees
files written since its last call.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Hashable, Iterator
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
