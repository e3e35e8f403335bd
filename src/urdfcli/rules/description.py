"""Description rules: the model loads, but something in it is misspelt, missing or points nowhere."""

from __future__ import annotations

import os
import re
from functools import partial

from ..diagnostics import Fix, SetAttribute
from ..model.kinematics import bodies
from ..model.meshes import input_folder, near_misses, resolved_resources, uri_style
from ..model.numbers import shown
from ..model.vocabulary import LOWER_TRIANGLE, SCHEMA, mistyped_moment
from ..read.expanded import display_path
from ..read.packages import cmake_project, uri_package
from .base import ERROR, INFO, PLACED, SAFE, WARNING, Kind, RuleSet, check
from .meshes import others_there, package_uri, written_with_find
from .suggestions import close_matches
from .xacro import UNEXPANDED, unprefixed_calls

ABSOLUTE = ("file", "absolute")  # the uri_style of a path of one machine

# Gazebo plugin parameters that name a joint or a link (ROS 1 and ROS 2 spellings).
PLUGIN_JOINT_TAGS = {
    "jointName", "joint_name", "leftJoint", "rightJoint", "left_joint", "right_joint",
    "leftFrontJoint", "rightFrontJoint", "leftRearJoint", "rightRearJoint",
    "left_front_joint", "right_front_joint", "left_rear_joint", "right_rear_joint",
}
PLUGIN_LINK_TAGS = {"bodyName", "body_name", "robotBaseFrame", "robot_base_frame", "frameName", "frame_name"}
WORLD_FRAMES = {"world", "map", "odom", ""}
TF_PREFIXED_TAGS = {"frameName", "robotBaseFrame"}  # ROS 1 gazebo_ros plugins put the tf_prefix before these (tf::resolve)


def _suggestion(word: str, known) -> str | None:
    close = close_matches(word, sorted(known))
    return close[0] if close else None


def _name_hint(word: str, known) -> str | None:
    """The hint of a name that is no link or joint: a ``{name}`` that xacro never read (its
    ``$`` missing, so every call wrote the same text), else the name it is closest to."""
    unexpanded = UNEXPANDED.search(word)
    if unexpanded is not None:
        return f"'{unexpanded.group(0)}' lacks its $: xacro copies it as written; write '${unexpanded.group(0)}'"
    close = _suggestion(word, known)
    return f"did you mean '{close}'?" if close else None


@check("D001", "unknown-element", WARNING, "A misspelt element: close to a URDF element missing where it is written.", rule_set=RuleSet.LINT)
def unknown_element(loaded, given):
    """## What it does
    Flags a child element that URDF does not define inside its parent and that
    is one or two letters away from an element missing there, such as
    `<metrial>` in a `<visual>`, and names the element meant; so too in the
    components of a `<ros2_control>` block, whose parser reads `<plugin>`,
    `<command_interface>`, `<state_interface>` and `<param>` by name and skips
    the rest (`<comand_interface>` leaves the joint without it). Documented
    extensions (Gazebo, PyBullet, Drake, Isaac, MuJoCo, vendors) are not typos;
    other unknown markup is D010 (info), Gazebo markup outside `<gazebo>` D011.

    ## Why is this bad?
    urdfdom and every other consumer skip elements they do not know, silently:
    the misspelt material, limit or origin is simply not there.

    ## Example
    ```xml
    <link name="base">
      <visual>
        <geometry><box size="1 1 1"/></geometry>
        <metrial name="grey"/>
      </visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base">
      <visual>
        <geometry><box size="1 1 1"/></geometry>
        <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
      </visual>
    </link>
    ```
    """
    for unknown in loaded.robot.unknown:
        if not unknown.attribute and unknown.typo_of:
            yield loaded.diagnostic("D001", f"<{unknown.name}> is not a {unknown.format} element inside <{unknown.parent}>; it is ignored",
                                    unknown.at, f"did you mean <{unknown.typo_of}>?")


@check("D002", "unknown-attribute", WARNING, "A misspelt attribute: close to a URDF attribute missing on its element.", rule_set=RuleSet.LINT)
def unknown_attribute(loaded, given):
    """## What it does
    Flags an attribute that URDF does not define on its element and that is one
    or two letters away from an attribute the element lacks, such as
    `<color rgb="...">` for `rgba`. An attribute already on the element is
    never suggested. Vendor attributes (Franka's `<dynamics K D mu_coulomb
    mu_viscous>`, ANYmal's `<limit command_effort current gear_velocity>`,
    Isaac's `dont_collapse`, PyBullet's collision `group`, `mask`, `concave`)
    are not typos; other unknown attributes are D010 (info). An `<inertia>`'s
    lower triangle (`iyx`, `izx`, `izy`) is a typo when its value differs from
    the upper triangle's (`ixy`, `ixz`, `iyz`): the diagonal moment of its row,
    one letter away, was meant (Fetch's fingers: `iyx="0.002"` beside `ixy="0"`
    and `iyy="0"`); repeating it, it is D010's.

    ## Why is this bad?
    The attribute is ignored: the colour, limit or axis it meant to set keeps
    its default, and nothing tells the author.

    ## Example
    ```xml
    <material name="orange">
      <color rgb="1 0.5 0 1"/>
    </material>
    ```

    ## Use instead
    ```xml
    <material name="orange">
      <color rgba="1 0.5 0 1"/>
    </material>
    ```
    """
    for unknown in loaded.robot.unknown:
        if unknown.attribute and unknown.typo_of:
            message, hint = _misspelt_attribute(loaded, unknown)
            yield loaded.diagnostic("D002", message, unknown.at, hint, attribute=unknown.name)


