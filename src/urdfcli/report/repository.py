"""A file's path as GitHub names it: from the top of the repository holding it.

GitHub reads the ``file`` of a workflow annotation and a SARIF result's relative
``uri`` as paths from the repository's top folder, wherever the command ran (a
colcon job lints ``ws/src/REPO`` from ``ws``). The repository is the nearest folder
with a ``.git`` at or above the file; for a checkout without one (actions/checkout
falls back to a download without git), ``GITHUB_WORKSPACE`` when it holds the file.
A file in no repository, standard input and a file at a git revision keep their names.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..read.folders import repository_root


class RepositoryPaths:
    """Each file's repository and its path in it, the folders above asked once."""

    def __init__(self, workspace: str | None = None) -> None:
        self.workspace = Path(os.path.abspath(workspace)) if workspace else None
        self._known: dict[Path, Path | None] = {}

    @classmethod
    def from_environment(cls) -> RepositoryPaths:
        return cls(os.environ.get("GITHUB_WORKSPACE"))

    def root(self, file: str) -> Path | None:
        """The top folder of the repository holding ``file`` (None when there is none)."""
        path = Path(file)
        if not path.is_file():  # standard input, REV:PATH: no file of the working tree
            return None
        absolute = Path(os.path.abspath(path))
        found = repository_root(absolute.parent, self._known)
        if found is None and self.workspace is not None and absolute.is_relative_to(self.workspace):
            return self.workspace
        return found

    def locate(self, file: str) -> tuple[Path | None, str]:
        """The repository holding ``file`` and the file's path from its top, with forward
        slashes; (None, ``file``) for a file in no repository."""
        root = self.root(file)
        return (root, Path(os.path.abspath(file)).relative_to(root).as_posix()) if root is not None else (None, file)

    def path(self, file: str) -> str:
        """``file`` from the top of its repository; else as given."""
        return self.locate(file)[1]
