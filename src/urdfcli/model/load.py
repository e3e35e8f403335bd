"""A description once loaded: its document, its robot model and what reading found.

read the input -> expand xacro where it is used (in the session's bounded
worker, origins kept) -> read the model's elements one top-level element at a
time, tolerantly, keeping no tree. The rules run on a :class:`Loaded` (see
:mod:`urdfcli.project.linter`). Nothing here exits the process or prints.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, Location, joined
from ..read import positions
from ..read.document import STDIN, SUPPRESSION_MARK, Document, Inputs, read_document
from ..read.packages import PackageResolver
from ..read.xml import XmlError, hyphenated_comment, parse
from .mesh_summaries import MeshSummaries
from .robot import Joint, Robot, read
from .srdf import SRDF_TAGS, Semantic, looks_semantic, named_srdf, read_semantic

if TYPE_CHECKING:
    import networkx as nx

    from .sources import XacroSources


class Loaded:
    """A document, the robot read from it (None when unreadable, ``robot.at`` None
    when its root is not ``<robot>``), what reading and expanding it found, and
    what the rules need to look further: the package resolver of its run (meshes),
    the session's mesh summaries, and whether this run reads mesh files at all
    (``check`` does not: it judges what a ``stat`` shows)."""

    def __init__(
        self,
        document: Document,
        robot: Robot | None = None,
        diagnostics: list[Diagnostic] | None = None,
        resolver: PackageResolver | None = None,
        meshes: MeshSummaries | None = None,
        reads_meshes: bool = True,
        sources: XacroSources | None = None,
    ) -> None:
        self.document = document
        self.robot = robot
        self.diagnostics = diagnostics if diagnostics is not None else []
        self.resolver = resolver if resolver is not None else PackageResolver((), document.file)
        self.meshes = meshes if meshes is not None else MeshSummaries()
        self.reads_meshes = reads_meshes
        self.derived: dict = {}  # worked out from the rest, once (see urdfcli.read.memo)
        self.xacro_sources = sources  # the xacro files behind it, for the source rules
        self.semantic: Semantic | None = None  # an SRDF: what it says (then there is no robot)
        self.described: Loaded | None = None  # an SRDF: the URDF of its robot, to check it against (set by the caller)
        # an SRDF whose URDF lacks names it gives: the expansion of the xacro file that generated that URDF (set by the caller)
        self.described_source: Loaded | None = None

    @property
    def path(self) -> str:
        return self.document.path

    @property
    def modelled(self) -> bool:
        """Whether a robot was read (its root element is ``<robot>``)."""
        return self.robot is not None and self.robot.at is not None

    def diagnostic(
        self, code: str, message: str, at: int | None, hint: str | None = None, attribute: str | None = None, subjects: tuple[str, ...] = ()
    ) -> Diagnostic:
        """A diagnostic about the element ``at`` (see :meth:`Document.diagnostic`)."""
        return self.document.diagnostic(code, message, at, hint, attribute, subjects)

    def value(self, at: int | None, attribute: str) -> str | None:
        """The value of an attribute of element ``at`` as the model's text has it (the
        expansion's, for xacro), for a fix that keeps the way a number was written."""
        text = self.document.model_source
        return text.value(at, attribute) if text is not None and at is not None else None

    @cached_property
    def parent_joints(self) -> dict[str, Joint]:
        """Each link's parent joint: the first written, when a link has several."""
        found: dict[str, Joint] = {}
        if self.robot is not None:
            for joint in self.robot.joints.values():
                if joint.child is not None:
                    found.setdefault(joint.child, joint)
        return found

    def parent_joint(self, link: str) -> Joint | None:
        return self.parent_joints.get(link)

    @cached_property
    def graph(self) -> nx.DiGraph | None:
        """The kinematic tree as a networkx DiGraph (links as nodes, joints on the edges)."""
        if not self.modelled:
            return None
        from .kinematics import build_graph

        return build_graph(self.robot)

    @cached_property
    def root(self) -> str | None:
        if not self.modelled:
            return None
        from .kinematics import roots

        found = roots(self.robot)
        return found[0] if len(found) == 1 else None


def load(
    path: str,
    inputs: Inputs,
    resolver: PackageResolver,
    mappings: dict[str, str] | None = None,
    vocabulary: bool = False,
    meshes: MeshSummaries | None = None,
    force_xacro: bool = False,
    reads_meshes: bool = True,
    sources: Callable[[Document], XacroSources] | None = None,
    configured_as: Callable[[], str] | None = None,
) -> Loaded:
    """Read one input and its robot. With ``vocabulary``, markup URDF does not define
    is classified too (for the description rules); without ``reads_meshes``, the rules
    open no mesh file; ``sources`` finds the xacro files behind a document, for the
    source rules; ``configured_as()``, asked when an argument is missing, how the hint
    names the input in [tool.urdfcli.xacro-args] (its file name when None). Raises InputError."""
    document, diagnostics = read_document(path, inputs, resolver, mappings, force_xacro)
    if document.missing_argument is not None:  # the expansion stopped there: its one diagnostic says so
        key = configured_as() if configured_as is not None else (Path(path).name if path != STDIN else "FILE")
        also = also_unset(document, mappings or {}, document.missing_argument)
        diagnostics = [needs_argument(d, document.missing_argument, key, also) for d in diagnostics]
    found_sources = sources(document) if sources is not None else None
    loaded = Loaded(document, diagnostics=diagnostics, resolver=resolver, meshes=meshes, reads_meshes=reads_meshes, sources=found_sources)
    if not document.readable:
        return loaded
    if _semantic(loaded):
        return loaded
    try:
        robot, found = read(document, vocabulary=vocabulary)
    except XmlError as error:
        _unreadable(loaded, error)
        return loaded
    except Exception:  # a stream may reach odd markup before the error after it: the error is what to say
        error = _not_well_formed(document.data)
        if error is None:
            raise
        _unreadable(loaded, error)
        return loaded
    if not document.is_xacro and document.file is not None:
        document.may_suppress = positions.may_contain(document.data, SUPPRESSION_MARK)
    loaded.diagnostics += _comment_hyphens(document)
    document.data = None  # a large model's text is not kept beside the model
    loaded.diagnostics += found
    loaded.robot = robot
    return loaded


