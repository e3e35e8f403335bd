"""Two versions of a robot read and compared: each a file, standard input, or
``REV:PATH``, a file at a git revision read with its includes as they were then
(see :mod:`urdfcli.read.revision`).

A file of a revision is read from a temporary copy of the repository's tree;
its packages are looked for there first, and a package the copy lacks where the
workspace around the repository finds it now (a sibling repository in ``ws/src``):
the difference notes each package so read, whose changes since the revision it
cannot see. Every location is worked out before the copy is removed, and names
its file ``REV:PATH``.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable
from pathlib import Path

from ..diagnostics import Call, Location
from ..model.compare import TOLERANCE, Change, Comparison, compare
from ..model.load import Loaded, load
from ..read.document import STDIN, InputError, Inputs
from ..read.packages import PackageResolver
from ..read.revision import Revision, RevisionError, checkout, revision_of
from ..report.diff import Difference

ResolverFor = Callable[..., PackageResolver]  # (extra package paths, input file[, fallback]) -> resolver
ArgumentsFor = Callable[[str], dict[str, str]]  # a file as given (a revision's: where it is now) -> its xacro arguments


class NotComparable(Exception):
    """A version cannot be read as a robot (a one-line reason): exit 2."""


def compare_versions(
    old: str, new: str, arguments_for: ArgumentsFor, inputs: Inputs, resolver_for: ResolverFor, tolerance: float | None = None,
) -> tuple[Difference, tuple[str, ...]]:
    """What changed from ``old`` to ``new`` (numbers equal within ``tolerance``, relative;
    TOLERANCE when None), and the revisions named (``REV`` of each ``REV:PATH``); each
    read with the xacro arguments ``arguments_for`` gives its file. Raises NotComparable."""
    if old == STDIN and new == STDIN:
        raise NotComparable("only one of OLD and NEW can be standard input ('-')")
    with contextlib.ExitStack() as stack:
        sides = [_open(given, arguments_for, inputs, resolver_for, stack) for given in (old, new)]
        notes = tuple(note for loaded, folder, revision in sides if revision is not None for note in _read_as_now(loaded, folder, revision))
        folders = [(folder, revision) for _, folder, revision in sides if revision is not None]
        comparison = compare(sides[0][0], sides[1][0], TOLERANCE if tolerance is None else tolerance, lambda file: _placed(file, folders))
        if folders:
            comparison = Comparison(tuple(_renamed(change, folders) for change in comparison.changes), comparison.old, comparison.new)
    revisions = tuple(dict.fromkeys(revision.revision for _, _, revision in sides if revision is not None))
    return Difference(old, new, comparison, notes), revisions


def _open(given: str, arguments_for: ArgumentsFor, inputs: Inputs, resolver_for: ResolverFor, stack: contextlib.ExitStack) -> tuple[Loaded, Path | None, Revision | None]:
    """One version loaded (its revision's tree kept until the stack closes); a revision's
    file with the arguments of the file where it is now (the configuration as it is)."""
    try:
        revision = revision_of(given)
    except RevisionError as error:
        raise NotComparable(str(error)) from None
    folder = None
    try:
        if revision is not None:
            folder = stack.enter_context(checkout(revision))
            file = folder / revision.path
            now = resolver_for((), revision.top / revision.path)  # the workspace around the repository, as it is
            resolver = resolver_for((str(folder),), file, now)  # its own packages first, as they were
            loaded = load(str(file), inputs, resolver, arguments_for(str(revision.top / revision.path)), reads_meshes=False)
        else:
            resolver = resolver_for((), None if given == STDIN else Path(given))
            loaded = load(given, inputs, resolver, arguments_for(given), reads_meshes=False)
    except (InputError, RevisionError) as error:
        raise NotComparable(str(error)) from None
    if not loaded.modelled:
        shown = revision.given if revision is not None else loaded.document.shown
        if loaded.document.missing_argument is not None:
            name = loaded.document.missing_argument
            raise NotComparable(f"{shown}: needs xacro argument '{name}': give {name}:=VALUE after the two files, or in [tool.urdfcli.xacro-args]")
        reason = next((d for d in loaded.diagnostics if d.code in ("X001", "X002", "X003", "X004", "R001")), None)
        if reason is None and loaded.robot is None:
            reason = next(iter(loaded.diagnostics), None)
        said = f"{reason.message}" if reason is not None else "no <robot> read"
        raise NotComparable(f"{shown}: cannot be read as a robot: {said}")
    return loaded, folder, revision


def _read_as_now(loaded: Loaded, folder: Path, revision: Revision) -> list[str]:
    """A note for each package of the workspace that the revision's copy lacks and its
    expansion included files of: read as it is now, its changes since then unseen."""
    fallback = loaded.resolver.fallback
    own = fallback.index.enclosing_package(revision.top / revision.path) if fallback is not None else None
    if own is None:
        return []
    workspace = (revision.top, *fallback.index.local_roots(own))
    packages: dict[Path, None] = {}
    for include in map(Path, loaded.document.includes):
        if _relative(include, folder) is not None or all(_relative(include, root) is None for root in workspace):
            continue  # the revision's own, or a package installed beside the workspace
        package = fallback.index.enclosing_package(Path(os.path.abspath(include)).parent)
        if package is not None:
            packages[package] = None
    notes = []
    for package in packages:
        name = fallback.index.package_name(package / "package.xml")
        notes.append(f"{revision.top.name} at {revision.revision} has no package '{name}': read as it is now, in {package}")
    return notes


def _placed(file: Path, folders: list[tuple[Path, Revision]]) -> Path:
    """A file of a revision's copy at its place in the repository (a mesh file ``$(find)``
    named in the copy is the one the working tree names); any other file as it is."""
    for folder, revision in folders:
        inside = _relative(file, folder)
        if inside is not None:
            return revision.top / inside
    return file


def _renamed(change: Change, folders: list[tuple[Path, Revision]]) -> Change:
    """A change whose locations, and values naming files ($(find)'s mesh paths), name
    the files of a revision's copy as ``REV:PATH``."""
    return change._replace(
        location=_located(change.location, folders), anchor=_located(change.anchor, folders),
        old=_value_named(change.old, folders), new=_value_named(change.new, folders),
    )


def _value_named(value, folders: list[tuple[Path, Revision]]):
    if not isinstance(value, str):
        return value
    for folder, revision in folders:  # the copy's folder is a fresh temporary name: met nowhere else
        value = value.replace(f"{os.path.abspath(folder)}{os.sep}", f"{revision.revision}:")
    return value


def _located(location: Location | None, folders: list[tuple[Path, Revision]]) -> Location | None:
    if location is None:
        return None
    trace = tuple(Call(_named(call.file, folders), call.line, call.column, call.macro) for call in location.trace)
    return location._replace(file=_named(location.file, folders), trace=trace)


def _named(file: str, folders: list[tuple[Path, Revision]]) -> str:
    for folder, revision in folders:
        inside = _relative(Path(file), folder)
        if inside is not None:
            return f"{revision.revision}:{inside.as_posix()}"
    return file


def _relative(file: Path, folder: Path) -> Path | None:
    """``file``'s path inside ``folder``, or None when it is not inside."""
    try:
        return Path(os.path.abspath(file)).relative_to(os.path.abspath(folder))
    except ValueError:
        return None
