"""Inertia rules that need the geometry or the whole model (warnings; `lint` and `inertia`).

They are not part of `check`, which stays a drop-in for check_urdf. The tensor a
link's geometry implies comes from :mod:`urdfcli.inertia`.
"""

from __future__ import annotations

from collections import defaultdict

from .. import massprops
from ..numbers import format_number
from . import WARNING, Option, check

SIZE_RATIO = 2.0  # links this many times apart in mass or size cannot share one honest tensor
TOLERANCE = Option(
    "tolerance",
    massprops.TOLERANCE,
    "Largest element difference between declared and expected tensors, relative to the larger's largest element. "
    "0.1 catches swapped or unrotated axes and lets values rounded to two digits pass.",
)
DENSITY = Option("density", 0.0, "kg/m³: when positive, masses come from the geometry's volume instead of the declared mass.")


def _inertia():
    """:mod:`urdfcli.inertia`, imported when one of these rules first runs (`check` runs none)."""
    from .. import inertia

    return inertia


def _declaring(loaded):
    """Links with positive mass and a tensor (frame links and broken inertials left out)."""
    for link in loaded.robot.links.values():
        if link.inertial is not None and link.inertial.inertia and (link.inertial.mass or 0) > 0:
            yield link


def _assess(loaded, link, options):
    return _inertia().assess(loaded, link, options.get("density") or None)


def _off_geometry(loaded, options):
    """(link, assessment, rotated fit) for each link whose tensor is off its geometry's."""
    for link in _declaring(loaded):
        found = _assess(loaded, link, options)
        if found is not None and found.off(options["tolerance"]):
            yield link, found, _inertia().rotated_fit(found)


def _implies(found) -> str | None:
    return f"its {found.implied.source} implies {_inertia().tensor_text(found.expected)}" if found and found.expected else None


@check("I007", "placeholder-identity", WARNING, "An inertia tensor that is the identity: a placeholder.", in_check=False, options=(TOLERANCE,))
def placeholder_identity(loaded, options):
    """## What it does
    Flags ``ixx=iyy=izz=1`` without products of inertia, unless the link's geometry really implies it.

    ## Why is this bad?
    The identity is what gets typed when the real value is unknown. On a 100 kg
    beam 20 m long it is off by a factor of three thousand: the simulated beam
    swings like a feather.

    ## Example
    ```xml
    <link name="beam">
      <collision><geometry><box size="1 1 20"/></geometry></collision>
      <inertial>
        <mass value="100"/>
        <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="beam">
      <collision><geometry><box size="1 1 20"/></geometry></collision>
      <inertial>
        <mass value="100"/>
        <inertia ixx="3341.67" ixy="0" ixz="0" iyy="3341.67" iyz="0" izz="16.6667"/>
      </inertial>
    </link>
    ```
    `urdfcli inertia --suggest` prints the values for each link.
    """
    for link in _declaring(loaded):
        if massprops.is_identity(_inertia().declared_tensor(link)):
            found = _assess(loaded, link, options)
            if found is not None and found.expected is not None and not found.off(options["tolerance"]):
                continue
            yield loaded.diagnostic("I007", f"inertia of link '{link.name}' is the identity, a placeholder", link.inertial.element.find("inertia"), _implies(found))


