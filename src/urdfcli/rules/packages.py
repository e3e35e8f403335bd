"""Rules on the package around a model: what its files use and its package.xml declares."""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from ..diagnostics import Diagnostic, Edit, Fix, Location
from ..model.sources import chain, parameters
from ..read.packages import named_package, uri_package
from ..read.xacro_scan import shown
from .base import SAFE, WARNING, Kind, RuleSet, check

_VARIABLE = re.compile(r"\$\{\s*(\w+)\s*\}")


def _uses(loaded) -> Iterator[tuple[str, str, str, Callable[[], Location]]]:
    """(file, package, path, where) for every package a file of the model
    names with a plain name, and the path written after it: the xacro sources read
    statically (conditions and uncalled macros included), or a plain URDF's meshes
    and textures. ``where`` is worked out only for the use reported."""
    if loaded.document.is_xacro:
        sources = loaded.xacro_sources
        own = {file.name for file in sources.files}
        for file in sources.files:
            for use in file.packages:
                if use.package and "$" not in use.package:
                    yield file.name, use.package, use.path, functools.partial(_at, file, use.place)
                else:  # a macro's parameter: each call names the package, where every call gives a plain name
                    for package, where, place in _given(sources, file, use):
                        if where.name in own:
                            yield where.name, package, use.path, functools.partial(_at, where, place)
    elif loaded.modelled:
        for at, _, uri in loaded.robot.resources:
            package = uri_package(uri)
            if package:
                yield loaded.document.shown, package, uri.partition(f"package://{package}")[2], functools.partial(loaded.document.locate, at)


def _in_own_package(owner: Path, paths: list[str]) -> bool:
    """Whether a path written after a package's name names a file of the package at
    ``owner``: its own package under a name it no longer has (op3_description's
    ``$(find robotis_op3_description)/urdf/robotis_op3.visuals.xacro``)."""
    return any(path.strip("/") and "$" not in path and (owner / path.strip("/")).is_file() for path in paths)


def _given(sources, file, use) -> list:
    """For ``$(find ${name})`` or ``package://${name}/`` in a macro whose parameter
    ``name`` every call gives as a plain name: (package, file, place) for each call
    (empty when one call computes it, or nothing calls the macro). A value with a folder
    (``pkg/sub`` for ``package://${name}/meshes``) names the package before its ``/``."""
    variable = _VARIABLE.fullmatch(use.package)
    if variable is None or use.macro is None or not sources.complete:
        return []
    name = variable.group(1)
    macro = next((m for m in chain(file, use.macro) if any(p.name == name for p in parameters(file, m))), None)
    given = (sources.given_by_calls(file, macro, name) or []) if macro is not None else []
    return [(named_package(value), where, place) for value, where, place in given]


def _at(file, place) -> Location:
    line, column = file.position(place)
    return Location(file.name, line, column)


@check("P001", "package-dependency-undeclared", WARNING, "A file uses a package that its package.xml does not declare.", kind=Kind.SOURCES, rule_set=RuleSet.LINT, fix=SAFE, fix_doc="Adds the dependency to package.xml, after its last dependency of the same kind and in its indentation "
       "(safe: a declaration; `exec_depend`, or `run_depend` in a format 1 manifest: the model's files are read where it is expanded and loaded, not to build).")
