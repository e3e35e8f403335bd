"""Libraries, models and the includes between them: which models a changed file affects.

A xacro file is a *library* when, outside its macro definitions, it writes no
``<link>``, no ``<joint>`` and no macro call: it defines macros and properties,
includes other files, or holds ``<gazebo>`` or ``<material>`` blocks for links
made elsewhere. Any other file is a *model*: every plain URDF, a xacro file
that makes a link, a joint or calls a macro at its top level, and a file that
cannot be read as XML (loading it says why). Only ``xacro:if`` and
``xacro:unless`` blocks are looked into; when in doubt a file is a library,
because a library is never reported as a broken robot. A file named ``.urdf``
is xacro when loading it expands it (a xacro element, a ``${...}``): Spot's
``spot_arm_macro.urdf``, a ``<robot>`` holding one macro, is a library too.

A library given to ``check`` or ``lint`` is checked through the top-level
models that include it, directly or through other files: the models of its
repository or workspace ``src/`` (see :func:`search_roots`) that no other file
includes, plus those listed in ``[tool.urdfcli] models``. Which models include it is decided by reading the
``xacro:include`` elements of every xacro file there, without expanding
anything: ``$(find pkg)``, ``$(arg x)`` with a default (a model's arguments and
properties reach the files it includes, as in xacro), ``$(dirname)``, ``$(env X)``
and ``${name}`` of a plain property are resolved. An include whose file name is
computed from something else (a macro parameter: ``${side}_arm.xacro``) may name
the files of its folder whose name fits; one whose folder is unknown (a package
not found here) names none. Only the models found are expanded, and a library
counts as checked through a model only when the model's expansion read it. The
models that include a file a change deletes (which pre-commit never passes) are
found the same way, and checked as if given: their include fails now.

A file that another file of a folder includes is not linted on its own when
the folder is: it is one of its models' parts (a *fragment*, such as Baxter's
end effectors), checked through the models that read it. A file given alone
that cannot be read without an error, and that models around it include, is
checked through them too, as is one that a model given with it read (an include
the search could not follow: Husky's ``$(arg urdf_extras)``, whose default an
included file declares). A plain URDF is such a part only when it holds no robot
(no name, no link, no joint: a placeholder); one that holds a robot is checked as
one, whoever includes it.
"""

from __future__ import annotations

import functools
import glob
import os
import re
from collections.abc import Callable, Iterable
from fnmatch import fnmatchcase
from pathlib import Path
from typing import NamedTuple

from ..diagnostics import Diagnostic, Location, Severity
from ..model.sources import XacroSources
from ..read.document import STDIN, Document
from ..read.document import is_xacro as reads_as_xacro  # (the file; xacro_scan.is_xacro is an element)
from ..read.packages import PackageIndex, PackageResolver, files_below
from ..read.files import SourceFile, SourceFiles
from ..read.xacro_scan import ARGUMENT, COMPUTED, DIRECTIVES, XacroFile, XacroGlobals, header_source, is_xacro, local_name, shown
from ..rules import structure
from ..rules.structure import X004 as PACKAGE_NOT_FOUND
from ..rules.tree import joint_link_not_found
from ..rules.suppression import U001 as UNUSED_SUPPRESSION
from ..model.result import Library, Result, Unreadable
from .config import agreeing
from .linter import unnamed

XACRO_SUFFIXES = (".xacro", ".urdf", ".srdf")
_SUBSTITUTION = re.compile(r"\$\(\s*(\w+)\s*([^()]*?)\s*\)|\$\{\s*([A-Za-z_]\w*)\s*\}")


class WorkspaceFile(NamedTuple):
    """What reading a file (not expanding it) tells about it in its workspace."""

    path: Path  # resolved
    kind: str  # "model" or "library"
    includes: tuple[str, ...] = ()  # filename attributes of its xacro:include elements, as written
    arguments: tuple[tuple[str, str], ...] = ()  # xacro:arg defaults
    properties: tuple[tuple[str, str], ...] = ()  # xacro:property values written as attributes


def workspace_file(path: Path, file: SourceFile | None) -> WorkspaceFile:
    """A file's kind and includes, from its source file (None: unreadable). Never
    raises: an unreadable file, or one that is not XML, is a model (loading it says why)."""
    if file is None:
        return WorkspaceFile(path, "model")
    if not path.name.endswith(".xacro") and (b"xacro" not in file.data or not reads_as_xacro(file)):
        return WorkspaceFile(path, "model")  # plain URDF, as loading it reads it
    found = file.scan
    if found is None:
        return WorkspaceFile(path, "model")
    kind = "model" if found.makes else "library"
    return WorkspaceFile(path, kind, tuple(found.includes), tuple(found.arguments), tuple(found.properties))


class Include(NamedTuple):
    """Where an include leads, as far as it can be told without expanding: a file
    (``path``), the files a glob written in it matches (``glob``), the files whose
    name fits a name computed from something unknown here, such as a macro
    parameter (``pattern``: the folder is known, ``${side}_arm.xacro`` is
    ``*_arm.xacro``), or nothing known (``unknown``: a package not found, a folder
    computed). Only a path is certain; a pattern says which files to look at."""

    kind: str  # "path", "glob", "pattern" or "unknown"
    value: str = ""  # the path, glob or pattern; for "unknown", the filename as written

    def may_be(self, file: Path) -> bool:
        if self.kind == "path":
            return Path(self.value) == file
        if self.kind in ("glob", "pattern"):
            return fnmatchcase(str(file), self.value)
        return False


def substitute(
    text: str, source: WorkspaceFile, find: Callable[[str], Path | None], arguments: dict[str, str] | None = None,
    properties: dict[str, str] | None = None,
) -> str:
    """``text`` with the substitutions that can be told without expanding replaced:
    ``$(find)``, ``$(arg)`` (the given values, else the defaults the file declares),
    ``$(dirname)``, ``$(env)``, ``$(optenv)``, and ``${name}`` of a plain property
    (the given ones, from the files that include this one, then the file's own)."""
    values = {**dict(source.arguments), **(arguments or {})}
    known = {**(properties or {}), **dict(source.properties)}

    def replace(match: re.Match) -> str:
        function, argument, prop = match.group(1), match.group(2), match.group(3)
        if prop is not None:
            value = known.get(prop)
        elif function == "find":
            folder = find(argument)
            value = str(folder) if folder is not None else None
        elif function == "arg":
            value = values.get(argument)
        elif function == "dirname":
            value = str(source.path.parent)
        elif function in ("env", "optenv"):
            name, _, default = argument.partition(" ")
            value = os.environ.get(name, default if function == "optenv" else None)
        else:
            value = None
        return match.group(0) if value is None else value

    for _ in range(5):  # a default may itself hold a substitution
        substituted = _SUBSTITUTION.sub(replace, text)
        if substituted == text:
            break
        text = substituted
    return text




def resolve_include(
    text: str, source: WorkspaceFile, find: Callable[[str], Path | None], arguments: dict[str, str] | None = None,
    properties: dict[str, str] | None = None, source_of: Callable[[str], str] = str,
) -> Include:
    """Where ``<xacro:include filename=text>`` in ``source`` leads, statically; ``source_of``
    gives a file of the workspace's install space as its source (the resolver's)."""
    written = text
    text = substitute(text, source, find, arguments, properties)
    folder, _, name = text.replace("\\", "/").rpartition("/")
    if "$" in folder or not name:
        return Include("unknown", written)
    base = Path(folder) if folder and Path(folder).is_absolute() else source.path.parent / folder if folder else source.path.parent
    if "$" in name:
        pattern = COMPUTED.sub("*", name)
        if not pattern.strip("*"):
            return Include("unknown", written)  # a name computed whole: it may be any file
        return Include("pattern", os.path.normpath(base / pattern))
    path = Path(os.path.normpath(base / name))
    if any(c in name for c in "*?["):
        return Include("glob", str(path))
    path = Path(source_of(str(path)))
    try:
        return Include("path", str(path.resolve()))
    except OSError:
        return Include("path", str(path))