@check("I008", "placeholder-repeated", WARNING, "The same inertia tensor on links of very different sizes.", in_check=False, options=(TOLERANCE,))
def placeholder_repeated(loaded, options):
    """## What it does
    Flags a tensor repeated on links whose masses or geometries differ by more
    than a factor of two, on each copy that does not fit its own geometry.

    ## Why is this bad?
    One small value pasted on every sensor and caster is a placeholder: a 35 g
    camera and a 125 g lidar cannot share an inertia. Identical wheels sharing one
    tensor are fine and are not flagged.

    ## Example
    ```xml
    <link name="laser">
      <collision><geometry><cylinder radius="0.04" length="0.04"/></geometry></collision>
      <inertial><mass value="0.125"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    </link>
    <link name="camera_link">
      <collision><geometry><box size="0.015 0.13 0.022"/></geometry></collision>
      <inertial><mass value="0.035"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="laser">
      <collision><geometry><cylinder radius="0.04" length="0.04"/></geometry></collision>
      <inertial><mass value="0.125"/><inertia ixx="6.66667e-05" ixy="0" ixz="0" iyy="6.66667e-05" iyz="0" izz="0.0001"/></inertial>
    </link>
    <link name="camera_link">
      <collision><geometry><box size="0.015 0.13 0.022"/></geometry></collision>
      <inertial><mass value="0.035"/><inertia ixx="5.0703e-05" ixy="0" ixz="0" iyy="2.06792e-06" iyz="0" izz="4.99479e-05"/></inertial>
    </link>
    ```
    """
    groups = defaultdict(list)
    for link in _declaring(loaded):
        tensor = _inertia().declared_tensor(link)
        if not massprops.is_zero(tensor):
            groups[tensor].append(link)
    for tensor, links in groups.items():
        if len(links) < 2:
            continue
        found = {link.name: _assess(loaded, link, options) for link in links}
        sizes = [massprops.scale_of(a.expected) for a in found.values() if a is not None and a.expected is not None]
        masses = [link.inertial.mass for link in links]
        if max(masses) <= SIZE_RATIO * min(masses) and (len(sizes) < 2 or max(sizes) <= SIZE_RATIO * min(sizes)):
            continue
        for link in links:
            assessment = found[link.name]
            if assessment is not None and assessment.expected is not None and not assessment.off(options["tolerance"]):
                continue
            others = [f"'{other.name}'" for other in links[:4] if other is not link][:3]
            shown = ", ".join(others) + (f" and {len(links) - 4} more" if len(links) > 4 else "")
            yield loaded.diagnostic(
                "I008",
                f"link '{link.name}' has the same inertia ({_inertia().tensor_text(tensor)}) as {shown}, links of very different size: a placeholder",
                link.inertial.element.find("inertia"),
                _implies(assessment),
            )


@check("I009", "inertia-geometry-mismatch", WARNING, "A declared inertia tensor far from what the geometry and mass imply.", in_check=False, options=(TOLERANCE, DENSITY))
def geometry_mismatch(loaded, options):
    """## What it does
    Computes the tensor the link's collision shapes (else its visual shapes) imply
    for its mass: uniform density, box, cylinder and sphere in closed form, meshes
    loaded by yourdfpy and trimesh, several shapes composed with their origins. Flags a declared
    tensor whose largest element difference exceeds ``tolerance`` (0.1) of the
    larger tensor's largest element. When the tensor fits once rotated as the
    shapes are, I010 is reported instead.

    ## Why is this bad?
    A tensor with swapped axes, the wrong formula or a made-up value makes a
    simulated body turn too easily about one axis and too hard about another: it
    shakes, drifts or explodes.

    ## Example
    ```xml
    <link name="camera">
      <collision><geometry><box size="0.02 0.05 0.05"/></geometry></collision>
      <inertial>
        <mass value="0.01"/>
        <inertia ixx="2.42e-06" ixy="0" ixz="0" iyy="2.42e-06" iyz="0" izz="4.17e-06"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="camera">
      <collision><geometry><box size="0.02 0.05 0.05"/></geometry></collision>
      <inertial>
        <mass value="0.01"/>
        <inertia ixx="4.17e-06" ixy="0" ixz="0" iyy="2.42e-06" iyz="0" izz="2.42e-06"/>
      </inertial>
    </link>
    ```
    """
    tolerance = options["tolerance"]
    for link, found, rotated in _off_geometry(loaded, options):
        if rotated is not None and rotated[1] <= tolerance:
            continue  # I010 explains it
        hints = ["`urdfcli inertia --suggest` prints the corrected <inertial>"]
        if massprops.moments_difference(found.declared, found.expected) <= tolerance:
            hints.insert(0, "the principal moments match: the axes are swapped or rotated")
        centre = found.implied.body.com
        if max(abs(c - x) for c, x in zip(centre, link.inertial.origin.xyz)) > 1e-6 * max(1.0, *map(abs, centre)):
            hints.insert(0, f"the geometry's centre is at xyz=\"{' '.join(f'{c:.6g}' for c in centre)}\"")
        basis = f"density {format_number(options['density'])}" if options.get("density") else f"mass {format_number(link.inertial.mass)}"
        yield loaded.diagnostic(
            "I009",
            f"inertia of link '{link.name}' is {found.difference:.0%} off what its {found.implied.source} implies for {basis}: "
            f"declared {_inertia().tensor_text(found.declared, found.expected)}, expected {_inertia().tensor_text(found.expected, found.declared)}",
            link.inertial.element.find("inertia"),
            "; ".join(hints),
        )