def _misspelt_attribute(loaded, unknown) -> tuple[str, str]:
    """D002's message and hint; for an ``<inertia>``'s lower-triangle name typed for a diagonal
    moment (:func:`mistyped_moment`), the value that tells it from a repeated product of inertia."""
    name, meant = unknown.name, unknown.typo_of
    value = partial(loaded.value, unknown.at)
    if unknown.parent != "inertia" or mistyped_moment(name, value) != meant:
        return f"<{unknown.parent}> has no attribute '{name}'; it is ignored", f"did you mean '{meant}'?"
    counterpart, read = LOWER_TRIANGLE[name], value(meant)
    return (
        f"<inertia> has no attribute '{name}', and its value {shown(value(name))} differs from {counterpart}'s {shown(value(counterpart))}: "
        "no repeated product of inertia; it is ignored",
        f"probably a mistyped '{meant}' (one letter away), which "
        + (f"URDF reads as {shown(read)}" if read is not None else "is not written"),
    )


def _belongs_in(tag: str) -> list[str]:
    return sorted(parent for parent, (_, children) in SCHEMA.items() if children and tag in children)


@check("D010", "unknown-markup", INFO, "Markup that neither URDF nor a known extension defines, and that is no typo.", rule_set=RuleSet.LINT)
def unknown_markup(loaded, given):
    """## What it does
    Notes an element or attribute that neither URDF nor a documented extension
    defines where it is written, and that is not close to a URDF name missing
    there: a URDF element in the wrong place (`<origin>` directly in `<link>`),
    an old or private extension (`<verbose>`, `<self_filter>`), an attribute
    on an element that takes none (an element's unknown attributes are one note:
    an `<inertia>` that also writes its lower triangle, `iyx`, `izx`, `izy`,
    repeating the upper; a value that differs is a typo, D002's).
    Info: shown, never fails a run.

    Known extensions draw nothing: Gazebo's tags inside `<gazebo>`, PyBullet's
    `<contact>` in a link, anything prefixed (`drake:`, `xacro:`), Isaac's
    `dont_collapse`, `<material>` in a `<collision>`, MuJoCo's `<mujoco>`,
    robot-level `<sensor>` (urdfdom, iDynTree), vendor attributes. Pinocchio
    reads URDF through urdfdom; its own extras live in SRDF. A xacro tag or macro
    call written without `xacro:` is X107's, which says so at its tag.

    ## Why is this bad?
    Every URDF consumer skips it: if it was meant to configure something, it
    does not. Often it is harmless leftover markup; sometimes a setting in the
    wrong place.

    ## Example
    ```xml
    <link name="tool_link">
      <origin xyz="0 0 0.1"/>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="tool_link">
      <inertial>
        <origin xyz="0 0 0.1"/>
        <mass value="0.2"/>
        <inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/>
      </inertial>
    </link>
    ```
    """
    calls = set(unprefixed_calls(loaded))
    sources = loaded.xacro_sources
    directives = {old.tag for file in sources.files for old in file.old} if sources is not None else set()
    attributes_of: dict[int, list] = {}  # an element's unknown attributes: one diagnostic (an <inertia>'s iyx, izx, izy)
    for unknown in loaded.robot.unknown:
        if (unknown.typo_of or unknown.gazebo or (unknown.attribute and unknown.parent == "material" and unknown.name == "rgba") or unknown in calls
                or (not unknown.attribute and unknown.name in directives)):
            continue  # a typo is D001/D002's, Gazebo markup D011's, a material's rgba M005's or M001's, a macro call or a xacro tag without xacro: X107's
        if unknown.attribute:
            attributes_of.setdefault(unknown.at, []).append(unknown)
            continue
        places = _belongs_in(unknown.name)
        if places:
            hint = f"<{unknown.name}> belongs in " + ", ".join(f"<{p}>" for p in places)
        else:
            hint = f"<{unknown.parent}> may hold " + ", ".join(f"<{c}>" for c in sorted(SCHEMA[unknown.parent][1]))
        yield loaded.diagnostic("D010", f"<{unknown.name}> is not URDF markup inside <{unknown.parent}>; URDF consumers ignore it", unknown.at, hint)
    for at, unknowns in attributes_of.items():
        tag, names = unknowns[0].parent, [u.name for u in unknowns]
        takes = sorted(SCHEMA[tag][0])
        hint = f"<{tag}> takes {', '.join(takes)}" if takes else f"<{tag}> takes no attributes"
        if len(names) == 1:
            yield loaded.diagnostic("D010", f"<{tag}> has no attribute '{names[0]}'; URDF consumers ignore it", at, hint, attribute=names[0])
        else:
            listed = ", ".join(f"'{name}'" for name in names[:-1]) + f" and '{names[-1]}'"
            yield loaded.diagnostic("D010", f"<{tag}> has no attributes {listed}; URDF consumers ignore them", at, hint, attribute=names[0])