def search_roots(file: Path, packages: PackageIndex) -> tuple[list[Path], bool]:
    """The folders whose models may include ``file``, and whether to search below
    them: those the package resolver searches for its siblings (repository,
    workspace ``src/``); for a package in neither, the package alone (the folder
    holding it may be /tmp or a venv's share/: nothing says its other files belong
    with it); for a file in no package, those the package resolver searches for it
    (the repository holding it, a workspace ``src/``), else its own folder alone."""
    package = packages.enclosing_package(file.parent)
    if package is None:
        roots = [root for root in packages.loose_roots(file.parent) if root.name != "src" or _workspace_src(root)]
        return (roots, True) if roots else ([file.parent], False)
    roots = packages.local_roots(package)
    if roots == [package.parent] and package.parent.name != "src" and not (package.parent / ".git").exists():
        return [package], True
    # A repository in a folder named src (~/src/my_robot) is searched beyond only
    # when that src is a ROS workspace's: the package look-up widens only when it
    # must, a search for models would read every file there on every commit.
    return [r for r in roots if r == roots[0] or _workspace_src(r)], True


_WORKSPACE_MARKS = ("build", "install", "log", "devel", ".catkin_workspace", ".catkin_tools", "colcon.meta")


def _workspace_src(src: Path) -> bool:
    """Whether a folder named src holds a ROS workspace: built or marked beside it, or
    holding packages up to three levels down in more than one of its folders (a
    repository may group its packages: create3_sim/irobot_create_common/<package>)."""
    if any((src.parent / mark).exists() for mark in _WORKSPACE_MARKS):
        return True
    try:
        children = [c for c in src.iterdir() if c.is_dir() and not c.name.startswith(".")]
    except OSError:
        return False
    holding = sum(1 for c in children if any(any(c.glob(pattern)) for pattern in ("package.xml", "*/package.xml", "*/*/package.xml")))
    return holding > 1


def source_files(root: Path, recursive: bool = True) -> Iterable[Path]:
    """``*.xacro`` and ``*.urdf`` files below a folder, skipping hidden, build and ignored folders."""
    return files_below(root, lambda name: name.endswith(XACRO_SUFFIXES), recursive)


