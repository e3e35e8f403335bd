"""Find ROS packages without ROS: `$(find pkg)` and `package://pkg/...`.

Sources are searched in this order, each scanned only when an earlier one
did not have the package:

1. ``-P/--package-path`` options: ``NAME=DIR``, or a directory scanned for
   ``package.xml`` files;
2. ``ROS_PACKAGE_PATH`` (directories scanned);
3. ``AMENT_PREFIX_PATH`` (``PREFIX/share/NAME``), then the ``install/`` space of the
   colcon workspace the input is in;
4. the package holding the input file;
5. its siblings in the repository (the nearest folder above it holding
   ``.git``), or in the workspace ``src/`` folder when that comes first (for a
   file in no package, such as a robot's setup folder in ``ws/src/``, the
   packages of the repository or workspace ``src/`` holding it);
6. then, when that repository sits inside a workspace ``src/`` folder (each
   repository cloned into ``ws/src/``, as ``vcs import`` lays them out, or a
   repository that is a workspace of its own, ``ws/src/cell/src/pkg``), the
   packages of the whole workspace;
7. a fallback resolver, when one is given: for a copy of a repository at a git
   revision, where the workspace around the repository finds packages now.

A package's name is the ``<name>`` in its ``package.xml``, never its folder name.

A package the workspace builds is found in its ``install/`` space first, as ROS finds
it: a package may install its files to other folders than its sources
(``description/urdf`` to ``share/NAME/urdf``). But a file read there is read, reported
on and fixed at its source in the workspace's ``src/`` (:meth:`PackageResolver.source_of`):
the file a ``--symlink-install`` links to, or that a plain build copied.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable, Iterator
from functools import cached_property
from pathlib import Path
from typing import NamedTuple

from .folders import nearest
from .xml import XmlError, parse

SKIP_DIRS = {"build", "install", "log", "devel", "node_modules", "__pycache__", "site-packages"}
MAX_SCAN_DEPTH = 8
MAX_SCAN_DIRS = 20_000
IGNORE_MARKS = ("CATKIN_IGNORE", "COLCON_IGNORE")  # a folder holding either is left out, with all below it


class PackageError(ValueError):
    """A ``-P`` option that is not ``NAME=DIR`` or an existing directory."""


AMENT_INDEX = Path("share/ament_index/resource_index/packages")
"""Where a ROS 2 install prefix registers its packages, one empty file per name:
the name ``package://`` and ``$(find)`` resolve, which may differ from the source folder's."""