@check("D011", "gazebo-tag-outside-gazebo", WARNING, "Gazebo markup written outside `<gazebo>`, where Gazebo never reads it.", rule_set=RuleSet.LINT)
def gazebo_outside_gazebo(loaded, given):
    """## What it does
    Flags Gazebo markup (`<surface>`, `<mu1>`, `<gravity>`, `<kinematic>`,
    `<selfCollide>`, `<sensor>` in a link, `<material>Gazebo/Grey</material>`,
    `<plugin>`...) written directly in a
    `<link>`, `<joint>`, `<visual>`, `<collision>` or `<robot>` instead of in a
    `<gazebo>` block: one diagnostic per element holding it, and one for the
    copies a macro's calls make of it (the four casters of one macro).

    ## Why is this bad?
    Gazebo reads its settings only from `<gazebo>` blocks; everything else is
    dropped while the URDF is converted to SDFormat. The friction, sensor or
    plugin written there is dead configuration: the simulation runs without it.

    ## Example
    ```xml
    <link name="wheel_link">
      <collision><geometry><cylinder radius="0.07" length="0.05"/></geometry></collision>
      <surface><friction><ode><mu1>1.0</mu1></ode></friction></surface>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wheel_link">
      <collision><geometry><cylinder radius="0.07" length="0.05"/></geometry></collision>
    </link>
    <gazebo reference="wheel_link">
      <mu1>1.0</mu1>
    </gazebo>
    ```
    """
    found: dict = {}
    for unknown in loaded.robot.unknown:
        if unknown.gazebo:
            found.setdefault(unknown.holder, []).append(unknown)
    for unknowns in found.values():
        tags = ", ".join(f"<{u.name}>" for u in unknowns)
        owner, parent = unknowns[0].owner, unknowns[0].parent
        kind = "joint" if parent == "joint" else "link"
        # the hint does not repeat the name, so the copies a macro's calls make are said once
        where = f"<{parent}>" + ("" if not owner else f" of '{owner}'" if parent == kind else f" of {kind} '{owner}'")
        hint = f'move it into a <gazebo reference="..."> block naming its {kind}' if owner else "move it into a <gazebo> block"
        if any(u.name == "gazebo" for u in unknowns):
            hint = f"move it to the top level of <robot>, with a reference naming its {kind}" if owner else "move it to the top level of <robot>"
            message = f"Gazebo markup {tags} in {where}: Gazebo reads <gazebo> blocks only at the top level of <robot>"
        else:
            message = f"Gazebo markup {tags} in {where} is outside <gazebo>: Gazebo never reads it"
        yield loaded.diagnostic("D011", message, unknowns[0].at, hint, subjects=(owner,) if owner else ())


@check("D003", "visual-without-collision", WARNING, "A moving body with visuals but no collision on any of its links.", rule_set=RuleSet.LINT)
def visual_without_collision(loaded, given):
    """## What it does
    Judges rigid bodies, not links: links joined by fixed joints form one body, as
    simulators lump them. Flags a body carried by a moving joint that has a `<visual>`
    but no `<collision>` on any of its links (a collision on a fixed child counts). The
    root's body is left alone (it may be fixed to the world), and so is a visual drawn
    in a colour of alpha 0 (the `invisible` material of a virtual wheel, which stands
    for a pair of real ones). A model with no collision at all gets one note (info)
    instead of a warning per body: it is meant for display.

    ## Why is this bad?
    A simulated body with no collision shape passes through the floor and through
    other bodies, and planners never see it; the visual makes it look solid.

    ## Example
    ```xml
    <link name="base_link">
      <collision><geometry><box size="1 1 0.2"/></geometry></collision>
    </link>
    <link name="arm">
      <visual><geometry><box size="0.1 0.1 1"/></geometry></visual>
    </link>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm"/>
    </joint>
    ```

    ## Use instead
    ```xml
    <link name="base_link">
      <collision><geometry><box size="1 1 0.2"/></geometry></collision>
    </link>
    <link name="arm">
      <visual><geometry><box size="0.1 0.1 1"/></geometry></visual>
      <collision><geometry><box size="0.1 0.1 1"/></geometry></collision>
    </link>
    <joint name="arm_joint" type="continuous">
      <parent link="base_link"/>
      <child link="arm"/>
    </joint>
    ```
    """
    links = loaded.robot.links
    bare = []  # (body, its first link with a visual) for each moving body without collision
    seen = set()
    for body in bodies(loaded).values():
        if body.top in seen or not body.moving:
            continue
        seen.add(body.top)
        members = [links[name] for name in body.links]
        shown = next((link for link in members if any(_visible(visual, loaded.robot.materials) for visual in link.visuals)), None)
        if shown is not None and not any(link.collisions for link in members):
            bare.append((body, shown))
    if bare and not any(link.collisions for link in links.values()):
        note = loaded.diagnostic("D003", "no link has a <collision>: the model can be displayed, not simulated or planned with", loaded.robot.at,
                                 "add collision shapes to the moving links if it is meant for simulation or planning")
        yield note.with_severity(INFO)
        return
    for body, shown in bare:
        members = [links[name] for name in body.links]
        fixed = f" (nor on the links fixed to it: {', '.join(repr(m.name) for m in members[1:])})" if len(members) > 1 else ""
        yield loaded.diagnostic(
            "D003",
            f"link '{body.top}', moved by joint '{body.joint.name}', has a visual but no collision{fixed}",
            shown.at,
            "add a <collision> (often the visual's geometry, or a simpler one)",
        )