class Index:
    """The files of the folders searched, and any file an include leads to, each read
    once (through the session's files), and the includes between them."""

    def __init__(self, package_paths: tuple[str, ...] = (), packages: PackageIndex | None = None, files: SourceFiles | None = None):
        self.scanned: dict[Path, list[Path]] = {}  # a searched folder -> its files
        self._package_paths = package_paths
        self.packages = packages if packages is not None else PackageIndex()
        self.files = files if files is not None else SourceFiles()
        self._resolvers: dict[Path | None, PackageResolver] = {}
        self._edges: dict[tuple[Path, tuple], tuple[WorkspaceFile, list[Include]]] = {}
        self._kinds: dict[Path, tuple[WorkspaceFile, str]] = {}
        self._read: set[Path] = set()  # the files not named .xacro asked for
        self._listed: dict[tuple[Path, bool], tuple[int, list[Path]]] = {}
        self.described: dict[tuple[str, tuple], object] = {}  # the URDFs SRDFs were checked against, loaded once

    def scan(self, roots: list[Path], recursive: bool = True) -> list[Path]:
        """The source files below the folders (listed again when a folder changes)."""
        files: list[Path] = []
        for root in roots:
            try:
                stamp = os.stat(root).st_mtime_ns
            except OSError:
                stamp = 0
            listed = self._listed.get((root, recursive))
            if listed is None or listed[0] != stamp:
                listed = self._listed[(root, recursive)] = (stamp, [self.packages.real_path(file) for file in source_files(root, recursive)])
            self.scanned[root] = listed[1]
            files += listed[1]
        return list(dict.fromkeys(files))

    def kind(self, file: Path, visiting: frozenset = frozenset()) -> str:
        """"model" or "library": a file that makes nothing itself but includes a
        model (a robot assembled from included files) is a model too."""
        source = self.source(file)
        known = self._kinds.get(file)
        if known is None or known[0] != source:
            kind = source.kind
            if kind == "library" and file not in visiting:
                for include in self.includes(file):
                    target = Path(include.value)
                    if include.kind == "path" and target.is_file() and self.kind(target, visiting | {file}) == "model":
                        kind = "model"
                        break
            known = self._kinds[file] = (source, kind)
        return known[1]

    def finder(self, file: Path) -> Callable[[str], Path | None]:
        """The package look-up the expansion of ``file`` would make."""
        return self.resolver(file).find

    def resolver(self, file: Path) -> PackageResolver:
        """The package resolver the expansion of ``file`` would use (shared per package)."""
        package = self.packages.enclosing_package(file.parent)
        if package not in self._resolvers:
            try:
                self._resolvers[package] = self.packages.resolver(self._package_paths, file)
            except ValueError:  # a bad -P is reported when the model loads
                self._resolvers[package] = self.packages.resolver((), file)
        return self._resolvers[package]

    def source(self, file: Path) -> WorkspaceFile:
        """What reading ``file`` tells (read again when the file changes)."""
        if not file.name.endswith(".xacro"):
            self._read.add(file)
        return self.files.derived(shown(file), workspace_file)

    def unknown(self, file: Path) -> bool:
        """Whether ``file`` may define or use xacro names that cannot be read: it is
        unreadable, or a xacro file that is not XML. A plain URDF holds none, and
        neither does the YAML that ``xacro.load_yaml`` read (xacro lists it with the
        files it included)."""
        found = self.files.get(shown(file))
        return found is None or (file.name.endswith(".xacro") and found.scan is None)

    def xacro_file(self, file: Path) -> XacroFile | None:
        """The scan of a xacro file (None: unreadable, not XML, or a plain URDF)."""
        if not file.name.endswith(".xacro"):
            source = self.source(file)
            if source.kind == "model" and not (source.includes or source.arguments or source.properties):
                return None  # a plain URDF, or near enough: read whole only by the model's own run
        found = self.files.get(shown(file))
        return found.scan if found is not None else None

    def reach(self, files: list[Path]) -> tuple[list[Path], bool]:
        """The files the includes of ``files`` may lead to, under any condition, and
        whether each include could be followed to a file (not one whose path is
        computed, or that does not exist)."""
        seen = dict.fromkeys(files)
        stack = list(files)
        complete = True
        while stack:
            file = stack.pop()
            for include in self.includes(file):
                if include.kind == "path":
                    targets = [Path(include.value)]
                elif include.kind == "glob":
                    targets = [Path(p) for p in sorted(glob.glob(include.value))]
                else:
                    complete = False
                    continue
                for target in targets:
                    if target in seen:
                        continue
                    if not target.is_file():
                        complete = False
                        continue
                    seen[target] = None
                    stack.append(target)
        return list(seen), complete


    def includes(self, file: Path, arguments: dict[str, str] | None = None, properties: dict[str, str] | None = None) -> list[Include]:
        """Where the includes of ``file`` lead, with the argument values and properties of
        the files that include it (xacro's arguments and top-level properties are global)."""
        key = (file, tuple(sorted((arguments or {}).items())), tuple(sorted((properties or {}).items())))
        source = self.source(file)
        known = self._edges.get(key)
        if known is None or known[0] != source:
            resolver = self.resolver(file)
            known = self._edges[key] = (source, [resolve_include(text, source, resolver.find, arguments, properties, resolver.source_of) for text in source.includes])
        return known[1]

    def includers(self, files: list[Path]) -> dict[Path, list[tuple[Path, Include, str]]]:
        """Which of ``files`` others of them include, and by which include: one that
        resolves to it, a glob written as such, or a file name computed from a macro
        parameter or an argument without a default that fits it."""
        found: dict[Path, list[tuple[Path, Include, str]]] = {}
        for file in files:
            if not file.name.endswith(".xacro"):
                continue  # a plain URDF includes nothing: not read here
            for include, text in zip(self.includes(file), self.source(file).includes):
                if include.kind == "path":
                    matched = [Path(include.value)]
                elif include.kind in ("glob", "pattern"):
                    matched = [f for f in files if f != file and include.may_be(f)]
                else:
                    continue
                for target in matched:
                    if target != file:
                        found.setdefault(target, []).append((file, include, text))
        return found

    def calling(self, files: list[Path], macros: set[str]) -> set[Path]:
        """The files among ``files`` whose expansion may call one of ``macros`` (names
        without ``xacro:``): a file that calls one outside any macro body, or calls a
        macro whose body calls one (on up), and a file that includes such a file."""
        scans = {file: scan for file in files if (scan := self.xacro_file(file)) is not None}
        names = set(macros)
        found: set[Path] = set()
        grown = True
        while grown:
            grown = False
            for file, scan in scans.items():
                for call in scan.calls:
                    if call.name.rpartition(".")[2] not in names:  # (ns.name: a macro of an include with a namespace)
                        continue
                    if call.macro is None:
                        grown |= file not in found
                        found.add(file)
                    elif (outer := scan.macros[call.macro].name.removeprefix("xacro:")) not in names:
                        names.add(outer)
                        grown = True
        includers = self.includers(list(scans))
        stack = list(found)
        while stack:
            for includer, _, _ in includers.get(stack.pop(), []):
                if includer not in found:
                    found.add(includer)
                    stack.append(includer)
        return found

    def top_level_models(self, files: list[Path]) -> list[Path]:
        """The models among ``files`` that none of them includes, or only files of other
        packages do (see :func:`included_from_other_packages`): included by a resolved path,
        or, a xacro file, by a glob or a name computed from a macro parameter that fits it
        (TALOS's ``${side}_arm.transmissions.urdf.xacro``, a fragment of the arm's macro)."""
        includers = self.includers(files)

        def included(file: Path) -> bool:
            found = includers.get(file, [])
            by = [includer for includer, include, _ in found if include.kind == "path" or part_of_model(str(file))]
            return bool(by) and not included_from_other_packages(file, by, self)

        return sorted(f for f in files if self.kind(f) == "model" and not included(f))

    def reaches(self, model: Path, file: Path, arguments: dict[str, str] | None = None) -> bool:
        """Whether a run of ``model`` may read ``file``: a description through any chain of
        includes (that resolve to it, or whose computed file name may be it); any other file
        (a mesh, the YAML of ``load_yaml``) when ``model`` or a file its includes may lead to
        writes its name whole (see :meth:`_writes`)."""
        files, includes = self.reachable(model, arguments)
        if file.name.endswith((".urdf", ".xacro")):
            return file in files or any(include.may_be(file) for include in includes)
        return any(self._writes(source, file.name) for source in (model, *files))

    def _writes(self, source: Path, name: str) -> bool:
        """Whether ``source`` writes the file name ``name`` whole: a mesh's as ``package://pkg/meshes/base.stl``
        or ``meshes/base.stl`` do, a YAML file's as ``$(find pkg)/config/joints.yaml`` does. A name computed
        from properties (``${link}.stl``) is not found, and one of another folder is (its model is checked for nothing)."""
        written = re.compile(rb"(?<![\w.-])" + re.escape(name.encode()) + rb"(?![\w.-])")
        try:
            return written.search(self.files.read(shown(source)).data) is not None
        except OSError:
            return False

    def reachable(self, model: Path, arguments: dict[str, str] | None = None) -> tuple[set[Path], list[Include]]:
        """The files expanding ``model`` may read (under any condition), and every include
        met on the way. Argument values and properties reach the included files, as in
        xacro; an include computed from them may name other files with other values."""
        seen = {model}
        met: list[Include] = []
        stack = [(model, arguments or {}, {})]
        while stack:
            file, args, props = stack.pop()
            source = self.source(file)
            args = {**dict(source.arguments), **args}  # a value given, else the first default declared
            props = {**props, **dict(source.properties)}
            # what the include names with these values, and which files it may name with others
            met += [i for i in self.includes(file) if i.kind in ("glob", "pattern")]
            for include in self.includes(file, args, props):
                met.append(include)
                if include.kind == "path":
                    nexts = [Path(include.value)]
                elif include.kind == "unknown":
                    nexts = []
                else:
                    known = {f for files in self.scanned.values() for f in files} | self._read
                    nexts = [f for f in known if include.may_be(f)]
                for nxt in nexts:
                    if nxt not in seen and nxt.is_file():
                        seen.add(nxt)
                        stack.append((nxt, args, props))
        return seen - {model}, met


def xacro_sources(document: Document, index: Index, xacro_names: Callable[[], XacroGlobals | None] = lambda: None) -> XacroSources:
    """The xacro files behind a read document, for the source rules: those its
    expansion read (none for a plain URDF), then, when a rule asks, those its
    includes may reach and those of the repository or workspace around it."""
    start = document.file.resolve() if document.file is not None and document.is_xacro else None  # (a plain URDF has no sources)
    names = [document.shown, *(shown(file) for file in _own(document, start, index))] if document.is_xacro else []
    files = [found.scan for name in dict.fromkeys(names) if (found := index.files.get(name)) is not None and found.scan is not None]

    def scanned(paths: list[Path]) -> list[XacroFile]:
        return [found for path in paths if (found := index.xacro_file(path)) is not None]

    def reach() -> tuple[list[XacroFile], bool]:
        if start is None or not document.is_xacro:
            return [], document.is_xacro is False
        paths, complete = index.reach([start, *(Path(file).resolve() for file in document.includes)])
        found = scanned(paths)
        return found, complete and not any(index.unknown(path) for path in paths if index.xacro_file(path) is None)

    def around() -> list[XacroFile]:
        if start is None or not document.is_xacro:
            return []
        return scanned(index.scan(*search_roots(start, index.packages)))

    return XacroSources(files, reach, around, xacro_names)

def _own(document: Document, start: Path | None, index: Index) -> list[str]:
    """The files a document's expansion included that belong to its repository or
    workspace: the source rules say nothing of a package installed elsewhere."""
    if start is None:
        return []
    roots, recursive = search_roots(start, index.packages)
    inside = []
    for file in document.includes:
        folder = Path(file).resolve().parent
        if any(folder == root or (recursive and root in folder.parents) for root in roots):
            inside.append(file)
    return inside


Example = tuple[str, tuple[tuple[str, ...], ...]]  # a model, and its argument sets (NAME:=VALUE each) for [tool.urdfcli] models