def dependency_undeclared(loaded, given) -> Iterator[Diagnostic]:
    """## What it does
    For each file of the model that belongs to a package (a `package.xml` in
    its folder or above), reads every `$(find NAME)`, `file://$(find NAME)` and
    `package://NAME/` it writes, under `xacro:if` and `xacro:unless` too (a
    condition does not install a package), and flags a package that is
    neither the file's own nor declared in its `package.xml` as `depend`,
    `exec_depend`, `build_export_depend`, `build_depend`, `test_depend` (or
    format 1's `run_depend`). The hint gives the line to add: `<exec_depend>`
    (in a format 1 manifest, `<run_depend>`), for an included file as for a
    mesh: both are read where the model is expanded and loaded (a launch file,
    rviz), not when the package builds, and a build dependency between two
    description packages that use each other's files (a robot's and its
    grippers') is a cycle that stops catkin. One diagnostic per file and
    package, at its first use. A package named by a macro's parameter (`$(find ${pkg})`,
    `package://${pkg}/`) is named by each call: when every call in the
    workspace gives a plain name (or leaves the plain default), each is judged
    where it is written (a value carrying a folder too, `my_robot/arm` before
    `/meshes/`, names the package before its `/`). Any other variable is left alone. A package that cannot
    be found here is flagged too (X004 and D005 say it is missing; this, that a
    fresh workspace would not install it either), unless it is the name of the
    file's own package folder: that is the package itself, named by its folder
    instead of its `<name>` (D005 says which to write), or a name that no package
    has whose path names a file of the file's own package (a package renamed,
    its files still naming the old name): declaring a dependency on it would only
    make rosdep fail on a key nobody provides. A package that itself depends on the
    file's package (a bringup package whose config a description's `<gazebo>` block
    names) cannot be declared: the message says so, and no line is offered.

    ## Why is this bad?
    It works where the package happens to be installed, and breaks in a fresh
    workspace, on the build farm, in a Docker image: rosdep installs only the
    dependencies a package declares.

    ## Example
    ```xml
    <!-- my_robot/package.xml -->
    <package format="3">
      <name>my_robot</name>
    </package>
    <!-- my_robot/urdf/robot.urdf.xacro -->
    <mesh filename="package://robot_meshes/meshes/arm.stl"/>
    ```

    ## Use instead
    ```xml
    <!-- my_robot/package.xml -->
    <package format="3">
      <name>my_robot</name>
      <exec_depend>robot_meshes</exec_depend>
    </package>
    ```
    """
    index = loaded.resolver.index
    reported: dict[tuple[str, str], list] = {}
    for file, package, path, where in _uses(loaded):
        key = (file, package)
        if key in reported:
            reported[key][0] += 1
            reported[key][2].append(path)
            continue
        reported[key] = [0, where, [path]]
    for (file, package), (others, where, paths) in reported.items():
        owner = index.enclosing_package(index.real_path(Path(file)).parent) if not file.startswith("<") else None
        manifest = index.manifest(owner / "package.xml") if owner is not None else None
        if manifest is None or manifest.name in (None, package) or package in manifest.dependencies:
            continue
        folder = loaded.resolver.find(package)
        if folder is not None and folder.resolve() == owner:
            continue  # its own, under another name (-P NAME=DIR)
        if folder is None and owner.name == package:
            continue  # its own, by its folder's name: D005 says which name to write, no dependency is missing
        if folder is None and _in_own_package(owner, paths):
            continue  # its own, by another name (X004 or D005 says it is not found): a dependency on that name would only make rosdep fail
        more = f" (and {others} more use{'s' if others > 1 else ''} in this file)" if others else ""
        name = shown(owner / "package.xml")
        used = index.manifest(folder / "package.xml") if folder is not None else None
        if used is not None and manifest.name in used.dependencies:
            yield Diagnostic(
                "P001",
                f"package '{package}' is used here{more} but {manifest.name}'s package.xml cannot declare it: {package} depends on {manifest.name}",
                where(),
                hint=f"declaring it would make a dependency cycle, which colcon refuses to order: move what is used into {manifest.name}, or let {package} pass it in as a xacro argument",
            )
            continue
        fix = declaration(loaded.document.files.get(name), name, package)
        yield Diagnostic(
            "P001",
            f"package '{package}' is used here{more} but {manifest.name}'s package.xml does not declare it",
            where(),
            hint=f"{fix.title}: rosdep installs only declared dependencies",  # (a format 1 manifest's tags)
            fix=fix,
        )


_ELEMENT = re.compile(r"<(\w+)(?:\s[^>]*)?>[^<]*</\1\s*>|<(\w+)(?:\s[^>]*)?/>")
_FORMAT = re.compile(r"""<package\b[^>]*\bformat\s*=\s*["'](\d+)["']""")
_ALL_KINDS = ("depend", "exec_depend", "build_depend", "build_export_depend", "run_depend", "test_depend", "buildtool_depend", "buildtool_export_depend", "doc_depend")


def declaration(source, name: str, package: str) -> Fix:
    """The edit that declares ``package`` in the package.xml ``source`` (named ``name``)
    as a run-time dependency: ``<exec_depend>``, or ``<run_depend>`` in a format 1
    manifest. A file a model includes or meshes it loads are read where the model is
    expanded and shown (launch, rviz), not to build; a build dependency between two
    description packages that use each other's files is a cycle catkin stops on. The
    line goes after the last dependency of the same tag, else after the last
    dependency of any tag, else before ``<export>`` or ``</package>``, in the
    indentation there."""
    if source is None:
        return Fix(f"add <exec_depend>{package}</exec_depend> to {name}", SAFE, reason=f"{name} cannot be read")
    text = source.text
    version = _FORMAT.search(text)
    tag = "exec_depend" if version is not None and version.group(1) != "1" else "run_depend"
    markup = f"<{tag}>{package}</{tag}>"
    title = f"add {markup} to {name}"
    elements = [(m.group(1) or m.group(2), m) for m in _ELEMENT.finditer(text) if not _in_comment(text, m.start())]
    same = [m for found, m in elements if found == tag]
    any_kind = [m for found, m in elements if found in _ALL_KINDS]
    anchor = (same or any_kind or [None])[-1]
    if anchor is not None:
        line_end = text.find("\n", anchor.end())
        at = len(text) if line_end < 0 else line_end
        return Fix(title, SAFE, edits=(Edit(name, at, at, "\n" + _indentation(text, anchor.start()) + markup),))
    before = re.search(r"<export\b|</package\s*>", text)
    if before is None:
        return Fix(title, SAFE, reason=f"{name} has no </package> to write it before")
    line_start = text.rfind("\n", 0, before.start()) + 1
    own = _indentation(text, before.start())
    indent = own + "  " if text[before.start():before.start() + 2] == "</" else own
    if text[line_start:before.start()].strip():
        return Fix(title, SAFE, edits=(Edit(name, before.start(), before.start(), markup + "\n" + own),))
    return Fix(title, SAFE, edits=(Edit(name, line_start, line_start, indent + markup + "\n"),))


def _in_comment(text: str, at: int) -> bool:
    opened = text.rfind("<!--", 0, at)
    return opened >= 0 and text.find("-->", opened, at) < 0


def _indentation(text: str, at: int) -> str:
    line_start = text.rfind("\n", 0, at) + 1
    before = text[line_start:at]
    return before[: len(before) - len(before.lstrip())]


__all__ = ["dependency_undeclared"]