_SRDF_MARKS = tuple(f"<{tag}".encode() for tag in SRDF_TAGS)


def _semantic(loaded: Loaded) -> bool:
    """Read the document as an SRDF when it is one: named so, or a xacro file whose
    expansion holds SRDF elements and no link (only those are parsed to tell)."""
    document = loaded.document
    named = named_srdf(document.path)
    if not named and not (document.is_xacro and any(mark in document.data for mark in _SRDF_MARKS)):
        return False
    try:
        root = parse(document.data)
    except XmlError as error:
        if not named:
            return False  # reading it as a URDF says why
        _unreadable(loaded, error)
        return True
    if not named and not looks_semantic(root):
        return False
    loaded.semantic = read_semantic(document, root)
    if loaded.semantic.name is None:
        loaded.diagnostics.append(document.diagnostic("R002", "<robot> has no 'name' attribute", 0))
    loaded.diagnostics += _comment_hyphens(document)
    document.data = None
    return True
def needs_argument(diagnostic: Diagnostic, name: str, key: str, also: list[str] | tuple[str, ...] = ()) -> Diagnostic:
    """xacro's 'Undefined substitution argument NAME', said so that it names the fix: the
    value on the command line or in [tool.urdfcli.xacro-args], where ``key`` names the input.
    ``also``: the other arguments the files read without a value (:func:`also_unset`),
    which xacro would stop at next: named in the hint, so that all are given at once."""
    message = (f"needs xacro argument '{name}': it has no value where it is used (no default, or used before its "
               f"<xacro:arg>); pass {name}:=VALUE, or give it in the configuration")
    names = (name, *also)
    given = " ".join(f"{n}:=VALUE" for n in names)
    table = ", ".join(f'{n} = "VALUE"' for n in names)
    listed = joined(f"'{n}'" for n in also)
    more = f" (the files also read {listed} without a <xacro:arg> default: they may be needed too)" if also else ""
    hint = (f'give {given} after the file on the command line{more}, or in pyproject.toml: [tool.urdfcli.xacro-args] "{key}" = {{ {table} }} '
            f"(each of several values: [tool.urdfcli] models)")
    return diagnostic._replace(message=message, hint=diagnostic.hint or hint)


_ARGUMENT_NAME = re.compile(r"[\w.-]+")


def also_unset(document: Document, mappings: dict[str, str], missing: str) -> list[str]:
    """The arguments other than ``missing`` that the files the expansion read before it
    stopped (the model's own file whole) read as ``$(arg NAME)``, that no ``<xacro:arg>``
    of theirs declares and that were not given: xacro stops at the first, one run each.
    A macro never called or a branch not taken may read one of them (said so)."""
    if document.files is None:
        return []
    scans = [found.scan for file in (document.shown, *document.includes) if (found := document.files.get(file)) is not None and found.scan is not None]
    declared = {d.name for scanned in scans for d in scanned.definitions if d.kind == "argument"}
    read = {s.argument.strip() for scanned in scans for s in scanned.substitutions if s.function == "arg"}
    return sorted(n for n in read - declared - set(mappings) - {missing} if _ARGUMENT_NAME.fullmatch(n))


def _unreadable(loaded: Loaded, error: XmlError) -> None:
    document = loaded.document
    document.data, document.readable = None, False
    loaded.diagnostics.append(Diagnostic(error.code, error.message, Location(document.shown, error.line, error.column)))


def _comment_hyphens(document: Document) -> list[Diagnostic]:
    """X007 at the first comment holding `--`, which the reader took as urdfdom does
    (xacro's expansion refuses such a file itself)."""
    data = document.data
    at = None if document.is_xacro else hyphenated_comment(data)
    if at is None:
        return []
    line = data.count(b"\n", 0, at) + 1
    column = at - data.rfind(b"\n", 0, at)
    message = "comment holds '--', which XML forbids: urdfdom and MoveIt read on to the next '-->', xacro and Python's XML parsers refuse the file"
    hint = "end the comment with '-->' and write no '--' inside it"
    return [Diagnostic("X007", message, Location(document.shown, line, column), None, hint)]


def _not_well_formed(data: bytes) -> XmlError | None:
    """Why ``data`` is not a well-formed document, or None when it is."""
    try:
        parse(data)
    except XmlError as error:
        return error
    return None


__all__ = ["STDIN", "Loaded", "load"]