class Target(NamedTuple):
    """One expansion to run: a model with an argument set, or a library on its own."""

    path: str
    arguments: tuple[tuple[str, str], ...] = ()  # from [tool.urdfcli] models
    alone: bool = False
    unchecked: str = ""  # alone: why the models that include it could not check it
    fragment: bool = False  # alone: a file that cannot be read on its own; only why no model checked it is said
    example: Example | None = None  # alone: for the hint, a model that includes it and the argument sets that would check it through that model
    environment: tuple[tuple[str, ...], ...] = ()  # alone: the ways environment variables make its models read it (NAME=VALUE each)
    stopped: str | None = None  # alone: a model that includes it whose expansion stopped at an error before reading it, when no other reason is

    @property
    def label(self) -> str:
        if not self.arguments:
            return self.path
        return f"{self.path} [{' '.join(f'{k}:={v}' for k, v in self.arguments)}]"


class Maybe(NamedTuple):
    """A model that may include a library through a file name it computes from what it is
    given (``$(find pkg)/urdf/${robot_model}.urdf.xacro``), none of whose runs reads it."""

    model: str  # as shown
    written: str  # the include, as written
    runs: tuple[Target, ...]  # the model's runs
    argument: tuple[str, str] | None = None  # the xacro argument, and its value, that name the library (when one does)


Gate = tuple[str, str, str]  # (function, name, value): see Gates


class Gates(NamedTuple):
    """What the models that include a library read to decide whether to read it
    (``include``: the conditions around each include leading to it, and the include's
    file name) and whether to call its macros (``call``: the conditions around each
    call). One set of gates a place (each place is one way in; all of its gates must
    open), places under no condition left out. A gate is (function, name, value):
    function "env" (``$(env)``, ``$(optenv)``) or "arg" (``$(arg)``), and the value
    that opens it ("" when it cannot be told)."""

    include: tuple[tuple[Gate, ...], ...] = ()
    call: tuple[tuple[Gate, ...], ...] = ()

    def arguments(self, reading: bool, calling: bool) -> tuple[str, ...]:
        """The first way in (of reading the library, of calling its macros) that xacro
        arguments alone open, each known: its NAME:=VALUE assignments (a condition's
        "1" or "0" written true or false, as boolean arguments are); () when none is."""
        ways = (self.include if reading else ()) + (self.call if calling else ())
        for way in ways:
            if all(function == "arg" and value in ("1", "0") for function, _, value in way):
                return tuple(dict.fromkeys(f"{name}:={'true' if value == '1' else 'false'}" for _, name, value in way))
        return ()

    def environment(self, reading: bool, calling: bool) -> tuple[tuple[str, ...], ...]:
        """The ways in (of reading the library, of calling its macros) that environment
        variables alone open, each as its NAME=VALUE assignments."""
        ways = (self.include if reading else ()) + (self.call if calling else ())
        return tuple(dict.fromkeys(
            tuple(dict.fromkeys(f"{name}={value or 'VALUE'}" for _, name, value in way)) for way in ways if all(g[0] == "env" for g in way)
        ))


class Entry(NamedTuple):
    """A given file: a model and its runs, or a library and the models it is checked through
    (and, when none is, those that may include it: ``maybe``), the macros it defines, and
    what its models read to decide whether to read it and call them (``gates``)."""

    path: str
    targets: list[Target]
    library: bool = False
    maybe: tuple[Maybe, ...] = ()
    macros: tuple[str, ...] = ()
    gates: Gates = Gates()


MODEL_SUFFIXES = (".urdf", ".urdf.xacro", ".srdf", ".srdf.xacro")
# The files that may be a library: a .urdf that is xacro and makes nothing is one
# (Spot's spot_arm_macro.urdf, a macro that spot_macro.xacro includes).
LIBRARY_SUFFIXES = (".xacro", ".urdf")


class Aside(NamedTuple):
    """A file of a folder left out of its models because a file there includes it:
    checked through the models whose expansion reads it."""

    path: str
    includers: tuple[tuple[str, str], ...]  # (file, the include as written) that may read it
    certain: bool  # some include resolves to it (else only a computed file name fits it)


class Models(list):
    """The files to check for the paths given (a list of paths), and, for a folder,
    the files left out because another file there includes them (``aside``)."""

    def __init__(self, files=(), aside: tuple[Aside, ...] = ()) -> None:
        super().__init__(files)
        self.aside = aside


def models_below(folder: Path, index: Index) -> Models:
    """The robot models below a folder, as ``check`` and ``lint`` find them: every
    ``*.urdf``, ``*.urdf.xacro``, ``*.srdf`` and ``*.srdf.xacro`` file, and each other
    ``*.xacro`` file that is a model (ROS 1's ``ur5.xacro``), unless a file of its
    package there includes it: a fragment (Baxter's ``left_end_effector.urdf.xacro``, a model's
    parts in their own file, a file included through a name computed from a macro
    parameter, a plain URDF that holds no robot) is checked through the models that
    read it, never expanded alone.
    Libraries are checked through the models that include them. ``index`` is the session's."""
    files = list(source_files(folder))
    resolved = {file: file.resolve() for file in files}
    includers = index.includers(list(resolved.values()))
    models, aside = [], []
    for file in sorted(files):
        path = resolved[file]
        if not (file.name.endswith(MODEL_SUFFIXES) or (file.name.endswith(".xacro") and index.kind(path) == "model")):
            continue
        found = includers.get(path)
        # a plain URDF that holds a robot is one, whoever includes it; a .urdf that is a xacro library is a part;
        # a xacro model that only other packages include is its own package's robot (a MoveIt config wraps the description's)
        if not found or not (part_of_model(str(file)) or index.kind(path) == "library") or included_from_other_packages(path, [f for f, _, _ in found], index):
            models.append(file)
        else:
            written = tuple((shown(includer), text) for includer, _, text in found)
            aside.append(Aside(shown(file), written, any(include.kind in ("path", "glob") for _, include, _ in found)))
    return Models(models, tuple(aside))


def included_from_other_packages(model: Path, includers: list[Path], index: Index) -> bool:
    """Whether a xacro model is included only by files of other packages than its own: the robot
    its package describes and launches, which a MoveIt config's ``robot.urdf.xacro`` wraps with its
    ros2_control, not a fragment of that wrapper (a fragment that cannot be read alone is still
    checked through the models that include it)."""
    package = index.packages.enclosing_package(model.parent)
    return (package is not None and index.kind(model) == "model"
            and all(index.packages.enclosing_package(includer.parent) != package for includer in includers))


def unread(aside: tuple[Aside, ...], results: list[Result], shown: list[Result] = ()) -> list[Result]:
    """For each file set aside that no model's expansion read (``results``: every run), a
    result that says so (not counted as checked): a fragment is never expanded alone, where
    its missing context would be reported as its mistakes. One note per include, whatever
    number of files it may name; it points at what the includer's result says (in
    ``shown``, the results shown) when it says why, else names the setting to use."""
    if not aside:
        return []
    resolved = _resolver()
    read = {resolved(file) for result in results for file in (result.path, *result.includes) if file != STDIN}
    # an error (it did not expand) or a note says why; a warning of a model that expanded does not
    saying = {resolved(result.path) for result in shown if result.errors or (result.library is not None and result.library.notes)}
    # a file an expansion read before it stopped at an error: what it includes later was never reached
    stopped = {resolved(f): result.shown for result in shown if result.errors and result.robot is None for f in result.includes}
    found = []
    for file in aside:
        if resolved(file.path) in read:
            continue
        includer, written = file.includers[0]
        if file.certain and resolved(includer) in saying:
            note = f"not checked: included by {includer}, whose expansion did not read it (see what it says)"
        elif file.certain and resolved(includer) in stopped:
            note = f"not checked: included by {includer}, where the expansion of {stopped[resolved(includer)]} stopped at an error before it (see what it says)"
        elif file.certain:
            note = (f"not checked: included by {includer}, whose expansion did not read it (under a condition, or in a macro not called): "
                    "list argument sets of a model that reads it in [tool.urdfcli] models")
        else:
            note = f"not checked: no model read it; {includer} includes '{written}', a file name computed from what it is given"
        found.append(Result(file.path, library=Library((), (note,), unchecked=True)))
    return found