def _visible(visual, materials) -> bool:
    """Whether a visual is drawn: not in a colour of alpha 0, its own or its named material's."""
    colour = visual.colour if visual.colour is not None else getattr(materials.get(visual.material), "rgba", None)
    return colour is None or len(colour) != 4 or colour[3] > 0


@check("D004", "resource-not-found", ERROR, "A mesh or texture file that does not exist.", kind=Kind.FILES, fix=SAFE,
       fix_doc="Names the file of its folder that differs only in case or extension, where the name was written (safe: the file meant is the one loaded on macOS and Windows)." f" {PLACED}")
def file_not_found(loaded, given):
    """## What it does
    Resolves each `<mesh filename>` and `<texture filename>` (`package://`,
    `file://`, absolute or relative paths; never a network address) and flags
    a file that does not exist: an error for a mesh, a warning for a texture.
    Relative paths are taken from the input's folder. Files in a folder that
    does not exist at all are one diagnostic per folder. Where a file differs
    only in case or extension (it loads on macOS and Windows, not on Linux), or
    has the name in a `meshes/` folder beside a folder above it, the hint names
    it; else an absolute path is told as this machine's (one `$(find pkg)`
    gives: in a package, whose `package://` URI loads on other machines too;
    in the input's repository or workspace) or another machine's. `check` reports it too:
    whether a file exists is a `stat`, no mesh is opened. A package that
    cannot be found is D005's.

    ## Why is this bad?
    RViz shows the link without it and logs an error, MuJoCo, PyBullet and
    Drake refuse to load the robot, and MoveIt and Gazebo lose the collision
    shape: the model cannot be used as written. A missing texture only loses
    the picture.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.STL"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    base = input_folder(loaded)
    missing_folders: dict = {}
    exists: dict = {}  # each file asked of the disk once (a mesh is often a link's visual and its collision)
    for at, kind, uri, path in resolved_resources(loaded):
        if path is None:  # a package not found (D005), a network address
            continue
        if path not in exists:
            exists[path] = path.exists()
        if exists[path]:
            continue
        if not path.parent.is_dir():
            missing_folders.setdefault(path.parent, []).append((at, kind, uri, path))
            continue
        looked = f" (looked for {path})" if str(path) != uri else ""
        hint = _meant(loaded, uri, path, base) or (_whose(loaded, at, uri, path) if uri_style(uri) in ABSOLUTE else None)
        found = loaded.diagnostic("D004", f"{kind} '{uri}' not found{looked}", at, hint)
        found = found.with_fix(_file_fix(loaded, at, uri, path, base))
        yield found.with_severity(WARNING) if kind == "texture" else found
    for folder, uses in missing_folders.items():  # a missing folder is one cause: one diagnostic
        at, kind, uri, path = uses[0]
        others = others_there(u for _, _, u, _ in uses)
        hint = _meant(loaded, uri, path, base)
        if hint is None and uri_style(uri) in ABSOLUTE:
            hint = _whose(loaded, at, uri, path) or "a path of another machine: put the files in a ROS package and write package://PACKAGE/..."
        found = loaded.diagnostic("D004", f"{kind} '{uri}'{others}: folder {folder} does not exist", at, hint)
        yield found.with_severity(WARNING) if all(kind == "texture" for _, kind, _, _ in uses) else found


def _whose(loaded, at: int, uri: str, path) -> str | None:
    """The hint for an absolute path (``file://`` or plain, as ``$(find)`` gives) of this
    machine to a missing file: in a package, the package:// URI that names it on any
    machine (unless a xacro source wrote it ``file://$(find ...)``, portable already);
    in the input's repository or workspace, where. None for another machine's path."""
    portable = package_uri(loaded, path)
    if portable is not None:
        said = f"a path of this machine, in package '{uri_package(portable)}', where the file is missing"
        if uri_style(uri) == "file" and written_with_find(loaded, at):
            return said
        return f"{said}; write '{portable}' for the model to load on other machines too"
    folder = loaded.resolver.workspace_of(path) if loaded.resolver is not None else None
    return f"a path of this machine, in {folder}, where the file is missing" if folder is not None else None


def _meant(loaded, uri: str, path, base) -> str | None:
    """The hint for a missing file: the file it probably meant, written as ``uri`` is (None: none)."""
    found = near_misses(path)
    if not found:
        return None
    written = uri_like(loaded, uri, found[0], base)
    if found[0].parent == path.parent and found[0].name.lower() == path.name.lower():
        return f"did you mean '{written}'? file names are case-sensitive on Linux (it loads on macOS and Windows only)"
    return f"did you mean '{written}'?"


def _file_fix(loaded, at: int, uri: str, path, base) -> Fix | None:
    """Name the one file of the missing file's folder that differs only in case or extension
    (None when there is none: a missing file, which nothing here can fix)."""
    same = [p for p in near_misses(path) if p.parent == path.parent]
    if not same:
        return None  # (a "no fix" line under each missing mesh would say only that it is missing)
    title = f"name the file that exists instead of '{path.name}'"
    if len(same) != 1:
        return Fix(title, SAFE, reason=f"{len(same)} files of its folder could be meant")
    written = uri[: len(uri) - len(path.name)] + same[0].name if uri.endswith(path.name) else uri_like(loaded, uri, same[0], base)
    return Fix(f"write '{written}'", SAFE, changes=(SetAttribute(at, "filename", written),))


def uri_like(loaded, uri: str, path, base) -> str:
    """``path`` written the way ``uri`` is: package://, file://, or a path from the input's folder."""
    package = uri_package(uri)
    if package:
        folder = loaded.resolver.find(package)
        if folder is not None and path.is_relative_to(folder):
            return f"package://{package}/{path.relative_to(folder).as_posix()}"
    if uri.startswith("file://"):
        return f"file://{path}"
    if uri_style(uri) not in ABSOLUTE and base is not None:
        return os.path.relpath(path, base)
    return str(path)


@check("D005", "package-uri-not-found", WARNING, "A `package://` URI names a package that cannot be found.", rule_set=RuleSet.LINT)
def package_not_found(loaded, given):
    """## What it does
    Flags a `package://NAME/...` mesh or texture whose package cannot be found
    with `-P/--package-path`, `ROS_PACKAGE_PATH`, `AMENT_PREFIX_PATH`, or next
    to the input file (its own package and its siblings), and a `package:///...`
    URI whose package name is empty. One diagnostic per missing package, at
    its first use, saying how many other files name it.

    ## Why is this bad?
    Consumers resolve `package://` through the ROS package index: a misspelt
    or missing package leaves the robot without its meshes.

    ## Example
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robto/meshes/arm.stl"/></geometry></visual>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="arm">
      <visual><geometry><mesh filename="package://my_robot/meshes/arm.stl"/></geometry></visual>
    </link>
    ```
    """
    if loaded.resolver is None:
        return
    missing: dict[str, list] = {}
    for at, kind, uri in loaded.robot.resources:
        package = uri_package(uri)
        if package is not None and loaded.resolver.find(package) is None:
            missing.setdefault(package, []).append((at, kind, uri))
    for package, uses in missing.items():  # one cause: one diagnostic, at the first use
        at, kind, uri = uses[0]
        others = f" (and {len(uses) - 1} other {'files' if len(uses) > 2 else 'file'})" if len(uses) > 1 else ""
        if package:
            message, hint = f"{kind} '{uri}'{others}: package '{package}' not found {loaded.resolver.where()}", "name the package's folder with -P NAME=DIR, or fix its name"
            misnamed = loaded.resolver.misnamed(package)
            if misnamed is not None:  # a package is named by its package.xml, not its folder
                folder, real = misnamed
                if cmake_project(folder) == package:  # ament installs it as `package`: the URI is right
                    hint = f"the folder {folder} installs as '{package}' (its CMakeLists.txt project): build and source the workspace, or give -P {package}={folder}"
                else:
                    hint = f"the folder {folder} holds the package named '{real}' (its package.xml): write package://{real}/, or give -P {package}={folder}"
            elif (holding := _folder_holding(loaded, uri, package)) is not None:
                hint = f"the folder {display_path(str(holding))} holds {uri[len('package://') + len(package):].lstrip('/')}: give -P {package}={display_path(str(holding))}"
        else:
            message, hint = f"{kind} '{uri}'{others}: the package name is empty", "a package URI is package://PACKAGE/PATH: two slashes, then the package's name"
        yield loaded.diagnostic("D005", message, at, hint)


def _folder_holding(loaded, uri: str, package: str):
    """The folder by the model that holds the file ``uri`` names in the package not found, as
    exports lay them out: a folder of the package's name beside the model (onshape-to-robot's
    ``package://assets/``), the model's own folder, or the one above it (a package without
    package.xml, its URDF in ``urdf/``). None when none does."""
    base, rest = input_folder(loaded), uri[len("package://") + len(package):].lstrip("/")
    if base is None or not rest:
        return None
    return next((folder for folder in (base / package, base, base.parent) if (folder / rest).is_file()), None)


# What sdformat's URDF conversion gives a link (or its collisions and visuals) from a
# <gazebo reference> block, and never a joint: under a joint's name, dropped.
_LINK_PROPERTIES = frozenset((
    "mu1", "mu2", "fdir1", "kp", "kd", "minDepth", "maxVel", "maxContacts", "laserRetro", "selfCollide",
    "material", "gravity", "turnGravityOff", "dampingFactor",
))


def _known_names(loaded) -> set[str]:
    return set(loaded.robot.links) | set(loaded.robot.joints)


@check("D006", "gazebo-reference-not-found", WARNING, "A `<gazebo reference>` naming no link or joint, or a joint for a link's properties.", rule_set=RuleSet.LINT)
def gazebo_reference(loaded, given):
    """## What it does
    Flags a `<gazebo reference="...">` block whose reference is neither a link
    nor a joint of the robot, and one that names a joint (no link of that name)
    but sets what Gazebo gives a link only: friction and contact (`<mu1>`,
    `<mu2>`, `<kp>`, `<kd>`, `<fdir1>`, `<minDepth>`, `<maxVel>`...), a
    `<material>`, `<selfCollide>`, `<gravity>`. The hint names the joint's
    child link, which the block was likely meant for (AgileX's Limo names its
    wheel joints `front_left_wheel` and sets their friction there).

    ## Why is this bad?
    Gazebo applies the block (sensors, materials, friction) to nothing, without
    a word: the camera or the wheel friction is simply missing in simulation.
    sdformat reads a link's properties from a block only when the reference is
    that link's name; under a joint's name they are dropped.

    ## Example
    ```xml
    <link name="camera_link"/>
    <gazebo reference="camera">
      <material>Gazebo/Black</material>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="camera_link"/>
    <gazebo reference="camera_link">
      <material>Gazebo/Black</material>
    </gazebo>
    ```
    """
    known = _known_names(loaded)
    for element in loaded.robot.blocks("gazebo"):
        reference = element.get("reference")
        if reference is not None and reference not in known:
            yield loaded.diagnostic("D006", f"<gazebo reference='{reference}'> names no link or joint", loaded.robot.place(element), _name_hint(reference, known))
        elif reference in loaded.robot.joints and reference not in loaded.robot.links:
            dropped = list(dict.fromkeys(child.tag for child in element if child.tag in _LINK_PROPERTIES))
            if dropped:
                child = loaded.robot.joints[reference].child
                tags = ", ".join(f"<{tag}>" for tag in dropped)
                yield loaded.diagnostic(
                    "D006", f"<gazebo reference='{reference}'> names a joint, and Gazebo gives {tags} to links only: it drops them",
                    loaded.robot.place(element), f"write reference='{child}', the joint's child link" if child else "name the link they are for",
                )


@check("D014", "gazebo-property-set-twice", WARNING, "A `<gazebo reference>` block setting one link property twice, to different values.", rule_set=RuleSet.LINT)
def gazebo_property_twice(loaded, given):
    """## What it does
    Flags a link property (`<mu1>`, `<mu2>`, `<kp>`, `<kd>`, `<material>`,
    `<selfCollide>`, `<gravity>`...) written twice in one `<gazebo reference>`
    block with different values, at the value Gazebo ignores. Leaves alone the
    same value written twice, and a property set again in another block for the
    same link (a library's default overridden by the model; sdformat warns of
    those itself).

    ## Why is this bad?
    sdformat keeps the last value without a word (ROBOTIS OP3's ankle sets
    `<mu1>9000</mu1>`, then `<mu1>1.5</mu1>`): whoever reads the block, or tunes
    the first value, is misled about the friction the simulation uses.

    ## Example
    ```xml
    <link name="foot"/>
    <gazebo reference="foot">
      <mu1>9000</mu1>
      <mu1>1.5</mu1>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="foot"/>
    <gazebo reference="foot">
      <mu1>1.5</mu1>
    </gazebo>
    ```
    """
    for block in loaded.robot.blocks("gazebo"):
        reference = block.get("reference")
        if reference not in loaded.robot.links:
            continue
        last: dict[str, object] = {}
        for element in reversed(block):
            if element.tag not in _LINK_PROPERTIES:
                continue
            kept = last.setdefault(element.tag, element)
            if kept is not element and _written(kept) != _written(element):
                yield loaded.diagnostic(
                    "D014", f"<gazebo reference='{reference}'> sets <{element.tag}> twice, to {_written(element)} and then {_written(kept)}: Gazebo keeps {_written(kept)}",
                    loaded.robot.place(element), "remove the value Gazebo ignores",
                )


def _written(element) -> str:
    """An element's text as one line, for saying which value is kept."""
    return " ".join("".join(element.itertext()).split()) or "nothing"


@check("D007", "transmission-joint-not-found", WARNING, "A transmission naming a joint that does not exist.", rule_set=RuleSet.LINT)
def transmission_joint(loaded, given):
    """## What it does
    Flags a `<transmission>` whose `<joint name>` is not a joint of the robot.

    ## Why is this bad?
    ros_control and gazebo_ros_control fail to load the controller for a
    transmission whose joint does not exist, and the robot does not move.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="wheel_link"/>
    <joint name="wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="wheel_link"/>
    </joint>
    <transmission name="wheel_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="wheel_jiont">
        <hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="wheel_link"/>
    <joint name="wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="wheel_link"/>
    </joint>
    <transmission name="wheel_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="wheel_joint">
        <hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```
    """
    joints = set(loaded.robot.joints)
    for transmission in loaded.robot.blocks("transmission"):
        for joint in transmission.iterfind("joint"):
            name = joint.get("name")
            if name is not None and name not in joints:
                yield loaded.diagnostic("D007", f"transmission '{transmission.get('name', '')}' names joint '{name}', which does not exist", loaded.robot.place(joint), _name_hint(name, joints))


@check("D013", "ros2-control-joint-not-found", ERROR, "A `<ros2_control>` joint that names no joint of the robot.")
def ros2_control_joint(loaded, given):
    """## What it does
    Flags a `<joint name>` inside `<ros2_control>` that is not a joint of the robot.

    ## Why is this bad?
    ros2_control's resource manager refuses the hardware description: the
    controller manager fails to start (gz_ros2_control and the real robot's
    hardware interface alike), and nothing moves.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    <ros2_control name="arm" type="system">
      <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
      <joint name="arm_jiont"><command_interface name="position"/><state_interface name="position"/></joint>
    </ros2_control>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="arm_link"/>
    <joint name="arm_joint" type="revolute">
      <parent link="base_link"/>
      <child link="arm_link"/>
      <limit lower="-1" upper="1" effort="10" velocity="1"/>
    </joint>
    <ros2_control name="arm" type="system">
      <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
      <joint name="arm_joint"><command_interface name="position"/><state_interface name="position"/></joint>
    </ros2_control>
    ```
    """
    joints = set(loaded.robot.joints)
    for control in loaded.robot.blocks("ros2_control"):
        for element in control.iterfind("joint"):
            name = element.get("name")
            if name is not None and name not in joints:
                close = _suggestion(name, joints)
                yield loaded.diagnostic(
                    "D013", f"ros2_control '{control.get('name', '')}' names joint '{name}', which does not exist", loaded.robot.place(element),
                    f"did you mean '{close}'?" if close else "name a joint of the robot, or remove this <joint>", subjects=(name,),
                )


@check("D012", "transmission-fixed-joint", WARNING, "A transmission or ros2_control command driving a fixed joint.", rule_set=RuleSet.LINT)
def transmission_fixed_joint(loaded, given):
    """## What it does
    Flags a `<transmission>` whose `<joint name>` is a fixed joint, and a
    `<ros2_control>` joint with a command interface that is a fixed joint.
    Interfaces that only read pass: a ros2_control joint with state interfaces
    alone, and a transmission whose hardware interfaces for the joint (or, in
    the older layout, for its actuators) are all state, model or sensor
    interfaces (`hardware_interface/JointStateInterface`, Franka's
    `franka_hw/FrankaModelInterface`, which names the chain's fixed flange as
    its tip).

    ## Why is this bad?
    A fixed joint has no degree of freedom to drive: ros_control,
    gazebo_ros_control and gz_ros2_control refuse or skip it, and the actuator
    it describes moves nothing. Usually the joint was fixed on purpose (a
    simplified model) and the transmission left behind, or the joint should
    move and its type is wrong.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="caster_link"/>
    <joint name="caster_joint" type="fixed">
      <parent link="base_link"/>
      <child link="caster_link"/>
    </joint>
    <transmission name="caster_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="caster_joint">
        <hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="caster_link"/>
    <joint name="caster_joint" type="continuous">
      <parent link="base_link"/>
      <child link="caster_link"/>
      <axis xyz="0 0 1"/>
    </joint>
    <transmission name="caster_trans">
      <type>transmission_interface/SimpleTransmission</type>
      <joint name="caster_joint">
        <hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>
      </joint>
    </transmission>
    ```
    """
    for transmission in loaded.robot.blocks("transmission"):
        for element in transmission.iterfind("joint"):
            joint = loaded.robot.joints.get(element.get("name"))
            if joint is not None and joint.type == "fixed" and _commands(transmission, element):
                yield loaded.diagnostic(
                    "D012",
                    f"transmission '{transmission.get('name', '')}' drives joint '{joint.name}', which is fixed",
                    loaded.robot.place(element),
                    "remove the transmission if the joint is fixed on purpose, or give the joint the type it moves with",
                )
    for control in loaded.robot.blocks("ros2_control"):
        for element in control.iterfind("joint"):
            joint = loaded.robot.joints.get(element.get("name"))
            if joint is not None and joint.type == "fixed" and element.find("command_interface") is not None:
                yield loaded.diagnostic(
                    "D012",
                    f"ros2_control '{control.get('name', '')}' commands joint '{joint.name}', which is fixed",
                    loaded.robot.place(element),
                    "remove its command interfaces if the joint is fixed on purpose, or give the joint the type it moves with",
                )


_READING_INTERFACES = ("StateInterface", "ModelInterface", "SensorInterface")


def _commands(transmission, joint) -> bool:
    """Whether a transmission commands its joint: some hardware interface of the joint
    (or else of the transmission's actuators) is not one that only reads. A joint
    given no interface at all is taken as commanded."""
    interfaces = _texts(joint, "hardwareInterface") or _texts(transmission, "actuator/hardwareInterface")
    return not interfaces or not all(name.endswith(_READING_INTERFACES) for name in interfaces)


def _texts(element, path: str) -> list[str]:
    """The non-blank texts of the elements at ``path`` under ``element``, stripped."""
    return [text for found in element.iterfind(path) if (text := (found.text or "").strip())]


def _plugin_references(loaded, tags: set[str]):
    """(element, name) for each plugin parameter among ``tags``; lists split on commas."""
    for plugin in (found for block in loaded.robot.blocks() for found in block.iter("plugin")):
        for element in plugin.iter():
            if element.tag in tags and element.text:
                for name in re.split(r"[,\s]+", element.text.strip()):
                    yield element, name.lstrip("/")


@check("D008", "plugin-joint-not-found", WARNING, "A Gazebo plugin parameter naming a joint that does not exist.", rule_set=RuleSet.LINT)
def plugin_joint(loaded, given):
    """## What it does
    Flags a Gazebo plugin parameter that names a joint (`leftJoint`,
    `right_joint`, `jointName`, `joint_name`...) when no joint has that name.

    ## Why is this bad?
    The plugin (a differential drive, a joint state publisher) fails to start
    or drives nothing, and only Gazebo's log says why.

    ## Example
    ```xml
    <link name="base_link"/>
    <link name="left_wheel_link"/>
    <joint name="left_wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="left_wheel_link"/>
    </joint>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <left_joint>left_wheel</left_joint>
      </plugin>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <link name="left_wheel_link"/>
    <joint name="left_wheel_joint" type="continuous">
      <parent link="base_link"/>
      <child link="left_wheel_link"/>
    </joint>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <left_joint>left_wheel_joint</left_joint>
      </plugin>
    </gazebo>
    ```
    """
    joints = set(loaded.robot.joints)
    for element, name in _plugin_references(loaded, PLUGIN_JOINT_TAGS):
        if name and name not in joints:
            close = _suggestion(name, joints)
            yield loaded.diagnostic("D008", f"plugin parameter <{element.tag}> names joint '{name}', which does not exist", loaded.robot.place(element), f"did you mean '{close}'?" if close else None)


@check("D009", "plugin-link-not-found", WARNING, "A Gazebo plugin parameter naming a link that does not exist.", rule_set=RuleSet.LINT)
def plugin_link(loaded, given):
    """## What it does
    Flags a Gazebo plugin parameter that names a link (`robotBaseFrame`,
    `robot_base_frame`, `bodyName`, `frame_name`...) when no link has that
    name. `world`, `map` and `odom` are frames outside the robot and pass.
    So does a ROS 1 `frameName` or `robotBaseFrame` written without the
    tf_prefix the links carry (`laser_link` when the link is
    `robot1/laser_link`): those plugins put the tf_prefix before it themselves.

    ## Why is this bad?
    The plugin publishes or applies forces in a frame that does not exist:
    TF lookups fail and sensors report in the wrong frame.

    ## Example
    ```xml
    <link name="base_link"/>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <robot_base_frame>base</robot_base_frame>
      </plugin>
    </gazebo>
    ```

    ## Use instead
    ```xml
    <link name="base_link"/>
    <gazebo>
      <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
        <robot_base_frame>base_link</robot_base_frame>
      </plugin>
    </gazebo>
    ```
    """
    links = set(loaded.robot.links)
    unprefixed = {link.rsplit("/", 1)[1] for link in links if "/" in link}  # a link's name after its tf_prefix
    for element, name in _plugin_references(loaded, PLUGIN_LINK_TAGS):
        resolved = element.tag in TF_PREFIXED_TAGS and not element.text.strip().startswith("/") and name in unprefixed
        if name not in links and name not in WORLD_FRAMES and not resolved:
            close = _suggestion(name, links)
            yield loaded.diagnostic("D009", f"plugin parameter <{element.tag}> names link '{name}', which does not exist", loaded.robot.place(element), f"did you mean '{close}'?" if close else None)