class PackageIndex:
    """What a session learns about packages, learnt once: each manifest's name,
    each folder's packages, each folder's enclosing package and sibling roots. A
    manifest or folder that changes on disk is read again. ``given()`` gives the texts
    that stand for files (absolute path -> bytes: an editor's unsaved buffers, the
    fixes not yet written), read for a package.xml instead of its file."""

    def __init__(self, given: Callable[[], dict[str, bytes]] = dict) -> None:
        self._given = given
        self._scans: dict[tuple[Path, int], list[tuple[str, Path]]] = {}
        self._enclosing: dict[Path, Path | None] = {}
        self._roots: dict[Path, list[Path]] = {}
        self._manifests: dict[tuple[str, int, int], Manifest | None] = {}
        self._real: dict[str, Path] = {}  # an absolute path -> its real path

    def __getstate__(self) -> dict:
        """What a copy in the xacro worker gets: the texts given stay here (the worker is given them itself)."""
        return {**self.__dict__, "_given": dict}

    def forget(self) -> None:
        """Look at the folders again: packages added, moved or removed on disk (each
        manifest is read again anyway when it changes)."""
        self._scans.clear()
        self._enclosing.clear()
        self._roots.clear()
        self._real.clear()

    def real_path(self, path: Path) -> Path:
        """``path.resolve()``, asked of the disk once: a run asks it of each input for its
        package, for its xacro source and among the other inputs, and of each file of the
        folders it lists. Each folder is resolved once (a dozen ``lstat`` calls), a name
        in it that is no link with one ``lstat``."""
        key = os.path.abspath(path)
        found = self._real.get(key)
        if found is None:
            parent = os.path.dirname(key)
            if parent == key or os.path.islink(key):
                found = Path(key).resolve()
            else:  # a name that is no link is where its folder really is: one lstat, the folder resolved once
                found = self.real_path(parent) / os.path.basename(key)
            self._real[key] = found
        return found

    def package_name(self, manifest: Path) -> str | None:
        """The ``<name>`` declared in a package.xml, or None when unreadable."""
        read = self.manifest(manifest)
        return read.name if read is not None else None

    def manifest(self, manifest: Path) -> Manifest | None:
        """What a package.xml declares (its name and dependencies), or None when unreadable."""
        given = self._given().get(os.path.abspath(manifest))
        if given is not None:
            key = (str(manifest), hash(given), -1)
            if key not in self._manifests:
                self._manifests[key] = manifest_of(given)
            return self._manifests[key]
        try:
            state = os.stat(manifest)
        except OSError:
            return None
        key = (str(manifest), state.st_mtime_ns, state.st_size)
        if key not in self._manifests:
            self._manifests[key] = read_manifest(manifest)
        return self._manifests[key]

    def scan(self, root: Path) -> list[tuple[str, Path]]:
        """(name, dir) for every package below root, without entering a package."""
        try:
            key = (root, os.stat(root).st_mtime_ns)
        except OSError:
            return []
        if key not in self._scans:
            self._scans[key] = list(_walk(root, self.package_name))
        return self._scans[key]

    def enclosing_package(self, start: Path) -> Path | None:
        """The nearest folder at or above ``start`` that holds a package.xml."""
        return nearest(start, _holds_package, self._enclosing)

    def local_roots(self, package_dir: Path) -> list[Path]:
        """The folders whose packages are siblings of package_dir, nearest first: the
        repository root or workspace ``src`` (whichever comes first), then a workspace
        ``src`` above that repository; else the package's own repository, or its parent folder."""
        if package_dir not in self._roots:
            self._roots[package_dir] = _local_roots(package_dir)
        return list(self._roots[package_dir])

    def loose_roots(self, folder: Path) -> list[Path]:
        """For a file in no package, in ``folder``: the folders whose packages it finds as a
        package's file there would, the repository or workspace ``src`` holding it (a robot's
        setup folder beside the packages in ``ws/src``); none when it is in neither."""
        key = folder / "package.xml"  # (a key no package folder has)
        if key not in self._roots:
            self._roots[key] = _roots_above([folder, *folder.parents])
        return list(self._roots[key])

    def resolver(self, options: Iterable[str] = (), input_file: Path | None = None, fallback: PackageResolver | None = None) -> PackageResolver:
        return PackageResolver(options, input_file, index=self, fallback=fallback)


def named_package(path: str) -> str:
    """The package the text after ``package://`` names: up to its first ``/``
    (``pkg/meshes/arm.stl``; a macro argument that carries a folder too, ``pkg/sub``)."""
    return path.split("/", 1)[0]


def uri_package(uri: str) -> str | None:
    """The package a ``package://`` URI names, or None for any other URI."""
    return named_package(uri[len("package://"):]) if uri.startswith("package://") else None


def cmake_lists(folder: Path) -> str | None:
    """The text of a package's CMakeLists.txt; None when it has none."""
    try:
        return (folder / "CMakeLists.txt").read_text(errors="replace")
    except OSError:
        return None


def cmake_project(folder: Path, text: str | None = None) -> str | None:
    """The ``project(NAME)`` of a package's CMakeLists.txt (``text``, when it was read
    already): the name ament_cmake installs and registers it under, whatever its
    package.xml says."""
    text = cmake_lists(folder) if text is None else text
    found = re.search(r"^\s*project\s*\(\s*([\w.+-]+)", text or "", re.MULTILINE | re.IGNORECASE)
    return found.group(1) if found else None


_INSTALL = re.compile(r"\binstall\s*\(([^()]*)\)", re.IGNORECASE)
# The words of install(DIRECTORY ...) that end its list of folders
_INSTALL_OPTIONS = frozenset((
    "DESTINATION", "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "PERMISSIONS", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS",
    "USE_SOURCE_PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "OPTIONAL", "MESSAGE_NEVER", "EXCLUDE_FROM_ALL", "TYPE",
))