def model_targets(path: str, argument_sets: list[dict[str, str]] | None) -> list[Target]:
    return [Target(path, tuple(arguments.items())) for arguments in (argument_sets or [{}])]


def asked(targets: list[Target], given: dict[str, str]) -> list[Target]:
    """The runs that the command line's arguments ask for: of each model, the runs whose
    argument set agrees with them (see :func:`~urdfcli.project.config.agreeing`), with them
    added, or, when none does, one run with them alone. A library on its own keeps its run."""
    if not given:
        return targets
    kept: list[Target] = []
    for path in dict.fromkeys(target.path for target in targets):
        runs = [target for target in targets if target.path == path]
        fitting = [run for run in runs if run.alone or agreeing([dict(run.arguments)], given)]
        chosen = fitting or [runs[0]._replace(arguments=())]
        kept += [run if run.alone else run._replace(arguments=tuple({**dict(run.arguments), **given}.items())) for run in chosen]
    return list(dict.fromkeys(kept))


def plan(
    paths: list[str], config_for, package_paths: tuple[str, ...] = (), packages: PackageIndex | None = None, files: SourceFiles | None = None,
    deleted: tuple[str, ...] = (),
) -> list[Entry]:
    """What to run for the given files: each model once per argument set, each
    library through the models that may include it (none: on its own). A file
    ``deleted`` (by a change, which pre-commit does not pass) is found as a library is:
    each model that may read it (see :meth:`Index.reaches`: a mesh or YAML file too) is run
    as if given (its include, its mesh or its ``load_yaml`` fails now).

    ``config_for(path)`` gives the configuration of a file (for ``models`` and
    package paths). ``files`` are the session's (each file read once for this
    search and the source rules). Raises what ``config_for`` raises.
    """
    packages = packages if packages is not None else PackageIndex()
    files = files if files is not None else SourceFiles()
    entries: list[Entry] = []
    index: Index | None = None
    candidates_of: dict[tuple, list[Path]] = {}  # the top-level models of each place searched, found once
    for path in paths:
        config = config_for(path)
        # a plain URDF is read only as far as telling it is not xacro (a .srdf is never a library)
        library = Path(path).resolve() if path != STDIN and path.endswith(LIBRARY_SUFFIXES) else None
        alone = files.derived(shown(library), workspace_file) if library is not None else None
        if alone is not None and alone.kind == "library":  # else no look-up at all
            index = index or Index(config.package_paths + package_paths, packages, files)
            if index.kind(library) == "model":
                library = None
        else:
            library = None
        if library is None or index is None:
            entries.append(Entry(path, model_targets(path, config.argument_sets(path))))
            continue
        targets = _includers(library, index, config, config_for, packages, candidates_of)
        maybe = () if targets else _computing_includers(library, index, config, config_for, packages, candidates_of)
        scan = index.xacro_file(library)
        macros = tuple(dict.fromkeys(m.name for m in scan.macros if m.name)) if scan is not None else ()
        gates = _gates(library, macros, targets, index) if targets else Gates()
        entries.append(Entry(path, targets, library=True, maybe=maybe, macros=macros, gates=gates))
    given = {Path(entry.path).resolve() for entry in entries if entry.path != STDIN}
    for path in deleted:
        config = config_for(path)
        index = index or Index(config.package_paths + package_paths, packages, files)
        targets = _includers(Path(path).resolve(), index, config, config_for, packages, candidates_of)
        for model in dict.fromkeys(target.path for target in targets):
            if Path(model).resolve() not in given:
                given.add(Path(model).resolve())
                entries.append(Entry(model, [target for target in targets if target.path == model]))
    return entries


def fragment_includers(config_for, package_paths: tuple[str, ...] = (), packages: PackageIndex | None = None, files: SourceFiles | None = None):
    """``includers(path)``: the runs of the models around a xacro file given as a model
    that include it (and around a plain URDF that holds no robot: see :func:`fragment_shaped`;
    none for any other file), and, when none does, the models that may include it through
    a file name computed from their arguments (:class:`Maybe`). Asked only of a model that
    cannot be read alone without an error, which may be a fragment of them (the search
    reads the repository or workspace around it)."""
    packages = packages if packages is not None else PackageIndex()
    index: Index | None = None
    candidates_of: dict[tuple, list[Path]] = {}

    def includers(path: str) -> tuple[list[Target], tuple[Maybe, ...]]:
        nonlocal index
        if path == STDIN or not (path.endswith(".xacro") or fragment_shaped(path)):
            return [], ()
        config = config_for(path)
        index = index or Index(config.package_paths + package_paths, packages, files)
        file = Path(path).resolve()
        targets = _includers(file, index, config, config_for, packages, candidates_of)
        return targets, () if targets else _computing_includers(file, index, config, config_for, packages, candidates_of)

    return includers


def _candidates(file: Path, index: Index, config, packages: PackageIndex, candidates_of: dict) -> list[Path]:
    """The top-level models of the repository or workspace around ``file``, and those
    ``[tool.urdfcli] models`` lists (not ``file`` itself)."""
    roots, recursive = search_roots(file, packages)
    key = (tuple(roots), recursive)
    if key not in candidates_of:
        candidates_of[key] = index.top_level_models(index.scan(roots, recursive))
    candidates = list(candidates_of[key])
    for model, _ in config.models:
        if model not in candidates and model.is_file():
            candidates.append(model)
    return [model for model in candidates if model != file]


def _includers(file: Path, index: Index, config, config_for, packages: PackageIndex, candidates_of: dict) -> list[Target]:
    """The runs of the models around ``file`` (see :func:`_candidates`) whose expansion may read it."""
    targets: list[Target] = []
    for model in _candidates(file, index, config, packages, candidates_of):
        sets = config_for(str(model)).argument_sets(str(model))
        if any(index.reaches(model, file, arguments) for arguments in (sets or [None])):
            targets += model_targets(shown(model), sets)
    return targets


_READS = re.compile(r"\$\(\s*(optenv|env|arg)\s+([^\s()]+)([^()]*)\)")
_FALSE = ("", "0", "false", "False")


def _gates(library: Path, macros: tuple[str, ...], targets: list[Target], index: Index) -> Gates:
    """What the models of ``targets`` read to decide whether to read ``library`` and whether
    to call its ``macros``: the substitutions of the xacro:if and xacro:unless around each
    include leading to it and each call of its macros (up to the macro body holding it,
    whose own callers decide), and those of the include's file name."""
    include: dict[tuple[Gate, ...], None] = {}
    call: dict[tuple[Gate, ...], None] = {}
    names = set(macros)
    for model in dict.fromkeys(Path(t.path).resolve() for t in targets):
        reached, _ = index.reachable(model)
        files = [model, *sorted(reached)]
        leading = {library}  # the files whose expansion reads the library
        grown = True
        while grown:
            grown = False
            for file in files:
                if file not in leading and any(i.may_be(target) for i in index.includes(file) for target in leading):
                    leading.add(file)
                    grown = True
        for file in files:
            found = index.files.get(shown(file))
            if found is None or found.tree is None or file == library:
                continue
            properties = dict(index.source(file).properties)
            includes = iter(index.includes(file))
            for element in found.tree.iter():
                if not is_xacro(element):
                    continue
                local = local_name(element.tag)
                if local == "include" and element.get("filename"):
                    leads = next(includes, None)
                    if leads is not None and any(leads.may_be(target) for target in leading):
                        include[tuple(dict.fromkeys(_conditions(element, properties) + _read_by(element.get("filename"), properties, shown(library))))] = None
                elif (element.get("macro", "") if local == "call" else "" if local in DIRECTIVES else local).rpartition(".")[2] in names:
                    call[tuple(dict.fromkeys(_conditions(element, properties)))] = None
    return Gates(tuple(way for way in include if way), tuple(way for way in call if way))


