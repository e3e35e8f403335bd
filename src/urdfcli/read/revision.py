"""A file as it was at a git revision: ``REV:PATH``, as ``git show`` names it.

The repository's tree at that revision is written with ``git archive`` into a
folder of the system's temporary folder, so that the file's includes,
``$(find pkg)`` and the packages beside it are read as they were then; the
working tree is never read or changed. Mesh and image files are left out: a
comparison reads the names of meshes, never the files. The folder is removed
when the ``with`` block ends.

``PATH`` is relative to the repository's top folder, or, written ``./PATH`` or
``../PATH``, to the current folder (as ``git show`` reads it).

:func:`deleted_files` asks git which files a change deletes: what pre-commit never
passes to a hook, though a model may still include one.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import subprocess
import tarfile
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import NamedTuple

LEFT_OUT = ("stl", "dae", "obj", "ply", "glb", "gltf", "fbx", "3ds", "png", "jpg", "jpeg", "tif", "tiff", "bmp", "tga", "psd", "pdf", "bag", "mcap", "db3")


class RevisionError(Exception):
    """The revision or the file in it cannot be read (a one-line reason)."""


class Revision(NamedTuple):
    """``REV:PATH``: the revision as given, the repository's top folder, and the file's path in it."""

    given: str
    revision: str
    top: Path
    path: str  # relative to ``top``, with forward slashes

    @property
    def shown(self) -> str:
        """How locations name a file of this revision: ``REV:PATH`` for its path in the repository."""
        return f"{self.revision}:{self.path}"


def revision_of(text: str, cwd: Path | None = None) -> Revision | None:
    """``text`` read as ``REV:PATH`` when it is not a file that exists and the part before
    the first ``:`` is a revision of the git repository around ``cwd``; else None.
    Raises RevisionError when it names a revision but not a file in it."""
    if text == "-" or ":" not in text or Path(text).exists():
        return None
    revision, _, path = text.partition(":")
    cwd = Path.cwd() if cwd is None else cwd
    if not revision or not path or len(revision) == 1 and revision.isalpha():  # C:\file on Windows
        return None
    top = _git(cwd, "rev-parse", "--show-toplevel")
    if top is None:
        if (cwd / path).is_file():  # REV:PATH given from a colcon workspace above the repository
            raise RevisionError(f"{text}: no such file; read as REV:PATH, no git repository holds the current folder: run urdfcli diff from the repository holding {path}")
        return None
    if _git(cwd, "rev-parse", "--verify", "--quiet", f"{revision}^{{commit}}") is None:
        return None
    top_folder = Path(top)
    if path.startswith(("./", "../")) or path in (".", ".."):
        try:
            path = Path(os.path.relpath(os.path.normpath(cwd.resolve() / path), top_folder.resolve())).as_posix()
        except ValueError:
            raise RevisionError(f"{text}: {path} is outside the repository at {top}") from None
        if path.startswith("../"):
            raise RevisionError(f"{text}: {path} is outside the repository at {top}")
    path = path.strip("/")
    kind = _git(top_folder, "cat-file", "-t", f"{revision}:{path}")
    if kind != "blob":
        what = "is a folder" if kind == "tree" else "does not exist"
        raise RevisionError(f"{text}: '{path}' {what} at revision {revision} (the path is relative to the repository's top folder, or ./PATH to this folder)")
    return Revision(text, revision, top_folder, path)


@contextlib.contextmanager
def checkout(revision: Revision) -> Iterator[Path]:
    """A temporary copy of the repository's tree at ``revision`` (without meshes and
    images), removed when the block ends; the file is ``folder / revision.path``."""
    folder = Path(tempfile.mkdtemp(prefix="urdfcli-revision-"))
    try:
        _archive(revision, folder)
        (folder / ".git").mkdir(exist_ok=True)  # the repository's top: package look-ups stop here
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _archive(revision: Revision, folder: Path) -> None:
    left_out = [f":(exclude,icase,glob)**/*.{extension}" for extension in LEFT_OUT]
    command = ["git", "-C", str(revision.top), "archive", "--format=tar", revision.revision, "--", ".", *left_out]
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as process:
        try:
            with tarfile.open(fileobj=process.stdout, mode="r|") as archive:
                archive.extractall(folder, filter="data")  # no links out of the folder, no devices
        except tarfile.TarError as error:
            process.kill()
            raise RevisionError(f"{revision.given}: git archive gave no readable tree ({error})") from None
        message = process.stderr.read().decode(errors="replace").strip()
    if process.returncode != 0:
        raise RevisionError(f"{revision.given}: git archive failed: {message.splitlines()[-1] if message else process.returncode}")


def deleted_files(cwd: Path, between: tuple[str, str] | None = None) -> list[Path]:
    """The files of the git work tree around ``cwd`` that its staged changes delete, or,
    ``between`` two revisions (pre-commit's from-ref and to-ref), that the later one
    deleted: a rename deletes its old name. None outside a git work tree (or without git)."""
    if between is not None and any(revision.startswith("-") for revision in between):
        return []  # an option, not a revision: never given to git
    top = _git(cwd, "rev-parse", "--show-toplevel")
    if top is None:
        return []
    listing = ("diff", "--name-only", "--no-renames", "-z", "--diff-filter=D")
    if between is None:
        listed = _git(Path(top), *listing, "--cached")
    else:  # as pre-commit lists the files changed: from the merge base, else (no common history) between the two
        listed = _git(Path(top), *listing, f"{between[0]}...{between[1]}")
        if listed is None:
            listed = _git(Path(top), *listing, f"{between[0]}..{between[1]}")
    return [Path(top) / name for name in (listed or "").split("\0") if name]


def _git(cwd: Path, *args: str) -> str | None:
    """git's answer, or None when it fails (or is not installed)."""
    try:
        # (a file name that is not UTF-8 is kept as the bytes git gave)
        done = subprocess.run(["git", "-C", str(cwd), *args], capture_output=True, text=True, errors="surrogateescape", timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return done.stdout.strip() if done.returncode == 0 else None