def installed_folders(package: Path) -> Iterator[tuple[tuple[str, ...], tuple[str, ...]]]:
    """What a package's CMakeLists.txt installs to its share folder with
    ``install(DIRECTORY ... DESTINATION share/${PROJECT_NAME})``: each folder's path in the
    package, and its path below ``share/NAME`` (a folder written with a final ``/`` installs
    its contents). Folders and destinations written with other variables are left out."""
    text = cmake_lists(package)
    if text is None:
        return
    project = cmake_project(package, text)
    text = re.sub(r"#[^\n]*", "", text)
    for call in _INSTALL.finditer(text):
        words = [word.strip('"') for word in call.group(1).split()]
        upper = [word.upper() for word in words]
        if not words or upper[0] != "DIRECTORY" or "DESTINATION" not in upper:
            continue
        at = upper.index("DESTINATION")
        destination = words[at + 1].strip("/").split("/") if at + 1 < len(words) else []
        if destination[:1] != ["share"] or len(destination) < 2 or destination[1] not in ("${PROJECT_NAME}", project):
            continue
        below = tuple(destination[2:])
        folders = words[1:next((i for i in range(1, at) if upper[i] in _INSTALL_OPTIONS), at)]
        for folder in folders:
            parts = tuple(part for part in folder.split("/") if part not in ("", "."))
            if parts and "$" not in folder and not folder.startswith("/") and ".." not in parts:
                yield parts, below if folder.endswith("/") else below + parts[-1:]


def installed_source(package: Path, written: tuple[str, ...]) -> Path | None:
    """The file of ``package`` its install rules put at ``written`` below its share folder
    (ros2_control_demos installs ``description/ros2_control`` as ``ros2_control``), or None."""
    for source, target in installed_folders(package):
        if len(written) > len(target) and written[:len(target)] == target:
            found = package.joinpath(*source, *written[len(target):])
            if found.is_file():
                return found
    return None


def _holds_package(folder: Path) -> Path | None:
    return folder if (folder / "package.xml").is_file() else None


# The dependencies that make a package available where this one is built, run or
# tested (format 1 says run_depend for exec_depend). doc_depend and buildtool_depend do not.
DEPENDENCY_KINDS = ("depend", "exec_depend", "build_export_depend", "build_depend", "test_depend", "run_depend")


class Manifest(NamedTuple):
    """A package.xml: the package's name and the packages it declares it depends on."""

    name: str | None
    dependencies: frozenset[str]


def read_package_name(manifest: Path) -> str | None:
    """The ``<name>`` declared in a package.xml, or None when unreadable."""
    read = read_manifest(manifest)
    return read.name if read is not None else None


def read_manifest(manifest: Path) -> Manifest | None:
    """What a package.xml declares, or None when it cannot be read."""
    try:
        return manifest_of(manifest.read_bytes())
    except OSError:
        return None


def manifest_of(data: bytes) -> Manifest | None:
    """What the text of a package.xml declares, or None when it is not XML."""
    try:
        root = parse(data)
    except XmlError:
        return None
    name = (root.findtext("name") or "").strip() or None
    dependencies = {(element.text or "").strip() for kind in DEPENDENCY_KINDS for element in root.findall(kind)}
    return Manifest(name, frozenset(d for d in dependencies if d))


def _walk(root: Path, package_name) -> Iterator[tuple[str, Path]]:
    budget = MAX_SCAN_DIRS
    stack = [(root, 0)]
    while stack and budget > 0:
        folder, depth = stack.pop()
        budget -= 1
        manifest = folder / "package.xml"
        if manifest.is_file():
            name = package_name(manifest)
            if name:
                yield name, folder
            continue  # ROS packages do not nest
        if depth >= MAX_SCAN_DEPTH:
            continue
        try:
            with os.scandir(folder) as listing:  # (the entries know their type: no stat for each file)
                entries = list(listing)
            if marked_ignored(entries):
                continue
            children = sorted(
                (Path(entry.path) for entry in entries if not entry.name.startswith(".") and entry.name not in SKIP_DIRS and entry_is(entry.is_dir)),
                reverse=True,
            )
        except OSError:
            continue
        stack.extend((child, depth + 1) for child in children)