def _conditions(element, properties: dict[str, str]) -> list[tuple[str, str, str]]:
    """The gates of the xacro:if and xacro:unless around an element, up to a macro body, outermost first."""
    found: list[Gate] = []
    for around in element.iterancestors():
        if not is_xacro(around):
            continue
        local = local_name(around.tag)
        if local == "macro":
            break
        if local in ("if", "unless"):
            found[:0] = _read_by(around.get("value") or "", properties, "1" if local == "if" else "0")
    return found


def _read_by(text: str, properties: dict[str, str], opening: str) -> list[tuple[str, str, str]]:
    """The environment variables and arguments ``text`` reads, directly or through a
    property's value, with the value that opens the gate: ``opening`` when the text is the
    substitution alone, "" when it is computed from it. For a condition ("1" or "0"),
    an optional variable whose default already opens it needs no value: it is left out."""
    text = text.strip()
    found = []
    property_ = re.fullmatch(r"\$\{\s*([A-Za-z_]\w*)\s*\}", text)
    if property_ is not None and property_.group(1) in properties:
        text = properties[property_.group(1)].strip()  # ${use_laser}: what the property reads
    for match in _READS.finditer(text):
        function, name, default = match.group(1), match.group(2), match.group(3).strip()
        alone = match.group(0) == text
        if alone and opening in ("1", "0") and function == "optenv" and (default in _FALSE) == (opening == "0"):
            continue  # its default opens it
        found.append(("arg" if function == "arg" else "env", name, opening if alone else ""))
    return found


def _computing_includers(file: Path, index: Index, config, config_for, packages: PackageIndex, candidates_of: dict) -> tuple[Maybe, ...]:
    """The models around ``file`` with an include whose file name is computed from their
    arguments and may be ``file`` with other values: Interbotix's
    ``$(find ...)/urdf/${robot_model}.urdf.xacro``, where the default robot_model names another
    file. The search resolves an argument to its default; here it stays open."""
    found = []
    for model in _candidates(file, index, config, packages, candidates_of):
        reached, _ = index.reachable(model)
        for source in (index.source(path) for path in (model, *sorted(reached))):
            written = _computed_include(source, file, index)
            if written is not None:
                runs = tuple(model_targets(shown(model), config_for(str(model)).argument_sets(str(model))))
                found.append(Maybe(shown(model), written, runs, _naming_argument(written, dict(source.properties), file.name)))
                break
    return tuple(found)


def _computed_include(source: WorkspaceFile, file: Path, index: Index) -> str | None:
    """The first include of ``source`` whose file name its arguments compute and may be ``file``."""
    # what its arguments compute is left open; other properties are what they are
    open_source = source._replace(arguments=(), properties=tuple((k, v) for k, v in source.properties if "$(arg" not in v))
    for written in source.includes:
        if COMPUTED.search(written.replace("\\", "/").rpartition("/")[2]) and resolve_include(written, open_source, index.finder(source.path)).may_be(file):
            return written
    return None




def _naming_argument(written: str, properties: dict[str, str], name: str) -> tuple[str, str] | None:
    """The xacro argument, and its value, with which an include computing one part of its
    file name (``$(arg x)``, or ``${p}`` of a property ``p`` that is ``$(arg x)``) names ``name``."""
    written_name = written.replace("\\", "/").rpartition("/")[2]
    computed = COMPUTED.findall(written_name)
    if len(computed) != 1:
        return None
    before, after = COMPUTED.split(written_name)
    value = re.fullmatch(re.escape(before) + "(.+)" + re.escape(after), name)
    token = computed[0]
    if token.startswith("${"):
        token = properties.get(token[2:-1].strip(), "").strip()
    argument = ARGUMENT.fullmatch(token)
    return (argument.group(1), value.group(1)) if argument and value else None


def _same(file: str, library: Path) -> bool:
    try:
        return Path(file).resolve() == library
    except OSError:
        return False


def _same_input(file: str, path: str) -> bool:
    """Whether a diagnostic's file is the input ``path``: by name, else resolved."""
    if path == STDIN:
        return file == "<stdin>"
    return file == path or _same(file, Path(path).resolve())


def _key(diagnostic: Diagnostic) -> tuple:
    """What one mistake says wherever it is found: a macro's, in each model calling it, whatever links it names."""
    location = diagnostic.location
    return (diagnostic.code, location.file, location.line, location.column, unnamed(diagnostic))


# What a model's part read alone reports of the context its includer gives it: a name or
# argument not defined (X003), a link of the includer's (J005), no name or no link of its own.
MISSING_CONTEXT = frozenset(rule.code for rule in (structure.X003, joint_link_not_found.rule, structure.R002, structure.R004))
UNDEFINED = frozenset(rule.code for rule in (structure.X003, joint_link_not_found.rule))  # a name, or a link, its includer defines


def assemble(
    entries: list[Entry], outcome: Callable[[Target], Result | Unreadable],
    includers: Callable[[str], tuple[list[Target], tuple[Maybe, ...]]] = lambda path: ([], ()),
    generated_from: Callable[[str], Path | None] = lambda path: None, real_path: Callable[[Path], Path] = Path.resolve,
) -> tuple[list[Result], list[Unreadable]]:
    """The results to show, in the order the files were given, and the reasons
    some inputs could not be read.

    ``outcome(target)`` runs a target (once: the caller remembers), giving its
    result or the one-line reason it could not be read. A diagnostic
    located in another file than the result's own, already shown for an
    earlier result, is not shown again: a library shared by three models
    reports its mistakes once. A xacro model with an error of a missing
    context (:data:`MISSING_CONTEXT`) is asked ``includers(path)``: when other
    models include it, it is a fragment of them, and is checked through them
    instead (its missing context is no mistake; its own mistakes are found there too). ``generated_from(path)`` names the
    xacro source a generated URDF was made from: what a model reading that source
    found is not said again at the copy. ``real_path`` is ``Path.resolve``, or the
    session's, which asks the disk once a file.
    """
    models = [outcome(target) for entry in entries if not entry.library for target in entry.targets]
    runs = {target: outcome(target) for entry in entries if not entry.library for target in entry.targets}
    resolved = _resolver(real_path)
    readers = _readers(runs, resolved)
    unused = _unused_in_all([m for m in models if isinstance(m, Result)], resolved)
    at_source = _found_at_sources([m for m in models if isinstance(m, Result)], generated_from, resolved)
    results, unreadable, shown_keys = [], [], set()
    for entry in entries:
        if not entry.library:
            for target in entry.targets:
                result = outcome(target)
                if isinstance(result, Unreadable):
                    unreadable.append(result)
                    continue
                missing = any(d.code in MISSING_CONTEXT for d in result.errors)
                through, maybe = includers(entry.path) if missing else ([], ())
                # a model of this run whose expansion read it (an include the search could not follow)
                read_by = [] if through or not missing or not part_of_model(entry.path) else readers(entry.path)
                if through or read_by:  # a fragment: read where its context is given
                    fragment = entry._replace(targets=through or read_by, library=True)
                    results.append(_library_result(fragment, outcome, shown_keys, unreadable, resolved, fragment=True, theirs=bool(read_by)))
                    break
                only_missing = missing and all(d.code in MISSING_CONTEXT for d in result.errors)  # else its own mistakes are said
                if only_missing and any(d.code in UNDEFINED or d.code == structure.R004.code for d in result.errors) and entry.path.endswith(".xacro") and fragment_shaped(entry.path):
                    # a xacro part nothing here includes: a name or a link its includer gives is missing, or it makes no link at all
                    # (an empty plain URDF nothing includes is a robot that failed, as check_urdf says: example-robot-data's ur3.urdf)
                    why = next((d.message for d in result.errors if d.code in UNDEFINED), "it makes no link")
                    notes = tuple(_may_include(m, outcome, fragment=True) for m in maybe) or (f"a fragment (its <robot> has no name) that no model includes: not checked ({why})",)
                    results.append(Result(entry.path, library=Library((), notes, unchecked=True, fragment=True)))
                    break
                is_own = functools.cache(lambda file, path=entry.path: _same_input(file, path))
                copied = at_source(result)
                shown_now = tuple(
                    d if is_own(d.path) or len(models) == 1 else _through(d, result)  # one model: it found them all
                    for d in result.diagnostics
                    if unused(d) and (d.code, d.message) not in copied and _fresh(d, is_own(d.path), shown_keys, entry.path)
                )
                failed = any(d.severity is Severity.ERROR for d in result.diagnostics if unused(d))
                results.append(result.but(diagnostics=shown_now, failed=failed))
            continue
        results.append(_library_result(entry, outcome, shown_keys, unreadable, resolved))
    return results, unreadable