@check("I010", "inertia-frame-rotated", WARNING, "An inertia tensor not rotated with the geometry it was computed for.", in_check=False, options=(TOLERANCE, DENSITY))
def frame_rotated(loaded, options):
    """## What it does
    Flags a tensor that is off its geometry's, but fits once rotated as the link's
    shapes are (their shared ``<origin rpy>``), or comes at least twice as close that way.

    ## Why is this bad?
    A wheel's cylinder is turned 90° about x to stand upright. The cylinder formula
    gives ``izz`` about the cylinder's axis, which is now the link's y axis; left
    unrotated, the simulated wheel resists spinning about the wrong axis.

    ## Example
    ```xml
    <link name="wheel">
      <collision>
        <origin rpy="1.5708 0 0"/>
        <geometry><cylinder radius="0.05" length="0.02"/></geometry>
      </collision>
      <inertial>
        <mass value="0.5"/>
        <inertia ixx="0.000329" ixy="0" ixz="0" iyy="0.000329" iyz="0" izz="0.000625"/>
      </inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="wheel">
      <collision>
        <origin rpy="1.5708 0 0"/>
        <geometry><cylinder radius="0.05" length="0.02"/></geometry>
      </collision>
      <inertial>
        <origin rpy="1.5708 0 0"/>
        <mass value="0.5"/>
        <inertia ixx="0.000329" ixy="0" ixz="0" iyy="0.000329" iyz="0" izz="0.000625"/>
      </inertial>
    </link>
    ```
    """
    tolerance = options["tolerance"]
    for link, found, rotated in _off_geometry(loaded, options):
        if rotated is None or (rotated[1] > tolerance and rotated[1] > found.difference / 2):
            continue
        rpy = " ".join(f"{a:.6g}" for a in rotated[0])
        where = found.implied.source.split(" ")[0]
        yield loaded.diagnostic(
            "I010",
            f"inertia of link '{link.name}' is not rotated with its {where} geometry (rpy {rpy}): "
            f"{found.difference:.0%} off as declared, {rotated[1]:.0%} once rotated",
            link.inertial.element.find("inertia"),
            f'give the <inertial> <origin rpy="{rpy}"/>, or use the rotated values `urdfcli inertia --suggest` prints',
        )


@check("I011", "root-inertia", WARNING, "The root link carries mass, which KDL ignores.", in_check=False)
def root_inertia(loaded):
    """## What it does
    Flags a root link with positive mass.

    ## Why is this bad?
    KDL (robot_state_publisher, MoveIt) cannot give the root link inertia: it
    warns and drops it, so the model's dynamics lose that body.

    ## Example
    ```xml
    <link name="base_link">
      <inertial><mass value="15"/><inertia ixx="0.28" ixy="0" ixz="0" iyy="0.28" iyz="0" izz="0.53"/></inertial>
    </link>
    ```

    ## Use instead
    ```xml
    <link name="base_footprint"/>
    <joint name="base_footprint_joint" type="fixed">
      <parent link="base_footprint"/>
      <child link="base_link"/>
    </joint>
    <link name="base_link">
      <inertial><mass value="15"/><inertia ixx="0.28" ixy="0" ixz="0" iyy="0.28" iyz="0" izz="0.53"/></inertial>
    </link>
    ```
    """
    root = loaded.root
    link = loaded.robot.links.get(root) if root is not None else None
    if link is not None and link.inertial is not None and (link.inertial.mass or 0) > 0:
        yield loaded.diagnostic(
            "I011",
            f"root link '{root}' has mass {format_number(link.inertial.mass)}, which KDL ignores",
            link.inertial.element,
            f"add a massless root link and a fixed joint from it to '{root}'",
        )