def marked_ignored(entries: list[os.DirEntry]) -> bool:
    """A folder's listing holds CATKIN_IGNORE or COLCON_IGNORE: the folder is left out, with
    all below it (told from the listing: no stat of two names in every folder)."""
    return any(entry.name in IGNORE_MARKS and os.path.exists(entry.path) for entry in entries)


def entry_is(test: Callable[[], bool]) -> bool:
    """A directory entry's type test (which follows a link, as Path's does); false when it cannot tell."""
    try:
        return test()
    except OSError:
        return False


def files_below(root: Path, wanted: Callable[[str], bool], recursive: bool = True) -> Iterator[Path]:
    """The files below a folder whose name is ``wanted``, skipping hidden, build and ignored folders."""
    budget = MAX_SCAN_DIRS
    stack = [root]
    while stack and budget > 0:
        folder = stack.pop()
        budget -= 1
        try:
            with os.scandir(folder) as listing:  # (the entries know their type: no stat for each mesh file)
                entries = sorted(listing, key=lambda entry: entry.name)
        except OSError:
            continue
        if folder != root and marked_ignored(entries):
            continue
        for entry in entries:
            name = entry.name
            if name.startswith("."):
                continue
            if wanted(name):
                if entry_is(entry.is_file):
                    yield folder / name
            elif recursive and name not in SKIP_DIRS and entry_is(entry.is_dir):
                stack.append(folder / name)


def common_tail(a: tuple[str, ...], b: tuple[str, ...]) -> int:
    """How many parts two paths end with in common."""
    count = 0
    for x, y in zip(reversed(a), reversed(b)):
        if x != y:
            break
        count += 1
    return count


def closest_file(package: Path, written: tuple[str, ...]) -> Path | None:
    """The file of ``package`` named as the path ``written`` (below the package's installed
    share folder) ends whose path ends the most like it, when no other ends as much like it
    and an install rule can have put it there; else None."""
    found = list(files_below(package, lambda name: name == written[-1]))
    ranked = sorted(found, key=lambda file: common_tail(file.parts, written), reverse=True)
    if not ranked or (len(ranked) > 1 and common_tail(ranked[0].parts, written) == common_tail(ranked[1].parts, written)):
        return None
    return ranked[0] if _installable(ranked[0].relative_to(package).parts, written) else None


def _installable(source: tuple[str, ...], written: tuple[str, ...]) -> bool:
    """Whether an install rule can put the file at ``source`` at ``written`` (both below
    their package): it copies a folder to another place (``description/urdf`` to ``urdf``,
    ``config`` to ``params``), so the folders before the paths' common end differ from the
    first; a path that only differs deeper down is another file (kortex_description's
    ``arms/gen3/7dof/urdf/X`` is not installed as ``arms/gen3/6dof/urdf/X``)."""
    shared = common_tail(source, written)
    return not (shared < len(source) and shared < len(written) and source[0] == written[0])


def _roots_above(folders: Iterable[Path]) -> list[Path]:
    """The repository root or workspace ``src`` among ``folders`` (a folder and those above
    it), whichever comes first, then a workspace ``src`` above that repository."""
    roots: list[Path] = []
    for folder in folders:
        if folder.name == "src":
            roots.append(folder)
            break
        if not roots and (folder / ".git").exists():
            roots.append(folder)
    if len(roots) == 1 and roots[0].name == "src" and (roots[0].parent / ".git").exists():
        # a workspace kept as a repository (repo/src/pkg), cloned into another workspace's
        # src/: colcon builds the packages of both, as it would those of repositories beside it
        roots += [outer for outer in roots[0].parent.parents if outer.name == "src"][:1]
    return roots


def _local_roots(package_dir: Path) -> list[Path]:
    roots = _roots_above(package_dir.parents)
    if roots:
        return roots
    # a repository that is one package, in no workspace: the folder holding it holds
    # other repositories, not its siblings
    return [package_dir] if (package_dir / ".git").exists() else [package_dir.parent]