def _found_at_sources(
    models: list[Result], generated_from: Callable[[str], Path | None], resolved: Callable[[str], Path]
) -> Callable[[Result], set[tuple[str, str]]]:
    """For a generated URDF whose xacro source another model of the run read, what
    that model found (code and message): said there, at the line of the source, and
    not again at the generated copy. What differs (a copy not generated again) stays."""
    readers: dict[Path, list[Result]] = {}
    for model in models:
        for file in (model.path, *model.includes):
            if file != STDIN:
                readers.setdefault(resolved(file), []).append(model)
    found = {id(model): {(d.code, d.message) for d in model.diagnostics} for model in models}

    def copied(result: Result) -> set[tuple[str, str]]:
        source = generated_from(result.path)
        if source is None:
            return set()
        return {key for reader in readers.get(source, ()) if reader is not result for key in found[id(reader)]}

    return copied


def _readers(runs: dict[Target, Result | Unreadable], resolved: Callable[[str], Path]) -> Callable[[str], list[Target]]:
    """``readers(path)``: the runs of the models given whose expansion read ``path`` (not itself)."""
    read: dict[Path, list[Target]] = {}
    for target, result in runs.items():
        if isinstance(result, Result):
            for file in result.includes:
                read.setdefault(resolved(file), []).append(target)
    return lambda path: [t for t in read.get(resolved(path), []) if resolved(t.path) != resolved(path)] if path != STDIN else []


_ROBOT_START = re.compile(rb"<robot\b[^>]*>")
_MAKES = re.compile(rb"<(?:link|joint)\b")
_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)


def fragment_shaped(path: str) -> bool:
    """Whether a file is a part written for another file to include, not a robot: its
    <robot> has no name (a robot always has one). A plain URDF must also hold no <link>
    and no <joint>, such as Husky's empty.urdf placeholder: one that does is a robot
    missing its name, whoever includes it; so is one xacro generated (its header says
    so: example-robot-data's empty ur3.urdf), a model's output, never a part."""
    if path == STDIN or not path.endswith((".xacro", ".urdf")):
        return False
    try:
        with open(path, "rb") as stream:
            head = stream.read(1 << 16)
    except OSError:
        return False
    found = _ROBOT_START.search(head)
    if found is None or re.search(rb"\sname\s*=", found.group(0)) is not None:
        return False
    if path.endswith(".xacro"):
        return True
    return header_source(head) is None and (b"xacro" in head or _MAKES.search(_COMMENT.sub(b"", head)) is None)


def part_of_model(path: str) -> bool:
    """Whether a file that cannot be read alone may be a part of the models that read
    it: any xacro file; a plain URDF only when it holds no robot (:func:`fragment_shaped`)."""
    return path.endswith(".xacro") or fragment_shaped(path)


def _through(diagnostic: Diagnostic, model: Result) -> Diagnostic:
    """The diagnostic, saying which model found it: unless a macro call of its trace,
    written in that model, says so already (and no xacro arguments need naming)."""
    if not model.arguments and any(_same_input(call.file, model.path) for call in diagnostic.location.trace):
        return diagnostic
    return diagnostic._replace(model=model.label)


def _unused_in_all(models: list[Result], resolved: Callable[[str], Path]) -> Callable[[Diagnostic], bool]:
    """Whether to keep a diagnostic: a U001 only when every model of the run that
    read its file reports it. A noqa in a shared macro may silence something for
    one model and nothing for another; it is useless only when useless for all."""
    read: list[set[Path]] = []
    counts: dict[tuple, int] = {}
    for model in models:
        read.append({resolved(file) for file in (model.path, *model.includes)})
        for place in {_place(d, resolved) for d in model.diagnostics if d.code == UNUSED_SUPPRESSION.code}:
            counts[place] = counts.get(place, 0) + 1
    agreed = {place for place, count in counts.items() if count == sum(place[0] in files for files in read)}
    return lambda diagnostic: diagnostic.code != UNUSED_SUPPRESSION.code or _place(diagnostic, resolved) in agreed


def _resolver(real_path: Callable[[Path], Path] = Path.resolve) -> Callable[[str], Path]:
    """A file's real path (standard input stays as it is), each asked of ``real_path`` once."""
    return functools.cache(lambda file: real_path(Path(file)) if file != STDIN else Path(file))


def _place(diagnostic: Diagnostic, resolved: Callable[[str], Path]) -> tuple:
    return (resolved(diagnostic.path), *_key(diagnostic)[2:])


def _fresh(diagnostic: Diagnostic, in_own_file: bool, shown_keys: set, given: str | None = None) -> bool:
    """Whether to show a diagnostic: in the own file of its input (``given``) once for that
    input, however many argument sets it is run with; elsewhere the first time."""
    key = _key(diagnostic)
    seen = (given, key) if in_own_file else key
    if seen in shown_keys:
        return False
    shown_keys.update((key, seen))
    return True


