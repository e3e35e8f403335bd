"""Worked out once per object: what several rules ask of one model (or one file) and
that costs to compute is kept on the object, keyed by the function that computes it."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

T = TypeVar("T")


def once(owner: Any, compute: Callable[..., T], *key: Any) -> T:
    """``compute(owner, *key)``, computed the first time it is asked for and kept in
    ``owner.derived`` (a dict): ``key`` says which of its values (hashable)."""
    memo = owner.derived
    index = (compute, key)
    if index not in memo:
        memo[index] = compute(owner, *key)
    return memo[index]


__all__ = ["once"]
