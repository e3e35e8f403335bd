"""Which URDF an SRDF describes: the robot of the same name, nearest first.

MoveIt pairs an SRDF with the ``robot_description`` of the same robot. Without
a launch file to tell, the URDF is looked for by the robot's name: in the
SRDF's own package, then in the packages its package.xml depends on, then in
the repository or workspace around it (see :func:`urdfcli.project.workspace.search_roots`).
In each place the files nearest the SRDF come first (those of its own robot's
folder, where one package holds several robots), then one named as the SRDF is
(``solo.urdf`` for ``solo.srdf``), then a top-level model before a file another
one includes, and a xacro source before a generated URDF. A robot's name is read
from its ``<robot name=...>`` as written (``$(arg name)`` resolved from the
argument's default or the ``[tool.urdfcli] models`` setting), and confirmed by
loading the model. The URDF named as the SRDF in its robot's folder, or in a
package the SRDF's package depends on (a MoveIt config's robot package), is a
candidate whatever name it gives (``go2.urdf`` says ``go2_description``,
``sia20d.xacro`` ``motoman_sia20d``, and an SRDF copied from another variant
keeps that variant's name).

A MoveIt config names its URDF itself: the ``.setup_assistant`` file at the top of
its package gives the robot package, the file's path in it and the xacro arguments
(``xacro_args: gripper:=robotiq_2f_85 dof:=7``), from which moveit_configs_utils builds
the ``robot_description`` it pairs with the SRDF the file names (MoveIt 1's Setup
Assistant writes the same file with the keys in capitals: ``URDF:``, ``SRDF:``), unless the
config package holds ``config/ROBOT.urdf.xacro``, the model the Setup Assistant wrote around
that URDF to add ros2_control to it, which moveit_configs_utils loads instead. That URDF,
with those arguments, is tried before any other.

Of the candidates, a few at most are loaded (:data:`TRIES`), and the SRDF is
checked against the one that lacks the fewest of the link and joint names it
gives, the nearest first among equals: where several variants share a robot
name (``solo.urdf`` and ``solo12.urdf``, both ``solo``), the one the SRDF was
written for. When that one gives another robot name than the SRDF, a warning
says so. A URDF of the SRDF's package or of one it depends on comes before any other,
however many names it lacks (a link renamed in the robot's model, which another package's
robot of that name still has), and one that cannot be read (a xacro argument it needs)
is not stood in for by another package's, which the config does not load: the SRDF is
left unchecked, and the note says why.
``--urdf FILE`` names the URDF instead.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from ..diagnostics import Diagnostic, Severity
from ..model.load import Loaded
from ..model.srdf import SRDF_TAGS, Semantic, named_srdf
from ..read.xacro_scan import shown
from .workspace import Index, search_roots, source_files, substitute

SETUP_ASSISTANT = ".setup_assistant"  # MoveIt Setup Assistant's record of a config package's URDF and SRDF

_ROBOT_TAG = re.compile(r"<robot\b[^>]*?\bname\s*=\s*(['\"])(.*?)\1", re.DOTALL)
_SRDF_MARK = re.compile(r"<(" + "|".join(sorted(SRDF_TAGS)) + r")\b")
HEAD = 1 << 16  # the root's start tag is in the first 64 KiB of any real file
TRIES = 4  # candidates loaded at most, when the first ones turn out not to be the robot


def robot_name(file: Path, index: Index, arguments: dict[str, str]) -> str | None:
    """The robot name a URDF or xacro file gives as written, substitutions resolved
    where they can be; None for an SRDF, a file without one, or a name that stays computed."""
    name, semantic = _written_name(file, index, arguments)
    return None if semantic else name


def _written_name(file: Path, index: Index, arguments: dict[str, str]) -> tuple[str | None, bool]:
    """The robot name a file gives as written (None: none, or one that stays computed), and whether the file is an SRDF
    (or an SRDF's macros)."""
    try:
        with open(file, "rb") as stream:
            text = stream.read(HEAD).decode("utf-8", "replace")
    except OSError:
        return None, False
    semantic = bool(_SRDF_MARK.search(text)) and "<link" not in text
    found = _ROBOT_TAG.search(text)
    if found is None:
        return None, semantic
    name = found.group(2)
    if "$" in name:
        name = substitute(name, index.source(file), index.finder(file), arguments)
    return (name if "$" not in name else None), semantic


def describing(models: list[tuple[Path, dict[str, str]]], index: Index, arguments_for: Callable[[Path], dict[str, str]]) -> list[Path]:
    """The SRDFs of the repository or workspace around each model (with its xacro arguments)
    that describe its robot: named for it, or named as the model's file (``panda.srdf`` for
    ``panda.urdf.xacro``). A change to a model can break them: a link renamed that a
    planning group or a collision pair still names."""
    found: dict[Path, None] = {}
    for model, arguments in models:
        name = robot_name(model, index, arguments)
        roots, recursive = search_roots(model, index.packages)
        for file in (f.resolve() for f in index.scan(roots, recursive) if named_srdf(f.name)):
            if file in found:
                continue
            written, _ = _written_name(file, index, arguments_for(file))  # (an SRDF by its file name: ur.srdf.xacro only calls macros)
            if (name is not None and written == name) or _stem(file) == _stem(model):
                found[file] = None
    return list(found)


def candidates(srdf: Path, index: Index, arguments_for: Callable[[Path], dict[str, str]]) -> Iterator[tuple[Path, bool]]:
    """The URDF and xacro files that may describe the SRDF's robot, nearest first, each
    with whether it is of the SRDF's package or of one its package.xml depends on (a
    MoveIt config's robot package)."""
    folders: list[tuple[Path, bool, bool]] = []  # (folder, searched below it, the SRDF's package or a dependency)
    package = index.packages.enclosing_package(srdf.parent)
    if package is not None:
        folders.append((package, True, True))
        manifest = index.packages.manifest(package / "package.xml")
        find = index.finder(srdf)
        for dependency in sorted(manifest.dependencies if manifest is not None else ()):
            found = find(dependency)
            if found is not None:
                folders.append((found, True, True))
    roots, recursive = search_roots(srdf, index.packages)
    folders += [(root, recursive, False) for root in roots]
    seen: set[Path] = set()
    for folder, below, depended in folders:
        files = [f.resolve() for f in source_files(folder, below) if not named_srdf(f.name)]
        included = {Path(i.value) for f in files if f.name.endswith(".xacro") for i in index.includes(f) if i.kind == "path"}
        order = sorted(files, key=lambda f: (-_shared(f, srdf), _stem(f) != _stem(srdf), f in included, f.name.endswith(".urdf"), str(f)))
        for file in order:
            if file not in seen:
                seen.add(file)
                yield file, depended


def setup_assistant(srdf: Path, robot_name: str, index: Index) -> tuple[Path, dict[str, str]] | None:
    """The URDF, and its xacro arguments, that the ``.setup_assistant`` of the SRDF's
    package names for it; None when there is none, it names another SRDF, or its robot
    package cannot be found. When the Setup Assistant added to the URDF (ros2_control,
    ``modified_urdf``), it wrote ``config/ROBOT.urdf.xacro`` in the config package, which
    includes the robot package's model: moveit_configs_utils loads that one first."""
    package = index.packages.enclosing_package(srdf.parent)
    if package is None or not (package / SETUP_ASSISTANT).is_file():
        return None
    import yaml  # (only for a MoveIt config package)

    try:
        written = yaml.safe_load((package / SETUP_ASSISTANT).read_text(encoding="utf-8"))
        config = written["moveit_setup_assistant_config"]
        # MoveIt 1 writes the keys in capitals (URDF:, SRDF:), MoveIt 2 in lower case
        urdf, named_srdf = _either(config, "urdf"), _either(config, "srdf")["relative_path"]
        robot, relative = urdf["package"], urdf["relative_path"]
    except (OSError, UnicodeDecodeError, yaml.YAMLError, TypeError, KeyError):
        return None
    if not isinstance(named_srdf, str) or (package / named_srdf).resolve() != srdf:
        return None
    # moveit_configs_utils splits xacro_args at white space, each NAME:=VALUE
    arguments = dict(word.partition(":=")[::2] for word in str(urdf.get("xacro_args") or "").split() if ":=" in word)
    modified = package / "config" / f"{robot_name}.urdf.xacro"
    if modified.is_file():
        return modified.resolve(), arguments
    folder = index.finder(srdf)(str(robot))
    if folder is None or not isinstance(relative, str):
        return None
    return (folder / relative).resolve(), arguments


def _either(config: dict, key: str):
    """``config[key]``, written in lower case (MoveIt 2) or in capitals (MoveIt 1)."""
    return config[key] if key in config else config[key.upper()]


def _shared(file: Path, srdf: Path) -> int:
    """How many folders a file shares with the SRDF's path: the more, the nearer."""
    return len(Path(os.path.commonpath([file.parent, srdf.parent])).parts)


def _stem(file: Path) -> str:
    """A file's name without its suffixes: ``alex_psyonic_hands`` of ``alex_psyonic_hands.srdf.xacro``."""
    return file.name.split(".")[0]


def described(
    loaded: Loaded,
    index: Index,
    urdf: str | None,
    arguments_for: Callable[[Path], dict[str, str]],
    load: Callable[[str, dict[str, str]], Loaded | str],
) -> Diagnostic | None:
    """Find and load the URDF the SRDF ``loaded`` describes into ``loaded.described``;
    the K008 diagnostic that says why it could not be checked, or None.
    ``load(path, arguments)`` loads a model (or says in one line why it cannot)."""
    semantic = loaded.semantic
    name = semantic.name
    document = loaded.document
    if urdf is not None:
        found = load(urdf, arguments_for(Path(urdf)))
        if isinstance(found, str) or not found.modelled or not found.robot.links:
            why = found if isinstance(found, str) else _why(found)
            missing = None if isinstance(found, str) else found.document.missing_argument
            hint = _give_argument(missing) if missing else "give --urdf the URDF or xacro model of the robot"
            # asked for by name: a warning, the run fails (an info would pass with the SRDF unchecked)
            return _without(loaded, f"the URDF given with --urdf cannot be read: {why}", Severity.WARNING, hint)
        loaded.described = found
        if found.robot.name != name:
            # the user named this URDF: its robot's, unless the SRDF's names do not fit it (then K001/K002 say which)
            other = None if unknown_names(semantic, found) == 0 else f"give --urdf the URDF of robot '{name}'"
            return _named_otherwise(loaded, urdf, found, other)
        return None
    if name is None or document.file is None:
        return None
    srdf = document.file.resolve()
    # fits: (names the URDF lacks, order, path, model, of the SRDF's package or a dependency); failures: (order, why, of those)
    fits, failures, beside = [], [], False
    unread: list[Loaded | str] = []  # what each failure read
    named_by_config = setup_assistant(srdf, name, index)
    tried = None  # (file, arguments) of the URDF the .setup_assistant names, once read
    if named_by_config is not None:
        file, given = named_by_config
        path = shown(file)
        tried = (file, {**given, **arguments_for(file)})
        found = load(path, tried[1])
        if not isinstance(found, str) and found.modelled and found.robot.links:
            loaded.described = found
            return None if found.robot.name == name else _named_otherwise(loaded, f"{path}, which its {SETUP_ASSISTANT} names,", found)
        failures.append((-1, f"{path}, which its {SETUP_ASSISTANT} names: {found if isinstance(found, str) else _why(found)}", True))
        unread.append(found)
    for order, (file, depended) in enumerate(candidates(srdf, index, arguments_for)):
        arguments = arguments_for(file)
        if (file, arguments) == tried:
            continue  # read above as the .setup_assistant names it: the same failure, said once
        named = robot_name(file, index, arguments) == name
        if not named:
            if beside or _stem(file) != _stem(srdf) or not (depended or srdf.parent.parent in file.parents):
                continue
            # named as the SRDF, in its robot's folder or in a package its package depends on (motoman_sia20d_support's
            # sia20d.xacro for motoman_sia20d_moveit_config's sia20d.srdf): a candidate whatever either says its name is
            beside = True
        path = shown(file)
        found = load(path, arguments)
        if isinstance(found, str) or not found.modelled or (named and found.robot.name != name) or not found.robot.links:
            if not _library(found):
                failures.append((order, f"{path}: {found if isinstance(found, str) else _why(found)}", depended))
                unread.append(found)
        else:
            fits.append((unknown_names(semantic, found), order, path, found, depended))
            if fits[-1][0] == 0:
                break  # nothing later can fit better
        if len(fits) + len(failures) >= TRIES:
            break
    own = [fit for fit in fits if fit[4]]  # the config loads its robot from its own package or a dependency, never another's
    best = min(own or fits, key=lambda fit: fit[:2], default=None)
    nearer = [own for order, _, own in failures if best is not None and order < best[1]]  # the nearer URDFs that could not be read
    if nearer and (best[0] > 0 or (any(nearer) and not best[4])):
        # one that lacks some of the names is another variant's (UR's bare ur5.urdf for a cell's SRDF); one outside the
        # config's packages is another package's robot of that name (doosan-robot2's m1013 for doosan-robot's config)
        best = None
    if best is not None:
        _, _, path, found, _ = best
        loaded.described = found
        if found.robot.name != name:
            return _named_otherwise(loaded, f"{path}, named as it is,", found)
        return None
    if failures:
        return _without(loaded, f"the URDF of robot '{name}' could not be read ({'; '.join(why for _, why, _ in failures)}): the SRDF's names are not checked",
                        hint=_unread_hint(unread))
    return _without(loaded, f"no URDF of robot '{name}' found in the SRDF's package or workspace: its names are not checked",
                    hint="give the URDF with --urdf FILE")


def _unread_hint(unread: list[Loaded | str]) -> str:
    """What to do when no URDF of the robot could be read: give the packages they need when that is
    all that stopped them (TALOS's calibration package), else name the arguments or the URDF."""
    if unread and all(not isinstance(found, str) and any(d.code == "X004" for d in found.diagnostics) for found in unread):
        return "build and source the workspace that has the package, or give its folder with -P NAME=DIR (package-paths in [tool.urdfcli])"
    missing = {found.document.missing_argument for found in unread if not isinstance(found, str)}
    if len(unread) == 1 and None not in missing:
        return _give_argument(*missing)  # all it lacks is one argument: say which (doosan's m1013.urdf.xacro needs namespace:=)
    return "list its xacro arguments in [tool.urdfcli] models, or give --urdf FILE"


def _give_argument(name: str) -> str:
    return f"give {name}:=VALUE after the SRDF (the arguments are the URDF's too), or in [tool.urdfcli.xacro-args]"


def unknown_names(semantic: Semantic, model: Loaded) -> int:
    """How many of the link and joint names an SRDF gives a model lacks: the fewer, the better it fits."""
    links = {named.name for _, named in semantic.named_links()} | {named.name for pair in semantic.disabled for named in pair}
    links -= set(model.robot.links)
    joints = {named.name for _, named in semantic.named_joints()} - set(model.robot.joints) - semantic.own_joints
    return len(links) + len(joints)


def _library(found: Loaded | str) -> bool:
    """Whether a file read as a URDF is a library of macros: it expands to a robot without links."""
    return not isinstance(found, str) and found.modelled and not found.robot.links


def _why(found: Loaded) -> str:
    if found.document.missing_argument is not None:
        return f"it needs xacro argument '{found.document.missing_argument}'"
    error = next((d for d in found.diagnostics if d.severity is Severity.ERROR or d.code.startswith("X")), None)
    if error is not None:
        return error.message
    if _library(found):
        return "it expands to no link (a library of macros?)"
    return "it describes another robot" if found.modelled else "it holds no robot"


def _named_otherwise(loaded: Loaded, urdf: str, found: Loaded, other: str | None = None) -> Diagnostic:
    """K008 for the URDF the SRDF was checked against, whose robot has another name: a warning,
    since srdfdom's Model::initXml logs an error when the names differ (and loads the SRDF all the same).
    ``other``: the way out when the SRDF may be another robot's."""
    name, urdf_name = loaded.semantic.name, found.robot.name
    if urdf_name is None:  # a part another file includes (urdfdom refuses a robot without a name)
        return _without(loaded, f"the SRDF is for robot '{name}', but {urdf} gives its <robot> no name: checked against it", Severity.WARNING,
                        "check it against the model that includes this file, with --urdf FILE: MoveIt's URDF reader refuses a <robot> without a name")
    write = f"write <robot name=\"{urdf_name}\"> in the SRDF"
    hint = (f"{write}: MoveIt's SRDF reader logs an error when the names differ" if other is None
            else f"if the SRDF is for robot '{urdf_name}', {write} (MoveIt's SRDF reader logs an error when the names differ); else {other}")
    return _without(loaded, f"the SRDF is for robot '{name}', but {urdf} describes robot '{urdf_name}': checked against it", Severity.WARNING, hint)


def _without(loaded: Loaded, message: str, severity: Severity | None = None, hint: str | None = None) -> Diagnostic:
    diagnostic = loaded.diagnostic("K008", message, 0, hint or "give the URDF with --urdf FILE")
    return diagnostic._replace(severity=severity) if severity is not None else diagnostic


__all__ = ["candidates", "described", "describing", "robot_name", "unknown_names"]
