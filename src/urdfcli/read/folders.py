"""Looking up the folders above a file: the nearest that holds something."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

T = TypeVar("T")


def nearest(start: Path, found_in: Callable[[Path], T | None], known: dict[Path, T | None]) -> T | None:
    """``found_in(folder)`` for the nearest folder at or above ``start`` where it is not
    None (None when there is none). ``known`` keeps the answers, so that the files of
    one repository, which share their ancestors, ask each folder once."""
    passed = []
    folder = start
    while folder not in known:
        passed.append(folder)
        own = found_in(folder)
        if own is not None or folder.parent == folder:
            known[folder] = own
            break
        folder = folder.parent
    answer = known[folder]
    for seen in passed:
        known[seen] = answer
    return answer


def repository_root(start: Path, known: dict[Path, Path | None]) -> Path | None:
    """The top folder of the git repository holding ``start``: the nearest folder at or
    above it with a ``.git`` (a folder, or the file of a worktree or a submodule)."""
    return nearest(start, lambda folder: folder if (folder / ".git").exists() else None, known)