def _library_result(
    entry: Entry, outcome, shown_keys: set, unreadable: list[Unreadable], resolved: Callable[[str], Path], fragment: bool = False,
    theirs: bool = False,
) -> Result:
    """A library's (or a fragment's) result: what the models that read it found in it, and
    what breaks them; a library no model could check is expanded on its own, a fragment never.
    ``theirs``: the models are inputs of the run too, which say what breaks them themselves."""
    library = Path(entry.path).resolve()
    checked_through: list[str] = []
    notes: list[str] = []  # why a model could not be used, or that none includes it
    found: list[Diagnostic] = []
    needing: list[str] = []  # models that include it but cannot be expanded without arguments
    example: Example | None = None  # the first of them and the argument it needs, for the hint
    unread: list[tuple[str, str]] = []  # models that expand but do not read it: (label, with which arguments)
    stopped: list[str] = []  # models whose expansion stopped at an error before reading it
    used: list[Result] = []  # the models it was checked through
    uncalled: list[str] = []  # models that read it but call none of its macros
    for target in entry.targets:
        model = outcome(target)
        if isinstance(model, Unreadable):
            notes.append(f"not checked through {target.label}: {model.reason}")
            continue
        if model.needs_argument is not None:  # the model cannot be expanded as it is: say how to make it, do not fail the library
            needing.append(f"{target.label} needs '{model.needs_argument}'")
            example = example or (target.path, ((f"{model.needs_argument}:=VALUE",),))
            notes.append(
                f"not checked through {target.label}: it needs xacro argument '{model.needs_argument}'; "
                "list the argument sets it is checked with in [tool.urdfcli] models"
            )
            continue
        missing = next((d for d in model.diagnostics if d.code == PACKAGE_NOT_FOUND.code and not _same(d.path, library)), None)
        if missing is not None:  # a package this machine lacks: the model cannot be expanded here
            notes.append(f"not checked through {target.label}: {missing.message}")
            continue
        reached = any(_same(f, library) for f in model.includes) or any(_same(d.path, library) for d in model.diagnostics)
        if not reached and model.robot is None and model.errors:  # its expansion stopped before it came to the include
            stopped.append(target.label)
            found += [] if theirs else [_through(d, model) for d in model.errors]  # what stopped it
            continue
        if not reached:  # an include under xacro:if, or a file name made from an argument
            unread.append((target.label, "the arguments it is checked with" if target.arguments else "its default arguments"))
            opening = entry.gates.arguments(reading=True, calling=False)
            example = example or ((target.path, ((), opening)) if opening else None)
            continue
        checked_through.append(target.label)
        used.append(model)
    called = {name.rpartition(".")[2] for model in used for name in model.called or ()}
    if entry.macros and used and all(model.called is not None for model in used) and not called & set(entry.macros):
        # it was read, but what it is for was not expanded: nothing in its macros was checked
        names = ", ".join(f"'{name}'" for name in entry.macros)
        for target in entry.targets:
            if target.label in checked_through:
                arguments = "the arguments it is checked with" if target.arguments else "its default arguments"
                uncalled.append(f"{target.label} reads it but calls none of its macros ({names}) with {arguments}")
                opening = entry.gates.arguments(reading=False, calling=True)
                example = example or ((target.path, ((), opening)) if opening else None)
        checked_through = []
    unused = _unused_in_all(used, resolved)
    for model in used:  # mistakes written in the library, and whatever breaks a model that uses it
        found += [_through(d, model) for d in model.diagnostics if unused(d) and (_same(d.path, library) or (d.severity is Severity.ERROR and not theirs))]
    # When models include it but none could check it, that is a gap (X006) the config closes.
    reasons = needing + [f"{label} does not read it with {arguments}" for label, arguments in unread] + uncalled
    reasons += [f"{label} stops at an error before reading it" for label in stopped]
    stopped_only = stopped[0] if stopped and len(reasons) == len(stopped) else None
    environment = entry.gates.environment(reading=bool(unread), calling=bool(uncalled))
    if not checked_through and fragment:
        if reasons:  # its X006 says why (the models that do not read it, or stop before), once
            said = outcome(Target(entry.path, alone=True, unchecked="; ".join(reasons), fragment=True, example=example, stopped=stopped_only))
            found += said.diagnostics if isinstance(said, Result) else ()
        else:
            notes.append("a fragment of the models that include it (it cannot be read on its own), and none read it: not checked")
    elif not checked_through:  # checked on its own: its X006 says why, and what would check it
        alone = outcome(Target(entry.path, alone=True, unchecked="; ".join(reasons), example=example, environment=environment, stopped=stopped_only))
        if isinstance(alone, Unreadable):
            unreadable.append(alone)
        else:
            found += alone.diagnostics
            notes += [_may_include(maybe, outcome) for maybe in entry.maybe]
            if not entry.targets and not entry.maybe and all(d.severity is Severity.INFO for d in alone.diagnostics):  # its own mistakes say enough
                notes.append("a xacro library that no model includes: checked on its own (its xacro, and its macros as written)")
    # One mistake written in a macro shows once, however many calls and models
    # made copies of it (the messages differ only by the names the calls gave).
    places = set()
    diagnostics = []
    for diagnostic in sorted(found, key=Diagnostic.sort_key):
        place = _key(diagnostic)[:4]
        if place not in places:
            places.add(place)
            if _fresh(diagnostic, False, shown_keys):
                diagnostics.append(diagnostic)
    read = tuple(dict.fromkeys(file for model in used for file in (model.path, *model.includes)))
    return Result(entry.path, tuple(diagnostics), library=Library(tuple(checked_through), tuple(notes), fragment=fragment, read=read))


def _toml_sets(sets: tuple[tuple[str, ...], ...]) -> str:
    """Argument sets as TOML writes them: ``[[], ["hand:=true"]]``."""
    return "[" + ", ".join("[" + ", ".join(f'"{assignment}"' for assignment in one) + "]" for one in sets) + "]"


def _may_include(maybe: Maybe, outcome, fragment: bool = False) -> str:
    """The note for a model that may include a library (or a ``fragment``, which is then not
    checked at all) through a computed file name: why it did not (it did not expand, or read
    another file), and the setting that makes it."""
    run = outcome(maybe.runs[0])
    arguments = "the arguments it is checked with" if maybe.runs[0].arguments else "its default arguments"
    if isinstance(run, Unreadable):
        why = f"cannot be read ({run.reason})"
    elif run.needs_argument is not None:
        why = f"needs xacro argument '{run.needs_argument}'"
    elif run.robot_name is None and run.errors:
        why = f"did not expand with {arguments} ({run.errors[0].message})"
    else:
        why = f"reads another file with {arguments}"
    example = f'models, e.g. models = {{ "{maybe.model}" = [["{maybe.argument[0]}:={maybe.argument[1]}"]] }} (paths from the configuration\'s folder)' if maybe.argument else "models"
    return (
        f"may be included by {maybe.model} through '{maybe.written}', a file name computed from what it is given, "
        f"and that model {why}: {'not checked' if fragment else 'checked on its own'}; list the argument sets it is checked with in [tool.urdfcli] {example}"
    )


def unchecked_library(
    path: str, unchecked: str, fragment: bool = False, example: Example | None = None, environment: tuple[tuple[str, ...], ...] = (),
    stopped: str | None = None,
) -> Diagnostic:
    """X006: a library (or a fragment, which cannot be read alone) that no model including it
    could check; ``example``: a model that includes it and the argument sets that would check
    it (the argument it needs; its default set and the one that makes it read the library), for the hint;
    ``environment``: the ways environment variables make its models use it (NAME=VALUE
    each), which no argument set can give (``[tool.urdfcli] models`` sets xacro arguments only);
    ``stopped``: the model whose expansion stopped at an error before reading it, the only reason."""
    what = "xacro fragment not checked" if fragment else "xacro library checked on its own only"
    model, sets = example if example is not None else ("urdf/robot.urdf.xacro", (("name:=VALUE",),))
    if stopped is not None:
        hint = f"correct the error that stops the expansion of {stopped}, then check again"
    elif environment:
        others = "".join(f" (or {' '.join(way)})" for way in environment[1:3])
        hint = f"its models use it only under environment variables, which argument sets cannot set: check with them set, e.g. {' '.join(environment[0])} urdfcli lint {path}{others}"
    else:
        hint = f'list their argument sets in [tool.urdfcli] models (paths from the configuration\'s folder), e.g. models = {{ "{model}" = {_toml_sets(sets)} }}'
    return Diagnostic("X006", f"{what}: no model that includes it could check it ({unchecked})", Location("<stdin>" if path == STDIN else path), hint=hint)


__all__ = [
    "Aside", "Entry", "Index", "Models", "Target", "WorkspaceFile", "assemble", "fragment_includers", "plan", "resolve_include", "search_roots",
    "substitute", "unchecked_library", "workspace_file", "xacro_sources",
]