class PackageResolver:
    def __init__(
        self, options: Iterable[str] = (), input_file: Path | None = None, env=None, index: PackageIndex | None = None,
        fallback: PackageResolver | None = None,
    ):
        env = os.environ if env is None else env
        self.index = index if index is not None else PackageIndex()
        self.fallback = fallback  # asked for what none of the places above holds
        self._explicit: dict[str, Path] = {}
        self._scan_roots: list[Path] = []
        for option in options:
            if "=" in option:
                name, _, folder = option.partition("=")
                if not name or not folder:
                    raise PackageError(f"--package-path {option!r}: expected NAME=DIR or DIR")
                if not Path(folder).expanduser().is_dir():
                    raise PackageError(f"--package-path {option!r}: {folder!r} is not a directory")
                self._explicit.setdefault(name, Path(folder).expanduser().resolve())
            else:
                folder = Path(option).expanduser()
                if not folder.is_dir():
                    raise PackageError(f"--package-path {option!r}: not a directory")
                if folder.resolve() not in self._scan_roots:
                    self._scan_roots.append(folder.resolve())
        self._scan_roots += [Path(p) for p in env.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
        self._ament = [Path(p) for p in env.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
        self._input_file = input_file
        self._found: dict[str, Path] = {}
        self._scanned: set[Path] = set()
        self._answers: dict[str, Path | None] = {}  # every look-up, found or not
        self._sources: dict[str, str] = {}  # each installed file asked for -> its source (a copy's is searched for)

    def settings(self) -> tuple:
        """Where it looks, as given: two resolvers of equal settings find the same packages."""
        fallback = self.fallback.settings() if self.fallback is not None else None
        return (tuple(self._explicit.items()), tuple(self._scan_roots), tuple(self._ament), self._input_file, fallback)

    @cached_property
    def _own(self) -> Path | None:
        """The package the input is in: looked for only when a look-up needs it."""
        return self.index.enclosing_package(self.index.real_path(self._input_file).parent) if self._input_file else None

    @cached_property
    def _local_roots(self) -> list[Path]:
        if self._own is not None:
            return self.index.local_roots(self._own)
        return self.index.loose_roots(self.index.real_path(self._input_file).parent) if self._input_file else []

    @cached_property
    def _workspace_source(self) -> Path | None:
        """The ``src/`` folder of the colcon workspace the input is in, or None."""
        return next((root for root in self._local_roots if root.name == "src"), None)

    @cached_property
    def _workspace_prefixes(self) -> list[Path]:
        """The install space of the colcon workspace the input is in (merged, or one
        prefix per package): what ``source install/setup.bash`` would add."""
        source = self._workspace_source
        install = source.parent / "install" if source is not None else None
        if install is None or not install.is_dir():
            return []
        return [install, *sorted(p for p in install.iterdir() if (p / "share").is_dir())]

    def source_of(self, path: str) -> str:
        """The file of the workspace's ``src/`` that ``path``, a file of its ``install/``
        space, was installed from: the file the user edits, where diagnostics and fixes
        belong. ``colcon build --symlink-install`` links each installed file to its
        source; a plain build copies it to ``share/NAME/`` and its path below one of the
        package's folders (``install(DIRECTORY description/urdf DESTINATION
        share/${PROJECT_NAME})``): the source is the package's file of that name whose
        path ends most like it. Any other path, or a copy of no such file, is given back. A
        path of a package's sources that the package lacks (a workspace not built) is the
        file its install rules put there (:func:`installed_source`), if one does."""
        absolute = Path(os.path.abspath(path))
        if not absolute.is_file():  # (not kept: a build may make it)
            package = self.index.enclosing_package(absolute.parent)
            found = installed_source(package, absolute.relative_to(package).parts) if package is not None else None
            return str(found) if found is not None else path
        source = self._workspace_source
        if source is None:
            return path
        try:
            below = absolute.relative_to(source.parent / "install").parts
        except ValueError:
            return path
        if path not in self._sources:
            self._sources[path] = self._installed_from(absolute, below, source) or path
        return self._sources[path]

    def _installed_from(self, absolute: Path, below: tuple[str, ...], source: Path) -> str | None:
        """The source of the installed file ``absolute`` (``below`` the install space), or None."""
        real, real_source = self.index.real_path(absolute), self.index.real_path(source)
        if real.is_relative_to(real_source):  # a symlink install: the link says where
            return str(source / real.relative_to(real_source))
        share = next((at for at in (0, 1) if below[at:at + 1] == ("share",)), None)  # merged, or one prefix per package
        if share is None or len(below) < share + 3:
            return None
        package = self._source_package(below[share + 1])
        copied = closest_file(package, below[share + 2:]) if package is not None else None
        return str(copied) if copied is not None else None

    def _source_package(self, name: str) -> Path | None:
        """The folder in the workspace's ``src/`` of the package installed as ``name``: by its
        package.xml, else by the CMake project name it is installed under."""
        packages = self.index.scan(self._workspace_source)
        found = next((folder for package, folder in packages if package == name), None)
        return found if found is not None else next((folder for _, folder in packages if cmake_project(folder) == name), None)

    def where(self) -> str:
        """Where packages were looked for, as ``(looked in ...)`` for error messages."""
        places = list(dict.fromkeys(self._places()))  # -P and ROS_PACKAGE_PATH may name one folder
        if not places:
            return "(the input is not inside a package and no package path is set: use -P NAME=DIR)"
        return f"(looked in {', '.join(places)})"

    def _places(self) -> list[str]:
        places = [f"-P {name}={path}" for name, path in self._explicit.items()]
        places += [str(p) for p in self._scan_roots]
        places += [f"{p}/share" for p in self._ament + self._workspace_prefixes]
        places += [str(p) for p in self._local_roots]
        return places + (self.fallback._places() if self.fallback is not None else [])

    def _scan_into_cache(self, root: Path) -> None:
        if root in self._scanned:
            return
        self._scanned.add(root)
        for name, folder in self.index.scan(root):
            self._found.setdefault(name, folder)

    def find(self, name: str) -> Path | None:
        """The folder of package ``name``, or None; each name is looked up once."""
        if name not in self._answers:
            self._answers[name] = self._find(name)
        return self._answers[name]

    def _find(self, name: str) -> Path | None:
        if not name:  # package:///file: no look-up may answer it (PREFIX/share/ would)
            return None
        if name in self._explicit:
            return self._explicit[name]
        if name in self._found:
            return self._found[name]
        for root in self._scan_roots:
            self._scan_into_cache(root)
            if name in self._found:
                return self._found[name]
        for prefix in self._ament + self._workspace_prefixes:
            share = prefix / "share" / name
            if share.is_dir() or (prefix / AMENT_INDEX / name).is_file():
                return share
        if self._own is not None and self.index.package_name(self._own / "package.xml") == name:
            return self._own
        for root in self._local_roots:  # the repository first, the whole workspace only when needed
            self._scan_into_cache(root)
            if name in self._found:
                break
        found = self._found.get(name)
        return found if found is not None or self.fallback is None else self.fallback.find(name)

    def workspace_of(self, path: Path) -> Path | None:
        """The input's repository or workspace ``src`` folder that holds ``path`` (which need
        not exist), or None: a path of this machine, not of another one."""
        return next((root for root in self._local_roots if path.is_relative_to(root)), None)

    def misnamed(self, name: str) -> tuple[Path, str] | None:
        """A folder called ``name``, among the packages looked at, whose package.xml
        gives another name: (folder, that name). What a look-up by folder name missed."""
        known = list(self._found.items())
        if self._own is not None:
            known.append((self.index.package_name(self._own / "package.xml") or "", self._own))
        for package, folder in known:
            if name and package and folder.name == name and package != name:
                return folder, package
        return self.fallback.misnamed(name) if self.fallback is not None else None

    def resolve_uri(self, uri: str, base_dir: Path | None = None) -> Path | None:
        """The file on disk a mesh or texture URI names; never fetched from a network."""
        from urllib.parse import unquote, urlparse  # (here: xacro's worker looks up packages, not URIs)

        parsed = urlparse(uri)
        if parsed.scheme == "package":
            folder = self.find(parsed.netloc)
            if folder is None:
                return None
            path = folder / unquote(parsed.path.lstrip("/"))
            return path if path.exists() else Path(self.source_of(str(path)))  # (before a build: where its install rules take it from)
        if parsed.scheme == "file":
            # file:///$(find pkg)/... expands to file:////opt/...: a system reads //opt as /opt, pathlib keeps both slashes
            return Path("/" + unquote(parsed.path).lstrip("/"))
        if parsed.scheme == "" or len(parsed.scheme) == 1:  # plain or Windows-style path
            path = Path(uri)
            return path if path.is_absolute() or base_dir is None else base_dir / path
        return None  # http, https, ...: never fetched
